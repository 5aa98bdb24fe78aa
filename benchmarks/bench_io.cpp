// Reading (and writing) a ~1M-triangle mesh: genmesh::read_soup against
// CGAL::IO, on a binary PLY and an OFF file.
//
// The mesh is a triangulated torus (1000 x 500 quads split in two: 500,000
// vertices, 1,000,000 triangles) made in memory and written once by
// genmesh::write_soup (PLY: binary little endian, double coordinates, uchar
// counts and int indices; OFF: shortest round-trip decimals) into a
// temporary directory.
//
//   build/benchmarks/genmesh_benchmarks --benchmark_filter='Read|Write'
//       --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <genmesh/generators.h>
#include <genmesh/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

struct Io_files {
  std::string ply;
  std::string off;
  std::size_t triangles = 0;
};

// Written once per process, on first use.
const Io_files& files() {
  static const Io_files f = [] {
    const auto dir = std::filesystem::temp_directory_path() / "genmesh_bench_io";
    std::filesystem::create_directories(dir);
    const genmesh::Polygon_soup torus = genmesh::make_torus(1000, 500, /*triangulate=*/true);
    Io_files r{(dir / "torus_1m.ply").string(), (dir / "torus_1m.off").string(), torus.num_faces()};
    genmesh::write_soup(r.ply, torus, {.binary = true});
    genmesh::write_soup(r.off, torus);
    return r;
  }();
  return f;
}

void report(benchmark::State& state, const std::string& path) {
  state.counters["triangles"] = static_cast<double>(files().triangles);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
}

void genmesh_read_soup(benchmark::State& state, const std::string& path) {
  for (auto _ : state) {
    genmesh::Polygon_soup s = genmesh::read_soup(path);
    if (s.num_faces() != files().triangles) throw std::runtime_error("wrong face count");
    benchmark::DoNotOptimize(s.points.data());
  }
}

void cgal_read_polygon_soup(benchmark::State& state, const std::string& path) {
  for (auto _ : state) {
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(path, points, polygons) || polygons.size() != files().triangles)
      throw std::runtime_error("CGAL::IO::read_polygon_soup failed");
    benchmark::DoNotOptimize(points.data());
  }
}

template <class Read>
void cgal_read_surface_mesh(benchmark::State& state, Read read) {
  for (auto _ : state) {
    CGAL::Surface_mesh<Point> m;
    if (!read(m) || m.number_of_faces() != files().triangles)
      throw std::runtime_error("CGAL::IO read into Surface_mesh failed");
    benchmark::DoNotOptimize(&m);
  }
}

void BM_ReadPly_genmesh_read_soup(benchmark::State& state) {
  genmesh_read_soup(state, files().ply);
  report(state, files().ply);
}
void BM_ReadPly_CGAL_read_polygon_soup(benchmark::State& state) {
  cgal_read_polygon_soup(state, files().ply);
  report(state, files().ply);
}
void BM_ReadPly_CGAL_read_PLY_Surface_mesh(benchmark::State& state) {
  cgal_read_surface_mesh(state, [](auto& m) { return CGAL::IO::read_PLY(files().ply, m); });
  report(state, files().ply);
}
void BM_ReadOff_genmesh_read_soup(benchmark::State& state) {
  genmesh_read_soup(state, files().off);
  report(state, files().off);
}
void BM_ReadOff_CGAL_read_polygon_soup(benchmark::State& state) {
  cgal_read_polygon_soup(state, files().off);
  report(state, files().off);
}
void BM_ReadOff_CGAL_read_OFF_Surface_mesh(benchmark::State& state) {
  cgal_read_surface_mesh(state, [](auto& m) { return CGAL::IO::read_OFF(files().off, m); });
  report(state, files().off);
}

// Writing the same mesh, each library from its own soup representation
// (both at 17 significant digits in OFF; binary PLY with double coordinates).
struct Cgal_soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};
const genmesh::Polygon_soup& torus_soup() {
  static const genmesh::Polygon_soup s = genmesh::read_soup(files().ply);
  return s;
}
const Cgal_soup& cgal_soup() {
  static const Cgal_soup s = [] {
    Cgal_soup r;
    if (!CGAL::IO::read_polygon_soup(files().ply, r.points, r.polygons))
      throw std::runtime_error("CGAL::IO::read_polygon_soup failed");
    return r;
  }();
  return s;
}
std::string out_path(const char* name) {
  return (std::filesystem::path(files().ply).parent_path() / name).string();
}

void BM_WritePly_genmesh_write_soup(benchmark::State& state) {
  const auto& s = torus_soup();
  const std::string p = out_path("w_genmesh.ply");
  for (auto _ : state) genmesh::write_soup(p, s, {.binary = true});
  report(state, p);
}
void BM_WritePly_CGAL_write_polygon_soup(benchmark::State& state) {
  const auto& s = cgal_soup();
  const std::string p = out_path("w_cgal.ply");
  for (auto _ : state)
    if (!CGAL::IO::write_polygon_soup(p, s.points, s.polygons, CGAL::parameters::use_binary_mode(true)))
      throw std::runtime_error("CGAL::IO::write_polygon_soup failed");
  report(state, p);
}
void BM_WriteOff_genmesh_write_soup(benchmark::State& state) {
  const auto& s = torus_soup();
  const std::string p = out_path("w_genmesh.off");
  for (auto _ : state) genmesh::write_soup(p, s);
  report(state, p);
}
void BM_WriteOff_CGAL_write_polygon_soup(benchmark::State& state) {
  const auto& s = cgal_soup();
  const std::string p = out_path("w_cgal.off");
  for (auto _ : state)
    if (!CGAL::IO::write_polygon_soup(p, s.points, s.polygons, CGAL::parameters::stream_precision(17)))
      throw std::runtime_error("CGAL::IO::write_polygon_soup failed");
  report(state, p);
}

} // namespace

BENCHMARK(BM_ReadPly_genmesh_read_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPly_CGAL_read_polygon_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPly_CGAL_read_PLY_Surface_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadOff_genmesh_read_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadOff_CGAL_read_polygon_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadOff_CGAL_read_OFF_Surface_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WritePly_genmesh_write_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WritePly_CGAL_write_polygon_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteOff_genmesh_write_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteOff_CGAL_write_polygon_soup)->Unit(benchmark::kMillisecond);
