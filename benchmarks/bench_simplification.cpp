// Simplification side by side: genmesh::simplify (Garland–Heckbert plane
// quadrics) on Halfedge_mesh, CGAL::Surface_mesh and Incidence_mesh; CGAL's
// Surface_mesh_simplification::edge_collapse with GH plane, GH probabilistic
// and Lindstrom–Turk policies; OpenMesh's Decimater with ModQuadricT;
// meshoptimizer's meshopt_simplify. Single thread.
//
// Inputs: armadillo.off after two Loop levels (832k triangles) → 10% and →
// 1%; mech-holes-shark.off (10k triangles, holes) → 10%; a flat 128 × 128
// grid (32k triangles in z = 0, dyadic coordinates: exactly coplanar faces,
// the self-intersection guard's worst case before its in-projection filter) → 25%.
//
//   genmesh_benchmarks --benchmark_filter=Simplification --benchmark_repetitions=3
//                      --benchmark_report_aggregates_only=true
//
// Timed: the algorithm alone, in CPU time of the calling thread
// (CLOCK_THREAD_CPUTIME_ID; the machine is shared, and wall time there
// measured 2-4x the CPU time under load). A fresh copy of the input per
// iteration, made and destroyed outside the timing. Counters, measured once per row on the
// result outside the timing: faces_out; peak_MB (heap peak above the input
// copy); hausdorff (symmetric, CGAL's approximate_symmetric_Hausdorff_distance
// with 100k samples per side, relative to the input's bounding-box diagonal);
// self_pairs (CGAL::Polygon_mesh_processing::self_intersections); manifold
// (1 if genmesh::check_soup / check_mesh find no non-manifold element).
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/measures.h>
#include <genmesh/simplification.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>
#include <genmesh/validity.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_probabilistic_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#ifdef GENMESH_HAVE_MESHOPTIMIZER
#include <meshoptimizer.h>
#endif

#include <benchmark/benchmark.h>

#include "bench_options.h"
#include "heap_counter.h"

#include <cstdio>
#include <ctime>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;
using Incidence_mesh = genmesh::Incidence_mesh<>;
struct Om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Om_tri = OpenMesh::TriMesh_ArrayKernelT<Om_traits>;
namespace SMS = CGAL::Surface_mesh_simplification;

enum class Input { armadillo_loop2, shark, armadillo, flat_grid };

std::filesystem::path mesh_path(const char* name) {
  const char* dir = std::getenv("GENMESH_DATA_DIR");
  return std::filesystem::path(dir ? dir : GENMESH_DATA_DIR) / "meshes" / name;
}

const genmesh::Polygon_soup& soup(Input in) {
  static const genmesh::Polygon_soup armadillo = [] {
    Halfedge_mesh g;
    genmesh::build_mesh(genmesh::read_soup(mesh_path("armadillo.off")), g);
    genmesh::loop_subdivision(g, {.iterations = 2});
    return genmesh::to_soup(g);
  }();
  static const genmesh::Polygon_soup shark = genmesh::read_soup(mesh_path("mech-holes-shark.off"));
  static const genmesh::Polygon_soup raw = genmesh::read_soup(mesh_path("armadillo.off"));
  static const genmesh::Polygon_soup flat = genmesh::make_grid(128, 128);
  return in == Input::armadillo_loop2 ? armadillo : in == Input::shark ? shark : in == Input::flat_grid ? flat : raw;
}

// A soup as a Surface_mesh, duplicating non-manifold vertices (for measuring
// results that are not manifold).
Surface_mesh to_surface_mesh(const genmesh::Polygon_soup& s) {
  Surface_mesh m;
  genmesh::build_mesh(s, m, {.repair = true});
  return m;
}

const Surface_mesh& input_sm(Input in) {
  static const Surface_mesh a = to_surface_mesh(soup(Input::armadillo_loop2));
  static const Surface_mesh b = to_surface_mesh(soup(Input::shark));
  static const Surface_mesh c = to_surface_mesh(soup(Input::armadillo));
  static const Surface_mesh d = to_surface_mesh(soup(Input::flat_grid));
  return in == Input::armadillo_loop2 ? a : in == Input::shark ? b : in == Input::flat_grid ? d : c;
}

