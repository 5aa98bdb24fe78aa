// Subdivision side by side on armadillo.off (libcgal-demo, 52k triangles):
// Loop × 3 and Catmull-Clark × 2 with genmesh on Halfedge_mesh, genmesh on
// CGAL::Surface_mesh, and CGAL::Subdivision_method_3 on Surface_mesh.
//
//   genmesh_benchmarks --benchmark_filter=Subdivision --benchmark_repetitions=5
//                      --benchmark_report_aggregates_only=true
//
// The input is read from $GENMESH_DATA_DIR/meshes (default: the build's data folder).
// peak_MB is the heap peak above the input copy while subdividing.
// Each iteration subdivides a fresh copy of the input (the copy is not timed).
#include <genmesh/adaptors/cgal.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/io.h>
#include <genmesh/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <benchmark/benchmark.h>

#include "heap_counter.h"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

using Surface_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;

std::string armadillo() {
  // GENMESH_DATA_DIR in the environment, else the build's data folder
  const char* dir = std::getenv("GENMESH_DATA_DIR");
  return (std::filesystem::path(dir ? dir : GENMESH_DATA_DIR) / "meshes" / "armadillo.off").string();
}

template <class G>
const G& input() {
  static const G g = [] {
    G m;
    genmesh::read_mesh(armadillo(), m);
    return m;
  }();
  return g;
}

enum class Scheme { loop, catmull_clark };
enum class Impl { genmesh, cgal };

template <class G, Scheme S, Impl I>
void BM_Subdivision(benchmark::State& state) {
  const int levels = S == Scheme::loop ? 3 : 2;
  std::size_t faces = 0;
  long long peak = 0;
  for (auto _ : state) {
    state.PauseTiming();
    G g = input<G>();
    const long long before = genmesh_bench::live_bytes();
    genmesh_bench::reset_peak();
    state.ResumeTiming();
    if constexpr (I == Impl::genmesh) {
      if constexpr (S == Scheme::loop) genmesh::loop_subdivision(g, {.iterations = levels});
      else genmesh::catmull_clark_subdivision(g, {.iterations = levels});
    } else {
      const auto np = CGAL::parameters::number_of_iterations(levels);
      if constexpr (S == Scheme::loop) CGAL::Subdivision_method_3::Loop_subdivision(g, np);
      else CGAL::Subdivision_method_3::CatmullClark_subdivision(g, np);
    }
    benchmark::DoNotOptimize(g);
    peak = genmesh_bench::peak_bytes() - before;
    faces = static_cast<std::size_t>(num_faces(g));
    state.PauseTiming();
    { G discard = std::move(g); } // destruction not timed
    state.ResumeTiming();
  }
  state.counters["faces_out"] = static_cast<double>(faces);
  state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
}

BENCHMARK(BM_Subdivision<Halfedge_mesh, Scheme::loop, Impl::genmesh>)
    ->Name("Subdivision/Loop3/genmesh_Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Subdivision<Surface_mesh, Scheme::loop, Impl::genmesh>)
    ->Name("Subdivision/Loop3/genmesh_Surface_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Subdivision<Surface_mesh, Scheme::loop, Impl::cgal>)
    ->Name("Subdivision/Loop3/CGAL_Surface_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Subdivision<Halfedge_mesh, Scheme::catmull_clark, Impl::genmesh>)
    ->Name("Subdivision/CatmullClark2/genmesh_Halfedge_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Subdivision<Surface_mesh, Scheme::catmull_clark, Impl::genmesh>)
    ->Name("Subdivision/CatmullClark2/genmesh_Surface_mesh")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Subdivision<Surface_mesh, Scheme::catmull_clark, Impl::cgal>)
    ->Name("Subdivision/CatmullClark2/CGAL_Surface_mesh")->Unit(benchmark::kMillisecond);

} // namespace
