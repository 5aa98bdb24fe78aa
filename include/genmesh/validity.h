// genmesh/validity.h — checks of halfedge meshes and polygon soups, and soup repair.
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
// check_soup(soup) finds what would stop a polygon soup from becoming a
// halfedge mesh: degenerate faces, indices out of range, non-finite points,
// duplicate faces, edges shared by three or more faces (fins), edges used in
// the same direction by two faces (inconsistent orientation) and vertices
// whose faces form several fans (bow-ties); zero-area faces and isolated
// points are reported but do not fail the check.
//
// repair_soup(soup) removes degenerate, duplicate and out-of-range faces,
// drops the faces beyond the first two on a fin edge, reorients every
// orientable connected component consistently and splits non-manifold
// vertices, saying what it changed; what it cannot fix (a Möbius strip, a NaN
// point) it reports.
//
// Guarantees: every walk is bounded by the element counts and every element is
// visited O(1) times, so the checks run in linear time (the soup check sorts
// per-vertex edge buckets) and terminate on any corrupt mesh.
// Limits: geometry is checked only for non-finite points and zero-area faces;
// self-intersections are not looked for.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/property_maps.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <unordered_map>
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

inline constexpr std::uint32_t k_null = 0xffffffffu; // the null descriptor
inline constexpr std::uint32_t k_bad = 0xfffffffeu;  // a descriptor that is not live

inline bool is_ref(std::uint32_t i) { return i < k_bad; }

template <class G, class Tag, bool Indexed>
struct Index_map_of {
  using type = int;
};
template <class G, class Tag>
struct Index_map_of<G, Tag, true> {
  using type = decltype(get(Tag{}, std::declval<const G&>()));
};

/// Dense numbers for the live elements of one kind: the backend's index map
/// when it has one, else the iteration order. Maps the null descriptor to
/// k_null and anything not live to k_bad.
template <class G, class Tag, class D>
class Dense_index {
  static constexpr bool indexed = HasIndexMap<G, Tag>;
  using Map = typename Index_map_of<G, Tag, indexed>::type;

public:
  template <class Range>
  Dense_index(const G& g, const Range& live, D null) : null_(null) {
    if constexpr (indexed) {
      map_.emplace(get(Tag{}, g));
      bound_ = static_cast<std::size_t>(index_bound(Tag{}, g));
      alive_.assign(bound_, 0);
      for (D d : live) {
        std::size_t i = static_cast<std::size_t>(get(*map_, d));
        if (i < bound_) alive_[i] = 1;
      }
    } else {
      for (D d : live) numbers_.emplace(d, static_cast<std::uint32_t>(numbers_.size()));
      bound_ = numbers_.size();
    }
  }

  std::size_t bound() const noexcept { return bound_; }
  /// Whether dense number i (< bound()) is a live element's.
  bool is_live(std::size_t i) const {
    if constexpr (indexed) return alive_[i] != 0;
    else return i < bound_;
  }

  std::uint32_t operator()(D d) const {
    if (d == null_) return k_null;
    if constexpr (indexed) {
      std::size_t i = static_cast<std::size_t>(get(*map_, d));
      return i < bound_ && alive_[i] ? static_cast<std::uint32_t>(i) : k_bad;
    } else {
      auto it = numbers_.find(d);
      return it == numbers_.end() ? k_bad : it->second;
    }
  }

private:
  D null_;
  std::size_t bound_ = 0;
  std::optional<Map> map_;
  std::vector<char> alive_;
  std::unordered_map<D, std::uint32_t> numbers_;
};

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

struct Union_find {
  std::vector<std::uint32_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  // The smaller root wins, so roots are deterministic.
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent[b] = a;
    else parent[a] = b;
  }
};

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

// ---------------------------------------------------------------------------
// Soup check
// ---------------------------------------------------------------------------

/// What a polygon-soup problem is about.
enum class Soup_problem_kind {
  index_out_of_range,   ///< error: a corner names no point
  degenerate_face,      ///< error: fewer than 3 corners, or a corner repeated
  non_finite_point,     ///< error: a coordinate is NaN or infinite
  duplicate_face,       ///< error: two faces with the same set of corners
  non_manifold_edge,    ///< error: an edge shared by three or more faces (a fin)
  inconsistent_orientation, ///< error: two faces use an edge in the same direction
  non_manifold_vertex,  ///< error: the faces around a vertex form several fans (a bow-tie)
  zero_area_face,       ///< warning: the face's vector area is (nearly) zero
  isolated_point,       ///< info: a point no face uses
};

