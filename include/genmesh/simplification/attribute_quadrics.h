// genmesh/simplification/attribute_quadrics.h — the quadric policy of
// genmesh::simplify that respects per-vertex attributes (colours, texture
// coordinates, normals, ...).
//
// Garland & Heckbert, "Simplifying surfaces with color and texture using
// quadric error metrics" (IEEE Visualization 1998): each vertex is a point of
// R^(3+k), its position followed by its k attribute values, each times its
// weight; a triangle contributes the squared distance to its plane in that
// space (the 2-plane through its three lifted corners). A collapse goes to
// the point of R^(3+k) minimizing the summed quadric: a position and the
// attribute values of the survivor, which simplify() hands back through
// .write. So an edge across a colour or UV seam costs what the seam would
// lose, and the survivor gets the values that fit its neighbourhood best.
// (Hoppe's 1999 metric is a variant of this one with a smaller matrix; the
// minimizer is the same for k ≤ 3 up to the weighting of the geometric term.)
//
//   std::vector<double> rgb(3 * n);  // by vertex index
//   genmesh::Attribute_quadrics a{.dimension = 3,
//       .read = [&](std::size_t v, double* out) { std::copy_n(&rgb[3 * v], 3, out); },
//       .write = [&](std::size_t v, const double* in) { std::copy_n(in, 3, &rgb[3 * v]); },
//       .weights = {0.1, 0.1, 0.1}};
//   genmesh::simplify(mesh, genmesh::Simplification_options<genmesh::Attribute_quadrics>{
//       .target_ratio = 0.1, .policy = a});
//
// The cost is the squared distance in R^(3+k): geometric distance squared
// plus (weight × attribute deviation) squared, so a weight says how many
// model units one unit of the attribute is worth. With dimension 0 this is
// Plane_quadrics without its fallback to the segment's minimizer. Deterministic across backends as
// the other policies (corners in canonical order, sums in face order).
#pragma once

#include <genmesh/exceptions.h>
#include <genmesh/geometry.h>
#include <genmesh/simplification/quadric.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace genmesh {

/// A quadric over R^n: Q(v) = vᵀAv + 2bᵀv + c, A symmetric n × n. The
/// default (n = 0) is the zero quadric of any dimension.
struct Generalized_quadric {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
  double c = 0;

  Eigen::Index dimension() const { return b.size(); }

  friend Generalized_quadric operator+(const Generalized_quadric& x, const Generalized_quadric& y) {
    if (x.dimension() == 0) return y;
    if (y.dimension() == 0) return x;
    return {x.a + y.a, x.b + y.b, x.c + y.c};
  }

  /// Q(v), clamped at 0.
  double operator()(const Eigen::VectorXd& v) const {
    if (dimension() == 0) return 0.0;
    const double r = v.dot(a * v) + 2 * b.dot(v) + c;
    return r > 0 ? r : 0.0;
  }

  /// The quadric of the 2-plane through p, q, r in R^n (Garland & Heckbert
  /// 1998, with orthonormal e₁, e₂ spanning it), times w; zero when they are
  /// collinear.
  static Generalized_quadric plane_through(const Eigen::VectorXd& p, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& r, double w) {
    const Eigen::Index n = p.size();
    Generalized_quadric g{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n), 0.0};
    Eigen::VectorXd e1 = q - p;
    const double l1 = e1.norm();
    if (!(l1 > 0)) return g;
    e1 /= l1;
    Eigen::VectorXd e2 = r - p;
    e2 -= e1.dot(e2) * e1;
    const double l2 = e2.norm();
    if (!(l2 > 0)) return g;
    e2 /= l2;
    const double p1 = p.dot(e1), p2 = p.dot(e2);
    g.a = w * (Eigen::MatrixXd::Identity(n, n) - e1 * e1.transpose() - e2 * e2.transpose());
    g.b = w * (p1 * e1 + p2 * e2 - p);
    g.c = w * (p.squaredNorm() - p1 * p1 - p2 * p2);
    return g;
  }
};

/// Garland–Heckbert 1998 quadrics over position and `dimension` attribute
/// values per vertex (see the top of this header). .read gives a vertex's
/// values before the first collapse; .write receives the survivor's optimal
/// values after each collapse (both by vertex index; .write may be empty).
struct Attribute_quadrics {
  /// Attribute values per vertex.
  std::size_t dimension = 0;
  /// Reads the `dimension` values of a vertex (by vertex index) into out.
  std::function<void(std::size_t vertex_index, double* out)> read = {};
  /// Receives the `dimension` values of the survivor of each collapse.
  std::function<void(std::size_t vertex_index, const double* values)> write = {};
  /// Per value: model units per unit of the value (empty: all 1; > 0).
  std::vector<double> weights = {};
  /// Weight each triangle's quadric by its area (in R^3).
  bool area_weighted = false;
  /// The optimal point is refused (the best of the ends and the midpoint
  /// taken instead) when A's LU pivots fall below this times the largest.
  double conditioning = 1e-9;
  /// The optimal position may be at most this many edge lengths from the midpoint.
  double max_distance_factor = 2.0;

