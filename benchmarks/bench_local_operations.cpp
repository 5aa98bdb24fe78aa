// Throughput of the local operations: genmesh on Halfedge_mesh, genmesh on
// CGAL::Surface_mesh, and CGAL::Euler on Surface_mesh, on the same mesh
// (icosphere(5), 20480 triangles) and the same edge lists.
//
//   build/benchmarks/genmesh_benchmarks --benchmark_filter=LocalOps --benchmark_repetitions=5
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
//
// (Interleaving spreads a shared machine's noise over all rows.)
// genmesh's operations check before they edit (can_flip_edge, link
// condition, ...) and split_edge places the new vertex at the midpoint;
// CGAL::Euler's do neither, so CGAL's collapse is timed with the
// does_satisfy_link_condition() call any caller needs, CGAL's flip on edges
// known to be flippable and with the checks written in CGAL, and CGAL's split
// bare and followed by the midpoint. Flips are timed in pairs (flip, flip
// back: the mesh is unchanged, so every flip stays valid). Splits and
// collapses change the mesh: each iteration starts from a fresh copy (copy not
// timed).
#include <genmesh/adaptors/cgal.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/local_operations.h>
#include <genmesh/soup_to_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using Surface_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
using Halfedge_mesh = genmesh::Halfedge_mesh<>;

// genmesh; CGAL::Euler as is; CGAL::Euler plus what genmesh's operation
// does beyond it, written with CGAL's own functions (what a careful CGAL
// caller does): the refusal checks before a flip, the midpoint after a split
// (CGAL::Euler::split_edge leaves the new point unset).
enum class Lib { genmesh, cgal, cgal_checked };

template <class G>
const G& base_mesh() {
  static const G g = [] {
    G m;
    genmesh::build_mesh(genmesh::make_icosphere(5), m);
    return m;
  }();
  return g;
}

// Edge indices in a fixed random order (same on every backend).
const std::vector<std::uint32_t>& edge_order() {
  static const std::vector<std::uint32_t> order = [] {
    const auto& g = base_mesh<Halfedge_mesh>();
    std::vector<std::uint32_t> v(g.n_edges());
    for (std::uint32_t i = 0; i < v.size(); ++i) v[i] = i;
    std::shuffle(v.begin(), v.end(), std::mt19937(42));
    return v;
  }();
  return order;
}

template <class G>
genmesh::halfedge_descriptor_t<G> hd(std::uint32_t e) {
  return genmesh::halfedge_descriptor_t<G>(2 * e);
}

template <class G, Lib lib>
void LocalOps_flip(benchmark::State& state) {
  G g = base_mesh<G>();
  std::vector<genmesh::halfedge_descriptor_t<G>> hs;
  for (auto e : edge_order())
    if (genmesh::can_flip_edge(hd<G>(e), g)) hs.push_back(hd<G>(e));
  for (auto _ : state) {
    for (const auto h : hs) {
      if constexpr (lib == Lib::genmesh) {
        benchmark::DoNotOptimize(genmesh::flip_edge(h, g));
        benchmark::DoNotOptimize(genmesh::flip_edge(h, g));
      } else if constexpr (lib == Lib::cgal) {
        CGAL::Euler::flip_edge(h, g);
        CGAL::Euler::flip_edge(h, g);
      } else {
        for (int k = 0; k < 2; ++k) {
          const auto oh = opposite(h, g);
          if (CGAL::is_border(h, g) || CGAL::is_border(oh, g) || !CGAL::is_triangle(h, g) ||
              !CGAL::is_triangle(oh, g))
            continue;
          const auto s2 = target(next(h, g), g), t2 = target(next(oh, g), g);
          if (s2 == t2 || halfedge(s2, t2, g).second) continue;
          if ((degree(source(h, g), g) < 4 && !CGAL::is_border(source(h, g), g)) ||
              (degree(target(h, g), g) < 4 && !CGAL::is_border(target(h, g), g)))
            continue;
          CGAL::Euler::flip_edge(h, g);
        }
      }
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(2 * hs.size()));
}

// In random edge order (cache-hostile) or in index order (as a pass over
// all edges, e.g. subdivision, makes it).
template <class G, Lib lib, bool random_order>
void LocalOps_split(benchmark::State& state) {
  std::vector<std::uint32_t> in_order(edge_order().size());
  for (std::uint32_t i = 0; i < in_order.size(); ++i) in_order[i] = i;
  const auto& order = random_order ? edge_order() : in_order;
  long n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    G g = base_mesh<G>();
    state.ResumeTiming();
    for (auto e : order) {
      if constexpr (lib == Lib::genmesh) {
        benchmark::DoNotOptimize(genmesh::split_edge(hd<G>(e), g));
      } else if constexpr (lib == Lib::cgal) {
        benchmark::DoNotOptimize(CGAL::Euler::split_edge(hd<G>(e), g));
      } else {
        const auto hnew = CGAL::Euler::split_edge(hd<G>(e), g);
        const auto& p = g.point(source(hnew, g));
        const auto& q = g.point(target(next(hnew, g), g));
        g.point(target(hnew, g)) = CGAL::midpoint(p, q);
      }
    }
    n += static_cast<long>(order.size());
    state.PauseTiming();
    g = G(); // destruction not timed
    state.ResumeTiming();
  }
  state.SetItemsProcessed(n);
}

