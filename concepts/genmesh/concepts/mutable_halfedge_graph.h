// genmesh/concepts/mutable_halfedge_graph.h — CGAL's MutableHalfedgeGraph.
//
// | expression            | returns          | meaning                                       |
// |-----------------------|------------------|-----------------------------------------------|
// | add_vertex(g)         | vertex_descriptor| a new isolated vertex                         |
// | remove_vertex(v, g)   |                  | removes v (no halfedge may still target it)   |
// | add_edge(g)           | edge_descriptor  | a new edge; its halfedges are not yet linked  |
// | remove_edge(e, g)     |                  | removes e and its two halfedges               |
// | set_target(h, v, g)   |                  | target(h, g) becomes v                        |
// | set_next(h1, h2, g)   |                  | next(h1) = h2 and prev(h2) = h1               |
// | set_halfedge(v, h, g) |                  | halfedge(v, g) becomes h (target(h) must be v)|
//
// These are the low-level edits; algorithms use the local operations built on
// them (<genmesh/local_operations.h>), never these directly.
#pragma once

#include <genmesh/concepts/halfedge_graph.h>

#include <concepts>

namespace genmesh {

/// A HalfedgeGraph whose elements and links can be created, removed and set.
template <class G>
concept MutableHalfedgeGraph = HalfedgeGraph<G> &&
    requires(G& g, halfedge_descriptor_t<G> h, edge_descriptor_t<G> e, vertex_descriptor_t<G> v) {
      { add_vertex(g) } -> std::convertible_to<vertex_descriptor_t<G>>;
      remove_vertex(v, g);
      { add_edge(g) } -> std::convertible_to<edge_descriptor_t<G>>;
      remove_edge(e, g);
      set_target(h, v, g);
      set_next(h, h, g);
      set_halfedge(v, h, g);
    };

} // namespace genmesh
