// genmesh/subdivision/detail/refinement.h — shared machinery of the
// subdivision schemes: a read-only snapshot of the old mesh, the checks, and
// the rebuild of the refined mesh from a polygon soup.
//
// The snapshot numbers vertices in vertex iteration order, edges in edge
// iteration order and faces in face iteration order, and stores every face as
// a cycle of corners (corner c of a face = the halfedge leaving its vertex),
// each face rotated to start at its lowest vertex number, so every scheme that
// reads only the snapshot gives the same soup on every backend.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/exceptions.h>
#include <genmesh/point_traits.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/property_maps.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision/types.h>
#include <genmesh/visitor.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

namespace detail::subdivision {

inline constexpr std::uint32_t k_none = 0xffffffffu;

/// The vertex point map an option names, or g's own (Default_map).
template <class G, class Pm>
auto point_map_of(G& g, const Pm& pm) {
  if constexpr (std::is_same_v<Pm, Default_map>) return get(vertex_point, g);
  else return pm;
}

/// The point type of a vertex point map.
template <class Pm>
using map_point_t = std::remove_cvref_t<typename boost::property_traits<Pm>::value_type>;

/// The old mesh, read once: points, face cycles as corners, twins, edges.
struct Snapshot {
  std::vector<Eigen::Vector3d> points;  ///< per vertex
  std::vector<std::uint32_t> face_begin{0}; ///< CSR: face f's corners are [face_begin[f], face_begin[f+1])
  std::vector<std::uint32_t> corner_vertex; ///< source vertex of the corner's halfedge
  std::vector<std::uint32_t> corner_face;
  std::vector<std::uint32_t> corner_twin;   ///< corner of the opposite halfedge, k_none on the border
  std::vector<std::uint32_t> corner_edge;
  std::vector<std::uint32_t> edge_corner;   ///< a corner of each edge (the one of halfedge(e) when it has a face)
  std::vector<std::uint32_t> vertex_corner; ///< an outgoing corner per vertex (a border one when there is), or k_none
  std::vector<std::uint32_t> border_edges;  ///< per vertex: number of border edges at it
  std::vector<std::uint32_t> valence;       ///< per vertex: number of edges at it

