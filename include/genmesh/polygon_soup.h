// genmesh/polygon_soup.h — a polygon soup: points and faces as index lists.
//
// The exchange format between files and meshes. Faces are stored flat
// (compressed rows: face i is indices[offsets[i] .. offsets[i+1])), so a
// million-face soup is three allocations, not a million.
//
// Per-point attributes (colours, normals, texture coordinates, any named
// PLY vertex property) ride along as channels: each a name, the names of
// its components and the numbers, `width` per point, stored flat. The readers
// fill them from PLY vertex properties and OFF's C/N/ST variants, the writers
// write them back (<genmesh/io.h>); build_mesh keeps the points' order, so
// channel value i belongs to the i-th vertex of the mesh built from the soup
// (see read_vertex_attribute / make_soup_attribute in <genmesh/soup_to_mesh.h>).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace genmesh {

/// The number type a file stores a value in (PLY's types; text formats
/// write the integer types as integers).
enum class Scalar_type : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// A per-point attribute channel of a Polygon_soup: components.size()
/// numbers per point, point i's at values[i * width() .. (i + 1) * width()).
struct Soup_attribute {
  /// "color" (red green blue [alpha]), "normal" (nx ny nz), "texcoord"
  /// (u v), or the name of a single PLY vertex property ("quality").
  std::string name;
  /// One name per value: the PLY property names ({"red", "green", "blue"}).
  std::vector<std::string> components;
  /// The type the file stored (written back so); uint8 colours are 0..255.
  Scalar_type type = Scalar_type::float64;
  std::vector<double> values;

  std::size_t width() const noexcept { return components.size(); }
  /// Point i's values.
  std::span<const double> of(std::size_t i) const noexcept { return {values.data() + i * width(), width()}; }
  std::span<double> of(std::size_t i) noexcept { return {values.data() + i * width(), width()}; }

  friend bool operator==(const Soup_attribute&, const Soup_attribute&) = default;
};

/// Points (double precision) and polygonal faces given as point indices in
/// counter-clockwise order seen from outside. Nothing is checked here; see
/// check_soup() in <genmesh/validity.h>.
struct Polygon_soup {
  using Index = std::uint32_t;

  std::vector<Eigen::Vector3d> points;
  std::vector<Index> indices;           ///< all faces' corners, face after face
  std::vector<Index> offsets{0};        ///< face i spans [offsets[i], offsets[i+1])
  /// Per-point attribute channels (each holds width() values per point).
  std::vector<Soup_attribute> vertex_attributes;

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

  /// Appends a point (its attribute values 0); returns its index.
  Index add_point(const Eigen::Vector3d& p) {
    points.push_back(p);
    for (Soup_attribute& a : vertex_attributes) a.values.resize(points.size() * a.width(), 0.0);
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

  /// The channel named `name`, or null.
  const Soup_attribute* vertex_attribute(std::string_view name) const noexcept {
    const auto it = std::find_if(vertex_attributes.begin(), vertex_attributes.end(),
                                 [&](const Soup_attribute& a) { return a.name == name; });
    return it == vertex_attributes.end() ? nullptr : &*it;
  }

  void clear() {
    points.clear();
    indices.clear();
    offsets.assign(1, 0);
    vertex_attributes.clear();
  }

  friend bool operator==(const Polygon_soup&, const Polygon_soup&) = default;
};

} // namespace genmesh