template <class G, Lib lib>
void LocalOps_collapse(benchmark::State& state) {
  const auto& order = edge_order();
  long n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    G g = base_mesh<G>();
    state.ResumeTiming();
    // Half the edges: the mesh stays a mesh, most collapses succeed.
    for (std::size_t i = 0; i < order.size() / 2; ++i) {
      const genmesh::edge_descriptor_t<G> e(hd<G>(order[i]));
      if (g.is_removed(e)) continue;
      if constexpr (lib == Lib::genmesh) {
        n += genmesh::collapse_edge(e, g).has_value();
      } else {
        if (CGAL::Euler::does_satisfy_link_condition(e, g)) {
          CGAL::Euler::collapse_edge(e, g);
          ++n;
        }
      }
    }
    state.PauseTiming();
    g = G();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(n);
}

// Sum of vertex degrees, circulating around each vertex.
template <class G, Lib lib>
void LocalOps_circulate(benchmark::State& state) {
  const G& g = base_mesh<G>();
  for (auto _ : state) {
    std::size_t sum = 0;
    for (const auto v : vertices(g)) {
      if constexpr (lib == Lib::genmesh) {
        const auto start = halfedge(v, g);
        auto h = start;
        do {
          ++sum;
          h = opposite(next(h, g), g);
        } while (h != start);
      } else {
        for (const auto h : CGAL::halfedges_around_target(v, g)) {
          benchmark::DoNotOptimize(h);
          ++sum;
        }
      }
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(num_halfedges(g)));
}

} // namespace

BENCHMARK_TEMPLATE(LocalOps_flip, Halfedge_mesh, Lib::genmesh)->Name("LocalOps/flip/genmesh_Halfedge_mesh");
BENCHMARK_TEMPLATE(LocalOps_flip, Surface_mesh, Lib::genmesh)->Name("LocalOps/flip/genmesh_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_flip, Surface_mesh, Lib::cgal)->Name("LocalOps/flip/CGAL_Euler_unchecked_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_flip, Surface_mesh, Lib::cgal_checked)->Name("LocalOps/flip/CGAL_Euler_checked_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Halfedge_mesh, Lib::genmesh, true)->Name("LocalOps/split_random_order/genmesh_Halfedge_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Surface_mesh, Lib::genmesh, true)->Name("LocalOps/split_random_order/genmesh_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Surface_mesh, Lib::cgal, true)->Name("LocalOps/split_random_order/CGAL_Euler_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Surface_mesh, Lib::cgal_checked, true)->Name("LocalOps/split_random_order/CGAL_Euler_midpoint_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Halfedge_mesh, Lib::genmesh, false)->Name("LocalOps/split_in_order/genmesh_Halfedge_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Surface_mesh, Lib::genmesh, false)->Name("LocalOps/split_in_order/genmesh_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Surface_mesh, Lib::cgal, false)->Name("LocalOps/split_in_order/CGAL_Euler_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_split, Surface_mesh, Lib::cgal_checked, false)->Name("LocalOps/split_in_order/CGAL_Euler_midpoint_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_collapse, Halfedge_mesh, Lib::genmesh)->Name("LocalOps/collapse/genmesh_Halfedge_mesh");
BENCHMARK_TEMPLATE(LocalOps_collapse, Surface_mesh, Lib::genmesh)->Name("LocalOps/collapse/genmesh_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_collapse, Surface_mesh, Lib::cgal)->Name("LocalOps/collapse/CGAL_Euler_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_circulate, Halfedge_mesh, Lib::genmesh)->Name("LocalOps/circulate/genmesh_Halfedge_mesh");
BENCHMARK_TEMPLATE(LocalOps_circulate, Surface_mesh, Lib::genmesh)->Name("LocalOps/circulate/genmesh_Surface_mesh");
BENCHMARK_TEMPLATE(LocalOps_circulate, Surface_mesh, Lib::cgal)->Name("LocalOps/circulate/CGAL_Surface_mesh");
