// genmesh/subdivision/detail/in_place.h — in-place refinement for Loop,
// Catmull-Clark, butterfly and midpoint (on triangle meshes): the old
// elements keep their indices, the new ones are appended, and the arrays are
// reserved once to the size of the last level.
//
// One level on a MutableFaceGraph g whose indices are dense (no removed
// elements; checked once per call):
//   1. read the old mesh: one pass over the old faces (face order, each from
//      its lowest-numbered vertex) numbers the old edges by first use and
//      writes every edge (and face) point straight into its appended vertex;
//      the old vertices' new positions go to one scratch array, written back
//      after all reads;
//   2. split every old edge k at its new vertex (the old edge keeps the half
//      from its halfedge(e)'s source, an appended edge the other half; border
//      cycles relinked), then
//   3. cut every old face: 1-to-4 (Loop, butterfly, midpoint: one piece,
//      refine_one_to_four, the schemes differ only in their point rules) or
//      into n quads around its face point (Catmull-Clark); the old face keeps
//      one of its children.
// The pieces shared by the schemes live here: the canonical face pass
// (for_each_canonical_triangle, edge_use, first_edge_point),
// the border edge points, the vertex masks for the visitor, the crease
// decrement, the counts, and run_in_place. Loop and Catmull-Clark move the
// old vertices (Vertex_sums, write_old_positions); butterfly and midpoint
// keep them (interpolating_one_to_four_level, an edge point being any mask
// of old vertices).
// √3 and Doo-Sabin are not refined here: their levels do not keep the old
// edges (√3 flips them, Doo-Sabin makes new faces from corner points), so
// they go through snapshot → soup → rebuild (detail/refinement.h), as does
// midpoint on polygons; the rebuild links a fresh mesh of the same type
// through detail::link_soup, which is native on every backend
// (genmesh_native_link_soup on Incidence_mesh, the backend's own
// MutableFaceGraph functions elsewhere): no other mesh type is involved.
// Canonical: faces are read from their lowest vertex, edges numbered by
// first use and every sum taken in that order, so the result depends only on
// the vertex numbering and the face cycles — not on halfedge(f), halfedge(v)
// or the edge order — and is the same on every backend.
// Element order: vertices = old ones, then one per old edge (first use), then
// (Catmull-Clark) one per old face (face order); edges = old edges, their
// other halves (first-use order), then the inner edges face by face; faces =
// old faces, then the new ones face by face. A backend may append elements in
// bulk with genmesh_native_append_elements(g, nv, ne, nf) (found by ADL:
// Halfedge_mesh in <genmesh/detail/halfedge/bulk.h>, one resize per array;
// CGAL::Surface_mesh in <genmesh/adaptors/cgal.h>, one reserve and names by
// arithmetic); otherwise (Polyhedron_3, OpenMesh) add_vertex/add_edge/
// add_face are called one by one and their descriptors kept in tables.
// Other backends (no set_next, as the incidence mesh) and meshes with removed
// elements refine the same way through the local operations instead
// (Local_refiner): every old edge k is split by genmesh::split_edge in
// first-use order, every old face is cut by genmesh::split_face (and, for
// Catmull-Clark, its face point made by splitting its first inner edge) in
// the order above, so a dense mesh gets the same elements in the same order
// as with the bulk path; each call reaches the backend's native operation
// (genmesh_native_split_edge, ...) when it has one. No copy is made.
// The old elements are read through their indices (arrays sized by the index
// bounds), so removed elements are skipped; on a mesh with removed elements
// new elements may reuse free slots, and the visitor's mask numbers are then
// vertex indices rather than iteration numbers.
#pragma once

#include <genmesh/local_operations.h>
#include <genmesh/subdivision/detail/refinement.h>

#include <algorithm>
#include <array>
#include <span>
#include <type_traits>

