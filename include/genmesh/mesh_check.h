// genmesh/mesh_check.h — check_mesh(g): every halfedge invariant of any graph.
//
// check_mesh(g) verifies every halfedge invariant of any FaceListGraph and
// names each violation (the element by its index, the broken relation in
// words), then counts vertices, edges, faces, border halfedges, boundary loops
// and connected components, and derives the Euler characteristic and genus.
// It is at least as strict as CGAL's is_valid_polygon_mesh, except that an
// isolated vertex (no halfedge) is allowed and counted, and that
// halfedge(edge(h)) == h is not demanded for both halfedges of an edge (CGAL's
// check does; it holds for Surface_mesh, whose edge descriptors carry a
// halfedge, not for an edge = h/2 representation). A border vertex whose
// halfedge(v) is not a border halfedge is counted, not flagged.
//
// Guarantees: every walk is bounded by the element counts and every element
// is visited O(1) times, so the check runs in linear time, in named passes
// (detail::mesh_check), and terminates on any corrupt mesh.
// Limits: connectivity only; positions are not looked at.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/validity/dense_index.h>
#include <genmesh/detail/validity/union_find.h>
#include <genmesh/property_maps.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace genmesh {

// ---------------------------------------------------------------------------
// Mesh check
// ---------------------------------------------------------------------------

/// What a halfedge-mesh problem is about.
enum class Mesh_problem_kind {
  invalid_reference,   ///< a link is null or names an element that is not live
  opposite,            ///< opposite(opposite(h)) != h, opposite(h) == h, or edges disagree
  next_prev,           ///< next(prev(h)) != h or prev(next(h)) != h
  next_not_unique,     ///< h is the next of zero or several halfedges
  next_source,         ///< source(next(h)) != target(h)
  next_face,           ///< face(next(h)) != face(h)
  self_loop,           ///< target(h) == source(h), or next(h) == h
  face_cycle,          ///< the cycle of f is not closed, shorter than 3, or misses halfedges of f
  face_halfedge,       ///< face(halfedge(f)) != f
  vertex_halfedge,     ///< target(halfedge(v)) != v, or halfedge(v) null while halfedges end at v
  vertex_cycle,        ///< the walk around v via opposite(next(h)) does not close at v
  edge_halfedge,       ///< halfedge(e) is not a halfedge of e
  edge_faces,          ///< both sides of an edge are the border, or the same face
  non_manifold_vertex, ///< several fans meet at v (a valid structure, but not a manifold)
};

/// The kind's name, e.g. "next_prev".
inline const char* to_string(Mesh_problem_kind k) {
  switch (k) {
    case Mesh_problem_kind::invalid_reference: return "invalid_reference";
    case Mesh_problem_kind::opposite: return "opposite";
    case Mesh_problem_kind::next_prev: return "next_prev";
    case Mesh_problem_kind::next_not_unique: return "next_not_unique";
    case Mesh_problem_kind::next_source: return "next_source";
    case Mesh_problem_kind::next_face: return "next_face";
    case Mesh_problem_kind::self_loop: return "self_loop";
    case Mesh_problem_kind::face_cycle: return "face_cycle";
    case Mesh_problem_kind::face_halfedge: return "face_halfedge";
    case Mesh_problem_kind::vertex_halfedge: return "vertex_halfedge";
    case Mesh_problem_kind::vertex_cycle: return "vertex_cycle";
    case Mesh_problem_kind::edge_halfedge: return "edge_halfedge";
    case Mesh_problem_kind::edge_faces: return "edge_faces";
    case Mesh_problem_kind::non_manifold_vertex: return "non_manifold_vertex";
  }
  return "unknown";
}

/// One violated invariant. `element` is "halfedge 12", "face 3", "vertex 7"
/// or "edge 5", numbered by the graph's index maps (or, without them, by
/// iteration order).
struct Mesh_problem {
  Mesh_problem_kind kind;
  std::string element;
  std::string message;
};

