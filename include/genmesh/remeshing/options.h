// genmesh/remeshing/options.h — the options and result of isotropic_remeshing
// and of its steps (split_long_edges, collapse_short_edges, equalize_valences,
// make_delaunay, tangential_relaxation), which all take the same options.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace genmesh {

/// How tangential_relaxation moves a free vertex, always within its tangent
/// plane: area_weighted goes to the point that minimizes the sum of the
/// squared areas of its triangles (pmp-library's rule; where that 3x3 system
/// is singular, the area-weighted centroid of its triangles); uniform to the
/// mean of its neighbours; none does not move it.
enum class Smoothing { area_weighted, uniform, none };

/// What the flip step optimizes: valences towards 6 (4 on the border), or
/// every edge locally Delaunay (opposite angles sum to at most π).
enum class Flips { valence, delaunay };

/// What happens to constrained edges (borders, feature edges, user
/// constrained edges): split and collapsed along their own polyline with
/// corners fixed (resample), or left exactly as they are (protect). Either
/// way they are never flipped, never collapsed across, and their vertices
/// never leave the polyline.
enum class Constraints { resample, protect };

/// Faces that are not triangles: triangulated first (genmesh::triangulate_faces)
/// or refused (invalid_input naming the first one).
enum class Polygons { triangulate, refuse };

/// Curvature-adapted sizing (pmp-library's adaptive remeshing): each input
/// vertex gets the length whose equilateral triangles deviate at most
/// approximation_error from a sphere of the vertex's largest principal
/// curvature κ (vertex_curvature, <genmesh/geometry.h>; smoothed twice over
/// the neighbours): √(6e/κ − 3e²), clamped to [min_length, max_length]
/// (flat: max_length). An edge's target is the mean of its ends'; a split's
/// new vertex takes the mean of its ends', a projected vertex the value
/// interpolated on the input triangle it lands on. Lengths in the mesh's units.
struct Adaptive_sizing {
  double min_length = 0;
  double max_length = 0;
  double approximation_error = 0;
};

/// Options of isotropic_remeshing() and its steps.
struct Remeshing_options {
  /// The target edge length L (absolute). Unset: relative_edge_length times
  /// the input's mean edge length. Zero, negative, infinite or NaN is refused.
  std::optional<double> target_edge_length = std::nullopt;
  /// L as a multiple of the input's mean edge length (used when
  /// target_edge_length is unset). Must be finite and positive.
  double relative_edge_length = 1.0;
  /// Rounds of split, collapse, flip, smooth, project (≥ 0).
  int iterations = 5;
  /// Tangential smoothing rule, steps per round and step size (0, 1].
  /// isotropic_remeshing smooths smoothing_steps steps in its last round and
  /// half as many (rounded up) in the rounds before.
  Smoothing smoothing = Smoothing::area_weighted;
  int smoothing_steps = 4;
  double smoothing_step_size = 1.0;
  /// Project every moved vertex back onto the input surface after each round.
  bool projection = true;
  /// The flip rule.
  Flips flips = Flips::valence;
  /// Edges whose faces' normals make an angle of at least this many degrees
  /// are features (constrained), as detect_sharp_edges (<genmesh/features.h>)
  /// finds them; 0 or less: no detection.
  double feature_angle = 0;
  /// User constrained edges, by edge index (get(edge_index, g)); empty: none.
  /// Shorter than the index bound: the missing ones are not constrained.
  std::vector<char> constrained_edges = {};
  /// Borders, features and constrained edges: resample or protect.
  Constraints constraints = Constraints::resample;
  /// Remesh only these faces (by face index); empty: every face. The patch's
  /// border acts as a constraint, the faces outside stay as they are.
  std::vector<char> faces = {};
  /// Curvature-adapted sizing instead of the uniform length L (then
  /// target_edge_length and relative_edge_length are not used).
  std::optional<Adaptive_sizing> adaptive = std::nullopt;
  /// Faces that are not triangles.
  Polygons polygons = Polygons::triangulate;
  /// Renumber g in a spatial order after a step that changed much (the
  /// first round's splits and collapses), so that the steps after read
  /// neighbours near each other in memory (armadillo: 3–25 % less time in
  /// same-run pairs, docs/benchmarks.md "Isotropic remeshing, session 7").
  /// Surviving elements then change indices during the call (the visitor's
  /// on_renumbered(maps, g) gives old -> new). Halfedge_mesh and
  /// Incidence_mesh carry every property along and drop their garbage;
  /// other meshes (CGAL::Surface_mesh, Polyhedron_3, OpenMesh) carry only
  /// connectivity and points, so their other per-element properties would
  /// stay with the slot: hence off by default. The same option gives the
  /// same mesh on every backend; on and off give different meshes (ties
  /// follow the numbering).
  bool renumber = false;
};

/// What isotropic_remeshing() did.
struct Remeshing_result {
  int iterations = 0;          ///< rounds done
  std::size_t splits = 0;      ///< edge splits
  std::size_t collapses = 0;   ///< edge collapses
  std::size_t flips = 0;       ///< edge flips
  std::size_t vertices = 0;    ///< live vertices at the end
  std::size_t faces = 0;       ///< live faces at the end
  double target_edge_length = 0; ///< L used (adaptive: max_length)
};

} // namespace genmesh
