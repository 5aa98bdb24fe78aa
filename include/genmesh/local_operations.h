// genmesh/local_operations.h — the local operations: the only way genmesh
// algorithms change a mesh.
//
// flip_edge, unflip_edge, split_edge, split_edge_and_triangulate,
// collapse_edge, split_face, join_face, add_center_vertex,
// remove_center_vertex, euler::add_face, euler::remove_face,
// triangulate_face(s), and the modelling operations erase_vertex,
// erase_edge, bevel_vertex, bevel_edge, bevel_face; each with a can_…
// predicate, generic over any MutableFaceGraph (written with set_next,
// set_target, set_face, set_halfedge, add_*/remove_*).
//
// Guarantees:
// - Checked: every operation first decides, from the mesh as it is, whether
//   it keeps a valid 2-manifold halfedge mesh; if not it returns an empty
//   result (std::nullopt, or false) and the mesh is bit-for-bit untouched.
//   All checks run before the first edit.
// - CGAL's conventions: each operation takes the descriptor CGAL::Euler's
//   operation of the same name takes and returns, wrapped in std::optional,
//   what CGAL::Euler returns (where CGAL returns void: flip_edge returns h,
//   remove_face a bool). Where CGAL::Euler has the operation, the
//   low-level edits are the same, in the same order, so on Halfedge_mesh and
//   CGAL::Surface_mesh (which allocate indices identically) the result equals
//   CGAL::Euler's element for element: same indices, same links, same
//   halfedge(v) and halfedge(f) choices, same free-list order. The tests
//   compare every array with CGAL::Euler's.
// - Deterministic: the same operations on the same input give the same
//   mesh on every backend.
// - No allocation per operation, except add_face, bevel_face, and
//   bevel_vertex / bevel_edge at vertices of degree above 8, and
//   triangulate_faces (one list), and the checks of join_face / erase_edge
//   and remove_center_vertex / erase_vertex when the merged face (or hole)
//   has more than 32 corners.
// - Every face visits each vertex once and every border vertex has one
//   border gap, before and after each operation: join_face, erase_edge,
//   remove_center_vertex, erase_vertex and collapse_edge refuse where the
//   edit would make a face (or hole) pass through a vertex twice, and
//   euler::remove_face and join_face into a hole refuse where a vertex would
//   be left with two border gaps (a pinch). CGAL::Euler is looser there (it
//   makes those faces); genmesh refuses, identically on every backend (the
//   incidence backend cannot represent either, docs/local_operations.md).
// - A visitor (<genmesh/visitor.h>) is called after each successful change
//   (its before_* hooks just before); never on a refusal.
// - The operations are function objects (see the end of this header), so
//   argument-dependent lookup never finds them: CGAL's unqualified calls on a
//   genmesh mesh stay CGAL's. add_face(vertices, g) and remove_face(h, g) are
//   spelled genmesh::euler::add_face / remove_face, because genmesh::add_face(g)
//   and remove_face(f, g) are Halfedge_mesh's MutableFaceGraph primitives.
//
// Flipping twice (the seeds' challenge "flipping an edge twice restores every
// array exactly"): flip_edge keeps CGAL::Euler::flip_edge's convention (the
// edge rotates one vertex forward in the face orientation; the tests compare
// it with CGAL array for array), so a second flip_edge gives the same mesh
// (same canonical soup) with the edge's two halfedges and faces exchanged,
// and four restore next, prev, target and face. The exact inverse is
// unflip_edge (one vertex backward): flip_edge then unflip_edge restores
// every next, prev, target and face; halfedge(v) of the two old ends and
// halfedge(f) of the two faces stay where flip_edge moved them, because
// flip_edge overwrites them as CGAL does and keeps no record (no flip can
// recover them). From then on every flip/unflip pair, either order, restores
// every array bit for bit. Tested on Halfedge_mesh with the raw arrays.
//
// Limits:
// - The input must be a valid, manifold halfedge mesh (check_mesh(g).ok());
//   the checks guard against what the operation would break, not against a
//   corrupt input.
// - Geometry: split_edge and split_edge_and_triangulate put the new vertex at
//   the edge midpoint and add_center_vertex at the face centroid (CGAL::Euler
//   leaves the point unset); collapse_edge keeps the surviving vertex's point;
//   bevel_edge slides the split ends along their faces' sides
//   (Bevel_edge_options::fraction). No operation looks at geometry to refuse
//   (no fold-over test): that is the caller's constraint.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/local_operations/primitives.h>
#include <genmesh/exceptions.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>
#include <genmesh/visitor.h>

#include <boost/container/small_vector.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace genmesh {

/// Where bevel_edge puts the vertices of the new face.
struct Bevel_edge_options {
  /// Each end of the edge that splits becomes two vertices; each slides from
  /// the old end along the other side, at that end, of the face it keeps
  /// (face(h) or face(opposite(h))), by this fraction of that side's length
  /// (Blender's "Percent" bevel amount). In [0, 1); 0 leaves them at the old
  /// point (a bevel of width 0, as bevel_vertex and bevel_face make).
  double fraction = 0.25;
};

namespace detail::lo {

// The midpoint of a and b (zero if g has no points).
template <class G>
Eigen::Vector3d midpoint(V<G> a, V<G> b, const G& g) {
  if constexpr (HasVertexPoints<G>) {
    auto pm = get(vertex_point, g);
    using P = point_t<G>;
    return 0.5 * (to_eigen(P(get(pm, a))) + to_eigen(P(get(pm, b))));
  } else {
    return Eigen::Vector3d::Zero();
  }
}

template <class G>
void set_point(V<G> v, const Eigen::Vector3d& p, G& g) {
  if constexpr (HasVertexPoints<G>) put(get(vertex_point, g), v, from_eigen<point_t<G>>(p));
}

// Puts v at the centroid of the corners of face(h).
template <class G>
void set_centroid(V<G> v, H<G> h, G& g) {
  if constexpr (HasVertexPoints<G>) {
    auto pm = get(vertex_point, g);
    using P = point_t<G>;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    int n = 0;
    H<G> x = h;
    do {
      c += to_eigen(P(get(pm, target(x, g))));
      ++n;
      x = next(x, g);
    } while (x != h);
    put(pm, v, from_eigen<P>(c / n));
  }
}

// ---------------------------------------------------------------------------
// flip_edge
// ---------------------------------------------------------------------------

/// Whether flip_edge(h, g) would flip: both sides of h are triangles (not
/// holes), their opposite corners differ and are not already joined by an
/// edge, and neither end of h is an inner vertex of degree 3 (it would be
/// left with two edges). A border end may be left with two (a corner).
template <MutableFaceGraph G>
bool can_flip_edge(halfedge_descriptor_t<G> h, const G& g) {
  namespace lo = detail::lo;
  const auto oh = opposite(h, g);
  if (lo::border(h, g) || lo::border(oh, g)) return false;
  if (!lo::triangle_at(h, g) || !lo::triangle_at(oh, g)) return false;
  const auto s2 = target(next(h, g), g), t2 = target(next(oh, g), g);
  if (s2 == t2) return false;
  if (lo::find_halfedge(s2, t2, g) != lo::null_h<G>()) return false;
  // The ends lose an edge: an inner end of degree 3 would be left with 2
  // (possible next to non-triangles; around triangles only, the new edge
  // would exist already).
  for (const auto v : {source(h, g), target(h, g)})
    if (lo::degree_below(v, 4, g) && !lo::border_vertex(v, g)) return false;
  return true;
}

/// Flips the edge of h inside the quadrilateral of its two triangles, as
/// CGAL::Euler::flip_edge: the edge rotates by one vertex in the direction of
/// the face orientation. Before: h goes s → t, next(h) ends at s2, next(opposite(h))
/// at t2. After: h goes s2 → t2, face(h) and face(opposite(h)) are kept
/// (face(h) = (s2, t2, t), halfedge(face(h)) == h), halfedge(s) and
/// halfedge(t) move off the edge if they were on it. Creates and removes
/// nothing. unflip_edge(h) is its inverse (see the top of this header).
/// \returns h, or nullopt (refused, see can_flip_edge).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> flip_edge(halfedge_descriptor_t<G> h, G& g, Visitor&& visitor = {}) {
  if (!can_flip_edge(h, g)) return std::nullopt;
  const auto s = source(h, g), t = target(h, g);
  const auto nh = next(h, g), nnh = next(nh, g), oh = opposite(h, g), noh = next(oh, g), nnoh = next(noh, g);
  const auto s2 = target(nh, g), t2 = target(noh, g);
  const auto fh = face(h, g), foh = face(oh, g);
  if (halfedge(s, g) == oh) set_halfedge(s, nnh, g);
  if (halfedge(t, g) == h) set_halfedge(t, nnoh, g);
  set_next(h, nnoh, g);
  set_next(oh, nnh, g);
  set_target(h, t2, g);
  set_target(oh, s2, g);
  set_next(nh, h, g);
  set_next(noh, oh, g);
  set_next(nnoh, nh, g);
  set_next(nnh, noh, g);
  set_face(nnoh, fh, g);
  set_face(nnh, foh, g);
  set_halfedge(fh, h, g);
  set_halfedge(foh, oh, g);
  visitor.on_flip(h, std::as_const(g));
  return h;
}

