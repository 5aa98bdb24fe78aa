// genmesh/remeshing/detail/reference_surface.h — the input surface that
// remeshing projects onto: a copy of the input triangles with their face
// adjacency, and a closest-point walk from a per-vertex hint face.
//
// Why a walk: between two projections a vertex moves by a fraction of the
// target length (a split midpoint, a tangential smoothing step), so the
// closest point is almost always on the hint face or next to it. The walk
// moves to a neighbouring face (across the edge, or around the vertex, where
// the current closest point lies) while that strictly shortens the
// distance; it ends on a local minimum of the distance, which is a point of
// the input surface (what the invariant asks) and, on every mesh we tried,
// the global closest point. Cost O(1) per query instead of a tree descent.
// Deterministic: triangles start at their lowest vertex, ties keep the
// current face.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/property_maps.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace genmesh::detail::remeshing {

inline constexpr std::uint32_t k_none = std::numeric_limits<std::uint32_t>::max();

/// The closest point of a triangle to q, with where it lies: the interior
/// (region 0), edge i from corner i to corner i+1 (region 1 + i), or corner
/// j (region 4 + j). Ericson, Real-Time Collision Detection, 5.1.5.
struct Triangle_closest {
  Eigen::Vector3d point;
  double squared_distance;
  int region;
};

inline Triangle_closest closest_on_triangle(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  auto done = [&](const Eigen::Vector3d& p, int region) {
    return Triangle_closest{p, (q - p).squaredNorm(), region};
  };
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = q - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return done(a, 4);
  const Eigen::Vector3d bp = q - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return done(b, 5);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return done(a + (d1 / (d1 - d3)) * ab, 1);
  const Eigen::Vector3d cp = q - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return done(c, 6);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return done(a + (d2 / (d2 - d6)) * ac, 3);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return done(b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), 2);
  const double sum = va + vb + vc;
  if (!(sum > 0)) { // degenerate triangle: the best of its three sides
    auto on_segment = [&](const Eigen::Vector3d& s, const Eigen::Vector3d& t, int region) {
      const Eigen::Vector3d d = t - s;
      const double l2 = d.squaredNorm();
      const double x = l2 > 0 ? std::clamp((q - s).dot(d) / l2, 0.0, 1.0) : 0.0;
      return done(s + x * d, region);
    };
    Triangle_closest best = on_segment(a, b, 1);
    for (const Triangle_closest& t : {on_segment(b, c, 2), on_segment(c, a, 3)})
      if (t.squared_distance < best.squared_distance) best = t;
    return best;
  }
  const double v = vb / sum, w = vc / sum;
  return done(a + v * ab + w * ac, 0);
}

/// A copy of a triangle mesh's geometry for closest-point queries.
class Reference_surface {
public:
  /// Copies g's triangles (faces in face order, each starting at its lowest
  /// vertex index) and their adjacency. g must be a manifold triangle mesh.
  template <class G>
  explicit Reference_surface(const G& g) {
    auto vi = get(vertex_index, g);
    auto fi = get(face_index, g);
    auto pm = get(vertex_point, const_cast<G&>(g));
    const std::size_t vb = index_bound(vertex_index, g), fb = index_bound(face_index, g);
    points_.assign(vb, Eigen::Vector3d::Zero());
    for (auto v : vertices(g)) points_[get(vi, v)] = to_eigen(get(pm, v));
    face_number_.assign(fb, k_none);
    std::uint32_t n = 0;
    for (auto f : faces(g)) face_number_[get(fi, f)] = n++;
    tri_.resize(n);
    adj_.resize(n);
    n = 0;
    for (auto f : faces(g)) {
      std::array<halfedge_descriptor_t<G>, 3> hs;
      hs[0] = halfedge(f, g);
      hs[1] = next(hs[0], g);
      hs[2] = next(hs[1], g);
      // Corner i = source(hs[i]); start at the lowest vertex.
      std::array<std::uint32_t, 3> vs;
      for (int i = 0; i < 3; ++i) vs[i] = static_cast<std::uint32_t>(get(vi, source(hs[i], g)));
      int s = 0;
      for (int i = 1; i < 3; ++i)
        if (vs[i] < vs[s]) s = i;
      for (int i = 0; i < 3; ++i) {
        const auto h = hs[(s + i) % 3];
        tri_[n][i] = vs[(s + i) % 3];
        const auto fo = face(opposite(h, g), g);
        adj_[n][i] = fo == boost::graph_traits<G>::null_face() ? k_none : face_number_[get(fi, fo)];
      }
      ++n;
    }
    // Faces around each vertex (compressed rows).
    vf_offset_.assign(vb + 1, 0);
    for (const auto& t : tri_)
      for (auto v : t) ++vf_offset_[v + 1];
    for (std::size_t i = 0; i < vb; ++i) vf_offset_[i + 1] += vf_offset_[i];
    vf_.resize(vf_offset_[vb]);
    std::vector<std::uint32_t> fill(vf_offset_.begin(), vf_offset_.end() - 1);
    for (std::uint32_t f = 0; f < tri_.size(); ++f)
      for (auto v : tri_[f]) vf_[fill[v]++] = f;
  }

  /// The reference face number of g's face index i (k_none if none).
  std::uint32_t face_number(std::size_t face_index) const {
    return face_index < face_number_.size() ? face_number_[face_index] : k_none;
  }
  /// A face of input vertex number v (the lowest-numbered), or k_none.
  std::uint32_t face_of_vertex(std::size_t v) const {
    return v + 1 < vf_offset_.size() && vf_offset_[v] < vf_offset_[v + 1] ? vf_[vf_offset_[v]] : k_none;
  }
  std::size_t size() const { return tri_.size(); }

  /// The closest point to q found by walking from face `hint` (updated to
  /// the face the point lies on).
  Eigen::Vector3d project(const Eigen::Vector3d& q, std::uint32_t& hint) const {
    if (tri_.empty()) return q;
    std::uint32_t f = hint < tri_.size() ? hint : 0;
    Triangle_closest best = on_face(q, f);
    for (int step = 0; step < 256 && best.region != 0; ++step) {
      std::uint32_t next_face = k_none;
      auto consider = [&](std::uint32_t c) {
        if (c == k_none || c == f) return;
        const Triangle_closest t = on_face(q, c);
        if (t.squared_distance < best.squared_distance) {
          best = t;
          next_face = c;
        }
      };
      if (best.region <= 3) {
        consider(adj_[f][best.region - 1]);
      } else {
        const std::uint32_t v = tri_[f][best.region - 4];
        for (std::uint32_t k = vf_offset_[v]; k < vf_offset_[v + 1]; ++k) consider(vf_[k]);
      }
      if (next_face == k_none) break;
      f = next_face;
    }
    hint = f;
    return best.point;
  }

  /// The squared distance from q to face f.
  double squared_distance(const Eigen::Vector3d& q, std::uint32_t f) const { return on_face(q, f).squared_distance; }

private:
  Triangle_closest on_face(const Eigen::Vector3d& q, std::uint32_t f) const {
    const auto& t = tri_[f];
    return closest_on_triangle(q, points_[t[0]], points_[t[1]], points_[t[2]]);
  }

  std::vector<Eigen::Vector3d> points_;
  std::vector<std::array<std::uint32_t, 3>> tri_, adj_;
  std::vector<std::uint32_t> face_number_, vf_offset_, vf_;
};

} // namespace genmesh::detail::remeshing