  std::size_t num_vertices() const { return points.size(); }
  std::size_t num_faces() const { return face_begin.size() - 1; }
  std::size_t num_edges() const { return edge_corner.size(); }
  std::uint32_t face_size(std::uint32_t f) const { return face_begin[f + 1] - face_begin[f]; }
  std::uint32_t next(std::uint32_t c) const {
    std::uint32_t f = corner_face[c];
    return c + 1 == face_begin[f + 1] ? face_begin[f] : c + 1;
  }
  std::uint32_t prev(std::uint32_t c) const {
    std::uint32_t f = corner_face[c];
    return c == face_begin[f] ? face_begin[f + 1] - 1 : c - 1;
  }
  /// Numbers the next edge: corner c and its twin o (k_none on the border);
  /// counts it in the valences and border-edge counts of its ends.
  void add_edge(std::uint32_t c, std::uint32_t o) {
    const auto en = static_cast<std::uint32_t>(edge_corner.size());
    edge_corner.push_back(c);
    corner_edge[c] = en;
    if (o != k_none) corner_edge[o] = en;
    const std::uint32_t a = corner_vertex[c], b = head(c);
    ++valence[a];
    ++valence[b];
    if (o == k_none) {
      ++border_edges[a];
      ++border_edges[b];
    }
  }
  /// Target vertex of corner c's halfedge.
  std::uint32_t head(std::uint32_t c) const { return corner_vertex[next(c)]; }
  bool is_border_edge(std::uint32_t e) const { return corner_twin[edge_corner[e]] == k_none; }
  /// A vertex on the border, or where the halfedge structure is not a single fan.
  bool is_border_vertex(std::uint32_t v) const { return border_edges[v] != 0 || vertex_corner[v] == k_none; }
  /// The outgoing corner after c counter-clockwise around its vertex, k_none past the border.
  std::uint32_t rotate_ccw(std::uint32_t c) const { return corner_twin[prev(c)]; }
  /// The two border neighbours of a border vertex with exactly two border edges
  /// (the one after it along the border, the one before it).
  std::pair<std::uint32_t, std::uint32_t> border_neighbours(std::uint32_t v) const {
    // vertex_corner[v] leaves v along a border edge (v → a); the walk ccw
    // ends at the corner whose prev comes into v along the other border edge.
    std::uint32_t c = vertex_corner[v], a = head(c);
    std::uint32_t last = c;
    for (std::size_t guard = 0; guard <= valence[v]; ++guard) {
      std::uint32_t n = rotate_ccw(last);
      if (n == k_none) break;
      last = n;
    }
    return {a, corner_vertex[prev(last)]};
  }
};

/// An outgoing corner per vertex; on the border the one along the border
/// edge (its ccw walk covers the whole fan). A vertex with more than one
/// border gap gets none: schemes treat it as a corner.
inline void set_vertex_corners(Snapshot& s) {
  for (std::size_t c = 0; c < s.corner_vertex.size(); ++c) {
    std::uint32_t v = s.corner_vertex[c];
    if (s.border_edges[v] == 0) {
      if (s.vertex_corner[v] == k_none) s.vertex_corner[v] = static_cast<std::uint32_t>(c);
    } else if (s.corner_twin[c] == k_none && s.border_edges[v] == 2) {
      s.vertex_corner[v] = static_cast<std::uint32_t>(c);
    }
  }
}

/// Reads g into a snapshot. Throws genmesh::invalid_input naming the face
/// when max_face_size is set and a face has another size than it (Loop, √3,
/// butterfly take triangles only), or when a face cycle is corrupt; g is
/// never touched.
template <class G, class Pm = Default_map>
Snapshot snapshot(G& g, const char* scheme, std::uint32_t required_face_size = 0, const Pm& pm = {}) {
  using H = halfedge_descriptor_t<G>;
  Snapshot s;
  auto pts = point_map_of(g, pm);
  auto vindex = get(vertex_index, g);
  auto hindex = get(halfedge_index, g);
  std::vector<std::uint32_t> vnum(index_bound(vertex_index, g), k_none);
  std::vector<std::uint32_t> hcorner(index_bound(halfedge_index, g), k_none);
  s.points.reserve(static_cast<std::size_t>(num_vertices(g)));
  for (auto v : vertices(g)) {
    vnum[static_cast<std::size_t>(get(vindex, v))] = static_cast<std::uint32_t>(s.points.size());
    s.points.push_back(to_eigen(get(pts, v)));
  }
  const std::size_t nv = s.points.size();
  const std::size_t nh = static_cast<std::size_t>(num_halfedges(g));
  s.corner_vertex.reserve(nh);
  s.corner_face.reserve(nh);
  s.face_begin.reserve(static_cast<std::size_t>(num_faces(g)) + 1);
  std::vector<H> cycle;
  std::vector<H> corner_h;
  corner_h.reserve(nh);
  std::uint32_t fnum = 0;
  for (auto f : faces(g)) {
    cycle.clear();
    H h0 = halfedge(f, g), h = h0;
    do {
      if (cycle.size() > nh) throw invalid_input(std::string(scheme) + ": the cycle of face " + std::to_string(fnum) + " is corrupt");
      cycle.push_back(h);
      h = next(h, g);
    } while (h != h0);
    if (required_face_size != 0 && cycle.size() != required_face_size)
      throw invalid_input(std::string(scheme) + ": face " + std::to_string(fnum) + " has " +
                          std::to_string(cycle.size()) + " sides; the scheme takes only " +
                          std::to_string(required_face_size) + "-sided faces (the mesh is unchanged)");
    // corner = halfedge leaving its vertex: source(h) = target(prev(h))
    auto src = [&](H x) { return vnum[static_cast<std::size_t>(get(vindex, source(x, g)))]; };
    auto lowest = std::min_element(cycle.begin(), cycle.end(), [&](H a, H b) { return src(a) < src(b); });
    std::rotate(cycle.begin(), lowest, cycle.end());
    for (H x : cycle) {
      hcorner[static_cast<std::size_t>(get(hindex, x))] = static_cast<std::uint32_t>(s.corner_vertex.size());
      s.corner_vertex.push_back(src(x));
      s.corner_face.push_back(fnum);
      corner_h.push_back(x);
    }
    s.face_begin.push_back(static_cast<std::uint32_t>(s.corner_vertex.size()));
    ++fnum;
  }
  const std::size_t nc = s.corner_vertex.size();
  s.corner_twin.assign(nc, k_none);
  s.corner_edge.assign(nc, k_none);
  for (std::size_t c = 0; c < nc; ++c)
    s.corner_twin[c] = hcorner[static_cast<std::size_t>(get(hindex, opposite(corner_h[c], g)))];
  s.edge_corner.reserve(static_cast<std::size_t>(num_edges(g)));
  s.border_edges.assign(nv, 0);
  s.valence.assign(nv, 0);
  s.vertex_corner.assign(nv, k_none);
  for (auto e : edges(g)) {
    H h = halfedge(e, g);
    std::uint32_t c = hcorner[static_cast<std::size_t>(get(hindex, h))];
    std::uint32_t o = hcorner[static_cast<std::size_t>(get(hindex, opposite(h, g)))];
    if (c == k_none) std::swap(c, o);
    if (c == k_none) throw invalid_input(std::string(scheme) + ": an edge has no face on either side");
    s.add_edge(c, o);
  }
  set_vertex_corners(s);
  return s;
}

/// The vertex each corner's halfedge goes to (the next corner's vertex).
inline std::vector<std::uint32_t> corner_heads(const Polygon_soup& s) {
  std::vector<std::uint32_t> head(s.indices.size());
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    const std::uint32_t b = s.offsets[f], e = s.offsets[f + 1];
    for (std::uint32_t c = b; c + 1 < e; ++c) head[c] = s.indices[c + 1];
    head[e - 1] = s.indices[b];
  }
  return head;
}