/// Whether unflip_edge(h, g) would rotate the edge back: the checks of
/// can_flip_edge, which are the same for either halfedge of the edge.
template <MutableFaceGraph G>
bool can_unflip_edge(halfedge_descriptor_t<G> h, const G& g) {
  return can_flip_edge(opposite(h, g), g);
}

/// The inverse of flip_edge: rotates the edge of h by one vertex *against*
/// the face orientation. Before: h goes a → b, next(h) ends at c,
/// next(opposite(h)) at d. After: h goes d → c, face(h) = (d, c, a) and
/// face(opposite(h)) = (c, d, b) are kept, halfedge(face(h)) == h,
/// halfedge(face(opposite(h))) == opposite(h), and halfedge(a) / halfedge(b)
/// move off the edge if they were on it. Creates and removes nothing.
///
/// unflip_edge(h) after flip_edge(h) puts every next, prev, target and face
/// back exactly. halfedge(v) of the edge's two old ends and halfedge(f) of
/// its two faces stay where flip_edge put them (flip_edge overwrites them as
/// CGAL::Euler does and keeps no record of the old choice); from then on,
/// every flip_edge/unflip_edge pair, in either order, restores every array
/// bit for bit (tested on Halfedge_mesh, raw arrays compared).
/// \returns h, or nullopt (refused, see can_unflip_edge).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> unflip_edge(halfedge_descriptor_t<G> h, G& g, Visitor&& visitor = {}) {
  if (!can_unflip_edge(h, g)) return std::nullopt;
  const auto a = source(h, g), b = target(h, g);
  const auto nh = next(h, g), nnh = next(nh, g), oh = opposite(h, g), noh = next(oh, g), nnoh = next(noh, g);
  const auto c = target(nh, g), d = target(noh, g);
  const auto fh = face(h, g), foh = face(oh, g);
  if (halfedge(a, g) == oh) set_halfedge(a, nnh, g);
  if (halfedge(b, g) == h) set_halfedge(b, nnoh, g);
  set_next(h, nnh, g);
  set_next(oh, nnoh, g);
  set_target(h, c, g);
  set_target(oh, d, g);
  set_next(nnh, noh, g);
  set_next(nnoh, nh, g);
  set_next(noh, h, g);
  set_next(nh, oh, g);
  set_face(noh, fh, g);
  set_face(nh, foh, g);
  set_halfedge(fh, h, g);
  set_halfedge(foh, oh, g);
  visitor.on_flip(h, std::as_const(g));
  return h;
}

// ---------------------------------------------------------------------------
// split_edge, split_edge_and_triangulate
// ---------------------------------------------------------------------------

/// True for any halfedge of a valid mesh (false for the null halfedge): an
/// edge can always be split.
template <MutableFaceGraph G>
bool can_split_edge(halfedge_descriptor_t<G> h, const G& /*g*/) {
  return h != detail::lo::null_h<G>();
}

/// Inserts a new vertex w on the edge of h (u → v), as CGAL::Euler::split_edge:
/// one new vertex, one new edge; the faces on both sides get one more side.
/// \returns hnew, going u → w, with next(hnew) == h (h now goes w → v) and
/// face(hnew) == face(h); opposite(hnew) follows opposite(h). As CGAL sets
/// them, halfedge(w) == hnew and halfedge(u) == opposite(hnew) (even if u is
/// a border vertex and opposite(hnew) is not a border halfedge).
/// w is placed at the midpoint of u and v.
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> split_edge(halfedge_descriptor_t<G> h, G& g, Visitor&& visitor = {}) {
  if (!can_split_edge(h, g)) return std::nullopt;
  // In a valid mesh next(prev(h)) == h, face(prev(h)) == face(h) and
  // target(prev(h)) == target(opposite(h)): read those instead (fewer cache lines).
  const auto h1 = prev(h, g), h2 = opposite(h, g);
  const auto u = target(h2, g), v = target(h, g);
  const auto fh = face(h, g);
  const auto hnew = halfedge(add_edge(g), g);
  const auto hnewopp = opposite(hnew, g);
  const auto w = add_vertex(g);
  // CGAL: opposite(split_vertex(prev(h), opposite(h))).
  set_next(hnew, next(h2, g), g);
  set_next(h2, hnew, g);
  set_face(hnew, face(h2, g), g);
  set_next(hnewopp, h, g);
  set_next(h1, hnewopp, g);
  set_face(hnewopp, fh, g);
  set_target(hnew, u, g);
  set_target(hnewopp, w, g);
  set_target(h2, w, g);
  set_halfedge(u, hnew, g);
  set_halfedge(w, hnewopp, g);
  // The points last: read before the edits, their cache misses stalled the
  // edits behind them (measured 10-20 % slower in random edge order).
  detail::lo::set_point(w, detail::lo::midpoint(u, v, g), g);
  visitor.on_split_edge(hnewopp, std::as_const(g));
  return hnewopp;
}

/// Whether split_edge_and_triangulate(h, g) applies: every face on either
/// side of h is a triangle.
template <MutableFaceGraph G>
bool can_split_edge_and_triangulate(halfedge_descriptor_t<G> h, const G& g) {
  namespace lo = detail::lo;
  if (!can_split_edge(h, g)) return false;
  const auto oh = opposite(h, g);
  if (lo::border(h, g) && lo::border(oh, g)) return false;
  return (lo::border(h, g) || lo::triangle_at(h, g)) && (lo::border(oh, g) || lo::triangle_at(oh, g));
}

/// The triangle-mesh edge split: a new vertex w at the midpoint of the edge of
/// h (u → v), joined to the opposite corner of each incident triangle, so
/// two triangles become four (one becomes two on the boundary). split_edge,
/// then split_face on the side of h, then on the other side.
/// \returns hnew (u → w, next(hnew) == h, as split_edge), or nullopt if a side
/// of h is not a triangle.
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> split_edge_and_triangulate(halfedge_descriptor_t<G> h, G& g,
                                                                   Visitor&& visitor = {}) {
  namespace lo = detail::lo;
  if (!can_split_edge_and_triangulate(h, g)) return std::nullopt;
  const auto oh = opposite(h, g);
  const bool side_h = !lo::border(h, g), side_oh = !lo::border(oh, g);
  Mutation_visitor quiet;
  const auto hnew = *split_edge(h, g, quiet);
  // Now hnew: u → w, h: w → v; oh: v → w, opposite(hnew): w → u.
  if (side_h) lo::split_face_raw(hnew, next(h, g), g);
  if (side_oh) lo::split_face_raw(oh, next(opposite(hnew, g), g), g);
  visitor.on_split_edge(hnew, std::as_const(g));
  return hnew;
}

// ---------------------------------------------------------------------------
// collapse_edge
// ---------------------------------------------------------------------------

