// fuzz/genmesh_fuzz.h — the bodies of genmesh's fuzz targets, shared by the
// libFuzzer executables (fuzz/*.cpp, built with -DGENMESH_BUILD_FUZZERS=ON
// and clang) and by the tests that replay the seed and regression corpora
// (tests/test_io.cpp, tests/test_cli.cpp) under any compiler.
//
// A target returns normally when the input is read or refused the documented
// way (genmesh::io_error, genmesh::invalid_input); anything else — another
// exception, a crash, a sanitizer report, a hang (libFuzzer's -timeout) — is
// a finding. See scripts/fuzz.sh and docs/cli.md ("Fuzzing").
#pragma once

#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace genmesh_fuzz {

/// Largest input a reader target takes (libFuzzer's -max_len should be at
/// most this): larger inputs only slow the search down.
inline constexpr std::size_t max_reader_input = 1 << 20;

/// Parses `data` as a file of `format` the way read_soup() does (the same
/// reader, without the disk), then feeds the soup to what follows a read in
/// genmesh: check_soup(), the incidence loader, build_mesh() on both meshes
/// and check_mesh(). Returns normally unless something unexpected happened,
/// in which case it aborts (a finding).
inline void read_one(genmesh::File_format format, const std::uint8_t* data, std::size_t size) {
  namespace d = genmesh::detail::io;
  if (size > max_reader_input) return;
  const char* name = format == genmesh::File_format::off   ? "fuzz.off"
                     : format == genmesh::File_format::obj ? "fuzz.obj"
                     : format == genmesh::File_format::ply ? "fuzz.ply"
                                                           : "fuzz.stl";
  const d::File_content file{name, std::string(reinterpret_cast<const char*>(data), size)};
  try {
    genmesh::Polygon_soup soup;
    switch (format) {
      case genmesh::File_format::off: soup = d::read_off(file); break;
      case genmesh::File_format::obj: soup = d::read_obj(file); break;
      case genmesh::File_format::ply: soup = d::read_ply(file); break;
      default: soup = d::read_stl(file); break;
    }
    const genmesh::Soup_report report = genmesh::check_soup(soup);
    (void)genmesh::to_string(report);
    try {
      genmesh::Incidence_mesh<> m;
      m.load_soup(soup);
      (void)genmesh::to_string(m.manifold_report());
    } catch (const genmesh::invalid_input&) {
    }
    genmesh::Halfedge_mesh<> h;
    genmesh::build_mesh(soup, h, {.repair = !report.ok()});
    if (!genmesh::check_mesh(h).ok()) std::abort();   // build_mesh must give a valid mesh or refuse
    genmesh::Incidence_mesh<> inc;
    genmesh::build_mesh(soup, inc, {.repair = !report.ok()});
    if (!(genmesh::to_soup(inc) == genmesh::to_soup(h))) std::abort();   // the backends agree
  } catch (const genmesh::io_error&) {
  } catch (const genmesh::invalid_input&) {
  }
}

/// A command line for the CLI target, from fuzz input text: one argument per
/// line (at most 16, each at most 256 bytes; an empty line is an empty
/// argument, a final newline none) up to a line "----"; what
/// follows is the crease file's content. In arguments, "@in" stands for
/// `in` (a small valid mesh), "@bad" for `bad` (a small non-manifold one),
/// "@rep" for `rep` (a soup with a face visiting a point twice),
/// "@creases" for `creases` (where the caller writes the crease content) and
/// "@out.EXT" for `out_stem` + ".EXT". A "demo" command is dropped (it runs
/// every algorithm on every backend: seconds, not a parse).
struct Cli_case {
  std::vector<std::string> args;
  std::string creases;
  bool runnable = true;
};

struct Cli_paths {
  std::string in, bad, rep, creases, out_stem;
};

inline Cli_case parse_cli_case(std::string_view text, const Cli_paths& paths) {
  Cli_case c;
  std::size_t i = 0;
  while (i < text.size()) {   // a final newline starts no argument
    std::size_t nl = text.find('\n', i);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(i, nl - i);
    i = nl + 1;
    if (line == "----") {
      if (i < text.size()) c.creases = std::string(text.substr(i));
      break;
    }
    if (c.args.size() == 16 || line.size() > 256) {
      c.runnable = false;
      break;
    }
    std::string a(line);
    if (a == "@in") a = paths.in;
    else if (a == "@bad") a = paths.bad;
    else if (a == "@rep") a = paths.rep;
    else if (a == "@creases") a = paths.creases;
    else if (a.starts_with("@out.") && a.size() <= 9) a = paths.out_stem + a.substr(4);
    if (a.find('\0') != std::string::npos) c.runnable = false;
    c.args.push_back(std::move(a));
    if (nl == text.size()) break;
  }
  if (!c.args.empty() && c.args[0] == "demo") c.runnable = false;
  return c;
}

/// The meshes behind "@in", "@bad" and "@rep".
inline const char* cli_cube_off = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                  "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
inline const char* cli_fin_off = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
inline const char* cli_repeat_off = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n5 1 3 2 1 0\n";

} // namespace genmesh_fuzz
