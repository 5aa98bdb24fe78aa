// genmesh/detail/geometry/triangle_intersection.h — exact intersection tests between
// closed triangles and segments in 3D (the machinery of triangles_intersect in
// <genmesh/geometry.h>).
//
// Non-degenerate, non-coplanar triangles: Guigue & Devillers, "Fast and
// robust triangle-triangle overlap test using orientation predicates" (JGT
// 2003), the test CGAL's do_intersect(Triangle_3, Triangle_3) uses; every
// decision is an exact orient3d sign, so touching counts and nothing depends
// on rounding. Coplanar input and degenerate (collinear) triangles go
// through exact 2D tests: coplanar sets intersect iff their projections onto
// all three axis planes intersect (intersecting sets project to intersecting
// sets, and at least one projection is one-to-one on their common plane).
#pragma once

#include <genmesh/detail/geometry/predicates.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>

namespace genmesh::detail::tri {

using Vec = Eigen::Vector3d;
using pred::orient3d;

struct P2 {
  double x, y;
};

inline P2 project(const Vec& p, int axis) {
  switch (axis) {
    case 0: return {p.y(), p.z()};
    case 1: return {p.z(), p.x()};
    default: return {p.x(), p.y()};
  }
}

inline int o2(P2 a, P2 b, P2 c) { return pred::orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

// c on the closed segment ab, given that a, b, c are collinear.
inline bool on_segment(P2 a, P2 b, P2 c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

inline bool segments_2d(P2 p, P2 q, P2 r, P2 s) {
  const int o1 = o2(p, q, r), o2_ = o2(p, q, s), o3 = o2(r, s, p), o4 = o2(r, s, q);
  if (o1 * o2_ < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && on_segment(p, q, r)) return true;
  if (o2_ == 0 && on_segment(p, q, s)) return true;
  if (o3 == 0 && on_segment(r, s, p)) return true;
  if (o4 == 0 && on_segment(r, s, q)) return true;
  return false;
}

// p in the closed triangle abc, abc not degenerate (orientation o != 0).
inline bool point_in_triangle_2d(P2 p, P2 a, P2 b, P2 c, int o) {
  return o2(a, b, p) * o >= 0 && o2(b, c, p) * o >= 0 && o2(c, a, p) * o >= 0;
}

// Two closed "triangles" in 2D, each possibly degenerate (a segment or a point).
inline bool triangles_2d(const std::array<P2, 3>& a, const std::array<P2, 3>& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_2d(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return true;
  const int oa = o2(a[0], a[1], a[2]), ob = o2(b[0], b[1], b[2]);
  if (ob != 0 && point_in_triangle_2d(a[0], b[0], b[1], b[2], ob)) return true;
  if (oa != 0 && point_in_triangle_2d(b[0], a[0], a[1], a[2], oa)) return true;
  return false;
}

// Coplanar closed triangles (or segments: repeat a corner).
inline bool coplanar_triangles(const Vec& p1, const Vec& q1, const Vec& r1, const Vec& p2,
                               const Vec& q2, const Vec& r2) {
  for (int axis = 0; axis < 3; ++axis)
    if (!triangles_2d({project(p1, axis), project(q1, axis), project(r1, axis)},
                      {project(p2, axis), project(q2, axis), project(r2, axis)}))
      return false;
  return true;
}

/// Exact: are a, b, c on one line (or equal)?
inline bool collinear(const Vec& a, const Vec& b, const Vec& c) {
  for (int axis = 0; axis < 3; ++axis)
    if (o2(project(a, axis), project(b, axis), project(c, axis)) != 0) return false;
  return true;
}

// Closed segment pq against closed non-degenerate triangle abc.
inline bool segment_triangle_nondegenerate(const Vec& p, const Vec& q, const Vec& a, const Vec& b,
                                           const Vec& c) {
  const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) return coplanar_triangles(p, q, q, a, b, c);
  // The line pq crosses the plane at one point; it lies in the triangle iff
  // the line passes on one side of all three edges (no two opposite signs).
  const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  const bool pos = s1 > 0 || s2 > 0 || s3 > 0, neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(pos && neg);
}

// Closed segments pq and rs in 3D.
inline bool segments_3d(const Vec& p, const Vec& q, const Vec& r, const Vec& s) {
  if (orient3d(p, q, r, s) != 0) return false;
  return coplanar_triangles(p, q, q, r, s, s);
}

/// Closed segment pq against the closed triangle abc (any degeneracy).
inline bool segment_triangle(const Vec& p, const Vec& q, const Vec& a, const Vec& b, const Vec& c) {
  if (!collinear(a, b, c)) return segment_triangle_nondegenerate(p, q, a, b, c);
  return segments_3d(p, q, a, b) || segments_3d(p, q, b, c) || segments_3d(p, q, c, a);
}

// Guigue–Devillers, after the triangle 1 corners were rotated so that p1 is
// alone on its side of triangle 2's plane (and triangle 2 reoriented to
// match): the intervals on the intersection line overlap.
inline bool check_min_max(const Vec& p1, const Vec& q1, const Vec& r1, const Vec& p2,
                          const Vec& q2, const Vec& r2) {
  if (orient3d(q1, p2, p1, q2) > 0) return false;
  if (orient3d(p1, p2, r1, r2) > 0) return false;
  return true;
}

inline bool tri_tri_3d(const Vec& p1, const Vec& q1, const Vec& r1, const Vec& p2, const Vec& q2,
                       const Vec& r2, int dp2, int dq2, int dr2, const Vec& P1, const Vec& Q1,
                       const Vec& R1, const Vec& P2, const Vec& Q2, const Vec& R2) {
  if (dp2 > 0) {
    if (dq2 > 0) return check_min_max(p1, r1, q1, r2, p2, q2);
    if (dr2 > 0) return check_min_max(p1, r1, q1, q2, r2, p2);
    return check_min_max(p1, q1, r1, p2, q2, r2);
  }
  if (dp2 < 0) {
    if (dq2 < 0) return check_min_max(p1, q1, r1, r2, p2, q2);
    if (dr2 < 0) return check_min_max(p1, q1, r1, q2, r2, p2);
    return check_min_max(p1, r1, q1, p2, q2, r2);
  }
  if (dq2 < 0) {
    if (dr2 >= 0) return check_min_max(p1, r1, q1, q2, r2, p2);
    return check_min_max(p1, q1, r1, p2, q2, r2);
  }
  if (dq2 > 0) {
    if (dr2 > 0) return check_min_max(p1, r1, q1, p2, q2, r2);
    return check_min_max(p1, q1, r1, q2, r2, p2);
  }
  if (dr2 > 0) return check_min_max(p1, q1, r1, r2, p2, q2);
  if (dr2 < 0) return check_min_max(p1, r1, q1, r2, p2, q2);
  return coplanar_triangles(P1, Q1, R1, P2, Q2, R2);
}

// Both triangles non-degenerate.
inline bool triangles_nondegenerate(const Vec& p1, const Vec& q1, const Vec& r1, const Vec& p2,
                                    const Vec& q2, const Vec& r2) {
  const int dp1 = orient3d(p2, q2, r2, p1), dq1 = orient3d(p2, q2, r2, q1),
            dr1 = orient3d(p2, q2, r2, r1);
  if (dp1 * dq1 > 0 && dp1 * dr1 > 0) return false;
  const int dp2 = orient3d(p1, q1, r1, p2), dq2 = orient3d(p1, q1, r1, q2),
            dr2 = orient3d(p1, q1, r1, r2);
  if (dp2 * dq2 > 0 && dp2 * dr2 > 0) return false;
  auto go = [&](const Vec& a, const Vec& b, const Vec& c, bool flip2) {
    return flip2 ? tri_tri_3d(a, b, c, p2, r2, q2, dp2, dr2, dq2, p1, q1, r1, p2, q2, r2)
                 : tri_tri_3d(a, b, c, p2, q2, r2, dp2, dq2, dr2, p1, q1, r1, p2, q2, r2);
  };
  if (dp1 > 0) {
    if (dq1 > 0) return go(r1, p1, q1, true);
    if (dr1 > 0) return go(q1, r1, p1, true);
    return go(p1, q1, r1, false);
  }
  if (dp1 < 0) {
    if (dq1 < 0) return go(r1, p1, q1, false);
    if (dr1 < 0) return go(q1, r1, p1, false);
    return go(p1, q1, r1, true);
  }
  if (dq1 < 0) {
    if (dr1 >= 0) return go(q1, r1, p1, true);
    return go(p1, q1, r1, false);
  }
  if (dq1 > 0) {
    if (dr1 > 0) return go(p1, q1, r1, true);
    return go(q1, r1, p1, false);
  }
  if (dr1 > 0) return go(r1, p1, q1, false);
  if (dr1 < 0) return go(r1, p1, q1, true);
  return coplanar_triangles(p1, q1, r1, p2, q2, r2);
}

/// Closed triangles, any degeneracy.
inline bool triangles(const Vec& a0, const Vec& a1, const Vec& a2, const Vec& b0, const Vec& b1,
                      const Vec& b2) {
  const bool da = collinear(a0, a1, a2), db = collinear(b0, b1, b2);
  if (!da && !db) return triangles_nondegenerate(a0, a1, a2, b0, b1, b2);
  if (da && !db)
    return segment_triangle_nondegenerate(a0, a1, b0, b1, b2) ||
           segment_triangle_nondegenerate(a1, a2, b0, b1, b2) ||
           segment_triangle_nondegenerate(a2, a0, b0, b1, b2);
  if (!da)
    return segment_triangle_nondegenerate(b0, b1, a0, a1, a2) ||
           segment_triangle_nondegenerate(b1, b2, a0, a1, a2) ||
           segment_triangle_nondegenerate(b2, b0, a0, a1, a2);
  const std::array<const Vec*, 3> a{&a0, &a1, &a2}, b{&b0, &b1, &b2};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_3d(*a[i], *a[(i + 1) % 3], *b[j], *b[(j + 1) % 3])) return true;
  return false;
}

} // namespace genmesh::detail::tri
