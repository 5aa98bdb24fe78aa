// genmesh/soup_to_mesh.h — halfedge meshes of any backend from polygon soups, and back.
//
// build_mesh(soup, g) checks the soup (check_soup), refuses it with a
// genmesh::invalid_input naming the offending faces, edges and vertices — or,
// with .repair = true, repairs a copy (repair_soup) — and then builds g
// directly with the MutableFaceGraph primitives in linear time.
//
// Guarantees (the same on every backend, so results can be compared exactly):
// - vertex i of the soup is the i-th vertex of g, face j the j-th face;
//   isolated points become isolated vertices;
// - edges are created in the order their first directed use appears (face by
//   face, corner by corner); the halfedge created first for an edge is the one
//   of that first use;
// - halfedge(f, g) is the halfedge whose target is f's first corner (on
//   backends that store it; Incidence_mesh derives a canonical one: the side
//   along f's lowest-numbered edge);
// - halfedge(v, g) is the incoming border halfedge for a border vertex (CGAL's
//   convention) and the first incoming halfedge in corner order otherwise.
// Works on every MutableFaceGraph with vertex points; tested on
// genmesh::Halfedge_mesh and CGAL::Surface_mesh (compared element for element:
// same indices, same links), CGAL::Polyhedron_3 and OpenMesh's PolyMesh.
// Speed: ~0.25 s for 1.3M triangles with check off, plus ~0.4 s for the
// check (one core, -O2).
//
// to_soup(g) numbers vertices in vertex iteration order and faces in face
// iteration order, each face starting at its lowest-numbered vertex
// (a rotation: the orientation is kept). canonical(soup) also sorts the faces.
//
// Per-vertex attributes: a soup's channels (Polygon_soup::vertex_attributes)
// go into vertex property maps of the mesh built from it with
// read_vertex_attribute(), and a mesh's maps become channels of to_soup(g)
// with make_soup_attribute() — both in vertex iteration order, the numbering
// build_mesh and to_soup share.
#pragma once

#include <genmesh/attribute_traits.h>
#include <genmesh/concepts.h>
#include <genmesh/exceptions.h>
#include <genmesh/point_traits.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/property_maps.h>
#include <genmesh/detail/validity/dense_index.h>
#include <genmesh/detail/validity/soup_edges.h>
#include <genmesh/soup_check.h>
#include <genmesh/soup_repair.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace genmesh {

/// How build_mesh() treats its input.
struct Build_options {
  bool repair = false; ///< repair a copy of a soup that fails check_soup() instead of refusing it
  /// Run check_soup() first. Off, build_mesh() still refuses (before touching
  /// g) what would corrupt the structure — degenerate faces, bad indices,
  /// fins, inconsistent orientation, a bow-tie on the border — but a vertex
  /// where several closed fans meet passes into g (check_mesh() reports it),
  /// and nothing is repaired.
  bool check = true;
  Soup_repair_options repair_options = {}; ///< what the repair may change
  /// Off: a soup build_mesh() refuses gives a report with built == false
  /// (and soup saying why) and leaves g empty, instead of throwing.
  bool throw_on_refusal = true;
};

/// What build_mesh() did.
struct Build_report {
  Soup_repair_report repair; ///< what the repair changed (empty when none was needed or asked)
  bool repaired = false;     ///< the soup failed check_soup() and a repaired copy was built
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t border_halfedges = 0;
  std::size_t zero_area_faces = 0; ///< warnings from check_soup() (built anyway)
  Soup_report soup;  ///< check_soup() of the input (empty with .check off)
  bool built = true; ///< false only when refused with .throw_on_refusal off
};

