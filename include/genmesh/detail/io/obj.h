// genmesh/detail/io/obj.h — Wavefront OBJ reader and writer.
//
// Reads `v x y z [w]` or `v x y z r g b` (a vertex colour), `vt u [v [w]]`,
// `vn x y z` and `f` with corners written v, v/vt, v//vn or v/vt/vn, 1-based
// or negative (relative to the vertices, texture coordinates or normals read
// so far), faces of any size, and lines continued with a backslash. Groups,
// objects, smoothing groups, materials, polylines and every other statement
// are skipped; a line that does not start with a keyword is an error. A face
// may refer to a vertex, texture coordinate or normal defined later in the
// file.
//
// Attributes (Obj_attributes): OBJ gives texture coordinates and normals per
// face corner, a soup per point. Where a vertex's corners give different
// texture coordinates (a texture seam; equal values under different indices
// count as one), split_seams (the default) makes each further one a point of
// its own — a copy of the position, appended after the file's vertices in
// the order the corners first use it — so the seam survives: the mesh built
// from the soup has a border along it. Normals never split a vertex (they
// follow from the geometry; a flat-shaded file would fall apart): a point
// keeps the normal of its first corner that gives one. first_corner keeps
// one point per vertex with the values of its first corner that gives them;
// none reads geometry only (vt, vn and colours skipped).
#pragma once

#include <genmesh/detail/io/common.h>

#include <cctype>
#include <string_view>
#include <unordered_map>

namespace genmesh {

/// What read_soup() makes of an OBJ file's texture coordinates (vt),
/// normals (vn) and vertex colours (v x y z r g b); see Read_options.
enum class Obj_attributes {
  /// Channels "normal", "color", "texcoord"; a vertex whose corners give
  /// different texture coordinates is split into one point per texture
  /// coordinate (appended after the file's vertices): texture seams survive.
  /// Different normals never split (the first corner's is kept).
  split_seams,
  /// The same channels, one point per vertex, with the values of its first
  /// corner that gives them (seams are lost; the connectivity is the file's).
  first_corner,
  /// Geometry only: vt, vn and colours are skipped.
  none,
};

} // namespace genmesh

