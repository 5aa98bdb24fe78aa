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

#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace genmesh_fuzz {

/// Largest input a reader target takes (libFuzzer's -max_len should be at
/// most this): larger inputs only slow the search down.
inline constexpr std::size_t max_reader_input = 1 << 20;

/// The reader target of a corpus file, from its extension (STL otherwise).
inline genmesh::File_format format_of(std::string_view name) {
  return name.ends_with(".off")   ? genmesh::File_format::off
         : name.ends_with(".obj") ? genmesh::File_format::obj
         : name.ends_with(".ply") ? genmesh::File_format::ply
                                  : genmesh::File_format::stl;
}

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
/// "@tri" for `tri` (a small valid triangle mesh),
/// "@creases" for `creases` (where the caller writes the crease content) and
/// "@out.EXT" for `out_stem` + ".EXT". A "demo" command is dropped (it runs
/// every algorithm on every backend: seconds, not a parse), and so is an
/// argument holding a '/' of its own (but "/" alone): a fuzzed output path
/// could name any file.
struct Cli_case {
  std::vector<std::string> args;
  std::string creases;
  bool runnable = true;
};

struct Cli_paths {
  std::string in, bad, rep, creases, out_stem, tri;
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
    else if (a == "@tri") a = paths.tri;
    else if (a.starts_with("@out.") && a.size() <= 9) a = paths.out_stem + a.substr(4);
    // No NUL (argv cannot hold it), and no path of the fuzzer's own: it
    // could name (and overwrite) any file. The CLI target runs in a scratch
    // folder, so plain names stay there; "/" alone is a directory to refuse.
    const bool substituted = a != line;
    if (a.find('\0') != std::string::npos || (!substituted && a != "/" && a.find('/') != std::string::npos))
      c.runnable = false;
    c.args.push_back(std::move(a));
    if (nl == text.size()) break;
  }
  if (!c.args.empty() && c.args[0] == "demo") c.runnable = false;
  return c;
}

/// The meshes behind "@in", "@bad", "@rep" and "@tri".
inline const char* cli_cube_off = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                  "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
inline const char* cli_fin_off = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
inline const char* cli_repeat_off = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n5 1 3 2 1 0\n";
inline const char* cli_octahedron_off = "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                        "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";

/// Writes the meshes behind the placeholders to `paths`.
inline void write_cli_meshes(const Cli_paths& paths) {
  for (const auto& [path, text] : {std::pair<std::string, const char*>{paths.in, cli_cube_off}, {paths.bad, cli_fin_off},
                                   {paths.rep, cli_repeat_off}, {paths.tri, cli_octahedron_off}})
    std::ofstream(path, std::ios::binary) << text;
}

/// A soup that exercises what the simple generators do not: awkward numbers
/// (pi, a subnormal-sized coordinate, 1e22), a pentagon over existing points
/// and a 300-corner face visiting points repeatedly.
inline genmesh::Polygon_soup awkward_soup() {
  genmesh::Polygon_soup s = genmesh::make_icosphere(1);
  for (auto& p : s.points) p = p * (1.0 / 3.0) + Eigen::Vector3d(3.141592653589793, -1e-300, 1e22);
  s.add_face({0, 1, 2, 3, 4});
  std::vector<genmesh::Polygon_soup::Index> big;
  for (genmesh::Polygon_soup::Index i = 0; i < 300; ++i)
    big.push_back(i % static_cast<genmesh::Polygon_soup::Index>(s.num_points()));
  s.add_face(big);
  return s;
}

/// A soup check_soup() refuses: a face and its reverse (a duplicate), and a
/// face visiting a point twice (what the incidence backend reports).
inline genmesh::Polygon_soup repeats_soup() {
  genmesh::Polygon_soup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.add_face({0, 1, 2});
  s.add_face({2, 1, 0});
  s.add_face({0, 1, 2, 0});
  return s;
}

/// A command line (parse_cli_case's format) the CLI target starts from, and
/// the exit code it gives (replayed by tests/test_cli.cpp).
struct Cli_seed {
  std::string name, text;
  int exit_code;
};

