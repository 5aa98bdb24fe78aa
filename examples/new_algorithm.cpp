// Writing a new algorithm on genmesh's shared layer (docs/concepts.md, "The
// layer under every algorithm"): split the longest edges until none is longer
// than a bound. It stands only on the layer — the LocalOperations concept in
// its requires-clause, a scratch property that grows while it adds vertices,
// the mutable priority queue, a visitor — and so runs unchanged on every
// backend; main() runs it on Halfedge_mesh and Incidence_mesh and checks that
// both give the same mesh.
#include <genmesh/concepts.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/local_operations.h>
#include <genmesh/priority_queue.h>
#include <genmesh/properties.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>
#include <genmesh/visitor.h>

#include <cstddef>
#include <functional>
#include <iostream>
#include <vector>

namespace example {

struct Split_result {
  std::size_t splits = 0;     ///< edges split
  std::size_t new_vertices = 0;  ///< vertices marked new by the scratch property
};

/// Splits the longest edge (ties: lowest edge index) while it is longer than
/// max_length, triangulating around each new vertex. Terminates: every split
/// halves an edge, so at most (longest / max_length) levels of splits happen.
template <genmesh::LocalOperations G, class Visitor = genmesh::Mutation_visitor>
  requires genmesh::HasVertexPoints<G> && genmesh::HasIndexMap<G, genmesh::edge_index_t> &&
           genmesh::HasIndexMap<G, genmesh::vertex_index_t>
Split_result split_long_edges(G& g, double max_length, Visitor&& visitor = {}) {
  using E = genmesh::edge_descriptor_t<G>;
  using H = genmesh::halfedge_descriptor_t<G>;
  using V = genmesh::vertex_descriptor_t<G>;
  const auto points = get(genmesh::vertex_point, g);
  const auto edge_index = get(genmesh::edge_index, g);
  const auto length = [&](E e) {
    const H h = halfedge(e, g);
    using P = genmesh::point_t<G>;
    return (genmesh::to_eigen(P(get(points, source(h, g)))) - genmesh::to_eigen(P(get(points, target(h, g))))).norm();
  };

  // Scratch data for the algorithm's duration; it keeps working for the
  // vertices the splits add.
  auto is_new = genmesh::scratch_property<bool>(genmesh::vertex_index, g, false);

  // Longest first: the queue's Compare is std::greater. Keys are edge
  // indices; edge_at maps them back to descriptors.
  genmesh::Mutable_priority_queue<double, std::greater<double>> queue(index_bound(genmesh::edge_index, g));
  std::vector<E> edge_at;
  const auto enqueue = [&](E e) {
    const std::size_t k = get(edge_index, e);
    if (k >= edge_at.size()) edge_at.resize(k + 1);
    edge_at[k] = e;
    const double l = length(e);
    if (l > max_length) queue.update(k, l);
    else queue.erase(k);
  };
  for (E e : edges(g)) enqueue(e);

  Split_result result;
  while (!queue.empty()) {
    const E e = edge_at[queue.pop()];
    const auto hnew = genmesh::split_edge_and_triangulate(halfedge(e, g), g, visitor);
    if (!hnew) continue;  // refused: leave the edge as it is
    ++result.splits;
    const V v = target(*hnew, g);
    is_new[v] = true;
    // Every edge at the new vertex is new or shorter: (re)queue them.
    H x = *hnew;
    do {
      enqueue(edge(x, g));
      x = opposite(next(x, g), g);
    } while (x != *hnew);
  }
  for (V v : vertices(g)) result.new_vertices += is_new[v] ? 1 : 0;
  return result;
}

} // namespace example

// A visitor that counts: algorithms pass it to every local operation.
struct Count_splits : genmesh::Mutation_visitor {
  std::size_t n = 0;
  void on_split_edge(const auto&, const auto&) { ++n; }
};

template <class G>
bool run(const char* name, genmesh::Polygon_soup& out) {
  G g;
  genmesh::build_mesh(genmesh::make_icosphere(1), g);
  Count_splits counter;
  const example::Split_result r = example::split_long_edges(g, 0.3, counter);
  const genmesh::Mesh_report report = genmesh::check_mesh(g);
  out = genmesh::to_soup(g);
  std::cout << name << ": " << r.splits << " splits, " << r.new_vertices << " new vertices, "
            << out.num_faces() << " faces" << (report.valid ? ", valid\n" : ", INVALID\n");
  return report.valid && r.splits > 0 && r.splits == counter.n && r.new_vertices == r.splits;
}

int main() {
  genmesh::Polygon_soup a, b;
  const bool ok = run<genmesh::Halfedge_mesh<>>("Halfedge_mesh", a) && run<genmesh::Incidence_mesh<>>("Incidence_mesh", b);
  const bool same = a.points == b.points && a.indices == b.indices && a.offsets == b.offsets;
  std::cout << (same ? "same mesh on both backends\n" : "DIFFERENT meshes\n");
  return ok && same ? 0 : 1;
}
