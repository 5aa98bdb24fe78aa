// Incidence_mesh against Halfedge_mesh: traversal, local operations on a
// small and a large real mesh (per-operation time must not grow with the
// mesh: O(local degree)), and bytes per triangle.
//
//   genmesh_benchmarks --benchmark_filter=Incidence --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true
//
// Meshes: elephant.off (5558 triangles) and refined_elephant.off (88928
// triangles) from libcgal-demo. Both backends get the same edges in the same
// seeded order and, the operations being identical on both, do the same
// work. Operations are timed in pairs that restore the mesh's size, so every
// iteration works on a mesh of the same size: flip + flip (the edge goes
// back), split_edge_and_triangulate + collapse of the new edge back into the
// split vertex's neighbour, add_center_vertex + remove_center_vertex.
// Items per second count single operations (two per pair).
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/soup_to_mesh.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "heap_counter.h"

namespace {

using Inc = genmesh::Incidence_mesh<>;
using Hm = genmesh::Halfedge_mesh<>;
using genmesh::Edge_index;
using genmesh::Halfedge_index;

const genmesh::Polygon_soup& soup(int which) {
  static const genmesh::Polygon_soup small =
      genmesh::read_soup(std::string(GENMESH_DATA_DIR) + "/meshes/elephant.off");
  static const genmesh::Polygon_soup large =
      genmesh::read_soup(std::string(GENMESH_DATA_DIR) + "/meshes/refined_elephant.off");
  return which == 0 ? small : large;
}

template <class G>
const G& base(int which) {
  static const G meshes[2] = {[] {
                                G m;
                                genmesh::build_mesh(soup(0), m);
                                return m;
                              }(),
                              [] {
                                G m;
                                genmesh::build_mesh(soup(1), m);
                                return m;
                              }()};
  return meshes[which];
}

std::vector<std::uint32_t> shuffled_edges(std::size_t n) {
  std::vector<std::uint32_t> v(n);
  for (std::uint32_t i = 0; i < v.size(); ++i) v[i] = i;
  std::shuffle(v.begin(), v.end(), std::mt19937(7));
  return v;
}

// ---- traversal --------------------------------------------------------------
// range(0): 0 = the small mesh (its incidence rows fit in L2), 1 = the large
// mesh (they do not: every derived step can miss).

template <class G>
void BM_Incidence_next(benchmark::State& state) {
  const G& g = base<G>(static_cast<int>(state.range(0)));
  std::vector<Halfedge_index> hs(halfedges(g).begin(), halfedges(g).end());
  for (auto _ : state) {
    std::uint64_t acc = 0;
    for (Halfedge_index h : hs) acc += next(h, g).idx();
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * hs.size()));
}

template <class G>
void BM_Incidence_opposite_face(benchmark::State& state) {
  const G& g = base<G>(static_cast<int>(state.range(0)));
  std::vector<Halfedge_index> hs(halfedges(g).begin(), halfedges(g).end());
  for (auto _ : state) {
    std::uint64_t acc = 0;
    for (Halfedge_index h : hs) acc += face(opposite(h, g), g).idx();
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * hs.size()));
}