namespace genmesh::detail::io {

/// True for a statement keyword: letters, digits and '_', starting with a
/// letter. Statements other than v and f are skipped, known or not (as other
/// readers do: exporters add their own); a line that does not start with a
/// keyword is an error.
inline bool is_obj_keyword(std::string_view kw) {
  if (kw.empty() || !std::isalpha(static_cast<unsigned char>(kw[0]))) return false;
  return std::all_of(kw.begin(), kw.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

namespace obj {

// Where the largest positive index of one kind (vertex, texture coordinate,
// normal) was: positive indices may point forward, so they are range-checked
// at the end.
struct Largest_index {
  std::int64_t index = 0;
  std::uint64_t line = 0;
  std::size_t face = 0;
};

// The 0-based index of corner index `idx` of kind `what` among `count`
// read so far (negative: relative to them); forward references are
// remembered in `largest` and checked at the end.
inline std::int64_t resolve(Text_cursor& in, std::int64_t idx, std::size_t count, std::size_t f, const char* what,
                            Largest_index& largest) {
  if (idx > 0) {
    if (idx > largest.index) largest = {idx, in.line(), f};
    if (idx - 1 >= std::int64_t{std::numeric_limits<Polygon_soup::Index>::max()})
      in.fail("face " + std::to_string(f) + " has " + what + " index " + std::to_string(idx) + " out of range");
    return idx - 1;
  }
  if (idx < 0) {
    const std::int64_t r = static_cast<std::int64_t>(count) + idx;
    if (r < 0)
      in.fail("face " + std::to_string(f) + " has relative " + what + " index " + std::to_string(idx) +
              " out of range (" + std::to_string(count) + " read so far)");
    return r;
  }
  in.fail("face " + std::to_string(f) + " has " + what + " index 0 (OBJ indices start at 1)");
}

inline void check_largest(const File_content& file, const Largest_index& largest, std::size_t count,
                          const char* what, const char* plural) {
  if (largest.index > static_cast<std::int64_t>(count))
    throw io_error(file.name,
                   "face " + std::to_string(largest.face) + " has " + what + " index " +
                       std::to_string(largest.index) + " out of range (" + std::to_string(count) + " " + plural +
                       ")",
                   largest.line);
}

// Indices of equal value tuples (width doubles each, -0 stored as 0) mapped
// to the first of them: a seam is where the values differ, not the indices
// (exporters repeat equal vt and vn lines).
inline std::vector<std::uint32_t> first_of_equal(const std::vector<double>& values, std::size_t width) {
  const std::size_t n = width ? values.size() / width : 0;
  std::vector<std::uint32_t> first(n);
  std::unordered_map<std::string_view, std::uint32_t> seen;
  seen.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string_view key(reinterpret_cast<const char*>(values.data() + i * width), width * sizeof(double));
    first[i] = seen.try_emplace(key, static_cast<std::uint32_t>(i)).first->second;
  }
  return first;
}

} // namespace obj

inline Polygon_soup read_obj(const File_content& file, Obj_attributes mode = Obj_attributes::split_seams) {
  Text_cursor in(file);
  in.set_line_continuation(true);
  Polygon_soup soup;
  soup.points.reserve(file.data.size() / 64);
  soup.indices.reserve(file.data.size() / 16);
  soup.offsets.reserve(file.data.size() / 48);
  const bool attributes = mode != Obj_attributes::none;
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  obj::Largest_index largest_v, largest_vt, largest_vn;
  std::vector<double> colour;    // 3 per vertex once one vertex has a colour
  std::vector<double> texcoord;  // 2 per vt line
  std::vector<double> normal;    // 3 per vn line
  std::vector<std::uint32_t> corner_vt, corner_vn; // per corner (none: not given), once one is given
  const auto value = [&](const char* what) {
    const double x = in.read_double(what);
    if (!std::isfinite(x)) in.fail(std::string("non-finite ") + what);
    return x + 0.0; // -0 as 0: equal values compare equal as bytes
  };

  while (in.next_content_line()) {
    const std::string_view kw = in.token();
    if (kw == "v") {
      Eigen::Vector3d p;
      p.x() = in.read_double("x coordinate");
      p.y() = in.read_double("y coordinate");
      p.z() = in.read_double("z coordinate");
      check_finite(p, soup.points.size(), file.name, in.line());
      if (soup.points.size() == std::numeric_limits<Polygon_soup::Index>::max())
        in.fail("too many vertices");
      if (attributes) {
        // x y z r g b: a vertex colour (x y z w and other counts: extras ignored).
        if (in.tokens_left() == 3) {
          colour.resize(3 * soup.points.size(), 0.0);
          for (const char* c : {"red value", "green value", "blue value"}) colour.push_back(value(c));
        }
      }
      soup.points.push_back(p);
    } else if (kw == "vt" && attributes) {
      texcoord.push_back(value("texture coordinate u"));
      texcoord.push_back(in.at_eol_or_comment() ? 0.0 : value("texture coordinate v"));
    } else if (kw == "vn" && attributes) {
      for (const char* c : {"normal x", "normal y", "normal z"}) normal.push_back(value(c));
    } else if (kw == "f") {
      const std::size_t f = soup.num_faces();
      std::size_t corners = 0;
      while (!in.at_eol_or_comment()) {
        const Text_cursor::Obj_corner c = in.read_obj_corner();
        soup.indices.push_back(static_cast<Polygon_soup::Index>(
            obj::resolve(in, c.v, soup.points.size(), f, "vertex", largest_v)));
        if (attributes) {
          const auto add = [&](bool has, std::int64_t idx, std::size_t count, const char* what,
                               obj::Largest_index& largest, std::vector<std::uint32_t>& out) {
            if (!has && out.empty()) return;
            out.resize(soup.indices.size() - 1, none);
            out.push_back(has ? static_cast<std::uint32_t>(obj::resolve(in, idx, count, f, what, largest)) : none);
          };
          add(c.has_vt, c.vt, texcoord.size() / 2, "texture coordinate", largest_vt, corner_vt);
          add(c.has_vn, c.vn, normal.size() / 3, "normal", largest_vn, corner_vn);
        }
        ++corners;
      }
      if (corners < 3)
        in.fail("face " + std::to_string(f) + " has " + std::to_string(corners) +
                " corners (at least 3 needed)");
      soup.offsets.push_back(static_cast<Polygon_soup::Index>(soup.indices.size()));
    } else if (!is_obj_keyword(kw)) {
      if (std::any_of(kw.begin(), kw.end(),
                      [](char c) { return !is_text_byte(static_cast<unsigned char>(c)); }))
        in.fail("binary data where text was expected: " + quote(kw));
      in.fail("not an OBJ statement: " + quote(kw));
    }
    in.next_line();
  }
  obj::check_largest(file, largest_v, soup.points.size(), "vertex", "vertices");
  obj::check_largest(file, largest_vt, texcoord.size() / 2, "texture coordinate", "texture coordinates");
  obj::check_largest(file, largest_vn, normal.size() / 3, "normal", "normals");
  if (!attributes) return soup;
  if (!colour.empty()) colour.resize(3 * soup.points.size(), 0.0);
  corner_vt.resize(corner_vt.empty() ? 0 : soup.indices.size(), none);
  corner_vn.resize(corner_vn.empty() ? 0 : soup.indices.size(), none);

  // Each point's texture coordinate and normal: its corners' (equal values
  // counted as one), the first given where they differ; with split_seams,
  // every other combination a vertex's corners give is a new point (a copy
  // of its position and colour) appended in corner order.
  const std::vector<std::uint32_t> vt_first = obj::first_of_equal(texcoord, 2);
  const std::vector<std::uint32_t> vn_first = obj::first_of_equal(normal, 3);
  const std::size_t nv = soup.points.size();
  std::vector<std::uint32_t> point_vt(corner_vt.empty() ? 0 : nv, none), point_vn(corner_vn.empty() ? 0 : nv, none);
  const auto corner_value = [&](const std::vector<std::uint32_t>& corner, const std::vector<std::uint32_t>& first,
                                std::size_t c) { return corner.empty() || corner[c] == none ? none : first[corner[c]]; };
  for (std::size_t c = 0; c < soup.indices.size(); ++c) {
    const std::uint32_t v = soup.indices[c];
    if (!point_vt.empty() && point_vt[v] == none) point_vt[v] = corner_value(corner_vt, vt_first, c);
    if (!point_vn.empty() && point_vn[v] == none) point_vn[v] = corner_value(corner_vn, vn_first, c);
  }
  if (mode == Obj_attributes::split_seams && !point_vt.empty()) {
    // Only texture seams split: normals follow from the geometry, and a
    // flat-shaded file (a normal per face) would otherwise fall apart into
    // separate faces. A copy takes the normal of the first corner using it.
    std::unordered_map<std::uint64_t, std::uint32_t> copies; // (vertex, vt) -> point
    for (std::size_t c = 0; c < soup.indices.size(); ++c) {
      const std::uint32_t v = soup.indices[c];
      std::uint32_t t = corner_value(corner_vt, vt_first, c);
      if (t == none) t = point_vt[v]; // not given here: the vertex's
      if (t == point_vt[v]) continue;
      std::uint32_t n = point_vn.empty() ? none : corner_value(corner_vn, vn_first, c);
      if (n == none && !point_vn.empty()) n = point_vn[v];
      const auto [it, added] =
          copies.try_emplace(std::uint64_t{v} << 32 | t, static_cast<std::uint32_t>(soup.points.size()));
      if (added) {
        if (soup.points.size() == std::numeric_limits<Polygon_soup::Index>::max())
          throw io_error(file.name, "too many vertices after splitting the texture seams");
        soup.points.push_back(soup.points[v]);
        if (!colour.empty()) {
          const double rgb[3] = {colour[3 * v], colour[3 * v + 1], colour[3 * v + 2]};
          colour.insert(colour.end(), rgb, rgb + 3);
        }
        point_vt.push_back(t);
        if (!point_vn.empty()) point_vn.push_back(n);
      }
      soup.indices[c] = it->second;
    }
  }
  // Channels in OFF's order: normal, colour, texture coordinates.
  const auto channel = [&](const char* name, std::vector<std::string> components, const std::vector<std::uint32_t>& of,
                           const std::vector<double>& values) {
    Soup_attribute a{name, std::move(components), Scalar_type::float64, {}};
    const std::size_t w = a.width();
    a.values.reserve(of.size() * w);
    for (const std::uint32_t i : of)
      for (std::size_t j = 0; j < w; ++j) a.values.push_back(i == none ? 0.0 : values[i * w + j]);
    soup.vertex_attributes.push_back(std::move(a));
  };
  if (!point_vn.empty()) channel("normal", {"nx", "ny", "nz"}, point_vn, normal);
  if (!colour.empty())
    soup.vertex_attributes.push_back({"color", {"red", "green", "blue"}, Scalar_type::float64, std::move(colour)});
  if (!point_vt.empty()) channel("texcoord", {"u", "v"}, point_vt, texcoord);
  return soup;
}

/// Writes `soup` (Soup_source or detail::Soup_view) as OBJ: `v x y z [r g b]`
/// lines, then a `vt` and a `vn` line per point when the soup has a
/// "texcoord" (2 values) or a "normal" (3 values) channel, and faces whose
/// corners name the point's own vt and vn (`f 1/1/1 ...`). Colours ("color",
/// 3 or 4 values; alpha dropped) are written in [0, 1]: uint8 ones divided
/// by 255, uint16 ones by 65535. Other channels are not written.
template <class Source>
void write_obj(Atomic_file& out, const Source& soup, int precision) {
  const auto channels = soup.vertex_attributes();
  check_attributes_for_write(channels, soup.num_points(), out.name());
  const Soup_attribute *colour = nullptr, *uv = nullptr, *normal = nullptr;
  for (const Soup_attribute& a : channels) {
    if (a.name == "color" && (a.width() == 3 || a.width() == 4) && !colour) colour = &a;
    if (a.name == "texcoord" && a.width() == 2 && !uv) uv = &a;
    if (a.name == "normal" && a.width() == 3 && !normal) normal = &a;
  }
  const double colour_full = !colour ? 1.0
                             : colour->type == Scalar_type::uint8  ? 255.0
                             : colour->type == Scalar_type::uint16 ? 65535.0
                                                                   : 1.0;
  std::string& b = out.buffer;
  b += "# written by genmesh\n";
  soup.for_each_point([&](std::size_t v, const Eigen::Vector3d& p) {
    check_point_for_write(p, v, out.name());
    b += "v ";
    append_point(b, p, precision);
    if (colour) {
      b.pop_back(); // the colour follows on the point's line
      for (std::size_t j = 0; j < 3; ++j) {
        b += ' ';
        append_double(b, colour->of(v)[j] / colour_full, precision);
      }
      b += '\n';
    }
    out.flush_if_large();
  });
  const auto lines = [&](const Soup_attribute* a, const char* keyword) {
    if (!a) return;
    for (std::size_t v = 0; v < soup.num_points(); ++v) {
      b += keyword;
      for (const double x : a->of(v)) {
        b += ' ';
        append_double(b, x, precision);
      }
      b += '\n';
      out.flush_if_large();
    }
  };
  lines(uv, "vt");
  lines(normal, "vn");
  soup.for_each_face([&](std::size_t f, std::span<const Polygon_soup::Index> c, auto) {
    check_face_for_write(c, f, soup.num_points(), out.name());
    b += 'f';
    for (auto i : c) {
      b += ' ';
      append_int(b, std::uint64_t{i} + 1);
      if (uv || normal) {
        b += '/';
        if (uv) append_int(b, std::uint64_t{i} + 1);
        if (normal) {
          b += '/';
          append_int(b, std::uint64_t{i} + 1);
        }
      }
    }
    b += '\n';
    out.flush_if_large();
  });
}

} // namespace genmesh::detail::io