double diagonal(const genmesh::Polygon_soup& s) {
  Eigen::AlignedBox3d box;
  for (const auto& p : s.points) box.extend(p);
  return box.diagonal().norm();
}

// The counters every row reports, from the result as a soup.
void measure(benchmark::State& state, Input in, const genmesh::Polygon_soup& out, bool manifold) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Surface_mesh result = to_surface_mesh(out);
  // CGAL 5.5 samples edges with its default generator (seeded from the clock)
  // whatever random_seed says: reseed it, so that a mesh always measures the same.
  CGAL::get_default_random() = CGAL::Random(7);
  const double h = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
      input_sm(in), result, CGAL::parameters::number_of_points_on_faces(100000).random_seed(7),
      CGAL::parameters::number_of_points_on_faces(100000).random_seed(7));
  std::vector<std::pair<Surface_mesh::Face_index, Surface_mesh::Face_index>> pairs;
  PMP::self_intersections<CGAL::Sequential_tag>(faces(result), result, std::back_inserter(pairs));
  state.counters["faces_out"] = static_cast<double>(out.num_faces());
  state.counters["hausdorff"] = h / diagonal(soup(in));
  state.counters["self_pairs"] = static_cast<double>(pairs.size());
  state.counters["manifold"] = manifold ? 1 : 0;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The name of the row being run (figures are kept per row).
std::string current_row;

std::size_t target_faces(Input in, double ratio) {
  return static_cast<std::size_t>(std::ceil(ratio * static_cast<double>(soup(in).num_faces())));
}

// Runs make() (untimed), run(g) (timed), then measures the first result.
template <class Make, class Run, class Result>
void run_case(benchmark::State& state, Input in, Make make, Run run, Result result) {
  // Measured once per row and process (repetitions reuse the figures).
  static std::map<std::string, std::map<std::string, double>> figures;
  auto& mine = figures[current_row];
  bool measured = !mine.empty();
  long long peak = 0;
  for (auto _ : state) {
    auto g = make();
    const long long before = genmesh_bench::live_bytes();
    genmesh_bench::reset_peak();
    const double t0 = thread_seconds();
    run(g);
    const double t1 = thread_seconds();
    peak = std::max(peak, genmesh_bench::peak_bytes() - before);
    state.SetIterationTime(t1 - t0);
    if (!measured && genmesh_bench::quality_wanted()) {
      auto [s, manifold] = result(g);
      measure(state, in, s, manifold);
      for (const auto& [k, v] : state.counters) mine[k] = v;
      measured = true;
    }
  }
  for (const auto& [k, v] : mine) state.counters[k] = v;
  state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
}

// The input as a mesh of type G (the soup is valid: no check).
template <class G>
G input_mesh(Input in) {
  G g;
  genmesh::build_mesh(soup(in), g, {.check = false});
  return g;
}

// genmesh's simplify with `Policy` on mesh type G; `guard`: .prevent_self_intersections;
// `schedule`: .schedule.
template <class G, class Policy = genmesh::Plane_quadrics>
void genmesh_row(benchmark::State& state, Input in, double ratio, bool guard = true,
                 genmesh::Schedule schedule = genmesh::Schedule::queue) {
  run_case(
      state, in,
      [&] { return input_mesh<G>(in); },
      [&](G& g) {
        genmesh::simplify(g, genmesh::Simplification_options<Policy>{.target_faces = target_faces(in, ratio),
                                                                      .prevent_self_intersections = guard,
                                                                      .schedule = schedule});
      },
      [](const G& g) { return std::pair{genmesh::to_soup(g), genmesh::check_mesh(g).ok()}; });
}