namespace genmesh {

namespace detail::subdivision {

/// A mesh refined in place: mutable, with vertex, halfedge and face indices.
template <class G>
concept In_place_refinable = MutableFaceGraph<G> && FaceListGraph<G> && VertexListGraph<G> && EdgeListGraph<G> &&
                             HasIndexMap<G, vertex_index_t> && HasIndexMap<G, halfedge_index_t> &&
                             HasIndexMap<G, edge_index_t> && HasIndexMap<G, face_index_t> && HasVertexPoints<G>;

template <class G>
concept Has_native_append = requires(G& g, std::size_t n) { genmesh_native_append_elements(g, n, n, n); };

/// Elements added one by one through the MutableFaceGraph functions.
template <class G>
struct Generic_appended {
  const G* g = nullptr;
  std::vector<vertex_descriptor_t<G>> vs;
  std::vector<halfedge_descriptor_t<G>> hs;
  std::vector<face_descriptor_t<G>> fs;
  vertex_descriptor_t<G> vertex(std::size_t k) const { return vs[k]; }
  halfedge_descriptor_t<G> halfedge(std::size_t k, unsigned i) const { return i == 0 ? hs[k] : opposite(hs[k], *g); }
  face_descriptor_t<G> face(std::size_t k) const { return fs[k]; }
};

/// The generic append: nv add_vertex, ne add_edge, nf add_face calls, the
/// descriptors kept in tables.
template <class G>
Generic_appended<G> generic_append_elements(G& g, std::size_t nv, std::size_t ne, std::size_t nf) {
  Generic_appended<G> a;
  a.g = &g;
  a.vs.reserve(nv);
  a.hs.reserve(ne);
  a.fs.reserve(nf);
  for (std::size_t k = 0; k < nv; ++k) a.vs.push_back(add_vertex(g));
  for (std::size_t k = 0; k < ne; ++k) a.hs.push_back(halfedge(add_edge(g), g));
  for (std::size_t k = 0; k < nf; ++k) a.fs.push_back(add_face(g));
  return a;
}

/// nv vertices, ne edges, nf faces more; the result names the k-th of each
/// (vertex(k), halfedge(k, 0 or 1), face(k)). The backend's
/// genmesh_native_append_elements (found by ADL) when it has one: it must
/// give the elements generic_append_elements would, in the same order.
template <class G>
auto append_elements(G& g, std::size_t nv, std::size_t ne, std::size_t nf) {
  if constexpr (Has_native_append<G>)
    return genmesh_native_append_elements(g, nv, ne, nf);
  else
    return generic_append_elements(g, nv, ne, nf);
}

/// No removed elements: iteration order is index order and new elements go to the end.
template <class G>
bool is_dense(const G& g) {
  std::size_t n = 0;
  for (auto v : vertices(g)) (void)v, ++n;
  if (n != index_bound(vertex_index, g)) return false;
  n = 0;
  for (auto h : halfedges(g)) (void)h, ++n;
  if (n != index_bound(halfedge_index, g)) return false;
  n = 0;
  for (auto f : faces(g)) (void)f, ++n;
  return n == index_bound(face_index, g);
}

/// The halfedges of face f into xs, xs[0] leaving f's lowest-numbered vertex
/// (the canonical start: the result does not depend on halfedge(f)).
/// old_target(x) gives the vertex number x pointed to before the split.
template <class G, class Old_target>
void canonical_cycle(const G& g, face_descriptor_t<G> f, std::vector<halfedge_descriptor_t<G>>& xs,
                     Old_target old_target) {
  xs.clear();
  const auto x0 = halfedge(f, g);
  auto x = x0;
  do {
    xs.push_back(x);
    x = next(x, g);
  } while (x != x0);
  const std::size_t n = xs.size();
  std::size_t best = 0;
  std::uint32_t lowest = k_none;
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t v = old_target(xs[t]); // the source of xs[t + 1]
    if (v < lowest) lowest = v, best = (t + 1) % n;
  }
  std::rotate(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(best), xs.end());
}

/// Per old vertex, from one pass over the old edges.
struct Stars {
  std::vector<std::uint32_t> valence;
  std::vector<std::uint8_t> border;      ///< border edges at the vertex (saturated at 255)
  std::vector<std::uint32_t> creases;    ///< crease edges (sharpness > 0, not border)
  std::vector<double> crease_sharpness;  ///< their sharpness sum
  std::vector<char> corner;              ///< tagged corners
  bool is_border(std::uint32_t v) const { return border[v] != 0 || valence[v] == 0; }
};

/// A vertex rule: new = self·v + ring·(Σ ring neighbours) + ends·(Σ crease
/// neighbours) + faces·(Σ face points around v). The ring is every neighbour
/// of an interior vertex and the border neighbours of a border vertex.
struct Vertex_rule {
  double self = 1, ring = 0, ends = 0, faces = 0;
};

/// The rule of old vertex v given its smooth interior rule: border (cubic
/// B-spline or fixed), tagged corner (stays), creases (DeRose, Kass, Truong
/// 1998: crease rule with two crease edges, corner rule with more, blended
/// by the mean sharpness below 1).
inline Vertex_rule vertex_rule(const Stars& st, std::uint32_t v, Boundary_rule boundary, Vertex_rule smooth) {
  if (!st.corner.empty() && st.corner[v]) return {};
  if (st.is_border(v)) {
    if (boundary == Boundary_rule::fixed || st.border[v] != 2) return {};
    return {0.75, 0.125, 0, 0};
  }
  if (st.creases.empty() || st.creases[v] < 2) return smooth;
  const Vertex_rule sharp = st.creases[v] == 2 ? Vertex_rule{0.75, 0, 0.125, 0} : Vertex_rule{};
  const double m = st.crease_sharpness[v] / st.creases[v];
  if (m >= 1) return sharp;
  return {(1 - m) * smooth.self + m * sharp.self, (1 - m) * smooth.ring, m * sharp.ends, (1 - m) * smooth.faces};
}

/// The old edges in edge iteration order with their index, halfedge, ends
/// (vertex indices) and border flag.
template <class G, class Fn>
void for_each_old_edge(G& g, Fn fn) {
  auto vi = get(vertex_index, g);
  auto ei = get(edge_index, g);
  for (auto e : edges(g)) {
    const auto k = static_cast<std::uint32_t>(get(ei, e));
    const auto h = halfedge(e, g), o = opposite(h, g);
    const bool border = face(h, g) == boost::graph_traits<G>::null_face() ||
                        face(o, g) == boost::graph_traits<G>::null_face();
    fn(k, h, static_cast<std::uint32_t>(get(vi, source(h, g))), static_cast<std::uint32_t>(get(vi, target(h, g))),
       border);
  }
}

/// sharp by edge index, corners as vertex indices; arrays by vertex index.
template <class G>
Stars stars(G& g, const std::vector<double>& sharp, const std::vector<std::uint32_t>& corners) {
  const std::size_t nv = index_bound(vertex_index, g);
  Stars st;
  st.valence.assign(nv, 0);
  st.border.assign(nv, 0);
  if (!sharp.empty()) {
    st.creases.assign(nv, 0);
    st.crease_sharpness.assign(nv, 0.0);
  }
  for_each_old_edge(g, [&](std::uint32_t k, auto h, std::uint32_t a, std::uint32_t b, bool border) {
    if (border && face(h, g) == boost::graph_traits<G>::null_face() &&
        face(opposite(h, g), g) == boost::graph_traits<G>::null_face())
      throw invalid_input("subdivision: edge " + std::to_string(k) + " has no face on either side (the mesh is unchanged)");
    ++st.valence[a], ++st.valence[b];
    if (border) {
      if (st.border[a] != 255) ++st.border[a];
      if (st.border[b] != 255) ++st.border[b];
    } else if (!sharp.empty() && sharp[k] > 0) {
      ++st.creases[a], ++st.creases[b];
      st.crease_sharpness[a] += sharp[k], st.crease_sharpness[b] += sharp[k];
    }
  });
  if (!corners.empty()) {
    st.corner.assign(nv, 0);
    for (std::uint32_t c : corners) st.corner[c] = 1;
  }
  return st;
}

/// Edge point weights: new = w_ends·(a + b) + w_wings·(wings); with creases
/// the smooth rule is blended towards the midpoint by the sharpness.
inline std::pair<double, double> edge_weights(double smooth_ends, double smooth_wings, bool border, double sharpness) {
  if (border || sharpness >= 1) return {0.5, 0.0};
  if (sharpness <= 0) return {smooth_ends, smooth_wings};
  return {(1 - sharpness) * smooth_ends + sharpness * 0.5, (1 - sharpness) * smooth_wings};
}

/// Masks for the visitor: per old vertex its neighbours with the edge
/// numbers (CSR), from the same edge pass as the rules.
struct Neighbours {
  std::vector<std::uint32_t> begin, vertex, edge;
};
template <class G>
Neighbours neighbours(G& g, const Stars& st, const std::vector<std::uint32_t>& number, std::size_t used) {
  Neighbours n;
  const std::size_t nv = st.valence.size();
  n.begin.assign(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v) n.begin[v + 1] = n.begin[v] + st.valence[v];
  n.vertex.resize(n.begin[nv]);
  n.edge.resize(n.begin[nv]);
  std::vector<std::uint32_t> ends(2 * used);
  for_each_old_edge(g, [&](std::uint32_t k, auto, std::uint32_t a, std::uint32_t b, bool) {
    ends[2 * number[k]] = a, ends[2 * number[k] + 1] = b;
  });
  std::vector<std::uint32_t> fill(n.begin.begin(), n.begin.end() - 1);
  for (std::uint32_t k = 0; k < used; ++k) { // in first-use order, as the sums
    const std::uint32_t a = ends[2 * k], b = ends[2 * k + 1];
    n.vertex[fill[a]] = b, n.edge[fill[a]++] = k;
    n.vertex[fill[b]] = a, n.edge[fill[b]++] = k;
  }
  return n;
}

/// Emits the mask of old vertex v's rule (face points given by face_mask,
/// which appends the corners of the faces around v with their weights).
template <class G, class V, class Border_edge, class Face_mask>
void emit_vertex_mask(V& vis, const Stars& st, const Neighbours& nb, const Vertex_rule& r,
                      std::uint32_t v, const std::vector<double>& sharp, Border_edge is_border_edge,
                      Face_mask face_mask, std::vector<std::uint32_t>& src, std::vector<double>& w) {
  src.assign(1, v);
  w.assign(1, r.self);
  const bool border = st.is_border(v);
  for (std::uint32_t i = nb.begin[v]; i < nb.begin[v + 1]; ++i) {
    const std::uint32_t k = nb.edge[i];
    if (r.ring != 0 && (!border || is_border_edge(k))) src.push_back(nb.vertex[i]), w.push_back(r.ring);
    if (r.ends != 0 && !is_border_edge(k) && !sharp.empty() && sharp[k] > 0)
      src.push_back(nb.vertex[i]), w.push_back(r.ends);
  }
  if (r.faces != 0) face_mask(v, r.faces, src, w);
  vis.on_vertex_mask(v, src, w);
}

/// Rotates the three halfedges x of a triangle so that x[0] leaves its
/// lowest-numbered vertex; t0..t2 are the numbers of the (old) targets.
template <class X>
void rotate_to_lowest(X (&x)[3], std::uint32_t t0, std::uint32_t t1, std::uint32_t t2) {
  if (t0 < t1 && t0 < t2) std::rotate(x, x + 1, x + 3);
  else if (t1 < t0 && t1 < t2) std::rotate(x, x + 2, x + 3);
}

/// Visits the first nf faces of the triangle mesh g in face order as
/// fn(j, xs): xs their halfedges, xs[0] leaving the lowest vertex.
template <class G, class Fn>
void for_each_canonical_triangle(const G& g, std::size_t nf, Fn fn) {
  auto vi = get(vertex_index, g);
  auto num = [&](auto v) { return static_cast<std::uint32_t>(get(vi, v)); };
  std::size_t j = 0;
  for (auto f : faces(g)) {
    if (j == nf) break;
    const auto x0 = halfedge(f, g), x1 = next(x0, g), x2 = next(x1, g);
    halfedge_descriptor_t<G> xs[3] = {x0, x1, x2};
    rotate_to_lowest(xs, num(target(x0, g)), num(target(x1, g)), num(target(x2, g)));
    fn(j++, xs);
  }
}

/// Whether the face pass has met old edge k before (a second use proves it
/// interior) and, at a first use, whether it is a border edge — read only
/// where it matters at once (want: creases, the visitor); the border edges'
/// points and the border vertices' rings are done after the pass.
struct Edge_use {
  bool seen, border;
};
template <class G>
Edge_use edge_use(const G& g, halfedge_descriptor_t<G> x, std::size_t k, const std::vector<std::uint32_t>& number,
                  const std::vector<double>& sharp, bool want_border) {
  const bool seen = number[k] != k_none;
  const bool want = want_border || (!sharp.empty() && sharp[k] > 0);
  return {seen, !seen && want && face(opposite(x, g), g) == boost::graph_traits<G>::null_face()};
}

/// The sums of the smoothing schemes (Loop, Catmull-Clark) over the old
/// vertices: ring neighbours (acc, interior ends only in the face pass) and
/// crease neighbours (ends, only with creases).
struct Vertex_sums {
  std::vector<Eigen::Vector3d> acc, ends;
};

/// First use of old edge x (a → b, crease sharpness s) as edge point m:
/// m = we·(a + b) + ww·wing; a and b enter each other's sums.
// Once per old edge in the hottest loop: out of line (GCC's choice) Loop
// runs 5% more instructions (callgrind, armadillo), hence always_inline.
template <class G, class Pts, class Points>
[[gnu::always_inline]] inline void first_edge_point(const G& g, Pts& pts, halfedge_descriptor_t<G> x, Points& points,
                                                    std::size_t m, double we, double ww, const Eigen::Vector3d& wing,
                                                    const Stars& st, bool border, double s, Vertex_sums& sums) {
  auto vi = get(vertex_index, g);
  const auto va = source(x, g), vb = target(x, g);
  const auto a = static_cast<std::uint32_t>(get(vi, va)), b = static_cast<std::uint32_t>(get(vi, vb));
  const Eigen::Vector3d pa = to_eigen(get(pts, va)), pb = to_eigen(get(pts, vb));
  Eigen::Vector3d p = we * (pa + pb);
  if (ww != 0) p += ww * wing;
  points.set(m, p);
  if (!st.is_border(a)) sums.acc[a] += pb;
  if (!st.is_border(b)) sums.acc[b] += pa;
  if (!border && s > 0) sums.ends[a] += pb, sums.ends[b] += pa;
}


/// After the face pass: border edges get their midpoints, border vertices
/// their border neighbours in acc (two per vertex where the ring is used:
/// the sum does not depend on the order).
template <class G, class Pts, class Points>
void border_edge_points(G& g, Pts& pts, Points& points, const std::vector<std::uint32_t>& number,
                        std::vector<Eigen::Vector3d>& acc) {
  for_each_old_edge(g, [&](std::uint32_t k, auto h, std::uint32_t a, std::uint32_t b, bool border) {
    if (!border) return;
    const Eigen::Vector3d pa = to_eigen(get(pts, source(h, g))), pb = to_eigen(get(pts, target(h, g)));
    points.set(number[k], Eigen::Vector3d(0.5 * (pa + pb)));
    acc[a] += pb;
    acc[b] += pa;
  });
}

/// The old vertices' new positions (acc by vertex index), written after every read.
template <class G, class Pts>
void write_old_positions(const G& g, Pts& pts, const std::vector<Eigen::Vector3d>& acc) {
  auto vi = get(vertex_index, g);
  for (auto v : vertices(g)) {
    const auto i = static_cast<std::size_t>(get(vi, v));
    if (i >= acc.size()) break; // appended: iteration is by increasing index
    put(pts, v, from_eigen<map_point_t<Pts>>(acc[i]));
  }
}

/// The visitor's masks of the old vertices (rules[v]; face points through
/// face_mask as in emit_vertex_mask); border_edge by edge point number.
template <class G, class V, class Face_mask>
void emit_vertex_masks(G& g, V& vis, const Stars& st, const std::vector<std::uint32_t>& number, std::size_t used,
                       const std::vector<double>& sharp, const std::vector<char>& border_edge,
                       const std::vector<Vertex_rule>& rules, Face_mask face_mask) {
  const Neighbours nb = neighbours(g, st, number, used);
  std::vector<double> sharp_by_number(sharp.empty() ? 0 : used);
  if (!sharp.empty())
    for (std::size_t k = 0; k < number.size(); ++k)
      if (number[k] != k_none) sharp_by_number[number[k]] = sharp[k];
  std::vector<std::uint32_t> src;
  std::vector<double> w;
  auto vi = get(vertex_index, g);
  for (auto vd : vertices(g)) {
    const auto v = static_cast<std::uint32_t>(get(vi, vd));
    if (v >= rules.size()) break;
    emit_vertex_mask<G>(vis, st, nb, rules[v], v, sharp_by_number,
                        [&](std::uint32_t k) { return border_edge[k] != 0; }, face_mask, src, w);
  }
}

/// The children's sharpness (by edge index): both halves of old edge k get
/// max(0, s − 1), the other new edges (index bound new_edges) 0. The other
/// half of edge number i is edge other[i], or edge ne + i when other is
/// empty (the bulk path on a dense mesh).
inline void decrement_creases(std::vector<double>& sharp, const std::vector<std::uint32_t>& number,
                              const std::vector<std::uint32_t>& other, std::size_t new_edges) {
  if (sharp.empty()) return;
  const std::size_t ne = number.size();
  std::vector<double> child(new_edges, 0.0);
  for (std::size_t k = 0; k < ne; ++k) {
    if (number[k] == k_none) continue;
    const std::size_t half = other.empty() ? ne + number[k] : other[number[k]];
    child[k] = child[half] = sharp[k] > 0 ? std::max(0.0, sharp[k] - 1.0) : 0.0;
  }
  sharp = std::move(child);
}

/// The halves of old halfedges after split_edges(): an old halfedge x of old
/// edge k is either halfedge(e_k) (now into the new vertex m_k = vertex nv + k)
/// or its opposite (still into its old target); the other half is a
/// halfedge of appended edge k.
template <class G, class Ae>
struct Halves {
  const G& g;
  const Ae& ae;
  std::size_t nv;
  struct Split {
    halfedge_descriptor_t<G> first, second; ///< from the old source to m, from m to the old target
    vertex_descriptor_t<G> m;
  };
  Split operator()(halfedge_descriptor_t<G> x) const {
    auto vi = get(vertex_index, g);
    const auto t = target(x, g);
    const auto i = static_cast<std::size_t>(get(vi, t));
    if (i >= nv) return {x, ae.halfedge(i - nv, 0), t};
    const auto m = target(opposite(x, g), g);
    return {ae.halfedge(static_cast<std::size_t>(get(vi, m)) - nv, 1), x, m};
  }
};

/// Step 2: split every old edge k (the first ne edges of the dense g) at
/// vertex av.vertex(i) = vertex nv + i, i = number[k] (its first use, see
/// the schemes): halfedge(e) now ends at m, appended edge i takes the other half. Sets targets, halfedge(m), halfedge(old
/// target), and links the border cycles; faces are linked by step 3, which
/// still finds each old face's old cycle through next().
template <class G, class Av, class Ae>
void split_edges(G& g, const Av& av, const Ae& ae, std::size_t nv, std::size_t ne,
                 const std::vector<std::uint32_t>& number) {
  const auto null_face = boost::graph_traits<G>::null_face();
  std::size_t k = 0;
  bool border = false;
  for (auto e : edges(g)) {
    if (k == ne) break;
    const std::uint32_t i = number[k];
    const auto m = av.vertex(i);
    const auto h = halfedge(e, g), o = opposite(h, g);
    const auto b = target(h, g);
    set_target(h, m, g);
    set_target(ae.halfedge(i, 0), b, g);
    set_target(ae.halfedge(i, 1), m, g);
    if (halfedge(b, g) == h) set_halfedge(b, ae.halfedge(i, 0), g);
    const bool fo = face(o, g) == null_face;
    set_halfedge(m, fo ? ae.halfedge(i, 1) : h, g);
    border = border || fo || face(h, g) == null_face;
    ++k;
  }
  if (!border) return;
  // border cycles: z → next(z) becomes first(z) → second(z) → first(next(z))
  const Halves<G, Ae> halves{g, ae, nv};
  k = 0;
  for (auto e : edges(g)) {
    if (k++ == ne) break;
    const auto h = halfedge(e, g);
    for (const auto z : {h, opposite(h, g)}) {
      if (face(z, g) != null_face) continue;
      const auto sz = halves(z), sw = halves(next(z, g));
      set_face(sz.first, null_face, g);
      set_face(sz.second, null_face, g);
      set_next(sz.first, sz.second, g);
      set_next(sz.second, sw.first, g);
    }
  }
}

/// Step 3 for Loop: the 1-to-4 cut of every old triangle j (the first nf
/// faces): the corner triangles become appended faces 3j + t (t from the
/// corner after the lowest vertex), the middle one
/// stays face j; its inner edges are appended edges ne + 3j + t.
template <class G, class Ae>
void cut_triangles(G& g, const Ae& ae, std::size_t nv, std::size_t ne, std::size_t nf) {
  const Halves<G, Ae> halves{g, ae, nv};
  auto vi = get(vertex_index, g);
  auto vnum = [&](auto v) { return static_cast<std::uint32_t>(get(vi, v)); };
  std::size_t j = 0;
  for (auto f : faces(g)) {
    if (j == nf) break;
    typename Halves<G, Ae>::Split x[3];
    halfedge_descriptor_t<G> d[3], e[3];
    const auto x0 = halfedge(f, g), x1 = next(x0, g), x2 = next(x1, g);
    x[0] = halves(x0), x[1] = halves(x1), x[2] = halves(x2);
    rotate_to_lowest(x, vnum(target(x[0].second, g)), vnum(target(x[1].second, g)), vnum(target(x[2].second, g)));
    for (int t = 0; t < 3; ++t) {
      d[t] = ae.halfedge(ne + 3 * j + t, 0);
      e[t] = ae.halfedge(ne + 3 * j + t, 1);
      set_target(d[t], x[t].m, g);
      set_target(e[t], x[(t + 1) % 3].m, g);
    }
    for (int t = 0; t < 3; ++t) {
      const auto ft = ae.face(3 * j + t);
      const auto s = x[t].second, fn = x[(t + 1) % 3].first;
      set_next(s, fn, g);
      set_next(fn, d[t], g);
      set_next(d[t], s, g);
      set_face(s, ft, g);
      set_face(fn, ft, g);
      set_face(d[t], ft, g);
      set_halfedge(ft, d[t], g);
      set_next(e[t], e[(t + 1) % 3], g);
      set_face(e[t], f, g);
    }
    set_halfedge(f, e[0], g);
    ++j;
  }
}

/// Steps 2 and 3 of a 1-to-4 level (Loop, butterfly, midpoint) once the
/// edge points av.vertex(number[k]) are placed.
template <class G, class Av>
void refine_one_to_four(G& g, const Av& av, std::size_t nv, std::size_t ne, std::size_t nf,
                        const std::vector<std::uint32_t>& number) {
  auto ae = append_elements(g, 0, ne + 3 * nf, 3 * nf);
  split_edges(g, av, ae, nv, ne, number);
  cut_triangles(g, ae, nv, ne, nf);
}

/// An edge point's mask: old vertices and their weights.
template <class G>
struct Mask {
  std::vector<vertex_descriptor_t<G>> vertex;
  std::vector<double> weight;
  void add(vertex_descriptor_t<G> v, double w) { vertex.push_back(v), weight.push_back(w); }
};

/// One level of an interpolating 1-to-4 scheme (butterfly, midpoint) in
/// place on the dense triangle mesh g of counts n: the old vertices stay,
/// and the point of old edge x (numbered by first use, as Loop's) is the
/// combination rule(x, mask) gives, read from the old mesh; the visitor
/// gets the same masks (an old vertex: itself, weight 1).
template <class G, class V, class Refiner, class Rule>
void interpolating_one_to_four_level(G& g, const std::array<std::size_t, 4>& n, V& vis, const Refiner& refiner,
                                     Rule rule) {
  constexpr bool masks = visits_vertex_masks<V>;
  const std::size_t nv = n[0], ne = n[1], nf = n[2];
  auto pts = refiner.pts;
  auto vi = get(vertex_index, g);
  auto ei = get(edge_index, g);
  std::vector<std::uint32_t> number(index_bound(edge_index, g), k_none), src;
  const std::size_t nvb = index_bound(vertex_index, g);
  auto points = refiner.new_points(g, ne);
  std::uint32_t used = 0;
  Mask<G> mask;
  for_each_canonical_triangle(g, nf, [&](std::size_t, auto& xs) {
    for (const auto x : xs) {
      const auto k = static_cast<std::size_t>(get(ei, edge(x, g)));
      if (number[k] != k_none) continue;
      const std::uint32_t i = number[k] = used++;
      mask.vertex.clear(), mask.weight.clear();
      rule(x, mask);
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (std::size_t t = 0; t < mask.vertex.size(); ++t) p += mask.weight[t] * to_eigen(get(pts, mask.vertex[t]));
      points.set(i, p);
      if constexpr (masks) {
        src.clear();
        for (const auto v : mask.vertex) src.push_back(static_cast<std::uint32_t>(get(vi, v)));
        vis.on_vertex_mask(static_cast<std::uint32_t>(nv + i), src, mask.weight);
      }
    }
  });
  if constexpr (masks) {
    const double one = 1.0;
    for (auto vd : vertices(g)) {
      const auto v = static_cast<std::uint32_t>(get(vi, vd));
      if (v >= nvb) break;
      vis.on_vertex_mask(v, {&v, 1}, {&one, 1});
    }
  }
  refiner.one_to_four(g, points, nv, ne, nf, number);
}

/// Step 3 for Catmull-Clark: every old n-gon j (the first nf faces) becomes n
/// quads around its face point av.vertex(ne + j): quad t (at the old target
/// of the face's t-th halfedge from its lowest vertex) is second_t, first_t+1,
/// m_t+1 → c, c → m_t; quads 0..n−2 are appended faces, quad n−1 stays f;
/// inner edge m_t – c is the next appended edge (face by face).
template <class G, class Av, class Ae>
void cut_polygons(G& g, const Av& av, const Ae& ae, std::size_t nv, std::size_t ne, std::size_t nf) {
  using Split = typename Halves<G, Ae>::Split;
  const Halves<G, Ae> halves{g, ae, nv};
  auto vi = get(vertex_index, g);
  std::vector<Split> xs;
  std::vector<halfedge_descriptor_t<G>> hs;
  std::size_t j = 0, inner = ne, new_faces = 0;
  for (auto f : faces(g)) {
    if (j == nf) break;
    const auto c = av.vertex(ne + j);
    canonical_cycle(g, f, hs, [&](auto x) { return static_cast<std::uint32_t>(get(vi, target(halves(x).second, g))); });
    xs.clear();
    for (const auto x : hs) xs.push_back(halves(x));
    const std::size_t n = xs.size();
    for (std::size_t t = 0; t < n; ++t) {
      set_target(ae.halfedge(inner + t, 0), c, g);
      set_target(ae.halfedge(inner + t, 1), xs[t].m, g);
    }
    for (std::size_t t = 0; t < n; ++t) {
      const std::size_t u = (t + 1) % n;
      const auto ft = t + 1 == n ? f : ae.face(new_faces + t);
      const auto in = ae.halfedge(inner + u, 0), out = ae.halfedge(inner + t, 1);
      set_next(xs[t].second, xs[u].first, g);
      set_next(xs[u].first, in, g);
      set_next(in, out, g);
      set_next(out, xs[t].second, g);
      for (const auto z : {xs[t].second, xs[u].first, in, out}) set_face(z, ft, g);
      set_halfedge(ft, out, g);
    }
    set_halfedge(c, ae.halfedge(inner, 0), g);
    inner += n;
    new_faces += n - 1;
    ++j;
  }
}

/// The new points of a level on the bulk path: vertices appended at once,
/// positions written straight into them.
template <class G, class Av, class Pts>
struct Appended_points {
  Av av;
  Pts pts;
  void set(std::size_t i, const Eigen::Vector3d& p) { put(pts, av.vertex(i), from_eigen<map_point_t<Pts>>(p)); }
  [[gnu::always_inline]] void add(std::size_t i, double w, const Eigen::Vector3d& p) {
    if (w != 0)
      put(pts, av.vertex(i), from_eigen<map_point_t<Pts>>(Eigen::Vector3d(to_eigen(get(pts, av.vertex(i))) + w * p)));
  }
};

/// The bulk path (a MutableFaceGraph without removed elements): elements
/// appended with append_elements, linked with set_next/set_target/...;
/// positions through the point map pts.
template <class Pm>
struct Bulk_refiner {
  Pm pts;
  template <class G>
  auto new_points(G& g, std::size_t n) const {
    auto av = append_elements(g, n, 0, 0);
    return Appended_points<G, decltype(av), Pm>{std::move(av), pts};
  }
  /// Returns the other half of each split edge (empty: edge ne + i).
  template <class G, class Points>
  std::vector<std::uint32_t> one_to_four(G& g, const Points& points, std::size_t nv, std::size_t ne, std::size_t nf,
                                         const std::vector<std::uint32_t>& number) const {
    refine_one_to_four(g, points.av, nv, ne, nf, number);
    return {};
  }
  template <class G, class Points>
  std::vector<std::uint32_t> quads(G& g, const Points& points, std::size_t nv, std::size_t ne, std::size_t nf,
                                   std::size_t nc, const std::vector<std::uint32_t>& number) const {
    auto ae = append_elements(g, 0, ne + nc, nc - nf);
    split_edges(g, points.av, ae, nv, ne, number);
    cut_polygons(g, points.av, ae, nv, ne, nf);
    return {};
  }
};

/// The new points of a level on the local-operations path, kept until the
/// operations make their vertices.
struct Buffered_points {
  std::vector<Eigen::Vector3d> p;
  void set(std::size_t i, const Eigen::Vector3d& x) { p[i] = x; }
  void add(std::size_t i, double w, const Eigen::Vector3d& x) {
    if (w != 0) p[i] += w * x;
  }
};

/// The local-operations path (any backend with split_edge and split_face,
/// native or generic; removed elements allowed): the same refinement as the
/// bulk path, one operation at a time, each reported to the visitor's
/// per-operation hooks (on_split_edge, on_split_face).
template <class V, class Pm>
struct Local_refiner {
  V* vis;
  Pm pts;

