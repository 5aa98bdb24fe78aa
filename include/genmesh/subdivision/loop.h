// genmesh/subdivision/loop.h — Loop subdivision of triangle meshes.
//
// Each level splits every triangle into four (1-to-4) and moves the vertices
// with Loop's masks (C. Loop, "Smooth subdivision surfaces based on
// triangles", M.S. thesis, Utah 1987):
//   edge point    3/8 (a + b) + 1/8 (c + d)         (c, d: the opposite corners)
//   vertex point  (1 − nβ) v + β Σ neighbours,
//                 β = (5/8 − (3/8 + 1/4 cos(2π/n))²) / n   (Loop_weights::loop, as CGAL and pmp)
//                 β = 3/16 (n = 3), 3/(8n) otherwise      (Loop_weights::warren)
//   border        edge midpoints; vertices 3/4 v + 1/8 (two border neighbours)
//                 (Boundary_rule::smooth, the cubic B-spline) or unchanged (fixed).
// Numbering: old vertices keep their order, then one new vertex per edge in
// edge iteration order; faces: per old face (a, b, c), the corner triangles at
// a, b, c, then the middle one.
// Guarantees: positions are computed from the old mesh only, then the mesh is
// rebuilt into a fresh G (the structure genmesh::build_mesh gives), moved into g; the same input
// gives the same mesh on every backend; V' = V + E, F' = 4F, the Euler
// characteristic and the border loops are kept.
// Creases (.crease_sharpness, per edge): an edge of sharpness s ≥ 1 gets its
// midpoint, 0 < s < 1 the blend (1 − s) smooth + s midpoint; an interior
// vertex with two crease edges the crease rule (p + 6v + q)/8, with three or
// more the corner rule (stays), blended likewise by the mean sharpness; the
// halves of a crease edge get s − 1 (DeRose, Kass, Truong, "Subdivision
// surfaces in character animation", SIGGRAPH 1998). Border vertices keep the
// border rule.
// Limits: triangles only (refused, mesh unchanged); g's other properties and
// its descriptors do not survive a level (a direct in-place refinement is
// future work); positions go through double precision.
#pragma once

#include <genmesh/subdivision/detail/refinement.h>

#include <cmath>
#include <numbers>

namespace genmesh {

/// The vertex weights of Loop's scheme.
enum class Loop_weights {
  loop,   ///< Loop's original β (CGAL, pmp-library, OpenMesh)
  warren, ///< Warren's simplified β = 3/(8n) (3/16 for n = 3)
};

/// Options of loop_subdivision().
struct Loop_options {
  int iterations = 1;                            ///< levels to apply (≥ 0)
  Boundary_rule boundary = Boundary_rule::smooth; ///< border rule
  Loop_weights weights = Loop_weights::loop;      ///< interior vertex weights
  /// Crease sharpness per edge, in edge iteration order (empty: no creases):
  /// 0 smooth, ∞ sharp, fractional semi-sharp (DeRose, Kass, Truong 1998).
  std::vector<double> crease_sharpness = {};
  /// After the last level (iterations ≥ 1), move every vertex to its limit
  /// position: (1 − nγ) v + γ Σ neighbours, γ = 1/(3/(8β) + n); border and
  /// crease vertices (p + 4v + q)/6, corners stay.
  bool limit = false;
};

namespace detail::subdivision {

inline double loop_beta(std::uint32_t n, Loop_weights w) {
  if (w == Loop_weights::warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}

inline Polygon_soup loop_level(const Snapshot& s, const Loop_options& o, const std::vector<double>& sharp) {
  const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices());
  Polygon_soup out;
  out.points.resize(s.num_vertices() + s.num_edges());
  // vertex points
  std::vector<Eigen::Vector3d> ring(nv, Eigen::Vector3d::Zero());
  for (std::uint32_t e = 0; e < s.num_edges(); ++e) {
    std::uint32_t c = s.edge_corner[e], a = s.corner_vertex[c], b = s.head(c);
    ring[a] += s.points[b];
    ring[b] += s.points[a];
  }
  const bool creases = !sharp.empty();
  const Crease_stars cs = creases ? crease_stars(s, sharp) : Crease_stars{};
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (s.is_border_vertex(v)) {
      out.points[v] = border_vertex_point(s, v, o.boundary);
    } else {
      const std::uint32_t n = s.valence[v];
      const double beta = loop_beta(n, o.weights);
      out.points[v] = (1.0 - n * beta) * s.points[v] + beta * ring[v];
      if (creases) out.points[v] = crease_vertex_point(s, cs, v, out.points[v]);
    }
  }
  // edge points
  for (std::uint32_t e = 0; e < s.num_edges(); ++e) {
    std::uint32_t c = s.edge_corner[e], t = s.corner_twin[c];
    const Eigen::Vector3d& a = s.points[s.corner_vertex[c]];
    const Eigen::Vector3d& b = s.points[s.head(c)];
    if (t == k_none) {
      out.points[nv + e] = 0.5 * (a + b);
    } else {
      const Eigen::Vector3d& x = s.points[s.corner_vertex[s.prev(c)]];
      const Eigen::Vector3d& y = s.points[s.corner_vertex[s.prev(t)]];
      out.points[nv + e] = 0.375 * (a + b) + 0.125 * (x + y);
      if (creases) out.points[nv + e] = crease_edge_point(s, sharp[e], e, out.points[nv + e]);
    }
  }
  emit_one_to_four(s, nv, out);
  return out;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of Loop subdivision to the triangle mesh
/// g (positions through get(genmesh::vertex_point, g)). Throws
/// genmesh::invalid_input naming the first non-triangle face (in face
/// iteration order) and leaves g unchanged when g is not a triangle mesh, or
/// when options.iterations < 0.
template <class G>
  requires detail::subdivision::Subdividable<G>
Subdivision_result loop_subdivision(G& g, const Loop_options& options = {}) {
  namespace ds = detail::subdivision;
  std::vector<double> sharp = options.crease_sharpness;
  Subdivision_result r = ds::run_levels(
      g, options.iterations, "loop_subdivision", 3, sharp,
      [&](const ds::Snapshot& s, int) { return ds::Refined{ds::loop_level(s, options, sharp), ds::one_to_four_twins(s)}; },
      ds::one_to_four_half);
  if (options.limit && options.iterations > 0)
    ds::move_to_limit(g, r.edge_sharpness, [&](const ds::Snapshot& s, std::uint32_t v) -> Eigen::Vector3d {
      if (s.is_border_vertex(v)) return ds::border_limit_point(s, v, options.boundary);
      const std::uint32_t n = s.valence[v];
      Eigen::Vector3d ring = Eigen::Vector3d::Zero();
      std::uint32_t c = s.vertex_corner[v];
      for (std::uint32_t k = 0; k < n; ++k, c = s.rotate_ccw(c)) ring += s.points[s.head(c)];
      const double gamma = 1.0 / (3.0 / (8.0 * ds::loop_beta(n, options.weights)) + n);
      return (1.0 - n * gamma) * s.points[v] + gamma * ring;
    });
  return r;
}

} // namespace genmesh
