// genmesh/detail/io/off.h — OFF reader and writer (Geomview's Object File Format).
//
// Reads the ASCII variants CGAL reads: the keyword [ST][C][N]OFF, '#' comments
// anywhere, the counts on the keyword's line or the next, and per-vertex
// extras (texture coordinates, normals, colors) and per-face colors after
// the values that matter, which are ignored. One vertex or face per line.
// Data after the last face the header announces is ignored (as CGAL does).
// Refused: binary OFF, 4OFF and nOFF (not 3D).
#pragma once

#include <genmesh/detail/io/common.h>

namespace genmesh::detail::io {

inline Polygon_soup read_off(const File_content& file) {
  Text_cursor in(file);
  if (!in.next_content_line()) in.fail("no OFF header (the file holds only comments or blanks)");
  const std::string_view keyword = in.token();
  {
    std::string_view k = keyword;
    if (k.starts_with("ST")) k.remove_prefix(2);
    if (k.starts_with("C")) k.remove_prefix(1);
    if (k.starts_with("N")) k.remove_prefix(1);
    if (k.starts_with("4") || k.starts_with("n"))
      in.fail("only 3D OFF is supported (" + quote(keyword) + ")");
    if (k != "OFF") {
      if (std::any_of(keyword.begin(), keyword.end(),
                      [](char c) { return !is_text_byte(static_cast<unsigned char>(c)); }))
        in.fail("binary data where the OFF header was expected: " + quote(keyword));
      in.fail("missing OFF header: expected 'OFF', found " + quote(keyword));
    }
  }
  // The counts follow on the keyword's line or on the next content line.
  if (in.at_eol_or_comment()) {
    in.next_line();
    if (!in.next_content_line()) in.fail("truncated: the OFF counts line is missing");
  } else {
    Text_cursor peek = in;
    if (peek.token() == "BINARY") in.fail("binary OFF is not supported");
  }
  const std::int64_t nv = in.read_int("vertex count");
  const std::int64_t nf = in.read_int("face count");
  if (!in.at_eol_or_comment()) (void)in.read_int("edge count");
  if (nv < 0 || nf < 0) in.fail("negative count in the OFF counts line");
  if (nv > std::numeric_limits<Polygon_soup::Index>::max())
    in.fail("too many vertices: " + std::to_string(nv));
  in.next_line();

  Polygon_soup soup;
  // Never trust a count for the allocation size: a lying header must give
  // an error, not a bad_alloc.
  const auto cap = file.data.size() / 2 + 1;
  soup.points.reserve(std::min<std::size_t>(static_cast<std::size_t>(nv), cap));
  soup.offsets.reserve(std::min<std::size_t>(static_cast<std::size_t>(nf), cap) + 1);
  soup.indices.reserve(std::min<std::size_t>(static_cast<std::size_t>(nf), cap / 3) * 3);

  for (std::int64_t i = 0; i < nv; ++i) {
    if (!in.next_content_line())
      in.fail("truncated: the header says " + std::to_string(nv) + " vertices, the file has " +
              std::to_string(i));
    Eigen::Vector3d p;
    p.x() = in.read_double("x coordinate");
    p.y() = in.read_double("y coordinate");
    p.z() = in.read_double("z coordinate");
    check_finite(p, static_cast<std::size_t>(i), file.name, in.line());
    soup.points.push_back(p);
    in.next_line();
  }
  for (std::int64_t f = 0; f < nf; ++f) {
    if (!in.next_content_line())
      in.fail("truncated: the header says " + std::to_string(nf) + " faces, the file has " +
              std::to_string(f));
    const std::int64_t n = in.read_int("face size");
    if (n < 3)
      in.fail("face " + std::to_string(f) + " has " + std::to_string(n) +
              " corners (at least 3 needed)");
    for (std::int64_t k = 0; k < n; ++k) {
      if (in.at_eol_or_comment())
        in.fail("face " + std::to_string(f) + " announces " + std::to_string(n) +
                " corners but lists " + std::to_string(k));
      const std::int64_t idx = in.read_int("vertex index");
      if (idx < 0 || idx >= nv)
        in.fail("face " + std::to_string(f) + " has index " + std::to_string(idx) +
                " out of range (" + std::to_string(nv) + " vertices)");
      soup.indices.push_back(static_cast<Polygon_soup::Index>(idx));
    }
    soup.offsets.push_back(static_cast<Polygon_soup::Index>(soup.indices.size()));
    in.next_line();
  }
  // Whatever follows the last face is ignored, as CGAL does: real files
  // (CGAL's own prim.off) have more faces than their header says.
  return soup;
}

/// Writes `soup` (Soup_source or detail::Soup_view) as OFF.
template <class Source>
void write_off(Atomic_file& out, const Source& soup, int precision) {
  std::string& b = out.buffer;
  b += "OFF\n";
  append_int(b, soup.num_points());
  b += ' ';
  append_int(b, soup.num_faces());
  b += " 0\n";
  soup.for_each_point([&](std::size_t v, const Eigen::Vector3d& p) {
    check_point_for_write(p, v, out.name());
    append_point(b, p, precision);
    out.flush_if_large();
  });
  soup.for_each_face([&](std::size_t f, std::span<const Polygon_soup::Index> c, auto) {
    check_face_for_write(c, f, soup.num_points(), out.name());
    append_int(b, c.size());
    for (auto i : c) {
      b += ' ';
      append_int(b, i);
    }
    b += '\n';
    out.flush_if_large();
  });
}

} // namespace genmesh::detail::io
