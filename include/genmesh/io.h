// genmesh/io.h — reading and writing polygon soups and meshes: OFF, OBJ, PLY, STL.
//
// What it reads: OFF ([ST][C][N]OFF, ASCII), OBJ (v, vt, vn and f; v, v/vt,
// v//vn, v/vt/vn corners; negative indices; line continuation), PLY (ascii, binary
// little and big endian; x y z of any numeric type among any other
// properties; vertex_indices lists of any integer types; other elements
// skipped) and STL (ASCII and binary, corners welded by exact equality).
// The whole file is read into memory and parsed from there with
// std::from_chars.
//
// STL corners with exactly equal coordinates are welded into one point
// (first-seen order); a facet that welding makes degenerate is kept — it is
// for check_soup() to report. OFF (and PLY) data after the elements the
// header announces is ignored, as CGAL does.
//
// Per-vertex attributes (Polygon_soup::vertex_attributes): PLY vertex
// properties beyond x y z are read into named channels (red green blue
// [alpha] → "color", nx ny nz → "normal", u v / s t / texture_u texture_v →
// "texcoord", any other scalar property → its own name) with their types;
// OFF's C, N and ST variants give "color", "normal" and "texcoord"; OBJ's
// vn, vertex colours and vt give "normal", "color" and "texcoord", a vertex
// with different texture coordinates at different corners (a texture seam)
// split into several points unless Read_options::obj_attributes says
// otherwise (different normals never split a vertex). The PLY writer
// writes every channel with its type; the OFF and OBJ writers write the
// channels they have a place for (normal, colour, texture coordinates); STL
// writes none. read_mesh() returns the file's channels, in the mesh's vertex
// order, and write_mesh() takes channels to write with the mesh. Malformed attribute values (not a number, not finite, an
// integer property outside its type) are io_errors naming the line or byte.
//
// Guarantees: every malformed file gives a genmesh::io_error naming the file
// and the line (text) or byte offset (binary) — never a crash, a silent
// partial soup or a bad_alloc from a lying header. Read soups have finite
// points, faces of at least 3 corners and in-range indices; nothing else is
// checked (repeated corners, non-manifold faces: see <genmesh/validity.h>).
// A write goes to a temporary file in the target's directory that is renamed
// over the target at the end, so a failed write leaves an existing file
// as it was.
//
// Limits: binary OFF, 4OFF/nOFF, OBJ free-form geometry and PLY tristrips are
// not read. Text output of doubles round-trips exactly at the default
// precision; binary STL stores floats; STL output triangulates polygons by
// fans.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/io/common.h>
#include <genmesh/detail/io/obj.h>
#include <genmesh/detail/io/off.h>
#include <genmesh/detail/io/ply.h>
#include <genmesh/detail/io/stl.h>
#include <genmesh/exceptions.h>
#include <genmesh/polygon_soup.h>
#include <genmesh/soup_to_mesh.h>

#include <cctype>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace genmesh {

/// A mesh file format.
enum class File_format {
  automatic,   ///< from the file name's extension (case-insensitive); for reading, from the content if that fails
  off,
  obj,
  ply,
  stl,
};

/// Options of read_soup() and read_mesh().
struct Read_options {
  File_format format = File_format::automatic;
  /// read_mesh only: passed to build_mesh() (split non-manifold vertices, reorient).
  bool repair = false;
  /// OBJ: texture coordinates, normals and vertex colours become channels;
  /// where a vertex's corners give different texture coordinates (a seam),
  /// it is split (split_seams), keeps its first corner's (first_corner), or
  /// nothing is read but geometry (none). Normals never split a vertex.
  Obj_attributes obj_attributes = Obj_attributes::split_seams;
  /// Largest input accepted, in bytes: a larger regular file is refused
  /// before it is read, a pipe once it has given more.
  std::uint64_t max_file_size = detail::io::default_max_file_size;
};

/// Options of write_soup() and write_mesh().
struct Write_options {
  File_format format = File_format::automatic;
  /// PLY and STL: binary (little endian) instead of text.
  bool binary = false;
  /// Significant digits of coordinates in text formats. 17 (or more) writes
  /// the shortest text that reads back as the same double.
  int precision = 17;
};

