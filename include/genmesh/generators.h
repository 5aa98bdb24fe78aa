// genmesh/generators.h — small meshes made in memory, as polygon soups.
//
// Used by `genmesh demo`, the tests and the benchmarks, so that no file is
// needed to exercise an algorithm. Every soup is a valid oriented 2-manifold
// (faces counter-clockwise seen from outside) with exactly the topology its
// name says; no point is isolated.
#pragma once

#include <genmesh/exceptions.h>
#include <genmesh/geometry.h>
#include <genmesh/polygon_soup.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

namespace genmesh {

namespace detail {

// Reverse face f when its normal points towards `inside`.
inline void orient_away_from(Polygon_soup& s, std::size_t f, const Eigen::Vector3d& inside) {
  auto c = s.face(f);
  std::vector<Eigen::Vector3d> corners;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (auto i : c) corners.push_back(s.points[i]), centroid += s.points[i];
  centroid /= static_cast<double>(c.size());
  if (polygon_normal(corners).dot(centroid - inside) < 0) std::reverse(c.begin(), c.end());
}

} // namespace detail

/// A regular tetrahedron: 4 vertices, 6 edges, 4 triangles; χ = 2.
inline Polygon_soup make_tetrahedron() {
  Polygon_soup s;
  s.add_point(1, 1, 1);
  s.add_point(1, -1, -1);
  s.add_point(-1, 1, -1);
  s.add_point(-1, -1, 1);
  s.add_face({0, 1, 2});
  s.add_face({0, 3, 1});
  s.add_face({0, 2, 3});
  s.add_face({1, 3, 2});
  for (std::size_t f = 0; f < 4; ++f) detail::orient_away_from(s, f, Eigen::Vector3d::Zero());
  return s;
}

/// The cube [-1,1]^3 with 6 quads: 8 vertices, 12 edges; χ = 2.
inline Polygon_soup make_cube() {
  Polygon_soup s;
  for (int i = 0; i < 8; ++i)  // vertex i has coordinates from its bits x, y, z
    s.add_point((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  s.add_face({0, 2, 3, 1});  // z = -1
  s.add_face({4, 5, 7, 6});  // z = +1
  s.add_face({0, 1, 5, 4});  // y = -1
  s.add_face({2, 6, 7, 3});  // y = +1
  s.add_face({0, 4, 6, 2});  // x = -1
  s.add_face({1, 3, 7, 5});  // x = +1
  for (std::size_t f = 0; f < 6; ++f) detail::orient_away_from(s, f, Eigen::Vector3d::Zero());
  return s;
}

/// The unit icosahedron refined `subdivisions` times (1-to-4, points pushed to
/// the sphere): 10·4^k + 2 vertices, 20·4^k triangles; χ = 2.
inline Polygon_soup make_icosphere(int subdivisions = 0) {
  if (subdivisions < 0 || subdivisions > 10)
    throw invalid_input("make_icosphere: subdivisions must be in [0, 10], got " +
                        std::to_string(subdivisions));
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Polygon_soup s;
  const double c[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : c) s.add_point(Eigen::Vector3d(p[0], p[1], p[2]).normalized());
  const Polygon_soup::Index f[20][3] = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& tri : f) s.add_face({tri[0], tri[1], tri[2]});
  for (std::size_t i = 0; i < s.num_faces(); ++i) detail::orient_away_from(s, i, Eigen::Vector3d::Zero());

  for (int level = 0; level < subdivisions; ++level) {
    Polygon_soup r;
    r.points = s.points;
    std::unordered_map<std::uint64_t, Polygon_soup::Index> midpoint;
    auto mid = [&](Polygon_soup::Index a, Polygon_soup::Index b) {
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      auto [it, inserted] = midpoint.try_emplace(key, 0);
      if (inserted) it->second = r.add_point((r.points[a] + r.points[b]).normalized());
      return it->second;
    };
    for (std::size_t i = 0; i < s.num_faces(); ++i) {
      auto tri = s.face(i);
      const auto a = tri[0], b = tri[1], cc = tri[2];
      const auto ab = mid(a, b), bc = mid(b, cc), ca = mid(cc, a);
      r.add_face({a, ab, ca});
      r.add_face({b, bc, ab});
      r.add_face({cc, ca, bc});
      r.add_face({ab, bc, ca});
    }
    s = std::move(r);
  }
  return s;
}

/// A torus around the z axis (radii 1 and 0.4) with `rings` × `sides` quads,
/// or twice as many triangles when `triangulate`: genus 1, χ = 0.
/// Requires rings, sides >= 3.
inline Polygon_soup make_torus(int rings = 24, int sides = 12, bool triangulate = false) {
  if (rings < 3 || sides < 3)
    throw invalid_input("make_torus: rings and sides must be >= 3, got " + std::to_string(rings) +
                        " and " + std::to_string(sides));
  const double R = 1.0, r = 0.4, two_pi = 2 * std::numbers::pi;
  Polygon_soup s;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double u = two_pi * i / rings, v = two_pi * j / sides;
      s.add_point((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                  r * std::sin(v));
    }
  auto id = [&](int i, int j) {
    return static_cast<Polygon_soup::Index>((i % rings) * sides + (j % sides));
  };
  // (a, b, c, d) runs along u, then along v: its normal is ∂u × ∂v, which
  // points away from the tube's centre line everywhere. The winding comes
  // from the parametrization, not from the (possibly non-planar) corners, so
  // it is consistent even on the coarsest torus.
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangulate) {
        s.add_face({a, b, c});
        s.add_face({a, c, d});
      } else {
        s.add_face({a, b, c, d});
      }
    }
  return s;
}

/// The unit square [0,1]^2 in the plane z = 0 split into nx × ny cells of two
/// triangles each, normals +z: a disk with one boundary loop, χ = 1.
inline Polygon_soup make_grid(int nx = 8, int ny = 8) {
  if (nx < 1 || ny < 1)
    throw invalid_input("make_grid: nx and ny must be >= 1, got " + std::to_string(nx) + " and " +
                        std::to_string(ny));
  Polygon_soup s;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) s.add_point(double(i) / nx, double(j) / ny, 0.0);
  auto id = [&](int i, int j) { return static_cast<Polygon_soup::Index>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

/// An n × n triangulated grid (as make_grid) whose middle third of cells is
/// removed: an annulus with two boundary loops, χ = 0. Requires n >= 3.
inline Polygon_soup make_grid_with_hole(int n = 9) {
  if (n < 3) throw invalid_input("make_grid_with_hole: n must be >= 3, got " + std::to_string(n));
  const int lo = n / 3, hi = n - n / 3;  // cells [lo, hi)^2 are removed
  Polygon_soup s;
  std::vector<Polygon_soup::Index> id((n + 1) * (n + 1), UINT32_MAX);
  auto vertex = [&](int i, int j) {
    auto& v = id[j * (n + 1) + i];
    if (v == UINT32_MAX) v = s.add_point(double(i) / n, double(j) / n, 0.0);
    return v;
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i >= lo && i < hi && j >= lo && j < hi) continue;
      const auto a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      s.add_face({a, b, c});
      s.add_face({a, c, d});
    }
  return s;
}

} // namespace genmesh