/// What check_mesh() found.
///
/// Components: connected components of the vertex–edge graph; an isolated
/// vertex is a component of its own (so χ = V − E + F sums over components,
/// an isolated vertex contributing 1). Genus: the sum over components with
/// faces of (2 − χ_c − b_c) / 2, b_c the boundary loops of the component;
/// empty when the mesh is not valid and manifold.
struct Mesh_report {
  std::size_t vertices = 0, halfedges = 0, edges = 0, faces = 0;
  std::size_t isolated_vertices = 0;
  std::size_t border_halfedges = 0;
  std::size_t boundary_loops = 0;
  std::size_t components = 0;
  std::size_t non_manifold_vertices = 0;
  /// Border vertices whose halfedge(v) is not a border halfedge. Not a
  /// problem: CGAL's Surface_mesh allows it (its Euler operations can leave
  /// it so), but code that finds the border through halfedge(v) misses these.
  /// build_mesh() never leaves one.
  std::size_t border_vertices_with_inner_halfedge = 0;
  long euler_characteristic = 0;
  std::optional<long> genus;
  bool is_triangle_mesh = true; ///< every face has three sides (true for no faces)
  bool is_quad_mesh = true;     ///< every face has four sides (true for no faces)
  bool is_closed = true;        ///< no border halfedge
  bool valid = true;            ///< no invariant problem (non-manifold vertices aside)
  bool manifold = true;         ///< valid and no non-manifold vertex

  /// The first max_problems problems found, in a deterministic order (check
  /// by check: halfedge links, edges, face cycles, vertices; each in index
  /// order), so equal meshes on different backends give equal lists.
  std::vector<Mesh_problem> problems;
  /// Every problem found, including those not kept in `problems`.
  std::size_t problem_count = 0;
  static constexpr std::size_t max_problems = 100;

  /// Valid and manifold.
  bool ok() const noexcept { return valid && manifold; }
};

namespace detail {

class Problem_sink {
public:
  explicit Problem_sink(Mesh_report& r) : r_(r) {}
  void operator()(Mesh_problem_kind kind, const char* element, std::size_t index, std::string msg) {
    ++r_.problem_count;
    if (r_.problems.size() < Mesh_report::max_problems)
      r_.problems.push_back({kind, std::string(element) + " " + std::to_string(index), std::move(msg)});
  }

private:
  Mesh_report& r_;
};

inline std::string ref_name(const char* what, std::uint32_t i) {
  if (i == k_null) return "the null " + std::string(what);
  if (i == k_bad) return std::string("a ") + what + " that is not live";
  return std::string(what) + " " + std::to_string(i);
}

} // namespace detail

namespace detail::mesh_check {

/// What every pass of check_mesh() reads: the graph, the report, and dense
/// numbers of its live elements. The passes follow the graph's own links by
/// descriptor (checking each link is live before following it), so the
/// check holds no copy of the links: per halfedge it keeps one byte
/// (next-count) and one word (which face cycle or vertex fan claimed it).
template <class G>
struct Context {
  using Traits = boost::graph_traits<G>;
  using V = vertex_descriptor_t<G>;
  using H = halfedge_descriptor_t<G>;
  using F = face_descriptor_t<G>;

  const G& g;
  Mesh_report& r;
  Problem_sink problem;
  Dense_index<G, vertex_index_t, V> vi;
  Dense_index<G, halfedge_index_t, H> hi;
  Dense_index<G, face_index_t, F> fi;

