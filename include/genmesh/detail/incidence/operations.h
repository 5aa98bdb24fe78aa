// genmesh/detail/incidence/operations.h — the local operations of
// Incidence_mesh, done natively by setting and clearing matrix entries
// (included at the end of <genmesh/incidence_mesh.h>).
//
// Each genmesh_native_<op> is found by argument-dependent lookup from the
// public operation objects of <genmesh/local_operations.h>
// (genmesh::flip_edge(h, g) on an Incidence_mesh lands here). Contract: the
// generic operation's, exactly — the same can_… predicate and refusals (mesh
// untouched on refusal), the same elements created and removed in the same
// order (so the same indices, by Halfedge_mesh's free-list policy), the same
// edge directions, the same returned descriptor, the same visitor calls.
// Where the generic code walks from halfedge(v) or halfedge(f) (bevel_vertex,
// bevel_face, erase_vertex) it walks from Incidence_mesh's canonical choice.
//
// How: an operation first reads the halfedges it needs (face cycles, the
// fan of a vertex) through the derived queries, then edits only the rows of
// the elements involved: set_edge_vertices (d0, d0ᵀ), add_side/remove_side
// (d1, d1ᵀ), add_*/remove_* (which also drop incidences). next, prev and the
// border cycles follow by themselves from the new face rows, so no pointer
// surgery is needed. Cost: O(sum of the degrees of the faces and vertices
// touched), plus O(d²) per face cycle walked.
//
// Limits:
// - On a mesh that is not manifold (is_manifold() false) every predicate is
//   false and every operation refuses.
// - A face may not visit a vertex twice (a row of d1 is a set of signed
//   edges, so it could not tell the visits apart). join_face, erase_edge,
//   remove_center_vertex, erase_vertex and collapse_edge therefore refuse where the generic
//   operation would make such a face (joining a face with a neighbour or a
//   hole that touches it at another vertex too); this is the one place
//   where the native predicates are stricter than the generic ones, with
//   euler::remove_face, which refuses to leave a vertex with two border gaps
//   (a pinch: the generic one makes it, and check_mesh then reports the
//   vertex), because the border's next there is not determined by the
//   incidences.
#pragma once

#include <genmesh/incidence_mesh.h>
#include <genmesh/local_operations.h>
#include <genmesh/visitor.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <optional>
#include <utility>