inline const char* to_string(Soup_problem_kind k) {
  switch (k) {
    case Soup_problem_kind::index_out_of_range: return "index_out_of_range";
    case Soup_problem_kind::degenerate_face: return "degenerate_face";
    case Soup_problem_kind::non_finite_point: return "non_finite_point";
    case Soup_problem_kind::duplicate_face: return "duplicate_face";
    case Soup_problem_kind::non_manifold_edge: return "non_manifold_edge";
    case Soup_problem_kind::inconsistent_orientation: return "inconsistent_orientation";
    case Soup_problem_kind::non_manifold_vertex: return "non_manifold_vertex";
    case Soup_problem_kind::zero_area_face: return "zero_area_face";
    case Soup_problem_kind::isolated_point: return "isolated_point";
  }
  return "unknown";
}

/// Whether a soup problem stops a halfedge mesh from being built.
inline bool is_error(Soup_problem_kind k) {
  return k != Soup_problem_kind::zero_area_face && k != Soup_problem_kind::isolated_point;
}

/// One soup problem: `element` names it ("face 4", "edge (2, 7)", "vertex 3",
/// "point 9"); `faces` and `vertices` list the soup indices involved.
struct Soup_problem {
  Soup_problem_kind kind;
  std::string element;
  std::string message;
  std::vector<std::size_t> faces;
  std::vector<std::size_t> vertices;
};

/// What check_soup() found. Counts cover every problem; `problems` keeps the
/// first max_problems of them (errors and warnings; isolated points are only
/// counted).
struct Soup_report {
  std::size_t points = 0, faces = 0;
  std::size_t out_of_range_faces = 0;
  std::size_t degenerate_faces = 0;
  std::size_t non_finite_points = 0;
  std::size_t duplicate_faces = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t inconsistent_edges = 0;
  std::size_t non_manifold_vertices = 0;
  std::size_t zero_area_faces = 0;
  std::size_t isolated_points = 0;
  std::size_t border_edges = 0; ///< edges used by exactly one face
  std::size_t edges = 0;        ///< undirected edges of the non-degenerate faces

  std::vector<Soup_problem> problems;
  std::size_t problem_count = 0;
  static constexpr std::size_t max_problems = 100;

  std::size_t errors() const noexcept {
    return out_of_range_faces + degenerate_faces + non_finite_points + duplicate_faces + non_manifold_edges +
           inconsistent_edges + non_manifold_vertices;
  }
  /// No error (warnings and isolated points allowed): a halfedge mesh can be built.
  bool ok() const noexcept { return errors() == 0; }
};

inline std::string to_string(const Soup_report& r) {
  std::ostringstream s;
  s << (r.ok() ? "soup ok" : "soup NOT ok") << ": " << r.points << " points, " << r.faces << " faces, " << r.edges
    << " edges (" << r.border_edges << " border)\n";
  auto line = [&](const char* what, std::size_t n) {
    if (n) s << what << ": " << n << "\n";
  };
  line("faces with an index out of range", r.out_of_range_faces);
  line("degenerate faces", r.degenerate_faces);
  line("non-finite points", r.non_finite_points);
  line("duplicate faces", r.duplicate_faces);
  line("non-manifold edges (fins)", r.non_manifold_edges);
  line("inconsistently oriented edges", r.inconsistent_edges);
  line("non-manifold vertices (bow-ties)", r.non_manifold_vertices);
  line("zero-area faces (warning)", r.zero_area_faces);
  line("isolated points (info)", r.isolated_points);
  for (const auto& p : r.problems)
    s << p.element << ": " << to_string(p.kind) << (is_error(p.kind) ? "" : " (warning)") << ": " << p.message << "\n";
  if (r.problem_count > r.problems.size())
    s << "... and " << (r.problem_count - r.problems.size()) << " more problems\n";
  return s.str();
}