/// The link condition's tests after the common-neighbour one (shared with
/// backends that find common neighbours natively): no isolated triangle on
/// either side; when e = edge(pq) is inner, not both ends on the border, not
/// an edge of a tetrahedron or of a two-triangle pillow.
// both_ends_on_border(): whether p and q are both border vertices, asked
// only when e is inner (a caller that has walked the ends passes what it
// found).
template <class G, class Both_ends_on_border>
bool link_condition_beyond_neighbours(halfedge_descriptor_t<G> pq, const G& g,
                                      const Both_ends_on_border& both_ends_on_border) {
  const auto qp = opposite(pq, g);
  const bool top = !border(pq, g), bottom = !border(qp, g);
  if (top && border(opposite(next(pq, g), g), g) && border(opposite(prev(pq, g), g), g)) return false;
  if (bottom && border(opposite(next(qp, g), g), g) && border(opposite(prev(qp, g), g), g)) return false;
  if (top && bottom) {
    if (both_ends_on_border()) return false;
    if (tetrahedron_at(pq, g)) return false;
    if (next(pq, g) == opposite(prev(qp, g), g) && prev(pq, g) == opposite(next(qp, g), g)) return false;
  }
  return true;
}
template <class G>
bool link_condition_beyond_neighbours(halfedge_descriptor_t<G> pq, const G& g) {
  return link_condition_beyond_neighbours(
      pq, g, [&] { return border_vertex(source(pq, g), g) && border_vertex(target(pq, g), g); });
}

// Appends v's neighbours (the sources of the halfedges into v, from
// halfedge(v) round) to `out`; returns whether v is a border vertex (an
// isolated v counts as one, as border_vertex). The link condition lists q's
// neighbours once with it (find_halfedge(k, q) for each neighbour k of p would
// walk q's fan again each time). Inlined: a call costs can_collapse_edge 5 %
// more instructions (the vector's spill and reload).
template <class G, class Out>
[[gnu::always_inline]] inline bool push_neighbours(V<G> v, const G& g, Out& out) {
  const auto s = halfedge(v, g);
  if (s == null_h<G>()) return true;
  bool on_border = false;
  auto y = s;
  do {
    out.push_back(source(y, g));
    on_border |= border(y, g);
    y = opposite(next(y, g), g);
  } while (y != s);
  return on_border;
}

/// The link condition of CGAL::Euler::does_satisfy_link_condition (Dey et
/// al. 1999): every vertex adjacent to both ends of e forms a face with e; no
/// isolated triangle; not both ends on the border when e is inner; not an
/// edge of a tetrahedron or of a two-triangle pillow.
template <MutableFaceGraph G>
bool does_satisfy_link_condition(edge_descriptor_t<G> e, const G& g) {
  namespace lo = detail::lo;
  const auto pq = halfedge(e, g), qp = opposite(pq, g);
  const auto p = target(qp, g), q = target(pq, g);
  const auto vl = target(next(pq, g), g), vr = target(next(qp, g), g);
  const bool top = !lo::border(pq, g), bottom = !lo::border(qp, g);
  // Common neighbours of p and q must be the opposite corners of e's faces
  // (q's neighbours listed once, on the stack up to 16).
  boost::container::small_vector<vertex_descriptor_t<G>, 16> around_q;
  lo::push_neighbours(q, g, around_q);
  const auto start = halfedge(p, g);
  auto x = start;
  do {
    const auto k = source(x, g);
    if (k != q && !((k == vl && top) || (k == vr && bottom)) &&
        std::find(around_q.begin(), around_q.end(), k) != around_q.end())
      return false;
    x = opposite(next(x, g), g);
  } while (x != start);
  return lo::link_condition_beyond_neighbours(pq, g);
}

/// Whether collapse_edge(e, g) would collapse: the faces of e are triangles
/// (holes allowed on one side), e is not an isolated edge, the link condition
/// holds, each opposite corner keeps at least two edges, and no other face
/// holds both ends of e (a polygon with p and q as non-adjacent corners: it
/// would pass through q twice; the link condition does not see it, and
/// CGAL::Euler::collapse_edge makes that face). Cost: the link condition plus
/// the sides of p's faces.
template <MutableFaceGraph G>
bool can_collapse_edge(edge_descriptor_t<G> e, const G& g) {
  namespace lo = detail::lo;
  const auto pq = halfedge(e, g), qp = opposite(pq, g);
  const bool top = !lo::border(pq, g), bottom = !lo::border(qp, g);
  if (!top && !bottom) return false;
  // The corners' degrees from the face's side (fan_below): walking from
  // halfedge(corner) would read the two-ring (the costliest part of this
  // test in simplification, where everything else is the edge's own star).
  if (top && (!lo::triangle_at(pq, g) || lo::fan_below(next(pq, g), 3, g))) return false;
  if (bottom && (!lo::triangle_at(qp, g) || lo::fan_below(next(qp, g), 3, g))) return false;
  // does_satisfy_link_condition(e, g), and the corners of p's other faces,
  // in one walk around q and one around p (the separate tests walked p's fan
  // three times: its neighbours, whether it is on the border, its faces).
  const auto q = target(pq, g);
  const auto vl = target(next(pq, g), g), vr = target(next(qp, g), g);
  const auto ft = face(pq, g), fb = face(qp, g);
  boost::container::small_vector<vertex_descriptor_t<G>, 16> around_q;
  const bool q_border = lo::push_neighbours(q, g, around_q);
  bool p_border = false;
  auto x = qp; // the halfedges into p
  do {
    // Common neighbours of p and q must be the opposite corners of e's faces.
    const auto k = source(x, g);
    if (k != q && !((k == vl && top) || (k == vr && bottom)) &&
        std::find(around_q.begin(), around_q.end(), k) != around_q.end())
      return false;
    const auto f = face(x, g);
    if (f == lo::null_f<G>()) {
      p_border = true;
    } else if (f != ft && f != fb) {
      // The corners of p's other faces that are not p's neighbours: the
      // targets from next(next(x)) to before prev(x). A triangle has none
      // (prev(x) == next(next(x)); prev shares x's cache line on the pointer
      // backends).
      const auto last = prev(x, g);
      for (auto y = next(next(x, g), g); y != last; y = next(y, g))
        if (target(y, g) == q) return false;
    }
    x = opposite(next(x, g), g);
  } while (x != qp);
  return lo::link_condition_beyond_neighbours(pq, g, [&] { return p_border && q_border; });
}

// collapse_edge's work without its test (below).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
vertex_descriptor_t<G> collapse_edge_unchecked(edge_descriptor_t<G> e, G& g, Visitor&& visitor = {});

/// Collapses e into its target, as CGAL::Euler::collapse_edge: with pq =
/// halfedge(e, g), p = source(pq) and q = target(pq), removes p, e, the
/// (one or two) triangles of e and, in each, the edge at p (pt on top, merged
/// into tq; qb at the bottom, merged into bp), in CGAL's order. Halfedges that
/// had p as target now have q. q keeps its point.
/// \returns q, or nullopt (refused, see can_collapse_edge).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<vertex_descriptor_t<G>> collapse_edge(edge_descriptor_t<G> e, G& g, Visitor&& visitor = {}) {
  if (!can_collapse_edge(e, g)) return std::nullopt;
  return collapse_edge_unchecked(e, g, std::forward<Visitor>(visitor));
}

// collapse_edge without its test, for a caller that has just made it
// (internal, like everything in detail::lo: see collapse_tested_edge).
// Precondition: can_collapse_edge(e, g).
template <MutableFaceGraph G, class Visitor>
vertex_descriptor_t<G> collapse_edge_unchecked(edge_descriptor_t<G> e, G& g, Visitor&& visitor) {
  namespace lo = detail::lo;
  const auto pq = halfedge(e, g), qp = opposite(pq, g);
  visitor.before_collapse(pq, std::as_const(g));
  const auto pt = opposite(prev(pq, g), g), qb = opposite(prev(qp, g), g);
  const bool top = !lo::border(pq, g), bottom = !lo::border(qp, g);
  const bool top_left = top && !lo::border(pt, g), bottom_right = bottom && !lo::border(qb, g);
  const auto q = target(pq, g), p = source(pq, g);
  bool p_erased = false;
  if (top) {
    if (top_left) {
      lo::join_face_raw(pt, g);
    } else {
      lo::remove_face_raw(opposite(pt, g), g);
      if (!bottom) p_erased = true;
    }
  }
  if (bottom) {
    if (bottom_right) {
      lo::join_face_raw(qb, g);
    } else {
      if (!top) {
        p_erased = true;
        // q's descriptor must survive: remove_face frees the isolated one.
        lo::swap_vertices_raw(p, q, g);
      }
      lo::remove_face_raw(opposite(qb, g), g);
    }
  }
  if (!p_erased) lo::join_vertex_raw(pq, g);
  visitor.on_collapse(q, std::as_const(g));
  return q;
}

