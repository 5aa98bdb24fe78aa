// genmesh/subdivision/midpoint.h — linear (midpoint) subdivision.
//
// Each level splits triangles 1-to-4 at their edge midpoints and every other
// n-gon into n quads around its centroid (the topology of Loop and
// Catmull-Clark, without smoothing: CGAL's Linear_mask_3 on quads,
// pmp-library's linear subdivision on triangles). Old vertices do not move, so
// the surface keeps its shape exactly; the border is refined likewise.
// Refinement: a triangle mesh is refined in place with Loop's 1-to-4
// refinement (see <genmesh/subdivision/detail/in_place.h>; old vertices keep
// their numbers, then the midpoints in first-use order: faces in face order,
// each from its lowest vertex). A mesh with other faces goes through
// snapshot → refined soup → rebuild: old vertices, midpoints in edge
// iteration order, then the centroids of the non-triangle faces in face
// iteration order.
// Guarantees: identical on every backend; V' = V + E + (faces with > 3
// sides), F' = 4 (triangles) + Σ deg (others); Euler characteristic and
// border loops kept.
// Attributes: the visitor's on_vertex_mask receives every new vertex's mask (an old
// vertex itself, a midpoint its two ends, a centroid its corners).
// Limits: g's other properties are not refined in place (new elements get
// their defaults) and do not survive a rebuild (a mesh with non-triangles:
// the rebuild links a fresh mesh through the backend's own link_soup).
#pragma once

#include <genmesh/subdivision/detail/in_place.h>

namespace genmesh {

/// Options of midpoint_subdivision().
template <class VertexPointMap = Default_map>
struct Midpoint_options {
  int iterations = 1; ///< levels to apply (≥ 0)
  /// Vertex → point (read-write; default get(genmesh::vertex_point, g)); it
  /// must accept the vertices the call adds.
  VertexPointMap vertex_point_map = {};
};

namespace detail::subdivision {

/// One level through a refined soup (any polygons); the visitor gets the
/// masks in the soup's point order (the rebuilt mesh's vertex order).
template <class V>
Polygon_soup midpoint_level(const Snapshot& s, V& vis) {
  constexpr bool masks = visits_vertex_masks<V>;
  const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices());
  const std::uint32_t ne = static_cast<std::uint32_t>(s.num_edges());
  Polygon_soup out;
  out.points.reserve(std::size_t(nv) + ne + s.num_faces());
  out.points = s.points;
  std::vector<std::uint32_t> src;
  std::vector<double> w;
  if constexpr (masks) {
    const double one = 1.0;
    for (std::uint32_t v = 0; v < nv; ++v) vis.on_vertex_mask(v, {&v, 1}, {&one, 1});
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    const std::uint32_t c = s.edge_corner[e], a = s.corner_vertex[c], b = s.head(c);
    out.points.push_back(0.5 * (s.points[a] + s.points[b]));
    if constexpr (masks) src.assign({a, b}), w.assign({0.5, 0.5}), vis.on_vertex_mask(nv + e, src, w);
  }
  for (std::uint32_t f = 0; f < s.num_faces(); ++f) {
    const std::uint32_t c0 = s.face_begin[f];
    if (s.face_size(f) == 3) {
      const std::uint32_t a = s.corner_vertex[c0], b = s.corner_vertex[c0 + 1], c = s.corner_vertex[c0 + 2];
      const std::uint32_t ab = nv + s.corner_edge[c0], bc = nv + s.corner_edge[c0 + 1], ca = nv + s.corner_edge[c0 + 2];
      out.add_face({a, ab, ca});
      out.add_face({b, bc, ab});
      out.add_face({c, ca, bc});
      out.add_face({ab, bc, ca});
    } else {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (std::uint32_t c = c0; c < s.face_begin[f + 1]; ++c) sum += s.points[s.corner_vertex[c]];
      const Polygon_soup::Index center = out.add_point(sum / double(s.face_size(f)));
      if constexpr (masks) {
        src.assign(s.corner_vertex.begin() + c0, s.corner_vertex.begin() + s.face_begin[f + 1]);
        w.assign(src.size(), 1.0 / double(src.size()));
        vis.on_vertex_mask(static_cast<std::uint32_t>(center), src, w);
      }
      for (std::uint32_t c = c0; c < s.face_begin[f + 1]; ++c)
        out.add_face({s.corner_vertex[c], nv + s.corner_edge[c], center, nv + s.corner_edge[s.prev(c)]});
    }
  }
  return out;
}

/// Whether every face of g is a triangle (the in-place 1-to-4 applies).
template <class G>
bool all_triangles(const G& g) {
  for (auto f : faces(g)) {
    const auto h = halfedge(f, g);
    if (next(next(next(h, g), g), g) != h) return false;
  }
  return true;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of midpoint subdivision to g (any
/// polygons). Throws genmesh::invalid_input, g unchanged, when
/// options.iterations < 0.
template <class G, class VertexPointMap = Default_map, class Visitor = Mutation_visitor>
  requires detail::subdivision::Subdividable<G>
Subdivision_result midpoint_subdivision(G& g, const Midpoint_options<VertexPointMap>& options = {}, Visitor&& visitor = {}) {
  namespace ds = detail::subdivision;
  visitor.on_started(std::as_const(g));
  Subdivision_result r;
  if (ds::all_triangles(g)) {
    r = ds::run_in_place(
        g, options.iterations, "midpoint_subdivision", Default_map{}, Default_map{}, options.vertex_point_map,
        [](const auto& m) { return ds::face_counts(m, "midpoint_subdivision", 3); },
        [&](auto& m, const std::array<std::size_t, 4>& n, std::vector<double>&, const std::vector<std::uint32_t>&,
            const auto& refiner) {
          ds::interpolating_one_to_four_level(m, n, visitor, refiner, [&](auto x, auto& mask) {
            mask.add(source(x, m), 0.5), mask.add(target(x, m), 0.5);
          });
        },
        ds::one_to_four_counts, visitor);
  } else {
    r = ds::run_levels(
        g, options.iterations, "midpoint_subdivision", 0,
        [&](const ds::Snapshot& s, int) { return ds::Refined{ds::midpoint_level(s, visitor), {}}; },
        visitor, options.vertex_point_map);
  }
  visitor.on_finished(std::as_const(g));
  return r;
}

} // namespace genmesh