namespace detail {

/// One directed edge of a face: corner `corner` (global position in
/// soup.indices) goes from `from` to `to`.
struct Soup_half {
  std::uint32_t lo, hi;   // the undirected edge, lo < hi
  std::uint32_t face;
  std::uint32_t corner;
  bool forward;           // from == lo
};

/// Which faces a soup analysis uses (not out of range, not degenerate) and
/// their directed edges grouped by undirected edge, in (lo, hi, face, corner)
/// order.
struct Soup_edges {
  std::vector<char> usable;                 // per face
  std::vector<Soup_half> halves;            // sorted
  std::vector<std::uint32_t> group_begin;   // groups of equal (lo, hi); last entry = halves.size()
};

inline bool face_in_range(const Polygon_soup& soup, std::size_t f) {
  for (auto i : soup.face(f))
    if (i >= soup.num_points()) return false;
  return true;
}

inline bool face_has_repeat(std::span<const Polygon_soup::Index> c) {
  if (c.size() <= 8) {
    for (std::size_t a = 0; a < c.size(); ++a)
      for (std::size_t b = a + 1; b < c.size(); ++b)
        if (c[a] == c[b]) return true;
    return false;
  }
  std::vector<Polygon_soup::Index> s(c.begin(), c.end());
  std::sort(s.begin(), s.end());
  return std::adjacent_find(s.begin(), s.end()) != s.end();
}

inline Soup_edges soup_edges(const Polygon_soup& soup) {
  Soup_edges e;
  const std::size_t nf = soup.num_faces(), np = soup.num_points();
  e.usable.assign(nf, 0);
  std::size_t total = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    auto c = soup.face(f);
    bool ok = c.size() >= 3 && face_in_range(soup, f) && !face_has_repeat(c);
    e.usable[f] = ok;
    if (ok) total += c.size();
  }
  // Bucket by the lower vertex (counting sort), then sort each small bucket.
  std::vector<std::uint32_t> start(np + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (!e.usable[f]) continue;
    auto c = soup.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) ++start[std::min(c[k], c[(k + 1) % c.size()]) + 1];
  }
  for (std::size_t v = 0; v < np; ++v) start[v + 1] += start[v];
  e.halves.resize(total);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < nf; ++f) {
    if (!e.usable[f]) continue;
    auto c = soup.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) {
      std::uint32_t a = c[k], b = c[(k + 1) % c.size()];
      e.halves[fill[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(f),
                                          static_cast<std::uint32_t>(soup.offsets[f] + k), a < b};
    }
  }
  for (std::size_t v = 0; v < np; ++v) {
    auto first = e.halves.begin() + start[v], last = e.halves.begin() + start[v + 1];
    if (last - first > 1)
      std::sort(first, last, [](const Soup_half& x, const Soup_half& y) {
        return std::tie(x.hi, x.corner) < std::tie(y.hi, y.corner);
      });
  }
  for (std::size_t i = 0; i < e.halves.size(); ++i)
    if (i == 0 || e.halves[i].lo != e.halves[i - 1].lo || e.halves[i].hi != e.halves[i - 1].hi)
      e.group_begin.push_back(static_cast<std::uint32_t>(i));
  e.group_begin.push_back(static_cast<std::uint32_t>(e.halves.size()));
  return e;
}

/// The corner after `corner` in its face.
inline std::uint32_t next_corner(const Polygon_soup& soup, std::uint32_t face, std::uint32_t corner) {
  return corner + 1 == soup.offsets[face + 1] ? soup.offsets[face] : corner + 1;
}

/// Union-find over corners joining, across every edge used by exactly two
/// faces, the corners of the same vertex; each root is one fan.
inline Union_find soup_fans(const Polygon_soup& soup, const Soup_edges& e) {
  Union_find uf(soup.indices.size());
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
    if (e.group_begin[g + 1] - e.group_begin[g] != 2) continue;
    const Soup_half& x = e.halves[e.group_begin[g]];
    const Soup_half& y = e.halves[e.group_begin[g] + 1];
    std::uint32_t x0 = x.corner, x1 = next_corner(soup, x.face, x.corner);
    std::uint32_t y0 = y.corner, y1 = next_corner(soup, y.face, y.corner);
    // x0 and x1 are x's source and target corners; match them by vertex.
    if (soup.indices[x0] == soup.indices[y0]) {
      uf.unite(x0, y0);
      uf.unite(x1, y1);
    } else {
      uf.unite(x0, y1);
      uf.unite(x1, y0);
    }
  }
  return uf;
}

