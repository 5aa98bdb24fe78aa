// Isotropic remeshing side by side: genmesh::isotropic_remeshing on
// Halfedge_mesh, CGAL::Surface_mesh and Incidence_mesh, and CGAL's
// PMP::isotropic_remeshing on Surface_mesh; target = the input's mean edge
// length, 5 iterations, on armadillo.off (52k triangles), bunny00.off (75k)
// and armadillo after two Loop levels (832k triangles, made here, as the
// geometry benchmarks make it; one iteration of each row, no Hausdorff).
//
//   genmesh_benchmarks --benchmark_filter=Remeshing --benchmark_repetitions=3
//                      --benchmark_report_aggregates_only=true
//
// Counters (from the last run, computed after timing): faces_out, peak_MB
// (heap peak above what was live before the call), min_angle (degrees),
// below30 (share of angles < 30°, %), valence6 (share of inner vertices of
// valence 6, %), hausdorff_rel (symmetric approximate Hausdorff distance to
// the input over the bounding-box diagonal, CGAL's sampler at 10 points per
// L²; not computed on the 832k mesh).
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/remeshing.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include "bench_options.h"
#include "heap_counter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace {

using Surface_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;
using Incidence_mesh = genmesh::Incidence_mesh<>;

enum class Input { armadillo, bunny, armadillo_loop2 };

const genmesh::Polygon_soup& soup(Input in) {
  auto read = [](const char* name) {
    const char* dir = std::getenv("GENMESH_DATA_DIR");
    return genmesh::read_soup(std::filesystem::path(dir ? dir : GENMESH_DATA_DIR) / "meshes" / name);
  };
  static const genmesh::Polygon_soup armadillo = read("armadillo.off");
  static const genmesh::Polygon_soup bunny = read("bunny00.off");
  if (in == Input::armadillo) return armadillo;
  if (in == Input::bunny) return bunny;
  static const genmesh::Polygon_soup loop2 = [] {
    Halfedge_mesh g;
    genmesh::build_mesh(armadillo, g);
    genmesh::loop_subdivision(g, {.iterations = 2});
    return genmesh::to_soup(g);
  }();
  return loop2;
}

/// The input's mean edge length (the target of every row).
double target(Input in) {
  Halfedge_mesh g;
  genmesh::build_mesh(soup(in), g, {.check = false});
  double sum = 0;
  std::size_t n = 0;
  for (auto e : edges(g)) {
    const auto h = halfedge(e, g);
    sum += (g.point(target(h, g)) - g.point(source(h, g))).norm();
    ++n;
  }
  return sum / static_cast<double>(n);
}

template <class G>
const G& input(Input in) {
  static std::map<Input, G> cache;
  auto it = cache.find(in);
  if (it == cache.end()) {
    G g;
    genmesh::build_mesh(soup(in), g, {.check = false});
    it = cache.emplace(in, std::move(g)).first;
  }
  return it->second;
}

struct Quality {
  double min_angle = 180, below30 = 0, valence6 = 0;
};

Quality quality(const genmesh::Polygon_soup& s) {
  Quality q;
  std::size_t angles = 0, small = 0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    const auto c = s.face(f);
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d a = s.points[c[i]], b = s.points[c[(i + 1) % 3]], d = s.points[c[(i + 2) % 3]];
      const double ang =
          std::acos(std::clamp((b - a).normalized().dot((d - a).normalized()), -1.0, 1.0)) * 180 / std::numbers::pi;
      q.min_angle = std::min(q.min_angle, ang);
      ++angles;
      small += ang < 30;
      ++edges[{std::min(c[i], c[(i + 1) % 3]), std::max(c[i], c[(i + 1) % 3])}];
    }
  }
  std::vector<int> val(s.num_points(), 0);
  std::vector<char> border(s.num_points(), 0);
  for (const auto& [e, k] : edges) {
    ++val[e.first], ++val[e.second];
    if (k == 1) border[e.first] = border[e.second] = 1;
  }
  std::size_t inner = 0, six = 0;
  for (std::size_t v = 0; v < val.size(); ++v)
    if (val[v] && !border[v]) ++inner, six += val[v] == 6;
  q.below30 = 100.0 * static_cast<double>(small) / static_cast<double>(angles);
  q.valence6 = 100.0 * static_cast<double>(six) / static_cast<double>(inner);
  return q;
}

