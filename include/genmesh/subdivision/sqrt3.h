// genmesh/subdivision/sqrt3.h — Kobbelt's √3 subdivision of triangle meshes.
//
// Each level inserts a point at every triangle's centroid, connects it to the
// triangle's corners and flips every old interior edge, so that the triangle
// count triples (L. Kobbelt, "√3-subdivision", SIGGRAPH 2000):
//   face point    (a + b + c) / 3
//   vertex point  (1 − α) v + α/n Σ neighbours,  α = (4 − 2 cos(2π/n)) / 9
// Border (Kobbelt's rule, as CGAL): at even levels of a call an old border
// edge keeps its triangle (a, b, face point) and border vertices stay; at odd
// levels (Boundary_rule::smooth) every face with one border edge splits that
// edge in three with the 1/27 (16, 10, 1) masks and border vertices move to
// (4, 19, 4)/27 — two levels then triple the border like the interior.
// Boundary_rule::fixed never refines the border.
// Numbering: old vertices, then per face in face order its face point (or,
// refined border faces, its two border points); faces: two per interior edge
// (edge iteration order), one per border edge.
// Attributes: the visitor's on_vertex_mask receives every new vertex's mask in the
// numbering above (a face point its corners, 1/3 each; an interior old vertex
// itself with 1 − α and its neighbours with α/n; a border vertex itself, or
// (4, 19, 4)/27 when it moves; a border point its (16, 10, 1)/27 mask).
// Guarantees: identical on every backend; V' = V + F, F' = 3F on closed
// meshes; Euler characteristic and border loops kept; equal to CGAL's
// Sqrt3_subdivision, also on meshes with borders whose border faces have one
// border edge each (CGAL assumes that; a face with more is not border-refined here).
// Limits: triangles only (refused, g unchanged); g's other properties and
// descriptors do not survive a level: its topology is not Loop's 1-to-4 (a
// face point per face, every old interior edge flipped, border edges split
// in three every second level), so it goes through snapshot → refined soup
// → rebuild rather than the in-place refinement.
#pragma once

#include <genmesh/subdivision/detail/in_place.h>
#include <genmesh/subdivision/detail/refinement.h>

#include <array>
#include <cmath>
#include <numbers>