/// Faces (among `usable`) whose corner set equals an earlier face's, with the
/// first face of that corner set. O(corners · log): faces are sorted by
/// (size, an order-independent hash of the corners), and only runs of equal
/// keys compare their sorted corners — however many faces share an edge.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_faces(const Polygon_soup& soup,
                                                                             const Soup_edges& e) {
  const std::size_t nf = soup.num_faces();
  std::vector<std::uint64_t> key(nf, 0);
  std::vector<std::uint32_t> order;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!e.usable[f]) continue;
    for (auto i : soup.face(f)) {
      std::uint64_t x = i + 0x9e3779b97f4a7c15ull;
      x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
      x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
      key[f] += x ^ (x >> 31);
    }
    order.push_back(static_cast<std::uint32_t>(f));
  }
  const auto by_key = [&](std::uint32_t x, std::uint32_t y) {
    return std::tuple(soup.face_size(x), key[x], x) < std::tuple(soup.face_size(y), key[y], y);
  };
  std::sort(order.begin(), order.end(), by_key);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> dups;
  std::vector<std::vector<Polygon_soup::Index>> sorted;
  std::vector<std::uint32_t> run;
  for (std::size_t b = 0; b < order.size();) {
    std::size_t end = b + 1;
    while (end < order.size() && key[order[end]] == key[order[b]] &&
           soup.face_size(order[end]) == soup.face_size(order[b]))
      ++end;
    if (end - b > 1) {
      // Equal keys: group by the sorted corners themselves (a hash collision
      // costs a sort of the run, never a wrong answer); each group's first
      // face (lowest index) is the original.
      sorted.clear();
      run.clear();
      for (std::size_t i = b; i < end; ++i) {
        auto c = soup.face(order[i]);
        sorted.emplace_back(c.begin(), c.end());
        std::sort(sorted.back().begin(), sorted.back().end());
        run.push_back(static_cast<std::uint32_t>(i - b));
      }
      std::stable_sort(run.begin(), run.end(), [&](std::uint32_t x, std::uint32_t y) { return sorted[x] < sorted[y]; });
      for (std::size_t i = 1, first = 0; i < run.size(); ++i) {
        if (sorted[run[i]] != sorted[run[first]]) first = i;
        else dups.emplace_back(order[b + run[i]], order[b + run[first]]);
      }
    }
    b = end;
  }
  std::sort(dups.begin(), dups.end());
  return dups;
}

/// "a, b, c" — at most `max_items` of them, then "... (N more)": a message
/// stays short however large the face or the fin (the problem's own vectors
/// keep every index).
inline std::string list(const std::vector<std::size_t>& v, std::size_t max_items = 10) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < max_items; ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  if (v.size() > max_items) s += ", ... (" + std::to_string(v.size() - max_items) + " more)";
  return s;
}

} // namespace detail

namespace detail::soup_check {

/// Records one soup problem (counted always, kept up to max_problems).
struct Problem_sink {
  Soup_report& r;
  void operator()(Soup_problem_kind kind, std::string element, std::string msg, std::vector<std::size_t> faces,
                  std::vector<std::size_t> verts) const {
    ++r.problem_count;
    if (r.problems.size() < Soup_report::max_problems)
      r.problems.push_back({kind, std::move(element), std::move(msg), std::move(faces), std::move(verts)});
  }
};

/// Points with a NaN or infinite coordinate.
inline void check_points(const Polygon_soup& soup, Soup_report& r, const Problem_sink& add) {
  for (std::size_t p = 0; p < soup.num_points(); ++p)
    if (!soup.points[p].allFinite()) {
      ++r.non_finite_points;
      add(Soup_problem_kind::non_finite_point, "point " + std::to_string(p), "has a NaN or infinite coordinate", {},
          {p});
    }
}

/// Faces with an index out of range, fewer than three corners or a repeated corner.
inline void check_faces(const Polygon_soup& soup, Soup_report& r, const Problem_sink& add) {
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto c = soup.face(f);
    if (!face_in_range(soup, f)) {
      ++r.out_of_range_faces;
      std::size_t bad = 0;
      for (auto i : c)
        if (i >= soup.num_points()) bad = i;
      add(Soup_problem_kind::index_out_of_range, "face " + std::to_string(f),
          "corner " + std::to_string(bad) + " is out of range (" + std::to_string(soup.num_points()) + " points)",
          {f}, {});
    } else if (c.size() < 3) {
      ++r.degenerate_faces;
      add(Soup_problem_kind::degenerate_face, "face " + std::to_string(f),
          "has " + std::to_string(c.size()) + " corners (< 3)", {f}, {});
    } else if (face_has_repeat(c)) {
      ++r.degenerate_faces;
      std::vector<std::size_t> vs(c.begin(), c.end());
      add(Soup_problem_kind::degenerate_face, "face " + std::to_string(f),
          "repeats a corner (corners " + list(vs) + ")", {f}, vs);
    }
  }
}

