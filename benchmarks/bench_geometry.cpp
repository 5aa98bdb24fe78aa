// The geometry layer side by side with CGAL: spatial index build, 1M
// closest-point queries, does_self_intersect / self_intersections and a
// 1e6-sample one-sided Hausdorff distance — genmesh's Aabb_tree and measures
// on Halfedge_mesh against CGAL's AABB_tree (with accelerate_distance_queries),
// PMP::does_self_intersect / self_intersections and
// PMP::approximate_Hausdorff_distance on Surface_mesh, all single-threaded,
// on armadillo.off after two Loop levels (832k triangles, made here).
//
//   genmesh_benchmarks --benchmark_filter=Geometry --benchmark_repetitions=3
//                      --benchmark_report_aggregates_only=true
//
// peak_MB is the heap peak above what was live before the timed call (the
// input mesh is not counted; the index and every temporary are).
#include <genmesh/aabb_tree.h>
#include <genmesh/adaptors/cgal.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/io.h>
#include <genmesh/measures.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include "heap_counter.h"

#include <cstdlib>
#include <filesystem>
#include <random>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<K::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;
using Cgal_tree =
    CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Surface_mesh>>>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Armadillo after `levels` Loop levels, as a soup.
const genmesh::Polygon_soup& armadillo(int levels) {
  static std::vector<genmesh::Polygon_soup> cache;
  if (cache.empty()) {
    const char* dir = std::getenv("GENMESH_DATA_DIR");
    Halfedge_mesh g;
    genmesh::build_mesh(
        genmesh::read_soup(std::filesystem::path(dir ? dir : GENMESH_DATA_DIR) / "meshes" / "armadillo.off"), g);
    for (int l = 0; l <= 2; ++l) {
      if (l) genmesh::loop_subdivision(g, {.iterations = 1});
      cache.push_back(genmesh::to_soup(g));
    }
  }
  return cache[levels];
}

template <class G>
const G& mesh(int levels) {
  static std::vector<G> cache = [] {
    std::vector<G> v(3);
    for (int l = 0; l < 3; ++l) genmesh::build_mesh(armadillo(l), v[l]);
    return v;
  }();
  return cache[levels];
}