namespace detail {

inline std::string refusal(const Soup_report& r) {
  return "build_mesh: the polygon soup cannot become a halfedge mesh (build with {.repair = true} to fix "
         "it):\n" + to_string(r);
}

/// A backend that cannot be built with the MutableFaceGraph primitives (the
/// incidence mesh stores no next/prev), or that has a faster bulk builder,
/// provides genmesh_native_link_soup(s, twin, border_out, ne, g, corner_edge),
/// found by argument-dependent lookup, with link_soup()'s contract below
/// (same vertex, edge, face order; same edge directions; same corner_edge).
template <class G>
concept Has_native_link_soup =
    requires(const Polygon_soup& s, const std::vector<std::uint32_t>& v, std::size_t n, G& g,
             std::vector<std::uint32_t>* ce) {
      { genmesh_native_link_soup(s, v, v, n, g, ce) } -> std::convertible_to<std::size_t>;
    };

/// What build_mesh() and the subdivision schemes can build into.
template <class G>
concept Soup_buildable = (MutableFaceGraph<G> || Has_native_link_soup<G>) && HasVertexPoints<G>;

/// Builds the empty g from soup s whose corners are already paired — the
/// linking half of build_mesh(), shared with the subdivision schemes, which
/// pair corners from their refinement pattern. twin[c] is the corner running
/// along c's edge the other way (k_null on the border); border_out[v] is the
/// border corner ending at v (whose opposite halfedge leaves v); ne is the
/// number of edges. Edges are created corner by corner at their first use,
/// halfedge(f) targets f's first corner, halfedge(v) is v's incoming border
/// halfedge on the border and its first incoming halfedge otherwise.
/// corner_edge, if given, receives each corner's edge number in creation
/// order. Never throws but for allocation. Returns the number of border
/// halfedges.
template <class G>
  requires Soup_buildable<G>
std::size_t link_soup(const Polygon_soup& s, const std::vector<std::uint32_t>& twin,
                      const std::vector<std::uint32_t>& border_out, std::size_t ne, G& g,
                      std::vector<std::uint32_t>* corner_edge = nullptr) {
  if constexpr (Has_native_link_soup<G>) {
    return genmesh_native_link_soup(s, twin, border_out, ne, g, corner_edge);
  } else {
  using H = halfedge_descriptor_t<G>;
  using V = vertex_descriptor_t<G>;
  using Traits = boost::graph_traits<G>;
  const std::size_t np = s.num_points(), nf = s.num_faces(), nc = s.indices.size();
  reserve(g, static_cast<typename Traits::vertices_size_type>(np),
          static_cast<typename Traits::edges_size_type>(ne), static_cast<typename Traits::faces_size_type>(nf));

  auto points = get(vertex_point, g);
  std::vector<V> vs(np);
  for (std::size_t i = 0; i < np; ++i) {
    vs[i] = add_vertex(g);
    put(points, vs[i], from_eigen<point_t<G>>(s.points[i]));
  }

  // Halfedge of each corner c: from c's vertex to the next corner's.
  std::vector<H> hc(nc, Traits::null_halfedge());
  if (corner_edge) corner_edge->assign(nc, k_null);
  std::uint32_t edge_number = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t first = s.offsets[f], last = s.offsets[f + 1] - 1;
    for (std::uint32_t c = first; c <= last; ++c) {
      if (hc[c] != Traits::null_halfedge()) continue; // made with its twin
      H h = halfedge(add_edge(g), g);
      H o = opposite(h, g);
      set_target(h, vs[s.indices[c == last ? first : c + 1]], g);
      set_target(o, vs[s.indices[c]], g);
      hc[c] = h;
      if (twin[c] != k_null) hc[twin[c]] = o;
      else set_face(o, Traits::null_face(), g);
      if (corner_edge) {
        (*corner_edge)[c] = edge_number;
        if (twin[c] != k_null) (*corner_edge)[twin[c]] = edge_number;
      }
      ++edge_number;
    }
  }

  // Faces, their cycles, and halfedge(v) = the first incoming halfedge.
  std::vector<char> vertex_set(np, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto fd = add_face(g);
    const std::uint32_t first = s.offsets[f], last = s.offsets[f + 1] - 1;
    for (std::uint32_t c = first; c <= last; ++c) {
      set_face(hc[c], fd, g);
      set_next(hc[c], hc[c == last ? first : c + 1], g);
      const std::uint32_t to = s.indices[c == last ? first : c + 1];
      if (!vertex_set[to]) {
        vertex_set[to] = 1;
        set_halfedge(vs[to], hc[c], g);
      }
    }
    set_halfedge(fd, hc[last], g); // targets the first corner
  }

  // Border cycles; a border vertex's halfedge becomes its incoming border halfedge.
  std::size_t border_halfedges = 0;
  for (std::uint32_t c = 0; c < nc; ++c)
    if (twin[c] == k_null) {
      H b = opposite(hc[c], g); // from c's next corner to c's vertex v
      const std::uint32_t v = s.indices[c];
      set_next(b, opposite(hc[border_out[v]], g), g);
      set_halfedge(vs[v], b, g);
      ++border_halfedges;
    }
  return border_halfedges;
  }
}

} // namespace detail

/// Builds g, which must be empty, from soup; see the header comment for the
/// guarantees. Throws genmesh::invalid_input when g is not empty, or when the
/// soup fails check_soup() and repair is off (what() lists the problems), or
/// when the repair could not fix everything (a Möbius strip, a NaN point).
template <class G>
  requires detail::Soup_buildable<G>
