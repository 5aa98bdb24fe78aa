// genmesh/concepts/local_operations.h — LocalOperations: the mutation vocabulary.
//
// What simplification, remeshing and subdivision call to change a mesh — and
// all they may call (DESIGN.md: algorithms never edit links). A graph models
// LocalOperations when every expression below is valid through the genmesh::
// customization point objects of <genmesh/local_operations.h>, with h, h1,
// h2 halfedge descriptors, e an edge descriptor, f a face descriptor, vs a
// range of vertex descriptors; each operation also takes a trailing visitor
// (<genmesh/visitor.h>):
//
// | expression                              | returns            | meaning (contract in local_operations.h)      |
// |-----------------------------------------|--------------------|-----------------------------------------------|
// | can_flip_edge(h, g) / flip_edge(h, g)   | bool / optional<H> | turn the edge of h inside its two triangles   |
// | can_split_edge(h, g) / split_edge(h, g) | bool / optional<H> | new vertex on the edge (at the midpoint)      |
// | can_split_edge_and_triangulate(h, g)    | bool               |                                               |
// | split_edge_and_triangulate(h, g)        | optional<H>        | split, then cut the new vertex's faces        |
// | does_satisfy_link_condition(e, g)       | bool               | the link condition of Dey et al.              |
// | can_collapse_edge(e, g)                 | bool               | link condition and no face made degenerate    |
// | collapse_edge(e, g)                     | optional<V>        | merge the ends; the surviving vertex          |
// | can_split_face(h1, h2, g)               | bool               |                                               |
// | split_face(h1, h2, g)                   | optional<H>        | new edge target(h1) → target(h2) in the face  |
// | can_join_face(h, g) / join_face(h, g)   | bool / optional<H> | remove the edge of h, merging its faces       |
// | can_add_center_vertex(h, g)             | bool               |                                               |
// | add_center_vertex(h, g)                 | optional<H>        | fan the face of h around a new vertex         |
// | can_triangulate_face(f, g)              | bool               |                                               |
// | triangulate_face(f, g)                  | bool               | cut f into triangles                          |
// | euler::can_add_face(vs, g)              | bool               |                                               |
// | euler::add_face(vs, g)                  | optional<F>        | a new face on existing vertices               |
// | euler::can_remove_face(h, g)            | bool               |                                               |
// | euler::remove_face(h, g)                | bool               | remove the face of h (and what it leaves bare)|
//
// A refused operation returns an empty optional (or false) and leaves the
// mesh untouched; g is a const G& for the predicates.
//
// How the concept refers to the operations, and why it needs nothing above
// this floor: each customization point object dispatches, per call, to the
// backend's genmesh_native_<op> when argument-dependent lookup finds one, and
// otherwise to the one generic implementation, which is written with
// set_next/set_target/set_face/... and so requires a MutableFaceGraph (and,
// for triangulate_face, a vertex index map). The concept states that rule
// itself instead of including <genmesh/local_operations.h> (which stands on
// the floor above, with the visitor and the geometry): G models
// LocalOperations if it is such a MutableFaceGraph, or if it provides every
// genmesh_native_<op> above with the documented result type. A backend thus
// qualifies by what it provides, and the concept stays in concepts/ with the
// others. tests/test_layer.cpp checks, for every model, that the
// customization point objects themselves accept every expression, so the
// rule stated here and the dispatch in local_operations.h cannot drift
// apart unnoticed.
//
// The bulk "append these elements" operation of the in-place subdivision,
// genmesh_native_append_elements(g, nv, ne, nf), is not part of this table:
// it appends elements with null connectivity for set_next & co. to link, so
// it only means something on the MutableFaceGraph branch, where it is an
// optional speed-up with a generic fallback
// (<genmesh/subdivision/detail/in_place.h>; native on Halfedge_mesh and
// CGAL::Surface_mesh). A backend without set_next refines through the
// native operations above, or, when it provides genmesh_native_relink(g,
// nv, ends, offsets, sides) (the same bulk append in incidence form: every
// edge's ends and every face's side cycle; native on Incidence_mesh), takes a
// whole level in that one call; also optional, outside this table.
#pragma once

#include <genmesh/concepts/descriptor.h>
#include <genmesh/concepts/edge_list_graph.h>
#include <genmesh/concepts/face_list_graph.h>
#include <genmesh/concepts/halfedge_list_graph.h>
#include <genmesh/concepts/mutable_face_graph.h>
#include <genmesh/concepts/vertex_list_graph.h>
#include <genmesh/property_maps.h>

#include <concepts>
#include <optional>
#include <vector>

namespace genmesh {

/// A backend that provides every local operation natively (found by ADL),
/// with the generic operations' result types.
template <class G>
concept NativeLocalOperations =
    requires(G& g, const G& cg, halfedge_descriptor_t<G> h, edge_descriptor_t<G> e, face_descriptor_t<G> f,
             const std::vector<vertex_descriptor_t<G>>& vs) {
      { genmesh_native_can_flip_edge(h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_flip_edge(h, g) } -> std::same_as<std::optional<halfedge_descriptor_t<G>>>;
      { genmesh_native_can_split_edge(h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_split_edge(h, g) } -> std::same_as<std::optional<halfedge_descriptor_t<G>>>;
      { genmesh_native_can_split_edge_and_triangulate(h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_split_edge_and_triangulate(h, g) } -> std::same_as<std::optional<halfedge_descriptor_t<G>>>;
      { genmesh_native_does_satisfy_link_condition(e, cg) } -> std::convertible_to<bool>;
      { genmesh_native_can_collapse_edge(e, cg) } -> std::convertible_to<bool>;
      { genmesh_native_collapse_edge(e, g) } -> std::same_as<std::optional<vertex_descriptor_t<G>>>;
      { genmesh_native_can_split_face(h, h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_split_face(h, h, g) } -> std::same_as<std::optional<halfedge_descriptor_t<G>>>;
      { genmesh_native_can_join_face(h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_join_face(h, g) } -> std::same_as<std::optional<halfedge_descriptor_t<G>>>;
      { genmesh_native_can_add_center_vertex(h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_add_center_vertex(h, g) } -> std::same_as<std::optional<halfedge_descriptor_t<G>>>;
      { genmesh_native_can_triangulate_face(f, cg) } -> std::convertible_to<bool>;
      { genmesh_native_triangulate_face(f, g) } -> std::convertible_to<bool>;
      { genmesh_native_can_add_face(vs, cg) } -> std::convertible_to<bool>;
      { genmesh_native_add_face(vs, g) } -> std::same_as<std::optional<face_descriptor_t<G>>>;
      { genmesh_native_can_remove_face(h, cg) } -> std::convertible_to<bool>;
      { genmesh_native_remove_face(h, g) } -> std::convertible_to<bool>;
    };

/// A mesh that algorithms can change through the local operations: a
/// halfedge mesh with live-element ranges whose operations are either the
/// generic ones (a MutableFaceGraph with a vertex index map) or its own.
template <class G>
concept LocalOperations =
    HalfedgeListGraph<G> && VertexListGraph<G> && EdgeListGraph<G> && FaceListGraph<G> &&
    ((MutableFaceGraph<G> && HasIndexMap<G, vertex_index_t>) || NativeLocalOperations<G>);

} // namespace genmesh