/// Pairs the corners of a refined soup through per-vertex buckets (linear time).
inline std::vector<std::uint32_t> pair_corners(const Polygon_soup& s) {
  const std::size_t np = s.num_points(), nc = s.indices.size();
  const std::vector<std::uint32_t> head = corner_heads(s);
  std::vector<std::uint32_t> begin(np + 1, 0), bucket(nc);
  for (std::size_t c = 0; c < nc; ++c) ++begin[s.indices[c] + 1];
  for (std::size_t v = 0; v < np; ++v) begin[v + 1] += begin[v];
  {
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (std::size_t c = 0; c < nc; ++c) bucket[fill[s.indices[c]]++] = static_cast<std::uint32_t>(c);
  }
  std::vector<std::uint32_t> twin(nc, k_none);
  std::vector<char> done(nc, 0);
  for (std::size_t c = 0; c < nc; ++c) {
    if (done[c]) continue;
    const std::uint32_t u = s.indices[c], v = head[c];
    for (std::uint32_t i = begin[v]; i < begin[v + 1]; ++i)
      if (head[bucket[i]] == u) {
        twin[c] = bucket[i];
        twin[bucket[i]] = static_cast<std::uint32_t>(c);
        done[bucket[i]] = 1;
        break;
      }
  }
  return twin;
}

/// Builds the empty g from a refined soup that is an oriented 2-manifold by
/// construction (every scheme's output is), with the same structure
/// genmesh::build_mesh gives (same vertex, edge, face and halfedge order), but
/// without checking and sorting: the refined meshes are large, and building
/// them is most of a level's time. `known_twin`, when not empty, gives each
/// corner's twin corner (k_none on the border) as the scheme knows it from the
/// refinement pattern; otherwise corners are paired through per-vertex
/// buckets in linear time.
template <class G>
void build_refined(const Polygon_soup& s, G& g, std::vector<std::uint32_t> known_twin = {}) {
  const std::size_t np = s.num_points(), nc = s.indices.size();
  const std::vector<std::uint32_t> head = corner_heads(s);
  std::vector<std::uint32_t> twin = std::move(known_twin), border_out(np, k_none);
  std::size_t ne = 0;
  if (twin.empty()) twin = pair_corners(s);
  for (std::size_t c = 0; c < nc; ++c) {
    if (twin[c] == k_none) {
      ++ne;
      border_out[head[c]] = static_cast<std::uint32_t>(c);
    } else if (twin[c] > c) {
      ++ne;
    }
  }
  genmesh::detail::link_soup(s, twin, border_out, ne, g, nullptr);
}