  template <class G>
  Buffered_points new_points(G&, std::size_t n) const {
    return {std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero())};
  }

  /// The old faces, then every old edge split at its point in first-use
  /// order (edge number i keeps the half at its halfedge's source, as
  /// split_edges); marks the new vertices in is_new; returns the index of
  /// each new half.
  template <class G>
  std::vector<std::uint32_t> split_all(G& g, const Buffered_points& points, std::size_t ne,
                                              const std::vector<std::uint32_t>& number, std::vector<char>& is_new,
                                              std::vector<face_descriptor_t<G>>& old_faces) const {
    using H = halfedge_descriptor_t<G>;
    auto ei = get(edge_index, g);
    auto vi = get(vertex_index, g);
    old_faces.clear();
    for (auto f : faces(g)) old_faces.push_back(f);
    std::vector<H> eh(ne);
    for (auto e : edges(g)) {
      const auto k = static_cast<std::size_t>(get(ei, e));
      if (k < number.size() && number[k] != k_none) eh[number[k]] = halfedge(e, g);
    }
    std::vector<std::uint32_t> other(ne);
    std::vector<std::uint32_t> made(ne);
    for (std::size_t i = 0; i < ne; ++i) {
      // split_edge(h) keeps h's edge on the target side of h: split the
      // opposite of halfedge(e), so that the old edge keeps its source's half
      const H hn = *genmesh::split_edge(opposite(eh[i], g), g, *vis);
      const auto m = target(hn, g);
      put(pts, m, from_eigen<map_point_t<Pm>>(points.p[i]));
      other[i] = static_cast<std::uint32_t>(get(ei, edge(hn, g)));
      made[i] = static_cast<std::uint32_t>(get(vi, m));
    }
    is_new.assign(index_bound(vertex_index, g), 0);
    for (std::uint32_t v : made) is_new[v] = 1;
    return other;
  }

