// genmesh/simplification.h — edge-collapse simplification of triangle meshes
// (Garland & Heckbert, "Surface simplification using quadric error metrics",
// SIGGRAPH 1997, the policies of <genmesh/simplification/quadric.h>, and
// Lindstrom & Turk's memoryless policy, <genmesh/simplification/lindstrom_turk.h>).
//
//   genmesh::simplify(mesh, {.target_ratio = 0.1});
//   genmesh::simplify(mesh, genmesh::Simplification_options<genmesh::Probabilistic_quadrics>{.target_faces = 5000});
//   genmesh::simplify(mesh, genmesh::Simplification_options<genmesh::Lindstrom_turk>{.target_ratio = 0.1});
//
// Repeatedly collapses the cheapest edge (collapse_edge, the local operation,
// so Incidence_mesh collapses natively) and puts the surviving vertex where
// the policy says, until a stop condition holds. Works on any mesh with the
// local operations, vertex points and vertex/edge/face index maps:
// genmesh::Halfedge_mesh, CGAL::Surface_mesh, genmesh::Incidence_mesh.
//
// Guarantees:
// - Every collapse satisfies the link condition (can_collapse_edge), so the
//   result is a valid manifold triangle mesh with the input's genus, border
//   loop count and components (a collapse that would change them is refused).
// - No face turns by more than .max_normal_deviation in one collapse and no
//   face is flipped or made degenerate (zero area) — ever.
// - Deterministic: the same input (same vertex and face order) and options
//   give the same mesh, bit for bit, on every backend. Costs are computed from
//   each face's corners in a canonical order (lowest vertex index first),
//   vertex quadrics are summed in face index order, and queue ties are broken
//   by the edge's sorted vertex-index pair.
// - The surviving vertex of a collapse of edge e is target(halfedge(e))
//   (the local operation's convention); its point is the policy's placement.
//   Removed elements stay removed-but-allocated on backends with garbage
//   (call collect_garbage to compact).
//
// Limits:
// - Triangles only (polygons are refused naming the face, or triangulated
//   first with .triangulate = true); non-manifold vertices and non-finite
//   points are refused naming the vertex.
// - With .prevent_self_intersections (the default), no collapse makes the
//   surface meet itself: the new faces are tested exactly against the faces
//   near them (a spatial hash of face boxes). Input that already intersects
//   itself keeps its intersections.
// - An edge refused by a geometric test leaves the queue and returns when a
//   collapse changes a vertex next to one of its ends (the test's inputs).
#pragma once

#include <genmesh/simplification/attribute_quadrics.h>
#include <genmesh/simplification/lindstrom_turk.h>
#include <genmesh/simplification/quadric.h>
#include <genmesh/visitor.h>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

