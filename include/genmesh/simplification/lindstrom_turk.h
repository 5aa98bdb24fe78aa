// genmesh/simplification/lindstrom_turk.h — the memoryless cost and
// placement of Lindstrom & Turk, "Fast and memory efficient polygonal
// simplification" (IEEE Visualization 1998), as CGAL's
// Surface_mesh_simplification uses it by default.
//
// Nothing is accumulated: each evaluation looks at the current triangles
// around the edge's two ends (a Collapse_profile). For a new point x:
// - volume: each triangle (a, b, c) and x span a tetrahedron; its signed
//   volume V = (n·x − det(a, b, c)) / 6 with n = (b − a) × (c − a) is what
//   the collapse adds or removes locally. Cost Σ V².
// - boundary: each border edge s → t and x span a triangle; its area
//   |(t − s) × (t − x)| / 2 is how far the border moves. Cost Σ area².
// - shape: Σ |x − link vertex|², favouring well-shaped triangles.
// Cost = w_v · volume + w_b · boundary · L² + w_s · shape · L⁴ with L the
// edge's length (the powers make the terms commensurate: volume², area²·L²,
// length²·L⁴ are all length⁶). Its square root (what .max_error bounds) has
// the unit length³, not a distance.
//
// Placement: x is fixed by three linear constraints taken in priority order,
// each kept only if its direction makes at least `alpha_degrees` with the
// ones already kept (so the 3×3 system stays well conditioned):
// 1. boundary preservation (border edges only): the sum of the border
//    edges' area vectors is unchanged — its gradient conditions;
// 2. volume preservation: Σ V = 0 (one plane);
// 3. boundary and volume optimization: the minimizer of w_v Σ V² +
//    9 w_b L² Σ area², restricted to the planes kept so far;
// 4. shape optimization: the minimizer of Σ |x − link|², likewise.
// If fewer than three constraints survive (a flat, featureless patch cannot
// happen: shape always adds what is missing), the edge is refused for now.
// All of it is computed relative to the edge's first end, which changes no
// result mathematically and keeps the determinants of far-from-origin
// meshes from cancelling.
#pragma once

#include <genmesh/simplification/profile.h>
#include <genmesh/simplification/quadric.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <numbers>

namespace genmesh {

namespace detail::simplification {

// Up to three linear constraints aᵢ·x = bᵢ with unit aᵢ, each added only when
// it is "alpha-compatible" with those already held (Lindstrom & Turk 1998, §3).
class Lt_constraints {
 public:
  explicit Lt_constraints(double alpha_radians)
      : cos2_(std::cos(alpha_radians) * std::cos(alpha_radians)),
        sin2_(std::sin(alpha_radians) * std::sin(alpha_radians)) {}

  int count() const { return n_; }

  void add(const Eigen::Vector3d& a, double b) {
    const double aa = a.squaredNorm();
    if (!std::isfinite(aa) || !(aa > 0)) return;
    if (n_ == 1) {
      // Not within alpha of parallel to the first.
      const Eigen::Vector3d a0 = rows_.row(0);
      const double d = a0.dot(a);
      if (d * d > a0.squaredNorm() * aa * cos2_) return;
    } else if (n_ == 2) {
      // Not within alpha of the plane of the first two.
      const Eigen::Vector3d m = Eigen::Vector3d(rows_.row(0)).cross(Eigen::Vector3d(rows_.row(1)));
      const double d = m.dot(a);
      if (d * d <= m.squaredNorm() * aa * sin2_) return;
    } else if (n_ == 3) {
      return;
    }
    const double len = std::sqrt(aa);
    rows_.row(n_) = a / len;
    rhs_[n_] = b / len;
    ++n_;
  }

  // The constraints that minimize ½xᵀHx + cᵀx in the subspace the constraints
  // held so far leave free: ∇ = Hx + c = 0 along each free direction q,
  // i.e. (Hq)·x = −q·c.
  void add_minimizer(const Eigen::Matrix3d& h, const Eigen::Vector3d& c) {
    if (n_ == 0) {
      for (int i = 0; i < 3; ++i) add(h.row(i).transpose(), -c[i]);
    } else if (n_ == 1) {
      const Eigen::Vector3d a0 = rows_.row(0);
      // A direction perpendicular to a0, from its largest component.
      Eigen::Index k = 0;
      a0.cwiseAbs().maxCoeff(&k);
      const Eigen::Vector3d q0 = k == 0   ? Eigen::Vector3d(-a0.z() / a0.x(), 0, 1)
                                 : k == 1 ? Eigen::Vector3d(0, -a0.z() / a0.y(), 1)
                                          : Eigen::Vector3d(1, 0, -a0.x() / a0.z());
      const Eigen::Vector3d q1 = a0.cross(q0);
      add(h * q0, -q0.dot(c));
      add(h * q1, -q1.dot(c));
    } else if (n_ == 2) {
      const Eigen::Vector3d q = Eigen::Vector3d(rows_.row(0)).cross(Eigen::Vector3d(rows_.row(1)));
      add(h * q, -q.dot(c));
    }
  }