/// Faces with the same corner set as an earlier face.
inline void check_duplicates(const Polygon_soup& soup, const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  for (auto [f, g] : duplicate_faces(soup, e)) {
    ++r.duplicate_faces;
    add(Soup_problem_kind::duplicate_face, "face " + std::to_string(f),
        "has the same corners as face " + std::to_string(g), {g, f}, {});
  }
}

/// Per undirected edge: border (one face), inconsistent orientation (two
/// faces, same direction) or fin (three or more faces).
inline void check_edge_groups(const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
    std::uint32_t b = e.group_begin[g], end = e.group_begin[g + 1];
    ++r.edges;
    const Soup_half& x = e.halves[b];
    if (end - b == 1) {
      ++r.border_edges;
    } else if (end - b == 2) {
      const Soup_half& y = e.halves[b + 1];
      if (x.forward == y.forward) {
        ++r.inconsistent_edges;
        std::uint32_t from = x.forward ? x.lo : x.hi, to = x.forward ? x.hi : x.lo;
        add(Soup_problem_kind::inconsistent_orientation,
            "edge (" + std::to_string(x.lo) + ", " + std::to_string(x.hi) + ")",
            "faces " + std::to_string(x.face) + " and " + std::to_string(y.face) + " both use it as " +
                std::to_string(from) + "→" + std::to_string(to) + " (one of them is flipped, or they duplicate)",
            {x.face, y.face}, {x.lo, x.hi});
      }
    } else {
      ++r.non_manifold_edges;
      std::vector<std::size_t> fs;
      for (std::uint32_t i = b; i < end; ++i) fs.push_back(e.halves[i].face);
      add(Soup_problem_kind::non_manifold_edge, "edge (" + std::to_string(x.lo) + ", " + std::to_string(x.hi) + ")",
          "is shared by " + std::to_string(end - b) + " faces (" + list(fs) + "); at most 2 are allowed", fs,
          {x.lo, x.hi});
    }
  }
}

/// Vertices whose faces form several fans (bow-ties), and isolated points
/// (used by no face; points used only by unusable faces count as used).
inline void check_fans(const Polygon_soup& soup, const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  std::vector<std::uint32_t> fans(soup.num_points(), 0);
  std::vector<char> used(soup.num_points(), 0);
  {
    Union_find uf = soup_fans(soup, e);
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      if (!e.usable[f]) continue;
      for (std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c) {
        used[soup.indices[c]] = 1;
        if (uf.find(c) == c) ++fans[soup.indices[c]];
      }
    }
  }
  for (std::size_t v = 0; v < soup.num_points(); ++v) {
    if (fans[v] > 1) {
      ++r.non_manifold_vertices;
      add(Soup_problem_kind::non_manifold_vertex, "vertex " + std::to_string(v),
          "its faces form " + std::to_string(fans[v]) + " fans that meet only at this vertex (bow-tie)", {}, {v});
    }
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    if (!e.usable[f])
      for (auto i : soup.face(f))
        if (i < soup.num_points()) used[i] = 1;
  for (std::size_t v = 0; v < soup.num_points(); ++v) r.isolated_points += !used[v];
}

