// genmesh/detail/io/obj.h — Wavefront OBJ reader and writer (geometry only).
//
// Reads `v x y z [w]` (extra values such as vertex colors ignored) and
// `f` with corners written v, v/vt, v//vn or v/vt/vn, 1-based or negative
// (relative to the vertices read so far), faces of any size, and lines
// continued with a backslash. Texture coordinates, normals, groups, objects,
// smoothing groups, materials, polylines and every other statement are
// skipped; a line that does not start with a keyword is an error. A face may
// refer to a vertex defined later in the file.
#pragma once

#include <genmesh/detail/io/common.h>

#include <cctype>

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

inline Polygon_soup read_obj(const File_content& file) {
  Text_cursor in(file);
  in.set_line_continuation(true);
  Polygon_soup soup;
  soup.points.reserve(file.data.size() / 64);
  soup.indices.reserve(file.data.size() / 16);
  soup.offsets.reserve(file.data.size() / 48);

  // Positive indices may point forward, so they are range-checked at the
  // end; only the largest one (and where it was) needs remembering.
  std::int64_t max_index = 0;
  std::uint64_t max_line = 0;
  std::size_t max_face = 0;

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
      soup.points.push_back(p);
    } else if (kw == "f") {
      const std::size_t f = soup.num_faces();
      std::size_t corners = 0;
      while (!in.at_eol_or_comment()) {
        const std::int64_t idx = in.read_int("vertex index", true);
        std::int64_t resolved;
        if (idx > 0) {
          resolved = idx - 1;
          if (idx > max_index) {
            max_index = idx;
            max_line = in.line();
            max_face = f;
          }
        } else if (idx < 0) {
          resolved = static_cast<std::int64_t>(soup.points.size()) + idx;
          if (resolved < 0)
            in.fail("face " + std::to_string(f) + " has relative index " + std::to_string(idx) +
                    " out of range (" + std::to_string(soup.points.size()) +
                    " vertices read so far)");
        } else {
          in.fail("face " + std::to_string(f) + " has index 0 (OBJ indices start at 1)");
        }
        if (resolved >= std::numeric_limits<Polygon_soup::Index>::max())
          in.fail("face " + std::to_string(f) + " has index " + std::to_string(idx) + " out of range");
        soup.indices.push_back(static_cast<Polygon_soup::Index>(resolved));
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
  if (max_index > static_cast<std::int64_t>(soup.points.size()))
    throw io_error(file.name,
                   "face " + std::to_string(max_face) + " has index " + std::to_string(max_index) +
                       " out of range (" + std::to_string(soup.points.size()) + " vertices)",
                   max_line);
  return soup;
}

/// Writes `soup` (Soup_source or detail::Soup_view) as OBJ.
template <class Source>
void write_obj(Atomic_file& out, const Source& soup, int precision) {
  std::string& b = out.buffer;
  b += "# written by genmesh\n";
  soup.for_each_point([&](std::size_t v, const Eigen::Vector3d& p) {
    check_point_for_write(p, v, out.name());
    b += "v ";
    append_point(b, p, precision);
    out.flush_if_large();
  });
  soup.for_each_face([&](std::size_t f, std::span<const Polygon_soup::Index> c, auto) {
    check_face_for_write(c, f, soup.num_points(), out.name());
    b += 'f';
    for (auto i : c) {
      b += ' ';
      append_int(b, std::uint64_t{i} + 1);
    }
    b += '\n';
    out.flush_if_large();
  });
}

} // namespace genmesh::detail::io
