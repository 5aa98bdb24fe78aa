// genmesh/detail/io/stl.h — STL reader and writer (ASCII and binary).
//
// STL stores each facet with its own copies of its corners. The reader welds
// them: corners with exactly equal coordinates become one point (points
// numbered in first-seen order; -0.0 and 0.0 are equal). Nothing else is
// merged and nothing is dropped: a facet that welding makes degenerate (two
// equal corners) stays in the soup, for the validity checks to report.
// Facet normals and the binary attribute bytes are ignored.
//
// Binary or ASCII: a file that starts with "solid" and whose next statement
// is "facet" or "endsolid" is ASCII; anything else is binary and must be
// exactly 84 + 50 n bytes long, n being the count at byte 80.
//
// The writer triangulates polygons as fans from their first corner and
// writes each facet's normal (zero for degenerate triangles). Binary STL
// stores single-precision floats.
#pragma once

#include <genmesh/detail/io/common.h>
#include <genmesh/geometry.h>

#include <unordered_map>

namespace genmesh::detail::io {

/// Welds corners with exactly equal coordinates, in first-seen order.
class Stl_welder {
public:
  explicit Stl_welder(Polygon_soup& soup, std::size_t expected) : soup_(soup) { map_.reserve(expected); }
  Polygon_soup::Index operator()(const Eigen::Vector3d& p) {
    Key k{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};   // + 0.0 turns -0.0 into 0.0
    auto [it, inserted] = map_.try_emplace(k, static_cast<Polygon_soup::Index>(soup_.points.size()));
    if (inserted) soup_.points.push_back(p);
    return it->second;
  }

private:
  struct Key {
    double x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const noexcept {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (double d : {k.x, k.y, k.z}) {
        std::uint64_t b;
        std::memcpy(&b, &d, 8);
        h ^= b + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdull;
      }
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  Polygon_soup& soup_;
  std::unordered_map<Key, Polygon_soup::Index, Hash> map_;
};

/// True if the content is ASCII STL (see the header comment).
inline bool stl_is_ascii(const std::string& data) {
  std::size_t i = data.starts_with("\xEF\xBB\xBF") ? 3 : 0;   // UTF-8 byte order mark
  while (i < data.size() && Text_cursor::is_space_or_newline(data[i])) ++i;
  if (data.compare(i, 5, "solid") != 0) return false;
  const auto nl = data.find_first_of("\r\n", i);
  if (nl == std::string::npos) return data.size() < 84;   // "solid name" alone: an empty ASCII STL
  i = nl + 1;
  while (i < data.size() && Text_cursor::is_space_or_newline(data[i])) ++i;
  return data.compare(i, 5, "facet") == 0 || data.compare(i, 8, "endsolid") == 0;
}

inline Polygon_soup read_stl_binary(const File_content& file) {
  const std::string& d = file.data;
  if (d.size() < 84)
    throw io_error(file.name,
                   "truncated: a binary STL file needs at least 84 bytes, this one has " +
                       std::to_string(d.size()),
                   std::nullopt, d.size());
  const std::uint64_t n = load<std::uint32_t>(d.data() + 80, true);
  if (d.size() != 84 + 50 * n) {
    throw io_error(file.name,
                   "binary STL size mismatch: the header says " + std::to_string(n) +
                       " triangles, which needs " + std::to_string(84 + 50 * n) +
                       " bytes, the file has " + std::to_string(d.size()) +
                       (d.size() < 84 + 50 * n ? " (truncated)" : ""),
                   std::nullopt, 80);
  }
  Polygon_soup soup;
  soup.points.reserve(n / 2 + 3);
  soup.indices.reserve(3 * n);
  soup.offsets.reserve(n + 1);
  Stl_welder weld(soup, n / 2 + 3);
  for (std::uint64_t t = 0; t < n; ++t) {
    const char* q = d.data() + 84 + 50 * t + 12;
    for (int c = 0; c < 3; ++c, q += 12) {
      const Eigen::Vector3d p(load<float>(q, true), load<float>(q + 4, true), load<float>(q + 8, true));
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        throw io_error(file.name,
                       "corner " + std::to_string(c) + " of facet " + std::to_string(t) +
                           " has a non-finite coordinate (NaN or inf)",
                       std::nullopt, static_cast<std::uint64_t>(q - d.data()));
      soup.indices.push_back(weld(p));
    }
    soup.offsets.push_back(static_cast<Polygon_soup::Index>(soup.indices.size()));
  }
  return soup;
}

inline Polygon_soup read_stl_ascii(const File_content& file) {
  Text_cursor in(file);
  Polygon_soup soup;
  Stl_welder weld(soup, file.data.size() / 200 + 3);
  const auto expect = [&](std::string_view word) {
    in.skip_whitespace_and_newlines();
    if (in.at_end()) in.fail("truncated: the file ends where '" + std::string(word) + "' was expected");
    const auto t = in.token();
    if (t != word) in.fail("expected '" + std::string(word) + "', found " + quote(t));
  };
  bool in_solid = false;
  for (;;) {
    in.skip_whitespace_and_newlines();
    if (in.at_end()) break;
    const auto t = in.token();
    if (t == "solid" && !in_solid) {
      in_solid = true;
      in.next_line();   // the rest of the line is the solid's name
      continue;
    }
    if (t == "endsolid" && in_solid) {
      in_solid = false;
      in.next_line();
      continue;
    }
    if (t != "facet" || !in_solid)
      in.fail(std::string("expected '") + (in_solid ? "facet' or 'endsolid" : "solid") + "', found " + quote(t));
    in.next_line();   // "facet normal nx ny nz": the normal is not needed
    expect("outer");
    expect("loop");
    const std::size_t f = soup.num_faces();
    std::size_t corners = 0;
    for (;;) {
      in.skip_whitespace_and_newlines();
      if (in.at_end()) in.fail("truncated: the file ends inside facet " + std::to_string(f));
      const auto w = in.token();
      if (w == "endloop") break;
      if (w != "vertex") in.fail("expected 'vertex' or 'endloop', found " + quote(w));
      Eigen::Vector3d p;
      p.x() = in.read_double("x coordinate");
      p.y() = in.read_double("y coordinate");
      p.z() = in.read_double("z coordinate");
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        in.fail("corner " + std::to_string(corners) + " of facet " + std::to_string(f) +
                " has a non-finite coordinate (NaN or inf)");
      soup.indices.push_back(weld(p));
      ++corners;
    }
    if (corners < 3)
      in.fail("facet " + std::to_string(f) + " has " + std::to_string(corners) + " corners (at least 3 needed)");
    soup.offsets.push_back(static_cast<Polygon_soup::Index>(soup.indices.size()));
    expect("endfacet");
  }
  if (in_solid) in.fail("truncated: 'endsolid' is missing");
  return soup;
}

inline Polygon_soup read_stl(const File_content& file) {
  return stl_is_ascii(file.data) ? read_stl_ascii(file) : read_stl_binary(file);
}

/// Writes `soup` (Soup_source or detail::Soup_view) as STL.
template <class Source>
void write_stl(Atomic_file& out, const Source& soup, bool binary, int precision) {
  std::string& b = out.buffer;
  std::uint64_t triangles = 0;
  soup.for_each_face([&](std::size_t f, std::span<const Polygon_soup::Index> c, auto) {
    check_face_for_write(c, f, soup.num_points(), out.name());
    triangles += c.size() - 2;
  });
  if (binary) {
    if (triangles > std::numeric_limits<std::uint32_t>::max())
      throw io_error(out.name(), "cannot write: too many triangles for binary STL");
    std::string header = "binary STL written by genmesh";
    header.resize(80, ' ');
    b += header;
    store_le(b, static_cast<std::uint32_t>(triangles));
  } else {
    b += "solid genmesh\n";
  }
  soup.for_each_point([&](std::size_t v, const Eigen::Vector3d& p) {
    check_point_for_write(p, v, out.name());
    if (binary && p.cwiseAbs().maxCoeff() > std::numeric_limits<float>::max())
      throw io_error(out.name(), "cannot write: point " + std::to_string(v) +
                                     " is out of the float range of binary STL");
  });
  soup.template for_each_face<true>([&](std::size_t, std::span<const Polygon_soup::Index> c,
                                        std::span<const Eigen::Vector3d> corner) {
    for (std::size_t k = 1; k + 1 < c.size(); ++k) {
      const Eigen::Vector3d* t[3] = {&corner[0], &corner[k], &corner[k + 1]};
      const Eigen::Vector3d n = normalized_or_zero(triangle_normal(*t[0], *t[1], *t[2]));
      if (binary) {
        for (int i = 0; i < 3; ++i) store_le(b, static_cast<float>(n[i]));
        for (auto* p : t)
          for (int i = 0; i < 3; ++i) store_le(b, static_cast<float>((*p)[i]));
        b += std::string_view("\0\0", 2);
      } else {
        b += "facet normal ";
        for (int i = 0; i < 3; ++i) {
          append_double(b, n[i], precision);
          b += i < 2 ? ' ' : '\n';
        }
        b += " outer loop\n";
        for (auto* p : t) {
          b += "  vertex ";
          for (int i = 0; i < 3; ++i) {
            append_double(b, (*p)[i], precision);
            b += i < 2 ? ' ' : '\n';
          }
        }
        b += " endloop\nendfacet\n";
      }
    }
    out.flush_if_large();
  });
  if (!binary) b += "endsolid genmesh\n";
}

} // namespace genmesh::detail::io