/// Zero-area faces (a warning): vector area (Newell) against the longest
/// edge squared.
inline void check_zero_area(const Polygon_soup& soup, const Soup_edges& e, Soup_report& r, const Problem_sink& add) {
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (!e.usable[f]) continue;
    auto c = soup.face(f);
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    double longest = 0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const Eigen::Vector3d& a = soup.points[c[k]];
      const Eigen::Vector3d& b = soup.points[c[(k + 1) % c.size()]];
      area += a.cross(b);
      longest = std::max(longest, (b - a).squaredNorm());
    }
    if (!(0.5 * area.norm() > 1e-12 * longest)) {
      ++r.zero_area_faces;
      add(Soup_problem_kind::zero_area_face, "face " + std::to_string(f), "has zero area", {f}, {});
    }
  }
}

} // namespace detail::soup_check

/// check_soup() on the edge table e = detail::soup_edges(soup) the caller
/// already built (build_mesh() builds one and shares it with the linking).
inline Soup_report check_soup(const Polygon_soup& soup, const detail::Soup_edges& e) {
  using namespace detail::soup_check;
  Soup_report r;
  r.points = soup.num_points();
  r.faces = soup.num_faces();
  const Problem_sink add{r};
  check_points(soup, r, add);
  check_faces(soup, r, add);
  check_duplicates(soup, e, r, add);
  check_edge_groups(e, r, add);
  check_fans(soup, e, r, add);
  check_zero_area(soup, e, r, add);
  return r;
}

/// Checks a polygon soup before a halfedge mesh is built from it; see the
/// header comment for what is looked for. Linear time up to small sorts.
inline Soup_report check_soup(const Polygon_soup& soup) { return check_soup(soup, detail::soup_edges(soup)); }

// ---------------------------------------------------------------------------
// Soup repair
// ---------------------------------------------------------------------------

/// What repair_soup() may change. Every step is on by default.
struct Soup_repair_options {
  bool remove_out_of_range_faces = true;
  bool remove_degenerate_faces = true;  ///< after merging consecutive repeated corners
  bool remove_duplicate_faces = true;   ///< keeps the first of faces with equal corner sets
  bool remove_fin_faces = true;         ///< keeps the two lowest-numbered faces of a fin edge
  bool reorient = true;                 ///< per component, to the orientation most faces have
  bool split_non_manifold_vertices = true; ///< one new point per extra fan, appended
};

/// What repair_soup() changed (in counts and words) and what is left.
struct Soup_repair_report {
  std::size_t merged_corners = 0;        ///< consecutive repeated corners merged
  std::size_t removed_out_of_range_faces = 0;
  std::size_t removed_degenerate_faces = 0;
  std::size_t removed_duplicate_faces = 0;
  std::size_t removed_fin_faces = 0;
  std::size_t reoriented_faces = 0;
  std::size_t unorientable_components = 0; ///< left as they were (e.g. a Möbius strip)
  std::size_t split_vertices = 0;          ///< non-manifold vertices split
  std::size_t added_points = 0;            ///< new points appended by the splits
  /// For each face of the repaired soup, its index in the input soup.
  std::vector<std::size_t> face_origin;
  /// For each point appended by a split, the point it copies.
  std::vector<std::size_t> point_origin;
  /// One sentence per change, in the order made, naming input faces and points.
  std::vector<std::string> changes;
  /// check_soup() of the repaired soup.
  Soup_report after;

  bool changed() const noexcept {
    return merged_corners + removed_out_of_range_faces + removed_degenerate_faces + removed_duplicate_faces +
               removed_fin_faces + reoriented_faces + added_points >
           0;
  }
  /// The repaired soup passes check_soup().
  bool ok() const noexcept { return after.ok(); }
};

inline std::string to_string(const Soup_repair_report& r) {
  std::ostringstream s;
  if (!r.changed()) s << "repair: nothing changed\n";
  for (const auto& c : r.changes) s << "repair: " << c << "\n";
  if (!r.ok()) s << "repair could not fix:\n" << to_string(r.after);
  return s.str();
}