// The floor of issue 12's speed goal: what any simplifier that makes genmesh's
// collapses on a valid halfedge mesh must do at least. The collapses of
// genmesh_Halfedge_mesh_passes_no_guard (the survivor, the vertex that goes,
// the new point) are recorded once, outside the timing, then replayed on a
// fresh copy of the input:
//   floor_replay_collapse: per collapse, find the edge, test it
//     (can_collapse_edge: the link condition and the face checks every valid
//     halfedge collapse needs), collapse it (without testing it again, as
//     simplify since session 13), move the survivor;
//   floor_replay_quadrics: the same, plus the least Garland–Heckbert work:
//     every vertex's plane quadric from its faces and every edge's optimal
//     placement once before the first collapse, then per collapse the merged
//     quadric and the placements of the survivor's edges (border planes left
//     out: less work, still a lower bound).
// No ordering (no heap, no sorted passes), no fold-over test, no
// self-intersection guard: not simplifiers. They were lower bounds on time
// until session 19; since then simplify's unguarded run is faster than
// floor_replay_quadrics at 832k (0.62 s against 0.91 s: the queue's near
// band, look-ahead walks and huge pages, none of which the replay has, and
// the replay finds each edge by a walk). Counter same_as_simplify: 1 if the
// replay made simplify's mesh, bit for bit.
struct Recorded_collapse {
  genmesh::Vertex_index gone, survivor;
  Eigen::Vector3d position;
};

struct Record_collapses : genmesh::Mutation_visitor {
  std::vector<Recorded_collapse>* out;
  void on_collapse_placement(const auto& h, const auto& position, double /*cost*/, const auto& g) {
    out->push_back({source(h, g), target(h, g), position});
  }
};

struct Recording {
  std::vector<Recorded_collapse> steps;
  genmesh::Polygon_soup result; // simplify's, which the replay must give too
};

const Recording& recorded_collapses(Input in, double ratio) {
  static std::map<std::pair<Input, double>, Recording> cache;
  auto [it, fresh] = cache.try_emplace({in, ratio});
  if (fresh) {
    Halfedge_mesh g = input_mesh<Halfedge_mesh>(in);
    genmesh::simplify(g,
                      genmesh::Simplification_options<>{.target_faces = target_faces(in, ratio),
                                                        .prevent_self_intersections = false,
                                                        .schedule = genmesh::Schedule::passes},
                      Record_collapses{.out = &it->second.steps});
    it->second.result = genmesh::to_soup(g);
  }
  return it->second;
}

void floor_row(benchmark::State& state, Input in, double ratio, bool quadrics) {
  const Recording& recording = recorded_collapses(in, ratio);
  run_case(
      state, in,
      [&] { return input_mesh<Halfedge_mesh>(in); },
      [&](Halfedge_mesh& g) {
        auto point = get(genmesh::vertex_point, g);
        const genmesh::Plane_quadrics policy;
        std::vector<genmesh::Quadric> q;
        double sum = 0; // the placements' costs, so that none is optimized away
        auto place_edges_of = [&](genmesh::Vertex_index v) {
          const auto start = halfedge(v, g);
          auto x = start;
          do {
            const auto w = source(x, g);
            sum += policy.place(q[v.idx()] + q[w.idx()], get(point, v), get(point, w)).cost;
            x = opposite(next(x, g), g);
          } while (x != start);
        };
        if (quadrics) {
          q.assign(num_vertices(g), {});
          for (const auto f : faces(g)) {
            const auto h0 = halfedge(f, g), h1 = next(h0, g), h2 = next(h1, g);
            const auto a = target(h0, g), b = target(h1, g), c = target(h2, g);
            const genmesh::Quadric fq = policy.face(get(point, a), get(point, b), get(point, c));
            q[a.idx()] += fq;
            q[b.idx()] += fq;
            q[c.idx()] += fq;
          }
          for (const auto e : edges(g)) {
            const auto h = halfedge(e, g);
            const auto a = source(h, g), b = target(h, g);
            sum += policy.place(q[a.idx()] + q[b.idx()], get(point, a), get(point, b)).cost;
          }
        }
        for (const auto& s : recording.steps) {
          const auto [h, found] = halfedge(s.gone, s.survivor, g);
          const auto e = edge(h, g);
          if (!found || !genmesh::can_collapse_edge(e, std::as_const(g))) {
            state.SkipWithError("a recorded collapse was refused on replay");
            return;
          }
          genmesh::detail::lo::collapse_tested_edge(e, g, genmesh::Mutation_visitor{}); // tested just above
          put(point, s.survivor, s.position);
          if (quadrics) {
            q[s.survivor.idx()] += q[s.gone.idx()];
            place_edges_of(s.survivor);
          }
        }
        benchmark::DoNotOptimize(sum);
      },
      [&](const Halfedge_mesh& g) {
        // same_as_simplify: 1 if the replay made simplify's mesh, bit for bit.
        auto out = genmesh::to_soup(g);
        state.counters["same_as_simplify"] = out == recording.result ? 1 : 0;
        return std::pair{std::move(out), genmesh::check_mesh(g).ok()};
      });
}

