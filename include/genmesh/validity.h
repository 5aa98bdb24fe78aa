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

/// Checks every halfedge invariant of g and counts its elements, boundary
/// loops and components. Never throws on a corrupt mesh and never loops:
/// every walk is bounded. Runs in time linear in the index bounds.
template <class G>
  requires FaceListGraph<G> && HalfedgeListGraph<G> && VertexListGraph<G> && EdgeListGraph<G>
Mesh_report check_mesh(const G& g) {
  using namespace detail;
  using Traits = boost::graph_traits<G>;
  using V = vertex_descriptor_t<G>;
  using H = halfedge_descriptor_t<G>;
  using F = face_descriptor_t<G>;

  Mesh_report r;
  Problem_sink problem(r);

  Dense_index<G, vertex_index_t, V> vi(g, vertices(g), Traits::null_vertex());
  Dense_index<G, halfedge_index_t, H> hi(g, halfedges(g), Traits::null_halfedge());
  Dense_index<G, face_index_t, F> fi(g, faces(g), Traits::null_face());
  const std::size_t nh_bound = hi.bound(), nv_bound = vi.bound(), nf_bound = fi.bound();

  // Links of every live halfedge, as dense numbers (k_null / k_bad when broken).
  std::vector<std::uint32_t> nxt(nh_bound, k_bad), prv(nh_bound, k_bad), opp(nh_bound, k_bad),
      tgt(nh_bound, k_bad), fac(nh_bound, k_bad);
  std::vector<char> live_h(nh_bound, 0);
  std::vector<std::uint32_t> order; // live halfedges in index order
  for (H h : halfedges(g)) {
    std::uint32_t i = hi(h);
    if (!is_ref(i)) continue;
    live_h[i] = 1;
    ++r.halfedges;
    nxt[i] = hi(next(h, g));
    prv[i] = hi(prev(h, g));
    H o = opposite(h, g);
    opp[i] = hi(o);
    tgt[i] = vi(target(h, g));
    fac[i] = fi(face(h, g));
    if (fac[i] == k_null) ++r.border_halfedges;
    if (is_ref(opp[i]) && !(edge(h, g) == edge(o, g)))
      problem(Mesh_problem_kind::opposite, "halfedge", i,
              "edge(h) differs from edge(opposite(h)) (opposite is halfedge " + std::to_string(opp[i]) + ")");
  }
  for (std::size_t i = 0; i < nh_bound; ++i)
    if (live_h[i]) order.push_back(static_cast<std::uint32_t>(i));

  // Halfedge invariants.
  std::vector<std::uint32_t> pred_count(nh_bound, 0);
  for (std::uint32_t i : order) {
    const std::uint32_t n = nxt[i], p = prv[i], o = opp[i], t = tgt[i], f = fac[i];
    if (!is_ref(n)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "next is " + ref_name("halfedge", n));
    if (!is_ref(p)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "prev is " + ref_name("halfedge", p));
    if (!is_ref(o)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "opposite is " + ref_name("halfedge", o));
    if (!is_ref(t)) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "target is " + ref_name("vertex", t));
    if (f == k_bad) problem(Mesh_problem_kind::invalid_reference, "halfedge", i, "face is a face that is not live");
    if (is_ref(n)) ++pred_count[n];
    if (is_ref(o)) {
      if (o == i) problem(Mesh_problem_kind::opposite, "halfedge", i, "opposite(h) == h");
      else if (opp[o] != i)
        problem(Mesh_problem_kind::opposite, "halfedge", i,
                "opposite(opposite(h)) is " + ref_name("halfedge", opp[o]) + ", not h (opposite is halfedge " +
                    std::to_string(o) + ")");
      if (is_ref(t) && tgt[o] == t)
        problem(Mesh_problem_kind::self_loop, "halfedge", i, "source and target are both vertex " + std::to_string(t));
      if (o != i && f == k_null && fac[o] == k_null)
        problem(Mesh_problem_kind::edge_faces, "halfedge", i,
                "both sides of its edge are border (edge without a face, opposite is halfedge " + std::to_string(o) + ")");
      else if (o != i && is_ref(f) && fac[o] == f && i < o)
        problem(Mesh_problem_kind::edge_faces, "halfedge", i,
                "face " + std::to_string(f) + " lies on both sides of its edge");
    }
    if (is_ref(n)) {
      if (n == i) problem(Mesh_problem_kind::self_loop, "halfedge", i, "next(h) == h");
      if (prv[n] != i)
        problem(Mesh_problem_kind::next_prev, "halfedge", i,
                "prev(next(h)) is " + ref_name("halfedge", prv[n]) + ", not h (next is halfedge " +
                    std::to_string(n) + ")");
      if (is_ref(opp[n]) && is_ref(t) && tgt[opp[n]] != t)
        problem(Mesh_problem_kind::next_source, "halfedge", i,
                "target is vertex " + std::to_string(t) + " but source(next(h)) is " + ref_name("vertex", tgt[opp[n]]) +
                    " (next is halfedge " + std::to_string(n) + ")");
      if (fac[n] != f && f != k_bad && fac[n] != k_bad)
        problem(Mesh_problem_kind::next_face, "halfedge", i,
                "face is " + ref_name("face", f) + " but face(next(h)) is " + ref_name("face", fac[n]) +
                    " (next is halfedge " + std::to_string(n) + ")");
    }
    if (is_ref(p) && nxt[p] != i)
      problem(Mesh_problem_kind::next_prev, "halfedge", i,
              "next(prev(h)) is " + ref_name("halfedge", nxt[p]) + ", not h (prev is halfedge " + std::to_string(p) + ")");
  }
  for (std::uint32_t i : order)
    if (pred_count[i] != 1)
      problem(Mesh_problem_kind::next_not_unique, "halfedge", i,
              "is next of " + std::to_string(pred_count[i]) + " halfedges, not exactly one");

  // Edges.
  Dense_index<G, edge_index_t, edge_descriptor_t<G>> ei(g, edges(g), edge_descriptor_t<G>{});
  for (auto e : edges(g)) {
    ++r.edges;
    H h = halfedge(e, g);
    std::uint32_t i = hi(h);
    if (!is_ref(i) || !(edge(h, g) == e))
      problem(Mesh_problem_kind::edge_halfedge, "edge", ei(e),
              "halfedge(e) is " + ref_name("halfedge", i) + (is_ref(i) ? ", whose edge is another" : ""));
  }

  // Faces: walk each cycle once; a halfedge seen by an earlier walk ends the walk.
  std::vector<std::uint32_t> seen_by(nh_bound, k_null);
  std::vector<char> live_f(nf_bound, 0);
  std::vector<std::uint32_t> face_start(nf_bound, k_null);
  for (F fd : faces(g)) {
    std::uint32_t f = fi(fd);
    if (!is_ref(f)) continue;
    live_f[f] = 1;
    ++r.faces;
    std::uint32_t h = hi(halfedge(fd, g));
    face_start[f] = h;
    if (!is_ref(h)) {
      problem(Mesh_problem_kind::invalid_reference, "face", f, "halfedge(f) is " + ref_name("halfedge", h));
      continue;
    }
    if (fac[h] != f) {
      problem(Mesh_problem_kind::face_halfedge, "face", f,
              "halfedge(f) is halfedge " + std::to_string(h) + " whose face is " + ref_name("face", fac[h]));
      continue;
    }
    std::size_t len = 0;
    std::uint32_t c = h;
    bool closed = false;
    std::string why;
    while (true) {
      if (seen_by[c] != k_null) {
        why = seen_by[c] == f ? "returns to halfedge " + std::to_string(c) + " without passing halfedge(f)"
                              : "runs into halfedge " + std::to_string(c) + " of face " + std::to_string(seen_by[c]) +
                                    "'s cycle";
        break;
      }
      seen_by[c] = f;
      ++len;
      std::uint32_t n = nxt[c];
      if (!is_ref(n)) {
        why = "reaches halfedge " + std::to_string(c) + " whose next is " + ref_name("halfedge", n);
        break;
      }
      if (n == h) {
        closed = true;
        break;
      }
      c = n;
    }
    if (!closed) problem(Mesh_problem_kind::face_cycle, "face", f, "the cycle from halfedge(f) " + why);
    else if (len < 3)
      problem(Mesh_problem_kind::face_cycle, "face", f, "its cycle has " + std::to_string(len) + " halfedges (< 3)");
    if (len != 3) r.is_triangle_mesh = false;
    if (len != 4) r.is_quad_mesh = false;
  }
  for (std::uint32_t i : order)
    if (is_ref(fac[i]) && seen_by[i] != fac[i] && live_f[fac[i]])
      problem(Mesh_problem_kind::face_cycle, "halfedge", i,
              "has face " + std::to_string(fac[i]) + " but is not on that face's cycle");

  // Boundary loops: cycles of border halfedges, each walked once.
  for (std::uint32_t i : order) {
    if (fac[i] != k_null || seen_by[i] != k_null) continue;
    ++r.boundary_loops;
    std::uint32_t c = i;
    while (is_ref(c) && seen_by[c] == k_null && fac[c] == k_null) {
      seen_by[c] = k_bad; // marks "on a boundary walk"
      c = nxt[c];
    }
  }

  // Vertices: halfedge(v) targets v, and one fan per vertex.
  std::vector<std::uint32_t> in_count(nv_bound, 0);
  for (std::uint32_t i : order)
    if (is_ref(tgt[i])) ++in_count[tgt[i]];
  std::vector<char> live_v(nv_bound, 0);
  std::vector<std::uint32_t> fan_seen(nh_bound, k_null);
  for (V vd : vertices(g)) {
    std::uint32_t v = vi(vd);
    if (!is_ref(v)) continue;
    live_v[v] = 1;
    ++r.vertices;
    std::uint32_t h = hi(halfedge(vd, g));
    if (h == k_null) {
      if (in_count[v] == 0) ++r.isolated_vertices;
      else
        problem(Mesh_problem_kind::vertex_halfedge, "vertex", v,
                "halfedge(v) is null but " + std::to_string(in_count[v]) + " halfedges end at it");
      continue;
    }
    if (h == k_bad) {
      problem(Mesh_problem_kind::invalid_reference, "vertex", v, "halfedge(v) is a halfedge that is not live");
      continue;
    }
    if (tgt[h] != v) {
      problem(Mesh_problem_kind::vertex_halfedge, "vertex", v,
              "halfedge(v) is halfedge " + std::to_string(h) + " whose target is " + ref_name("vertex", tgt[h]));
      continue;
    }
    std::size_t len = 0;
    std::uint32_t c = h;
    bool closed = false, on_border = false;
    std::size_t border_in = 0; // border halfedges ending at v: one per gap in its fan
    while (len <= in_count[v]) {
      if (!is_ref(c) || tgt[c] != v || fan_seen[c] != k_null) break;
      fan_seen[c] = v;
      on_border = on_border || fac[c] == k_null;
      border_in += fac[c] == k_null ? 1 : 0;
      ++len;
      std::uint32_t n = nxt[c];
      if (!is_ref(n)) break;
      c = opp[n];
      if (c == h) {
        closed = true;
        break;
      }
    }
    if (closed && on_border && fac[h] != k_null) ++r.border_vertices_with_inner_halfedge;
    if (!closed)
      problem(Mesh_problem_kind::vertex_cycle, "vertex", v,
              "the walk around it via opposite(next(h)) from halfedge " + std::to_string(h) + " does not close");
    else if (len != in_count[v]) {
      ++r.non_manifold_vertices;
      problem(Mesh_problem_kind::non_manifold_vertex, "vertex", v,
              std::to_string(in_count[v]) + " halfedges end at it but its fan has only " + std::to_string(len) +
                  ": several fans meet here");
    } else if (border_in > 1) {
      // The border links can join two fans into one closed walk: the walk
      // is complete, yet the border passes through v more than once.
      ++r.non_manifold_vertices;
      problem(Mesh_problem_kind::non_manifold_vertex, "vertex", v,
              "the border passes through it " + std::to_string(border_in) + " times: several fans meet here");
    }
  }

  r.valid = r.problem_count == r.non_manifold_vertices;
  r.manifold = r.valid && r.non_manifold_vertices == 0;
  r.is_closed = r.border_halfedges == 0;
  if (r.faces == 0) r.is_triangle_mesh = r.is_quad_mesh = true;
  r.euler_characteristic = static_cast<long>(r.vertices) - static_cast<long>(r.edges) + static_cast<long>(r.faces);

  // Components: union-find over vertices joined by edges.
  Union_find uf(nv_bound);
  for (std::uint32_t i : order)
    if (is_ref(tgt[i]) && is_ref(opp[i]) && is_ref(tgt[opp[i]])) uf.unite(tgt[i], tgt[opp[i]]);
  for (std::size_t v = 0; v < nv_bound; ++v)
    if (live_v[v] && uf.find(static_cast<std::uint32_t>(v)) == v) ++r.components;

  // Genus per component with faces, only where it is well defined.
  if (r.ok()) {
    std::vector<long> chi(nv_bound, 0), loops(nv_bound, 0);
    std::vector<char> has_face(nv_bound, 0);
    for (std::size_t v = 0; v < nv_bound; ++v)
      if (live_v[v]) ++chi[uf.find(static_cast<std::uint32_t>(v))];
    std::vector<char> loop_seen(nh_bound, 0);
    for (std::uint32_t i : order) {
      std::uint32_t root = uf.find(tgt[i]);
      if (i < opp[i]) --chi[root]; // one per edge
      if (fac[i] == k_null && !loop_seen[i]) {
        ++loops[root];
        for (std::uint32_t c = i; !loop_seen[c]; c = nxt[c]) loop_seen[c] = 1;
      }
    }
    for (std::size_t f = 0; f < nf_bound; ++f)
      if (live_f[f]) {
        std::uint32_t root = uf.find(tgt[face_start[f]]);
        ++chi[root];
        has_face[root] = 1;
      }
    long genus = 0;
    bool defined = true;
    for (std::size_t v = 0; v < nv_bound; ++v) {
      if (!live_v[v] || !has_face[v] || uf.find(static_cast<std::uint32_t>(v)) != v) continue;
      long twice = 2 - chi[v] - loops[v];
      if (twice < 0 || twice % 2 != 0) defined = false;
      else genus += twice / 2;
    }
    if (defined) r.genus = genus;
  }
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

