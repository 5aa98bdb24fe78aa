// Subdivision side by side: genmesh on Halfedge_mesh, genmesh on
// CGAL::Surface_mesh (and on Incidence_mesh for Loop × 3 and Catmull-Clark
// × 2: its bulk relink against its local operations), CGAL::Subdivision_method_3 on Surface_mesh and
// OpenMesh's uniform subdividers (LoopT, CatmullClarkT, Sqrt3T,
// ModifiedButterflyT), on armadillo.off (libcgal-demo, 52k triangles: Loop × 3,
// Catmull-Clark × 2, √3 × 3, butterfly × 3, midpoint × 3) and on a 1.3M-triangle icosphere
// (make_icosphere(8); Loop × 1, Catmull-Clark × 1).
//
//   genmesh_benchmarks --benchmark_filter=Subdivision --benchmark_repetitions=5
//                      --benchmark_report_aggregates_only=true
//
// The input is read from $GENMESH_DATA_DIR/meshes (default: the build's data folder).
// peak_MB is the heap peak above what was live before the call (the input
// copy, which the call may free or grow, is counted in "before").
// Each iteration subdivides a fresh copy of the input (the copy is not timed,
// nor is the destruction of the result).
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <benchmark/benchmark.h>

#include "heap_counter.h"

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

using Surface_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;
struct Om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Om_tri = OpenMesh::TriMesh_ArrayKernelT<Om_traits>;
using Om_poly = OpenMesh::PolyMesh_ArrayKernelT<Om_traits>;

enum class Input { armadillo, sphere };

const genmesh::Polygon_soup& soup(Input in) {
  static const genmesh::Polygon_soup armadillo = [] {
    const char* dir = std::getenv("GENMESH_DATA_DIR");
    return genmesh::read_soup(std::filesystem::path(dir ? dir : GENMESH_DATA_DIR) / "meshes" / "armadillo.off");
  }();
  if (in == Input::armadillo) return armadillo;
  static const genmesh::Polygon_soup sphere = genmesh::make_icosphere(8);
  return sphere;
}

template <class G>
G make(Input in) {
  G g;
  if constexpr (std::is_same_v<G, Om_tri> || std::is_same_v<G, Om_poly>) {
    const auto& s = soup(in);
    std::vector<typename G::VertexHandle> vh;
    vh.reserve(s.num_points());
    for (const auto& p : s.points) vh.push_back(g.add_vertex(typename G::Point(p.x(), p.y(), p.z())));
    std::vector<typename G::VertexHandle> f;
    for (std::size_t i = 0; i < s.num_faces(); ++i) {
      f.clear();
      for (auto c : s.face(i)) f.push_back(vh[c]);
      g.add_face(f);
    }
  } else {
    genmesh::build_mesh(soup(in), g, {.check = false});
  }
  return g;
}

template <class G>
const G& input(Input in) {
  static const G armadillo = make<G>(Input::armadillo);
  if (in == Input::armadillo) return armadillo;
  static const G sphere = make<G>(Input::sphere);
  return sphere;
}

/// The input with one removed vertex at the end of the index range: not
/// dense, so the in-place schemes take the local operations (the path a dense
/// Incidence_mesh took before its bulk relink); the first new vertex reuses
/// the slot, so the result is the same mesh.
template <class G>
const G& input_with_free_slot(Input in) {
  auto make_one = [](Input i) {
    G g = make<G>(i);
    if constexpr (requires { g.remove_vertex(g.add_vertex()); }) g.remove_vertex(g.add_vertex());
    return g;
  };
  static const G armadillo = make_one(Input::armadillo);
  if (in == Input::armadillo) return armadillo;
  static const G sphere = make_one(Input::sphere);
  return sphere;
}

template <class G>
std::size_t face_count(const G& g) {
  if constexpr (std::is_same_v<G, Om_tri> || std::is_same_v<G, Om_poly>) return g.n_faces();
  else return static_cast<std::size_t>(num_faces(g));
}

template <class G, class Run>
void run_case(benchmark::State& state, Input in, Run run, bool free_slot = false) {
  std::size_t faces = 0;
  long long peak = 0;
  for (auto _ : state) {
    state.PauseTiming();
    G g = free_slot ? input_with_free_slot<G>(in) : input<G>(in);
    const long long before = genmesh_bench::live_bytes();
    genmesh_bench::reset_peak();
    state.ResumeTiming();
    run(g);
    benchmark::DoNotOptimize(g);
    peak = genmesh_bench::peak_bytes() - before;
    faces = face_count(g);
    state.PauseTiming();
    { G discard = std::move(g); } // destruction not timed
    state.ResumeTiming();
  }
  state.counters["faces_out"] = static_cast<double>(faces);
  state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
}

template <template <class, class> class Subdivider, class G>
void openmesh(G& g, int levels) {
  Subdivider<G, double> s;
  s.attach(g);
  s(static_cast<std::size_t>(levels));
  s.detach();
}

/// An OpenMesh run on mesh type M.
template <class M>
struct Om_run {
  using Mesh = M;
  std::function<void(M&)> run;
  void operator()(M& g) const { run(g); }
};