/// The snapshot of the mesh build_refined(soup, g, twin) would make, taken
/// from the soup directly (same numbering as snapshot(g) of that mesh), so
/// that the levels of one call between the first and the last never build a
/// mesh.
inline Snapshot snapshot_of_soup(Polygon_soup&& soup, const std::vector<std::uint32_t>& twin) {
  Snapshot s;
  const std::size_t nv = soup.num_points(), nf = soup.num_faces(), nc = soup.indices.size();
  s.points = std::move(soup.points);
  s.face_begin.assign(soup.offsets.begin(), soup.offsets.end());
  s.corner_vertex.resize(nc);
  s.corner_face.resize(nc);
  std::vector<std::uint32_t> remap(nc);
  for (std::uint32_t f = 0; f < nf; ++f) {
    const std::uint32_t b = soup.offsets[f], n = soup.offsets[f + 1] - b;
    std::uint32_t r = 0;
    for (std::uint32_t k = 1; k < n; ++k)
      if (soup.indices[b + k] < soup.indices[b + r]) r = k;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t to = b + (k + n - r) % n;
      remap[b + k] = to;
      s.corner_vertex[to] = soup.indices[b + k];
      s.corner_face[to] = f;
    }
  }
  s.corner_twin.assign(nc, k_none);
  for (std::size_t c = 0; c < nc; ++c)
    if (twin[c] != k_none) s.corner_twin[remap[c]] = remap[twin[c]];
  // edges in build_refined's creation order: first use, corner by corner
  s.corner_edge.assign(nc, k_none);
  s.border_edges.assign(nv, 0);
  s.valence.assign(nv, 0);
  s.vertex_corner.assign(nv, k_none);
  for (std::size_t c = 0; c < nc; ++c) {
    const std::uint32_t rc = remap[c];
    if (s.corner_edge[rc] == k_none) s.add_edge(rc, s.corner_twin[rc]);
  }
  set_vertex_corners(s);
  return s;
}

/// Replaces g by the mesh of soup (built into a fresh G, then moved into g),
/// and records the counts.
template <class G, class Pm = Default_map>
void rebuild(G& g, const Polygon_soup& soup, Subdivision_result& r, std::vector<std::uint32_t> twin = {},
             const Pm& pm = {}) {
  G fresh;
  build_refined(soup, fresh, std::move(twin));
  g = std::move(fresh);
  if constexpr (!std::is_same_v<Pm, Default_map>) { // the caller's map gets the positions too
    Pm out = pm;
    std::size_t k = 0;
    for (auto v : vertices(g)) put(out, v, from_eigen<map_point_t<Pm>>(soup.points[k++]));
  }
  ++r.levels_done;
  r.vertices = soup.num_points();
  r.faces = soup.num_faces();
}

/// Creases at the vertices (DeRose, Kass, Truong 1998): per vertex the number
/// of incident crease edges (sharpness > 0, border edges not counted), the sum
/// of their sharpness and of their other ends.
struct Crease_stars {
  std::vector<std::uint32_t> count;
  std::vector<double> sharpness;
  std::vector<Eigen::Vector3d> ends;
};

inline Crease_stars crease_stars(const Snapshot& s, const std::vector<double>& sharp) {
  Crease_stars cs{std::vector<std::uint32_t>(s.num_vertices(), 0), std::vector<double>(s.num_vertices(), 0.0),
                  std::vector<Eigen::Vector3d>(s.num_vertices(), Eigen::Vector3d::Zero())};
  for (std::uint32_t e = 0; e < s.num_edges(); ++e) {
    if (sharp[e] <= 0 || s.is_border_edge(e)) continue;
    const std::uint32_t c = s.edge_corner[e], a = s.corner_vertex[c], b = s.head(c);
    ++cs.count[a], ++cs.count[b];
    cs.sharpness[a] += sharp[e], cs.sharpness[b] += sharp[e];
    cs.ends[a] += s.points[b], cs.ends[b] += s.points[a];
  }
  return cs;
}