namespace detail::io {

inline File_format format_from_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".off") return File_format::off;
  if (ext == ".obj") return File_format::obj;
  if (ext == ".ply") return File_format::ply;
  if (ext == ".stl") return File_format::stl;
  return File_format::automatic;
}

/// Guesses the format from the content; automatic when nothing fits.
inline File_format format_from_content(const std::string& d) {
  const std::size_t bom = d.starts_with("\xEF\xBB\xBF") ? 3 : 0;   // UTF-8 byte order mark
  if (d.compare(bom, 4, "ply\n") == 0 || d.compare(bom, 4, "ply\r") == 0) return File_format::ply;
  if (stl_is_ascii(d)) return File_format::stl;
  // First token of the first line that is not blank or a comment.
  std::size_t i = bom;
  for (;;) {
    while (i < d.size() && Text_cursor::is_space_or_newline(d[i])) ++i;
    if (i < d.size() && d[i] == '#') {
      i = d.find_first_of("\r\n", i);
      if (i == std::string::npos) break;
      continue;
    }
    break;
  }
  if (i < d.size()) {
    std::size_t j = i;
    while (j < d.size() && !Text_cursor::is_space_or_newline(d[j])) ++j;
    std::string_view t(d.data() + i, j - i);
    if (t.ends_with("OFF") && t.size() <= 7) return File_format::off;
    for (std::string_view k : {"v", "vt", "vn", "f", "o", "g", "s", "mtllib", "usemtl"})
      if (t == k) return File_format::obj;
  }
  if (d.size() >= 84 && d.size() == 84 + 50 * std::uint64_t{load<std::uint32_t>(d.data() + 80, true)})
    return File_format::stl;
  return File_format::automatic;
}

} // namespace detail::io

/// Reads a polygon soup from an OFF, OBJ, PLY or STL file. The format comes
/// from options.format, else from the extension, else from the content.
/// Throws io_error (naming the file, and the line or byte offset) on any
/// problem: missing or empty file, unknown format, truncated data, wrong
/// counts, indices out of range, faces with fewer than 3 corners, NaN or inf
/// coordinates, malformed numbers, binary data in a text format.
inline Polygon_soup read_soup(const std::filesystem::path& path, const Read_options& options = {}) {
  namespace d = detail::io;
  const d::File_content file = d::read_whole_file(path, options.max_file_size);
  File_format format = options.format;
  if (format == File_format::automatic) format = d::format_from_extension(path);
  if (format == File_format::automatic) format = d::format_from_content(file.data);
  try {
    switch (format) {
      case File_format::off: return d::read_off(file);
      case File_format::obj: return d::read_obj(file, options.obj_attributes);
      case File_format::ply: return d::read_ply(file);
      case File_format::stl: return d::read_stl(file);
      case File_format::automatic: break;
    }
  } catch (const std::bad_alloc&) {
    throw io_error(file.name, "out of memory while parsing the file (" + d::human_bytes(file.data.size()) + ")");
  }
  throw io_error(file.name,
                 "unknown format: the extension " + d::quote(path.extension().string()) +
                     " is not .off, .obj, .ply or .stl and the content is none of them",
                 std::nullopt, 0);
}

namespace detail::io {

/// write_soup() and write_mesh(): `source` is a Soup_source or a
/// detail::Soup_view, streamed to a temporary renamed over `path` at the end.
template <class Source>
void write_source(const std::filesystem::path& path, const Source& source, const Write_options& options) {
  File_format format = options.format;
  if (format == File_format::automatic) format = format_from_extension(path);
  if (std::error_code ec; std::filesystem::is_directory(path, ec))
    throw io_error(path.string(), "cannot write: it is a directory");
  if (format == File_format::automatic)
    throw io_error(path.string(), "unknown format: the extension " + quote(path.extension().string()) +
                                      " is not .off, .obj, .ply or .stl");
  Atomic_file out(path);
  switch (format) {
    case File_format::off: write_off(out, source, options.precision); break;
    case File_format::obj: write_obj(out, source, options.precision); break;
    case File_format::ply: write_ply(out, source, options.binary, options.precision); break;
    case File_format::stl: write_stl(out, source, options.binary, options.precision); break;
    case File_format::automatic: break;
  }
  out.commit();
}

} // namespace detail::io

