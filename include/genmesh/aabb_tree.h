// genmesh/aabb_tree.h — a bounding volume hierarchy over the triangles of a
// mesh: closest point, ray hit, triangle and box overlap queries.
//
// Aabb_tree<G> copies the mesh's triangles (polygons are split into the fan
// from their lowest-index corner, as geometry.h's face_normal does) into
// leaf order, in double precision, and builds a binary tree of axis-aligned
// boxes over them with the surface area heuristic (binned, 16 bins; Wald,
// "On fast construction of SAH-based bounding volume hierarchies", 2007).
// Boxes are stored in float, rounded outward, so they stay conservative.
// The tree is a snapshot: it does not follow later edits of the mesh.
//
// Guarantees: closest_point returns a point of the nearest triangle, the
// same squared distance a brute-force scan with the same point–triangle
// routine finds (Ericson, "Real-Time Collision Detection", 5.1.5); among
// equally near triangles which one is returned is unspecified.
// faces_intersecting(triangle) uses the exact triangles_intersect of
// <genmesh/geometry.h>; ray hits are computed in floating point
// (Möller–Trumbore), inclusive of edges. Queries are const and may run
// concurrently on one tree.
//
// Chosen over CGAL's AABB_tree by measurement (docs/benchmarks.md, "Spatial
// index and measures"); CGAL is not needed by this header.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/exceptions.h>
#include <genmesh/geometry.h>
#include <genmesh/property_maps.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace genmesh {

/// The point of triangle (a, b, c) nearest to p, and its barycentric
/// coordinates (point = b[0]·a + b[1]·b + b[2]·c). Degenerate triangles are
/// handled (their nearest edge point is returned).
struct Triangle_closest {
  Eigen::Vector3d point;
  Eigen::Vector3d barycentric;
};

namespace detail::aabb {

inline Triangle_closest closest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double l = ab.squaredNorm();
  double t = l > 0 ? (p - a).dot(ab) / l : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return {a + t * ab, Eigen::Vector3d(1 - t, t, 0)};
}

} // namespace detail::aabb

inline Triangle_closest closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                  const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {a + v * ab, {1 - v, v, 0}};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {a + w * ac, {1 - w, 0, w}};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), {0, 1 - w, w}};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0)) {  // degenerate (or NaN): the nearest of the three sides
    Triangle_closest best = detail::aabb::closest_on_segment(p, a, b);
    Triangle_closest s = detail::aabb::closest_on_segment(p, b, c);
    s.barycentric = {0, s.barycentric[0], s.barycentric[1]};
    if ((s.point - p).squaredNorm() < (best.point - p).squaredNorm()) best = s;
    s = detail::aabb::closest_on_segment(p, c, a);
    s.barycentric = {s.barycentric[1], 0, s.barycentric[0]};
    if ((s.point - p).squaredNorm() < (best.point - p).squaredNorm()) best = s;
    return best;
  }
  const double denom = 1.0 / sum;
  const double v = vb * denom, w = vc * denom;
  return {a + ab * v + ac * w, {1 - v - w, v, w}};
}

/// A spatial index over the triangles of a FaceListGraph (see the header comment).
template <class G>
  requires FaceListGraph<G>
class Aabb_tree {
public:
  using Face = face_descriptor_t<G>;
  using Vertex = vertex_descriptor_t<G>;

  /// What closest_point() finds.
  struct Closest {
    Eigen::Vector3d point;
    Face face;                      ///< the face the point lies on
    std::array<Vertex, 3> corners;  ///< the (fan) triangle of that face it lies in
    Eigen::Vector3d barycentric;    ///< point = Σ barycentric[i] · position(corners[i])
    double squared_distance;
  };

  /// What first_hit() finds.
  struct Ray_hit {
    double t;  ///< point = origin + t · direction
    Eigen::Vector3d point;
    Face face;
    std::array<Vertex, 3> corners;
    Eigen::Vector3d barycentric;
  };

  Aabb_tree() = default;
  /// Builds the tree over g's faces (read through pm). Faces with NaN or
  /// infinite coordinates are left out (and counted in skipped_faces()).
  template <class PointMap>
  Aabb_tree(const G& g, PointMap pm) {
    build(g, pm);
  }
  explicit Aabb_tree(const G& g) : Aabb_tree(g, get(vertex_point, g)) {}