/// A refined level: its faces (and new points), and each corner's twin
/// (empty: found by pair_corners).
struct Refined {
  Polygon_soup soup;
  std::vector<std::uint32_t> twin;
};

/// Runs `iterations` levels on g: snapshot g once (refusing faces of another
/// size than face_size, if not 0, before anything changes), then
/// level(snapshot, i) → Refined per level; the levels before the last go from
/// soup to snapshot directly, the last one rebuilds g (through
/// genmesh::detail::link_soup: the backend's native genmesh_native_link_soup
/// where it has one, its own MutableFaceGraph functions otherwise).
template <class G, class Level, class V, class Pm = Default_map>
Subdivision_result run_levels(G& g, int iterations, const char* scheme, std::uint32_t face_size, Level level, V& vis,
                              const Pm& pm = {}) {
  if (iterations < 0) throw invalid_input(std::string(scheme) + ": iterations must be ≥ 0");
  // live counts by iteration: num_* may count removed elements (Surface_mesh)
  std::size_t nv = 0, nf = 0;
  for (auto v : vertices(g)) (void)v, ++nv;
  for (auto f : faces(g)) (void)f, ++nf;
  Subdivision_result r{0, nv, nf};
  if (iterations > 0) {
    Snapshot s = snapshot(g, scheme, face_size, pm);
    for (int i = 0; i < iterations; ++i) {
      vis.on_step("level", static_cast<std::size_t>(i), static_cast<std::size_t>(iterations));
      Refined out = level(s, i);
      if (i + 1 < iterations) {
        if (out.twin.empty()) out.twin = pair_corners(out.soup);
        Snapshot next = snapshot_of_soup(std::move(out.soup), out.twin);
        ++r.levels_done;
        r.vertices = next.num_vertices();
        r.faces = next.num_faces();
        s = std::move(next);
      } else {
        rebuild(g, out.soup, r, std::move(out.twin), pm);
      }
    }
    vis.on_step("level", static_cast<std::size_t>(iterations), static_cast<std::size_t>(iterations));
  }
  return r;
}

/// Writes limit positions into g after the last level: limit(s, v) for every
/// vertex of s (= snapshot(g)), through g's point map in vertex order.
template <class G, class Limit, class Pm = Default_map>
void move_to_limit(G& g, const std::vector<double>& sharp, Limit limit, const Pm& pm = {}) {
  Snapshot s = snapshot(g, "limit positions", 0, pm);
  const Crease_stars cs = sharp.empty() ? Crease_stars{} : crease_stars(s, sharp);
  auto pts = point_map_of(g, pm);
  std::uint32_t v = 0;
  for (auto vd : vertices(g)) {
    Eigen::Vector3d p;
    if (!sharp.empty() && !s.is_border_vertex(v) && cs.count[v] >= 2)
      p = cs.count[v] == 2 ? Eigen::Vector3d((cs.ends[v] + 4.0 * s.points[v]) / 6.0) : s.points[v];
    else
      p = limit(s, v);
    put(pts, vd, from_eigen<map_point_t<decltype(pts)>>(p));
    ++v;
  }
}

/// The limit position of a border vertex: the cubic B-spline limit
/// (p + 4v + q)/6 for Boundary_rule::smooth, v for fixed or a corner.
inline Eigen::Vector3d border_limit_point(const Snapshot& s, std::uint32_t v, Boundary_rule rule) {
  if (rule == Boundary_rule::fixed || s.border_edges[v] != 2 || s.vertex_corner[v] == k_none) return s.points[v];
  auto [a, b] = s.border_neighbours(v);
  return (s.points[a] + 4.0 * s.points[v] + s.points[b]) / 6.0;
}

template <class G>
concept Subdividable = genmesh::detail::Soup_buildable<G> && FaceListGraph<G> && VertexListGraph<G> && EdgeListGraph<G> &&
                       HasVertexPoints<G> && HasIndexMap<G, vertex_index_t> && HasIndexMap<G, halfedge_index_t> &&
                       std::default_initializable<G> && std::movable<G>;

} // namespace detail::subdivision
} // namespace genmesh
