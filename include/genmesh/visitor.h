// genmesh/visitor.h — the mutation visitor that rides along every local operation.
//
// Every local operation (<genmesh/local_operations.h>) takes an optional
// visitor and calls the matching hook once, after a successful change (or,
// for the before_* hooks, just before the change, while the elements that
// are about to disappear still exist). A refused operation calls no hook.
// Derive from Mutation_visitor and define the hooks you need with concrete
// descriptor types; the others stay no-ops and cost nothing:
//
//   struct Count_flips : genmesh::Mutation_visitor {
//     int n = 0;
//     void on_flip(genmesh::Halfedge_index, const genmesh::Halfedge_mesh<>&) { ++n; }
//   };
//   Count_flips c;
//   genmesh::flip_edge(h, mesh, c);
//
// Hooks receive the mesh as const: they observe and copy attributes (through
// property maps they hold), they never edit connectivity.
#pragma once

namespace genmesh {

/// No-op hooks for every local operation. Each hook is a template so that a
/// derived visitor may hide just the ones it needs.
struct Mutation_visitor {
  /// After flip_edge(h) and unflip_edge(h): h is the turned edge's halfedge.
  void on_flip(const auto& /*h*/, const auto& /*g*/) {}
  /// After split_edge(h) and split_edge_and_triangulate(h): hnew is the
  /// returned halfedge, target(hnew) the new vertex, next(hnew) == h.
  void on_split_edge(const auto& /*hnew*/, const auto& /*g*/) {}
  /// Before collapse_edge(e): h = halfedge(e); source(h) will disappear,
  /// target(h) survives.
  void before_collapse(const auto& /*h*/, const auto& /*g*/) {}
  /// After collapse_edge: v is the surviving vertex.
  void on_collapse(const auto& /*v*/, const auto& /*g*/) {}
  /// After split_face(h1, h2): h is the new halfedge (next(h1) == h); face(h)
  /// is the old face, face(opposite(h)) the new one.
  void on_split_face(const auto& /*h*/, const auto& /*g*/) {}
  /// Before join_face(h): face(opposite(h)) will disappear.
  void before_join_face(const auto& /*h*/, const auto& /*g*/) {}
  /// After add_center_vertex: target(h) is the new vertex.
  void on_add_center_vertex(const auto& /*h*/, const auto& /*g*/) {}
  /// Before remove_center_vertex(h): target(h) and its faces will disappear.
  void before_remove_center_vertex(const auto& /*h*/, const auto& /*g*/) {}
  /// After bevel_vertex: f is the new face where the vertex was.
  void on_bevel_vertex(const auto& /*f*/, const auto& /*g*/) {}
  /// After bevel_edge(h): face(hq) is the new face where the edge was (hq ==
  /// opposite(h), see bevel_edge).
  void on_bevel_edge(const auto& /*hq*/, const auto& /*g*/) {}
  /// After bevel_face: f is the inset face.
  void on_bevel_face(const auto& /*f*/, const auto& /*g*/) {}
  /// After add_face: f is the new face.
  void on_add_face(const auto& /*f*/, const auto& /*g*/) {}
  /// Before remove_face(h): face(h) will disappear.
  void before_remove_face(const auto& /*h*/, const auto& /*g*/) {}
};

} // namespace genmesh