// CGAL's edge_collapse stops on an edge count; on these meshes the face
// count follows (closed: F = 2E/3; the shark's border is 1% of its edges).
template <class Policies>
void cgal_row(benchmark::State& state, Input in, double ratio) {
  run_case(
      state, in, [&] { return input_sm(in); },
      [&](Surface_mesh& g) {
        const std::size_t target = target_faces(in, ratio);
        auto stop = [&](const auto&, const auto&, std::size_t, std::size_t) { return g.number_of_faces() <= target; };
        if constexpr (std::is_same_v<Policies, void>) {
          SMS::edge_collapse(g, stop);
        } else {
          Policies p(g);
          SMS::edge_collapse(g, stop, CGAL::parameters::get_cost(p.get_cost()).get_placement(p.get_placement()));
        }
      },
      [](Surface_mesh& g) {
        g.collect_garbage();
        return std::pair{genmesh::to_soup(g), genmesh::check_mesh(g).ok()};
      });
}

void openmesh_row(benchmark::State& state, Input in, double ratio) {
  run_case(
      state, in,
      [&] {
        auto g = std::make_unique<Om_tri>();
        const auto& s = soup(in);
        std::vector<Om_tri::VertexHandle> vh;
        for (const auto& p : s.points) vh.push_back(g->add_vertex(Om_tri::Point(p.x(), p.y(), p.z())));
        for (std::size_t i = 0; i < s.num_faces(); ++i) {
          auto f = s.face(i);
          g->add_face(vh[f[0]], vh[f[1]], vh[f[2]]);
        }
        return g;
      },
      [&](std::unique_ptr<Om_tri>& g) {
        OpenMesh::Decimater::DecimaterT<Om_tri> dec(*g);
        OpenMesh::Decimater::ModQuadricT<Om_tri>::Handle quadric;
        dec.add(quadric);
        dec.initialize();
        dec.decimate_to_faces(0, target_faces(in, ratio));
        g->garbage_collection();
      },
      [](std::unique_ptr<Om_tri>& g) {
        genmesh::Polygon_soup s;
        for (auto v : g->vertices()) {
          const auto p = g->point(v);
          s.add_point(p[0], p[1], p[2]);
        }
        for (auto f : g->faces()) {
          std::vector<genmesh::Polygon_soup::Index> c;
          for (auto v : g->fv_range(f)) c.push_back(static_cast<genmesh::Polygon_soup::Index>(v.idx()));
          s.add_face(c);
        }
        return std::pair{s, genmesh::check_soup(s).ok()};
      });
}

#ifdef GENMESH_HAVE_MESHOPTIMIZER
struct Meshopt_input {
  std::vector<float> positions;
  std::vector<unsigned> indices, out;
};

