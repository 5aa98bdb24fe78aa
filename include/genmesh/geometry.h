// genmesh/geometry.h — the vector math every algorithm shares: normals,
// areas, angles, lengths, bounding box, volume, and an exact triangle
// intersection test, over any FaceGraph and any point type.
//
// Every function computes in double (Eigen::Vector3d) and reads positions
// through a vertex point map, the last argument, defaulting to
// get(genmesh::vertex_point, g); point types are read through
// <genmesh/point_traits.h>.
//
// Conventions:
// - face_normal(f) is the vector area times two: Σ (pᵢ − p₀) × (pᵢ₊₁ − p₀)
//   over the fan of f, started at the corner with the lowest vertex index
//   (so every backend rounds alike). Its length is 2·area for a planar face,
//   its direction follows the face orientation (counter-clockwise seen from
//   where it points). face_area(f) = |face_normal(f)| / 2.
// - Angles are in radians. corner_angle(h) is the angle at target(h) inside
//   face(h); dihedral_angle(h) the signed bend across edge(h): 0 flat,
//   positive convex, negative concave, in [−π, π] (0 on a border edge).
// - A degenerate face (zero area) has a zero unit_face_normal; a vertex
//   whose faces all are degenerate has a zero vertex_normal. NaN coordinates
//   propagate as NaN; nothing here throws or loops on them.
// - triangles_intersect() decides with exact predicates (robust for any
//   finite input, touching counts as intersecting).
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/geometry/triangle_intersection.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>

namespace genmesh {

namespace detail::geom {

// The halfedge of f whose target has the lowest vertex index (halfedge(f, g)
// when g has no vertex index map), so that per-face sums do not depend on
// where a backend starts a face.
template <FaceGraph G>
halfedge_descriptor_t<G> canonical_halfedge(face_descriptor_t<G> f, const G& g) {
  const halfedge_descriptor_t<G> h0 = halfedge(f, g);
  if constexpr (HasIndexMap<G, vertex_index_t>) {
    const auto vi = get(vertex_index, g);
    halfedge_descriptor_t<G> best = h0, h = next(h0, g);
    std::size_t bi = get(vi, target(h0, g));
    while (h != h0) {
      const std::size_t i = get(vi, target(h, g));
      if (i < bi) bi = i, best = h;
      h = next(h, g);
    }
    return best;
  } else {
    return h0;
  }
}

// The halfedge into v whose source has the lowest vertex index (halfedge(v, g)
// without a vertex index map): the start of per-vertex sums that must round
// alike on every backend. null_halfedge() for an isolated vertex.
template <FaceGraph G>
halfedge_descriptor_t<G> canonical_halfedge_into(vertex_descriptor_t<G> v, const G& g) {
  const halfedge_descriptor_t<G> h0 = halfedge(v, g);
  if constexpr (HasIndexMap<G, vertex_index_t>) {
    if (h0 == boost::graph_traits<G>::null_halfedge()) return h0;
    const auto vi = get(vertex_index, g);
    halfedge_descriptor_t<G> best = h0, h = opposite(next(h0, g), g);
    std::size_t bi = get(vi, source(h0, g));
    while (h != h0) {
      const std::size_t i = get(vi, source(h, g));
      if (i < bi) bi = i, best = h;
      h = opposite(next(h, g), g);
    }
    return best;
  } else {
    return h0;
  }
}

} // namespace detail::geom

// On points: the primitives the mesh functions below, the readers and
// writers (STL facet normals) and the algorithms share.

/// (b − a) × (c − a): twice the vector area of triangle abc, directed by
/// its orientation.
inline Eigen::Vector3d triangle_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c) {
  // Eigen's cross() of two difference expressions, written out: the same
  // arithmetic, but GCC 12 kept Eigen's as an out-of-line call (6% of a
  // simplification run's samples).
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
  const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

/// triangle_normal(ia, a, ib, b, ic, c): the same normal of the triangle
/// with corners a, b, c (in this cyclic order) of vertex indices ia, ib, ic,
/// computed from the corner of lowest index, as face_normal does: the same
/// bits whichever corner a caller starts from.
inline Eigen::Vector3d triangle_normal(std::size_t ia, const Eigen::Vector3d& a, std::size_t ib,
                                       const Eigen::Vector3d& b, std::size_t ic, const Eigen::Vector3d& c) {
  if (ia < ib && ia < ic) return triangle_normal(a, b, c);
  if (ib < ic) return triangle_normal(b, c, a);
  return triangle_normal(c, a, b);
}

/// The aspect ratio of triangle abc: circumradius / (2 · inradius), 1 for
/// the equilateral triangle, growing without bound as it degenerates;
/// infinity for a degenerate (zero-area) triangle.
inline double triangle_aspect_ratio(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double area = 0.5 * triangle_normal(a, b, c).norm();
  if (!(area > 0)) return std::numeric_limits<double>::infinity();
  // R = abc / (4 area), r = 2 area / (a + b + c).
  return (la * lb * lc / (4 * area)) / (2 * (2 * area / (la + lb + lc)));
}

/// v / |v|, or zero when |v| is zero (a degenerate face has no direction).
inline Eigen::Vector3d normalized_or_zero(const Eigen::Vector3d& v) {
  const double l = v.norm();
  return l > 0 ? Eigen::Vector3d(v / l) : Eigen::Vector3d::Zero();
}

/// Twice the vector area of the polygon with these corners, as a fan from
/// corners[0] (so it equals face_normal when corners[0] is the face's
/// canonical corner); zero for fewer than three corners.
inline Eigen::Vector3d polygon_normal(std::span<const Eigen::Vector3d> corners) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) n += triangle_normal(corners[0], corners[k], corners[k + 1]);
  return n;
}

