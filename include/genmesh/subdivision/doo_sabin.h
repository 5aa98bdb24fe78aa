// genmesh/subdivision/doo_sabin.h — Doo-Sabin subdivision of polygon meshes.
//
// Each level makes one new point per face corner and three kinds of faces
// (D. Doo and M. Sabin, "Behaviour of recursive division surfaces near
// extraordinary points", CAD 10(6), 1978): per old face the polygon of its
// corner points (F-face), per interior edge a quad (E-face), per interior
// vertex the polygon of its corner points around it (V-face).
//   corner point of corner i in an n-gon   Σ_k α_k p_{i+k},
//     α_0 = (n + 5) / (4n),  α_k = (3 + 2 cos(2πk/n)) / (4n)   (CGAL's DooSabin_mask_3)
// Border: border edges and border vertices make no E- and V-faces, so the
// surface recedes from the border by half a face per level (no border rule is
// applied; CGAL's DQQ refinement does not take borders).
// Numbering: the corner points in face order, corner by corner from each
// face's lowest vertex; faces: F-faces (face order), E-faces (edge order),
// V-faces (vertex order).
// Attributes: the visitor's on_vertex_mask receives every new vertex's mask (the
// corner point's α_k over its face's corners).
// Guarantees: identical on every backend; on closed meshes V' = Σ deg f,
// F' = F + E + V, the Euler characteristic is kept and every new vertex has
// valence 4; the border loop count is kept. Equal to CGAL's
// DooSabin_subdivision on closed meshes.
// Limits: g's other properties and descriptors do not survive a level: no
// old vertex or edge survives as an element, so the level is not refined in
// place (as Loop's is) but goes through snapshot → refined soup → rebuild.
#pragma once

#include <genmesh/subdivision/detail/in_place.h>
#include <genmesh/subdivision/detail/refinement.h>

#include <cmath>
#include <numbers>

namespace genmesh {

/// Options of doo_sabin_subdivision().
template <class VertexPointMap = Default_map>
struct Doo_sabin_options {
  int iterations = 1; ///< levels to apply (≥ 0)
  /// Vertex → point (read-write; default get(genmesh::vertex_point, g)); it
  /// must accept the vertices the call adds.
  VertexPointMap vertex_point_map = {};
};

namespace detail::subdivision {

/// One level; the visitor gets every new vertex's mask in the soup's point
/// order (the rebuilt mesh's vertex order).
template <class V = Mutation_visitor>
Polygon_soup doo_sabin_level(const Snapshot& s, V&& vis = {}) {
  constexpr bool masks = visits_vertex_masks<V>;
  const std::size_t nc = s.corner_vertex.size();
  Polygon_soup out;
  out.points.resize(nc);
  std::vector<double> w;
  std::vector<std::uint32_t> src;
  for (std::uint32_t f = 0; f < s.num_faces(); ++f) {
    const std::uint32_t n = s.face_size(f), b = s.face_begin[f];
    w.resize(n);
    for (std::uint32_t k = 0; k < n; ++k)
      w[k] = k == 0 ? (n + 5.0) / (4.0 * n) : (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * k / n)) / (4.0 * n);
    for (std::uint32_t i = 0; i < n; ++i) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (std::uint32_t k = 0; k < n; ++k) p += w[k] * s.points[s.corner_vertex[b + (i + k) % n]];
      out.points[b + i] = p;
      if constexpr (masks) {
        src.resize(n);
        for (std::uint32_t k = 0; k < n; ++k) src[k] = s.corner_vertex[b + (i + k) % n];
        vis.on_vertex_mask(b + i, src, w);
      }
    }
  }
  out.indices.reserve(4 * nc);
  std::vector<Polygon_soup::Index> poly;
  for (std::uint32_t f = 0; f < s.num_faces(); ++f) {
    poly.clear();
    for (std::uint32_t c = s.face_begin[f]; c < s.face_begin[f + 1]; ++c) poly.push_back(c);
    out.add_face(poly);
  }
  for (std::uint32_t e = 0; e < s.num_edges(); ++e) {
    std::uint32_t c = s.edge_corner[e], t = s.corner_twin[c];
    if (t != k_none) out.add_face({s.next(t), t, s.next(c), c});
  }
  for (std::uint32_t v = 0; v < s.num_vertices(); ++v) {
    if (s.is_border_vertex(v)) continue;
    poly.clear();
    std::uint32_t c = s.vertex_corner[v];
    do {
      poly.push_back(c);
      c = s.rotate_ccw(c);
    } while (c != s.vertex_corner[v] && c != k_none && poly.size() <= s.valence[v]);
    out.add_face(poly);
  }
  return out;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of Doo-Sabin subdivision to g (any
/// polygons). Throws genmesh::invalid_input, g unchanged, when
/// options.iterations < 0.
template <class G, class VertexPointMap = Default_map, class Visitor = Mutation_visitor>
  requires detail::subdivision::Subdividable<G>
Subdivision_result doo_sabin_subdivision(G& g, const Doo_sabin_options<VertexPointMap>& options = {}, Visitor&& visitor = {}) {
  namespace ds = detail::subdivision;
  visitor.on_started(std::as_const(g));
  Subdivision_result r = ds::run_levels(
      g, options.iterations, "doo_sabin_subdivision", 0,
      [&](const ds::Snapshot& s, int) { return ds::Refined{ds::doo_sabin_level(s, visitor), {}}; },
      visitor, options.vertex_point_map);
  visitor.on_finished(std::as_const(g));
  return r;
}

} // namespace genmesh