void meshopt_row(benchmark::State& state, Input in, double ratio) {
  run_case(
      state, in,
      [&] {
        Meshopt_input m;
        const auto& s = soup(in);
        for (const auto& p : s.points)
          for (int i = 0; i < 3; ++i) m.positions.push_back(static_cast<float>(p[i]));
        m.indices.assign(s.indices.begin(), s.indices.end());
        m.out.resize(m.indices.size());
        return m;
      },
      [&](Meshopt_input& m) {
        const std::size_t n = meshopt_simplify(m.out.data(), m.indices.data(), m.indices.size(), m.positions.data(),
                                               m.positions.size() / 3, 3 * sizeof(float), 3 * target_faces(in, ratio),
                                               1e30f);
        m.out.resize(n);
      },
      [&](Meshopt_input& m) {
        genmesh::Polygon_soup s;
        std::vector<unsigned> number(soup(in).points.size(), ~0u);
        for (unsigned& i : m.out) {
          if (number[i] == ~0u) {
            number[i] = static_cast<unsigned>(s.points.size());
            s.points.push_back(soup(in).points[i]);
          }
          i = number[i];
        }
        for (std::size_t i = 0; i + 2 < m.out.size(); i += 3) s.add_face({m.out[i], m.out[i + 1], m.out[i + 2]});
        return std::pair{s, genmesh::check_soup(s).ok()};
      });
}
#endif

// One row: run once, timed by hand (CPU time of the algorithm).
template <class Fn>
void register_row(const std::string& name, Fn fn) {
  benchmark::RegisterBenchmark(name.c_str(),
                               [name, fn](benchmark::State& s) {
                                 current_row = name;
                                 fn(s);
                               })
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->Iterations(1);
}

void register_all() {
  struct Case {
    const char* name;
    Input in;
    double ratio;
  };
  for (const Case c : {Case{"armadillo832k_to10pc", Input::armadillo_loop2, 0.1},
                       Case{"armadillo832k_to1pc", Input::armadillo_loop2, 0.01},
                       Case{"shark_to10pc", Input::shark, 0.1},
                       Case{"flat_grid128_to25pc", Input::flat_grid, 0.25}}) {
    auto reg = [&](const std::string& row, auto fn) {
      register_row("Simplification/" + std::string(c.name) + "/" + row, fn);
    };
    const Input in = c.in;
    const double r = c.ratio;
    reg("genmesh_Halfedge_mesh", [=](benchmark::State& s) { genmesh_row<Halfedge_mesh>(s, in, r); });
    reg("genmesh_Surface_mesh", [=](benchmark::State& s) { genmesh_row<Surface_mesh>(s, in, r); });
    reg("genmesh_Incidence_mesh", [=](benchmark::State& s) { genmesh_row<Incidence_mesh>(s, in, r); });
    reg("genmesh_Halfedge_mesh_no_guard",
        [=](benchmark::State& s) { genmesh_row<Halfedge_mesh>(s, in, r, false); });
    reg("genmesh_Surface_mesh_no_guard",
        [=](benchmark::State& s) { genmesh_row<Surface_mesh>(s, in, r, false); });
    // Schedule::passes (meshoptimizer's order: sorted passes, no heap), with and without the guard.
    reg("genmesh_Halfedge_mesh_passes",
        [=](benchmark::State& s) { genmesh_row<Halfedge_mesh>(s, in, r, true, genmesh::Schedule::passes); });
    reg("genmesh_Halfedge_mesh_passes_no_guard",
        [=](benchmark::State& s) { genmesh_row<Halfedge_mesh>(s, in, r, false, genmesh::Schedule::passes); });
    reg("genmesh_Surface_mesh_passes",
        [=](benchmark::State& s) { genmesh_row<Surface_mesh>(s, in, r, true, genmesh::Schedule::passes); });
    // Lower bounds on time for the collapses above (see floor_row).
    reg("genmesh_floor_replay_collapse", [=](benchmark::State& s) { floor_row(s, in, r, false); });
    reg("genmesh_floor_replay_quadrics", [=](benchmark::State& s) { floor_row(s, in, r, true); });
    reg("genmesh_Halfedge_mesh_Lindstrom_Turk",
        [=](benchmark::State& s) { genmesh_row<Halfedge_mesh, genmesh::Lindstrom_turk>(s, in, r); });
    reg("CGAL_GH_plane", [=](benchmark::State& s) {
      cgal_row<SMS::GarlandHeckbert_plane_policies<Surface_mesh, Kernel>>(s, in, r);
    });
    reg("CGAL_GH_probabilistic", [=](benchmark::State& s) {
      cgal_row<SMS::GarlandHeckbert_probabilistic_plane_policies<Surface_mesh, Kernel>>(s, in, r);
    });
    reg("CGAL_Lindstrom_Turk", [=](benchmark::State& s) { cgal_row<void>(s, in, r); });
    reg("OpenMesh_ModQuadric", [=](benchmark::State& s) { openmesh_row(s, in, r); });
#ifdef GENMESH_HAVE_MESHOPTIMIZER
    reg("meshoptimizer", [=](benchmark::State& s) { meshopt_row(s, in, r); });
#endif
  }
}

