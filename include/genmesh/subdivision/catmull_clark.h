// genmesh/subdivision/catmull_clark.h — Catmull-Clark subdivision of polygon meshes.
//
// Each level splits every n-gon into n quads (face point, edge points, old
// vertex) with the masks of E. Catmull and J. Clark, "Recursively generated
// B-spline surfaces on arbitrary topological meshes", CAD 10(6), 1978:
//   face point    centroid of the face's corners
//   edge point    (a + b + f₁ + f₂) / 4             (f: face points of the two faces)
//   vertex point  (Q + 2R + (n − 3) v) / n           (Q: mean of the n face points,
//                                                    R: mean of the n edge midpoints)
//   border        edge midpoints; vertices 3/4 v + 1/8 (two border neighbours)
//                 (Boundary_rule::smooth) or unchanged (fixed).
// Numbering (in place, see <genmesh/subdivision/detail/in_place.h>): old
// vertices keep their numbers, then edge points in first-use order (faces in
// face order, each from its lowest vertex), then
// face points in face iteration order; old edges keep theirs (the half at
// their halfedge's source), then the other halves, then the inner edges (edge
// point – face point) face by face; each old n-gon keeps one of its n quads,
// the others are appended.
// Guarantees: computed from the old mesh, then refined in place (arrays
// reserved once to the last level's size); identical on every backend;
// V' = V + E + F, F' = Σ deg f, Euler characteristic and border loops kept.
// Same masks as CGAL's CatmullClark_mask_3 on closed meshes.
// Creases (.crease_sharpness): the rules of <genmesh/subdivision/loop.h>
// (DeRose, Kass, Truong 1998) with Catmull-Clark's smooth masks; tagged
// corners (.corners) stay; the visitor's on_vertex_mask receives every new
// vertex's mask.
// Limits: g's other properties are not refined (new elements get their
// defaults); a backend without set_next, or a mesh with removed elements, is
// refined through the local operations (split_edge, split_face: the
// backend's own), never on a copy.
#pragma once

#include <genmesh/subdivision/detail/in_place.h>

#include <utility>