void register_all() {
  using namespace genmesh;
  namespace sm3 = CGAL::Subdivision_method_3;
  auto reg = [](const std::string& name, auto fn) {
    benchmark::RegisterBenchmark(("Subdivision/" + name).c_str(), fn)->Unit(benchmark::kMillisecond);
  };
  // genmesh on both backends, CGAL and OpenMesh: the rows of one case
  auto reg_case = [&](const std::string& n, Input in, auto genmesh_run, auto cgal_run, const std::string& om_name,
                      auto om_run) {
    reg(n + "/genmesh_Halfedge_mesh", [=](benchmark::State& s) { run_case<Halfedge_mesh>(s, in, genmesh_run); });
    reg(n + "/genmesh_Surface_mesh", [=](benchmark::State& s) { run_case<Surface_mesh>(s, in, genmesh_run); });
    reg(n + "/CGAL_Surface_mesh", [=](benchmark::State& s) { run_case<Surface_mesh>(s, in, cgal_run); });
    reg(n + "/OpenMesh_" + om_name, [=](benchmark::State& s) {
      using Om = std::decay_t<decltype(om_run)>::Mesh;
      run_case<Om>(s, in, om_run);
    });
  };
  struct Case {
    const char* name;
    Input in;
    int levels;
  };
  for (Case c : {Case{"Loop3", Input::armadillo, 3}, Case{"Loop1_sphere1M", Input::sphere, 1}}) {
    const int l = c.levels;
    reg_case(
        c.name, c.in, [=](auto& g) { loop_subdivision(g, {.iterations = l}); },
        [=](auto& g) { sm3::Loop_subdivision(g, CGAL::parameters::number_of_iterations(l)); }, "LoopT",
        Om_run<Om_tri>{[=](Om_tri& g) { openmesh<OpenMesh::Subdivider::Uniform::LoopT>(g, l); }});
  }
  for (Case c : {Case{"CatmullClark2", Input::armadillo, 2}, Case{"CatmullClark1_sphere1M", Input::sphere, 1}}) {
    const int l = c.levels;
    reg_case(
        c.name, c.in, [=](auto& g) { catmull_clark_subdivision(g, {.iterations = l}); },
        [=](auto& g) { sm3::CatmullClark_subdivision(g, CGAL::parameters::number_of_iterations(l)); },
        "CatmullClarkT",
        Om_run<Om_poly>{[=](Om_poly& g) { openmesh<OpenMesh::Subdivider::Uniform::CatmullClarkT>(g, l); }});
  }
  // Incidence_mesh: the bulk relink (a dense input) against its local
  // operations (the same input with a free vertex slot), same result.
  for (Case c : {Case{"Loop3", Input::armadillo, 3}, Case{"CatmullClark2", Input::armadillo, 2}}) {
    const int l = c.levels;
    const bool loop = c.name == std::string("Loop3");
    auto sub = [=](auto& g) {
      if (loop) loop_subdivision(g, {.iterations = l});
      else catmull_clark_subdivision(g, {.iterations = l});
    };
    reg(std::string(c.name) + "/genmesh_Incidence_mesh",
        [=](benchmark::State& s) { run_case<genmesh::Incidence_mesh<>>(s, c.in, sub); });
    reg(std::string(c.name) + "/genmesh_Incidence_mesh_local_operations",
        [=](benchmark::State& s) { run_case<genmesh::Incidence_mesh<>>(s, c.in, sub, true); });
  }
  reg("Sqrt3_3/genmesh_Halfedge_mesh", [](benchmark::State& s) {
    run_case<Halfedge_mesh>(s, Input::armadillo, [](auto& g) { sqrt3_subdivision(g, {.iterations = 3}); });
  });
  reg("Sqrt3_3/CGAL_Surface_mesh", [](benchmark::State& s) {
    run_case<Surface_mesh>(s, Input::armadillo,
                           [](auto& g) { sm3::Sqrt3_subdivision(g, CGAL::parameters::number_of_iterations(3)); });
  });
  reg("Sqrt3_3/OpenMesh_Sqrt3T", [](benchmark::State& s) {
    run_case<Om_tri>(s, Input::armadillo, [](auto& g) { openmesh<OpenMesh::Subdivider::Uniform::Sqrt3T>(g, 3); });
  });
  reg("Butterfly3/genmesh_Halfedge_mesh", [](benchmark::State& s) {
    run_case<Halfedge_mesh>(s, Input::armadillo, [](auto& g) { butterfly_subdivision(g, {.iterations = 3}); });
  });
  reg("Butterfly3/genmesh_Surface_mesh", [](benchmark::State& s) {
    run_case<Surface_mesh>(s, Input::armadillo, [](auto& g) { butterfly_subdivision(g, {.iterations = 3}); });
  });
  reg("Butterfly3/OpenMesh_ModifiedButterflyT", [](benchmark::State& s) {
    run_case<Om_tri>(s, Input::armadillo,
                     [](auto& g) { openmesh<OpenMesh::Subdivider::Uniform::ModifiedButterflyT>(g, 3); });
  });
  // Midpoint (linear 1-to-4): no CGAL or OpenMesh counterpart on triangles
  // (CGAL's Linear_mask_3 is for quads, OpenMesh's MidpointT is another
  // scheme); compare with Loop × 3 above, the same refinement.
  reg("Midpoint3/genmesh_Halfedge_mesh", [](benchmark::State& s) {
    run_case<Halfedge_mesh>(s, Input::armadillo, [](auto& g) { midpoint_subdivision(g, {.iterations = 3}); });
  });
  reg("Midpoint3/genmesh_Surface_mesh", [](benchmark::State& s) {
    run_case<Surface_mesh>(s, Input::armadillo, [](auto& g) { midpoint_subdivision(g, {.iterations = 3}); });
  });
}

const bool registered = (register_all(), true);

} // namespace
