// genmesh/subdivision/butterfly.h — modified butterfly subdivision (interpolating).
//
// Each level splits every triangle 1-to-4; old vertices keep their positions
// and each edge point comes from the modified butterfly masks of D. Zorin,
// P. Schröder and W. Sweldens, "Interpolating subdivision for meshes with
// arbitrary topology", SIGGRAPH 1996:
//   both endpoints of valence 6  1/2 (a + b) + 1/8 (c + d) − 1/16 (four wing vertices)
//   one endpoint a of valence k ≠ 6 (the other regular)
//                                3/4 a + Σ_j s_j q_j  (q_j: a's neighbours from b on)
//       k = 3: s = 5/12, −1/12, −1/12;  k = 4: s = 3/8, 0, −1/8, 0;
//       k ≥ 5: s_j = (1/4 + cos(2πj/k) + 1/2 cos(4πj/k)) / k
//   both endpoints irregular     the mean of the two endpoint masks
//   border edge                  the four-point rule −1/16, 9/16, 9/16, −1/16 along the border
// Near the border (simplified, not Zorin's border-adjacent masks): an interior
// edge uses an endpoint's valence-k mask only when that endpoint is interior;
// otherwise the eight-point mask, a missing wing vertex replaced by its
// reflection p + q − o across the wing edge (p, q), which keeps linear
// precision.
// Numbering: old vertices, then edge points in edge iteration order (as Loop).
// Guarantees: identical on every backend; old vertices interpolated exactly;
// V' = V + E, F' = 4F, Euler characteristic and border loops kept.
// Limits: triangles only (refused, g unchanged); g's other properties and
// descriptors do not survive a level.
#pragma once

#include <genmesh/subdivision/detail/refinement.h>

#include <cmath>
#include <numbers>

namespace genmesh {

/// Options of butterfly_subdivision().
struct Butterfly_options {
  int iterations = 1; ///< levels to apply (≥ 0)
};

namespace detail::subdivision {

// The wing vertex across the edge of corner c (the face on c's other side),
// or the reflection of c's face's third vertex when that edge is a border.
inline Eigen::Vector3d butterfly_wing(const Snapshot& s, std::uint32_t c) {
  std::uint32_t t = s.corner_twin[c];
  if (t != k_none) return s.points[s.corner_vertex[s.prev(t)]];
  return s.points[s.corner_vertex[c]] + s.points[s.head(c)] - s.points[s.corner_vertex[s.prev(c)]];
}

// Valence-k mask at interior vertex a for the edge of corner c (a → b).
inline Eigen::Vector3d butterfly_irregular(const Snapshot& s, std::uint32_t c) {
  const std::uint32_t a = s.corner_vertex[c];
  const std::uint32_t k = s.valence[a];
  Eigen::Vector3d p = 0.75 * s.points[a];
  std::uint32_t x = c;
  for (std::uint32_t j = 0; j < k; ++j, x = s.rotate_ccw(x)) {
    double w;
    if (k == 3) w = j == 0 ? 5.0 / 12.0 : -1.0 / 12.0;
    else if (k == 4) w = j == 0 ? 3.0 / 8.0 : (j == 2 ? -1.0 / 8.0 : 0.0);
    else {
      const double t = 2.0 * std::numbers::pi * j / k;
      w = (0.25 + std::cos(t) + 0.5 * std::cos(2.0 * t)) / k;
    }
    p += w * s.points[s.head(x)];
  }
  return p;
}

inline Polygon_soup butterfly_level(const Snapshot& s) {
  const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices());
  Polygon_soup out;
  out.points.resize(s.num_vertices() + s.num_edges());
  std::copy(s.points.begin(), s.points.end(), out.points.begin());
  for (std::uint32_t e = 0; e < s.num_edges(); ++e) {
    const std::uint32_t c = s.edge_corner[e], t = s.corner_twin[c];
    const std::uint32_t a = s.corner_vertex[c], b = s.head(c);
    const Eigen::Vector3d& pa = s.points[a];
    const Eigen::Vector3d& pb = s.points[b];
    Eigen::Vector3d p;
    if (t == k_none) {
      // four-point rule along the border (a → b runs against the border cycle)
      auto other = [&](std::uint32_t v, std::uint32_t not_this) -> std::uint32_t {
        if (s.border_edges[v] != 2 || s.vertex_corner[v] == k_none) return k_none;
        auto [x, y] = s.border_neighbours(v);
        return x == not_this ? y : x;
      };
      std::uint32_t a2 = other(a, b), b2 = other(b, a);
      if (a2 == k_none || b2 == k_none) p = 0.5 * (pa + pb);
      else p = (9.0 / 16.0) * (pa + pb) - (1.0 / 16.0) * (s.points[a2] + s.points[b2]);
    } else {
      const bool ia = !s.is_border_vertex(a) && s.valence[a] != 6;
      const bool ib = !s.is_border_vertex(b) && s.valence[b] != 6;
      if (ia && ib) p = 0.5 * (butterfly_irregular(s, c) + butterfly_irregular(s, t));
      else if (ia) p = butterfly_irregular(s, c);
      else if (ib) p = butterfly_irregular(s, t);
      else {
        const Eigen::Vector3d& pc = s.points[s.corner_vertex[s.prev(c)]];
        const Eigen::Vector3d& pd = s.points[s.corner_vertex[s.prev(t)]];
        Eigen::Vector3d wings = butterfly_wing(s, s.next(c)) + butterfly_wing(s, s.prev(c)) +
                                butterfly_wing(s, s.next(t)) + butterfly_wing(s, s.prev(t));
        p = 0.5 * (pa + pb) + 0.125 * (pc + pd) - 0.0625 * wings;
      }
    }
    out.points[nv + e] = p;
  }
  emit_one_to_four(s, nv, out);
  return out;
}

} // namespace detail::subdivision

/// Applies options.iterations levels of modified butterfly subdivision to the
/// triangle mesh g. Throws genmesh::invalid_input naming the first
/// non-triangle face, g unchanged, when g is not a triangle mesh or
/// options.iterations < 0.
template <class G>
  requires detail::subdivision::Subdividable<G>
Subdivision_result butterfly_subdivision(G& g, const Butterfly_options& options = {}) {
  namespace ds = detail::subdivision;
  std::vector<double> none;
  return ds::run_levels(
      g, options.iterations, "butterfly_subdivision", 3, none,
      [](const ds::Snapshot& s, int) { return ds::Refined{ds::butterfly_level(s), ds::one_to_four_twins(s)}; },
      ds::no_half);
}

} // namespace genmesh
