// genmesh/visitor.h — the one visitor design of genmesh: observation,
// progress and attribute transport for every local operation and every
// algorithm.
//
// A visitor is a struct deriving from genmesh::Mutation_visitor that defines
// the hooks it needs (with concrete parameter types, or as templates); the
// others stay the base's no-ops and cost nothing. Every local operation
// (<genmesh/local_operations.h>) and every algorithm (subdivision,
// simplification, remeshing) takes it as its last argument, by reference, so
// the caller keeps its state:
//
//   struct Count_flips : genmesh::Mutation_visitor {
//     int n = 0;
//     void on_flip(genmesh::Halfedge_index, const genmesh::Halfedge_mesh<>&) { ++n; }
//   };
//   Count_flips c;
//   genmesh::flip_edge(h, mesh, c);
//   genmesh::loop_subdivision(mesh, {.iterations = 3}, c);   // same visitor type
//
// Two kinds of hooks:
// - per operation (on_flip, on_split_edge, before_collapse, ...): called once
//   after a successful change (or, for before_*, just before it, while the
//   elements about to disappear still exist); a refused operation calls none.
//   An algorithm calls them for the local operations it performs through
//   <genmesh/local_operations.h>; a backend's bulk path (e.g. subdivision's
//   in-place refinement of Halfedge_mesh) performs none and calls none.
//   on_vertex_mask is the per-vertex hook of subdivision (attribute transport);
//   on_vertex_moved follows a vertex move that changes no connectivity
//   (remeshing's smoothing and projection).
// - per algorithm: on_started(g) once before the algorithm changes g,
//   on_step(step, done, total) for progress (called with done = 0 before the
//   first unit of work and again after each unit, so the last call has done
//   == total; step names the unit, e.g. "level"), on_finished(g) once after
//   the last change (not called when the algorithm throws).
// Hooks receive the mesh as const: they observe and copy attributes (through
// property maps they hold), they never edit connectivity.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace genmesh {

/// No-op hooks for every local operation. Each hook is a template so that a
/// derived visitor may hide just the ones it needs.
struct Mutation_visitor {
  /// Once before the algorithm changes g.
  void on_started(const auto& /*g*/) {}
  /// Progress: `done` of `total` units named `step` ("level", ...) are done;
  /// called with done = 0 first and with done == total last.
  void on_step(std::string_view /*step*/, std::size_t /*done*/, std::size_t /*total*/) {}
  /// Once after the algorithm's last change to g.
  void on_finished(const auto& /*g*/) {}
  /// Subdivision: new vertex `vertex` of the level being refined (numbered in
  /// the refined mesh's vertex iteration order) is the affine combination,
  /// weights summing to 1, of the old vertices `sources` (numbered in the old
  /// mesh's vertex iteration order; a source may repeat: add its weights).
  /// Called for every vertex of the level, before its topology changes, in
  /// no promised order. Only computed when a visitor defines this hook.
  void on_vertex_mask(std::uint32_t /*vertex*/, std::span<const std::uint32_t> /*sources*/,
                      std::span<const double> /*weights*/) {}
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
  /// Simplification, before each collapse (before before_collapse): edge(h)
  /// collapses, source(h) disappears, target(h) survives and moves to
  /// `position` (an Eigen::Vector3d); `cost` is the policy's cost.
  void on_collapse_placement(const auto& /*h*/, const auto& /*position*/, double /*cost*/, const auto& /*g*/) {}
  /// After an algorithm moved vertex v without changing connectivity
  /// (remeshing's tangential smoothing and projection): v's point is new.
  /// Called once per vertex and move step, after the point is written.
  void on_vertex_moved(const auto& /*v*/, const auto& /*g*/) {}
  /// After an algorithm renumbered g (genmesh::renumber, <genmesh/renumbering.h>;
  /// remeshing does between rounds): maps.vertices[i], maps.edges[i],
  /// maps.faces[i] are the new indices of the elements that had index i
  /// (Renumbering_maps::null for removed ones). Descriptors held from before
  /// are stale; data kept by index follows these maps.
  void on_renumbered(const auto& /*maps*/, const auto& /*g*/) {}
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

/// Whether visitor type V defines its own on_vertex_mask (then subdivision
/// computes the masks; otherwise it skips that work).
template <class V>
inline constexpr bool visits_vertex_masks =
    !requires { requires std::is_same_v<decltype(&std::remove_cvref_t<V>::on_vertex_mask),
                                        void (Mutation_visitor::*)(std::uint32_t, std::span<const std::uint32_t>,
                                                                   std::span<const double>)>; };

} // namespace genmesh
