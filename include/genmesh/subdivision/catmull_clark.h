// genmesh/subdivision/catmull_clark.h — Catmull-Clark subdivision of polygon meshes.
//
// Each level splits every n-gon into n quads (face point, edge points, old
// vertex) with the masks of E. Catmull and J. Clark, "Recursively generated
// B-spline surfaces on arbitrary topological meshes", CAD 10(6), 1978:
//   face point    centroid of the face's corners
//   edge point    (a + b + f₁ + f₂) / 4             (f: face points of the two faces)
//   vertex point  (Q + 2R + (n − 3) v) / n           (Q: mean of the n face points,
//                                                    R: mean of the n edge midpoints)
//   border        edge midpoints; vertices 3/4 v + 1/8 (two border neighbours)
//                 (Boundary_rule::smooth) or unchanged (fixed).
// Numbering: old vertices, then edge points in edge iteration order, then face
// points in face iteration order; faces: per old face, one quad per corner.
// Guarantees: computed from the old mesh, then rebuilt into a fresh G (the
// structure genmesh::build_mesh gives); identical on every backend; V' = V + E + F, F' = Σ deg f,
// Euler characteristic and border loops kept. Same masks as CGAL's
// CatmullClark_mask_3 on closed meshes.
// Creases (.crease_sharpness): the rules of <genmesh/subdivision/loop.h>
// (DeRose, Kass, Truong 1998) with Catmull-Clark's smooth masks.
// Limits: g's other properties and descriptors do not survive a level
// (in-place refinement is future work).
#pragma once

#include <genmesh/subdivision/detail/refinement.h>

namespace genmesh {

/// Options of catmull_clark_subdivision().
struct Catmull_clark_options {
  int iterations = 1;                             ///< levels to apply (≥ 0)
  Boundary_rule boundary = Boundary_rule::smooth; ///< border rule
  /// Crease sharpness per edge, in edge iteration order (empty: no creases):
  /// 0 smooth, ∞ sharp, fractional semi-sharp (DeRose, Kass, Truong 1998).
  std::vector<double> crease_sharpness = {};
  /// After the last level (iterations ≥ 1: all faces are quads), move every
  /// vertex to its limit position (n² v + 4 Σ edge neighbours + Σ diagonal
  /// neighbours) / (n (n + 5)); border and crease vertices (p + 4v + q)/6,
  /// corners stay.
  bool limit = false;
};

namespace detail::subdivision {

inline Polygon_soup catmull_clark_level(const Snapshot& s, const Catmull_clark_options& o,
                                        const std::vector<double>& sharp) {
  const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices());
  const std::uint32_t ne = static_cast<std::uint32_t>(s.num_edges());
  const std::uint32_t nf = static_cast<std::uint32_t>(s.num_faces());
  Polygon_soup out;
  out.points.resize(std::size_t(nv) + ne + nf);
  std::vector<Eigen::Vector3d> fp = face_centroids(s);
  for (std::uint32_t f = 0; f < nf; ++f) out.points[std::size_t(nv) + ne + f] = fp[f];
  std::vector<Eigen::Vector3d> q(nv, Eigen::Vector3d::Zero()), r(nv, Eigen::Vector3d::Zero());
  for (std::uint32_t c = 0; c < s.corner_vertex.size(); ++c) q[s.corner_vertex[c]] += fp[s.corner_face[c]];
  for (std::uint32_t e = 0; e < ne; ++e) {
    std::uint32_t c = s.edge_corner[e], t = s.corner_twin[c];
    std::uint32_t a = s.corner_vertex[c], b = s.head(c);
    Eigen::Vector3d mid = 0.5 * (s.points[a] + s.points[b]);
    r[a] += mid;
    r[b] += mid;
    out.points[nv + e] = t == k_none ? mid
                                     : Eigen::Vector3d((s.points[a] + s.points[b] + fp[s.corner_face[c]] +
                                                        fp[s.corner_face[t]]) / 4.0);
    if (!sharp.empty() && t != k_none) out.points[nv + e] = crease_edge_point(s, sharp[e], e, out.points[nv + e]);
  }
  const Crease_stars cs = sharp.empty() ? Crease_stars{} : crease_stars(s, sharp);
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (s.is_border_vertex(v)) {
      out.points[v] = border_vertex_point(s, v, o.boundary);
    } else {
      const double n = s.valence[v];
      out.points[v] = (q[v] / n + 2.0 * r[v] / n + (n - 3.0) * s.points[v]) / n;
      if (!sharp.empty()) out.points[v] = crease_vertex_point(s, cs, v, out.points[v]);
    }
  }
  out.indices.reserve(4 * s.corner_vertex.size());
  out.offsets.reserve(s.corner_vertex.size() + 1);
  for (std::uint32_t f = 0; f < nf; ++f)
    for (std::uint32_t c = s.face_begin[f]; c < s.face_begin[f + 1]; ++c)
      out.add_face({s.corner_vertex[c], nv + s.corner_edge[c], nv + ne + f, nv + s.corner_edge[s.prev(c)]});
  return out;
}