/// Repairs soup in place (see Soup_repair_options); point indices of the
/// input stay valid (new points are appended), faces keep their relative
/// order (report.face_origin maps them back). Non-finite points and
/// unorientable components are reported in `after`, not fixed.
inline Soup_repair_report repair_soup(Polygon_soup& soup, const Soup_repair_options& opt = {}) {
  using namespace detail;
  Soup_repair_report rep;
  const std::size_t nf = soup.num_faces();
  if (Soup_report before = check_soup(soup); before.ok()) { // nothing to repair
    rep.face_origin.resize(nf);
    std::iota(rep.face_origin.begin(), rep.face_origin.end(), std::size_t{0});
    rep.after = std::move(before);
    return rep;
  }
  std::vector<std::size_t> origin(nf);
  std::iota(origin.begin(), origin.end(), std::size_t{0});
  std::vector<char> keep(nf, 1);

  // Rebuild the soup from the kept faces.
  auto compact = [&]() {
    Polygon_soup out;
    out.points = std::move(soup.points);
    std::vector<std::size_t> o;
    for (std::size_t f = 0; f < soup.num_faces(); ++f)
      if (keep[f]) {
        out.add_face(soup.face(f));
        o.push_back(origin[f]);
      }
    soup = std::move(out);
    origin = std::move(o);
    keep.assign(soup.num_faces(), 1);
  };

  // 1. Out-of-range and degenerate faces.
  {
    Polygon_soup out;
    out.points = soup.points;
    std::vector<Polygon_soup::Index> c;
    std::vector<std::size_t> o;
    for (std::size_t f = 0; f < nf; ++f) {
      auto in = soup.face(f);
      if (!face_in_range(soup, f)) {
        if (opt.remove_out_of_range_faces) {
          ++rep.removed_out_of_range_faces;
          rep.changes.push_back("removed face " + std::to_string(f) + " (a corner is out of range)");
          continue;
        }
        out.add_face(in);
        o.push_back(f);
        continue;
      }
      c.assign(in.begin(), in.end());
      if (opt.remove_degenerate_faces) {
        std::vector<Polygon_soup::Index> m;
        for (std::size_t k = 0; k < c.size(); ++k)
          if (m.empty() || m.back() != c[k]) m.push_back(c[k]);
        while (m.size() > 1 && m.front() == m.back()) m.pop_back();
        if (m.size() != c.size()) {
          rep.merged_corners += c.size() - m.size();
          rep.changes.push_back("face " + std::to_string(f) + ": merged " + std::to_string(c.size() - m.size()) +
                                " repeated consecutive corner(s)");
        }
        c = std::move(m);
        if (c.size() < 3 || face_has_repeat(c)) {
          ++rep.removed_degenerate_faces;
          rep.changes.push_back("removed degenerate face " + std::to_string(f) + " (" +
                                (c.size() < 3 ? "fewer than 3 distinct corners" : "a corner repeats") + ")");
          continue;
        }
      }
      out.add_face(c);
      o.push_back(f);
    }
    soup = std::move(out);
    origin = std::move(o);
    keep.assign(soup.num_faces(), 1);
  }

  // 2. Duplicate faces.
  if (opt.remove_duplicate_faces) {
    Soup_edges e = soup_edges(soup);
    for (auto [f, g] : duplicate_faces(soup, e)) {
      keep[f] = 0;
      ++rep.removed_duplicate_faces;
      rep.changes.push_back("removed face " + std::to_string(origin[f]) + " (same corners as face " +
                            std::to_string(origin[g]) + ")");
    }
    compact();
  }

  // 3. Fins: keep the two lowest-numbered faces of each edge.
  if (opt.remove_fin_faces) {
    Soup_edges e = soup_edges(soup);
    for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
      std::uint32_t b = e.group_begin[g], end = e.group_begin[g + 1];
      if (end - b <= 2) continue;
      std::vector<std::uint32_t> fs;
      for (std::uint32_t i = b; i < end; ++i)
        if (keep[e.halves[i].face]) fs.push_back(e.halves[i].face);
      std::sort(fs.begin(), fs.end());
      for (std::size_t k = 2; k < fs.size(); ++k) {
        keep[fs[k]] = 0;
        ++rep.removed_fin_faces;
        rep.changes.push_back("removed face " + std::to_string(origin[fs[k]]) + " (third or later face on edge (" +
                              std::to_string(e.halves[b].lo) + ", " + std::to_string(e.halves[b].hi) + "))");
      }
    }
    compact();
  }

  // 4. Orientation: 2-colour the faces of each component across two-face edges.
  if (opt.reorient && soup.num_faces() > 0) {
    Soup_edges e = soup_edges(soup);
    const std::size_t n = soup.num_faces();
    // Face adjacency (CSR) with "same direction" flags.
    std::vector<std::uint32_t> deg(n + 1, 0);
    for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g)
      if (e.group_begin[g + 1] - e.group_begin[g] == 2) {
        ++deg[e.halves[e.group_begin[g]].face + 1];
        ++deg[e.halves[e.group_begin[g] + 1].face + 1];
      }
    for (std::size_t f = 0; f < n; ++f) deg[f + 1] += deg[f];
    std::vector<std::pair<std::uint32_t, bool>> adj(deg[n]);
    std::vector<std::uint32_t> fill(deg.begin(), deg.end() - 1);
    for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g)
      if (e.group_begin[g + 1] - e.group_begin[g] == 2) {
        const Soup_half& x = e.halves[e.group_begin[g]];
        const Soup_half& y = e.halves[e.group_begin[g] + 1];
        bool same = x.forward == y.forward;
        adj[fill[x.face]++] = {y.face, same};
        adj[fill[y.face]++] = {x.face, same};
      }
    std::vector<int> flip(n, -1);
    std::vector<std::uint32_t> queue;
    for (std::size_t s = 0; s < n; ++s) {
      if (flip[s] != -1) continue;
      queue.assign(1, static_cast<std::uint32_t>(s));
      flip[s] = 0;
      bool orientable = true;
      for (std::size_t q = 0; q < queue.size(); ++q) {
        std::uint32_t f = queue[q];
        for (std::uint32_t k = deg[f]; k < deg[f + 1]; ++k) {
          auto [g, same] = adj[k];
          int want = flip[f] ^ (same ? 1 : 0);
          if (flip[g] == -1) {
            flip[g] = want;
            queue.push_back(g);
          } else if (flip[g] != want) {
            orientable = false;
          }
        }
      }
      if (!orientable) {
        ++rep.unorientable_components;
        std::size_t first = *std::min_element(queue.begin(), queue.end());
        rep.changes.push_back("left the component of face " + std::to_string(origin[first]) + " (" +
                              std::to_string(queue.size()) + " faces) as it was: it is not orientable");
        for (auto f : queue) flip[f] = 0;
        continue;
      }
      // Flip the minority; on a tie keep the component's first face as it is.
      std::size_t ones = 0;
      for (auto f : queue) ones += flip[f] == 1;
      bool invert = 2 * ones > queue.size();
      for (auto f : queue) flip[f] ^= invert ? 1 : 0;
    }
    for (std::size_t f = 0; f < n; ++f)
      if (flip[f] == 1) {
        auto c = soup.face(f);
        std::reverse(c.begin() + 1, c.end()); // keeps the first corner
        ++rep.reoriented_faces;
        rep.changes.push_back("reversed the orientation of face " + std::to_string(origin[f]));
      }
  }

  // 5. Non-manifold vertices: one new point per fan beyond the first.
  if (opt.split_non_manifold_vertices) {
    Soup_edges e = soup_edges(soup);
    Union_find uf = soup_fans(soup, e);
    const std::size_t np = soup.num_points();
    // The fan holding a vertex's lowest corner keeps the vertex.
    std::vector<std::uint32_t> first_root(np, k_null);
    std::vector<std::uint32_t> new_point(soup.indices.size(), k_null); // per root corner
    std::vector<std::uint32_t> extra(np, 0);
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      if (!e.usable[f]) continue;
      for (std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c) {
        std::uint32_t v = soup.indices[c], root = uf.find(c);
        if (first_root[v] == k_null) first_root[v] = root;
        if (root == first_root[v]) continue;
        if (new_point[root] == k_null) {
          new_point[root] = soup.add_point(Eigen::Vector3d(soup.points[v]));
          rep.point_origin.push_back(v);
          ++rep.added_points;
          if (extra[v]++ == 0) ++rep.split_vertices;
          rep.changes.push_back("split vertex " + std::to_string(v) + ": a further fan (with face " +
                                std::to_string(origin[f]) + ") now uses new point " + std::to_string(new_point[root]));
        }
        soup.indices[c] = new_point[root];
      }
    }
  }

  rep.face_origin = std::move(origin);
  rep.after = check_soup(soup);
  return rep;
}

} // namespace genmesh
