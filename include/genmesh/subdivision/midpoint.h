// genmesh/subdivision/midpoint.h — linear (midpoint) subdivision.
//
// Each level splits triangles 1-to-4 at their edge midpoints and every other
// n-gon into n quads around its centroid (the topology of Loop and
// Catmull-Clark, without smoothing: CGAL's Linear_mask_3 on quads,
// pmp-library's linear subdivision on triangles). Old vertices do not move, so
// the surface keeps its shape exactly; the border is refined likewise.
// Numbering: old vertices, edge midpoints in edge iteration order, then the
// centroids of the non-triangle faces in face iteration order.
// Guarantees: identical on every backend; V' = V + E + (faces with > 3
// sides), F' = 4 (triangles) + Σ deg (others); Euler characteristic and
// border loops kept.
// Limits: g's other properties and descriptors do not survive a level.
#pragma once

#include <genmesh/subdivision/detail/refinement.h>

namespace genmesh {

/// Options of midpoint_subdivision().
struct Midpoint_options {
  int iterations = 1; ///< levels to apply (≥ 0)
};

namespace detail::subdivision {

inline Polygon_soup midpoint_level(const Snapshot& s) {
  const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices());
  const std::uint32_t ne = static_cast<std::uint32_t>(s.num_edges());
  Polygon_soup out;
  out.points.reserve(std::size_t(nv) + ne + s.num_faces());
  out.points = s.points;
  for (std::uint32_t e = 0; e < ne; ++e) {
    std::uint32_t c = s.edge_corner[e];
    out.points.push_back(0.5 * (s.points[s.corner_vertex[c]] + s.points[s.head(c)]));
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
      for (std::uint32_t c = c0; c < s.face_begin[f + 1]; ++c)
        out.add_face({s.corner_vertex[c], nv + s.corner_edge[c], center, nv + s.corner_edge[s.prev(c)]});
    }
  }
  return out;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of midpoint subdivision to g (any
/// polygons). Throws genmesh::invalid_input, g unchanged, when
/// options.iterations < 0.
template <class G>
  requires detail::subdivision::Subdividable<G>
Subdivision_result midpoint_subdivision(G& g, const Midpoint_options& options = {}) {
  namespace ds = detail::subdivision;
  std::vector<double> none;
  return ds::run_levels(
      g, options.iterations, "midpoint_subdivision", 0, none,
      [](const ds::Snapshot& s, int) { return ds::Refined{ds::midpoint_level(s), {}}; }, ds::no_half);
}

} // namespace genmesh