  Context(const G& graph, Mesh_report& report)
      : g(graph), r(report), problem(report), vi(graph, vertices(graph), Traits::null_vertex()),
        hi(graph, halfedges(graph), Traits::null_halfedge()), fi(graph, faces(graph), Traits::null_face()) {}
};

/// Pass 1: the links of every live halfedge — references live, opposite an
/// involution on distinct edges, next/prev inverse, source(next(h)) ==
/// target(h), face(next(h)) == face(h), one face per side — and how many
/// halfedges name each as next (saturating at 255).
template <class G>
void check_halfedge_links(Context<G>& c, std::vector<std::uint8_t>& pred_count) {
  const G& g = c.g;
  auto& problem = c.problem;
  for (auto h : halfedges(g)) {
    const std::uint32_t i = c.hi(h);
    if (!is_ref(i)) continue;
    ++c.r.halfedges;
    const auto nd = next(h, g), pd = prev(h, g), od = opposite(h, g);
    const std::uint32_t n = c.hi(nd), p = c.hi(pd), o = c.hi(od), t = c.vi(target(h, g)), f = c.fi(face(h, g));
    if (f == k_null) ++c.r.border_halfedges;
    if (!is_ref(n)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "next is " + ref_name("halfedge", n));
    if (!is_ref(p)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "prev is " + ref_name("halfedge", p));
    if (!is_ref(o)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "opposite is " + ref_name("halfedge", o));
    if (!is_ref(t)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "target is " + ref_name("vertex", t));
    if (f == k_bad) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "face is a face that is not live");
    if (is_ref(n) && pred_count[n] != 255) ++pred_count[n];
    if (is_ref(o)) {
      if (!(edge(h, g) == edge(od, g)))
        problem(Mesh_problem_kind::opposite, "halfedge", i,
                "edge(h) differs from edge(opposite(h)) (opposite is halfedge " + std::to_string(o) + ")");
      const std::uint32_t oo = c.hi(opposite(od, g)), ot = c.vi(target(od, g)), of = c.fi(face(od, g));
      if (o == i) problem(Mesh_problem_kind::opposite, "halfedge", i, "opposite(h) == h");
      else if (oo != i)
        problem(Mesh_problem_kind::opposite, "halfedge", i,
                "opposite(opposite(h)) is " + ref_name("halfedge", oo) + ", not h (opposite is halfedge " +
                    std::to_string(o) + ")");
      if (is_ref(t) && ot == t)
        problem(Mesh_problem_kind::self_loop, "halfedge", i, "source and target are both vertex " + std::to_string(t));
      if (o != i && f == k_null && of == k_null)
        problem(Mesh_problem_kind::edge_faces, "halfedge", i,
                "both sides of its edge are border (edge without a face, opposite is halfedge " + std::to_string(o) + ")");
      else if (o != i && is_ref(f) && of == f && i < o)
        problem(Mesh_problem_kind::edge_faces, "halfedge", i,
                "face " + std::to_string(f) + " lies on both sides of its edge");
    }
    if (is_ref(n)) {
      if (n == i) problem(Mesh_problem_kind::self_loop, "halfedge", i, "next(h) == h");
      const std::uint32_t np = c.hi(prev(nd, g)), nf = c.fi(face(nd, g));
      if (np != i)
        problem(Mesh_problem_kind::next_prev, "halfedge", i,
                "prev(next(h)) is " + ref_name("halfedge", np) + ", not h (next is halfedge " + std::to_string(n) + ")");
      const auto nod = opposite(nd, g);
      if (is_ref(c.hi(nod)) && is_ref(t)) {
        const std::uint32_t ns = c.vi(target(nod, g));
        if (ns != t)
          problem(Mesh_problem_kind::next_source, "halfedge", i,
                  "target is vertex " + std::to_string(t) + " but source(next(h)) is " + ref_name("vertex", ns) +
                      " (next is halfedge " + std::to_string(n) + ")");
      }
      if (nf != f && f != k_bad && nf != k_bad)
        problem(Mesh_problem_kind::next_face, "halfedge", i,
                "face is " + ref_name("face", f) + " but face(next(h)) is " + ref_name("face", nf) +
                    " (next is halfedge " + std::to_string(n) + ")");
    }
    if (is_ref(p)) {
      const std::uint32_t pn = c.hi(next(pd, g));
      if (pn != i)
        problem(Mesh_problem_kind::next_prev, "halfedge", i,
                "next(prev(h)) is " + ref_name("halfedge", pn) + ", not h (prev is halfedge " + std::to_string(p) + ")");
    }
  }
}

/// Pass 2: every live halfedge is next of exactly one halfedge.
template <class G>
void check_next_unique(Context<G>& c, const std::vector<std::uint8_t>& pred_count) {
  for (std::size_t i = 0; i < pred_count.size(); ++i)
    if (c.hi.is_live(i) && pred_count[i] != 1)
      c.problem(Mesh_problem_kind::next_not_unique, "halfedge", i,
                "is next of " + std::string(pred_count[i] == 255 ? "255 or more" : std::to_string(pred_count[i])) +
                    " halfedges, not exactly one");
}

/// Pass 3: halfedge(e) is a live halfedge of e; counts edges.
template <class G>
void check_edges(Context<G>& c) {
  const G& g = c.g;
  Dense_index<G, edge_index_t, edge_descriptor_t<G>> ei(g, edges(g), edge_descriptor_t<G>{});
  for (auto e : edges(g)) {
    ++c.r.edges;
    const auto h = halfedge(e, g);
    const std::uint32_t i = c.hi(h);
    if (!is_ref(i) || !(edge(h, g) == e))
      c.problem(Mesh_problem_kind::edge_halfedge, "edge", ei(e),
                "halfedge(e) is " + ref_name("halfedge", i) + (is_ref(i) ? ", whose edge is another" : ""));
  }
}