Build_report build_mesh(const Polygon_soup& soup, G& g, const Build_options& options = {}) {
  using namespace detail;

  if (num_vertices(g) != 0 || num_faces(g) != 0 || num_halfedges(g) != 0)
    throw invalid_input("build_mesh: the target mesh is not empty (" + std::to_string(num_vertices(g)) +
                        " vertices, " + std::to_string(num_faces(g)) + " faces)");

  // One edge table serves the check and the pairing of corners, and is
  // freed before the mesh is allocated.
  Build_report report;
  Polygon_soup repaired;
  const Polygon_soup* in = &soup;
  Soup_edges e = soup_edges(soup);
  if (options.check) {
    report.soup = check_soup(soup, e);
    report.zero_area_faces = report.soup.zero_area_faces;
    if (!report.soup.ok()) {
      if (!options.repair) {
        if (!options.throw_on_refusal) {
          report.built = false;
          return report;
        }
        throw invalid_input(refusal(report.soup));
      }
      e = Soup_edges{};
      repaired = soup;
      report.repair = repair_soup(repaired, options.repair_options);
      report.repaired = true;
      if (!report.repair.ok())
        throw invalid_input("build_mesh: the repair could not fix the polygon soup:\n" + to_string(report.repair));
      report.zero_area_faces = report.repair.after.zero_area_faces;
      in = &repaired;
      e = soup_edges(repaired);
    }
  }
  const Polygon_soup& s = *in;
  const std::size_t np = s.num_points(), nf = s.num_faces(), nc = s.indices.size();

  // Pair every corner (directed edge corner → next corner) with its twin.
  // Soup_edges groups them by undirected edge; on a checked soup a group has
  // one or two members.
  std::vector<std::uint32_t> twin(nc, k_null);
  std::size_t ne = 0;
  for (std::size_t gi = 0; gi + 1 < e.group_begin.size(); ++gi) {
    std::uint32_t b = e.group_begin[gi], end = e.group_begin[gi + 1];
    ++ne;
    if (end - b == 2) {
      if (e.halves[b].forward == e.halves[b + 1].forward) throw invalid_input(refusal(check_soup(s)));
      twin[e.halves[b].corner] = e.halves[b + 1].corner;
      twin[e.halves[b + 1].corner] = e.halves[b].corner;
    } else if (end - b > 2) {
      throw invalid_input(refusal(check_soup(s)));
    }
  }
  std::vector<char> usable = std::move(e.usable);
  e = Soup_edges{};

  // The border halfedge into vertex v continues with the border halfedge out
  // of v; the one out of v is the twin of the border corner ending at v
  // (unique unless several border gaps meet at v: a bow-tie).
  std::vector<std::uint32_t> border_out(np, k_null); // border corner whose twin leaves v
  for (std::size_t f = 0; f < nf; ++f) {
    if (!usable[f]) throw invalid_input(refusal(check_soup(s)));
    for (std::uint32_t c = s.offsets[f]; c < s.offsets[f + 1]; ++c) {
      if (twin[c] != k_null) continue;
      std::uint32_t v = s.indices[next_corner(s, static_cast<std::uint32_t>(f), c)];
      if (border_out[v] != k_null) throw invalid_input(refusal(check_soup(s)));
      border_out[v] = c;
    }
  }

  usable = {};

  // Nothing below throws (but for allocation): g is built whole or not at all.
  report.border_halfedges = link_soup(s, twin, border_out, ne, g);

  report.vertices = np;
  report.edges = ne;
  report.faces = nf;
  return report;
}

namespace detail {

/// g read as a soup without copying it: vertices numbered 0..n-1 in
/// iteration order, faces in iteration order, each face's corners rotated to
/// start at its lowest number. What to_soup() and the mesh writers
/// (write_mesh() in <genmesh/io.h>) share; it holds only the numbering (one
/// integer per vertex index), g must outlive it and stay unchanged.
template <class G>
  requires FaceListGraph<G> && VertexListGraph<G> && HasVertexPoints<G>
class Soup_view {
  using V = vertex_descriptor_t<G>;
  using H = halfedge_descriptor_t<G>;

 public:
  using Index = Polygon_soup::Index;

