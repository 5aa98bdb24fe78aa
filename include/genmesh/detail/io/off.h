// genmesh/detail/io/off.h — OFF reader and writer (Geomview's Object File Format).
//
// Reads the ASCII variants CGAL reads: the keyword [ST][C][N]OFF, '#' comments
// anywhere, the counts on the keyword's line or the next, and per-face
// colors after the indices, which are ignored. One vertex or face per line.
// The per-vertex extras the keyword announces become the soup's attribute
// channels, in Geomview's order after x y z: N → "normal" (nx ny nz), C →
// "color", ST → "texcoord" (s t). Colours are read as CGAL reads them: 3 or
// 4 values, or none, on each line (a line without colour reads as 0 0 0, a
// missing alpha as opaque: 255, or 1 for float colours); the channel has 4
// values if any line gives alpha, and is uint8 when every colour value in
// the file is an integer literal in 0..255, else double. A missing normal or
// texture coordinate, a malformed or non-finite extra, or 1, 2 or more than 4
// colour values is an error naming the line. Numbers after the announced
// extras are ignored, except with C: a line's colour count is what it leaves
// before the texture coordinates. Writes the [ST][C][N]OFF keyword for the
// channels named "texcoord" (2 values), "color" (3 or 4) and "normal" (3);
// other channels are not written (OFF has no place for them).
// Data after the last face the header announces is ignored (as CGAL does).
// Refused: binary OFF, 4OFF and nOFF (not 3D).
#pragma once

#include <genmesh/detail/io/common.h>

namespace genmesh::detail::io {

inline Polygon_soup read_off(const File_content& file) {
  Text_cursor in(file);
  if (!in.next_content_line()) in.fail("no OFF header (the file holds only comments or blanks)");
  const std::string_view keyword = in.token();
  bool has_st = false, has_c = false, has_n = false;
  {
    std::string_view k = keyword;
    if (k.starts_with("ST")) k.remove_prefix(2), has_st = true;
    if (k.starts_with("C")) k.remove_prefix(1), has_c = true;
    if (k.starts_with("N")) k.remove_prefix(1), has_n = true;
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

  // The announced extras, in Geomview's order.
  Soup_attribute* normal = nullptr;
  Soup_attribute* colour = nullptr;
  Soup_attribute* texcoord = nullptr;
  const auto channel = [&](const char* name, std::vector<std::string> components) {
    Soup_attribute a;
    a.name = name;
    a.components = std::move(components);
    a.values.reserve(std::min<std::size_t>(static_cast<std::size_t>(nv), cap) * a.width());
    soup.vertex_attributes.push_back(std::move(a));
  };
  if (has_n) channel("normal", {"nx", "ny", "nz"});
  if (has_c) channel("color", {"red", "green", "blue"});
  if (has_st) channel("texcoord", {"s", "t"});
  {
    std::size_t k = 0;
    if (has_n) normal = &soup.vertex_attributes[k++];
    if (has_c) colour = &soup.vertex_attributes[k++];
    if (has_st) texcoord = &soup.vertex_attributes[k++];
  }
  bool colour_integers = true;  // every colour value an integer literal in 0..255
  bool alpha = false;            // some vertex gives 4 colour values
  std::vector<double> rgba;      // 4 per vertex, NaN where the line gives none
  if (colour) rgba.reserve(std::min<std::size_t>(static_cast<std::size_t>(nv), cap) * 4);
  // Reads n values of vertex `vertex` (named `what`) into out.
  const auto read_extra = [&](const Soup_attribute& a, const char* what, std::int64_t vertex, std::size_t n,
                              std::vector<double>& out) {
    for (std::size_t j = 0; j < n; ++j) {
      const std::string& c = a.components[std::min(j, a.components.size() - 1)];
      if (in.at_eol_or_comment())
        in.fail("vertex " + std::to_string(vertex) + " has no " + what + " value '" + c + "' (the keyword " +
                quote(keyword) + " announces it)");
      Text_cursor peek = in;
      const std::string_view token = peek.token();
      const double v = in.read_double((std::string(what) + " value").c_str());
      if (!std::isfinite(v)) in.fail("vertex " + std::to_string(vertex) + " has a non-finite " + what + " value");
      if (&a == colour && (token.find_first_of(".eEnN") != std::string_view::npos || v < 0 || v > 255))
        colour_integers = false;
      out.push_back(v);
    }
  };

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
    if (normal) read_extra(*normal, "normal", i, 3, normal->values);
    if (colour) {
      // 0, 3 or 4 colour values: what is left before the texture coordinates.
      const std::size_t left = in.tokens_left();
      const std::size_t n = left - std::min<std::size_t>(left, texcoord ? 2 : 0);
      if (n != 0 && n != 3 && n != 4)
        in.fail("vertex " + std::to_string(i) + " has " + std::to_string(n) + " colour values (3 or 4 expected)");
      alpha = alpha || n == 4;
      read_extra(*colour, "colour", i, n, rgba);
      rgba.resize(rgba.size() + 4 - n, std::numeric_limits<double>::quiet_NaN());
    }
    if (texcoord) read_extra(*texcoord, "texture coordinate", i, 2, texcoord->values);
    in.next_line();
  }
  if (colour) {
    colour->type = colour_integers ? Scalar_type::uint8 : Scalar_type::float64;
    if (alpha) colour->components.push_back("alpha");
    const std::size_t w = colour->width();
    colour->values.resize(static_cast<std::size_t>(nv) * w);
    for (std::size_t v = 0; v < static_cast<std::size_t>(nv); ++v)
      for (std::size_t j = 0; j < w; ++j) {
        const double x = rgba[4 * v + j];
        colour->values[v * w + j] = x == x ? x : j < 3 ? 0.0 : colour_integers ? 255.0 : 1.0;
      }
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
  // The channels OFF has a place for, in Geomview's order.
  const auto channels = soup.vertex_attributes();
  check_attributes_for_write(channels, soup.num_points(), out.name());
  const Soup_attribute* extras[3] = {nullptr, nullptr, nullptr}; // normal, colour, texture coordinates
  for (const Soup_attribute& a : channels) {
    if (a.name == "normal" && a.width() == 3 && !extras[0]) extras[0] = &a;
    if (a.name == "color" && (a.width() == 3 || a.width() == 4) && !extras[1]) extras[1] = &a;
    if (a.name == "texcoord" && a.width() == 2 && !extras[2]) extras[2] = &a;
  }
  std::string& b = out.buffer;
  if (extras[2]) b += "ST";
  if (extras[1]) b += "C";
  if (extras[0]) b += "N";
  b += "OFF\n";
  append_int(b, soup.num_points());
  b += ' ';
  append_int(b, soup.num_faces());
  b += " 0\n";
  soup.for_each_point([&](std::size_t v, const Eigen::Vector3d& p) {
    check_point_for_write(p, v, out.name());
    append_point(b, p, precision);
    if (extras[0] || extras[1] || extras[2]) {
      b.pop_back(); // the point's newline: its extras follow on its line
      for (const Soup_attribute* a : extras)
        if (a)
          for (const double x : a->of(v)) {
            b += ' ';
            append_attribute(b, x, a->type, precision);
          }
      b += '\n';
    }
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