// Walks every element's cycle from start(x), h = step(h) until back at the
// start, adding up visit(h): items = steps.
void circulate(benchmark::State& state, const auto& elements, auto start_of, auto step, auto visit) {
  std::int64_t steps = 0;
  for (auto _ : state) {
    std::uint64_t acc = 0;
    for (auto x : elements) {
      const Halfedge_index start = start_of(x);
      Halfedge_index h = start;
      do {
        acc += visit(h);
        ++steps;
        h = step(h);
      } while (h != start);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(steps);
}

// Every vertex's ring (halfedge(v), then opposite(next(h))).
template <class G>
void BM_Incidence_around_vertex(benchmark::State& state) {
  const G& g = base<G>(static_cast<int>(state.range(0)));
  circulate(
      state, vertices(g), [&](auto v) { return halfedge(v, g); },
      [&](Halfedge_index h) { return opposite(next(h, g), g); }, [&](Halfedge_index h) { return source(h, g).idx(); });
}

// Every face's cycle (halfedge(f), then next).
template <class G>
void BM_Incidence_around_face(benchmark::State& state) {
  const G& g = base<G>(static_cast<int>(state.range(0)));
  circulate(
      state, faces(g), [&](auto f) { return halfedge(f, g); }, [&](Halfedge_index h) { return next(h, g); },
      [&](Halfedge_index h) { return target(h, g).idx(); });
}

// ---- local operations ---------------------------------------------------------
// range(0): 0 = the small mesh, 1 = the large mesh, 2 = the large mesh with
// the operations restricted to its first edges, as many as the small mesh
// has (a working set of the small mesh's size inside the large mesh: if an
// operation cost grew with the mesh, 2 would be slower than 0; if 1 is
// slower than 0 and 2 is not, the difference is cache misses).

// The edges an operation draws from, in a fixed random order.
template <class G>
std::vector<std::uint32_t> edges_for(const G& g, std::int64_t mode) {
  return shuffled_edges(mode == 2 ? base<G>(0).edges_size() : g.edges_size());
}

template <class G>
G& mesh_for(std::int64_t mode) {
  static thread_local G copy;
  copy = base<G>(mode == 0 ? 0 : 1);
  return copy;
}

// Times pair(g, e) over the edges in order: two operations at edge e that
// restore the mesh's size, true when both applied. Items = operations.
template <class G>
void time_pairs(benchmark::State& state, auto pair) {
  G& g = mesh_for<G>(state.range(0));
  const auto order = edges_for(g, state.range(0));
  std::size_t i = 0, done = 0;
  for (auto _ : state)
    if (pair(g, order[i++ % order.size()])) ++done;
  state.SetItemsProcessed(static_cast<std::int64_t>(2 * done));
}

template <class G>
void BM_Incidence_flip_pair(benchmark::State& state) {
  time_pairs<G>(state, [](G& g, std::uint32_t e) {
    const Halfedge_index h(2 * e);
    if (!genmesh::flip_edge(h, g)) return false;
    genmesh::flip_edge(h, g); // the edge goes back
    return true;
  });
}

template <class G>
void BM_Incidence_split_collapse_pair(benchmark::State& state) {
  time_pairs<G>(state, [](G& g, std::uint32_t e) {
    if (e >= g.edges_size() || g.is_removed(Edge_index(e))) return false;
    const auto hnew = genmesh::split_edge_and_triangulate(Halfedge_index(2 * e), g);
    // hnew: u → w; collapsing w into u restores the mesh's size.
    return hnew && genmesh::collapse_edge(Edge_index(g.opposite(*hnew)), g).has_value();
  });
}

template <class G>
void BM_Incidence_center_vertex_pair(benchmark::State& state) {
  time_pairs<G>(state, [](G& g, std::uint32_t e) {
    const auto hnew = genmesh::add_center_vertex(Halfedge_index(2 * e), g);
    return hnew && genmesh::remove_center_vertex(*hnew, g).has_value();
  });
}

// ---- memory -----------------------------------------------------------------

template <class G>
void BM_Incidence_bytes_per_triangle(benchmark::State& state) {
  const genmesh::Polygon_soup& s = soup(1);
  long long held = 0;
  std::size_t reported = 0;
  for (auto _ : state) {
    const long long before = genmesh_bench::live_bytes();
    {
      G mesh;
      genmesh::build_mesh(s, mesh);
      held = genmesh_bench::live_bytes() - before;
      reported = mesh.memory_bytes();
      benchmark::DoNotOptimize(mesh);
    }
  }
  // The heap counter sees operator new only; Eigen allocates a sparse
  // matrix's outer index and non-zero counts with std::malloc, so
  // memory_bytes() (every array's capacity) is the complete figure.
  state.counters["bytes_per_triangle"] = double(held) / double(s.num_faces());
  state.counters["memory_bytes_per_triangle"] = double(reported) / double(s.num_faces());
}

#define GENMESH_INCIDENCE_BENCH(fn, name)                                                \
  BENCHMARK_TEMPLATE(fn, Inc)->Name("Incidence/" name "/Incidence_mesh")->Arg(0)->Arg(1); \
  BENCHMARK_TEMPLATE(fn, Hm)->Name("Incidence/" name "/Halfedge_mesh")->Arg(0)->Arg(1);
GENMESH_INCIDENCE_BENCH(BM_Incidence_next, "traversal_next")
GENMESH_INCIDENCE_BENCH(BM_Incidence_opposite_face, "traversal_opposite_face")
GENMESH_INCIDENCE_BENCH(BM_Incidence_around_vertex, "traversal_around_vertex")
GENMESH_INCIDENCE_BENCH(BM_Incidence_around_face, "traversal_around_face")
#undef GENMESH_INCIDENCE_BENCH

#define GENMESH_INCIDENCE_OP_BENCH(fn, name)                                                      \
  BENCHMARK_TEMPLATE(fn, Inc)->Name("Incidence/" name "/Incidence_mesh")->Arg(0)->Arg(1)->Arg(2); \
  BENCHMARK_TEMPLATE(fn, Hm)->Name("Incidence/" name "/Halfedge_mesh")->Arg(0)->Arg(1)->Arg(2);
GENMESH_INCIDENCE_OP_BENCH(BM_Incidence_flip_pair, "flip_pair")
GENMESH_INCIDENCE_OP_BENCH(BM_Incidence_split_collapse_pair, "split_and_triangulate_collapse_pair")
GENMESH_INCIDENCE_OP_BENCH(BM_Incidence_center_vertex_pair, "add_remove_center_vertex_pair")
#undef GENMESH_INCIDENCE_OP_BENCH

BENCHMARK_TEMPLATE(BM_Incidence_bytes_per_triangle, Inc)
    ->Name("Incidence/bytes_per_triangle/Incidence_mesh")->Iterations(1);
BENCHMARK_TEMPLATE(BM_Incidence_bytes_per_triangle, Hm)
    ->Name("Incidence/bytes_per_triangle/Halfedge_mesh")->Iterations(1);

} // namespace
