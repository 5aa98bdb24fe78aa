// genmesh/concepts/face_graph.h — CGAL's FaceGraph as a C++20 concept.
//
// | expression                   | returns             | meaning                           |
// |------------------------------|---------------------|-----------------------------------|
// | face(h, g)                   | face_descriptor     | the face left of h, or null_face() on the border |
// | halfedge(f, g)               | halfedge_descriptor | a halfedge h with face(h, g) == f |
// | degree(f, g)                 | integral            | number of halfedges around f      |
// | graph_traits<G>::null_face() | face_descriptor     | the border "face"                 |
#pragma once

#include <genmesh/concepts/halfedge_graph.h>

#include <concepts>

namespace genmesh {

/// A HalfedgeGraph whose halfedge cycles bound faces.
template <class G>
concept FaceGraph = HalfedgeGraph<G> && requires {
  typename boost::graph_traits<G>::face_descriptor;
} && Descriptor<face_descriptor_t<G>> &&
    requires(const G& g, halfedge_descriptor_t<G> h, face_descriptor_t<G> f) {
      { boost::graph_traits<G>::null_face() } -> std::convertible_to<face_descriptor_t<G>>;
      { face(h, g) } -> std::convertible_to<face_descriptor_t<G>>;
      { halfedge(f, g) } -> std::convertible_to<halfedge_descriptor_t<G>>;
    };

} // namespace genmesh