  /// `channels`: per-vertex attribute channels in vertices(g) order, written
  /// with the mesh (they must outlive the view).
  explicit Soup_view(const G& g, std::span<const Soup_attribute> channels = {})
      // HasVertexPoints promises get() on a non-const graph only; the map is only read.
      : g_(g), points_(get(vertex_point, const_cast<G&>(g))), channels_(channels) {
    if constexpr (HasIndexMap<G, vertex_index_t>) number_.assign(index_bound(vertex_index, g), k_null);
    for (V v : vertices(g)) {
      const auto n = static_cast<std::uint32_t>(num_points_++);
      if constexpr (HasIndexMap<G, vertex_index_t>) number_[vindex(v)] = n;
      else numbers_.emplace(v, n);
    }
    // Counted, not num_faces(g): on CGAL::Surface_mesh that is the index
    // bound, removed faces included.
    for ([[maybe_unused]] auto f : faces(g)) ++num_faces_;
  }

  std::size_t num_points() const noexcept { return num_points_; }
  std::size_t num_faces() const noexcept { return num_faces_; }
  /// The channels given to the constructor (none by default: a mesh's
  /// attributes are its property maps; make_soup_attribute() makes channels
  /// of them).
  std::span<const Soup_attribute> vertex_attributes() const noexcept { return channels_; }

  /// f(number, point) for every vertex, in number order.
  template <class F>
  void for_each_point(F&& f) const {
    std::size_t n = 0;
    for (V v : vertices(g_)) f(n++, to_eigen(get(points_, v)));
  }

  /// f(number, corners, corner points) for every face, in iteration order;
  /// corner points is empty unless WithPoints. Throws genmesh::invalid_input
  /// when a face cycle does not close (a corrupt mesh).
  template <bool WithPoints = false, class F>
  void for_each_face(F&& f) const {
    const std::size_t max_len = static_cast<std::size_t>(num_halfedges(g_));
    std::vector<Index> c;
    std::vector<Eigen::Vector3d> p;
    std::size_t fnum = 0;
    for (auto fd : faces(g_)) {
      c.clear();
      p.clear();
      const H h0 = halfedge(fd, g_);
      H h = h0;
      do {
        const V t = target(h, g_);
        const std::uint32_t v = number(t);
        if (v == k_null || c.size() > max_len)
          throw invalid_input("to_soup: the cycle of face " + std::to_string(fnum) + " is corrupt");
        c.push_back(v);
        if constexpr (WithPoints) p.push_back(to_eigen(get(points_, t)));
        h = next(h, g_);
      } while (h != h0);
      const auto first = std::min_element(c.begin(), c.end()) - c.begin();
      std::rotate(c.begin(), c.begin() + first, c.end());
      if constexpr (WithPoints) std::rotate(p.begin(), p.begin() + first, p.end());
      f(fnum, std::span<const Index>(c), std::span<const Eigen::Vector3d>(p));
      ++fnum;
    }
  }

 private:
  std::size_t vindex(V v) const {
    if constexpr (HasIndexMap<G, vertex_index_t>) return static_cast<std::size_t>(get(get(vertex_index, g_), v));
    else return 0;
  }
  std::uint32_t number(V v) const {
    if constexpr (HasIndexMap<G, vertex_index_t>) {
      const std::size_t i = vindex(v);
      return i < number_.size() ? number_[i] : k_null;
    } else {
      const auto it = numbers_.find(v);
      return it == numbers_.end() ? k_null : it->second;
    }
  }

  const G& g_;
  decltype(get(vertex_point, std::declval<G&>())) points_;
  std::span<const Soup_attribute> channels_;
  std::size_t num_points_ = 0;
  std::size_t num_faces_ = 0;
  std::vector<std::uint32_t> number_;           // by vertex index (graphs with an index map)
  std::unordered_map<V, std::uint32_t> numbers_; // otherwise
};

} // namespace detail

/// The soup of g: vertices in vertex iteration order (isolated ones
/// included), faces in face iteration order, each face rotated to start at
/// its lowest-numbered vertex. Throws genmesh::invalid_input when a face cycle
/// does not close (a corrupt mesh).
template <class G>
  requires FaceListGraph<G> && VertexListGraph<G> && HasVertexPoints<G>
Polygon_soup to_soup(const G& g) {
  const detail::Soup_view<G> view(g);
  Polygon_soup s;
  s.points.reserve(view.num_points());
  view.for_each_point([&](std::size_t, const Eigen::Vector3d& p) { s.points.push_back(p); });
  s.indices.reserve(3 * view.num_faces());
  s.offsets.reserve(view.num_faces() + 1);
  view.for_each_face([&](std::size_t, std::span<const Polygon_soup::Index> c, auto) { s.add_face(c); });
  return s;
}

/// Puts soup channel `a` into the vertex property map `map` of g, a mesh
/// built from that soup (build_mesh: point i is the i-th vertex of
/// vertices(g)): the i-th vertex gets point i's values. The map's value type
/// is any genmesh::Attribute_value (double, Eigen vector, std::array,
/// std::vector, point type). Throws genmesh::invalid_input when g's vertex
/// count is not the number of points `a` holds values for, or when the
/// value type cannot hold a.width() values.
template <class G, class Map>
  requires VertexListGraph<G> && Attribute_value<typename boost::property_traits<Map>::value_type>