  /// The cycle of old face f after split_all, from the halfedge leaving its
  /// lowest old vertex: old → m_0, m_0 → old, old → m_1, ...
  template <class G>
  static void split_cycle(const G& g, face_descriptor_t<G> f, const std::vector<char>& is_new,
                          std::vector<halfedge_descriptor_t<G>>& xs) {
    auto vi = get(vertex_index, g);
    canonical_cycle(g, f, xs, [&](auto x) {
      const auto v = static_cast<std::uint32_t>(get(vi, target(x, g)));
      return is_new[v] ? k_none : v;
    });
  }

  template <class G>
  std::vector<std::uint32_t> one_to_four(G& g, const Buffered_points& points, std::size_t, std::size_t ne,
                                         std::size_t, const std::vector<std::uint32_t>& number) const {
    std::vector<char> is_new;
    std::vector<face_descriptor_t<G>> old_faces;
    std::vector<std::uint32_t> other = split_all(g, points, ne, number, is_new, old_faces);
    std::vector<halfedge_descriptor_t<G>> xs;
    for (const auto f : old_faces) {
      split_cycle(g, f, is_new, xs);
      // corner t (at the old vertex after m_t) is cut off as the next new face
      for (std::size_t t = 0; t < 3; ++t)
        genmesh::split_face(prev(xs[2 * t + 1], g), xs[(2 * t + 2) % 6], g, *vis);
    }
    return other;
  }