/// Pass 4: each face's cycle from halfedge(f) closes, has ≥ 3 halfedges and
/// shares none with another cycle; seen_by[h] becomes the face whose walk
/// passed h. Then every halfedge with a face lies on that face's cycle.
template <class G>
void check_face_cycles(Context<G>& c, std::vector<std::uint32_t>& seen_by) {
  const G& g = c.g;
  for (auto fd : faces(g)) {
    const std::uint32_t f = c.fi(fd);
    if (!is_ref(f)) continue;
    ++c.r.faces;
    const auto hd = halfedge(fd, g);
    const std::uint32_t h = c.hi(hd);
    if (!is_ref(h)) {
      c.problem(Mesh_problem_kind::invalid_reference, "face", f, "halfedge(f) is " + ref_name("halfedge", h));
      continue;
    }
    if (const std::uint32_t hf = c.fi(face(hd, g)); hf != f) {
      c.problem(Mesh_problem_kind::face_halfedge, "face", f,
                "halfedge(f) is halfedge " + std::to_string(h) + " whose face is " + ref_name("face", hf));
      continue;
    }
    std::size_t len = 0;
    halfedge_descriptor_t<G> cd = hd;
    std::uint32_t ci = h;
    bool closed = false;
    std::string why;
    while (true) {
      if (seen_by[ci] != k_null) {
        why = seen_by[ci] == f ? "returns to halfedge " + std::to_string(ci) + " without passing halfedge(f)"
                               : "runs into halfedge " + std::to_string(ci) + " of face " + std::to_string(seen_by[ci]) +
                                     "'s cycle";
        break;
      }
      seen_by[ci] = f;
      ++len;
      const auto nd = next(cd, g);
      const std::uint32_t n = c.hi(nd);
      if (!is_ref(n)) {
        why = "reaches halfedge " + std::to_string(ci) + " whose next is " + ref_name("halfedge", n);
        break;
      }
      if (n == h) {
        closed = true;
        break;
      }
      cd = nd;
      ci = n;
    }
    if (!closed) c.problem(Mesh_problem_kind::face_cycle, "face", f, "the cycle from halfedge(f) " + why);
    else if (len < 3)
      c.problem(Mesh_problem_kind::face_cycle, "face", f, "its cycle has " + std::to_string(len) + " halfedges (< 3)");
    if (len != 3) c.r.is_triangle_mesh = false;
    if (len != 4) c.r.is_quad_mesh = false;
  }
  for (auto hd : halfedges(g)) {
    const std::uint32_t i = c.hi(hd);
    if (!is_ref(i)) continue;
    const std::uint32_t f = c.fi(face(hd, g));
    if (is_ref(f) && seen_by[i] != f && c.fi.is_live(f))
      c.problem(Mesh_problem_kind::face_cycle, "halfedge", i,
                "has face " + std::to_string(f) + " but is not on that face's cycle");
  }
}

/// Pass 5: cycles of border halfedges not yet walked, each counted once.
template <class G>
void count_boundary_loops(Context<G>& c, std::vector<std::uint32_t>& seen_by) {
  const G& g = c.g;
  for (auto hd : halfedges(g)) {
    const std::uint32_t i = c.hi(hd);
    if (!is_ref(i) || seen_by[i] != k_null || c.fi(face(hd, g)) != k_null) continue;
    ++c.r.boundary_loops;
    halfedge_descriptor_t<G> cd = hd;
    std::uint32_t ci = i;
    while (is_ref(ci) && seen_by[ci] == k_null && c.fi(face(cd, g)) == k_null) {
      seen_by[ci] = k_bad; // marks "on a boundary walk"
      cd = next(cd, g);
      ci = c.hi(cd);
    }
  }
}

