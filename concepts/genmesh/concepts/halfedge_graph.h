// genmesh/concepts/halfedge_graph.h — CGAL's HalfedgeGraph as a C++20 concept.
//
// | expression          | returns               | meaning                                   |
// |---------------------|-----------------------|-------------------------------------------|
// | edge(h, g)          | edge_descriptor       | the edge of h                             |
// | halfedge(e, g)      | halfedge_descriptor   | one of e's two halfedges                  |
// | halfedge(v, g)      | halfedge_descriptor   | a halfedge with target v (null if isolated)|
// | halfedge(u, v, g)   | pair<halfedge, bool>  | the halfedge u→v, if it exists            |
// | opposite(h, g)      | halfedge_descriptor   | the other halfedge of edge(h, g)          |
// | source(h, g)        | vertex_descriptor     | target(opposite(h, g), g)                 |
// | target(h, g)        | vertex_descriptor     | the vertex h points to                    |
// | next(h, g)          | halfedge_descriptor   | next halfedge around face(h, g) (or border)|
// | prev(h, g)          | halfedge_descriptor   | previous halfedge around the same cycle   |
// | graph_traits<G>::null_halfedge() | halfedge_descriptor | the invalid halfedge           |
//
// The conventions (target-based halfedge(v,g), live counts vs index bounds,
// ordered hashable descriptors) are written once in descriptor.h.
#pragma once

#include <genmesh/concepts/descriptor.h>

#include <boost/graph/graph_traits.hpp>

#include <concepts>

namespace genmesh {

template <class G>
using vertex_descriptor_t = typename boost::graph_traits<G>::vertex_descriptor;
template <class G>
using halfedge_descriptor_t = typename boost::graph_traits<G>::halfedge_descriptor;
template <class G>
using edge_descriptor_t = typename boost::graph_traits<G>::edge_descriptor;
template <class G>
using face_descriptor_t = typename boost::graph_traits<G>::face_descriptor;

/// CGAL's HalfedgeGraph: vertices and edges, each edge two opposite halfedges
/// linked into cycles by next/prev.
template <class G>
concept HalfedgeGraph = requires {
  typename boost::graph_traits<G>::vertex_descriptor;
  typename boost::graph_traits<G>::edge_descriptor;
  typename boost::graph_traits<G>::halfedge_descriptor;
} && Descriptor<vertex_descriptor_t<G>> && Descriptor<halfedge_descriptor_t<G>> &&
    Descriptor<edge_descriptor_t<G>> &&
    requires(const G& g, halfedge_descriptor_t<G> h, edge_descriptor_t<G> e,
             vertex_descriptor_t<G> v) {
      { boost::graph_traits<G>::null_halfedge() } -> std::convertible_to<halfedge_descriptor_t<G>>;
      { boost::graph_traits<G>::null_vertex() } -> std::convertible_to<vertex_descriptor_t<G>>;
      { edge(h, g) } -> std::convertible_to<edge_descriptor_t<G>>;
      { halfedge(e, g) } -> std::convertible_to<halfedge_descriptor_t<G>>;
      { halfedge(v, g) } -> std::convertible_to<halfedge_descriptor_t<G>>;
      { halfedge(v, v, g).first } -> std::convertible_to<halfedge_descriptor_t<G>>;
      { halfedge(v, v, g).second } -> std::convertible_to<bool>;
      { opposite(h, g) } -> std::convertible_to<halfedge_descriptor_t<G>>;
      { source(h, g) } -> std::convertible_to<vertex_descriptor_t<G>>;
      { target(h, g) } -> std::convertible_to<vertex_descriptor_t<G>>;
      { next(h, g) } -> std::convertible_to<halfedge_descriptor_t<G>>;
      { prev(h, g) } -> std::convertible_to<halfedge_descriptor_t<G>>;
    };

} // namespace genmesh