// Every function below is a function object (as the local operations are),
// so argument-dependent lookup never finds it: CGAL's unqualified calls such
// as edge_length(h, g, np) on a genmesh mesh stay CGAL's.

/// A readable vertex point map of G.
template <class M, class G>
concept PointMapOf = requires(const M& m, vertex_descriptor_t<G> v) {
  { to_eigen(typename boost::property_traits<M>::value_type(get(m, v))) };
};

/// point(v, g[, pm]): the position of v as Eigen::Vector3d.
inline constexpr struct Point_fn {
  template <HalfedgeGraph G, PointMapOf<G> PointMap>
  Eigen::Vector3d operator()(vertex_descriptor_t<G> v, const G&, const PointMap& pm) const {
    using P = typename boost::property_traits<PointMap>::value_type;
    return to_eigen(P(get(pm, v)));
  }
  template <HalfedgeGraph G>
  Eigen::Vector3d operator()(vertex_descriptor_t<G> v, const G& g) const {
    return (*this)(v, g, get(vertex_point, g));
  }
} point{};

/// face_normal(f, g[, pm]): twice the vector area of f (see the header
/// comment); zero for a degenerate face.
inline constexpr struct Face_normal_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  Eigen::Vector3d operator()(face_descriptor_t<G> f, const G& g, const PointMap& pm) const {
    const auto h0 = detail::geom::canonical_halfedge(f, g);
    const Eigen::Vector3d p0 = point(target(h0, g), g, pm);
    auto h = next(h0, g);
    Eigen::Vector3d prev = point(target(h, g), g, pm) - p0;
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (h = next(h, g); h != h0; h = next(h, g)) {
      const Eigen::Vector3d cur = point(target(h, g), g, pm) - p0;
      n += prev.cross(cur);
      prev = cur;
    }
    return n;
  }
  template <FaceGraph G>
  Eigen::Vector3d operator()(face_descriptor_t<G> f, const G& g) const {
    return (*this)(f, g, get(vertex_point, g));
  }
} face_normal{};

/// unit_face_normal(f, g[, pm]): face_normal normalized; zero for a degenerate face.
inline constexpr struct Unit_face_normal_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  Eigen::Vector3d operator()(face_descriptor_t<G> f, const G& g, const PointMap& pm) const {
    return normalized_or_zero(face_normal(f, g, pm));
  }
  template <FaceGraph G>
  Eigen::Vector3d operator()(face_descriptor_t<G> f, const G& g) const {
    return (*this)(f, g, get(vertex_point, g));
  }
} unit_face_normal{};