namespace genmesh {

namespace detail::inc {

template <class P>
using M = Incidence_mesh<P>;
using Hs = boost::container::small_vector<Halfedge_index, 8>;

// h, next(h), ... once around h's cycle.
template <class P>
Hs cycle(Halfedge_index h, const M<P>& g) {
  Hs out;
  const std::size_t bound = g.halfedges_size() + 1;
  Halfedge_index x = h;
  do {
    out.push_back(x);
    x = g.next(x);
  } while (x != h && out.size() <= bound);
  return out;
}

// Brings the faces' cyclic orders (Incidence_mesh::update_face_orders) up to
// date when an operation returns, whichever way it returns.
template <class P>
struct Face_order_update {
  M<P>& g;
  explicit Face_order_update(M<P>& mesh) : g(mesh) {}
  Face_order_update(const Face_order_update&) = delete;
  Face_order_update& operator=(const Face_order_update&) = delete;
  ~Face_order_update() { g.update_face_orders(); }
};

template <class P>
P midpoint(const P& a, const P& b) {
  if constexpr (Point3<P>) {
    const Eigen::Vector3d m = 0.5 * (to_eigen(a) + to_eigen(b));
    return from_eigen<P>(m);
  } else {
    return a;
  }
}

// The raw edits (see detail/local_operations/primitives.h): same element
// order as there.

template <class P>
Halfedge_index split_face_raw(Halfedge_index h1, Halfedge_index h2, M<P>& g) {
  const Face_index f = g.face(h1);
  Hs moved; // next(h1) ... h2: they go to the new face
  for (Halfedge_index x = g.next(h1);; x = g.next(x)) {
    moved.push_back(x);
    if (x == h2) break;
  }
  const Vertex_index a = g.target(h1), b = g.target(h2);
  const Edge_index e = g.add_edge();
  const Face_index fnew = g.add_face();
  g.set_edge_vertices(e, a, b);
  const Halfedge_index hnew = g.halfedge(e, 0), ohnew = g.halfedge(e, 1);
  for (const Halfedge_index x : moved) {
    g.remove_side(f, x);
    g.add_side(fnew, x);
  }
  g.add_side(f, hnew);
  g.add_side(fnew, ohnew);
  return hnew;
}

// flip and unflip: h becomes u → v inside its two triangles; side `to_h`
// moves from face(opposite(h)) to face(h), side `to_oh` the other way.
template <class P>
void turn_edge_raw(Halfedge_index h, Vertex_index u, Vertex_index v, Halfedge_index to_h, Halfedge_index to_oh,
                   M<P>& g) {
  const Face_index fh = g.face(h), foh = g.face(M<P>::opposite(h));
  g.set_halfedge_vertices(h, u, v);
  g.remove_side(foh, to_h);
  g.add_side(fh, to_h);
  g.remove_side(fh, to_oh);
  g.add_side(foh, to_oh);
}

template <class P>
Halfedge_index join_face_raw(Halfedge_index h, M<P>& g) {
  const Halfedge_index hop = M<P>::opposite(h);
  const Halfedge_index hprev = g.prev(h);
  const Face_index f = g.face(h), f2 = g.face(hop);
  Hs other = cycle(hop, g);
  if (f2.is_valid()) g.remove_face(f2);
  // The edge leaves f's row before the other sides join it: two triangles
  // never need five entries (which would turn d1's home slots general).
  g.remove_edge(M<P>::edge(h));
  if (f.is_valid())
    for (std::size_t i = 1; i < other.size(); ++i) g.add_side(f, other[i]);
  return hprev;
}

template <class P>
void join_vertex_raw(Halfedge_index h, M<P>& g) {
  const Vertex_index removed = g.source(h), v = g.target(h);
  g.remove_edge(M<P>::edge(h));
  g.move_incidences(removed, v);
  g.remove_vertex(removed);
}

template <class P>
void remove_face_raw(Halfedge_index h, M<P>& g) {
  const Face_index f = g.face(h);
  const Hs c = cycle(h, g);
  const std::size_t n = c.size();
  boost::container::small_vector<char, 8> border(n), tip(n);
  for (std::size_t i = 0; i < n; ++i) border[i] = !g.face(M<P>::opposite(c[i])).is_valid();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    tip[i] = border[i] && border[j] && g.next(M<P>::opposite(c[j])) == M<P>::opposite(c[i]);
  }
  boost::container::small_vector<Vertex_index, 8> tip_vertex(n);
  for (std::size_t i = 0; i < n; ++i)
    if (tip[i]) tip_vertex[i] = g.target(c[i]);
  for (std::size_t i = 0; i < n; ++i) {
    if (tip[i]) g.remove_vertex(tip_vertex[i]);
    if (border[i] && i != 0) g.remove_edge(M<P>::edge(c[i]));
  }
  g.remove_face(f);
  if (border[0]) g.remove_edge(M<P>::edge(c[0]));
}

template <class P>
bool manifold(const M<P>& g) {
  return g.is_manifold();
}

} // namespace detail::inc

// ---------------------------------------------------------------------------
// flip_edge, unflip_edge
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_flip_edge(Halfedge_index h, const Incidence_mesh<P>& g) {
  namespace lo = detail::lo;
  if (!g.is_manifold() || !h.is_valid()) return false;
  const auto oh = opposite(h, g);
  if (lo::border(h, g) || lo::border(oh, g)) return false;
  if (!lo::triangle_at(h, g) || !lo::triangle_at(oh, g)) return false;
  const auto s2 = target(next(h, g), g), t2 = target(next(oh, g), g);
  if (s2 == t2) return false;
  if (g.halfedge(s2, t2).is_valid()) return false;
  for (const auto v : {source(h, g), target(h, g)})
    if (g.degree(v) < 4 && !lo::border_vertex(v, g)) return false;
  return true;
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_flip_edge(Halfedge_index h, Incidence_mesh<P>& g,
                                                       Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_flip_edge(h, std::as_const(g))) return std::nullopt;
  const Halfedge_index nh = g.next(h), noh = g.next(g.opposite(h));
  detail::inc::turn_edge_raw(h, g.target(nh), g.target(noh), g.next(noh), g.next(nh), g);
  visitor.on_flip(h, std::as_const(g));
  return h;
}

template <class P>
bool genmesh_native_can_unflip_edge(Halfedge_index h, const Incidence_mesh<P>& g) {
  return h.is_valid() && genmesh_native_can_flip_edge(Incidence_mesh<P>::opposite(h), g);
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_unflip_edge(Halfedge_index h, Incidence_mesh<P>& g,
                                                         Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_unflip_edge(h, std::as_const(g))) return std::nullopt;
  const Halfedge_index nh = g.next(h), noh = g.next(g.opposite(h));
  detail::inc::turn_edge_raw(h, g.target(noh), g.target(nh), noh, nh, g);
  visitor.on_flip(h, std::as_const(g));
  return h;
}