/// Pass 6: halfedge(v) targets v, and the halfedges ending at v form one fan
/// (walked via opposite(next(h))) with at most one border gap. fan_seen is
/// scratch (all k_null on entry).
template <class G>
void check_vertex_fans(Context<G>& c, std::vector<std::uint32_t>& fan_seen) {
  const G& g = c.g;
  std::vector<std::uint32_t> in_count(c.vi.bound(), 0);
  for (auto hd : halfedges(g))
    if (is_ref(c.hi(hd)))
      if (const std::uint32_t t = c.vi(target(hd, g)); is_ref(t)) ++in_count[t];
  for (auto vd : vertices(g)) {
    const std::uint32_t v = c.vi(vd);
    if (!is_ref(v)) continue;
    ++c.r.vertices;
    const auto hd = halfedge(vd, g);
    const std::uint32_t h = c.hi(hd);
    if (h == k_null) {
      if (in_count[v] == 0) ++c.r.isolated_vertices;
      else
        c.problem(Mesh_problem_kind::vertex_halfedge, "vertex", v,
                  "halfedge(v) is null but " + std::to_string(in_count[v]) + " halfedges end at it");
      continue;
    }
    if (h == k_bad) {
      c.problem(Mesh_problem_kind::invalid_reference, "vertex", v, "halfedge(v) is a halfedge that is not live");
      continue;
    }
    if (const std::uint32_t t = c.vi(target(hd, g)); t != v) {
      c.problem(Mesh_problem_kind::vertex_halfedge, "vertex", v,
                "halfedge(v) is halfedge " + std::to_string(h) + " whose target is " + ref_name("vertex", t));
      continue;
    }
    std::size_t len = 0;
    halfedge_descriptor_t<G> cd = hd;
    std::uint32_t ci = h;
    bool closed = false, on_border = false;
    std::size_t border_in = 0; // border halfedges ending at v: one per gap in its fan
    while (len <= in_count[v]) {
      if (!is_ref(ci) || c.vi(target(cd, g)) != v || fan_seen[ci] != k_null) break;
      fan_seen[ci] = v;
      const bool border = c.fi(face(cd, g)) == k_null;
      on_border = on_border || border;
      border_in += border ? 1 : 0;
      ++len;
      const auto nd = next(cd, g);
      if (!is_ref(c.hi(nd))) break;
      cd = opposite(nd, g);
      ci = c.hi(cd);
      if (ci == h) {
        closed = true;
        break;
      }
    }
    if (closed && on_border && c.fi(face(hd, g)) != k_null) ++c.r.border_vertices_with_inner_halfedge;
    if (!closed)
      c.problem(Mesh_problem_kind::vertex_cycle, "vertex", v,
                "the walk around it via opposite(next(h)) from halfedge " + std::to_string(h) + " does not close");
    else if (len != in_count[v]) {
      ++c.r.non_manifold_vertices;
      c.problem(Mesh_problem_kind::non_manifold_vertex, "vertex", v,
                std::to_string(in_count[v]) + " halfedges end at it but its fan has only " + std::to_string(len) +
                    ": several fans meet here");
    } else if (border_in > 1) {
      // The border links can join two fans into one closed walk: the walk
      // is complete, yet the border passes through v more than once.
      ++c.r.non_manifold_vertices;
      c.problem(Mesh_problem_kind::non_manifold_vertex, "vertex", v,
                "the border passes through it " + std::to_string(border_in) + " times: several fans meet here");
    }
  }
}

/// The two ends of h as dense vertex numbers, if h and its opposite are live.
template <class G>
bool halfedge_ends(const Context<G>& c, halfedge_descriptor_t<G> hd, std::uint32_t& s, std::uint32_t& t) {
  const auto od = opposite(hd, c.g);
  if (!is_ref(c.hi(od))) return false;
  t = c.vi(target(hd, c.g));
  s = c.vi(target(od, c.g));
  return is_ref(t) && is_ref(s);
}

/// Pass 7: connected components of the vertex–edge graph (isolated vertices
/// count); returns the union-find for the genus.
template <class G>
Union_find count_components(Context<G>& c) {
  Union_find uf(c.vi.bound());
  for (auto hd : halfedges(c.g)) {
    std::uint32_t s = 0, t = 0;
    if (is_ref(c.hi(hd)) && halfedge_ends(c, hd, s, t)) uf.unite(t, s);
  }
  for (std::size_t v = 0; v < c.vi.bound(); ++v)
    if (c.vi.is_live(v) && uf.find(static_cast<std::uint32_t>(v)) == v) ++c.r.components;
  return uf;
}

