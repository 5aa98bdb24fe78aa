// genmesh/concepts/mutable_face_graph.h — CGAL's MutableFaceGraph.
//
// | expression                 | returns         | meaning                                    |
// |----------------------------|-----------------|--------------------------------------------|
// | add_face(g)                | face_descriptor | a new face with no halfedge yet            |
// | remove_face(f, g)          |                 | removes f (its halfedges become border)    |
// | set_face(h, f, g)          |                 | face(h, g) becomes f                       |
// | set_halfedge(f, h, g)      |                 | halfedge(f, g) becomes h                   |
// | reserve(g, nv, ne, nf)     |                 | capacity for nv vertices, ne edges, nf faces|
#pragma once

#include <genmesh/concepts/face_graph.h>
#include <genmesh/concepts/mutable_halfedge_graph.h>

#include <concepts>

namespace genmesh {

/// A FaceGraph and MutableHalfedgeGraph whose faces can be created, removed and set.
template <class G>
concept MutableFaceGraph = FaceGraph<G> && MutableHalfedgeGraph<G> &&
    requires(G& g, halfedge_descriptor_t<G> h, face_descriptor_t<G> f) {
      { add_face(g) } -> std::convertible_to<face_descriptor_t<G>>;
      remove_face(f, g);
      set_face(h, f, g);
      set_halfedge(f, h, g);
      reserve(g, 1, 1, 1);
    };

} // namespace genmesh