// ---------------------------------------------------------------------------
// split_edge, split_edge_and_triangulate
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_split_edge(Halfedge_index h, const Incidence_mesh<P>& g) {
  return h.is_valid() && g.is_manifold();
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_split_edge(Halfedge_index h, Incidence_mesh<P>& g,
                                                        Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_split_edge(h, std::as_const(g))) return std::nullopt;
  const Halfedge_index h2 = g.opposite(h);
  const Vertex_index u = g.target(h2), v = g.target(h);
  const Face_index fh = g.face(h), fo = g.face(h2);
  const Edge_index e = g.add_edge();
  const Vertex_index w = g.add_vertex(detail::inc::midpoint(g.point(u), g.point(v)));
  const Halfedge_index hnew = g.halfedge(e, 0), hnewopp = g.halfedge(e, 1);
  g.set_edge_vertices(e, w, u);   // hnew: w → u, after h2 in face(h2)
  g.set_halfedge_vertices(h2, v, w);
  if (fo.is_valid()) g.add_side(fo, hnew);
  if (fh.is_valid()) g.add_side(fh, hnewopp); // u → w, before h
  visitor.on_split_edge(hnewopp, std::as_const(g));
  return hnewopp;
}

template <class P>
bool genmesh_native_can_split_edge_and_triangulate(Halfedge_index h, const Incidence_mesh<P>& g) {
  namespace lo = detail::lo;
  if (!genmesh_native_can_split_edge(h, g)) return false;
  const auto oh = opposite(h, g);
  if (lo::border(h, g) && lo::border(oh, g)) return false;
  return (lo::border(h, g) || g.degree(g.face(h)) == 3) && (lo::border(oh, g) || g.degree(g.face(oh)) == 3);
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_split_edge_and_triangulate(Halfedge_index h, Incidence_mesh<P>& g,
                                                                        Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_split_edge_and_triangulate(h, std::as_const(g))) return std::nullopt;
  const Halfedge_index oh = g.opposite(h);
  const bool side_h = g.face(h).is_valid(), side_oh = g.face(oh).is_valid();
  Mutation_visitor quiet;
  const Halfedge_index hnew = *genmesh_native_split_edge(h, g, quiet);
  if (side_h) detail::inc::split_face_raw(hnew, g.next(h), g);
  if (side_oh) detail::inc::split_face_raw(oh, g.next(g.opposite(hnew)), g);
  visitor.on_split_edge(hnew, std::as_const(g));
  return hnew;
}

// ---------------------------------------------------------------------------
// collapse_edge
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_does_satisfy_link_condition(Edge_index e, const Incidence_mesh<P>& g) {
  namespace lo = detail::lo;
  if (!g.is_manifold()) return false;
  const auto pq = halfedge(e, g), qp = opposite(pq, g);
  const auto p = target(qp, g), q = target(pq, g);
  const auto vl = target(next(pq, g), g), vr = target(next(qp, g), g);
  const bool top = !lo::border(pq, g), bottom = !lo::border(qp, g);
  // Common neighbours of p and q must be the opposite corners of e's faces
  // (read from d0ᵀ: p's edges, then each neighbour's edge to q).
  const auto& vt = g.d0t_rows();
  for (int k = 0; k < vt.size(p.idx()); ++k) {
    const Halfedge_index x(2u * static_cast<std::uint32_t>(vt.cols(p.idx())[k]));
    const Vertex_index a = g.target(x), b = g.source(x);
    const Vertex_index kv = a == p ? b : a;
    if (kv != q && !((kv == vl && top) || (kv == vr && bottom)) && g.halfedge(kv, q).is_valid()) return false;
  }
  return lo::link_condition_beyond_neighbours(pq, g);
}