/// face_area(f, g[, pm]): |face_normal| / 2 (exact for triangles and planar polygons).
inline constexpr struct Face_area_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  double operator()(face_descriptor_t<G> f, const G& g, const PointMap& pm) const {
    return 0.5 * face_normal(f, g, pm).norm();
  }
  template <FaceGraph G>
  double operator()(face_descriptor_t<G> f, const G& g) const {
    return (*this)(f, g, get(vertex_point, g));
  }
} face_area{};

/// face_centroid(f, g[, pm]): the mean of f's corners.
inline constexpr struct Face_centroid_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  Eigen::Vector3d operator()(face_descriptor_t<G> f, const G& g, const PointMap& pm) const {
    const auto h0 = detail::geom::canonical_halfedge(f, g);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    int n = 0;
    auto h = h0;
    do {
      c += point(target(h, g), g, pm);
      ++n;
      h = next(h, g);
    } while (h != h0);
    return c / n;
  }
  template <FaceGraph G>
  Eigen::Vector3d operator()(face_descriptor_t<G> f, const G& g) const {
    return (*this)(f, g, get(vertex_point, g));
  }
} face_centroid{};

/// The angle between the vectors a and b, in [0, π] (0 if either is zero).
inline double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// The cotangent of the angle between the vectors a and b: a·b / |a × b|;
/// 0 when they are parallel or one is zero.
inline double cotangent_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double s = a.cross(b).norm();
  return s > 0 ? a.dot(b) / s : 0.0;
}

/// corner_angle(h, g[, pm]): the angle of face(h) at target(h), between the
/// sides to source(h) and to target(next(h)), in radians.
inline constexpr struct Corner_angle_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  double operator()(halfedge_descriptor_t<G> h, const G& g, const PointMap& pm) const {
    const Eigen::Vector3d p = point(target(h, g), g, pm);
    return angle_between(point(source(h, g), g, pm) - p, point(target(next(h, g), g), g, pm) - p);
  }
  template <FaceGraph G>
  double operator()(halfedge_descriptor_t<G> h, const G& g) const {
    return (*this)(h, g, get(vertex_point, g));
  }
} corner_angle{};

/// dihedral_angle(h, g[, pm]): the signed bend of the surface across
/// edge(h), in radians: 0 where face(h) and face(opposite(h)) are coplanar,
/// positive at a convex edge, negative at a concave one; 0 on a border edge
/// or next to a degenerate face.
inline constexpr struct Dihedral_angle_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  double operator()(halfedge_descriptor_t<G> h, const G& g, const PointMap& pm) const {
    const auto null = boost::graph_traits<G>::null_face();
    const auto f1 = face(h, g), f2 = face(opposite(h, g), g);
    if (f1 == null || f2 == null) return 0.0;
    const Eigen::Vector3d n1 = face_normal(f1, g, pm), n2 = face_normal(f2, g, pm);
    if (n1.squaredNorm() == 0 || n2.squaredNorm() == 0) return 0.0;
    const Eigen::Vector3d c = n1.cross(n2);
    const double a = std::atan2(c.norm(), n1.dot(n2));
    const Eigen::Vector3d e = point(target(h, g), g, pm) - point(source(h, g), g, pm);
    return c.dot(e) < 0 ? -a : a;
  }
  template <FaceGraph G>
  double operator()(halfedge_descriptor_t<G> h, const G& g) const {
    return (*this)(h, g, get(vertex_point, g));
  }
} dihedral_angle{};

/// squared_edge_length(h, g[, pm]): the squared length of edge(h).
inline constexpr struct Squared_edge_length_fn {
  template <HalfedgeGraph G, PointMapOf<G> PointMap>
  double operator()(halfedge_descriptor_t<G> h, const G& g, const PointMap& pm) const {
    return (point(target(h, g), g, pm) - point(source(h, g), g, pm)).squaredNorm();
  }
  template <HalfedgeGraph G>
  double operator()(halfedge_descriptor_t<G> h, const G& g) const {
    return (*this)(h, g, get(vertex_point, g));
  }
} squared_edge_length{};