void read_vertex_attribute(const Soup_attribute& a, const G& g, Map map) {
  using T = typename boost::property_traits<Map>::value_type;
  const std::size_t w = a.width();
  std::size_t n = 0;
  for ([[maybe_unused]] auto v : vertices(g)) ++n;
  if (w == 0 || a.values.size() != n * w)
    throw invalid_input("read_vertex_attribute: attribute '" + a.name + "' holds " + std::to_string(a.values.size()) +
                        " values, not " + std::to_string(w) + " for each of the mesh's " + std::to_string(n) +
                        " vertices");
  std::size_t i = 0;
  for (auto v : vertices(g)) {
    T x = get(map, v);
    if (!Attribute_traits<T>::assign(x, a.values.data() + i * w, w))
      throw invalid_input("read_vertex_attribute: attribute '" + a.name + "' has " + std::to_string(w) +
                          " values per vertex, more or fewer than the map's value type holds");
    put(map, v, x);
    ++i;
  }
}

/// A channel named `name` holding map's values for g's vertices in
/// iteration order (to_soup(g)'s point numbering), to be stored as `type`.
/// `components` names each value (PLY property names); empty: "red green
/// blue [alpha]" for "color", "nx ny nz" for "normal", "u v" for
/// "texcoord", the name itself for one value, else name_0, name_1, ...
/// Throws genmesh::invalid_input when the vertices' values differ in width,
/// or `components` has another size than that width.
template <class G, class Map>
  requires VertexListGraph<G> && Attribute_value<typename boost::property_traits<Map>::value_type>
Soup_attribute make_soup_attribute(const G& g, Map map, std::string name, std::vector<std::string> components = {},
                                   Scalar_type type = Scalar_type::float64) {
  using T = typename boost::property_traits<Map>::value_type;
  using Traits = Attribute_traits<T>;
  Soup_attribute a;
  a.name = std::move(name);
  a.type = type;
  std::size_t w = 0, n = 0;
  for (auto v : vertices(g)) {
    const T& x = get(map, v);
    const std::size_t k = Traits::width(x);
    if (n == 0) w = k;
    if (k != w || k == 0)
      throw invalid_input("make_soup_attribute: attribute '" + a.name + "' has " + std::to_string(k) +
                          " values at vertex number " + std::to_string(n) + " but " + std::to_string(w) +
                          " at the first");
    for (std::size_t j = 0; j < k; ++j) a.values.push_back(Traits::get(x, j));
    ++n;
  }
  if (components.empty()) {
    static const std::vector<std::string> colour{"red", "green", "blue", "alpha"}, normal{"nx", "ny", "nz"},
        uv{"u", "v"};
    if (a.name == "color" && (w == 3 || w == 4)) components.assign(colour.begin(), colour.begin() + w);
    else if (a.name == "normal" && w == 3) components = normal;
    else if (a.name == "texcoord" && w == 2) components = uv;
    else if (w == 1) components = {a.name};
    else
      for (std::size_t j = 0; j < w; ++j) components.push_back(a.name + "_" + std::to_string(j));
  }
  if (n > 0 && components.size() != w)
    throw invalid_input("make_soup_attribute: attribute '" + a.name + "' has " + std::to_string(w) +
                        " values per vertex but " + std::to_string(components.size()) + " component names");
  a.components = std::move(components);
  return a;
}

/// soup with every face rotated to start at its lowest corner (orientation kept).
inline Polygon_soup rotate_faces_to_lowest(Polygon_soup soup) {
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto c = soup.face(f);
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  }
  return soup;
}

/// soup with faces rotated to start at their lowest corner and sorted
/// lexicographically; points (and their attributes) untouched. Two meshes with equal canonical soups
/// have the same points, the same faces and the same orientations.
inline Polygon_soup canonical(Polygon_soup soup) {
  soup = rotate_faces_to_lowest(std::move(soup));
  std::vector<std::size_t> order(soup.num_faces());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    auto x = soup.face(a), y = soup.face(b);
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
  });
  Polygon_soup out;
  out.points = std::move(soup.points);
  out.vertex_attributes = std::move(soup.vertex_attributes);
  out.indices.reserve(soup.indices.size());
  out.offsets.reserve(soup.offsets.size());
  for (auto f : order) out.add_face(soup.face(f));
  return out;
}

} // namespace genmesh
