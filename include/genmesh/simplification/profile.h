// genmesh/simplification/profile.h — what a memoryless cost/placement policy
// of genmesh::simplify sees of an edge: the current neighbourhood of its two
// ends (CGAL's Edge_profile, reduced to points).
//
// A memoryless policy keeps no per-vertex data: it recomputes cost and
// placement from the current mesh around the edge each time (Lindstrom &
// Turk 1998). simplify() builds the profile in a canonical order (the fans
// of the two ends walked from the edge, as the faces' orientation turns), so
// sums over it round the same way on every backend.
//
// Writing a memoryless policy: a type with
//   static constexpr bool memoryless = true;
//   Placement place(const Collapse_profile&) const;                      // cost infinite: refuse for now
//   Placement fixed(const Collapse_profile&, const Eigen::Vector3d& x) const; // cost of collapsing onto x
#pragma once

#include <Eigen/Core>

#include <span>

namespace genmesh {

/// A triangle of a profile, corners in the face's orientation.
struct Profile_triangle {
  Eigen::Vector3d a, b, c;
};

/// A border edge of a profile, s → t along its face (the face is on the left).
struct Profile_border_edge {
  Eigen::Vector3d s, t;
};

/// The neighbourhood of edge (p0, p1) before its collapse.
struct Collapse_profile {
  Eigen::Vector3d p0, p1; ///< the edge's ends, p0 the one with the lower vertex index
  /// Every face around p0 or p1, once (the two faces of the edge included):
  /// p0's fan from the face left of p1 → p0, then p1's from the face left of
  /// p0 → p1, turning as the faces are oriented; each face starts at its
  /// corner of lowest vertex index.
  std::span<const Profile_triangle> triangles;
  /// Every border edge at p0 or p1, once, in the same walk order; empty with
  /// Border_mode::free.
  std::span<const Profile_border_edge> border_edges;
  /// The neighbours of p0 and p1 (neither end), once, in the same walk order.
  std::span<const Eigen::Vector3d> link;
};

namespace detail::simplification {
template <class Policy>
inline constexpr bool is_memoryless = requires { requires Policy::memoryless; };
// A policy's default .max_normal_deviation (degrees): its own, else 45.
template <class Policy>
inline constexpr double default_normal_deviation = [] {
  if constexpr (requires { Policy::default_max_normal_deviation; }) return Policy::default_max_normal_deviation;
  else return 45.0;
}();
} // namespace detail::simplification

} // namespace genmesh
