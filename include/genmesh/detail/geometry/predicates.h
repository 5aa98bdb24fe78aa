// genmesh/detail/geometry/predicates.h — exact orientation predicates on double input.
//
// orient3d and orient2d return the exact sign of their determinant for any
// finite double input: a floating-point evaluation with Shewchuk's static
// error bound answers almost every call; the rest are decided exactly with
// floating-point expansions (Shewchuk 1997, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates"), written
// here without the adaptive middle stages: only degenerate or nearly
// degenerate input reaches the exact path.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

namespace genmesh::detail::pred {

// Only nearly degenerate input reaches the expansions: plain vectors will do.
using Expansion = std::vector<double>;

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// e + b, e nonoverlapping with increasing magnitude; zero components dropped.
inline Expansion grow(const Expansion& e, double b) {
  Expansion h;
  double q = b;
  for (const double ei : e) {
    double s, t;
    two_sum(q, ei, s, t);
    if (t != 0) h.push_back(t);
    q = s;
  }
  if (q != 0 || h.empty()) h.push_back(q);
  return h;
}

inline Expansion sum(const Expansion& e, const Expansion& f) {
  Expansion h = e;
  for (const double fi : f) h = grow(h, fi);
  return h;
}

inline Expansion negate(Expansion e) {
  for (double& x : e) x = -x;
  return e;
}

inline Expansion scale(const Expansion& e, double b) {
  Expansion h;
  double q, t;
  two_product(e[0], b, q, t);
  if (t != 0) h.push_back(t);
  for (std::size_t i = 1; i < e.size(); ++i) {
    double p1, p0, s;
    two_product(e[i], b, p1, p0);
    two_sum(q, p0, s, t);
    if (t != 0) h.push_back(t);
    two_sum(p1, s, q, t);
    if (t != 0) h.push_back(t);
  }
  if (q != 0 || h.empty()) h.push_back(q);
  return h;
}

inline Expansion product(const Expansion& e, const Expansion& f) {
  Expansion h{0.0};
  for (const double fi : f) h = sum(h, scale(e, fi));
  return h;
}

inline Expansion difference(double a, double b) {
  double x, y;
  two_sum(a, -b, x, y);
  Expansion h;
  if (y != 0) h.push_back(y);
  if (x != 0 || h.empty()) h.push_back(x);
  return h;
}

inline int sign_of(const Expansion& e) {
  for (auto it = e.rbegin(); it != e.rend(); ++it)
    if (*it != 0) return *it > 0 ? 1 : -1;
  return 0;
}

inline constexpr double eps = std::numeric_limits<double>::epsilon() / 2; // 2^-53
inline constexpr double o3d_bound = (7.0 + 56.0 * eps) * eps;
inline constexpr double o2d_bound = (3.0 + 16.0 * eps) * eps;

/// Sign of (b − a) × (c − a) · (d − a): +1 when d lies on the side the
/// normal of the counter-clockwise triangle a, b, c points to.
inline int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& d) {
  const double bx = b.x() - a.x(), by = b.y() - a.y(), bz = b.z() - a.z();
  const double cx = c.x() - a.x(), cy = c.y() - a.y(), cz = c.z() - a.z();
  const double dx = d.x() - a.x(), dy = d.y() - a.y(), dz = d.z() - a.z();
  const double m1 = by * cz - bz * cy, m2 = bz * cx - bx * cz, m3 = bx * cy - by * cx;
  const double det = dx * m1 + dy * m2 + dz * m3;
  const double perm = std::abs(dx) * (std::abs(by * cz) + std::abs(bz * cy)) +
                      std::abs(dy) * (std::abs(bz * cx) + std::abs(bx * cz)) +
                      std::abs(dz) * (std::abs(bx * cy) + std::abs(by * cx));
  const double bound = o3d_bound * perm;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  if (perm == 0) return 0;
  // Exact: the differences as two-component expansions, the determinant by
  // cofactors along d.
  const Expansion ebx = difference(b.x(), a.x()), eby = difference(b.y(), a.y()),
                  ebz = difference(b.z(), a.z());
  const Expansion ecx = difference(c.x(), a.x()), ecy = difference(c.y(), a.y()),
                  ecz = difference(c.z(), a.z());
  const Expansion edx = difference(d.x(), a.x()), edy = difference(d.y(), a.y()),
                  edz = difference(d.z(), a.z());
  const Expansion e1 = sum(product(eby, ecz), negate(product(ebz, ecy)));
  const Expansion e2 = sum(product(ebz, ecx), negate(product(ebx, ecz)));
  const Expansion e3 = sum(product(ebx, ecy), negate(product(eby, ecx)));
  return sign_of(sum(sum(product(edx, e1), product(edy, e2)), product(edz, e3)));
}

/// Sign of (b − a) × (c − a) for 2D points (x, y): +1 counter-clockwise.
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double l = (bx - ax) * (cy - ay), r = (by - ay) * (cx - ax);
  const double det = l - r;
  const double bound = o2d_bound * (std::abs(l) + std::abs(r));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  if (l == 0 && r == 0) return 0;
  const Expansion ebx = difference(bx, ax), eby = difference(by, ay);
  const Expansion ecx = difference(cx, ax), ecy = difference(cy, ay);
  return sign_of(sum(product(ebx, ecy), negate(product(eby, ecx))));
}

} // namespace genmesh::detail::pred