// ---------------------------------------------------------------------------
// split_face, join_face
// ---------------------------------------------------------------------------

/// Whether split_face(h1, h2, g) would split: h1 != h2 on the same face (not
/// a hole), not consecutive, and no edge joins their targets yet.
template <MutableFaceGraph G>
bool can_split_face(halfedge_descriptor_t<G> h1, halfedge_descriptor_t<G> h2, const G& g) {
  namespace lo = detail::lo;
  if (h1 == h2 || lo::border(h1, g) || face(h1, g) != face(h2, g)) return false;
  if (next(h1, g) == h2 || next(h2, g) == h1) return false;
  return lo::find_halfedge(target(h1, g), target(h2, g), g) == lo::null_h<G>();
}

/// Splits face(h1) by a new edge from target(h1) to target(h2), as
/// CGAL::Euler::split_face: one new edge, one new face.
/// \returns h3, with next(h1) == h3, going target(h1) → target(h2); face(h3)
/// is the old face, the new face is face(opposite(h3)) (next(h2) ==
/// opposite(h3)). Or nullopt (see can_split_face).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> split_face(halfedge_descriptor_t<G> h1, halfedge_descriptor_t<G> h2, G& g,
                                                   Visitor&& visitor = {}) {
  if (!can_split_face(h1, h2, g)) return std::nullopt;
  const auto h3 = detail::lo::split_face_raw(h1, h2, g);
  visitor.on_split_face(h3, std::as_const(g));
  return h3;
}

/// Whether join_face(h, g) would join: the two sides of h are different faces
/// (at most one a hole), both ends of h keep at least two edges, and the
/// merged cycle stays simple. Unlike CGAL::Euler::join_face, which joins
/// anyway, genmesh refuses when
/// - the two sides share another edge (the merged face would lie on both
///   sides of it);
/// - they share another vertex (the merged face, or hole, would pass through
///   it twice);
/// - face(h) is a hole and another corner of face(opposite(h)) is on a
///   border: on this hole it would be visited twice, on another one it would
///   be left with two border gaps (a pinch).
/// Cost: the two cycles (the hole's too when face(opposite(h)) is the hole),
/// plus the degrees of face(opposite(h))'s corners when joining into a hole.
template <MutableFaceGraph G>
bool can_join_face(halfedge_descriptor_t<G> h, const G& g) {
  namespace lo = detail::lo;
  const auto oh = opposite(h, g);
  if (lo::border(h, g) && lo::border(oh, g)) return false;
  const auto f = face(h, g);
  if (f == face(oh, g)) return false;
  if (lo::degree_below(source(h, g), 3, g) || lo::degree_below(target(h, g), 3, g)) return false;
  for (auto x = next(oh, g); x != oh; x = next(x, g))
    if (face(opposite(x, g), g) == f) return false;
  return lo::join_keeps_a_simple_cycle(h, g);
}

/// Removes the edge of h, merging face(opposite(h)) into face(h), as
/// CGAL::Euler::join_face (if face(h) is a hole, face(opposite(h)) joins the
/// hole). Removes one edge and one face.
/// \returns prev(h) (taken before the join), or nullopt (see can_join_face).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> join_face(halfedge_descriptor_t<G> h, G& g, Visitor&& visitor = {}) {
  if (!can_join_face(h, g)) return std::nullopt;
  visitor.before_join_face(h, std::as_const(g));
  return detail::lo::join_face_raw(h, g);
}

// ---------------------------------------------------------------------------
// add_center_vertex, remove_center_vertex
// ---------------------------------------------------------------------------

/// Whether add_center_vertex(h, g) applies: h is not a border halfedge.
template <MutableFaceGraph G>
bool can_add_center_vertex(halfedge_descriptor_t<G> h, const G& g) {
  return !detail::lo::border(h, g);
}

/// Adds a vertex c inside face(h) joined to every corner, as
/// CGAL::Euler::add_center_vertex: an n-gon becomes n triangles (one new
/// vertex, n new edges, n − 1 new faces; face(h) is kept for h's triangle).
/// c is placed at the centroid of the corners.
/// \returns the new halfedge from target(h) to c (next(h) == it), or nullopt.
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> add_center_vertex(halfedge_descriptor_t<G> h, G& g,
                                                          Visitor&& visitor = {}) {
  if (!can_add_center_vertex(h, g)) return std::nullopt;
  const auto f = face(h, g);
  const auto hnew = halfedge(add_edge(g), g);
  const auto vnew = add_vertex(g);
  detail::lo::set_centroid(vnew, h, g);
  set_next(hnew, opposite(hnew, g), g);
  set_target(hnew, vnew, g);
  set_halfedge(vnew, hnew, g);
  set_next(opposite(hnew, g), next(h, g), g);
  set_next(h, hnew, g);
  set_target(opposite(hnew, g), target(h, g), g);
  set_face(hnew, f, g);
  set_halfedge(f, h, g);
  auto h2 = next(opposite(hnew, g), g);
  while (next(h2, g) != hnew) {
    const auto gnew = halfedge(add_edge(g), g);
    set_next(gnew, next(hnew, g), g);
    set_next(hnew, opposite(gnew, g), g);
    set_target(gnew, target(hnew, g), g);
    set_next(opposite(gnew, g), next(h2, g), g);
    set_next(h2, gnew, g);
    set_target(opposite(gnew, g), target(h2, g), g);
    const auto fnew = add_face(g);
    set_face(h2, fnew, g);
    set_face(gnew, fnew, g);
    set_face(next(gnew, g), fnew, g);
    set_halfedge(fnew, h2, g);
    h2 = next(opposite(gnew, g), g);
  }
  set_face(next(hnew, g), f, g);
  set_halfedge(target(hnew, g), hnew, g);
  visitor.on_add_center_vertex(hnew, std::as_const(g));
  return hnew;
}

/// Whether remove_center_vertex(h, g) applies: target(h) is an inner vertex
/// of degree ≥ 3, the faces beyond its star are not all one and the same
/// face (which would leave two faces glued back to back, as at a vertex of a
/// tetrahedron), and the link visits each vertex once (else the merged face
/// would pass through it twice; CGAL::Euler::remove_center_vertex makes that
/// face). Cost: the sides of v's faces.
template <MutableFaceGraph G>
bool can_remove_center_vertex(halfedge_descriptor_t<G> h, const G& g) {
  return detail::lo::center_vertex_removable(h, g);
}

/// Removes target(h), its edges and faces, leaving one face bounded by its
/// link, as CGAL::Euler::remove_center_vertex (the inverse of
/// add_center_vertex). The surviving face is face(prev(h)).
/// \returns prev(h) (taken before), or nullopt (see can_remove_center_vertex).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> remove_center_vertex(halfedge_descriptor_t<G> h, G& g,
                                                             Visitor&& visitor = {}) {
  namespace lo = detail::lo;
  if (!can_remove_center_vertex(h, g)) return std::nullopt;
  visitor.before_remove_center_vertex(h, std::as_const(g));
  auto h2 = opposite(next(h, g), g);
  const auto hret = prev(h, g);
  while (h2 != h) {
    const auto gprev = prev(h2, g);
    set_halfedge(target(gprev, g), gprev, g);
    lo::skip_tip(gprev, g);
    remove_face(face(h2, g), g);
    const auto gnext = opposite(next(h2, g), g);
    remove_edge(edge(h2, g), g);
    h2 = gnext;
  }
  set_halfedge(target(hret, g), hret, g);
  lo::skip_tip(hret, g);
  remove_vertex(target(h, g), g);
  remove_edge(edge(h, g), g);
  const auto f = face(hret, g);
  auto x = hret;
  do {
    set_face(x, f, g);
    x = next(x, g);
  } while (x != hret);
  set_halfedge(f, hret, g);
  return hret;
}

// ---------------------------------------------------------------------------
// add_face, remove_face
// ---------------------------------------------------------------------------