double hausdorff_relative(const genmesh::Polygon_soup& out, Input in, double L) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Surface_mesh& a = input<Surface_mesh>(in);
  Surface_mesh b;
  genmesh::build_mesh(out, b, {.check = false});
  // Seeded (faces by random_seed; CGAL 5.5 samples edges with its default
  // generator, seeded from the clock, whatever random_seed says): a mesh
  // always measures the same.
  const auto np = CGAL::parameters::number_of_points_per_area_unit(10 / (L * L)).random_seed(7);
  CGAL::get_default_random() = CGAL::Random(7);
  const double h = std::max(PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(a, b, np),
                            PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(b, a, np));
  const auto box = PMP::bbox(a);
  const double diag = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                CGAL::square(box.zmax() - box.zmin()));
  return h / diag;
}

template <class G, class Run>
void run_case(benchmark::State& state, Input in, Run run) {
  const double L = target(in);
  long long peak = 0;
  genmesh::Polygon_soup out;
  for (auto _ : state) {
    state.PauseTiming();
    G g = input<G>(in);
    const long long before = genmesh_bench::live_bytes();
    genmesh_bench::reset_peak();
    state.ResumeTiming();
    run(g, L);
    benchmark::DoNotOptimize(g);
    state.PauseTiming();
    peak = genmesh_bench::peak_bytes() - before;
    out = genmesh::to_soup(g);
    { G discard = std::move(g); } // destruction not timed
    state.ResumeTiming();
  }
  state.counters["faces_out"] = static_cast<double>(out.num_faces());
  state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
  if (!genmesh_bench::quality_wanted()) return;
  const Quality q = quality(out);
  state.counters["min_angle"] = q.min_angle;
  state.counters["below30"] = q.below30;
  state.counters["valence6"] = q.valence6;
  if (in != Input::armadillo_loop2) state.counters["hausdorff_rel"] = hausdorff_relative(out, in, L);
}

void register_all() {
  auto ours = [](auto& g, double L) { genmesh::isotropic_remeshing(g, {.target_edge_length = L, .iterations = 5}); };
  // With .renumber = true (a spatial renumbering where a step changed much;
  // off by default: on Surface_mesh it would leave user properties behind).
  auto renumbered = [](auto& g, double L) {
    genmesh::isotropic_remeshing(g, {.target_edge_length = L, .iterations = 5, .renumber = true});
  };
  auto cgal = [](Surface_mesh& g, double L) {
    CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(g), L, g, CGAL::parameters::number_of_iterations(5));
  };
  struct Case {
    const char* name;
    Input in;
  };
  for (Case c : {Case{"armadillo", Input::armadillo}, Case{"bunny", Input::bunny}, Case{"armadillo_loop2", Input::armadillo_loop2}}) {
    const std::string n = std::string("Remeshing/") + c.name;
    const Input in = c.in;
    auto reg = [&](const std::string& row, auto fn) {
      auto* b = benchmark::RegisterBenchmark((n + "/" + row).c_str(), fn)->Unit(benchmark::kMillisecond);
      if (in == Input::armadillo_loop2) b->Iterations(1);
    };
    reg("genmesh_Halfedge_mesh", [=](benchmark::State& s) { run_case<Halfedge_mesh>(s, in, ours); });
    reg("genmesh_Halfedge_mesh_renumber", [=](benchmark::State& s) { run_case<Halfedge_mesh>(s, in, renumbered); });
    reg("genmesh_Surface_mesh", [=](benchmark::State& s) { run_case<Surface_mesh>(s, in, ours); });
    reg("genmesh_Incidence_mesh", [=](benchmark::State& s) { run_case<Incidence_mesh>(s, in, ours); });
    reg("CGAL_Surface_mesh", [=](benchmark::State& s) { run_case<Surface_mesh>(s, in, cgal); });
  }
}

const int registered = (register_all(), 0);

} // namespace