/// Checks a polygon soup before a halfedge mesh is built from it; see the
/// header comment for what is looked for. Linear time up to small sorts.
inline Soup_report check_soup(const Polygon_soup& soup) {
  using namespace detail;
  Soup_report r;
  r.points = soup.num_points();
  r.faces = soup.num_faces();
  auto add = [&](Soup_problem_kind kind, std::string element, std::string msg, std::vector<std::size_t> faces,
                 std::vector<std::size_t> verts) {
    ++r.problem_count;
    if (r.problems.size() < Soup_report::max_problems)
      r.problems.push_back({kind, std::move(element), std::move(msg), std::move(faces), std::move(verts)});
  };

  for (std::size_t p = 0; p < soup.num_points(); ++p)
    if (!soup.points[p].allFinite()) {
      ++r.non_finite_points;
      add(Soup_problem_kind::non_finite_point, "point " + std::to_string(p), "has a NaN or infinite coordinate", {},
          {p});
    }
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

  Soup_edges e = soup_edges(soup);
  for (auto [f, g] : duplicate_faces(soup, e)) {
    ++r.duplicate_faces;
    add(Soup_problem_kind::duplicate_face, "face " + std::to_string(f),
        "has the same corners as face " + std::to_string(g), {g, f}, {});
  }
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
    std::uint32_t b = e.group_begin[g], end = e.group_begin[g + 1];
    ++r.edges;
    const Soup_half& x = e.halves[b];
    std::string name = "edge (" + std::to_string(x.lo) + ", " + std::to_string(x.hi) + ")";
    if (end - b == 1) {
      ++r.border_edges;
    } else if (end - b == 2) {
      const Soup_half& y = e.halves[b + 1];
      if (x.forward == y.forward) {
        ++r.inconsistent_edges;
        std::uint32_t from = x.forward ? x.lo : x.hi, to = x.forward ? x.hi : x.lo;
        add(Soup_problem_kind::inconsistent_orientation, name,
            "faces " + std::to_string(x.face) + " and " + std::to_string(y.face) + " both use it as " +
                std::to_string(from) + "→" + std::to_string(to) + " (one of them is flipped, or they duplicate)",
            {x.face, y.face}, {x.lo, x.hi});
      }
    } else {
      ++r.non_manifold_edges;
      std::vector<std::size_t> fs;
      for (std::uint32_t i = b; i < end; ++i) fs.push_back(e.halves[i].face);
      add(Soup_problem_kind::non_manifold_edge, name,
          "is shared by " + std::to_string(end - b) + " faces (" + list(fs) + "); at most 2 are allowed", fs,
          {x.lo, x.hi});
    }
  }

  // Fans per vertex: roots of the corner union-find.
  Union_find uf = soup_fans(soup, e);
  std::vector<std::uint32_t> fans(soup.num_points(), 0);
  std::vector<char> used(soup.num_points(), 0);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (!e.usable[f]) continue;
    for (std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c) {
      used[soup.indices[c]] = 1;
      if (uf.find(c) == c) ++fans[soup.indices[c]];
    }
  }
  for (std::size_t v = 0; v < soup.num_points(); ++v) {
    if (fans[v] > 1) {
      ++r.non_manifold_vertices;
      add(Soup_problem_kind::non_manifold_vertex, "vertex " + std::to_string(v),
          "its faces form " + std::to_string(fans[v]) + " fans that meet only at this vertex (bow-tie)", {}, {v});
    }
  }
  // Points used only by unusable faces still count as used (they are not isolated).
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    if (!e.usable[f])
      for (auto i : soup.face(f))
        if (i < soup.num_points()) used[i] = 1;
  for (std::size_t v = 0; v < soup.num_points(); ++v) r.isolated_points += !used[v];

  // Zero-area faces: vector area (Newell) against the longest edge squared.
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
  return r;
}

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