template <class P>
bool genmesh_native_can_collapse_edge(Edge_index e, const Incidence_mesh<P>& g) {
  namespace lo = detail::lo;
  if (!g.is_manifold() || !e.is_valid()) return false;
  const auto pq = halfedge(e, g), qp = opposite(pq, g);
  const bool top = !lo::border(pq, g), bottom = !lo::border(qp, g);
  if (!top && !bottom) return false;
  if (top && (g.degree(g.face(pq)) != 3 || g.degree(target(next(pq, g), g)) <= 2)) return false;
  if (bottom && (g.degree(g.face(qp)) != 3 || g.degree(target(next(qp, g), g)) <= 2)) return false;
  if (!genmesh_native_does_satisfy_link_condition(e, g)) return false;
  // Stricter than the generic predicate (see the header): a face other than
  // e's triangles that holds both p and q would pass through q twice.
  const Vertex_index p = g.source(pq), q = g.target(pq);
  const Face_index ft = g.face(pq), fb = g.face(qp);
  const auto& vt = g.d0t_rows();
  const auto& et = g.d1t_rows();
  const auto& fr = g.d1_rows();
  for (int k = 0; k < vt.size(p.idx()); ++k) {
    const auto x = static_cast<std::uint32_t>(vt.cols(p.idx())[k]);
    for (int j = 0; j < et.size(x); ++j) {
      const Face_index f(static_cast<std::uint32_t>(et.cols(x)[j]));
      if (f == ft || f == fb) continue;
      for (int i = 0; i < fr.size(f.idx()); ++i) {
        const Halfedge_index y(2u * static_cast<std::uint32_t>(fr.cols(f.idx())[i]));
        if (g.target(y) == q || g.source(y) == q) return false;
      }
    }
  }
  return true;
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Vertex_index> genmesh_native_collapse_edge(Edge_index e, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  namespace inc = detail::inc;
  if (!genmesh_native_can_collapse_edge(e, std::as_const(g))) return std::nullopt;
  const Halfedge_index pq = g.halfedge(e), qp = g.opposite(pq);
  visitor.before_collapse(pq, std::as_const(g));
  const Halfedge_index pt = g.opposite(g.prev(pq)), qb = g.opposite(g.prev(qp));
  const bool top = g.face(pq).is_valid(), bottom = g.face(qp).is_valid();
  const bool top_left = top && g.face(pt).is_valid(), bottom_right = bottom && g.face(qb).is_valid();
  const Vertex_index q = g.target(pq), p = g.source(pq);
  bool p_erased = false;
  if (top) {
    if (top_left) {
      inc::join_face_raw(pt, g);
    } else {
      inc::remove_face_raw(g.opposite(pt), g);
      if (!bottom) p_erased = true;
    }
  }
  if (bottom) {
    if (bottom_right) {
      inc::join_face_raw(qb, g);
    } else {
      if (!top) {
        p_erased = true;
        g.swap_incidences(p, q); // q's descriptor must survive
      }
      inc::remove_face_raw(g.opposite(qb), g);
    }
  }
  if (!p_erased) inc::join_vertex_raw(pq, g);
  visitor.on_collapse(q, std::as_const(g));
  return q;
}

// ---------------------------------------------------------------------------
// split_face, join_face
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_split_face(Halfedge_index h1, Halfedge_index h2, const Incidence_mesh<P>& g) {
  if (!g.is_manifold() || !h1.is_valid() || !h2.is_valid()) return false;
  if (h1 == h2 || !g.face(h1).is_valid() || g.face(h1) != g.face(h2)) return false;
  if (g.next(h1) == h2 || g.next(h2) == h1) return false;
  return !g.halfedge(g.target(h1), g.target(h2)).is_valid();
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_split_face(Halfedge_index h1, Halfedge_index h2, Incidence_mesh<P>& g,
                                                        Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_split_face(h1, h2, std::as_const(g))) return std::nullopt;
  const Halfedge_index h3 = detail::inc::split_face_raw(h1, h2, g);
  visitor.on_split_face(h3, std::as_const(g));
  return h3;
}

template <class P>
bool genmesh_native_can_join_face(Halfedge_index h, const Incidence_mesh<P>& g) {
  if (!g.is_manifold() || !h.is_valid()) return false;
  const Halfedge_index oh = g.opposite(h);
  const Face_index f = g.face(h), fo = g.face(oh);
  if (!f.is_valid() && !fo.is_valid()) return false;
  if (f == fo) return false;
  if (g.degree(g.source(h)) < 3 || g.degree(g.target(h)) < 3) return false;
  // The merged face must visit each vertex once: a face row (a set of signed
  // edges) cannot represent a cycle through a vertex twice. The generic
  // join_face makes such a face when the two cycles share another vertex.
  boost::container::small_vector<Vertex_index, 16> vs;
  for (const Halfedge_index x : detail::inc::cycle(h, g)) vs.push_back(g.target(x));
  for (const Halfedge_index x : detail::inc::cycle(oh, g)) vs.push_back(g.target(x));
  std::sort(vs.begin(), vs.end());
  if (static_cast<std::size_t>(std::unique(vs.begin(), vs.end()) - vs.begin()) + 2 != vs.size()) return false;
  // A face joining a hole must not touch another hole elsewhere: that vertex
  // would be left with two border gaps (see can_remove_face).
  if (!f.is_valid())
    for (const Halfedge_index x : detail::inc::cycle(oh, g)) {
      const Vertex_index w = g.target(x);
      if (w != g.source(h) && w != g.target(h) && detail::lo::border_vertex(w, g)) return false;
    }
  return true;
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_join_face(Halfedge_index h, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_join_face(h, std::as_const(g))) return std::nullopt;
  visitor.before_join_face(h, std::as_const(g));
  return detail::inc::join_face_raw(h, g);
}

// ---------------------------------------------------------------------------
// add_center_vertex, remove_center_vertex
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_add_center_vertex(Halfedge_index h, const Incidence_mesh<P>& g) {
  return g.is_manifold() && h.is_valid() && g.face(h).is_valid();
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_add_center_vertex(Halfedge_index h, Incidence_mesh<P>& g,
                                                               Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_add_center_vertex(h, std::as_const(g))) return std::nullopt;
  const Face_index f = g.face(h);
  const detail::inc::Hs c = detail::inc::cycle(h, g);
  P centre = g.point(g.target(h));
  if constexpr (Point3<P>) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (const Halfedge_index x : c) {
      sum += to_eigen(g.point(g.target(x)));
      ++n;
    }
    centre = from_eigen<P>(sum / n);
  }
  const Edge_index e0 = g.add_edge();
  const Vertex_index vc = g.add_vertex(centre);
  g.set_edge_vertices(e0, g.target(h), vc);
  const Halfedge_index hnew = g.halfedge(e0, 0);
  Halfedge_index spoke = hnew; // the last spoke, towards vc
  for (std::size_t k = 1; k < c.size(); ++k) {
    const Halfedge_index x = c[k];
    const Edge_index ek = g.add_edge();
    g.set_edge_vertices(ek, g.target(x), vc);
    const Face_index fk = g.add_face();
    g.remove_side(f, x);
    g.add_side(fk, x);
    g.add_side(fk, g.halfedge(ek, 0));
    g.add_side(fk, g.opposite(spoke));
    spoke = g.halfedge(ek, 0);
  }
  g.add_side(f, hnew);
  g.add_side(f, g.opposite(spoke));
  visitor.on_add_center_vertex(hnew, std::as_const(g));
  return hnew;
}