  using Vertex_data = Generalized_quadric;

  /// A triangle's contribution (corners with their vertex indices, so that
  /// the attributes can be read).
  Generalized_quadric face(std::size_t ia, const Eigen::Vector3d& a, std::size_t ib, const Eigen::Vector3d& b,
                           std::size_t ic, const Eigen::Vector3d& c) const {
    const double w = area_weighted ? 0.5 * triangle_normal(a, b, c).norm() : 1.0;
    return Generalized_quadric::plane_through(lift(ia, a), lift(ib, b), lift(ic, c), w);
  }

  /// The border quadric of Plane_quadrics, on the geometric coordinates.
  Generalized_quadric border(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                             double weight) const {
    const Quadric q = detail::simplification::border_plane(a, b, c, weight, area_weighted);
    const Eigen::Index n = 3 + static_cast<Eigen::Index>(dimension);
    Generalized_quadric g{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n), q.c};
    g.a.topLeftCorner<3, 3>() << q.a00, q.a01, q.a02, q.a01, q.a11, q.a12, q.a02, q.a12, q.a22;
    g.b.head<3>() << q.b0, q.b1, q.b2;
    return g;
  }

  Placement place(const Generalized_quadric& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    if (q.dimension() == 0) return {0.0, 0.5 * (a + b)};
    Eigen::FullPivLU<Eigen::MatrixXd> lu(q.a);
    lu.setThreshold(conditioning);
    if (lu.isInvertible()) {
      const Eigen::VectorXd v = lu.solve(-q.b);
      const Eigen::Vector3d x = v.head<3>();
      const double limit = max_distance_factor * max_distance_factor * (b - a).squaredNorm();
      if (v.allFinite() && (x - 0.5 * (a + b)).squaredNorm() <= limit) return {q(v), x};
    }
    Placement r = fixed(q, a, b, a);
    const Placement pb = fixed(q, a, b, b);
    if (pb.cost < r.cost) r = pb;
    const Placement pm = fixed(q, a, b, 0.5 * (a + b));
    if (pm.cost < r.cost) r = pm;
    return r;
  }

  /// The cost at position x with the best attribute values there.
  Placement fixed(const Generalized_quadric& q, const Eigen::Vector3d&, const Eigen::Vector3d&,
                  const Eigen::Vector3d& x) const {
    if (q.dimension() == 0) return {0.0, x};
    return {q(best_at(q, x)), x};
  }

  /// After a collapse: the survivor's values, the minimizer at its position.
  void collapsed(std::size_t survivor, const Generalized_quadric& q, const Eigen::Vector3d& x) const {
    if (!write || dimension == 0 || q.dimension() == 0) return;
    const Eigen::VectorXd v = best_at(q, x);
    std::vector<double> values(dimension);
    for (std::size_t i = 0; i < dimension; ++i) values[i] = v[3 + static_cast<Eigen::Index>(i)] / weight(i);
    write(survivor, values.data());
  }

 private:
  double weight(std::size_t i) const { return i < weights.size() ? weights[i] : 1.0; }

  // (x, weight · values of vertex v).
  Eigen::VectorXd lift(std::size_t v, const Eigen::Vector3d& x) const {
    Eigen::VectorXd r(3 + static_cast<Eigen::Index>(dimension));
    r.head<3>() = x;
    if (dimension > 0) {
      if (!read) throw invalid_input("simplify: Attribute_quadrics has a dimension but no .read");
      std::vector<double> values(dimension);
      read(v, values.data());
      for (std::size_t i = 0; i < dimension; ++i) r[3 + static_cast<Eigen::Index>(i)] = weight(i) * values[i];
    }
    return r;
  }

  // (x, s) with s minimizing Q(x, ·): A_ss s = −(A_sx x + b_s). A_ss is
  // positive semi-definite; a tiny multiple of its trace on the diagonal
  // makes it definite where a vertex's faces do not constrain a value.
  static Eigen::VectorXd best_at(const Generalized_quadric& q, const Eigen::Vector3d& x) {
    const Eigen::Index n = q.dimension(), k = n - 3;
    Eigen::VectorXd v(n);
    v.head<3>() = x;
    if (k == 0) return v;
    Eigen::MatrixXd ass = q.a.bottomRightCorner(k, k);
    const double tiny = 1e-12 * std::max(ass.trace(), std::numeric_limits<double>::min());
    ass.diagonal().array() += tiny;
    const Eigen::VectorXd rhs = -(q.a.bottomLeftCorner(k, 3) * x + q.b.tail(k));
    v.tail(k) = ass.ldlt().solve(rhs);
    return v;
  }
};

} // namespace genmesh