// What add_face needs to know about the new face's sides.
template <class G>
struct Face_plan {
  boost::container::small_vector<V<G>, 8> vertices;
  boost::container::small_vector<H<G>, 8> halfedges; // existing u_i → u_{i+1}, or null
};

// Decides add_face without changing g; fills plan.
template <class G, class Range>
bool plan_face(const Range& range, const G& g, Face_plan<G>& plan) {
  for (const auto& v : range) plan.vertices.push_back(v);
  const std::size_t n = plan.vertices.size();
  if (n < 3) return false;
  auto sorted = plan.vertices;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  plan.halfedges.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto v = plan.vertices[i];
    if (v == boost::graph_traits<G>::null_vertex()) return false;
    if (halfedge(v, g) != null_h<G>() && !border_vertex(v, g)) return false;
    const auto hv = find_halfedge(v, plan.vertices[(i + 1) % n], g);
    if (hv != null_h<G>() && !border(hv, g)) return false;
    plan.halfedges[i] = hv;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t ii = (i + 1) % n;
    const bool new_prev = plan.halfedges[i] == null_h<G>(), new_next = plan.halfedges[ii] == null_h<G>();
    const auto v = plan.vertices[ii];
    // Two existing sides must already follow each other (CGAL would re-link
    // a patch here; we refuse).
    if (!new_prev && !new_next && next(plan.halfedges[i], g) != plan.halfedges[ii]) return false;
    // Two new sides at a vertex that has edges: a second fan (non-manifold).
    if (new_prev && new_next && halfedge(v, g) != null_h<G>()) return false;
  }
  return true;
}

/// Whether add_face(vertices, g) would add the face: at least three distinct
/// vertices, each isolated or on the border, each existing side a border
/// halfedge, and the face fits without re-linking (two existing sides at a
/// vertex already consecutive on the border) and without making a vertex
/// non-manifold (two new sides at a vertex that already has edges).
template <MutableFaceGraph G, class Range>
bool can_add_face(const Range& vertices, const G& g) {
  detail::lo::Face_plan<G> plan;
  return detail::lo::plan_face(vertices, g, plan);
}

/// Adds the face with the given vertices in order, as CGAL::Euler::add_face:
/// missing edges are created, existing border halfedges reused; each vertex's
/// halfedge is then set to a border halfedge if it has one.
/// \returns the new face, or nullopt (see can_add_face). Unlike CGAL, a face
/// that needs a patch re-linked or makes a non-manifold vertex is refused.
template <MutableFaceGraph G, class Range, class Visitor = Mutation_visitor>
std::optional<face_descriptor_t<G>> add_face(const Range& vertices, G& g, Visitor&& visitor = {}) {
  namespace lo = detail::lo;
  using H = halfedge_descriptor_t<G>;
  lo::Face_plan<G> plan;
  if (!lo::plan_face(vertices, g, plan)) return std::nullopt;
  const std::size_t n = plan.vertices.size();
  boost::container::small_vector<bool, 8> is_new(n);
  for (std::size_t i = 0; i < n; ++i) is_new[i] = plan.halfedges[i] == lo::null_h<G>();
  auto& hs = plan.halfedges;
  boost::container::small_vector<std::pair<H, H>, 24> next_cache;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_new[i]) continue;
    const auto e = add_edge(g);
    hs[i] = halfedge(e, g);
    set_target(hs[i], plan.vertices[(i + 1) % n], g);
    set_target(opposite(hs[i], g), plan.vertices[i], g);
    set_face(opposite(hs[i], g), lo::null_f<G>(), g);
  }
  const auto f = add_face(g);
  set_halfedge(f, hs[n - 1], g);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t ii = (i + 1) % n;
    const auto v = plan.vertices[ii];
    const H inner_prev = hs[i], inner_next = hs[ii];
    const unsigned id = (is_new[i] ? 1u : 0u) | (is_new[ii] ? 2u : 0u);
    if (id != 0) {
      const H outer_prev = opposite(inner_next, g), outer_next = opposite(inner_prev, g);
      if (id == 1) {
        const H border_prev = prev(inner_next, g);
        next_cache.emplace_back(border_prev, outer_next);
        set_halfedge(v, border_prev, g);
      } else if (id == 2) {
        const H border_next = next(inner_prev, g);
        next_cache.emplace_back(outer_prev, border_next);
        set_halfedge(v, outer_prev, g);
      } else { // both new: v was isolated (plan_face)
        set_halfedge(v, outer_prev, g);
        next_cache.emplace_back(outer_prev, outer_next);
      }
      next_cache.emplace_back(inner_prev, inner_next);
    }
    set_face(hs[i], f, g);
  }
  for (const auto& [a, b] : next_cache) set_next(a, b, g);
  for (std::size_t i = 0; i < n; ++i) {
    // CGAL's adjust_incoming_halfedge: the first border halfedge around v.
    const auto v = plan.vertices[i];
    H x = halfedge(v, g);
    if (x == lo::null_h<G>()) continue;
    const H start = x;
    do {
      if (lo::border(x, g)) {
        set_halfedge(v, x, g);
        break;
      }
      x = opposite(next(x, g), g);
    } while (x != start);
  }
  visitor.on_add_face(f, std::as_const(g));
  return f;
}

/// Whether remove_face(h, g) applies: h is not a border halfedge, and no
/// corner of face(h) that is already on the border has both its sides in the
/// face inner (removing the face would give that vertex a second border gap,
/// a pinch; CGAL::Euler::remove_face makes it). Cost: the face's degree plus
/// its border corners' degrees.
template <MutableFaceGraph G>
bool can_remove_face(halfedge_descriptor_t<G> h, const G& g) {
  return !detail::lo::border(h, g) && detail::lo::removal_keeps_border_simple(h, g);
}

/// Removes face(h), as CGAL::Euler::remove_face: its sides become border;
/// edges with no face left and vertices with no edge left are removed too.
/// \returns true, or false (refused, see can_remove_face: h is a border
/// halfedge, or the removal would pinch a border vertex).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
bool remove_face(halfedge_descriptor_t<G> h, G& g, Visitor&& visitor = {}) {
  if (!can_remove_face(h, g)) return false;
  visitor.before_remove_face(h, std::as_const(g));
  detail::lo::remove_face_raw(h, g);
  return true;
}

// ---------------------------------------------------------------------------
// triangulate_face, triangulate_faces
// ---------------------------------------------------------------------------

// The halfedge of f targeting its lowest-index vertex.
template <class G>
H<G> lowest_corner(F<G> f, const G& g) {
  const auto index = get(vertex_index, g);
  const H<G> start = halfedge(f, g);
  H<G> best = start, x = next(start, g);
  while (x != start) {
    if (get(index, target(x, g)) < get(index, target(best, g))) best = x;
    x = next(x, g);
  }
  return best;
}

/// Whether triangulate_face(f, g) would succeed: f is a face and none of the
/// fan's diagonals (from its lowest-index vertex) exists already.
template <MutableFaceGraph G>
  requires HasIndexMap<G, vertex_index_t>
bool can_triangulate_face(face_descriptor_t<G> f, const G& g) {
  namespace lo = detail::lo;
  if (f == lo::null_f<G>()) return false;
  const auto h0 = lo::lowest_corner(f, g);
  const auto v0 = target(h0, g);
  // Diagonals v0 → target(x) for x from next(next(h0)) up to prev(prev(h0)).
  for (auto x = next(next(h0, g), g); next(x, g) != h0; x = next(x, g))
    if (lo::find_halfedge(v0, target(x, g), g) != lo::null_h<G>()) return false;
  return true;
}

/// Triangulates f by a fan from its lowest-index vertex v0 (deterministic
/// across backends), with split_face: an n-gon gives n − 2 triangles,
/// n − 3 new edges and faces; f keeps the last triangle. A triangle is left
/// as is. The visitor sees each split (on_split_face).
/// \returns true, or false (refused: a diagonal exists; nothing changed).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
  requires HasIndexMap<G, vertex_index_t>