namespace genmesh {

/// What happens at the mesh's borders.
enum class Border_mode {
  preserve, ///< border edges collapse along the border, held by boundary quadrics (planes through each border edge perpendicular to its face, weighted by .border_weight)
  lock,     ///< border vertices never move and are never removed
  free      ///< no special treatment (borders shrink and wander)
};

/// The order in which simplify() collapses edges.
enum class Schedule {
  /// Always the cheapest edge next: a mutable heap of every edge's cost,
  /// updated after each collapse (the classic order of Garland–Heckbert and
  /// CGAL).
  queue,
  /// In passes (meshoptimizer's design): each pass computes every live edge's
  /// cost once, takes the cheapest in cost order up to a budget (costs up to
  /// 1.5x the cost at the rank of a quarter of the collapses still needed),
  /// and collapses them, skipping an edge once a collapse of this pass changed
  /// one of its ends (for a memoryless policy or with feature lines: a
  /// vertex next to its ends). No heap: less memory, and the work is
  /// sequential; the order differs, so the result does too (as good by the
  /// Hausdorff oracle tests). Ties by the edge's vertex-index pair; the same
  /// mesh on every backend.
  passes
};

/// Why simplify() stopped.
enum class Stop_reason {
  target_faces,       ///< the face target (.target_faces or .target_ratio) was reached
  max_error,          ///< the next collapse would exceed .max_error
  no_collapse_left,   ///< every remaining edge is refused by the constraints
  target_already_met  ///< the mesh had no more faces than the target: nothing done
};

inline const char* to_string(Stop_reason r) {
  switch (r) {
  case Stop_reason::target_faces: return "target_faces";
  case Stop_reason::max_error: return "max_error";
  case Stop_reason::no_collapse_left: return "no_collapse_left";
  case Stop_reason::target_already_met: return "target_already_met";
  }
  return "unknown";
}

/// The options of simplify(). Stop conditions combine: the first one met wins.
/// With no target and no .max_error, simplify() collapses until no collapse
/// is left.
template <class Policy = Plane_quadrics>
struct Simplification_options {
  std::optional<std::size_t> target_faces = std::nullopt; ///< stop at or below this many faces
  std::optional<double> target_ratio = std::nullopt;///< stop at or below ratio × the input's faces, ratio in [0, 1]
  /// Stop before a collapse whose error (the square root of its cost: for
  /// plane quadrics a distance in model units) exceeds this.
  double max_error = std::numeric_limits<double>::infinity();
  bool max_error_relative = false; ///< .max_error is a fraction of the bounding-box diagonal
  Policy policy = {};              ///< cost and placement
  /// Largest turn of a face's normal in one collapse, degrees. Flipped or
  /// degenerate faces are refused whatever this is. Default: 45° for the
  /// quadric policies; 90° (flips only, as CGAL) for Lindstrom_turk, whose
  /// volume term already charges a fold (45° cost it up to 2x the Hausdorff
  /// distance of CGAL's LT at 2% of the elephant's faces; 90° matches CGAL's).
  double max_normal_deviation = detail::simplification::default_normal_deviation<Policy>;
  Border_mode border = Border_mode::preserve;
  double border_weight = 100.0; ///< boundary quadric weight (CGAL's GH discontinuity multiplier); quadric policies only
  bool triangulate = false;     ///< triangulate polygons first instead of refusing them
  bool check_input = true;      ///< refuse non-manifold vertices (an O(n) pass)
  /// Refuse a collapse whose new faces would meet another face of the
  /// surface (or each other) beyond the corners and edges they share: exact
  /// predicates (genmesh::faces_intersect) against the faces near each new
  /// face, found in a spatial hash of face boxes kept up to date.
  bool prevent_self_intersections = true;
  /// Smallest angle, degrees (at most 60), of a face a collapse changes; a
  /// face already worse may stay as bad but not get worse. 0: no limit.
  double min_angle = 0.0;
  /// Largest aspect ratio (circumradius / (2 · inradius), 1 for the
  /// equilateral triangle: genmesh::triangle_aspect_ratio) of a face a
  /// collapse changes; a face already worse may stay as bad but not get
  /// worse. 0: no limit.
  double max_aspect_ratio = 0.0;
  /// Largest valence the surviving vertex of a collapse may get. 0: no limit.
  std::size_t max_valence = 0;
  /// Feature lines: interior edges whose two faces' normals make at least
  /// this angle, degrees (genmesh::detect_sharp_edges). A collapse never
  /// crosses a feature line, only runs along it: a vertex on a line (two
  /// feature edges) moves only along its segments; line ends and corners
  /// (one, or three or more feature edges, or any at the border) never move.
  std::optional<double> feature_angle = std::nullopt;
  /// More feature edges (by edge index of the input mesh), read once before
  /// the first collapse; with .feature_angle, the union.
  std::function<bool(std::size_t edge_index)> edge_is_constrained = {};
  /// Vertices (by vertex index) that never move and never disappear.
  std::function<bool(std::size_t vertex_index)> is_locked = {};
  /// The collapse order (see Schedule): the cheapest edge each time, or passes.
  Schedule schedule = Schedule::queue;
};

/// What simplify() achieved.
struct Simplification_result {
  std::size_t collapses = 0;
  std::size_t vertices = 0, edges = 0, faces = 0; ///< live counts after
  double max_error = 0;                           ///< the largest error (sqrt of cost) of a collapse done
  Stop_reason stop_reason = Stop_reason::no_collapse_left;
  /// The self-intersection guard's exact triangle tests (faces_intersect):
  /// the candidate pairs its floating filters could not separate. A measure
  /// of the guard's cost, for tuning and tests; 0 without the guard.
  std::size_t exact_intersection_tests = 0;
};

} // namespace genmesh

#include <genmesh/simplification/detail/collapse.h>

namespace genmesh {

/// Simplifies g in place by edge collapses (see the top of this header).
/// Throws genmesh::invalid_input (g untouched) on a non-triangle face (unless
/// .triangulate), a non-finite point, a non-manifold vertex, or a target
/// ratio outside [0, 1].
///
/// The visitor (<genmesh/visitor.h>) sees on_started, then on_step("faces",
/// done, total) — faces removed of the faces to remove (all of them with no
/// target), every 16384 collapses, last with done == total whatever stopped
/// it — and on_finished; and for each collapse, in this order:
/// on_collapse_placement(h, position, cost, g) (edge(h) collapses,
/// source(h) disappears, target(h) survives at `position`, an
/// Eigen::Vector3d, at the policy's `cost`), before_collapse(h, g) and
/// on_collapse(target(h), g). The mesh's points are current in every hook
/// (on_collapse sees the survivor at its new point), so user data rides along.
template <detail::simplification::Simplifiable G, class Policy = Plane_quadrics, class Visitor = Mutation_visitor>
Simplification_result simplify(G& g, const Simplification_options<Policy>& options = {}, Visitor&& visitor = {}) {
  detail::simplification::Collapser<G, Policy, std::remove_reference_t<Visitor>> c(g, options, visitor);
  return c.run();
}

} // namespace genmesh
