// genmesh/point_traits.h — how genmesh reads and makes points of any type.
//
// Algorithms compute in Eigen::Vector3d and read/write user points through
// Point_traits<P>. Specializations exist for Eigen fixed-size 3-vectors and
// std::array<T,3>; adaptors/ add CGAL::Point_3 and OpenMesh::VectorT.
#pragma once

#include <Eigen/Core>

#include <array>
#include <type_traits>

namespace genmesh {

/// Point_traits<P>: `static double coord(const P&, int i)` and
/// `static P make(double x, double y, double z)`.
template <class P, class Enable = void>
struct Point_traits;

template <class Scalar>
struct Point_traits<Eigen::Matrix<Scalar, 3, 1>> {
  using Point = Eigen::Matrix<Scalar, 3, 1>;
  static double coord(const Point& p, int i) { return static_cast<double>(p[i]); }
  static Point make(double x, double y, double z) {
    return Point(static_cast<Scalar>(x), static_cast<Scalar>(y), static_cast<Scalar>(z));
  }
};

template <class Scalar>
struct Point_traits<std::array<Scalar, 3>> {
  using Point = std::array<Scalar, 3>;
  static double coord(const Point& p, int i) { return static_cast<double>(p[i]); }
  static Point make(double x, double y, double z) {
    return {static_cast<Scalar>(x), static_cast<Scalar>(y), static_cast<Scalar>(z)};
  }
};

/// A point type genmesh can read and make.
template <class P>
concept Point3 = requires(const P& p) {
  { Point_traits<P>::coord(p, 0) } -> std::convertible_to<double>;
  { Point_traits<P>::make(0.0, 0.0, 0.0) } -> std::convertible_to<P>;
};

/// The point as Eigen::Vector3d, for internal arithmetic.
template <Point3 P>
Eigen::Vector3d to_eigen(const P& p) {
  using T = Point_traits<P>;
  return {T::coord(p, 0), T::coord(p, 1), T::coord(p, 2)};
}

/// The Eigen vector as a P.
template <Point3 P>
P from_eigen(const Eigen::Vector3d& v) {
  return Point_traits<P>::make(v.x(), v.y(), v.z());
}

namespace detail {
/// The origin for a 3D point type, a value-initialized P otherwise: the
/// position of a vertex added without one.
template <class P>
P default_point() {
  if constexpr (Point3<P>)
    return Point_traits<P>::make(0.0, 0.0, 0.0);
  else
    return P{};
}
} // namespace detail

} // namespace genmesh
