// genmesh/concepts/vertex_list_graph.h — Boost's VertexListGraph, as CGAL uses it.
//
// | expression        | returns                          | meaning                    |
// |-------------------|----------------------------------|----------------------------|
// | vertices(g)       | range (pair-like, .first/.second, begin()/end()) | live vertices |
// | num_vertices(g)   | integral                         | number of live vertices    |
#pragma once

#include <genmesh/concepts/halfedge_graph.h>

#include <concepts>

namespace genmesh {

/// A graph whose live vertices can be iterated and counted.
template <class G>
concept VertexListGraph = requires(const G& g) {
  { *vertices(g).first } -> std::convertible_to<vertex_descriptor_t<G>>;
  { *vertices(g).begin() } -> std::convertible_to<vertex_descriptor_t<G>>;
  vertices(g).end();
  { num_vertices(g) } -> std::integral;
};

} // namespace genmesh