// The error-versus-face-count curve of docs/simplification.md (drawn by
// docs/make_simplification_pictures.py from this family's JSON output):
// armadillo.off (52k faces) at ratios from 50% to 0.5%, genmesh (GH plane
// quadrics, guard on), CGAL's GH plane policies, meshoptimizer.
void register_curve() {
  for (const double r : {0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005}) {
    auto reg = [&](const std::string& row, auto fn) {
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%g", r);
      register_row("SimplificationCurve/" + std::string(ratio) + "/" + row, fn);
    };
    reg("genmesh", [=](benchmark::State& s) { genmesh_row<Halfedge_mesh>(s, Input::armadillo, r); });
    reg("CGAL_GH_plane", [=](benchmark::State& s) {
      cgal_row<SMS::GarlandHeckbert_plane_policies<Surface_mesh, Kernel>>(s, Input::armadillo, r);
    });
#ifdef GENMESH_HAVE_MESHOPTIMIZER
    reg("meshoptimizer", [=](benchmark::State& s) { meshopt_row(s, Input::armadillo, r); });
#endif
  }
}

const bool registered = (register_all(), register_curve(), true);

// ---- Attribute simplification (docs/benchmarks.md, "Attribute simplification, session 6")
// Attribute_quadrics against plain Plane_quadrics on meshes with per-vertex
// colours, → 10% on Halfedge_mesh (guard on, as every row above):
// - dino.off (7,828 faces) with its own COFF colours (4 uchar values per
//   vertex, uniform grey: the cost does not depend on the values), weight 1
//   per full scale as `genmesh simplify --attributes 1` gives;
// - armadillo.off (51,996 faces) coloured by position (r, g, b: x, y, z
//   scaled into [0, 1] over the bounding box), weight 1.
// Rows: Plane_quadrics (the colours not used); Attribute_quadrics<G>
// (heap-stored quadrics: session 5's code, allocations in every evaluation);
// Attribute_quadrics<G, 8> (inline storage, same results to the bit);
// Attribute_quadrics<G, N> with N = 3 + the colour's width (7, 6);
// Hoppe_quadrics<G> (Hoppe 1999, heap storage) and Hoppe_quadrics<G, 4>
// (inline). The colour map holds Eigen vectors of at most 4 values (inline
// too), so the rows differ only in the quadrics. Timed: simplify() alone,
// thread CPU time; counters faces_out, peak_MB (heap peak above the input
// mesh) and hausdorff (genmesh's seeded symmetric estimate, relative to the
// bounding-box diagonal; what the attributes cost the geometry).
//
//   genmesh_benchmarks --benchmark_filter=AttributeSimplification --benchmark_repetitions=5
//                      --benchmark_report_aggregates_only=true
struct Coloured_input {
  genmesh::Polygon_soup soup;
  genmesh::Soup_attribute colour;
  double weight = 1;
};

const Coloured_input& coloured_input(bool dino) {
  static const Coloured_input d = [] {
    Coloured_input c;
    c.soup = genmesh::read_soup(mesh_path("dino.off"));
    c.colour = *c.soup.vertex_attribute("color");
    c.weight = 1.0 / 255; // uchar colours in units of full scale
    return c;
  }();
  static const Coloured_input a = [] {
    Coloured_input c;
    c.soup = soup(Input::armadillo);
    Eigen::AlignedBox3d box;
    for (const auto& p : c.soup.points) box.extend(p);
    c.colour = {"color", {"red", "green", "blue"}, genmesh::Scalar_type::float64, {}};
    for (const auto& p : c.soup.points)
      for (int k = 0; k < 3; ++k) c.colour.values.push_back((p[k] - box.min()[k]) / box.sizes()[k]);
    return c;
  }();
  return dino ? d : a;
}

