// genmesh/remeshing.h — isotropic remeshing of triangle meshes.
//
// isotropic_remeshing(g, {options}) repeats, options.iterations times, the
// loop of Botsch & Kobbelt ("A remeshing approach to multiresolution
// modeling", SGP 2004): split every edge longer than 4/3 L at its midpoint;
// collapse every edge shorter than 4/5 L where no edge longer than 4/3 L
// appears and no triangle turns over; flip edges to bring valences towards 6
// (4 on the border) — or, with Flips::delaunay, until every free edge is
// locally Delaunay; move the free vertices tangentially (area-weighted
// centroid, or uniform; half the steps in every round but the last);
// project them back onto the input surface; flip away triangles below 36°.
// After the last round, a clean-up moves the free corners of triangles still
// below 36° along the surface where that raises their ring's smallest angle.
// Each step is usable alone: <genmesh/remeshing/split_long_edges.h>,
// collapse_short_edges.h, equalize_valences.h, make_delaunay.h,
// tangential_relaxation.h.
//
// Guarantees:
// - Refusals before any change (genmesh::invalid_input naming the element):
//   a target length that is zero, negative, infinite or NaN; a non-manifold
//   vertex; an edge without faces; a polygon with Polygons::refuse (with
//   Polygons::triangulate, the default, polygons are triangulated first).
// - Every step keeps a valid manifold triangle mesh: it changes g only
//   through the checked local operations (split_edge_and_triangulate,
//   collapse_edge with the link condition, flip_edge). Borders keep their
//   loops; genus and components are kept.
// - Constrained edges (the border, feature edges above .feature_angle,
//   .constrained_edges, the border of a .faces patch) are never flipped or
//   collapsed across, their vertices never leave them; with
//   Constraints::resample (default) they are split at midpoints and
//   collapsed along themselves with corners (vertices with 1 or 3+
//   constrained edges) fixed; with Constraints::protect they are untouched.
// - Projection: each round ends by moving every vertex that may move to a
//   closest point of a copy of the input (detail/reference_surface.h), so
//   every vertex lies on the input surface.
// - Deterministic: the same input gives the same mesh (same canonical soup)
//   on Halfedge_mesh, CGAL::Surface_mesh and Incidence_mesh (its native
//   operations; never a copy). See detail/remesher.h for how, and for the
//   bound on every loop.
// - Renumbering (options.renumber, off by default): after a step that
//   changed much, g is renumbered in a spatial order (genmesh::renumber,
//   <genmesh/renumbering.h>) for memory locality; surviving elements change
//   indices (the visitor's on_renumbered(maps, g) gives old -> new).
//   Halfedge_mesh and Incidence_mesh drop their garbage then and carry every
//   property; other meshes keep removed slots and carry only connectivity
//   and points (see renumbering.h), which is why it is not the default.
// Limits: triangles only after the optional triangulation; adaptive sizing
// is pmp-library's rule (curvature of the input, options.h).
#pragma once

#include <genmesh/remeshing/collapse_short_edges.h>
#include <genmesh/remeshing/equalize_valences.h>
#include <genmesh/remeshing/make_delaunay.h>
#include <genmesh/remeshing/options.h>
#include <genmesh/remeshing/split_long_edges.h>
#include <genmesh/remeshing/tangential_relaxation.h>
#include <genmesh/visitor.h>

#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

/// Remeshes the triangle mesh g in place towards edges of length L
/// (options.target_edge_length, or options.relative_edge_length times the
/// mean edge length). Returns what was done. Throws genmesh::invalid_input
/// (g unchanged) on the refusals listed at the top of this header.
/// The visitor (<genmesh/visitor.h>) sees every split, collapse and flip,
/// every vertex move of smoothing and projection (on_vertex_moved), each
/// renumbering (on_renumbered), and on_step("iteration", done,
/// options.iterations) after each round.
template <detail::remeshing::Remeshable G, class Visitor = Mutation_visitor>
Remeshing_result isotropic_remeshing(G& g, const Remeshing_options& options = {}, Visitor&& visitor = {}) {
  detail::remeshing::Remesher<G, std::remove_cvref_t<Visitor>> r(g, options, "isotropic_remeshing", visitor);
  visitor.on_started(std::as_const(g));
  visitor.on_step("iteration", 0, static_cast<std::size_t>(options.iterations));
  if (options.projection) r.build_reference();
  // The triangles below 36° after the last round, when its steps found them.
  std::optional<std::vector<face_descriptor_t<G>>> still_bad;
  for (int i = 0; i < options.iterations; ++i) {
    // Splits append their elements in a spatially random order (a length
    // heap) and collapses leave holes: with options.renumber, where they
    // changed much (the first round), the mesh is renumbered in a spatial order, so that the steps
    // after read neighbours near each other in memory (armadillo: flips,
    // smoothing and projection 20-50 % less time, docs/benchmarks.md session 7).
    r.split_long_edges();
    r.renumber_if_scattered();
    r.collapse_short_edges();
    r.renumber_if_scattered();
    if (options.flips == Flips::delaunay)
      r.make_delaunay();
    else
      r.equalize_valences();
    // Rounds before the last smooth half as many steps: the last round and
    // the clean-up decide the quality (armadillo: 8 % fewer instructions,
    // valence 6 share up, docs/benchmarks.md session 5).
    const bool last = i + 1 == options.iterations;
    r.tangential_relaxation_project_and_remove_bad_triangles(
        last ? options.smoothing_steps : (options.smoothing_steps + 1) / 2, last ? &still_bad : nullptr);
    ++r.result().iterations;
    visitor.on_step("iteration", static_cast<std::size_t>(i + 1), static_cast<std::size_t>(options.iterations));
  }
  if (options.iterations > 0) still_bad ? r.improve_min_angle(std::move(*still_bad)) : r.improve_min_angle();
  r.finish();
  visitor.on_finished(std::as_const(g));
  return r.result();
}

} // namespace genmesh