template <class P>
bool genmesh_native_can_remove_center_vertex(Halfedge_index h, const Incidence_mesh<P>& g) {
  return g.is_manifold() && h.is_valid() && detail::lo::center_vertex_removable(h, g);
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_remove_center_vertex(Halfedge_index h, Incidence_mesh<P>& g,
                                                                  Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_remove_center_vertex(h, std::as_const(g))) return std::nullopt;
  visitor.before_remove_center_vertex(h, std::as_const(g));
  const Vertex_index v = g.target(h);
  const Halfedge_index hret = g.prev(h);
  const Face_index f = g.face(h);
  detail::inc::Hs spokes, link;
  boost::container::small_vector<Face_index, 8> star;
  for (Halfedge_index h2 = g.opposite(g.next(h)); h2 != h; h2 = g.opposite(g.next(h2))) {
    spokes.push_back(h2);
    star.push_back(g.face(h2));
    // The sides of face(h2) away from v: from next(next(h2)) up to prev(h2)'s predecessor... i.e.
    // every side but h2 (into v) and next(h2) (out of v).
    const Halfedge_index out = g.next(h2);
    for (Halfedge_index y = g.next(out); y != h2; y = g.next(y)) link.push_back(y);
  }
  for (std::size_t i = 0; i < spokes.size(); ++i) {
    g.remove_face(star[i]);
    g.remove_edge(Incidence_mesh<P>::edge(spokes[i]));
  }
  g.remove_vertex(v);
  g.remove_edge(Incidence_mesh<P>::edge(h));
  for (const Halfedge_index y : link) g.add_side(f, y);
  return hret;
}

// ---------------------------------------------------------------------------
// euler::add_face, euler::remove_face
// ---------------------------------------------------------------------------