  template <class G>
  std::vector<std::uint32_t> quads(G& g, const Buffered_points& points, std::size_t, std::size_t ne, std::size_t,
                                   std::size_t, const std::vector<std::uint32_t>& number) const {
    std::vector<char> is_new;
    std::vector<face_descriptor_t<G>> old_faces;
    std::vector<std::uint32_t> other = split_all(g, points, ne, number, is_new, old_faces);
    std::vector<halfedge_descriptor_t<G>> xs;
    std::size_t j = 0;
    for (const auto f : old_faces) {
      split_cycle(g, f, is_new, xs);
      const std::size_t n = xs.size() / 2;
      // quad 0 is cut off by m_0 → m_1, whose split makes the face point c
      // (the old edge keeps m_0 – c, the new one is m_1 – c); then quad t by
      // c → m_t+1; quad n − 1 stays f
      const auto h = *genmesh::split_face(xs[0], xs[2], g, *vis);
      const auto hc = *genmesh::split_edge(opposite(h, g), g, *vis);
      put(pts, target(hc, g), from_eigen<map_point_t<Pm>>(points.p[ne + j]));
      for (std::size_t t = 1; t + 1 < n; ++t) genmesh::split_face(h, xs[2 * (t + 1)], g, *vis);
      ++j;
    }
    return other;
  }
};