/// edge_length(h, g[, pm]): the length of edge(h).
inline constexpr struct Edge_length_fn {
  template <HalfedgeGraph G, PointMapOf<G> PointMap>
  double operator()(halfedge_descriptor_t<G> h, const G& g, const PointMap& pm) const {
    return std::sqrt(squared_edge_length(h, g, pm));
  }
  template <HalfedgeGraph G>
  double operator()(halfedge_descriptor_t<G> h, const G& g) const {
    return (*this)(h, g, get(vertex_point, g));
  }
} edge_length{};

/// vertex_normal(v, g[, pm]): the unit normal at v: the unit normals of its
/// faces weighted by their corner angles at v (Thürmer & Wüthrich 1998);
/// zero for an isolated vertex or one whose faces are all degenerate.
inline constexpr struct Vertex_normal_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  Eigen::Vector3d operator()(vertex_descriptor_t<G> v, const G& g, const PointMap& pm) const {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    const auto h0 = halfedge(v, g);
    if (h0 == boost::graph_traits<G>::null_halfedge()) return n;
    auto h = h0;
    do {
      if (face(h, g) != boost::graph_traits<G>::null_face())
        n += corner_angle(h, g, pm) * unit_face_normal(face(h, g), g, pm);
      h = opposite(next(h, g), g);
    } while (h != h0);
    const double l = n.norm();
    return l > 0 ? Eigen::Vector3d(n / l) : Eigen::Vector3d::Zero();
  }
  template <FaceGraph G>
  Eigen::Vector3d operator()(vertex_descriptor_t<G> v, const G& g) const {
    return (*this)(v, g, get(vertex_point, g));
  }
} vertex_normal{};

/// The discrete curvatures at a vertex (see vertex_curvature).
struct Vertex_curvature {
  double mean = 0;      ///< mean curvature H ≥ 0 (half the length of the cotangent Laplacian of the position)
  double gaussian = 0;  ///< Gaussian curvature K (angle defect over area)
  double min = 0;       ///< H − √max(0, H² − K)
  double max = 0;       ///< H + √max(0, H² − K)
  /// The larger principal curvature in absolute value.
  double max_abs() const { return std::max(std::abs(min), std::abs(max)); }
};

/// vertex_curvature(v, g[, pm]): the discrete curvatures at the inner vertex
/// v of a triangle mesh (Meyer, Desbrun, Schröder & Barr 2003): the mean
/// curvature from the cotangent Laplacian and the Gaussian curvature from the
/// angle defect, both over v's mixed Voronoi area; the principal curvatures
/// from them (pmp-library's SurfaceCurvature::analyze). All zero for a border
/// or isolated vertex and for a vertex whose area is zero. Sums start at the
/// neighbour with the lowest vertex index, so every backend rounds alike.
inline constexpr struct Vertex_curvature_fn {
  template <FaceGraph G, PointMapOf<G> PointMap>
  Vertex_curvature operator()(vertex_descriptor_t<G> v, const G& g, const PointMap& pm) const {
    Vertex_curvature k;
    const auto h0 = detail::geom::canonical_halfedge_into(v, g);
    if (h0 == boost::graph_traits<G>::null_halfedge()) return k;
    const auto null = boost::graph_traits<G>::null_face();
    const Eigen::Vector3d p = point(v, g, pm);
    const auto cot = cotangent_between;
    Eigen::Vector3d laplace = Eigen::Vector3d::Zero();
    double area = 0, angles = 0;
    auto h = h0;
    do {
      if (face(h, g) == null || face(opposite(h, g), g) == null) return k;
      // Face (a, v, c): h = a → v, c the third corner.
      const Eigen::Vector3d a = point(source(h, g), g, pm), c = point(target(next(h, g), g), g, pm);
      const Eigen::Vector3d b = point(target(next(opposite(h, g), g), g), g, pm); // across edge (a, v)
      laplace += (cot(p - c, a - c) + cot(p - b, a - b)) * (a - p);
      const Eigen::Vector3d va = a - p, vc = c - p;
      const double angle_v = angle_between(va, vc), angle_a = angle_between(p - a, c - a);
      const double angle_c = angle_between(p - c, a - c);
      angles += angle_v;
      const double half = std::numbers::pi / 2;
      if (angle_v > half) area += 0.25 * triangle_normal(p, a, c).norm();
      else if (angle_a > half || angle_c > half) area += 0.125 * triangle_normal(p, a, c).norm();
      else area += (va.squaredNorm() * cot(p - c, a - c) + vc.squaredNorm() * cot(p - a, c - a)) / 8;
      h = opposite(next(h, g), g);
    } while (h != h0);
    if (!(area > 0)) return k;
    k.mean = 0.5 * laplace.norm() / (2 * area);
    k.gaussian = (2 * std::numbers::pi - angles) / area;
    const double s = std::sqrt(std::max(0.0, k.mean * k.mean - k.gaussian));
    k.min = k.mean - s;
    k.max = k.mean + s;
    return k;
  }
  template <FaceGraph G>
  Vertex_curvature operator()(vertex_descriptor_t<G> v, const G& g) const {
    return (*this)(v, g, get(vertex_point, g));
  }
} vertex_curvature{};