bool triangulate_face(face_descriptor_t<G> f, G& g, Visitor&& visitor = {}) {
  namespace lo = detail::lo;
  if (!can_triangulate_face(f, g)) return false;
  const auto h0 = lo::lowest_corner(f, g);
  while (next(next(next(h0, g), g), g) != h0) {
    const auto h3 = lo::split_face_raw(h0, next(next(h0, g), g), g);
    visitor.on_split_face(h3, std::as_const(g));
  }
  return true;
}

// ---------------------------------------------------------------------------
// bevel_face
// ---------------------------------------------------------------------------

/// Whether bevel_face(f, g) applies: f is a face.
template <MutableFaceGraph G>
bool can_bevel_face(face_descriptor_t<G> f, const G& /*g*/) {
  return f != null_f<G>();
}

/// Insets face f (the seeds' bevel_face, an extrusion of height 0): f, with
/// corners v_0 … v_{n−1} from halfedge(f), becomes the inner face of n new
/// vertices w_i (at v_i's point), joined to the old corners by n spoke edges
/// v_i–w_i; between them, n new quads (v_i, v_{i+1}, w_{i+1}, w_i) take over
/// f's old sides. Adds n vertices, 2n edges and n faces, in corner order
/// starting at halfedge(f) (vertices, then spoke/ring edge pairs, then faces).
/// \returns f (now bounded by the w_i; halfedge(f) targets w_1), or nullopt
/// if f is null. Move the w_i (e.g. inward and along the normal) to bevel.
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<face_descriptor_t<G>> bevel_face(face_descriptor_t<G> f, G& g, Visitor&& visitor = {}) {
  if (!can_bevel_face(f, g)) return std::nullopt;
  using Hd = H<G>;
  using Vd = V<G>;
  using Fd = F<G>;
  // Collect: the sides h_i = v_i → v_{i+1}.
  boost::container::small_vector<Hd, 8> side;
  {
    const Hd start = halfedge(f, g);
    Hd x = next(start, g);
    do {
      side.push_back(x);
      x = next(x, g);
    } while (x != next(start, g));
  }
  const std::size_t n = side.size();
  // Create.
  boost::container::small_vector<Vd, 8> w(n);
  boost::container::small_vector<Hd, 8> spoke(n), ring(n); // spoke_i: v_i → w_i; ring_i: w_i → w_{i+1}
  boost::container::small_vector<Fd, 8> quad(n);
  for (std::size_t i = 0; i < n; ++i) {
    w[i] = add_vertex(g);
    if constexpr (HasVertexPoints<G>) {
      auto pm = get(vertex_point, g);
      const Vd vi = source(side[i], g);
      put(pm, w[i], point_t<G>(get(pm, vi)));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    spoke[i] = halfedge(add_edge(g), g);
    ring[i] = halfedge(add_edge(g), g);
  }
  for (std::size_t i = 0; i < n; ++i) quad[i] = add_face(g);
  // Connect.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const Hd h = side[i];
    const Hd sp_j = spoke[j], sp_i_back = opposite(spoke[i], g), ring_back = opposite(ring[i], g);
    // Quad i: h (v_i → v_j), spoke_j (v_j → w_j), ring_i reversed (w_j → w_i), spoke_i reversed (w_i → v_i).
    set_target(sp_j, w[j], g);
    set_target(opposite(sp_j, g), target(h, g), g);
    set_target(ring[i], w[j], g);
    set_target(ring_back, w[i], g);
    set_next(h, sp_j, g);
    set_next(sp_j, ring_back, g);
    set_next(ring_back, sp_i_back, g);
    set_next(sp_i_back, h, g);
    for (const Hd x : {h, sp_j, ring_back, sp_i_back}) set_face(x, quad[i], g);
    set_halfedge(quad[i], h, g);
    // The inner face: ring_i → ring_j.
    set_next(ring[i], ring[j], g);
    set_face(ring[i], f, g);
    set_halfedge(w[j], ring[i], g);
  }
  set_halfedge(f, ring[0], g);
  visitor.on_bevel_face(f, std::as_const(g));
  return f;
}

/// Whether bevel_vertex(v, g) applies: v is an inner vertex of degree ≥ 3.
template <MutableFaceGraph G>
bool can_bevel_vertex(vertex_descriptor_t<G> v, const G& g) {
  return halfedge(v, g) != null_h<G>() && !border_vertex(v, g) && !degree_below(v, 3, g);
}

/// Replaces inner vertex v of degree d by a new d-sided face (the seeds'
/// bevel_vertex, of size 0): each edge a_i–v now ends at a new vertex w_i (at
/// v's point), consecutive w_i are joined by d new edges, one inside each face
/// around v (which gains a side), and the w_i bound the new face. Removes v;
/// adds d vertices, d edges and one face. The w_i follow the incoming
/// halfedges of v from halfedge(v), turning as opposite(next(h)).
/// \returns the new face, or nullopt (see can_bevel_vertex). Move the w_i
/// along their edges to bevel.
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<face_descriptor_t<G>> bevel_vertex(vertex_descriptor_t<G> v, G& g, Visitor&& visitor = {}) {
  if (!can_bevel_vertex(v, g)) return std::nullopt;
  using Hd = H<G>;
  boost::container::small_vector<Hd, 8> in; // in_{i+1} = opposite(next(in_i))
  {
    const Hd start = halfedge(v, g);
    Hd x = start;
    do {
      in.push_back(x);
      x = opposite(next(x, g), g);
    } while (x != start);
  }
  const std::size_t d = in.size();
  boost::container::small_vector<V<G>, 8> w(d);
  boost::container::small_vector<Hd, 8> ring(d); // ring_i: w_i → w_{i+1}, inside face(in_i)
  for (std::size_t i = 0; i < d; ++i) {
    w[i] = add_vertex(g);
    if constexpr (HasVertexPoints<G>) {
      auto pm = get(vertex_point, g);
      put(pm, w[i], point_t<G>(get(pm, v)));
    }
  }
  for (std::size_t i = 0; i < d; ++i) ring[i] = halfedge(add_edge(g), g);
  const auto nf = add_face(g);
  for (std::size_t i = 0; i < d; ++i) set_target(in[i], w[i], g);
  for (std::size_t i = 0; i < d; ++i) {
    const std::size_t j = (i + 1) % d, k = (i + d - 1) % d;
    const Hd out_j = opposite(in[j], g); // was next(in_i)
    set_next(in[i], ring[i], g);
    set_next(ring[i], out_j, g);
    set_target(ring[i], w[j], g);
    set_face(ring[i], face(in[i], g), g);
    set_target(opposite(ring[i], g), w[i], g);
    set_next(opposite(ring[i], g), opposite(ring[k], g), g);
    set_face(opposite(ring[i], g), nf, g);
    set_halfedge(w[i], in[i], g);
  }
  set_halfedge(nf, opposite(ring[0], g), g);
  remove_vertex(v, g);
  visitor.on_bevel_vertex(nf, std::as_const(g));
  return nf;
}

// ---------------------------------------------------------------------------
// bevel_edge
// ---------------------------------------------------------------------------

// The halfedges into target(h), from h on, turning as opposite(next(x)).
template <class G, class Out>
void incoming_from(H<G> h, const G& g, Out& out) {
  H<G> x = h;
  do {
    out.push_back(x);
    x = opposite(next(x, g), g);
  } while (x != h);
}

// halfedge(target(h)) := the first border halfedge into it from h on, else h.
template <class G>
void set_vertex_halfedge(H<G> h, G& g) {
  H<G> x = h;
  do {
    if (border(x, g)) break;
    x = opposite(next(x, g), g);
  } while (x != h);
  set_halfedge(target(h, g), border(x, g) ? x : h, g);
}

/// Whether bevel_edge(h, g) applies: h is an edge with a face on at least
/// one side, not the same face on both, and at least one end of degree ≥ 3
/// (an end of degree 2 is not split; with both ends so, the new face would
/// have two sides).
template <MutableFaceGraph G>
bool can_bevel_edge(halfedge_descriptor_t<G> h, const G& g) {
  if (h == null_h<G>()) return false;
  const auto oh = opposite(h, g);
  if (face(h, g) == face(oh, g)) return false; // both holes, or one face on both sides
  return !degree_below(target(h, g), 3, g) || !degree_below(source(h, g), 3, g);
}