/// A backend that takes a level's result in incidence form in one call
/// (Incidence_mesh: it has no set_next for the bulk path's linking).
template <class G>
concept Has_native_relink = requires(G& g, std::size_t n, const std::vector<std::uint32_t>& a) {
  genmesh_native_relink(g, n, a, a, a);
};

/// The bulk path of a backend with genmesh_native_relink (and no removed
/// elements): the same elements in the same order as the bulk path and the
/// local operations give — vertices nv + i for the edge points, then the
/// face points; old edge k keeps the half at its halfedge's source, the
/// other half is edge ne + number[k]; then the inner edges face by face; old
/// face j keeps the middle triangle (1-to-4) or its last quad, the others
/// are appended face by face — computed from the old mesh, then handed to
/// the backend as edge ends and face side cycles (halfedge 2e + side), and
/// the new points written through pts. The per-operation visitor hooks are
/// not called (as on the bulk path).
template <class Pm>
struct Relink_refiner {
  Pm pts;

  template <class G>
  Buffered_points new_points(G&, std::size_t n) const {
    return {std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero())};
  }

  /// Old halfedge x of a split edge: (first, second) as sides, from the old
  /// source to m and from m to the old target, and m. x runs along its edge
  /// k when it leaves the edge's source (ends[2k], from split_ends; not
  /// x == halfedge(edge(x)), which some descriptors make true for both).
  struct Halves_of {
    std::uint32_t first, second, m;
  };
  template <class G>
  static Halves_of halves(const G& g, halfedge_descriptor_t<G> x, std::size_t nv, std::size_t ne,
                          const std::vector<std::uint32_t>& number, const std::vector<std::uint32_t>& ends) {
    const auto k = static_cast<std::uint32_t>(get(get(edge_index, g), edge(x, g)));
    const std::uint32_t i = number[k], half = static_cast<std::uint32_t>(ne) + i;
    const auto m = static_cast<std::uint32_t>(nv + i);
    if (static_cast<std::uint32_t>(get(get(vertex_index, g), source(x, g))) == ends[2 * k])
      return {2 * k, 2 * half, m};
    return {2 * half + 1, 2 * k + 1, m};
  }

  /// Edge ends after the split of the ne old edges, with room for `inner`
  /// more edges.
  template <class G>
  static std::vector<std::uint32_t> split_ends(const G& g, std::size_t nv, std::size_t ne, std::size_t inner,
                                               const std::vector<std::uint32_t>& number) {
    auto vi = get(vertex_index, g);
    auto ei = get(edge_index, g);
    std::vector<std::uint32_t> ends(2 * (2 * ne + inner));
    for (auto e : edges(g)) {
      const auto k = static_cast<std::size_t>(get(ei, e));
      if (k >= ne) break;
      const auto h = halfedge(e, g);
      const std::size_t i = number[k], m = nv + i;
      ends[2 * k] = static_cast<std::uint32_t>(get(vi, source(h, g)));
      ends[2 * k + 1] = static_cast<std::uint32_t>(m);
      ends[2 * (ne + i)] = static_cast<std::uint32_t>(m);
      ends[2 * (ne + i) + 1] = static_cast<std::uint32_t>(get(vi, target(h, g)));
    }
    return ends;
  }

  template <class G>
  void finish(G& g, const Buffered_points& points, std::size_t nv, const std::vector<std::uint32_t>& ends,
              const std::vector<std::uint32_t>& offsets, const std::vector<std::uint32_t>& sides) const {
    genmesh_native_relink(g, nv + points.p.size(), ends, offsets, sides);
    std::size_t i = 0;
    for (auto v : vertices(g)) // no removed elements: iteration is by index
      if (i++ >= nv) put(pts, v, from_eigen<map_point_t<Pm>>(points.p[i - 1 - nv]));
  }

  template <class G>
  std::vector<std::uint32_t> one_to_four(G& g, const Buffered_points& points, std::size_t nv, std::size_t ne,
                                         std::size_t nf, const std::vector<std::uint32_t>& number) const {
    auto vi = get(vertex_index, g);
    auto vnum = [&](auto v) { return static_cast<std::uint32_t>(get(vi, v)); };
    std::vector<std::uint32_t> ends = split_ends(g, nv, ne, 3 * nf, number);
    std::vector<std::uint32_t> offsets(4 * nf + 1), sides(12 * nf);
    for (std::size_t f = 0; f <= 4 * nf; ++f) offsets[f] = static_cast<std::uint32_t>(3 * f);
    std::size_t j = 0;
    for (auto f : faces(g)) {
      if (j == nf) break;
      const auto x0 = halfedge(f, g), x1 = next(x0, g), x2 = next(x1, g);
      Halves_of x[3] = {halves(g, x0, nv, ne, number, ends), halves(g, x1, nv, ne, number, ends),
                        halves(g, x2, nv, ne, number, ends)};
      rotate_to_lowest(x, vnum(target(x0, g)), vnum(target(x1, g)), vnum(target(x2, g)));
      for (std::size_t t = 0; t < 3; ++t) {
        const std::size_t inner = 2 * ne + 3 * j + t, u = (t + 1) % 3;
        ends[2 * inner] = x[u].m; // side 0 ends at m_t, side 1 at m_t+1
        ends[2 * inner + 1] = x[t].m;
        sides[3 * j + t] = static_cast<std::uint32_t>(2 * inner + 1); // the middle triangle stays face j
        std::uint32_t* corner = &sides[3 * (nf + 3 * j + t)];
        corner[0] = x[t].second, corner[1] = x[u].first, corner[2] = static_cast<std::uint32_t>(2 * inner);
      }
      ++j;
    }
    finish(g, points, nv, ends, offsets, sides);
    return {};
  }

  template <class G>
  std::vector<std::uint32_t> quads(G& g, const Buffered_points& points, std::size_t nv, std::size_t ne, std::size_t nf,
                                   std::size_t nc, const std::vector<std::uint32_t>& number) const {
    auto vi = get(vertex_index, g);
    std::vector<std::uint32_t> ends = split_ends(g, nv, ne, nc, number);
    std::vector<std::uint32_t> offsets(nc + 1), sides(4 * nc);
    for (std::size_t f = 0; f <= nc; ++f) offsets[f] = static_cast<std::uint32_t>(4 * f);
    std::vector<halfedge_descriptor_t<G>> hs;
    std::vector<Halves_of> xs;
    std::size_t j = 0, inner = 2 * ne, new_faces = nf;
    for (auto f : faces(g)) {
      if (j == nf) break;
      const auto c = static_cast<std::uint32_t>(nv + ne + j);
      canonical_cycle(g, f, hs, [&](auto x) { return static_cast<std::uint32_t>(get(vi, target(x, g))); });
      xs.clear();
      for (const auto x : hs) xs.push_back(halves(g, x, nv, ne, number, ends));
      const std::size_t n = xs.size();
      for (std::size_t t = 0; t < n; ++t) { // inner edge t: m_t → c
        ends[2 * (inner + t)] = xs[t].m;
        ends[2 * (inner + t) + 1] = c;
      }
      for (std::size_t t = 0; t < n; ++t) { // quad t: second_t, first_t+1, m_t+1 → c, c → m_t
        const std::size_t u = (t + 1) % n, ft = t + 1 == n ? j : new_faces + t;
        std::uint32_t* corner = &sides[4 * ft];
        corner[0] = xs[t].second, corner[1] = xs[u].first;
        corner[2] = static_cast<std::uint32_t>(2 * (inner + u)), corner[3] = static_cast<std::uint32_t>(2 * (inner + t) + 1);
      }
      inner += n;
      new_faces += n - 1;
      ++j;
    }
    finish(g, points, nv, ends, offsets, sides);
    return {};
  }
};

