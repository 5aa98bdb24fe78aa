// genmesh/attribute_traits.h — how genmesh reads and writes the value of a
// per-vertex attribute (a colour, a normal, texture coordinates) as numbers.
//
// An attribute value is a short vector of numbers. Attribute_traits<T> says
// how many a T holds and converts to and from doubles:
//   static std::size_t width(const T&);
//   static double get(const T&, std::size_t i);
//   static bool assign(T&, const double* values, std::size_t n);  // false: a T cannot hold n values
// Provided for arithmetic types (width 1), Eigen column vectors (fixed or
// dynamic size), std::array, std::vector, and any Point3 type
// (<genmesh/point_traits.h>: CGAL::Point_3, OpenMesh::VectorT<S, 3>, ...;
// width 3). Integer components are rounded to the nearest integer and
// clamped to their type's range (a uchar colour stays in [0, 255]).
//
// Used by Attribute_quadrics (<genmesh/simplification/attribute_quadrics.h>)
// and by the soup ⇄ vertex map helpers of <genmesh/soup_to_mesh.h>.
#pragma once

#include <genmesh/point_traits.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace genmesh {

template <class T, class Enable = void>
struct Attribute_traits;

namespace detail {
// A double as an S: rounded and clamped for integer types.
template <class S>
S attribute_component(double x) {
  if constexpr (std::is_integral_v<S>) {
    if (!(x == x)) return S{};
    const double lo = static_cast<double>(std::numeric_limits<S>::lowest());
    const double hi = static_cast<double>(std::numeric_limits<S>::max());
    return static_cast<S>(std::clamp(std::nearbyint(x), lo, hi));
  } else {
    return static_cast<S>(x);
  }
}
} // namespace detail

template <class S>
  requires std::is_arithmetic_v<S>
struct Attribute_traits<S> {
  static std::size_t width(const S&) { return 1; }
  static double get(const S& s, std::size_t) { return static_cast<double>(s); }
  static bool assign(S& s, const double* v, std::size_t n) {
    if (n != 1) return false;
    s = detail::attribute_component<S>(v[0]);
    return true;
  }
};

template <class S, int Rows, int Options, int MaxRows>
struct Attribute_traits<Eigen::Matrix<S, Rows, 1, Options, MaxRows, 1>> {
  using T = Eigen::Matrix<S, Rows, 1, Options, MaxRows, 1>;
  static std::size_t width(const T& t) { return static_cast<std::size_t>(t.size()); }
  static double get(const T& t, std::size_t i) { return static_cast<double>(t[static_cast<Eigen::Index>(i)]); }
  static bool assign(T& t, const double* v, std::size_t n) {
    if constexpr (Rows == Eigen::Dynamic) t.resize(static_cast<Eigen::Index>(n));
    else if (n != static_cast<std::size_t>(Rows)) return false;
    for (std::size_t i = 0; i < n; ++i) t[static_cast<Eigen::Index>(i)] = detail::attribute_component<S>(v[i]);
    return true;
  }
};

template <class S, std::size_t N>
struct Attribute_traits<std::array<S, N>> {
  static std::size_t width(const std::array<S, N>&) { return N; }
  static double get(const std::array<S, N>& t, std::size_t i) { return static_cast<double>(t[i]); }
  static bool assign(std::array<S, N>& t, const double* v, std::size_t n) {
    if (n != N) return false;
    for (std::size_t i = 0; i < N; ++i) t[i] = detail::attribute_component<S>(v[i]);
    return true;
  }
};

template <class S, class A>
struct Attribute_traits<std::vector<S, A>> {
  static std::size_t width(const std::vector<S, A>& t) { return t.size(); }
  static double get(const std::vector<S, A>& t, std::size_t i) { return static_cast<double>(t[i]); }
  static bool assign(std::vector<S, A>& t, const double* v, std::size_t n) {
    t.resize(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = detail::attribute_component<S>(v[i]);
    return true;
  }
};

// Any other point type (CGAL::Point_3, OpenMesh::VectorT<S, 3>): three values.
template <class P>
  requires(Point3<P> && !std::is_arithmetic_v<P>)
struct Attribute_traits<P> {
  static std::size_t width(const P&) { return 3; }
  static double get(const P& p, std::size_t i) { return Point_traits<P>::coord(p, static_cast<int>(i)); }
  static bool assign(P& p, const double* v, std::size_t n) {
    if (n != 3) return false;
    p = Point_traits<P>::make(v[0], v[1], v[2]);
    return true;
  }
};

/// A type genmesh can read and write as an attribute value.
template <class T>
concept Attribute_value = requires(const T& c, T& t, const double* v) {
  { Attribute_traits<T>::width(c) } -> std::convertible_to<std::size_t>;
  { Attribute_traits<T>::get(c, std::size_t{0}) } -> std::convertible_to<double>;
  { Attribute_traits<T>::assign(t, v, std::size_t{0}) } -> std::convertible_to<bool>;
};

} // namespace genmesh