namespace genmesh {

/// Options of catmull_clark_subdivision(). With maps, name the type by its
/// arguments' deduction: genmesh::Catmull_clark_options{.crease_map = m}.
template <class CreaseMap = Default_map, class CornerMap = Default_map, class VertexPointMap = Default_map>
struct Catmull_clark_options {
  int iterations = 1;                             ///< levels to apply (≥ 0)
  Boundary_rule boundary = Boundary_rule::smooth; ///< border rule
  /// Edge → crease sharpness, as Loop_options::crease_map: read before the
  /// first level, holding every edge's sharpness of the result after the
  /// last (the map must accept the edges the call adds).
  CreaseMap crease_map = {};
  /// After the last level (iterations ≥ 1: all faces are quads), move every
  /// vertex to its limit position (n² v + 4 Σ edge neighbours + Σ diagonal
  /// neighbours) / (n (n + 5)); border and crease vertices (p + 4v + q)/6,
  /// corners stay.
  bool limit = false;
  /// Vertex → bool (read once; default: none): tagged vertices are corners,
  /// they keep their position at every level.
  CornerMap corner_map = {};
  /// Vertex → point (read-write; default get(genmesh::vertex_point, g)): the
  /// positions read and written; it must accept the vertices the call adds.
  VertexPointMap vertex_point_map = {};
};

namespace detail::subdivision {

inline std::array<std::size_t, 4> quad_split_counts(std::array<std::size_t, 4> n) {
  return {n[0] + n[1] + n[2], 2 * n[1] + n[3], n[3], 4 * n[3]};
}

/// One Catmull-Clark level in place on the dense mesh g of counts n.
template <class G, class O, class V, class Refiner>
void catmull_clark_level_in_place(G& g, const std::array<std::size_t, 4>& n, std::vector<double>& sharp,
                                  const std::vector<std::uint32_t>& corners, const O& o, V& vis,
                                  const Refiner& refiner) {
  using Vec = Eigen::Vector3d;
  constexpr bool masks = visits_vertex_masks<V>;
  const std::size_t nv = n[0], ne = n[1], nf = n[2], nc = n[3];
  auto pts = refiner.pts;
  auto vi = get(vertex_index, g);
  auto fi = get(face_index, g);
  auto num = [&](auto v) { return static_cast<std::uint32_t>(get(vi, v)); };
  const Stars st = stars(g, sharp, corners);
  const bool creases = !sharp.empty();
  const std::size_t nvb = index_bound(vertex_index, g);
  std::vector<std::uint32_t> number(index_bound(edge_index, g), k_none);
  std::vector<std::uint32_t> face_number; // by face index (masks)
  if constexpr (masks) {
    face_number.assign(index_bound(face_index, g), k_none);
    std::uint32_t j = 0;
    for (auto f : faces(g)) face_number[static_cast<std::size_t>(get(fi, f))] = j++;
  }
  auto points = refiner.new_points(g, ne + nf);
  // Σ face points per vertex (q), Σ ring neighbours (acc), Σ crease neighbours (ends)
  std::vector<Vec> q(nvb, Vec::Zero());
  Vertex_sums sums{std::vector<Vec>(nvb, Vec::Zero()), std::vector<Vec>(creases ? nvb : 0, Vec::Zero())};
  std::vector<std::uint32_t> face_begin, face_corner; // for the visitor's masks
  if constexpr (masks) face_begin.assign(1, 0), face_corner.reserve(nc);
  std::vector<std::uint32_t> src;
  std::vector<double> w;
  std::vector<halfedge_descriptor_t<G>> xs;
  auto old_target = [&](auto x) { return num(target(x, g)); };
  std::vector<char> border_edge(masks ? ne : 0, 0);
  std::vector<std::uint32_t> edge_faces(masks ? 4 * ne : 0); // a, b, f1, f2 per edge point (masks)
  auto ei = get(edge_index, g);
  // One pass over the faces (face order, each from its lowest vertex): face
  // points, and the edge points numbered by first use (the face of the first
  // use contributes first), so that the numbering and every sum are canonical.
  std::uint32_t used = 0;
  std::size_t j = 0;
  for (auto f : faces(g)) {
    if (j == nf) break;
    canonical_cycle(g, f, xs, old_target);
    Vec sum = Vec::Zero();
    for (const auto x : xs) sum += to_eigen(get(pts, source(x, g)));
    const Vec c = sum / double(xs.size());
    for (const auto x : xs) q[num(source(x, g))] += c;
    points.set(ne + j, c);
    if constexpr (masks) {
      src.clear();
      for (const auto x : xs) face_corner.push_back(num(source(x, g))), src.push_back(face_corner.back());
      face_begin.push_back(static_cast<std::uint32_t>(face_corner.size()));
      w.assign(xs.size(), 1.0 / double(xs.size()));
      vis.on_vertex_mask(static_cast<std::uint32_t>(nv + ne + j), src, w);
    }
    for (const auto x : xs) {
      const std::size_t k = static_cast<std::size_t>(get(ei, edge(x, g)));
      const Edge_use use = edge_use(g, x, k, number, sharp, masks);
      const double s = creases ? sharp[k] : 0.0;
      const auto [we, ww] = edge_weights(0.25, 0.25, use.border, s);
      if (use.seen) { // second use: the other face point
        points.add(number[k], ww, c);
        continue;
      }
      const std::uint32_t i = number[k] = used++;
      first_edge_point(g, pts, x, points, i, we, ww, c, st, use.border, s, sums);
      if constexpr (masks) {
        border_edge[i] = use.border;
        edge_faces[4 * i] = num(source(x, g)), edge_faces[4 * i + 1] = num(target(x, g));
        edge_faces[4 * i + 2] = static_cast<std::uint32_t>(j);
        edge_faces[4 * i + 3] =
            use.border ? k_none : face_number[static_cast<std::size_t>(get(fi, face(opposite(x, g), g)))];
      }
    }
    ++j;
  }
  border_edge_points(g, pts, points, number, sums.acc);
  auto add_face_mask = [&](std::size_t jf, double weight, std::vector<std::uint32_t>& s, std::vector<double>& ws) {
    const std::uint32_t b = face_begin[jf], e = face_begin[jf + 1];
    for (std::uint32_t c = b; c < e; ++c) s.push_back(face_corner[c]), ws.push_back(weight / double(e - b));
  };
  if constexpr (masks) {
    std::vector<std::uint32_t> k_of(ne);
    for (std::uint32_t k = 0; k < number.size(); ++k)
      if (number[k] != k_none) k_of[number[k]] = k;
    for (std::uint32_t i = 0; i < ne; ++i) {
      const bool border = border_edge[i] != 0;
      const auto [we, ww] = edge_weights(0.25, 0.25, border, creases ? sharp[k_of[i]] : 0.0);
      src.assign({edge_faces[4 * i], edge_faces[4 * i + 1]});
      w.assign({we, we});
      if (ww != 0) {
        add_face_mask(edge_faces[4 * i + 2], ww, src, w);
        add_face_mask(edge_faces[4 * i + 3], ww, src, w);
      }
      vis.on_vertex_mask(static_cast<std::uint32_t>(nv + i), src, w);
    }
  }
  std::vector<Vertex_rule> rules(masks ? nvb : 0);
  {
    for (auto v : vertices(g)) {
      const auto i = static_cast<std::uint32_t>(get(vi, v));
      if (i >= nvb) break; // appended (bulk path): iteration is by increasing index
      const double val = st.valence[i];
      const Vertex_rule smooth = val == 0 ? Vertex_rule{} : Vertex_rule{(val - 2.0) / val, 1.0 / (val * val), 0, 1.0 / (val * val)};
      const Vertex_rule r = vertex_rule(st, i, o.boundary, smooth);
      Vec p = r.self * to_eigen(get(pts, v)) + r.ring * sums.acc[i];
      if (r.faces != 0) p += r.faces * q[i];
      if (r.ends != 0) p += r.ends * sums.ends[i];
      sums.acc[i] = p;
      if constexpr (masks) rules[i] = r;
    }
  }
  if constexpr (masks) {
    // the faces around each old vertex, from the corner lists
    std::vector<std::uint32_t> vf_begin(nvb + 1, 0), vf(face_corner.size());
    for (std::uint32_t c : face_corner) ++vf_begin[c + 1];
    for (std::size_t v = 0; v < nvb; ++v) vf_begin[v + 1] += vf_begin[v];
    std::vector<std::uint32_t> fill(vf_begin.begin(), vf_begin.end() - 1);
    for (std::uint32_t jf = 0; jf < nf; ++jf)
      for (std::uint32_t c = face_begin[jf]; c < face_begin[jf + 1]; ++c) vf[fill[face_corner[c]]++] = jf;
    emit_vertex_masks(g, vis, st, number, used, sharp, border_edge, rules,
                      [&](std::uint32_t x, double weight, std::vector<std::uint32_t>& s, std::vector<double>& ws) {
                        for (std::uint32_t i = vf_begin[x]; i < vf_begin[x + 1]; ++i)
                          add_face_mask(vf[i], weight, s, ws);
                      });
  }
  write_old_positions(g, pts, sums.acc);
  sums = Vertex_sums{};
  std::vector<Vec>().swap(q);
  const std::vector<std::uint32_t> other = refiner.quads(g, points, nv, ne, nf, nc, number);
  decrement_creases(sharp, number, other, index_bound(edge_index, g));
}

} // namespace detail::subdivision

/// Applies options.iterations levels of Catmull-Clark subdivision to g (any
/// polygons). Throws genmesh::invalid_input, g unchanged, when
/// options.iterations < 0, a face cycle is corrupt, the crease map gives an
/// edge a negative or NaN sharpness, or an edge has no face on either side.
template <class G, class CreaseMap = Default_map, class CornerMap = Default_map, class VertexPointMap = Default_map,
          class Visitor = Mutation_visitor>
  requires detail::subdivision::Subdividable<G>
Subdivision_result catmull_clark_subdivision(G& g, const Catmull_clark_options<CreaseMap, CornerMap, VertexPointMap>& options = {},
                                             Visitor&& visitor = {}) {
  namespace ds = detail::subdivision;
  visitor.on_started(std::as_const(g));
  ds::Final_tags tags;
  Subdivision_result r = ds::run_in_place(
      g, options.iterations, "catmull_clark_subdivision", options.crease_map, options.corner_map, options.vertex_point_map,
      [](const auto& m) { return ds::face_counts(m, "catmull_clark_subdivision", 0); },
      [&](auto& m, const std::array<std::size_t, 4>& n, std::vector<double>& sharp,
          const std::vector<std::uint32_t>& corners, const auto& refiner) {
        ds::catmull_clark_level_in_place(m, n, sharp, corners, options, visitor, refiner);
      },
      ds::quad_split_counts, visitor, &tags);
  if (options.limit && options.iterations > 0) {
    auto interior = [&](const ds::Snapshot& s, std::uint32_t v) -> Eigen::Vector3d {
      const double n = s.valence[v];
      Eigen::Vector3d edges = Eigen::Vector3d::Zero(), diagonals = Eigen::Vector3d::Zero();
      std::uint32_t c = s.vertex_corner[v];
      for (std::uint32_t k = 0; k < s.valence[v]; ++k, c = s.rotate_ccw(c)) {
        edges += s.points[s.head(c)];
        diagonals += s.points[s.head(s.next(c))]; // the quad's corner opposite v
      }
      return (n * n * s.points[v] + 4.0 * edges + diagonals) / (n * (n + 5.0));
    };
    ds::move_to_limit(g, tags, options.boundary, interior, options.vertex_point_map);
  }
  visitor.on_finished(std::as_const(g));
  return r;
}

} // namespace genmesh