/// Counts {V, E, F, corners} of g; throws, naming the face, when a face
/// cycle does not close or (face_size ≠ 0) a face has another size.
template <class G>
std::array<std::size_t, 4> face_counts(const G& g, const char* scheme, std::size_t face_size) {
  std::size_t nv = 0, ne = 0, nf = 0, nc = 0;
  for (auto v : vertices(g)) (void)v, ++nv;
  for (auto e : edges(g)) (void)e, ++ne;
  for (auto f : faces(g)) {
    const auto h0 = halfedge(f, g);
    auto h = h0;
    std::size_t n = 0;
    do {
      h = next(h, g);
      if (++n > 2 * ne)
        throw invalid_input(std::string(scheme) + ": the cycle of face " + std::to_string(nf) + " is corrupt");
    } while (h != h0);
    if (face_size != 0 && n != face_size)
      throw invalid_input(std::string(scheme) + ": face " + std::to_string(nf) + " has " + std::to_string(n) +
                          " sides; the scheme takes only " + std::to_string(face_size) +
                          "-sided faces (the mesh is unchanged)");
    nc += n;
    ++nf;
  }
  return {nv, ne, nf, nc};
}

/// The creases and corners after the last level, for the limit projection:
/// sharpness in edge iteration order, corner flags in vertex iteration order
/// (each empty when not given).
struct Final_tags {
  std::vector<double> sharp;
  std::vector<char> corner;
};