template <class P, class Range>
bool genmesh_native_can_add_face(const Range& vertices, const Incidence_mesh<P>& g) {
  if (!g.is_manifold()) return false;
  detail::lo::Face_plan<Incidence_mesh<P>> plan;
  return detail::lo::plan_face(vertices, g, plan);
}

template <class P, class Range, class Visitor = Mutation_visitor>
std::optional<Face_index> genmesh_native_add_face(const Range& vertices, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!g.is_manifold()) return std::nullopt;
  detail::lo::Face_plan<Incidence_mesh<P>> plan;
  if (!detail::lo::plan_face(vertices, std::as_const(g), plan)) return std::nullopt;
  const std::size_t n = plan.vertices.size();
  auto& hs = plan.halfedges;
  for (std::size_t i = 0; i < n; ++i) {
    if (hs[i].is_valid()) continue;
    const Edge_index e = g.add_edge();
    g.set_edge_vertices(e, plan.vertices[i], plan.vertices[(i + 1) % n]);
    hs[i] = g.halfedge(e, 0);
  }
  const Face_index f = g.add_face();
  for (std::size_t i = 0; i < n; ++i) g.add_side(f, hs[i]);
  visitor.on_add_face(f, std::as_const(g));
  return f;
}

template <class P>
bool genmesh_native_can_remove_face(Halfedge_index h, const Incidence_mesh<P>& g) {
  if (!g.is_manifold() || !h.is_valid() || !g.face(h).is_valid()) return false;
  // Stricter than the generic predicate (see the header): a border vertex of
  // the face whose two sides in the face are both inner would be left with
  // two border gaps (a pinch), where the border's next is not determined by
  // the incidences.
  for (const Halfedge_index x : detail::inc::cycle(h, g)) {
    const Halfedge_index nx = g.next(x);
    if (!g.face(g.opposite(x)).is_valid() || !g.face(g.opposite(nx)).is_valid()) continue;
    if (detail::lo::border_vertex(g.target(x), g)) return false;
  }
  return true;
}

template <class P, class Visitor = Mutation_visitor>
bool genmesh_native_remove_face(Halfedge_index h, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_remove_face(h, std::as_const(g))) return false;
  visitor.before_remove_face(h, std::as_const(g));
  detail::inc::remove_face_raw(h, g);
  return true;
}

// ---------------------------------------------------------------------------
// triangulate_face(s)
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_triangulate_face(Face_index f, const Incidence_mesh<P>& g) {
  if (!g.is_manifold() || !f.is_valid()) return false;
  const Halfedge_index h0 = g.lowest_corner(f); // as the generic lo::lowest_corner
  const Vertex_index v0 = g.target(h0);
  for (Halfedge_index x = g.next(g.next(h0)); g.next(x) != h0; x = g.next(x))
    if (g.halfedge(v0, g.target(x)).is_valid()) return false;
  return true;
}

template <class P, class Visitor = Mutation_visitor>
bool genmesh_native_triangulate_face(Face_index f, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_triangulate_face(f, std::as_const(g))) return false;
  const Halfedge_index h0 = g.lowest_corner(f);
  while (g.degree(g.face(h0)) > 3) {
    const Halfedge_index h3 = detail::inc::split_face_raw(h0, g.next(g.next(h0)), g);
    visitor.on_split_face(h3, std::as_const(g));
  }
  return true;
}

template <class P, class Visitor = Mutation_visitor>
std::size_t genmesh_native_triangulate_faces(Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  std::vector<Face_index> todo;
  for (const Face_index f : g.faces())
    if (g.degree(f) != 3) todo.push_back(f);
  std::size_t refused = 0;
  for (const Face_index f : todo)
    if (!genmesh_native_triangulate_face(f, g, visitor)) ++refused;
  return refused;
}

// ---------------------------------------------------------------------------
// bevel_face, bevel_vertex
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_bevel_face(Face_index f, const Incidence_mesh<P>& g) {
  return g.is_manifold() && f.is_valid();
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Face_index> genmesh_native_bevel_face(Face_index f, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_bevel_face(f, std::as_const(g))) return std::nullopt;
  // The sides h_i = v_i → v_{i+1}, from next(halfedge(f)).
  const detail::inc::Hs side = detail::inc::cycle(g.next(g.halfedge(f)), g);
  const std::size_t n = side.size();
  boost::container::small_vector<Vertex_index, 8> w(n);
  boost::container::small_vector<Edge_index, 8> spoke(n), ring(n);
  boost::container::small_vector<Face_index, 8> quad(n);
  for (std::size_t i = 0; i < n; ++i) w[i] = g.add_vertex(P(g.point(g.source(side[i]))));
  for (std::size_t i = 0; i < n; ++i) {
    spoke[i] = g.add_edge();
    ring[i] = g.add_edge();
  }
  for (std::size_t i = 0; i < n; ++i) quad[i] = g.add_face();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    g.set_edge_vertices(spoke[j], g.target(side[i]), w[j]);
    g.set_edge_vertices(ring[i], w[i], w[j]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    g.remove_side(f, side[i]);
    g.add_side(quad[i], side[i]);
    g.add_side(quad[i], g.halfedge(spoke[j], 0));
    g.add_side(quad[i], g.halfedge(ring[i], 1));
    g.add_side(quad[i], g.halfedge(spoke[i], 1));
    g.add_side(f, g.halfedge(ring[i], 0));
  }
  visitor.on_bevel_face(f, std::as_const(g));
  return f;
}