/// mean_edge_length(g[, pm]): the mean length of g's edges (0 without edges).
inline constexpr struct Mean_edge_length_fn {
  template <class G, PointMapOf<G> PointMap>
    requires HalfedgeGraph<G> && EdgeListGraph<G>
  double operator()(const G& g, const PointMap& pm) const {
    double s = 0;
    std::size_t n = 0;
    for (const auto e : edges(g)) {
      s += edge_length(halfedge(e, g), g, pm);
      ++n;
    }
    return n ? s / static_cast<double>(n) : 0.0;
  }
  template <class G>
    requires HalfedgeGraph<G> && EdgeListGraph<G>
  double operator()(const G& g) const {
    return (*this)(g, get(vertex_point, g));
  }
} mean_edge_length{};

/// bounding_box(g[, pm]): the box of g's vertices (isEmpty() without vertices).
inline constexpr struct Bounding_box_fn {
  template <class G, PointMapOf<G> PointMap>
    requires HalfedgeGraph<G> && VertexListGraph<G>
  Eigen::AlignedBox3d operator()(const G& g, const PointMap& pm) const {
    Eigen::AlignedBox3d box;  // Eigen's default box is empty
    for (const auto v : vertices(g)) box.extend(point(v, g, pm));
    return box;
  }
  template <class G>
    requires HalfedgeGraph<G> && VertexListGraph<G>
  Eigen::AlignedBox3d operator()(const G& g) const {
    return (*this)(g, get(vertex_point, g));
  }
} bounding_box{};

/// diagonal(g[, pm]): the length of the bounding box's diagonal (0 for an empty mesh).
inline constexpr struct Diagonal_fn {
  template <class G, PointMapOf<G> PointMap>
    requires HalfedgeGraph<G> && VertexListGraph<G>
  double operator()(const G& g, const PointMap& pm) const {
    const Eigen::AlignedBox3d b = bounding_box(g, pm);
    return b.isEmpty() ? 0.0 : b.diagonal().norm();
  }
  template <class G>
    requires HalfedgeGraph<G> && VertexListGraph<G>
  double operator()(const G& g) const {
    return (*this)(g, get(vertex_point, g));
  }
} diagonal{};

/// surface_area(g[, pm]): the sum of the face areas.
inline constexpr struct Surface_area_fn {
  template <FaceListGraph G, PointMapOf<G> PointMap>
  double operator()(const G& g, const PointMap& pm) const {
    double s = 0;
    for (const auto f : faces(g)) s += face_area(f, g, pm);
    return s;
  }
  template <FaceListGraph G>
  double operator()(const G& g) const {
    return (*this)(g, get(vertex_point, g));
  }
} surface_area{};