/// Replaces the edge of h by a new face (the seeds' bevel_edge; Blender's
/// one-segment edge bevel): the edge opens into a strip.
///
/// h goes u → v, L = face(h), R = face(opposite(h)) (either may be a hole).
/// Each end x ∈ {u, v} of degree d ≥ 3 splits in two: x keeps the edges on
/// L's side, a new vertex x' takes the m = ⌊(d − 1)/2⌋ other edges next to
/// R, and a new edge x–x' joins them across the corner (face or hole) where
/// the two groups meet, which gains a side. A new edge e' = u'–v' takes over
/// the edge's side of R. The new face Q = (v, u, u', v') lies between the
/// edge, which keeps L, and e': a quad, or a triangle when one end has
/// degree 2 (a border corner, not split). L and R keep their size.
///
/// Adds, in this order, edge e', the edges u–u' and v–v' and then the
/// vertices u' and v' (those of split ends), and the face Q: 2 vertices,
/// 3 edges and 1 face when both ends split; removes nothing. h keeps its
/// source, target and face; halfedge(Q) is the returned halfedge;
/// halfedge(R) becomes e''s halfedge in R; each vertex whose edges changed
/// gets a border halfedge as halfedge(x) if it has one.
///
/// Geometry: a split end x moves along L's other side at x and x' along R's
/// other side at x, by options.fraction of their length; an end that does
/// not split stays.
/// \returns opposite(h), now the side v → u of Q (face(result) is Q), or
/// nullopt (see can_bevel_edge). Throws invalid_input if options.fraction is
/// not in [0, 1) (before any change).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<halfedge_descriptor_t<G>> bevel_edge(halfedge_descriptor_t<G> h, G& g,
                                                   const Bevel_edge_options& options = {},
                                                   Visitor&& visitor = {}) {
  if (!(options.fraction >= 0.0 && options.fraction < 1.0))
    throw invalid_input("bevel_edge: fraction " + std::to_string(options.fraction) + " is not in [0, 1)");
  if (!can_bevel_edge(h, g)) return std::nullopt;
  using Hd = H<G>;
  using Vd = V<G>;
  // Collect: the halfedges into v from h (h, then towards R) and into u
  // from opposite(h) (opposite(h), then towards L).
  const Hd oh = opposite(h, g);
  const Vd u = source(h, g), v = target(h, g);
  const F<G> fr = face(oh, g);
  boost::container::small_vector<Hd, 8> in_v, in_u;
  detail::lo::incoming_from(h, g, in_v);
  detail::lo::incoming_from(oh, g, in_u);
  const std::size_t dv = in_v.size(), du = in_u.size();
  const std::size_t mv = dv >= 3 ? (dv - 1) / 2 : 0, mu = du >= 3 ? (du - 1) / 2 : 0;
  // Geometry, read before any change: x slides along L's other side at x,
  // x' along R's.
  [[maybe_unused]] Eigen::Vector3d pv, pv2, pu, pu2;
  if constexpr (HasVertexPoints<G>) {
    auto pm = get(vertex_point, g);
    using P = point_t<G>;
    const double t = options.fraction;
    auto at = [&](Vd x) { return to_eigen(P(get(pm, x))); };
    auto slide = [&](Vd from, Vd to) { return Eigen::Vector3d((1 - t) * at(from) + t * at(to)); };
    pv = mv ? slide(v, source(in_v[1], g)) : at(v);
    pv2 = mv ? slide(v, source(in_v[dv - 1], g)) : at(v);
    pu = mu ? slide(u, source(in_u[du - 1], g)) : at(u);
    pu2 = mu ? slide(u, source(in_u[1], g)) : at(u);
  }
  // Create.
  const Hd eq = halfedge(add_edge(g), g), er = opposite(eq, g); // e': u' → v' in Q, v' → u' in R
  const Hd cu = mu ? halfedge(add_edge(g), g) : null_h<G>();     // u' → u in the corner, u → u' in Q
  const Hd cv = mv ? halfedge(add_edge(g), g) : null_h<G>();     // v → v' in the corner, v' → v in Q
  const Vd u2 = mu ? add_vertex(g) : u;
  const Vd v2 = mv ? add_vertex(g) : v;
  const F<G> q = add_face(g);
  // Connect: hand the R-side edges to the new ends, close each cut corner.
  if (mv) {
    const std::size_t k = dv - 1 - mv; // the corner face(in_v[k]) gets v → v'
    for (std::size_t i = k + 1; i < dv; ++i) set_target(in_v[i], v2, g);
    set_next(in_v[k], cv, g);
    set_next(cv, opposite(in_v[k + 1], g), g);
    set_face(cv, face(in_v[k], g), g);
    set_target(cv, v2, g);
    set_target(opposite(cv, g), v, g);
  }
  if (mu) {
    for (std::size_t i = 1; i <= mu; ++i) set_target(in_u[i], u2, g); // the corner face(in_u[mu]) gets u' → u
    set_next(in_u[mu], cu, g);
    set_next(cu, opposite(in_u[mu + 1], g), g);
    set_face(cu, face(in_u[mu], g), g);
    set_target(cu, u, g);
    set_target(opposite(cu, g), u2, g);
  }
  // R: ... → v', e' reversed, u' → ...
  set_next(in_v[dv - 1], er, g);
  set_next(er, opposite(in_u[1], g), g);
  set_face(er, fr, g);
  set_target(er, u2, g);
  if (fr != null_f<G>()) set_halfedge(fr, er, g);
  // Q: opposite(h), u → u', e', v' → v.
  set_target(eq, v2, g);
  const Hd cuq = mu ? opposite(cu, g) : eq;
  const Hd cvq = mv ? opposite(cv, g) : oh;
  set_next(oh, cuq, g);
  if (mu) set_next(cuq, eq, g);
  set_next(eq, cvq, g);
  if (mv) set_next(cvq, oh, g);
  Hd x = oh;
  do {
    set_face(x, q, g);
    x = next(x, g);
  } while (x != oh);
  set_halfedge(q, oh, g);
  detail::lo::set_vertex_halfedge(h, g);
  detail::lo::set_vertex_halfedge(oh, g);
  if (mv) detail::lo::set_vertex_halfedge(cv, g);
  if (mu) detail::lo::set_vertex_halfedge(opposite(cu, g), g);
  if constexpr (HasVertexPoints<G>) {
    auto pm = get(vertex_point, g);
    using P = point_t<G>;
    put(pm, v, from_eigen<P>(pv));
    put(pm, v2, from_eigen<P>(pv2));
    put(pm, u, from_eigen<P>(pu));
    put(pm, u2, from_eigen<P>(pu2));
  }
  visitor.on_bevel_edge(oh, std::as_const(g));
  return oh;
}

// ---------------------------------------------------------------------------
// erase_vertex, erase_edge (the modelling names)
// ---------------------------------------------------------------------------

/// Whether erase_vertex(v, g) applies (see remove_center_vertex).
template <MutableFaceGraph G>
bool can_erase_vertex(vertex_descriptor_t<G> v, const G& g) {
  const auto h = halfedge(v, g);
  return h != null_h<G>() && can_remove_center_vertex(h, g);
}

/// Erases inner vertex v and its edges, merging its faces into one:
/// remove_center_vertex(halfedge(v, g), g).
/// \returns the merged face, or nullopt (v isolated, on the border, of
/// degree < 3, a tetrahedron vertex, or its link passes through a vertex
/// twice: see can_remove_center_vertex).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<face_descriptor_t<G>> erase_vertex(vertex_descriptor_t<G> v, G& g, Visitor&& visitor = {}) {
  if (!can_erase_vertex(v, g)) return std::nullopt;
  const auto h = remove_center_vertex(halfedge(v, g), g, visitor);
  return face(*h, g);
}

/// Whether erase_edge(e, g) applies (see join_face).
template <MutableFaceGraph G>
bool can_erase_edge(edge_descriptor_t<G> e, const G& g) {
  return can_join_face(halfedge(e, g), g);
}

/// Erases e, merging the faces on its two sides: join_face(halfedge(e), g)
/// (if halfedge(e) is a border halfedge, the other face joins the hole).
/// \returns the merged face (null if it joined a hole), or nullopt (see
/// can_join_face).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
std::optional<face_descriptor_t<G>> erase_edge(edge_descriptor_t<G> e, G& g, Visitor&& visitor = {}) {
  const auto h = halfedge(e, g);
  if (!can_join_face(h, g)) return std::nullopt;
  const auto r = join_face(h, g, visitor);
  return face(*r, g);
}