// The twin of every corner of the quad split: quad c (per old corner c, in
// corner order) is (v_i, e_i, face point, e_i-1), so corner 4c + j.
inline std::vector<std::uint32_t> quad_split_twins(const Snapshot& s) {
  const std::size_t nc = s.corner_vertex.size();
  std::vector<std::uint32_t> twin(4 * nc, k_none);
  for (std::uint32_t c = 0; c < nc; ++c) {
    const std::uint32_t n = s.next(c);
    twin[4 * c + 1] = 4 * n + 2; // e_i → face point, in quad c; back in quad next(c)
    twin[4 * n + 2] = 4 * c + 1;
    const std::uint32_t t = s.corner_twin[c];
    if (t == k_none) continue;
    twin[4 * c] = 4 * s.next(t) + 3;     // first half of c ↔ second half of t
    twin[4 * n + 3] = 4 * t;             // second half of c ↔ first half of t
  }
  return twin;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of Catmull-Clark subdivision to g (any
/// polygons). Throws genmesh::invalid_input, g unchanged, when
/// options.iterations < 0 or a face cycle is corrupt.
template <class G>
  requires detail::subdivision::Subdividable<G>
Subdivision_result catmull_clark_subdivision(G& g, const Catmull_clark_options& options = {}) {
  namespace ds = detail::subdivision;
  std::vector<double> sharp = options.crease_sharpness;
  Subdivision_result r = ds::run_levels(
      g, options.iterations, "catmull_clark_subdivision", 0, sharp,
      [&](const ds::Snapshot& s, int) {
        return ds::Refined{ds::catmull_clark_level(s, options, sharp), ds::quad_split_twins(s)};
      },
      [](const ds::Snapshot& s, std::uint32_t c, int h) { return h == 0 ? 4 * c : 4 * s.next(c) + 3; });
  if (options.limit && options.iterations > 0)
    ds::move_to_limit(g, r.edge_sharpness, [&](const ds::Snapshot& s, std::uint32_t v) -> Eigen::Vector3d {
      if (s.is_border_vertex(v)) return ds::border_limit_point(s, v, options.boundary);
      const double n = s.valence[v];
      Eigen::Vector3d edges = Eigen::Vector3d::Zero(), diagonals = Eigen::Vector3d::Zero();
      std::uint32_t c = s.vertex_corner[v];
      for (std::uint32_t k = 0; k < s.valence[v]; ++k, c = s.rotate_ccw(c)) {
        edges += s.points[s.head(c)];
        diagonals += s.points[s.head(s.next(c))]; // the quad's corner opposite v
      }
      return (n * n * s.points[v] + 4.0 * edges + diagonals) / (n * (n + 5.0));
    });
  return r;
}

} // namespace genmesh
