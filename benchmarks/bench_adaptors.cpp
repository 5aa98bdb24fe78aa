// genmesh on the adapted meshes, build → Loop × 2 → write, per backend, so
// a cliff in an adaptor (an index map that is not O(1), a slow add_face)
// shows beside Halfedge_mesh and Surface_mesh: hand.off (libcgal-demo,
// 2.4k triangles → 38k after two levels) and armadillo.off (52k → 832k).
//
//   genmesh_benchmarks --benchmark_filter=Adaptors --benchmark_repetitions=5
//                      --benchmark_report_aggregates_only=true
//
// Each iteration: build_mesh from the soup read once (not timed), then
// loop_subdivision({.iterations = 2}), then write_mesh to an OFF file in the
// system's temporary folder; the counters split the time into the three steps.
#include <genmesh/adaptors/cgal.h>
#include <genmesh/adaptors/openmesh.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
struct Om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Om_poly = OpenMesh::PolyMesh_ArrayKernelT<Om_traits>;

const genmesh::Polygon_soup& soup(const std::string& name) {
  static std::map<std::string, genmesh::Polygon_soup> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    const char* dir = std::getenv("GENMESH_DATA_DIR");
    it = cache.emplace(name, genmesh::read_soup(std::filesystem::path(dir ? dir : GENMESH_DATA_DIR) / "meshes" / name))
             .first;
  }
  return it->second;
}

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

template <class G>
void pipeline(benchmark::State& state, const std::string& name) {
  const auto out = std::filesystem::temp_directory_path() /
                   ("genmesh_bench_adaptors_" + std::to_string(::getpid()) + ".off");
  double build = 0, subdivide = 0, write = 0;
  for (auto _ : state) {
    auto t = std::chrono::steady_clock::now();
    G g;
    genmesh::build_mesh(soup(name), g);
    build += since(t);
    t = std::chrono::steady_clock::now();
    genmesh::loop_subdivision(g, {.iterations = 2});
    subdivide += since(t);
    t = std::chrono::steady_clock::now();
    genmesh::write_mesh(out, g);
    write += since(t);
  }
  std::filesystem::remove(out);
  const double n = static_cast<double>(state.iterations());
  state.counters["build_ms"] = 1e3 * build / n;
  state.counters["subdivide_ms"] = 1e3 * subdivide / n;
  state.counters["write_ms"] = 1e3 * write / n;
}

void register_all() {
  for (const std::string name : {"hand.off", "armadillo.off"}) {
    const std::string base = "Adaptors/" + name.substr(0, name.find('.')) + "/";
    auto reg = [&](const std::string& backend, void (*fn)(benchmark::State&, const std::string&)) {
      benchmark::RegisterBenchmark((base + backend).c_str(), fn, name)->Unit(benchmark::kMillisecond);
    };
    reg("Halfedge_mesh", pipeline<genmesh::Halfedge_mesh<>>);
    reg("Surface_mesh", pipeline<Surface_mesh>);
    reg("Incidence_mesh", pipeline<genmesh::Incidence_mesh<>>);
    reg("Polyhedron_3", pipeline<Polyhedron>);
    reg("OpenMesh_PolyMesh", pipeline<Om_poly>);
  }
}

const int registered = (register_all(), 0);

} // namespace