/// Pass 8 (valid meshes only): genus per component with faces, summed;
/// left empty where 2 − χ_c − b_c is odd or negative.
template <class G>
void compute_genus(Context<G>& c, Union_find& uf) {
  const G& g = c.g;
  const std::size_t nv = c.vi.bound();
  std::vector<long> chi(nv, 0), loops(nv, 0);
  std::vector<char> has_face(nv, 0);
  for (std::size_t v = 0; v < nv; ++v)
    if (c.vi.is_live(v)) ++chi[uf.find(static_cast<std::uint32_t>(v))];
  std::vector<char> loop_seen(c.hi.bound(), 0);
  for (auto hd : halfedges(g)) {
    const std::uint32_t i = c.hi(hd);
    if (!is_ref(i)) continue;
    const std::uint32_t root = uf.find(c.vi(target(hd, g)));
    if (i < c.hi(opposite(hd, g))) --chi[root]; // one per edge
    if (c.fi(face(hd, g)) == k_null && !loop_seen[i]) {
      ++loops[root];
      halfedge_descriptor_t<G> cd = hd;
      for (std::uint32_t ci = i; !loop_seen[ci]; cd = next(cd, g), ci = c.hi(cd)) loop_seen[ci] = 1;
    }
  }
  for (auto fd : faces(g)) {
    if (!is_ref(c.fi(fd))) continue;
    const std::uint32_t root = uf.find(c.vi(target(halfedge(fd, g), g)));
    ++chi[root];
    has_face[root] = 1;
  }
  long genus = 0;
  bool defined = true;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!c.vi.is_live(v) || !has_face[v] || uf.find(static_cast<std::uint32_t>(v)) != v) continue;
    const long twice = 2 - chi[v] - loops[v];
    if (twice < 0 || twice % 2 != 0) defined = false;
    else genus += twice / 2;
  }
  if (defined) c.r.genus = genus;
}

} // namespace detail::mesh_check

/// Checks every halfedge invariant of g and counts its elements, boundary
/// loops and components. Never throws on a corrupt mesh and never loops:
/// every walk is bounded. Runs in time linear in the index bounds, in named
/// passes (detail::mesh_check) that follow g's own links: besides three
/// dense-number tables it holds 5 bytes per halfedge and ~25 per vertex.
template <class G>
  requires FaceListGraph<G> && HalfedgeListGraph<G> && VertexListGraph<G> && EdgeListGraph<G>
Mesh_report check_mesh(const G& g) {
  using namespace detail;
  using namespace detail::mesh_check;
  Mesh_report r;
  Context<G> c(g, r);
  {
    std::vector<std::uint8_t> pred_count(c.hi.bound(), 0);
    check_halfedge_links(c, pred_count);
    check_next_unique(c, pred_count);
  }
  check_edges(c);
  {
    std::vector<std::uint32_t> seen_by(c.hi.bound(), k_null);
    check_face_cycles(c, seen_by);
    count_boundary_loops(c, seen_by);
    std::fill(seen_by.begin(), seen_by.end(), k_null);
    check_vertex_fans(c, seen_by);
  }

  r.valid = r.problem_count == r.non_manifold_vertices;
  r.manifold = r.valid && r.non_manifold_vertices == 0;
  r.is_closed = r.border_halfedges == 0;
  if (r.faces == 0) r.is_triangle_mesh = r.is_quad_mesh = true;
  r.euler_characteristic = static_cast<long>(r.vertices) - static_cast<long>(r.edges) + static_cast<long>(r.faces);

  Union_find uf = count_components(c);
  if (r.ok()) compute_genus(c, uf);
  return r;
}

/// Human-readable lines: the counts, then one line per problem kept.
inline std::string to_string(const Mesh_report& r) {
  std::ostringstream s;
  s << (r.ok() ? "valid manifold mesh" : r.valid ? "valid but non-manifold mesh" : "INVALID mesh") << "\n"
    << "vertices " << r.vertices << " (isolated " << r.isolated_vertices << "), halfedges " << r.halfedges
    << ", edges " << r.edges << ", faces " << r.faces << "\n"
    << "border halfedges " << r.border_halfedges << ", boundary loops " << r.boundary_loops << ", components "
    << r.components << "\n"
    << "euler characteristic " << r.euler_characteristic << ", genus "
    << (r.genus ? std::to_string(*r.genus) : std::string("undefined")) << "\n"
    << (r.is_triangle_mesh ? "triangle mesh" : r.is_quad_mesh ? "quad mesh" : "polygon mesh")
    << (r.is_closed ? ", closed" : ", with border") << "\n";
  for (const auto& p : r.problems) s << p.element << ": " << to_string(p.kind) << ": " << p.message << "\n";
  if (r.problem_count > r.problems.size())
    s << "... and " << (r.problem_count - r.problems.size()) << " more problems\n";
  return s.str();
}

} // namespace genmesh