// Policy: Plane_quadrics, Attribute_quadrics<Halfedge_mesh, N> or Hoppe_quadrics<Halfedge_mesh, N>.
template <class Policy>
void attribute_row(benchmark::State& state, bool dino) {
  const Coloured_input& in = coloured_input(dino);
  using Colour = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 4, 1>;
  long long peak = 0;
  std::size_t faces_out = 0;
  double hausdorff = -1;
  for (auto _ : state) {
    Halfedge_mesh g;
    genmesh::build_mesh(in.soup, g, {.check = false});
    auto colour = genmesh::scratch_property<Colour>(genmesh::vertex_index, g);
    genmesh::read_vertex_attribute(in.colour, g, colour);
    genmesh::Simplification_options<Policy> o{.target_ratio = 0.1};
    if constexpr (!std::is_same_v<Policy, genmesh::Plane_quadrics>)
      o.policy.attributes = {genmesh::vertex_attribute(colour, in.weight, "color")};
    const long long before = genmesh_bench::live_bytes();
    genmesh_bench::reset_peak();
    const double t0 = thread_seconds();
    genmesh::simplify(g, o);
    const double t1 = thread_seconds();
    peak = std::max(peak, genmesh_bench::peak_bytes() - before);
    faces_out = num_faces(g);
    state.SetIterationTime(t1 - t0);
    if (hausdorff < 0 && genmesh_bench::quality_wanted()) {
      Halfedge_mesh input;
      genmesh::build_mesh(in.soup, input, {.check = false});
      genmesh::Hausdorff_options ho;
      ho.seed = 7;
      hausdorff = genmesh::hausdorff_distance(input, g, ho).hausdorff / diagonal(in.soup);
    }
  }
  state.counters["faces_out"] = static_cast<double>(faces_out);
  state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
  if (hausdorff >= 0) state.counters["hausdorff"] = hausdorff;
}

void register_attribute_rows() {
  for (const bool dino : {true, false}) {
    const std::string mesh = dino ? "dino" : "armadillo";
    register_row("AttributeSimplification/" + mesh + "/Plane_quadrics",
                 [=](benchmark::State& s) { attribute_row<genmesh::Plane_quadrics>(s, dino); });
    register_row("AttributeSimplification/" + mesh + "/Attribute_quadrics_heap",
                 [=](benchmark::State& s) { attribute_row<genmesh::Attribute_quadrics<Halfedge_mesh>>(s, dino); });
    register_row("AttributeSimplification/" + mesh + "/Attribute_quadrics_inline8",
                 [=](benchmark::State& s) { attribute_row<genmesh::Attribute_quadrics<Halfedge_mesh, 8>>(s, dino); });
    // The bound that fits exactly: 3 + 4 (dino's RGBA), 3 + 3 (armadillo's RGB).
    register_row("AttributeSimplification/" + mesh + "/Attribute_quadrics_inline_exact", [=](benchmark::State& s) {
      if (dino) attribute_row<genmesh::Attribute_quadrics<Halfedge_mesh, 7>>(s, dino);
      else attribute_row<genmesh::Attribute_quadrics<Halfedge_mesh, 6>>(s, dino);
    });
    register_row("AttributeSimplification/" + mesh + "/Hoppe_quadrics_heap",
                 [=](benchmark::State& s) { attribute_row<genmesh::Hoppe_quadrics<Halfedge_mesh>>(s, dino); });
    register_row("AttributeSimplification/" + mesh + "/Hoppe_quadrics_inline4",
                 [=](benchmark::State& s) { attribute_row<genmesh::Hoppe_quadrics<Halfedge_mesh, 4>>(s, dino); });
  }
}

const bool attribute_rows_registered = (register_attribute_rows(), true);

} // namespace