namespace genmesh {

/// Options of sqrt3_subdivision().
template <class VertexPointMap = Default_map>
struct Sqrt3_options {
  int iterations = 1; ///< levels to apply (≥ 0)
  /// smooth: Kobbelt's border rule at every second level of a call (levels
  /// 1, 3, ... counted from 0, as CGAL's Sqrt3_subdivision); fixed: the border
  /// polygon is never refined and border vertices never move.
  Boundary_rule boundary = Boundary_rule::smooth;
  /// Vertex → point (read-write; default get(genmesh::vertex_point, g)); it
  /// must accept the vertices the call adds.
  VertexPointMap vertex_point_map = {};
};

namespace detail::subdivision {

// One √3 level. With refine_border (Kobbelt's border rule, CGAL's odd
// levels), a face with exactly one border edge (src → tgt, third vertex x) gets
// no face point: the border edge is split in three by
//   n1 = (16 src + 10 tgt + p) / 27,  n2 = (10 src + 16 tgt + q) / 27
// (p: the border vertex after src, q: the one before tgt along the border),
// the middle triangle is (n1, n2, x), and n1 / n2 stand in for the face point
// of the edges x → src / tgt → x; tgt moves to (4 (its border neighbours) + 19 tgt) / 27.
// The visitor gets every new vertex's mask in the soup's point order (the
// rebuilt mesh's vertex order).
template <class V = Mutation_visitor>
Polygon_soup sqrt3_level(const Snapshot& s, bool refine_border, V&& vis = {}) {
  const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices());
  const std::uint32_t ne = static_cast<std::uint32_t>(s.num_edges());
  const std::uint32_t nf = static_cast<std::uint32_t>(s.num_faces());
  Polygon_soup out;
  out.points.resize(nv);
  out.points.reserve(std::size_t(nv) + 2 * std::size_t(nf));
  std::vector<Eigen::Vector3d> ring(nv, Eigen::Vector3d::Zero());
  for (std::uint32_t e = 0; e < ne; ++e) {
    std::uint32_t c = s.edge_corner[e], a = s.corner_vertex[c], b = s.head(c);
    ring[a] += s.points[b];
    ring[b] += s.points[a];
  }
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (s.is_border_vertex(v)) {
      out.points[v] = s.points[v];
    } else {
      const double n = s.valence[v];
      const double alpha = (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / n)) / 9.0;
      out.points[v] = (1.0 - alpha) * s.points[v] + (alpha / n) * ring[v];
    }
  }
  // per face: its new point (face point, or n1 with n2 = n1 + 1) and its border corner
  std::vector<std::uint32_t> first_point(nf), border_corner(nf, k_none);
  // for the visitor: per refined border face its p and q; per moved border vertex tgt its (src, q)
  constexpr bool masks = visits_vertex_masks<V>;
  std::vector<std::array<std::uint32_t, 2>> face_pq(masks ? nf : 0), moved(masks ? nv : 0, {k_none, k_none});
  for (std::uint32_t f = 0; f < nf; ++f) {
    std::uint32_t borders = 0, bc = k_none;
    for (std::uint32_t c = s.face_begin[f]; c < s.face_begin[f + 1]; ++c)
      if (s.corner_twin[c] == k_none) ++borders, bc = c;
    first_point[f] = static_cast<std::uint32_t>(out.points.size());
    if (refine_border && borders == 1 && s.border_edges[s.corner_vertex[bc]] == 2 &&
        s.border_edges[s.head(bc)] == 2 && s.vertex_corner[s.corner_vertex[bc]] != k_none &&
        s.vertex_corner[s.head(bc)] != k_none) {
      border_corner[f] = bc;
      const std::uint32_t src = s.corner_vertex[bc], tgt = s.head(bc);
      // p: src's other border neighbour; q: tgt's
      const auto [src_next, src_prev] = s.border_neighbours(src);
      const auto [tgt_next, tgt_prev] = s.border_neighbours(tgt);
      const std::uint32_t p = src_prev == tgt ? src_next : src_prev;
      const std::uint32_t q = tgt_next == src ? tgt_prev : tgt_next;
      out.points.push_back((16.0 * s.points[src] + 10.0 * s.points[tgt] + s.points[p]) / 27.0);
      out.points.push_back((10.0 * s.points[src] + 16.0 * s.points[tgt] + s.points[q]) / 27.0);
      out.points[tgt] = (4.0 * (s.points[src] + s.points[q]) + 19.0 * s.points[tgt]) / 27.0;
      if (masks) face_pq[f] = {p, q}, moved[tgt] = {src, q};
    } else {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (std::uint32_t c = s.face_begin[f]; c < s.face_begin[f + 1]; ++c) sum += s.points[s.corner_vertex[c]];
      out.points.push_back(sum / double(s.face_size(f)));
    }
  }
  if constexpr (masks) {
    std::vector<std::uint32_t> src;
    std::vector<double> w;
    std::vector<std::vector<std::uint32_t>> neighbours(nv);
    for (std::uint32_t e = 0; e < ne; ++e) {
      const std::uint32_t c = s.edge_corner[e], a = s.corner_vertex[c], b = s.head(c);
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
    for (std::uint32_t v = 0; v < nv; ++v) {
      if (moved[v][0] != k_none) {
        src.assign({moved[v][0], moved[v][1], v}), w.assign({4.0 / 27.0, 4.0 / 27.0, 19.0 / 27.0});
      } else if (s.is_border_vertex(v)) {
        src.assign({v}), w.assign({1.0});
      } else {
        const double n = s.valence[v];
        const double alpha = (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / n)) / 9.0;
        src.assign({v}), w.assign({1.0 - alpha});
        for (std::uint32_t u : neighbours[v]) src.push_back(u), w.push_back(alpha / n);
      }
      vis.on_vertex_mask(v, src, w);
    }
    for (std::uint32_t f = 0; f < nf; ++f) {
      const std::uint32_t bc = border_corner[f];
      if (bc == k_none) {
        src.assign(s.corner_vertex.begin() + s.face_begin[f], s.corner_vertex.begin() + s.face_begin[f + 1]);
        w.assign(src.size(), 1.0 / double(src.size()));
        vis.on_vertex_mask(first_point[f], src, w);
      } else {
        const std::uint32_t a = s.corner_vertex[bc], b = s.head(bc);
        w.assign({16.0 / 27.0, 10.0 / 27.0, 1.0 / 27.0});
        src.assign({a, b, face_pq[f][0]}), vis.on_vertex_mask(first_point[f], src, w);
        src.assign({b, a, face_pq[f][1]}), vis.on_vertex_mask(first_point[f] + 1, src, w);
      }
    }
  }
  // the point standing for corner c's face on c's edge
  auto apex = [&](std::uint32_t c) -> std::uint32_t {
    const std::uint32_t f = s.corner_face[c], bc = border_corner[f];
    if (bc == k_none) return first_point[f];
    return c == s.prev(bc) ? first_point[f] : first_point[f] + 1; // x → src: n1; tgt → x: n2
  };
  out.indices.reserve(9 * std::size_t(nf));
  out.offsets.reserve(3 * std::size_t(nf) + 1);
  for (std::uint32_t e = 0; e < ne; ++e) {
    std::uint32_t c = s.edge_corner[e], t = s.corner_twin[c];
    std::uint32_t a = s.corner_vertex[c], b = s.head(c);
    if (t == k_none) {
      const std::uint32_t f = s.corner_face[c];
      if (border_corner[f] == c) out.add_face({first_point[f], first_point[f] + 1, s.corner_vertex[s.prev(c)]});
      else out.add_face({a, b, first_point[f]});
    } else {
      const std::uint32_t c0 = apex(c), c1 = apex(t);
      out.add_face({a, c1, c0});
      out.add_face({c1, b, c0});
    }
  }
  return out;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of √3 subdivision to the triangle mesh
/// g. Throws genmesh::invalid_input naming the first non-triangle face, g
/// unchanged, when g is not a triangle mesh or options.iterations < 0.
template <class G, class VertexPointMap = Default_map, class Visitor = Mutation_visitor>
  requires detail::subdivision::Subdividable<G>
Subdivision_result sqrt3_subdivision(G& g, const Sqrt3_options<VertexPointMap>& options = {}, Visitor&& visitor = {}) {
  namespace ds = detail::subdivision;
  visitor.on_started(std::as_const(g));
  Subdivision_result r = ds::run_levels(
      g, options.iterations, "sqrt3_subdivision", 3,
      [&](const ds::Snapshot& s, int i) {
        return ds::Refined{ds::sqrt3_level(s, options.boundary == Boundary_rule::smooth && i % 2 == 1, visitor), {}};
      },
      visitor, options.vertex_point_map);
  visitor.on_finished(std::as_const(g));
  return r;
}

} // namespace genmesh