/// volume(g[, pm]): the signed volume enclosed by g: Σ over the fan
/// triangles (p₀, pᵢ, pᵢ₊₁) of every face of p₀ · (pᵢ × pᵢ₊₁) / 6, as CGAL's
/// PMP::volume (positive for a closed, outward-oriented mesh; for an open
/// mesh, the volume of the cone from the origin).
inline constexpr struct Volume_fn {
  template <FaceListGraph G, PointMapOf<G> PointMap>
  double operator()(const G& g, const PointMap& pm) const {
    double s = 0;
    for (const auto f : faces(g)) {
      const auto h0 = detail::geom::canonical_halfedge(f, g);
      const Eigen::Vector3d p0 = point(target(h0, g), g, pm);
      auto h = next(h0, g);
      Eigen::Vector3d prev = point(target(h, g), g, pm);
      for (h = next(h, g); h != h0; h = next(h, g)) {
        const Eigen::Vector3d cur = point(target(h, g), g, pm);
        s += p0.dot(prev.cross(cur));
        prev = cur;
      }
    }
    return s / 6.0;
  }
  template <FaceListGraph G>
  double operator()(const G& g) const {
    return (*this)(g, get(vertex_point, g));
  }
} volume{};

/// Do the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point?
/// Exact for any finite input, degenerate triangles included (a collinear
/// triangle is the segment it spans). Touching counts: two faces of a mesh
/// that share a corner always "intersect" here; for them use
/// faces_intersect() below, which knows which corners are shared.
inline bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                                const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  return detail::tri::triangles(a0, a1, a2, b0, b1, b2);
}

/// Does the closed segment pq meet the closed triangle abc? Exact.
inline bool segment_triangle_intersect(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                       const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c) {
  return detail::tri::segment_triangle(p, q, a, b, c);
}

/// Are the three points on one line? Exact (a degenerate, zero-area triangle).
inline bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return detail::tri::collinear(a, b, c);
}

/// A triangle of a mesh: its corner points and the ids of its vertices
/// (any integers; equal ids mean the same mesh vertex).
template <class Id = std::size_t>
struct Mesh_triangle {
  std::array<Eigen::Vector3d, 3> p;
  std::array<Id, 3> id;
};

/// Do two triangles of one mesh intersect beyond what they share? The
/// shared-vertex-aware test of CGAL's PMP::self_intersections, exactly:
/// - no shared vertex: triangles_intersect();
/// - one shared vertex: the side opposite it in either triangle meets the
///   other triangle;
/// - two shared vertices (a shared edge): the two triangles are coplanar and
///   their third corners lie on the same side of the edge (they overlap);
/// - three (the same corners twice): always.
/// Degenerate triangles are the caller's matter (self_intersections() reports
/// them on their own, as CGAL does).
template <class Id>
bool faces_intersect(const Mesh_triangle<Id>& a, const Mesh_triangle<Id>& b) {
  int shared = 0, ia = -1, ib = -1;
  std::array<bool, 3> a_shared{}, b_shared{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.id[i] == b.id[j]) {
        ++shared;
        a_shared[i] = b_shared[j] = true;
        if (ia < 0) ia = i, ib = j;
      }
  if (shared == 0) return triangles_intersect(a.p[0], a.p[1], a.p[2], b.p[0], b.p[1], b.p[2]);
  if (shared >= 3) return true;
  if (shared == 2) {
    int ra = 0, rb = 0;
    while (a_shared[ra]) ++ra;
    while (b_shared[rb]) ++rb;
    const Eigen::Vector3d& u = a.p[(ra + 1) % 3];
    const Eigen::Vector3d& v = a.p[(ra + 2) % 3];
    const Eigen::Vector3d& r = a.p[ra];
    const Eigen::Vector3d& s = b.p[rb];
    if (detail::pred::orient3d(u, v, r, s) != 0) return false;
    // r and s on the same side of the line uv in their common plane: their
    // 2D orientations agree in every projection where r's is not zero.
    for (int axis = 0; axis < 3; ++axis) {
      using detail::tri::o2;
      using detail::tri::project;
      const int or_ = o2(project(u, axis), project(v, axis), project(r, axis));
      if (or_ != 0) return o2(project(u, axis), project(v, axis), project(s, axis)) == or_;
    }
    return false;  // a degenerate triangle: not this test's matter
  }
  const auto& sa = a.p;
  const auto& sb = b.p;
  return segment_triangle_intersect(sb[(ib + 1) % 3], sb[(ib + 2) % 3], sa[0], sa[1], sa[2]) ||
         segment_triangle_intersect(sa[(ia + 1) % 3], sa[(ia + 2) % 3], sb[0], sb[1], sb[2]);
}

} // namespace genmesh
