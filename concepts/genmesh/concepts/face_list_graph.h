// genmesh/concepts/face_list_graph.h — CGAL's FaceListGraph.
//
// | expression    | returns                             | meaning              |
// |---------------|-------------------------------------|----------------------|
// | faces(g)      | range (pair-like and begin()/end()) | live faces           |
// | num_faces(g)  | integral                            | number of live faces |
#pragma once

#include <genmesh/concepts/face_graph.h>

#include <concepts>

namespace genmesh {

/// A FaceGraph whose live faces can be iterated and counted.
template <class G>
concept FaceListGraph = FaceGraph<G> && requires(const G& g) {
  { *faces(g).first } -> std::convertible_to<face_descriptor_t<G>>;
  { *faces(g).begin() } -> std::convertible_to<face_descriptor_t<G>>;
  faces(g).end();
  { num_faces(g) } -> std::integral;
};

} // namespace genmesh