template <class P>
bool genmesh_native_can_bevel_vertex(Vertex_index v, const Incidence_mesh<P>& g) {
  return g.is_manifold() && v.is_valid() && g.degree(v) >= 3 && !detail::lo::border_vertex(v, g);
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Face_index> genmesh_native_bevel_vertex(Vertex_index v, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_bevel_vertex(v, std::as_const(g))) return std::nullopt;
  detail::inc::Hs in;
  {
    const Halfedge_index start = g.halfedge(v);
    Halfedge_index x = start;
    do {
      in.push_back(x);
      x = g.opposite(g.next(x));
    } while (x != start);
  }
  const std::size_t d = in.size();
  boost::container::small_vector<Face_index, 8> fin(d);
  boost::container::small_vector<Vertex_index, 8> src(d);
  for (std::size_t i = 0; i < d; ++i) {
    fin[i] = g.face(in[i]);
    src[i] = g.source(in[i]);
  }
  boost::container::small_vector<Vertex_index, 8> w(d);
  boost::container::small_vector<Edge_index, 8> ring(d);
  for (std::size_t i = 0; i < d; ++i) w[i] = g.add_vertex(P(g.point(v)));
  for (std::size_t i = 0; i < d; ++i) ring[i] = g.add_edge();
  const Face_index nf = g.add_face();
  for (std::size_t i = 0; i < d; ++i) g.set_halfedge_vertices(in[i], src[i], w[i]);
  for (std::size_t i = 0; i < d; ++i) {
    const std::size_t j = (i + 1) % d;
    g.set_edge_vertices(ring[i], w[i], w[j]);
    g.add_side(fin[i], g.halfedge(ring[i], 0));
    g.add_side(nf, g.halfedge(ring[i], 1));
  }
  g.remove_vertex(v);
  visitor.on_bevel_vertex(nf, std::as_const(g));
  return nf;
}

