// genmesh/polygon_soup.h — a polygon soup: points and faces as index lists.
//
// The exchange format between files and meshes. Faces are stored flat
// (compressed rows: face i is indices[offsets[i] .. offsets[i+1])), so a
// million-face soup is three allocations, not a million.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace genmesh {

/// Points (double precision) and polygonal faces given as point indices in
/// counter-clockwise order seen from outside. Nothing is checked here; see
/// check_soup() in <genmesh/validity.h>.
struct Polygon_soup {
  using Index = std::uint32_t;

  std::vector<Eigen::Vector3d> points;
  std::vector<Index> indices;           ///< all faces' corners, face after face
  std::vector<Index> offsets{0};        ///< face i spans [offsets[i], offsets[i+1])

  std::size_t num_points() const noexcept { return points.size(); }
  std::size_t num_faces() const noexcept { return offsets.size() - 1; }

  /// Corners of face i.
  std::span<const Index> face(std::size_t i) const noexcept {
    return {indices.data() + offsets[i], indices.data() + offsets[i + 1]};
  }
  std::span<Index> face(std::size_t i) noexcept {
    return {indices.data() + offsets[i], indices.data() + offsets[i + 1]};
  }
  std::size_t face_size(std::size_t i) const noexcept { return offsets[i + 1] - offsets[i]; }

  Index add_point(const Eigen::Vector3d& p) {
    points.push_back(p);
    return static_cast<Index>(points.size() - 1);
  }
  Index add_point(double x, double y, double z) { return add_point(Eigen::Vector3d(x, y, z)); }

  /// Appends a face; returns its index.
  std::size_t add_face(std::span<const Index> corners) {
    indices.insert(indices.end(), corners.begin(), corners.end());
    offsets.push_back(static_cast<Index>(indices.size()));
    return num_faces() - 1;
  }
  std::size_t add_face(std::initializer_list<Index> corners) {
    return add_face(std::span<const Index>(corners.begin(), corners.size()));
  }

  void clear() {
    points.clear();
    indices.clear();
    offsets.assign(1, 0);
  }

  friend bool operator==(const Polygon_soup&, const Polygon_soup&) = default;
};

} // namespace genmesh