  /// The number of triangles indexed.
  std::size_t size() const { return tris_.size(); }
  bool empty() const { return tris_.empty(); }
  std::size_t skipped_faces() const { return skipped_; }
  /// The box of every indexed triangle.
  Eigen::AlignedBox3d bounding_box() const { return box_; }
  /// Bytes held by the tree.
  std::size_t memory_bytes() const {
    return tris_.capacity() * sizeof(Tri) + info_.capacity() * sizeof(Info) +
           nodes_.capacity() * sizeof(Node);
  }

  /// The point of the indexed surface nearest to q. Precondition: !empty().
  Closest closest_point(const Eigen::Vector3d& q) const {
    return closest_point(q, std::numeric_limits<double>::infinity());
  }

  /// As closest_point(q), searching only within sqrt(max_squared_distance)
  /// of q (a bound known to the caller, e.g. the previous query's distance
  /// plus the step since, prunes the search); nullopt-like result with
  /// squared_distance = infinity and face = null_face() when nothing is nearer.
  Closest closest_point(const Eigen::Vector3d& q, double max_squared_distance) const {
    Closest r{};
    r.squared_distance = max_squared_distance;
    r.face = boost::graph_traits<G>::null_face();
    std::uint32_t best = npos;
    if (nodes_.empty()) return r;
    double best_d = max_squared_distance;
    Triangle_closest best_c{};
    std::uint32_t stack[max_depth + 2];
    int sp = 0;
    std::uint32_t n = 0;
    if (box_distance(nodes_[0], q) > best_d) return r;
    for (;;) {
      const Node& node = nodes_[n];
      if (node.count) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          const Tri& t = tris_[i];
          const Triangle_closest c = closest_point_on_triangle(q, t.p[0], t.p[1], t.p[2]);
          const double d = (c.point - q).squaredNorm();
          if (d < best_d) best_d = d, best_c = c, best = i;
        }
      } else {
        std::uint32_t a = node.first, b = node.first + 1;
        double da = box_distance(nodes_[a], q), db = box_distance(nodes_[b], q);
        if (db < da) std::swap(a, b), std::swap(da, db);
        if (da <= best_d) {
          if (db <= best_d) stack[sp++] = b;
          n = a;
          continue;
        }
      }
      // Pop the next subtree still within reach.
      for (;;) {
        if (sp == 0) goto done;
        n = stack[--sp];
        if (box_distance(nodes_[n], q) <= best_d) break;
      }
    }
  done:
    if (best != npos) {
      r.point = best_c.point;
      r.barycentric = best_c.barycentric;
      r.squared_distance = best_d;
      r.face = info_[best].face;
      r.corners = info_[best].corners;
    }
    return r;
  }

  /// The squared distance from q to the indexed surface (infinity if empty).
  double squared_distance(const Eigen::Vector3d& q) const {
    return empty() ? std::numeric_limits<double>::infinity() : closest_point(q).squared_distance;
  }

  /// The nearest triangle hit by the ray origin + t·direction, t in [t_min,
  /// t_max] (edges and corners count as hits); nullopt when none.
  std::optional<Ray_hit> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                   double t_min = 0.0,
                                   double t_max = std::numeric_limits<double>::infinity()) const {
    if (nodes_.empty()) return std::nullopt;
    const Eigen::Vector3d inv = direction.cwiseInverse();
    double best_t = t_max;
    std::uint32_t best = npos;
    double bu = 0, bv = 0;
    std::uint32_t stack[max_depth + 2];
    int sp = 0;
    stack[sp++] = 0;
    while (sp) {
      const Node& node = nodes_[stack[--sp]];
      if (!ray_box(node, origin, inv, t_min, best_t)) continue;
      if (node.count) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          const Tri& tr = tris_[i];
          double t, u, v;
          if (ray_triangle(origin, direction, tr, t, u, v) && t >= t_min && t <= best_t)
            best_t = t, best = i, bu = u, bv = v;
        }
      } else {
        stack[sp++] = node.first + 1;
        stack[sp++] = node.first;
      }
    }
    if (best == npos) return std::nullopt;
    return Ray_hit{best_t, origin + best_t * direction, info_[best].face, info_[best].corners,
                   Eigen::Vector3d(1 - bu - bv, bu, bv)};
  }

  /// Calls fn(face, corners, triangle points) for every indexed triangle
  /// whose bounding box meets the closed box (a broad phase; the triangle
  /// itself may miss the box). A face split into several triangles is
  /// reported once per triangle.
  template <class Fn>
  void for_each_in_box(const Eigen::AlignedBox3d& box, Fn&& fn) const {
    visit_box(box, [&](std::uint32_t i) {
      fn(info_[i].face, info_[i].corners, tris_[i].p);
      return true;
    });
  }

  /// The faces with a triangle whose bounding box meets the closed box,
  /// each once, in the tree's order.
  std::vector<Face> faces_in_box(const Eigen::AlignedBox3d& box) const {
    std::vector<Face> out;
    visit_box(box, [&](std::uint32_t i) {
      out.push_back(info_[i].face);
      return true;
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  /// The faces with a triangle meeting the closed triangle (a, b, c), exactly
  /// (triangles_intersect), each once, sorted.
  std::vector<Face> faces_intersecting(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c) const {
    std::vector<Face> out;
    visit_box(triangle_box(a, b, c), [&](std::uint32_t i) {
      const Tri& t = tris_[i];
      if (triangles_intersect(a, b, c, t.p[0], t.p[1], t.p[2])) out.push_back(info_[i].face);
      return true;
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  /// Does any indexed triangle meet the closed triangle (a, b, c)? Exact.
  bool intersects(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) const {
    bool hit = false;
    visit_box(triangle_box(a, b, c), [&](std::uint32_t i) {
      const Tri& t = tris_[i];
      hit = triangles_intersect(a, b, c, t.p[0], t.p[1], t.p[2]);
      return !hit;
    });
    return hit;
  }

  /// For internal drivers (self-intersection): the triangles in leaf order.
  /// Each entry: points, face and corners of triangle i.
  std::size_t triangle_count() const { return tris_.size(); }
  const std::array<Eigen::Vector3d, 3>& triangle_points(std::size_t i) const { return tris_[i].p; }
  Face triangle_face(std::size_t i) const { return info_[i].face; }
  const std::array<Vertex, 3>& triangle_corners(std::size_t i) const { return info_[i].corners; }
  /// Calls fn(j) for every triangle j whose box meets the box; stops when fn returns false.
  template <class Fn>
  void visit_triangles_in_box(const Eigen::AlignedBox3d& box, Fn&& fn) const {
    visit_box(box, [&](std::uint32_t i) { return fn(static_cast<std::size_t>(i)); });
  }

private:
  static constexpr std::uint32_t npos = std::numeric_limits<std::uint32_t>::max();
  // Deeper than this, nodes split at the median (bounds the traversal stacks).
  static constexpr std::uint32_t max_depth = 100;

  struct Tri {
    std::array<Eigen::Vector3d, 3> p;
  };
  struct Info {
    Face face;
    std::array<Vertex, 3> corners;
  };
  // A node's box; count > 0: a leaf over tris_[first, first + count);
  // count == 0: children first and first + 1.
  struct Node {
    float lo[3], hi[3];
    std::uint32_t first, count;
  };

  static Eigen::AlignedBox3d triangle_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
    Eigen::AlignedBox3d box(a);
    box.extend(b);
    box.extend(c);
    return box;
  }

  static double box_distance(const Node& n, const Eigen::Vector3d& q) {
    double d = 0;
    for (int k = 0; k < 3; ++k) {
      const double lo = n.lo[k], hi = n.hi[k];
      const double e = q[k] < lo ? lo - q[k] : (q[k] > hi ? q[k] - hi : 0.0);
      d += e * e;
    }
    return d;
  }

  static bool box_overlap(const Node& n, const Eigen::AlignedBox3d& b) {
    for (int k = 0; k < 3; ++k)
      if (b.max()[k] < n.lo[k] || b.min()[k] > n.hi[k]) return false;
    return true;
  }

  static bool ray_box(const Node& n, const Eigen::Vector3d& o, const Eigen::Vector3d& inv, double t0,
                      double t1) {
    for (int k = 0; k < 3; ++k) {
      double a = (n.lo[k] - o[k]) * inv[k], b = (n.hi[k] - o[k]) * inv[k];
      if (a > b) std::swap(a, b);
      if (std::isnan(a) || std::isnan(b)) {  // direction 0 on this axis and the origin on a slab plane
        if (o[k] < n.lo[k] || o[k] > n.hi[k]) return false;
        continue;
      }
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      if (t0 > t1) return false;
    }
    return true;
  }

  static bool ray_triangle(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Tri& tr, double& t,
                           double& u, double& v) {
    const Eigen::Vector3d e1 = tr.p[1] - tr.p[0], e2 = tr.p[2] - tr.p[0];
    const Eigen::Vector3d pv = d.cross(e2);
    const double det = e1.dot(pv);
    if (det == 0 || !std::isfinite(det)) return false;
    const double inv = 1.0 / det;
    const Eigen::Vector3d tv = o - tr.p[0];
    u = tv.dot(pv) * inv;
    if (u < 0 || u > 1) return false;
    const Eigen::Vector3d qv = tv.cross(e1);
    v = d.dot(qv) * inv;
    if (v < 0 || u + v > 1) return false;
    t = e2.dot(qv) * inv;
    return true;
  }

  template <class Fn>
  void visit_box(const Eigen::AlignedBox3d& box, Fn&& fn) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[max_depth + 2];
    int sp = 0;
    stack[sp++] = 0;
    while (sp) {
      const Node& node = nodes_[stack[--sp]];
      if (!box_overlap(node, box)) continue;
      if (node.count) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          const Tri& t = tris_[i];
          bool hit = true;
          for (int k = 0; k < 3 && hit; ++k) {
            const double lo = std::min({t.p[0][k], t.p[1][k], t.p[2][k]});
            const double hi = std::max({t.p[0][k], t.p[1][k], t.p[2][k]});
            hit = !(box.max()[k] < lo || box.min()[k] > hi);
          }
          if (hit && !fn(i)) return;
        }
      } else {
        stack[sp++] = node.first + 1;
        stack[sp++] = node.first;
      }
    }
  }

  static float down(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
  }
  static float up(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  }

  template <class PointMap>
  void build(const G& g, PointMap pm) {
    std::vector<Tri> tris;
    std::vector<Info> info;
    for (const auto f : faces(g)) {
      const auto h0 = detail::geom::canonical_halfedge(f, g);
      const Vertex v0 = target(h0, g);
      const Eigen::Vector3d p0 = point(v0, g, pm);
      auto h = next(h0, g);
      Vertex vp = target(h, g);
      Eigen::Vector3d pp = point(vp, g, pm);
      bool finite = p0.allFinite() && pp.allFinite();
      const std::size_t first = tris.size();
      for (h = next(h, g); h != h0; h = next(h, g)) {
        const Vertex vc = target(h, g);
        const Eigen::Vector3d pc = point(vc, g, pm);
        finite = finite && pc.allFinite();
        tris.push_back(Tri{{p0, pp, pc}});
        info.push_back(Info{f, {v0, vp, vc}});
        vp = vc;
        pp = pc;
      }
      if (!finite) {
        tris.resize(first);
        info.resize(first);
        ++skipped_;
      }
    }
    const std::size_t n = tris.size();
    if (n == 0) return;
    if (n >= npos / 2) throw invalid_input("Aabb_tree: too many triangles");
    // Centroids and boxes, then the SAH build over an index permutation.
    std::vector<Eigen::AlignedBox3d> boxes(n);
    std::vector<Eigen::Vector3d> centers(n);
    for (std::size_t i = 0; i < n; ++i) {
      boxes[i] = triangle_box(tris[i].p[0], tris[i].p[1], tris[i].p[2]);
      centers[i] = boxes[i].center();
      box_.extend(boxes[i]);
    }
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
    nodes_.reserve(2 * n);
    nodes_.push_back({});
    struct Task {
      std::uint32_t node, begin, end, depth;
    };
    std::vector<Task> tasks{{0, 0, static_cast<std::uint32_t>(n), 0}};
    constexpr int bins = 16;
    constexpr std::uint32_t leaf_size = 4;
    while (!tasks.empty()) {
      const Task t = tasks.back();
      tasks.pop_back();
      Eigen::AlignedBox3d nb, cb;
      for (std::uint32_t i = t.begin; i < t.end; ++i) nb.extend(boxes[order[i]]), cb.extend(centers[order[i]]);
      Node& node = nodes_[t.node];
      for (int k = 0; k < 3; ++k) node.lo[k] = down(nb.min()[k]), node.hi[k] = up(nb.max()[k]);
      const std::uint32_t count = t.end - t.begin;
      auto make_leaf = [&] {
        nodes_[t.node].first = t.begin;
        nodes_[t.node].count = count;
      };
      if (count <= leaf_size) {
        make_leaf();
        continue;
      }
      // Binned SAH along the widest centroid axis.
      int axis = 0;
      const Eigen::Vector3d ext = cb.sizes();
      if (ext[1] > ext[axis]) axis = 1;
      if (ext[2] > ext[axis]) axis = 2;
      std::uint32_t mid;
      if (!(ext[axis] > 0) || t.depth >= max_depth - 40) {
        mid = t.begin + count / 2;  // all centroids equal: split in the middle
      } else {
        const double lo = cb.min()[axis], scale = bins / ext[axis];
        auto bin_of = [&](std::uint32_t i) {
          return std::min(bins - 1, static_cast<int>((centers[i][axis] - lo) * scale));
        };
        Eigen::AlignedBox3d bb[bins];
        std::uint32_t bc[bins] = {};
        for (std::uint32_t i = t.begin; i < t.end; ++i) {
          const int b = bin_of(order[i]);
          bb[b].extend(boxes[order[i]]);
          ++bc[b];
        }
        auto area = [](const Eigen::AlignedBox3d& b) {
          if (b.isEmpty()) return 0.0;
          const Eigen::Vector3d s = b.sizes();
          return s.x() * s.y() + s.y() * s.z() + s.z() * s.x();
        };
        double right_area[bins];
        std::uint32_t right_count[bins];
        Eigen::AlignedBox3d acc;
        std::uint32_t cnt = 0;
        for (int b = bins - 1; b > 0; --b) {
          acc.extend(bb[b]);
          cnt += bc[b];
          right_area[b] = area(acc);
          right_count[b] = cnt;
        }
        acc.setEmpty();
        cnt = 0;
        double best_cost = std::numeric_limits<double>::infinity();
        int best_split = -1;
        for (int b = 1; b < bins; ++b) {
          acc.extend(bb[b - 1]);
          cnt += bc[b - 1];
          if (cnt == 0 || right_count[b] == 0) continue;
          const double cost = area(acc) * cnt + right_area[b] * right_count[b];
          if (cost < best_cost) best_cost = cost, best_split = b;
        }
        if (best_split < 0) {
          mid = t.begin + count / 2;
        } else {
          mid = static_cast<std::uint32_t>(
              std::partition(order.begin() + t.begin, order.begin() + t.end,
                             [&](std::uint32_t i) { return bin_of(i) < best_split; }) -
              order.begin());
        }
      }
      if (mid == t.begin || mid == t.end || t.depth >= max_depth - 40) {
        mid = t.begin + count / 2;
        std::nth_element(order.begin() + t.begin, order.begin() + mid, order.begin() + t.end,
                         [&](std::uint32_t a, std::uint32_t b) { return centers[a][axis] < centers[b][axis]; });
      }
      const auto left = static_cast<std::uint32_t>(nodes_.size());
      nodes_[t.node].first = left;
      nodes_[t.node].count = 0;
      nodes_.push_back({});
      nodes_.push_back({});
      tasks.push_back({left + 1, mid, t.end, t.depth + 1});
      tasks.push_back({left, t.begin, mid, t.depth + 1});
    }
    nodes_.shrink_to_fit();
    tris_.resize(n);
    info_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      tris_[i] = tris[order[i]];
      info_[i] = info[order[i]];
    }
  }

  std::vector<Tri> tris_;
  std::vector<Info> info_;
  std::vector<Node> nodes_;
  Eigen::AlignedBox3d box_;
  std::size_t skipped_ = 0;
};

} // namespace genmesh