// 1M query points: half uniform in the box grown by 10%, half within 1% of
// the diagonal of a vertex.
const std::vector<Eigen::Vector3d>& queries() {
  static const std::vector<Eigen::Vector3d> q = [] {
    const auto& s = armadillo(2);
    Eigen::AlignedBox3d box;
    for (const auto& p : s.points) box.extend(p);
    const double diag = box.diagonal().norm();
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Eigen::Vector3d> out;
    for (int i = 0; i < 1'000'000; ++i) {
      if (i % 2) {
        const auto& p = s.points[rng() % s.points.size()];
        out.push_back(p + 0.01 * diag * Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
      } else {
        Eigen::Vector3d p;
        for (int k = 0; k < 3; ++k) p[k] = box.min()[k] - 0.1 * box.sizes()[k] + u(rng) * 1.2 * box.sizes()[k];
        out.push_back(p);
      }
    }
    return out;
  }();
  return q;
}

// Times run() once per iteration and records the heap peak above "before".
template <class Run>
void measure(benchmark::State& state, Run run) {
  long long peak = 0;
  for (auto _ : state) {
    const long long before = genmesh_bench::live_bytes();
    genmesh_bench::reset_peak();
    run();
    peak = genmesh_bench::peak_bytes() - before;
  }
  state.counters["peak_MB"] = static_cast<double>(peak) / 1e6;
  state.counters["faces"] = static_cast<double>(armadillo(2).num_faces());
}

void Geometry_index_build_genmesh(benchmark::State& state) {
  const auto& g = mesh<Halfedge_mesh>(2);
  measure(state, [&] {
    genmesh::Aabb_tree<Halfedge_mesh> tree(g);
    benchmark::DoNotOptimize(tree);
  });
}

void Geometry_index_build_cgal(benchmark::State& state) {
  const auto& sm = mesh<Surface_mesh>(2);
  measure(state, [&] {
    Cgal_tree tree(faces(sm).first, faces(sm).second, sm);
    tree.build();
    tree.accelerate_distance_queries();
    benchmark::DoNotOptimize(tree);
  });
}

void Geometry_closest_1M_genmesh(benchmark::State& state) {
  const auto& g = mesh<Halfedge_mesh>(2);
  const genmesh::Aabb_tree<Halfedge_mesh> tree(g);
  const auto& q = queries();
  double sum = 0;
  measure(state, [&] {
    for (const auto& p : q) sum += tree.closest_point(p).squared_distance;
  });
  benchmark::DoNotOptimize(sum);
}

void Geometry_closest_1M_cgal(benchmark::State& state) {
  const auto& sm = mesh<Surface_mesh>(2);
  Cgal_tree tree(faces(sm).first, faces(sm).second, sm);
  tree.build();
  tree.accelerate_distance_queries();
  const auto& q = queries();
  double sum = 0;
  measure(state, [&] {
    for (const auto& p : q) {
      const K::Point_3 x(p.x(), p.y(), p.z());
      sum += CGAL::squared_distance(x, tree.closest_point(x));
    }
  });
  benchmark::DoNotOptimize(sum);
}

void Geometry_does_self_intersect_genmesh(benchmark::State& state) {
  const auto& g = mesh<Halfedge_mesh>(2);
  bool r = false;
  measure(state, [&] { r = genmesh::does_self_intersect(g); });
  state.counters["intersects"] = r;
}

void Geometry_does_self_intersect_cgal(benchmark::State& state) {
  const auto& sm = mesh<Surface_mesh>(2);
  bool r = false;
  measure(state, [&] { r = PMP::does_self_intersect<CGAL::Sequential_tag>(sm); });
  state.counters["intersects"] = r;
}

void Geometry_self_intersections_genmesh(benchmark::State& state) {
  const auto& g = mesh<Halfedge_mesh>(2);
  std::size_t n = 0;
  measure(state, [&] { n = genmesh::self_intersections(g).size(); });
  state.counters["pairs"] = static_cast<double>(n);
}

void Geometry_self_intersections_cgal(benchmark::State& state) {
  const auto& sm = mesh<Surface_mesh>(2);
  std::size_t n = 0;
  measure(state, [&] {
    std::vector<std::pair<Surface_mesh::Face_index, Surface_mesh::Face_index>> out;
    PMP::self_intersections<CGAL::Sequential_tag>(sm, std::back_inserter(out));
    n = out.size();
  });
  state.counters["pairs"] = static_cast<double>(n);
}

// One-sided, from the 832k-face level to the 208k-face level, 1e6 face
// samples (no vertex or edge samples on either side), index build included.
void Geometry_hausdorff_1M_genmesh(benchmark::State& state) {
  const auto& a = mesh<Halfedge_mesh>(2);
  const auto& b = mesh<Halfedge_mesh>(1);
  double d = 0;
  measure(state, [&] {
    genmesh::Hausdorff_options o;
    o.samples = 1'000'000;
    o.vertices = o.edge_midpoints = false;
    d = genmesh::one_sided_hausdorff(a, b, o).max;
  });
  state.counters["distance"] = d;
}

void Geometry_hausdorff_1M_cgal(benchmark::State& state) {
  const auto& a = mesh<Surface_mesh>(2);
  const auto& b = mesh<Surface_mesh>(1);
  double d = 0;
  measure(state, [&] {
    d = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
        a, b,
        CGAL::parameters::number_of_points_on_faces(1'000'000).do_sample_vertices(false).do_sample_edges(false));
  });
  state.counters["distance"] = d;
}

} // namespace

BENCHMARK(Geometry_index_build_genmesh)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_index_build_cgal)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_closest_1M_genmesh)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_closest_1M_cgal)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_does_self_intersect_genmesh)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_does_self_intersect_cgal)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_self_intersections_genmesh)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_self_intersections_cgal)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_hausdorff_1M_genmesh)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Geometry_hausdorff_1M_cgal)->Unit(benchmark::kMillisecond)->Iterations(1);
