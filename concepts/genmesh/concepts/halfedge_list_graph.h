// genmesh/concepts/halfedge_list_graph.h — CGAL's HalfedgeListGraph.
//
// | expression        | returns                             | meaning                   |
// |-------------------|-------------------------------------|---------------------------|
// | halfedges(g)      | range (pair-like and begin()/end()) | live halfedges            |
// | num_halfedges(g)  | integral                            | number of live halfedges  |
#pragma once

#include <genmesh/concepts/halfedge_graph.h>

#include <concepts>

namespace genmesh {

/// A HalfedgeGraph whose live halfedges can be iterated and counted.
template <class G>
concept HalfedgeListGraph = HalfedgeGraph<G> && requires(const G& g) {
  { *halfedges(g).first } -> std::convertible_to<halfedge_descriptor_t<G>>;
  { *halfedges(g).begin() } -> std::convertible_to<halfedge_descriptor_t<G>>;
  halfedges(g).end();
  { num_halfedges(g) } -> std::integral;
};

} // namespace genmesh
