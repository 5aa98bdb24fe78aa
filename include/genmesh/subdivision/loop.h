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
// Numbering (in place, see <genmesh/subdivision/detail/in_place.h>): old
// vertices keep their numbers, then one new vertex per old edge in first-use
// order (faces in face order, each from its lowest vertex); old edges keep
// theirs (the half at their halfedge's source), then the other halves in the
// same order, then three inner edges per old face; each old face becomes the
// middle triangle, the corner triangles are appended.
// Guarantees: positions are computed from the old mesh only, then the
// topology is refined in place with the MutableFaceGraph functions (new
// elements appended, arrays reserved once to the last level's size); the
// same input gives the same mesh on every backend; V' = V + E, F' = 4F, the
// Euler characteristic and the border loops are kept.
// Creases (.crease_sharpness, per edge): an edge of sharpness s ≥ 1 gets its
// midpoint, 0 < s < 1 the blend (1 − s) smooth + s midpoint; an interior
// vertex with two crease edges the crease rule (p + 6v + q)/8, with three or
// more the corner rule (stays), blended likewise by the mean sharpness; the
// halves of a crease edge get s − 1 (DeRose, Kass, Truong, "Subdivision
// surfaces in character animation", SIGGRAPH 1998). Border vertices keep the
// border rule. Tagged corners (.corners) stay where they are.
// Attributes: the visitor's on_vertex_mask receives every new vertex's mask (old
// vertices and weights), so user data can be blended with the same rules.
// Limits: triangles only (refused, mesh unchanged); g's other properties
// are not refined (new elements get their defaults); a backend without
// set_next, or a mesh with removed elements, is refined through the local
// operations (split_edge, split_face: the backend's own), never on a copy;
// positions go through double precision.
#pragma once

#include <genmesh/subdivision/detail/in_place.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace genmesh {

/// The vertex weights of Loop's scheme.
enum class Loop_weights {
  loop,   ///< Loop's original β (CGAL, pmp-library, OpenMesh)
  warren, ///< Warren's simplified β = 3/(8n) (3/16 for n = 3)
};

/// Options of loop_subdivision(). With maps, name the type by its
/// arguments' deduction: genmesh::Loop_options{.iterations = 2, .crease_map = m}.
template <class CreaseMap = Default_map, class CornerMap = Default_map, class VertexPointMap = Default_map>
struct Loop_options {
  int iterations = 1;                            ///< levels to apply (≥ 0)
  Boundary_rule boundary = Boundary_rule::smooth; ///< border rule
  Loop_weights weights = Loop_weights::loop;      ///< interior vertex weights
  /// Edge → crease sharpness (a read-write property map, values convertible
  /// to double; default: no creases): 0 smooth, ∞ sharp, fractional
  /// semi-sharp (DeRose, Kass, Truong 1998). After the call every edge of the
  /// result holds its sharpness (the halves of an edge of sharpness s get
  /// max(0, s − 1), new edges 0), so the map must accept the edges the call
  /// adds: a property map of g, genmesh::make_crease_map(g), or any
  /// map indexed by edge index that grows (boost::vector_property_map).
  CreaseMap crease_map = {};
  /// After the last level (iterations ≥ 1), move every vertex to its limit
  /// position: (1 − nγ) v + γ Σ neighbours, γ = 1/(3/(8β) + n); border and
  /// crease vertices (p + 4v + q)/6, corners stay.
  bool limit = false;
  /// Vertex → bool (read once, before the first level; default: none):
  /// tagged vertices are corners, they keep their position at every level,
  /// like a vertex with three or more crease edges.
  CornerMap corner_map = {};
  /// Vertex → point (read-write; default get(genmesh::vertex_point, g)): the
  /// positions read and written; it must accept the vertices the call adds.
  VertexPointMap vertex_point_map = {};
};