  // The point all three constraints meet at, if they are three and it is finite.
  bool solve(Eigen::Vector3d& x) const {
    if (n_ != 3) return false;
    const double det = rows_.determinant();
    if (!(std::abs(det) > 0)) return false;
    x = rows_.inverse() * rhs_;
    return x.allFinite();
  }

 private:
  Eigen::Matrix3d rows_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs_ = Eigen::Vector3d::Zero();
  int n_ = 0;
  double cos2_, sin2_;
};

// |u|² I − u uᵀ: the quadratic form of |u × x|².
inline Eigen::Matrix3d cross_form(const Eigen::Vector3d& u) {
  return u.squaredNorm() * Eigen::Matrix3d::Identity() - u * u.transpose();
}

} // namespace detail::simplification

/// Lindstrom–Turk memoryless cost and placement (CGAL's default policy; see
/// the top of this header). Weights as CGAL's defaults: volume 0.5,
/// boundary 0.5, shape 0 (shape still breaks ties in the placement).
/// Border edges count only with Border_mode::preserve and lock
/// (.border_weight of Simplification_options is not used: boundary_weight is).
struct Lindstrom_turk {
  double volume_weight = 0.5;
  double boundary_weight = 0.5;
  double shape_weight = 0.0;
  /// The smallest angle between two placement constraints, degrees.
  double alpha_degrees = 1.0;

  static constexpr bool memoryless = true;
  /// simplify's default .max_normal_deviation with this policy: flips only.
  static constexpr double default_max_normal_deviation = 90.0;

  Placement place(const Collapse_profile& p) const {
    using namespace detail::simplification;
    const Eigen::Vector3d o = p.p0;
    Lt_constraints k(alpha_degrees * std::numbers::pi / 180.0);
    // Border data relative to o: e = t − s, m = t × s.
    Eigen::Vector3d sum_e = Eigen::Vector3d::Zero(), sum_m = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hb = Eigen::Matrix3d::Zero();
    Eigen::Vector3d cb = Eigen::Vector3d::Zero();
    for (const auto& b : p.border_edges) {
      const Eigen::Vector3d s = b.s - o, t = b.t - o;
      const Eigen::Vector3d e = t - s, m = t.cross(s);
      sum_e += e;
      sum_m += m;
      hb += cross_form(e);
      cb += e.cross(m);
    }
    // 1. Boundary preservation.
    if (!p.border_edges.empty()) k.add_minimizer(cross_form(sum_e), sum_e.cross(sum_m));
    // 2. Volume preservation; 3. volume (and boundary) optimization.
    Eigen::Vector3d sum_n = Eigen::Vector3d::Zero();
    double sum_l = 0;
    Eigen::Matrix3d hv = Eigen::Matrix3d::Zero();
    Eigen::Vector3d cv = Eigen::Vector3d::Zero();
    for (const auto& t : p.triangles) {
      const Eigen::Vector3d a = t.a - o, b = t.b - o, c = t.c - o;
      const Eigen::Vector3d n = triangle_normal(a, b, c);
      const double l = a.cross(b).dot(c);
      sum_n += n;
      sum_l += l;
      hv += n * n.transpose();
      cv -= l * n;
    }
    if (k.count() < 3) k.add(sum_n, sum_l);
    if (k.count() < 3) {
      if (p.border_edges.empty()) {
        k.add_minimizer(hv, cv);
      } else {
        const double w = 9.0 * boundary_weight * (p.p1 - p.p0).squaredNorm();
        k.add_minimizer(volume_weight * hv + w * hb, volume_weight * cv + w * cb);
      }
    }
    // 4. Shape optimization.
    if (k.count() < 3) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const auto& q : p.link) c -= q - o;
      k.add_minimizer(static_cast<double>(p.link.size()) * Eigen::Matrix3d::Identity(), c);
    }
    Eigen::Vector3d x;
    if (!k.solve(x)) return {};
    return fixed(p, x + o);
  }

  Placement fixed(const Collapse_profile& p, const Eigen::Vector3d& x) const {
    const Eigen::Vector3d o = p.p0, v = x - o;
    const double l2 = (p.p1 - p.p0).squaredNorm();
    double volume = 0, boundary = 0, shape = 0;
    for (const auto& t : p.triangles) {
      const Eigen::Vector3d a = t.a - o, b = t.b - o, c = t.c - o;
      const double f = triangle_normal(a, b, c).dot(v) - a.cross(b).dot(c);
      volume += f * f;
    }
    for (const auto& b : p.border_edges) boundary += (b.t - b.s).cross(b.t - x).squaredNorm();
    if (shape_weight != 0)
      for (const auto& q : p.link) shape += (x - q).squaredNorm();
    const double cost = volume_weight * volume / 36.0 + boundary_weight * boundary / 4.0 * l2 +
                        shape_weight * shape * l2 * l2;
    if (!std::isfinite(cost)) return {};
    return {cost, x};
  }
};

} // namespace genmesh