/// Writes a polygon soup as OFF, OBJ, PLY (ascii or binary little endian) or
/// STL (ASCII or binary; polygons triangulated as fans). The format comes from
/// options.format, else from the extension. Throws io_error if the format is
/// unknown, the directory does not exist or is not writable, or the soup
/// cannot be written (an index out of range, a face of fewer than 3 corners,
/// a non-finite point); the target is then untouched.
inline void write_soup(const std::filesystem::path& path, const Polygon_soup& soup,
                       const Write_options& options = {}) {
  detail::io::write_source(path, detail::io::Soup_source(soup), options);
}

/// Removes the temporary files of the writes in progress (see write_soup()):
/// async-signal-safe (unlink() on fixed buffers), for a program's SIGINT,
/// SIGTERM or SIGHUP handler, which then ends the program. A write whose
/// temporary is removed so cannot commit: the target stays as it was.
inline void remove_pending_temporaries() noexcept {
  auto& p = detail::io::pending_temporaries;
  for (int i = 0; i < p.slots; ++i)
    if (p.state[i].load() == p.ready) ::unlink(p.path[i]);
}

/// Reads a file into the (empty) mesh g: read_soup(), then build_mesh()
/// (vertex and face order kept). A soup that build_mesh refuses (non-manifold,
/// inconsistently oriented; see Read_options::repair) gives an io_error naming
/// the file, with build_mesh's message. Returns the file's per-vertex
/// attribute channels, value i for the i-th vertex of vertices(g) (with
/// .repair, a split vertex's copies get its values): put them into property
/// maps with read_vertex_attribute(), or hand them to write_mesh() as they are.
template <class G>
  requires detail::Soup_buildable<G>
std::vector<Soup_attribute> read_mesh(const std::filesystem::path& path, G& g, const Read_options& options = {}) {
  Polygon_soup soup = read_soup(path, options);
  try {
    // Repaired here rather than in build_mesh, so that the channels follow the split vertices.
    if (options.repair && !soup.vertex_attributes.empty()) repair_soup(soup); // nothing when the soup is fine
    build_mesh(soup, g, Build_options{.repair = options.repair});
  } catch (const invalid_input& e) {
    throw io_error(path.string(), e.what());
  }
  return std::move(soup.vertex_attributes);
}

/// Writes the mesh g as write_soup(path, to_soup(g), options) would, byte
/// for byte, but streamed from g: no copy of the mesh is made (the writer
/// holds one integer per vertex, numbering the vertices).
template <FaceListGraph G>
void write_mesh(const std::filesystem::path& path, const G& g, const Write_options& options = {}) {
  detail::io::write_source(path, detail::Soup_view<G>(g), options);
}

/// write_mesh() with per-vertex attribute channels: value i of each channel
/// belongs to the i-th vertex of vertices(g) (what read_mesh() returns for an
/// unchanged mesh, or make_soup_attribute() makes from a property map). The
/// format writes those it has a place for (format_stores()). Throws io_error,
/// before the target changes, when a channel does not hold width() finite
/// values for each vertex.
template <FaceListGraph G>
void write_mesh(const std::filesystem::path& path, const G& g, std::span<const Soup_attribute> vertex_attributes,
                const Write_options& options = {}) {
  detail::io::write_source(path, detail::Soup_view<G>(g, vertex_attributes), options);
}

/// The format of `path` written with `options` (the extension's when
/// options.format is automatic; automatic when unknown).
inline File_format output_format(const std::filesystem::path& path, const Write_options& options = {}) {
  return options.format == File_format::automatic ? detail::io::format_from_extension(path) : options.format;
}

/// True when files of format f hold channel a: PLY holds every channel; OFF
/// and OBJ "normal" (3 values), "color" (3 or 4; OBJ drops alpha) and
/// "texcoord" (2); STL none.
inline bool format_stores(File_format f, const Soup_attribute& a) {
  const bool known = (a.name == "normal" && a.width() == 3) ||
                     (a.name == "color" && (a.width() == 3 || a.width() == 4)) ||
                     (a.name == "texcoord" && a.width() == 2);
  return f == File_format::ply || ((f == File_format::off || f == File_format::obj) && known);
}

} // namespace genmesh