/// Triangulates every face with more than three sides (triangulate_face, in
/// face order). \returns the number of faces refused (left as they were).
template <MutableFaceGraph G, class Visitor = Mutation_visitor>
  requires FaceListGraph<G> && HasIndexMap<G, vertex_index_t>
std::size_t triangulate_faces(G& g, Visitor&& visitor = {}) {
  std::vector<face_descriptor_t<G>> todo;
  for (const auto f : faces(g))
    if (!detail::lo::triangle_at(halfedge(f, g), g)) todo.push_back(f);
  std::size_t refused = 0;
  for (const auto f : todo)
    if (!triangulate_face(f, g, visitor)) ++refused;
  return refused;
}

} // namespace detail::lo

// ---------------------------------------------------------------------------
// The public names: customization point objects
// ---------------------------------------------------------------------------
//
// Each operation is a function object that forwards to the generic
// implementation above (documented there, same name, in detail::lo). Being objects, they are invisible to argument-
// dependent lookup: CGAL's own unqualified calls (CGAL::Euler::collapse_edge
// calls join_face(h, g)) on a genmesh mesh never pick them up, and the
// MutableFaceGraph concept's remove_face(f, g) still means the backend's.
//
// A backend overrides an operation natively (the incidence mesh stores no
// next/prev to set) by providing, next to its graph traits, a free function
// genmesh_native_<operation>(same arguments) found by argument-dependent
// lookup, e.g. genmesh_native_flip_edge(h, g, visitor). It must keep the
// operation's contract (same result, same refusals, mesh untouched on
// refusal); the typed tests hold it to that.

#define GENMESH_LOCAL_OPERATION(name)                                                   \
  inline constexpr auto name = []<class... Args>(Args&&... args) -> decltype(auto)        \
    requires requires { genmesh_native_##name(std::forward<Args>(args)...); } ||         \
             requires { detail::lo::name(std::forward<Args>(args)...); }                 \
  {                                                                                     \
    if constexpr (requires { genmesh_native_##name(std::forward<Args>(args)...); })      \
      return genmesh_native_##name(std::forward<Args>(args)...);                         \
    else                                                                                \
      return detail::lo::name(std::forward<Args>(args)...);                              \
  };
GENMESH_LOCAL_OPERATION(can_flip_edge)
GENMESH_LOCAL_OPERATION(flip_edge)
GENMESH_LOCAL_OPERATION(can_unflip_edge)
GENMESH_LOCAL_OPERATION(unflip_edge)
GENMESH_LOCAL_OPERATION(can_split_edge)
GENMESH_LOCAL_OPERATION(split_edge)
GENMESH_LOCAL_OPERATION(can_split_edge_and_triangulate)
GENMESH_LOCAL_OPERATION(split_edge_and_triangulate)
GENMESH_LOCAL_OPERATION(does_satisfy_link_condition)
GENMESH_LOCAL_OPERATION(can_collapse_edge)
GENMESH_LOCAL_OPERATION(collapse_edge)
GENMESH_LOCAL_OPERATION(can_split_face)
GENMESH_LOCAL_OPERATION(split_face)
GENMESH_LOCAL_OPERATION(can_join_face)
GENMESH_LOCAL_OPERATION(join_face)
GENMESH_LOCAL_OPERATION(can_add_center_vertex)
GENMESH_LOCAL_OPERATION(add_center_vertex)
GENMESH_LOCAL_OPERATION(can_remove_center_vertex)
GENMESH_LOCAL_OPERATION(remove_center_vertex)
GENMESH_LOCAL_OPERATION(can_add_face)
GENMESH_LOCAL_OPERATION(can_remove_face)
GENMESH_LOCAL_OPERATION(can_triangulate_face)
GENMESH_LOCAL_OPERATION(triangulate_face)
GENMESH_LOCAL_OPERATION(triangulate_faces)
GENMESH_LOCAL_OPERATION(can_bevel_face)
GENMESH_LOCAL_OPERATION(bevel_face)
GENMESH_LOCAL_OPERATION(can_bevel_vertex)
GENMESH_LOCAL_OPERATION(bevel_vertex)
GENMESH_LOCAL_OPERATION(can_bevel_edge)
GENMESH_LOCAL_OPERATION(can_erase_vertex)
GENMESH_LOCAL_OPERATION(erase_vertex)
GENMESH_LOCAL_OPERATION(can_erase_edge)
GENMESH_LOCAL_OPERATION(erase_edge)

namespace detail::lo {
// collapse_edge for a caller that has just tested can_collapse_edge(e, g)
// (simplify: the second test was 4 % of its instructions on a small mesh):
// the generic operation without the test, or a backend's native
// collapse_edge as it is (it tests again).
template <class G, class Visitor>
std::optional<vertex_descriptor_t<G>> collapse_tested_edge(edge_descriptor_t<G> e, G& g, Visitor&& visitor) {
  if constexpr (requires { genmesh_native_collapse_edge(e, g, std::forward<Visitor>(visitor)); })
    return genmesh_native_collapse_edge(e, g, std::forward<Visitor>(visitor));
  else
    return collapse_edge_unchecked(e, g, std::forward<Visitor>(visitor));
}

// bevel_edge as an object like the others, spelled out so that its options
// can be written as a braced list: bevel_edge(h, g, {.fraction = 0.1}). A
// native override receives all four arguments.
struct Bevel_edge_fn {
  template <class Hd, class G, class Visitor = Mutation_visitor>
  auto operator()(Hd h, G& g, const Bevel_edge_options& options = {}, Visitor&& visitor = {}) const
    requires requires { genmesh_native_bevel_edge(h, g, options, std::forward<Visitor>(visitor)); } ||
             requires { detail::lo::bevel_edge(h, g, options, std::forward<Visitor>(visitor)); }
  {
    if constexpr (requires { genmesh_native_bevel_edge(h, g, options, std::forward<Visitor>(visitor)); })
      return genmesh_native_bevel_edge(h, g, options, std::forward<Visitor>(visitor));
    else
      return detail::lo::bevel_edge(h, g, options, std::forward<Visitor>(visitor));
  }
};
} // namespace detail::lo
inline constexpr detail::lo::Bevel_edge_fn bevel_edge{};

/// All local operations again, under CGAL::Euler's names: add_face(vertices, g)
/// and remove_face(h, g) exist only here, because genmesh::add_face(g) and
/// genmesh::remove_face(f, g) are Halfedge_mesh's MutableFaceGraph primitives.
namespace euler {
GENMESH_LOCAL_OPERATION(add_face)
GENMESH_LOCAL_OPERATION(remove_face)
using genmesh::can_flip_edge;
using genmesh::flip_edge;
using genmesh::can_unflip_edge;
using genmesh::unflip_edge;
using genmesh::can_split_edge;
using genmesh::split_edge;
using genmesh::can_split_edge_and_triangulate;
using genmesh::split_edge_and_triangulate;
using genmesh::does_satisfy_link_condition;
using genmesh::can_collapse_edge;
using genmesh::collapse_edge;
using genmesh::can_split_face;
using genmesh::split_face;
using genmesh::can_join_face;
using genmesh::join_face;
using genmesh::can_add_center_vertex;
using genmesh::add_center_vertex;
using genmesh::can_remove_center_vertex;
using genmesh::remove_center_vertex;
using genmesh::can_add_face;
using genmesh::can_remove_face;
using genmesh::can_triangulate_face;
using genmesh::triangulate_face;
using genmesh::triangulate_faces;
using genmesh::can_bevel_face;
using genmesh::bevel_face;
using genmesh::can_bevel_vertex;
using genmesh::bevel_vertex;
using genmesh::can_bevel_edge;
using genmesh::bevel_edge;
using genmesh::can_erase_vertex;
using genmesh::erase_vertex;
using genmesh::can_erase_edge;
using genmesh::erase_edge;
} // namespace euler

#undef GENMESH_LOCAL_OPERATION

} // namespace genmesh
