// genmesh/detail/local_operations/primitives.h — unchecked building blocks of
// the local operations: queries (border, degree, halfedge between two
// vertices, the vertex-once and no-pinch checks) and the raw edits join_face, join_vertex, remove_face and
// swap_vertices.
//
// The raw edits perform, on any MutableFaceGraph, the same low-level edits in
// the same order as CGAL::Euler's operations of the same name, so that
// elements are freed (and later recycled) in the same order and the results
// are identical index for index. They check nothing: the public operations in
// <genmesh/local_operations.h> decide first, then call these.
#pragma once

#include <genmesh/concepts.h>

#include <boost/container/small_vector.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>

namespace genmesh::detail::lo {

template <class G>
using H = halfedge_descriptor_t<G>;
template <class G>
using V = vertex_descriptor_t<G>;
template <class G>
using F = face_descriptor_t<G>;

template <class G>
constexpr H<G> null_h() {
  return boost::graph_traits<G>::null_halfedge();
}
template <class G>
constexpr F<G> null_f() {
  return boost::graph_traits<G>::null_face();
}

template <class G>
bool border(H<G> h, const G& g) {
  return face(h, g) == null_f<G>();
}

/// v is isolated or has a border halfedge around it (all halfedges looked at,
/// so halfedge(v) need not be a border halfedge).
template <class G>
bool border_vertex(V<G> v, const G& g) {
  const H<G> start = halfedge(v, g);
  if (start == null_h<G>()) return true;
  H<G> h = start;
  do {
    if (border(h, g)) return true;
    h = opposite(next(h, g), g);
  } while (h != start);
  return false;
}

template <class G>
std::size_t vertex_degree(V<G> v, const G& g) {
  const H<G> start = halfedge(v, g);
  if (start == null_h<G>()) return 0;
  std::size_t n = 0;
  H<G> h = start;
  do {
    ++n;
    h = opposite(next(h, g), g);
  } while (h != start);
  return n;
}

/// The cycle of halfedges around target(h) through h (the edges at target(h),
/// when it is manifold) has fewer than k halfedges (stops counting at k).
/// Unlike degree_below(target(h)), reads nothing of the vertex: from a face's
/// halfedge into its corner, the first steps stay in that face's
/// neighbourhood.
template <class G>
bool fan_below(H<G> h, std::size_t k, const G& g) {
  std::size_t n = 0;
  H<G> x = h;
  do {
    if (++n >= k) return false;
    x = opposite(next(x, g), g);
  } while (x != h);
  return true;
}

/// v has fewer than k edges (stops counting at k).
template <class G>
bool degree_below(V<G> v, std::size_t k, const G& g) {
  const H<G> start = halfedge(v, g);
  return start == null_h<G>() ? k > 0 : fan_below(start, k, g);
}

/// The halfedge from u to v, or null.
template <class G>
H<G> find_halfedge(V<G> u, V<G> v, const G& g) {
  const H<G> start = halfedge(v, g);
  if (start == null_h<G>()) return null_h<G>();
  H<G> h = start;
  do {
    if (target(opposite(h, g), g) == u) return h;
    h = opposite(next(h, g), g);
  } while (h != start);
  return null_h<G>();
}

// next(h) skips the tip at target(h): h's successor becomes next(opposite(next(h))).
template <class G>
void skip_tip(H<G> h, G& g) {
  set_next(h, next(opposite(next(h, g), g), g), g);
}

/// Removes edge(h) and face(opposite(h)), merging it into face(h) (which may
/// be a hole). Returns prev(h) (as CGAL::Euler::join_face).
template <class G>
H<G> join_face_raw(H<G> h, G& g) {
  const H<G> hop = opposite(h, g);
  const H<G> hprev = prev(h, g), gprev = prev(hop, g);
  const F<G> f = face(h, g), f2 = face(hop, g);
  lo::skip_tip(hprev, g);
  lo::skip_tip(gprev, g);
  if (!border(hop, g)) remove_face(f2, g);
  const bool fnull = border(h, g);
  for (H<G> x = hprev; x != gprev;) {
    x = next(x, g);
    set_face(x, f, g);
  }
  if (!fnull) set_halfedge(f, hprev, g);
  set_halfedge(target(hprev, g), hprev, g);
  set_halfedge(target(gprev, g), gprev, g);
  remove_edge(edge(h, g), g);
  return hprev;
}

/// Sets the target of every halfedge of start's fan (those around
/// target(start), from start) to v.
template <class G>
void retarget_fan(H<G> start, V<G> v, G& g) {
  H<G> x = start;
  do {
    set_target(x, v, g);
    x = opposite(next(x, g), g);
  } while (x != start);
}

/// Merges source(h) into target(h), removing edge(h) and source(h). Both
/// faces of h must keep at least three sides. Returns prev(opposite(h)).
template <class G>
H<G> join_vertex_raw(H<G> h, G& g) {
  const H<G> hop = opposite(h, g);
  const H<G> hprev = prev(hop, g), gprev = prev(h, g), hnext = next(hop, g), gnext = next(h, g);
  const V<G> removed = target(hop, g), v = target(h, g);
  retarget_fan(hop, v, g);
  set_next(hprev, hnext, g);
  set_next(gprev, gnext, g);
  set_halfedge(v, gprev, g);
  if (!border(gprev, g)) set_halfedge(face(gprev, g), gprev, g);
  if (!border(hprev, g)) set_halfedge(face(hprev, g), hprev, g);
  remove_edge(edge(h, g), g);
  remove_vertex(removed, g);
  return hprev;
}

/// Removes face(h) (h not border); edges left with no face on either side and
/// vertices left with no edge are removed too (as CGAL::Euler::remove_face).
template <class G>
void remove_face_raw(H<G> h, G& g) {
  const F<G> f = face(h, g);
  const H<G> end = h;
  do {
    set_face(h, null_f<G>(), g);
    const H<G> nh = next(h, g);
    const bool h_border = border(opposite(h, g), g);
    const bool nh_border = border(opposite(nh, g), g);
    if (h_border && nh_border && next(opposite(nh, g), g) == opposite(h, g)) {
      remove_vertex(target(h, g), g);
      if (h != end) remove_edge(edge(h, g), g);
    } else {
      if (nh_border) {
        const H<G> x = opposite(next(opposite(nh, g), g), g);
        set_halfedge(target(x, g), x, g);
        lo::skip_tip(h, g);
      }
      if (h_border) {
        const H<G> x = opposite(next(h, g), g);
        set_halfedge(target(x, g), x, g);
        lo::skip_tip(prev(opposite(h, g), g), g);
        if (h != end) remove_edge(edge(h, g), g);
      }
    }
    h = nh;
  } while (h != end);
  remove_face(f, g);
  if (border(opposite(h, g), g)) remove_edge(edge(h, g), g);
}

/// Exchanges the connectivity of p and q (not their points).
template <class G>
void swap_vertices_raw(V<G> p, V<G> q, G& g) {
  const H<G> hq = halfedge(q, g), hp = halfedge(p, g);
  retarget_fan(hq, p, g);
  retarget_fan(hp, q, g);
  set_halfedge(p, hq, g);
  set_halfedge(q, hp, g);
}

/// The triangle of h (three sides).
template <class G>
bool triangle_at(H<G> h, const G& g) {
  return next(next(next(h, g), g), g) == h;
}

/// h and its opposite bound a tetrahedron (four triangles, three at each vertex).
template <class G>
bool tetrahedron_at(H<G> h1, const G& g) {
  if (border(h1, g)) return false;
  const H<G> h2 = next(h1, g), h3 = next(h2, g);
  const H<G> h4 = next(opposite(h1, g), g), h5 = next(opposite(h2, g), g), h6 = next(opposite(h3, g), g);
  if (h4 == opposite(h3, g) || h5 == opposite(h1, g) || h6 == opposite(h2, g)) return false;
  if (next(opposite(h4, g), g) != opposite(h3, g) || next(opposite(h5, g), g) != opposite(h1, g) ||
      next(opposite(h6, g), g) != opposite(h2, g))
    return false;
  if (opposite(next(h4, g), g) != h5 || opposite(next(h5, g), g) != h6 || opposite(next(h6, g), g) != h4)
    return false;
  if (!triangle_at(h1, g) || !triangle_at(h4, g) || !triangle_at(h5, g) || !triangle_at(h6, g)) return false;
  return !border(h4, g) && !border(h5, g) && !border(h6, g);
}

// Vertices of up to this many corners are sorted on the stack; a merged
// face with more corners allocates once.
template <class G>
using Corner_list = boost::container::small_vector<V<G>, 32>;

/// The corners hold no vertex twice (sorts them).
template <class G>
bool all_distinct(Corner_list<G>& vs) {
  std::sort(vs.begin(), vs.end());
  return std::adjacent_find(vs.begin(), vs.end()) == vs.end();
}

/// can_remove_center_vertex's test, read-only (every backend's predicate
/// calls it): target(h) is an inner vertex of degree ≥ 3, the faces beyond
/// its star are not all one and the same face, and the link visits each
/// vertex once.
template <class G>
bool center_vertex_removable(H<G> h, const G& g) {
  const V<G> v = target(h, g);
  if (border_vertex(v, g) || vertex_degree(v, g) < 3) return false;
  // Faces across the link: the sides of the star's faces away from v.
  bool found = false, distinct = false, any_hole = false;
  F<G> first{};
  Corner_list<G> link;
  H<G> x = h;
  do {
    // x targets v; walk face(x) from next(x) (leaving v) to prev(x) excluded.
    for (H<G> y = next(next(x, g), g); y != x; y = next(y, g)) {
      if (target(y, g) == v) break;
      link.push_back(target(y, g));
      const F<G> fo = face(opposite(y, g), g);
      if (fo == null_f<G>()) {
        any_hole = true;
      } else if (!found) {
        first = fo;
        found = true;
      } else if (fo != first) {
        distinct = true;
      }
    }
    x = opposite(next(x, g), g);
  } while (x != h);
  return (any_hole || distinct || !found) && all_distinct<G>(link);
}

/// Whether the face (or hole) that join_face_raw(h) leaves visits each vertex
/// once and, when face(opposite(h)) joins a hole, leaves no vertex with two
/// border gaps (a pinch). Cost: joining into a hole (h a border halfedge),
/// face(opposite(h))'s cycle and its corners' degrees; otherwise both
/// cycles, sorted (the hole's included when opposite(h) is the border side).
template <class G>
bool join_keeps_a_simple_cycle(H<G> h, const G& g) {
  const H<G> oh = opposite(h, g);
  const V<G> a = target(oh, g), b = target(h, g);
  if (border(h, g)) {
    // Another corner of face(oh) on this hole would be visited twice, one on
    // another hole would be pinched between the two.
    for (H<G> x = next(oh, g); x != oh; x = next(x, g))
      if (target(x, g) != a && target(x, g) != b && border_vertex(target(x, g), g)) return false;
    return true;
  }
  Corner_list<G> vs;
  H<G> x = h;
  do {
    if (target(x, g) != a && target(x, g) != b) vs.push_back(target(x, g));
    x = next(x, g);
  } while (x != h);
  x = oh;
  do {
    if (target(x, g) != a && target(x, g) != b) vs.push_back(target(x, g));
    x = next(x, g);
  } while (x != oh);
  return all_distinct<G>(vs);
}

/// Whether removing face(h) (not a hole) leaves no vertex with two border
/// gaps: no corner on the border may have both its sides in the face inner.
/// Cost: the face's degree plus its border corners' degrees.
template <class G>
bool removal_keeps_border_simple(H<G> h, const G& g) {
  H<G> x = h;
  do {
    const H<G> nx = next(x, g);
    if (!border(opposite(x, g), g) && !border(opposite(nx, g), g) && border_vertex(target(x, g), g)) return false;
    x = nx;
  } while (x != h);
  return true;
}

/// Splits face(h1) by a new edge target(h1) → target(h2) (CGAL::Euler::split_face).
template <class G>
H<G> split_face_raw(H<G> h1, H<G> h2, G& g) {
  const H<G> hnew = halfedge(add_edge(g), g);
  const H<G> ohnew = opposite(hnew, g);
  const F<G> fnew = add_face(g);
  set_next(hnew, next(h2, g), g);
  set_next(h2, ohnew, g);
  set_target(hnew, target(h2, g), g);
  set_next(ohnew, next(h1, g), g);
  set_next(h1, hnew, g);
  set_target(ohnew, target(h1, g), g);
  set_face(hnew, face(h1, g), g);
  H<G> x = ohnew;
  do {
    set_face(x, fnew, g);
    x = next(x, g);
  } while (x != ohnew);
  set_halfedge(face(hnew, g), hnew, g);
  set_halfedge(fnew, ohnew, g);
  return hnew;
}

} // namespace genmesh::detail::lo
