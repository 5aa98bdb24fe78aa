// Building a mesh from a soup and walking it: genmesh's Halfedge_mesh against
// CGAL::Surface_mesh, on the same 1.3M-triangle soup, in one run.
//
//   build-bench/benchmarks/genmesh_benchmarks --benchmark_filter='Build|Traverse'
//       --benchmark_repetitions=5 --benchmark_report_aggregates_only=true   (one line)
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/soup_to_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <benchmark/benchmark.h>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;

const genmesh::Polygon_soup& soup() {
  static const genmesh::Polygon_soup s = genmesh::make_icosphere(8);  // 1,310,720 triangles
  return s;
}

template <class Mesh>
const Mesh& built() {
  static const Mesh m = [] {
    Mesh mesh;
    genmesh::build_mesh(soup(), mesh);
    return mesh;
  }();
  return m;
}

template <class Mesh, bool Check>
void BM_Build(benchmark::State& state) {
  for (auto _ : state) {
    Mesh mesh;
    genmesh::build_mesh(soup(), mesh, {.check = Check});
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["triangles/s"] =
      benchmark::Counter(double(soup().num_faces()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK_TEMPLATE(BM_Build, Halfedge_mesh, true)->Name("Build/genmesh::build_mesh(checked)/Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Build, Halfedge_mesh, false)->Name("Build/genmesh::build_mesh(unchecked)/Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Build, Surface_mesh, false)->Name("Build/genmesh::build_mesh(unchecked)/Surface_mesh")->Unit(benchmark::kMillisecond);

void BM_Build_cgal(benchmark::State& state) {
  std::vector<Kernel::Point_3> points;
  for (const auto& p : soup().points) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::array<std::size_t, 3>> faces;
  for (std::size_t f = 0; f < soup().num_faces(); ++f) {
    auto c = soup().face(f);
    faces.push_back({c[0], c[1], c[2]});
  }
  for (auto _ : state) {
    Surface_mesh mesh;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["triangles/s"] =
      benchmark::Counter(double(soup().num_faces()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Build_cgal)->Name("Build/CGAL::polygon_soup_to_polygon_mesh(unchecked)/Surface_mesh")->Unit(benchmark::kMillisecond);

// The one-ring of every vertex, through the generic free functions.
template <class Mesh>
void BM_Traverse_one_ring(benchmark::State& state) {
  const Mesh& m = built<Mesh>();
  const auto index = get(genmesh::vertex_index, m);
  for (auto _ : state) {
    std::size_t sum = 0;
    for (auto v : vertices(m)) {
      auto h = halfedge(v, m), start = h;
      do {
        sum += get(index, source(h, m));
        h = opposite(next(h, m), m);
      } while (h != start);
    }
    benchmark::DoNotOptimize(sum);
  }
}

template <class Mesh>
void BM_Traverse_face_cycles(benchmark::State& state) {
  const Mesh& m = built<Mesh>();
  for (auto _ : state) {
    std::size_t corners = 0;
    for (auto f : faces(m)) {
      auto h = halfedge(f, m), start = h;
      do {
        ++corners;
        h = next(h, m);
      } while (h != start);
    }
    benchmark::DoNotOptimize(corners);
  }
}

template <class Mesh>
void BM_Traverse_points(benchmark::State& state) {
  const Mesh& m = built<Mesh>();
  const auto points = get(genmesh::vertex_point, m);
  for (auto _ : state) {
    double s = 0;
    for (auto v : vertices(m)) s += genmesh::to_eigen(get(points, v)).sum();
    benchmark::DoNotOptimize(s);
  }
}

BENCHMARK_TEMPLATE(BM_Traverse_one_ring, Halfedge_mesh)->Name("Traverse/one_ring/Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Traverse_one_ring, Surface_mesh)->Name("Traverse/one_ring/Surface_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Traverse_face_cycles, Halfedge_mesh)->Name("Traverse/face_cycles/Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Traverse_face_cycles, Surface_mesh)->Name("Traverse/face_cycles/Surface_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Traverse_points, Halfedge_mesh)->Name("Traverse/points/Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Traverse_points, Surface_mesh)->Name("Traverse/points/Surface_mesh")->Unit(benchmark::kMillisecond);

} // namespace
