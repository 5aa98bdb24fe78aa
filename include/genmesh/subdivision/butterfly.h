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
// Refinement: in place, the 1-to-4 refinement of Loop (see
// <genmesh/subdivision/detail/in_place.h>): old vertices keep their numbers,
// then one edge point per old edge in first-use order (faces in face order,
// each from its lowest vertex); old faces keep the middle triangle.
// Guarantees: identical on every backend; old vertices interpolated exactly;
// V' = V + E, F' = 4F, Euler characteristic and border loops kept.
// Attributes: the visitor's on_vertex_mask receives every new vertex's mask (an old
// vertex: itself with weight 1; the weights of an edge point sum to 1 and
// include the negative wing weights).
// Limits: triangles only (refused, g unchanged); g's other properties are not
// refined (new elements get their defaults); a backend without set_next, or a
// mesh with removed elements, is refined through the local operations
// (split_edge, split_face: the backend's own), never on a copy.
#pragma once

#include <genmesh/subdivision/detail/in_place.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace genmesh {

/// Options of butterfly_subdivision().
template <class VertexPointMap = Default_map>
struct Butterfly_options {
  int iterations = 1; ///< levels to apply (≥ 0)
  /// Vertex → point (read-write; default get(genmesh::vertex_point, g)); it
  /// must accept the vertices the call adds.
  VertexPointMap vertex_point_map = {};
};

namespace detail::subdivision {

/// The weight s_j of a's j-th neighbour (from b on) in the valence-k mask.
inline double butterfly_weight(std::uint32_t k, std::uint32_t j) {
  if (k == 3) return j == 0 ? 5.0 / 12.0 : -1.0 / 12.0;
  if (k == 4) return j == 0 ? 3.0 / 8.0 : (j == 2 ? -1.0 / 8.0 : 0.0);
  const double t = 2.0 * std::numbers::pi * j / k;
  return (0.25 + std::cos(t) + 0.5 * std::cos(2.0 * t)) / k;
}

/// One butterfly level in place on the dense triangle mesh g of counts n.
template <class G, class V, class Refiner>
void butterfly_level_in_place(G& g, const std::array<std::size_t, 4>& n, V& vis, const Refiner& refiner) {
  using H = halfedge_descriptor_t<G>;
  const Stars st = stars(g, {}, {});
  auto vi = get(vertex_index, g);
  auto num = [&](auto v) { return static_cast<std::uint32_t>(get(vi, v)); };
  const auto null_face = boost::graph_traits<G>::null_face();
  // The wing vertex across edge y (the third corner of the face on y's
  // other side), or the reflection of y's own third corner when that side
  // is the border.
  auto wing = [&](H y, double w, Mask<G>& m) {
    const H o = opposite(y, g);
    if (face(o, g) != null_face) return m.add(target(next(o, g), g), w);
    m.add(source(y, g), w), m.add(target(y, g), w), m.add(target(next(y, g), g), -w);
  };
  // The valence-k mask at interior vertex a = source(x), scaled; its
  // weights computed once per valence, not per edge.
  std::vector<std::vector<double>> weights_of;
  auto irregular = [&](H x, double scale, Mask<G>& m) {
    const std::uint32_t k = st.valence[num(source(x, g))];
    if (k >= weights_of.size()) weights_of.resize(k + 1);
    std::vector<double>& s = weights_of[k];
    if (s.empty())
      for (std::uint32_t j = 0; j < k; ++j) s.push_back(butterfly_weight(k, j));
    m.add(source(x, g), 0.75 * scale);
    H y = x;
    for (std::uint32_t j = 0; j < k; ++j, y = opposite(prev(y, g), g)) m.add(target(y, g), scale * s[j]);
  };
  interpolating_one_to_four_level(g, n, vis, refiner, [&](H x, Mask<G>& m) {
    const H o = opposite(x, g);
    const auto va = source(x, g), vb = target(x, g);
    const std::uint32_t a = num(va), b = num(vb);
    if (face(o, g) == null_face) {
      // four-point rule along the border: o runs b → a in the border cycle
      if (st.border[a] != 2 || st.border[b] != 2) return m.add(va, 0.5), m.add(vb, 0.5);
      m.add(va, 9.0 / 16.0), m.add(vb, 9.0 / 16.0);
      m.add(target(next(o, g), g), -1.0 / 16.0), m.add(source(prev(o, g), g), -1.0 / 16.0);
      return;
    }
    const bool ia = !st.is_border(a) && st.valence[a] != 6, ib = !st.is_border(b) && st.valence[b] != 6;
    if (ia && ib) return irregular(x, 0.5, m), irregular(o, 0.5, m);
    if (ia) return irregular(x, 1.0, m);
    if (ib) return irregular(o, 1.0, m);
    m.add(va, 0.5), m.add(vb, 0.5);
    m.add(target(next(x, g), g), 0.125), m.add(target(next(o, g), g), 0.125);
    for (const H y : {next(x, g), prev(x, g), next(o, g), prev(o, g)}) wing(y, -0.0625, m);
  });
}

} // namespace detail::subdivision

/// Applies options.iterations levels of modified butterfly subdivision to the
/// triangle mesh g. Throws genmesh::invalid_input naming the first
/// non-triangle face, g unchanged, when g is not a triangle mesh,
/// options.iterations < 0, or an edge has no face on either side.
template <class G, class VertexPointMap = Default_map, class Visitor = Mutation_visitor>
  requires detail::subdivision::Subdividable<G>
Subdivision_result butterfly_subdivision(G& g, const Butterfly_options<VertexPointMap>& options = {}, Visitor&& visitor = {}) {
  namespace ds = detail::subdivision;
  visitor.on_started(std::as_const(g));
  Subdivision_result r = ds::run_in_place(
      g, options.iterations, "butterfly_subdivision", Default_map{}, Default_map{}, options.vertex_point_map,
      [](const auto& m) { return ds::face_counts(m, "butterfly_subdivision", 3); },
      [&](auto& m, const std::array<std::size_t, 4>& n, std::vector<double>&, const std::vector<std::uint32_t>&,
          const auto& refiner) { ds::butterfly_level_in_place(m, n, visitor, refiner); },
      ds::one_to_four_counts, visitor);
  visitor.on_finished(std::as_const(g));
  return r;
}

} // namespace genmesh
