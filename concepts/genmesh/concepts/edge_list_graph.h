// genmesh/concepts/edge_list_graph.h — Boost's EdgeListGraph, as CGAL uses it.
//
// | expression     | returns                          | meaning                  |
// |----------------|----------------------------------|--------------------------|
// | edges(g)       | range (pair-like and begin()/end()) | live edges            |
// | num_edges(g)   | integral                         | number of live edges     |
#pragma once

#include <genmesh/concepts/halfedge_graph.h>

#include <concepts>

namespace genmesh {

/// A graph whose live edges can be iterated and counted.
template <class G>
concept EdgeListGraph = requires(const G& g) {
  { *edges(g).first } -> std::convertible_to<edge_descriptor_t<G>>;
  { *edges(g).begin() } -> std::convertible_to<edge_descriptor_t<G>>;
  edges(g).end();
  { num_edges(g) } -> std::integral;
};

} // namespace genmesh