/// The limit positions after the last level of a smoothing scheme (Loop,
/// Catmull-Clark): tagged corners stay, border vertices get the border
/// limit, the others interior(s, v); crease vertices see move_to_limit.
template <class G, class Interior, class Pm>
void move_to_limit(G& g, const Final_tags& tags, Boundary_rule boundary, Interior interior, const Pm& pm) {
  move_to_limit(g, tags.sharp, [&](const Snapshot& s, std::uint32_t v) -> Eigen::Vector3d {
    if (!tags.corner.empty() && tags.corner[v]) return s.points[v];
    if (s.is_border_vertex(v)) return border_limit_point(s, v, boundary);
    return interior(s, v);
  }, pm);
}

inline std::array<std::size_t, 4> one_to_four_counts(std::array<std::size_t, 4> n) {
  return {n[0] + n[1], 2 * n[1] + 3 * n[2], 4 * n[2], 12 * n[2]};
}

/// The crease map's sharpness by edge index (empty when no map is given).
/// Throws genmesh::invalid_input naming the edge (iteration order) for a
/// negative or NaN sharpness.
template <class G, class CreaseMap>
std::vector<double> read_sharpness(const G& g, const CreaseMap& crease_map, const char* scheme) {
  if constexpr (std::is_same_v<CreaseMap, Default_map>) {
    return {};
  } else {
    auto ei = get(edge_index, g);
    std::vector<double> sharp(index_bound(edge_index, g), 0.0);
    std::size_t k = 0;
    for (auto e : edges(g)) {
      const double s = static_cast<double>(get(crease_map, e));
      if (!(s >= 0))
        throw invalid_input(std::string(scheme) + ": crease_map gives edge " + std::to_string(k) +
                            " a negative or NaN sharpness (the mesh is unchanged)");
      sharp[static_cast<std::size_t>(get(ei, e))] = s;
      ++k;
    }
    return sharp;
  }
}

/// The vertices the corner map tags, as vertex indices.
template <class G, class CornerMap>
std::vector<std::uint32_t> read_corners(const G& g, const CornerMap& corner_map) {
  std::vector<std::uint32_t> out;
  if constexpr (!std::is_same_v<CornerMap, Default_map>) {
    auto vi = get(vertex_index, g);
    for (auto v : vertices(g))
      if (static_cast<bool>(get(corner_map, v))) out.push_back(static_cast<std::uint32_t>(get(vi, v)));
  }
  return out;
}

/// Runs `iterations` levels of scheme on g, in place: level(g, counts,
/// sharp, corners, refiner) per level (sharp by edge index, corners as
/// vertex indices), with the Bulk_refiner when g is a MutableFaceGraph
/// without removed elements (arrays reserved once to the last level's
/// size), else the Local_refiner. check(g) throws (g untouched) before
/// anything changes; grow(counts) gives the counts after one level. The
/// crease map receives the sharpness of every edge of the result; tags (if
/// given) what the limit projection needs.
template <class G, class CreaseMap, class CornerMap, class Pm, class Check, class Level, class V>
Subdivision_result run_in_place(G& g, int iterations, const char* scheme, const CreaseMap& crease_map,
                                const CornerMap& corner_map, const Pm& point_map, Check check, Level level,
                                std::array<std::size_t, 4> (*grow)(std::array<std::size_t, 4>), V& vis,
                                Final_tags* tags = nullptr) {
  if (iterations < 0) throw invalid_input(std::string(scheme) + ": iterations must be ≥ 0");
  std::vector<double> sharp = read_sharpness(g, crease_map, scheme);
  Subdivision_result r{0, 0, 0};
  for (auto v : vertices(g)) (void)v, ++r.vertices;
  if (iterations == 0) {
    for (auto f : faces(g)) (void)f, ++r.faces;
    return r;
  }
  const std::array<std::size_t, 4> counts = check(g); // V, E, F, corners
  const std::vector<std::uint32_t> corner_index = read_corners(g, corner_map);
  const auto total = static_cast<std::size_t>(iterations);
  std::array<std::size_t, 4> now = counts;
  auto run = [&](const auto& refiner) {
    vis.on_step("level", 0, total);
    for (int i = 0; i < iterations; ++i) {
      level(g, now, sharp, corner_index, refiner);
      now = grow(now);
      ++r.levels_done;
      vis.on_step("level", static_cast<std::size_t>(r.levels_done), total);
    }
  };
  bool bulk = false;
  if constexpr (In_place_refinable<G>) {
    if (is_dense(g)) {
      bulk = true;
      std::array<std::size_t, 4> last = counts;
      for (int i = 0; i < iterations; ++i) last = grow(last);
      reserve(g, static_cast<typename boost::graph_traits<G>::vertices_size_type>(last[0]),
              static_cast<typename boost::graph_traits<G>::edges_size_type>(last[1]),
              static_cast<typename boost::graph_traits<G>::faces_size_type>(last[2]));
      run(Bulk_refiner<decltype(point_map_of(g, point_map))>{point_map_of(g, point_map)});
    }
  }
  if constexpr (!In_place_refinable<G> && Has_native_relink<G>) {
    if (is_dense(g)) {
      bulk = true;
      run(Relink_refiner<decltype(point_map_of(g, point_map))>{point_map_of(g, point_map)});
    }
  }
  if (!bulk) run(Local_refiner<V, decltype(point_map_of(g, point_map))>{&vis, point_map_of(g, point_map)});
  r.vertices = now[0];
  r.faces = now[2];
  if constexpr (!std::is_same_v<CreaseMap, Default_map>) { // the refined mesh's sharpness, edge by edge
    CreaseMap out = crease_map; // a property map is a handle: writes reach the caller's storage
    auto ei = get(edge_index, g);
    for (auto e : edges(g)) {
      const double s = sharp[static_cast<std::size_t>(get(ei, e))];
      put(out, e, s);
      if (tags) tags->sharp.push_back(s);
    }
  }
  if (tags && !corner_index.empty()) {
    std::vector<char> is_corner(index_bound(vertex_index, g), 0);
    for (std::uint32_t c : corner_index) is_corner[c] = 1;
    auto vi = get(vertex_index, g);
    for (auto v : vertices(g)) tags->corner.push_back(is_corner[static_cast<std::size_t>(get(vi, v))]);
  }
  return r;
}

} // namespace detail::subdivision
} // namespace genmesh
