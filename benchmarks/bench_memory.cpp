// Bytes per triangle of each backend, measured by counting the heap bytes a
// mesh holds after it is built from the same soup (every allocation of the
// process goes through the counting operator new below, which also keeps the
// peak other benchmarks read through heap_counter.h).
//
//   build/benchmarks/genmesh_benchmarks --benchmark_filter=Memory
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/soup_to_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "heap_counter.h"

namespace {
std::atomic<long long> live_bytes{0};
std::atomic<long long> peak_bytes{0};
} // namespace

long long genmesh_bench::live_bytes() { return ::live_bytes.load(); }
long long genmesh_bench::peak_bytes() { return ::peak_bytes.load(); }
void genmesh_bench::reset_peak() { ::peak_bytes.store(::live_bytes.load()); }

// Each block carries its size in a 16-byte header so delete can subtract it.
void* operator new(std::size_t n) {
  void* p = std::malloc(n + 16);
  if (!p) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  const long long now = live_bytes.fetch_add(static_cast<long long>(n), std::memory_order_relaxed) +
                        static_cast<long long>(n);
  long long peak = peak_bytes.load(std::memory_order_relaxed);
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
  return static_cast<char*>(p) + 16;
}
void operator delete(void* p) noexcept {
  if (!p) return;
  void* base = static_cast<char*>(p) - 16;
  live_bytes.fetch_sub(static_cast<long long>(*static_cast<std::size_t*>(base)),
                       std::memory_order_relaxed);
  std::free(base);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
// Over-aligned blocks (genmesh's Large_allocator asks for 2 MiB alignment):
// the size sits in the `alignment` bytes before the block.
void* operator new(std::size_t n, std::align_val_t al) {
  const std::size_t a = std::max(static_cast<std::size_t>(al), std::size_t{16});
  void* p = std::aligned_alloc(a, (n + a + a - 1) / a * a);
  if (!p) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  const long long now = live_bytes.fetch_add(static_cast<long long>(n), std::memory_order_relaxed) +
                        static_cast<long long>(n);
  long long peak = peak_bytes.load(std::memory_order_relaxed);
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
  return static_cast<char*>(p) + a;
}
void operator delete(void* p, std::align_val_t al) noexcept {
  if (!p) return;
  const std::size_t a = std::max(static_cast<std::size_t>(al), std::size_t{16});
  void* base = static_cast<char*>(p) - a;
  live_bytes.fetch_sub(static_cast<long long>(*static_cast<std::size_t*>(base)), std::memory_order_relaxed);
  std::free(base);
}
void operator delete(void* p, std::size_t, std::align_val_t al) noexcept { operator delete(p, al); }
void* operator new[](std::size_t n, std::align_val_t al) { return operator new(n, al); }
void operator delete[](void* p, std::align_val_t al) noexcept { operator delete(p, al); }
void operator delete[](void* p, std::size_t, std::align_val_t al) noexcept { operator delete(p, al); }
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;

const genmesh::Polygon_soup& input() {
  static const genmesh::Polygon_soup soup = genmesh::make_icosphere(7);  // 327,680 triangles
  return soup;
}

template <class Mesh>
void BM_Memory_bytes_per_triangle(benchmark::State& state) {
  const auto& soup = input();
  long long held = 0;
  for (auto _ : state) {
    const long long before = live_bytes.load();
    {
      Mesh mesh;
      genmesh::build_mesh(soup, mesh);
      held = live_bytes.load() - before;
      benchmark::DoNotOptimize(mesh);
    }
  }
  state.counters["bytes_per_triangle"] = double(held) / double(soup.num_faces());
  state.counters["triangles"] = double(soup.num_faces());
}
BENCHMARK_TEMPLATE(BM_Memory_bytes_per_triangle, genmesh::Halfedge_mesh<>)
    ->Name("Memory/bytes_per_triangle/Halfedge_mesh<Vector3d>")->Iterations(1);
BENCHMARK_TEMPLATE(BM_Memory_bytes_per_triangle, genmesh::Halfedge_mesh<Kernel::Point_3>)
    ->Name("Memory/bytes_per_triangle/Halfedge_mesh<EPICK::Point_3>")->Iterations(1);
BENCHMARK_TEMPLATE(BM_Memory_bytes_per_triangle, Surface_mesh)
    ->Name("Memory/bytes_per_triangle/Surface_mesh(genmesh build)")->Iterations(1);

// Surface_mesh built by CGAL's own soup converter, as a CGAL user would.
void BM_Memory_bytes_per_triangle_cgal_builder(benchmark::State& state) {
  const auto& soup = input();
  std::vector<Kernel::Point_3> points;
  for (const auto& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::array<std::size_t, 3>> faces;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto c = soup.face(f);
    faces.push_back({c[0], c[1], c[2]});
  }
  long long held = 0;
  for (auto _ : state) {
    const long long before = live_bytes.load();
    {
      Surface_mesh mesh;
      CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
      held = live_bytes.load() - before;
      benchmark::DoNotOptimize(mesh);
    }
  }
  state.counters["bytes_per_triangle"] = double(held) / double(soup.num_faces());
  state.counters["triangles"] = double(soup.num_faces());
}
BENCHMARK(BM_Memory_bytes_per_triangle_cgal_builder)
    ->Name("Memory/bytes_per_triangle/Surface_mesh(CGAL polygon_soup_to_polygon_mesh)")
    ->Iterations(1);

} // namespace