namespace detail::subdivision {

inline double loop_beta(std::uint32_t n, Loop_weights w) {
  if (w == Loop_weights::warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}

/// One Loop level in place on the triangle mesh g of counts n (sharp by
/// edge index, corners as vertex indices), topology through refiner.
template <class G, class O, class V, class Refiner>
void loop_level_in_place(G& g, const std::array<std::size_t, 4>& n, std::vector<double>& sharp,
                         const std::vector<std::uint32_t>& corners, const O& o, V& vis, const Refiner& refiner) {
  using Vec = Eigen::Vector3d;
  constexpr bool masks = visits_vertex_masks<V>;
  const std::size_t nv = n[0], ne = n[1], nf = n[2];
  auto pts = refiner.pts;
  const Stars st = stars(g, sharp, corners);
  const bool creases = !sharp.empty();
  const std::size_t nvb = index_bound(vertex_index, g);
  std::vector<std::uint32_t> number(index_bound(edge_index, g), k_none);
  auto points = refiner.new_points(g, ne);
  Vertex_sums sums{std::vector<Vec>(nvb, Vec::Zero()), std::vector<Vec>(creases ? nvb : 0, Vec::Zero())};
  std::vector<char> border_edge(masks ? ne : 0, 0);
  std::vector<std::uint32_t> src;
  std::vector<double> w;
  auto vi = get(vertex_index, g);
  auto ei = get(edge_index, g);
  auto num = [&](auto v) { return static_cast<std::uint32_t>(get(vi, v)); };
  // Edge points, numbered by first use (faces in face order, each from its
  // lowest vertex), so that the numbering and every sum are canonical.
  std::uint32_t used = 0;
  for_each_canonical_triangle(g, nf, [&](std::size_t, auto& xs) {
    for (int t = 0; t < 3; ++t) {
      const auto x = xs[t];
      const std::size_t k = static_cast<std::size_t>(get(ei, edge(x, g)));
      const Edge_use use = edge_use(g, x, k, number, sharp, masks);
      const double s = creases ? sharp[k] : 0.0;
      const auto [we, ww] = edge_weights(0.375, 0.125, use.border, s);
      const auto vc = target(xs[(t + 1) % 3], g); // this face's wing
      if (use.seen) { // second use: the other wing
        points.add(number[k], ww, to_eigen(get(pts, vc)));
        continue;
      }
      const std::uint32_t i = number[k] = used++;
      first_edge_point(g, pts, x, points, i, we, ww, to_eigen(get(pts, vc)), st, use.border, s, sums);
      if constexpr (masks) {
        border_edge[i] = use.border;
        src.assign({num(source(x, g)), num(target(x, g))});
        w.assign({we, we});
        if (ww != 0) {
          const auto vd = target(next(opposite(x, g), g), g);
          src.push_back(num(vc)), src.push_back(num(vd)), w.push_back(ww), w.push_back(ww);
        }
        vis.on_vertex_mask(static_cast<std::uint32_t>(nv + i), src, w);
      }
    }
  });
  border_edge_points(g, pts, points, number, sums.acc);
  std::vector<Vertex_rule> rules(masks ? nvb : 0);
  {
    std::array<double, 64> beta_of; // β by valence (a cosine per vertex is measurable)
    beta_of.fill(-1.0);
    for (auto v : vertices(g)) {
      const auto i = static_cast<std::uint32_t>(get(vi, v));
      if (i >= nvb) break; // appended (bulk path): iteration is by increasing index
      const std::uint32_t val = st.valence[i];
      if (val < beta_of.size() && beta_of[val] < 0) beta_of[val] = loop_beta(val, o.weights);
      const double beta = val == 0 ? 0.0 : val < beta_of.size() ? beta_of[val] : loop_beta(val, o.weights);
      const Vertex_rule r = vertex_rule(st, i, o.boundary, {1.0 - val * beta, beta, 0, 0});
      Vec p = r.self * to_eigen(get(pts, v)) + r.ring * sums.acc[i];
      if (r.ends != 0) p += r.ends * sums.ends[i];
      sums.acc[i] = p;
      if constexpr (masks) rules[i] = r;
    }
  }
  if constexpr (masks) emit_vertex_masks(g, vis, st, number, used, sharp, border_edge, rules, [](auto...) {});
  write_old_positions(g, pts, sums.acc);
  sums = Vertex_sums{};
  const std::vector<std::uint32_t> other = refiner.one_to_four(g, points, nv, ne, nf, number);
  decrement_creases(sharp, number, other, index_bound(edge_index, g));
}

} // namespace detail::subdivision

/// Applies options.iterations levels of Loop subdivision to the triangle mesh
/// g (positions through get(genmesh::vertex_point, g)). Throws
/// genmesh::invalid_input naming the first non-triangle face (in face
/// iteration order) and leaves g unchanged when g is not a triangle mesh,
/// when options.iterations < 0, when the crease map gives an edge a negative
/// or NaN sharpness, or when an edge has no face on either side.
template <class G, class CreaseMap = Default_map, class CornerMap = Default_map, class VertexPointMap = Default_map,
          class Visitor = Mutation_visitor>
  requires detail::subdivision::Subdividable<G>
Subdivision_result loop_subdivision(G& g, const Loop_options<CreaseMap, CornerMap, VertexPointMap>& options = {},
                                    Visitor&& visitor = {}) {
  namespace ds = detail::subdivision;
  visitor.on_started(std::as_const(g));
  ds::Final_tags tags;
  Subdivision_result r = ds::run_in_place(
      g, options.iterations, "loop_subdivision", options.crease_map, options.corner_map, options.vertex_point_map,
      [](const auto& m) { return ds::face_counts(m, "loop_subdivision", 3); },
      [&](auto& m, const std::array<std::size_t, 4>& n, std::vector<double>& sharp,
          const std::vector<std::uint32_t>& corners, const auto& refiner) {
        ds::loop_level_in_place(m, n, sharp, corners, options, visitor, refiner);
      },
      ds::one_to_four_counts, visitor, &tags);
  if (options.limit && options.iterations > 0) {
    auto interior = [&](const ds::Snapshot& s, std::uint32_t v) -> Eigen::Vector3d {
      const std::uint32_t n = s.valence[v];
      Eigen::Vector3d ring = Eigen::Vector3d::Zero();
      std::uint32_t c = s.vertex_corner[v];
      for (std::uint32_t k = 0; k < n; ++k, c = s.rotate_ccw(c)) ring += s.points[s.head(c)];
      const double gamma = 1.0 / (3.0 / (8.0 * ds::loop_beta(n, options.weights)) + n);
      return (1.0 - n * gamma) * s.points[v] + gamma * ring;
    };
    ds::move_to_limit(g, tags, options.boundary, interior, options.vertex_point_map);
  }
  visitor.on_finished(std::as_const(g));
  return r;
}

} // namespace genmesh