/// Every command with its options, a crease file among them; invalid meshes
/// on the paths that report them (exit 1) and repair them (exit 0).
inline const std::vector<Cli_seed> cli_seeds{
    {"info", "info\n@in\n", 0},
    {"info_json_incidence", "info\n@bad\n--json\n--backend\nincidence\n", 1},
    {"check_incidence_fin", "check\n@bad\n--backend\nincidence\n", 1},
    {"check_repair", "check\n@rep\n--repair\n--backend\nsurface-mesh\n", 0},
    {"convert_ply_binary", "convert\n@in\n@out.ply\n--binary\n", 0},
    {"convert_repair_obj", "convert\n@bad\n@out.obj\n--repair\n", 0},
    {"convert_repair_repeated_corner", "convert\n@rep\n@out.off\n--repair\n--backend\nsurface-mesh\n", 0},
    {"subdivide_cc_creases", "subdivide\n@in\n@out.off\n--scheme\ncatmull-clark\n--levels\n2\n--creases\n@creases\n"
                             "----\n# cube edges\n0 1 inf\n1 2 0.5\n2 3 1e0\n", 0},
    {"subdivide_midpoint_fixed", "subdivide\n@in\n@out.stl\n--scheme\nmidpoint\n--levels\n1\n--boundary\nfixed\n", 0},
    {"subdivide_doo_sabin", "subdivide\n@in\n@out.off\n--scheme\ndoo-sabin\n--json\n--backend\nincidence\n", 0},
    {"simplify_faces", "simplify\n@tri\n@out.off\n--faces\n6\n--policy\nlength\n--boundary\nlock\n", 0},
    {"simplify_ratio", "simplify\n@tri\n@out.obj\n--ratio\n0.5\n--policy\nprobabilistic\n", 0},
    {"simplify_error", "simplify\n@tri\n@out.ply\n--error\n0.01\n--backend\nincidence\n", 0},
    {"subdivide_loop_tri", "subdivide\n@tri\n@out.off\n--scheme\nloop\n--levels\n2\n--creases\n@creases\n----\n0 2 inf\n", 0},
    {"subdivide_sqrt3", "subdivide\n@tri\n@out.obj\n--scheme\nsqrt3\n--backend\nsurface-mesh\n", 0},
    {"measure_two", "measure\n@in\n@in\n--samples\n100\n--json\n", 0},
    {"limits", "info\n@in\n--max-file-size\n1k\n--max-memory\n1G\n", 0},
};

/// Writes the seed corpus: for each reader format a folder DIR/FORMAT with
/// the generated meshes (and awkward_soup(), repeats_soup()) in that format, ASCII and, for
/// PLY and STL, binary; DIR/cli with cli_seeds. Used by the tests
/// (tests/test_io.cpp) and by scripts/fuzz.sh (through fuzz/make_seeds.cpp).
inline void write_seed_corpus(const std::filesystem::path& dir) {
  const std::vector<std::pair<std::string, genmesh::Polygon_soup>> meshes{
      {"tetrahedron", genmesh::make_tetrahedron()}, {"cube", genmesh::make_cube()},
      {"icosphere1", genmesh::make_icosphere(1)},   {"grid_hole", genmesh::make_grid_with_hole(4)},
      {"torus", genmesh::make_torus(5, 4, false)},  {"awkward", awkward_soup()},
      {"repeats", repeats_soup()}};
  for (const std::string fmt : {"off", "obj", "ply", "stl"}) {
    std::filesystem::create_directories(dir / fmt);
    for (const auto& [name, soup] : meshes) {
      genmesh::write_soup((dir / fmt / (name + "." + fmt)).string(), soup);
      if (fmt == "ply" || fmt == "stl")
        genmesh::write_soup((dir / fmt / (name + "_binary." + fmt)).string(), soup, {.binary = true});
    }
  }
  std::filesystem::create_directories(dir / "cli");
  for (const auto& seed : cli_seeds) std::ofstream(dir / "cli" / (seed.name + ".args"), std::ios::binary) << seed.text;
}

} // namespace genmesh_fuzz