// ---------------------------------------------------------------------------
// bevel_edge
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_bevel_edge(Halfedge_index h, const Incidence_mesh<P>& g) {
  if (!g.is_manifold() || !h.is_valid()) return false;
  if (g.face(h) == g.face(g.opposite(h))) return false;
  return g.degree(g.target(h)) >= 3 || g.degree(g.source(h)) >= 3;
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Halfedge_index> genmesh_native_bevel_edge(Halfedge_index h, Incidence_mesh<P>& g,
                                                        const Bevel_edge_options& options = {},
                                                        Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!(options.fraction >= 0.0 && options.fraction < 1.0))
    throw invalid_input("bevel_edge: fraction " + std::to_string(options.fraction) + " is not in [0, 1)");
  if (!genmesh_native_can_bevel_edge(h, std::as_const(g))) return std::nullopt;
  // Read: the halfedges into v from h (towards R) and into u from opposite(h).
  const Halfedge_index oh = g.opposite(h);
  const Vertex_index u = g.source(h), v = g.target(h);
  const Face_index fr = g.face(oh);
  detail::inc::Hs in_v, in_u;
  for (Halfedge_index x = h;;) {
    in_v.push_back(x);
    x = g.opposite(g.next(x));
    if (x == h) break;
  }
  for (Halfedge_index x = oh;;) {
    in_u.push_back(x);
    x = g.opposite(g.next(x));
    if (x == oh) break;
  }
  const std::size_t dv = in_v.size(), du = in_u.size();
  const std::size_t mv = dv >= 3 ? (dv - 1) / 2 : 0, mu = du >= 3 ? (du - 1) / 2 : 0;
  const std::size_t k = mv ? dv - 1 - mv : 0;
  const Face_index fvk = mv ? g.face(in_v[k]) : Face_index(), fuk = mu ? g.face(in_u[mu]) : Face_index();
  boost::container::small_vector<Vertex_index, 8> src_v(dv), src_u(du);
  for (std::size_t i = 0; i < dv; ++i) src_v[i] = g.source(in_v[i]);
  for (std::size_t i = 0; i < du; ++i) src_u[i] = g.source(in_u[i]);
  [[maybe_unused]] Eigen::Vector3d pv, pv2, pu, pu2;
  if constexpr (Point3<P>) {
    const double t = options.fraction;
    auto at = [&](Vertex_index x) { return to_eigen(g.point(x)); };
    auto slide = [&](Vertex_index from, Vertex_index to) {
      return Eigen::Vector3d((1 - t) * at(from) + t * at(to));
    };
    pv = mv ? slide(v, src_v[1]) : at(v);
    pv2 = mv ? slide(v, src_v[dv - 1]) : at(v);
    pu = mu ? slide(u, src_u[du - 1]) : at(u);
    pu2 = mu ? slide(u, src_u[1]) : at(u);
  }
  // Create, in the generic order: e', u–u', v–v', u', v', Q.
  const Edge_index ee = g.add_edge();
  const Edge_index ecu = mu ? g.add_edge() : Edge_index();
  const Edge_index ecv = mv ? g.add_edge() : Edge_index();
  const Vertex_index u2 = mu ? g.add_vertex() : u;
  const Vertex_index v2 = mv ? g.add_vertex() : v;
  const Face_index q = g.add_face();
  // Connect: the R-side edges go to the new ends; each cut corner gains a side.
  if (mv) {
    for (std::size_t i = k + 1; i < dv; ++i) g.set_halfedge_vertices(in_v[i], src_v[i], v2);
    g.set_edge_vertices(ecv, v, v2);
    if (fvk.is_valid()) g.add_side(fvk, g.halfedge(ecv, 0));
  }
  if (mu) {
    for (std::size_t i = 1; i <= mu; ++i) g.set_halfedge_vertices(in_u[i], src_u[i], u2);
    g.set_edge_vertices(ecu, u2, u);
    if (fuk.is_valid()) g.add_side(fuk, g.halfedge(ecu, 0));
  }
  g.set_edge_vertices(ee, u2, v2); // e': u' → v' in Q, v' → u' in R
  if (fr.is_valid()) {
    g.remove_side(fr, oh);
    g.add_side(fr, g.halfedge(ee, 1));
  }
  g.add_side(q, oh);
  g.add_side(q, g.halfedge(ee, 0));
  if (mu) g.add_side(q, g.halfedge(ecu, 1));
  if (mv) g.add_side(q, g.halfedge(ecv, 1));
  if constexpr (Point3<P>) {
    g.point(v) = from_eigen<P>(pv);
    g.point(v2) = from_eigen<P>(pv2);
    g.point(u) = from_eigen<P>(pu);
    g.point(u2) = from_eigen<P>(pu2);
  }
  visitor.on_bevel_edge(oh, std::as_const(g));
  return oh;
}

// ---------------------------------------------------------------------------
// erase_vertex, erase_edge
// ---------------------------------------------------------------------------

template <class P>
bool genmesh_native_can_erase_vertex(Vertex_index v, const Incidence_mesh<P>& g) {
  if (!g.is_manifold() || !v.is_valid()) return false;
  const Halfedge_index h = g.halfedge(v);
  return h.is_valid() && genmesh_native_can_remove_center_vertex(h, g);
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Face_index> genmesh_native_erase_vertex(Vertex_index v, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_erase_vertex(v, std::as_const(g))) return std::nullopt;
  const auto h = genmesh_native_remove_center_vertex(g.halfedge(v), g, visitor);
  return g.face(*h);
}

template <class P>
bool genmesh_native_can_erase_edge(Edge_index e, const Incidence_mesh<P>& g) {
  return e.is_valid() && genmesh_native_can_join_face(g.halfedge(e), g);
}

template <class P, class Visitor = Mutation_visitor>
std::optional<Face_index> genmesh_native_erase_edge(Edge_index e, Incidence_mesh<P>& g, Visitor&& visitor = {}) {
  const detail::inc::Face_order_update<P> orders{g};
  if (!genmesh_native_can_erase_edge(e, std::as_const(g))) return std::nullopt;
  const auto r = genmesh_native_join_face(g.halfedge(e), g, visitor);
  return g.face(*r);
}

} // namespace genmesh
