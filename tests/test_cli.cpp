// The genmesh program as a user runs it: exit codes (0 ok, 1 invalid mesh,
// 2 bad input or usage), messages naming the file and line, --json records
// whose counts equal CGAL's on the same file, on every backend.
#include "backends.h"

#include <genmesh/generators.h>
#include <genmesh/io.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include <csignal>
#include <thread>
#include <unistd.h>

#include "../fuzz/genmesh_fuzz.h"

namespace {

using genmesh_test::real_mesh;
using genmesh_test::tmp_path;

struct Cli_run {
  int exit_code;
  std::string out;  // stdout
  std::string err;  // stderr
};

// The program under test: the build's genmesh, or $GENMESH_TEST_CLI (to
// replay these tests against another build, e.g. one from before a fix).
const char* cli_program() {
  const char* other = std::getenv("GENMESH_TEST_CLI");
  return other && *other ? other : GENMESH_CLI;
}

// Runs the genmesh program with `args` (already shell-quoted where needed).
Cli_run genmesh(const std::string& args) {
  const std::string err_file = tmp_path("cli_stderr.txt");
  const std::string cmd = std::string(cli_program()) + " " + args + " 2>" + err_file;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed: " + cmd);
  std::string out;
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  std::ifstream e(err_file);
  std::stringstream es;
  es << e.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, es.str()};
}

// The integer field `key` of a one-line JSON record.
long long json_int(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\":(-?[0-9]+)")))
    throw std::runtime_error("no integer field '" + key + "' in: " + json);
  return std::stoll(m[1]);
}

// The floating-point field `key` of a one-line JSON record.
double json_double(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\":(-?[0-9.eE+-]+)")))
    throw std::runtime_error("no number field '" + key + "' in: " + json);
  return std::stod(m[1]);
}

bool json_bool(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\":(true|false)")))
    throw std::runtime_error("no boolean field '" + key + "' in: " + json);
  return m[1] == "true";
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(Cli, DemoRunsEveryBackendAndTheyAgree) {
  Cli_run r = genmesh("demo");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("all backends agree"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("surface-mesh"), std::string::npos);
  EXPECT_NE(r.out.find("incidence"), std::string::npos);
  EXPECT_EQ(r.out.find("DIFFERS"), std::string::npos) << r.out;

  Cli_run j = genmesh("demo --json");
  EXPECT_EQ(j.exit_code, 0);
  std::istringstream lines(j.out);
  int records = 0;
  for (std::string line; std::getline(lines, line); ++records)
    EXPECT_TRUE(json_bool(line, "same_as_reference")) << line;
  EXPECT_GE(records, 90);  // six meshes, five steps, three backends
}

// `info --json` on real meshes equals CGAL's own reading of the file.
TEST(Cli, InfoCountsEqualCgalOnRealMeshes) {
  for (const char* name : {"elephant.off", "armadillo.off", "blobby_3cc.off", "cube_quad.off", "b9.ply"}) {
    const std::string path = real_mesh(name);
    genmesh_test::Surface_mesh sm;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, sm)) << path;
    std::vector<genmesh_test::Surface_mesh::Halfedge_index> cycles;
    CGAL::Polygon_mesh_processing::extract_boundary_cycles(sm, std::back_inserter(cycles));
    auto fcc = sm.add_property_map<genmesh_test::Surface_mesh::Face_index, std::size_t>("f:cc").first;
    // genmesh counts an isolated vertex as a component of its own (so that
    // χ = V − E + F sums over components); CGAL counts face components only.
    std::size_t components = CGAL::Polygon_mesh_processing::connected_components(sm, fcc);
    for (auto v : sm.vertices()) components += sm.is_isolated(v) ? 1 : 0;

    for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
      SCOPED_TRACE(std::string(name) + " on " + backend);
      Cli_run r = genmesh("info --json --backend " + std::string(backend) + " " + path);
      ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
      EXPECT_EQ(json_int(r.out, "vertices"), static_cast<long long>(sm.number_of_vertices()));
      EXPECT_EQ(json_int(r.out, "edges"), static_cast<long long>(sm.number_of_edges()));
      EXPECT_EQ(json_int(r.out, "faces"), static_cast<long long>(sm.number_of_faces()));
      EXPECT_EQ(json_int(r.out, "boundary_loops"), static_cast<long long>(cycles.size()));
      EXPECT_EQ(json_int(r.out, "components"), static_cast<long long>(components));
      EXPECT_EQ(json_int(r.out, "euler_characteristic"),
                static_cast<long long>(sm.number_of_vertices()) -
                    static_cast<long long>(sm.number_of_edges()) +
                    static_cast<long long>(sm.number_of_faces()));
      EXPECT_TRUE(json_bool(r.out, "manifold"));
      EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one line: " << r.out;
    }
  }
}

// A fin: three triangles share the edge 0-1.
//
//        2
//        |
//   3 -- 0 -- 4      (all three faces hang on edge 0-1)
//        |
//        1
TEST(Cli, CheckRefusesNonManifoldWithExitOne) {
  const std::string path = tmp_path("fin.off");
  write_file(path, "OFF\n5 3 0\n0 0 0\n0 -1 0\n0 1 1\n-1 0 1\n1 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    Cli_run r = genmesh(std::string("check --backend ") + backend + " " + path);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("non-manifold"), std::string::npos) << r.out;
  }
  // The incidence mesh loads the fin as it is and names its edge (the first
  // edge made: 0 → 1, edge 0).
  Cli_run r = genmesh("check --backend incidence " + path);
  EXPECT_NE(r.out.find("edges in three or more faces: 0\n"), std::string::npos) << r.out;
}

TEST(Cli, CheckRepairsABowTie) {
  // Two triangles touching at vertex 0 only.
  const std::string path = tmp_path("bowtie.off");
  write_file(path, "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n");
  Cli_run refused = genmesh("check " + path);
  EXPECT_EQ(refused.exit_code, 1) << refused.out << refused.err;
  Cli_run named = genmesh("check --backend incidence " + path);
  EXPECT_EQ(named.exit_code, 1) << named.out << named.err;
  EXPECT_NE(named.out.find("vertices whose faces form several fans: 0\n"), std::string::npos) << named.out;
  Cli_run repaired = genmesh("info --json --repair " + path);
  EXPECT_EQ(repaired.exit_code, 0) << repaired.out << repaired.err;
  EXPECT_EQ(json_int(repaired.out, "vertices"), 6);  // the bow-tie vertex is split in two
  EXPECT_EQ(json_int(repaired.out, "components"), 2);
}

TEST(Cli, BadInputExitsTwoNamingFileAndLine) {
  const std::string path = tmp_path("truncated.off");
  write_file(path, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n");  // one vertex and both faces missing
  Cli_run r = genmesh("info " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex(":[0-9]+:"))) << "no line number: " << r.err;

  Cli_run missing = genmesh("check " + tmp_path("does-not-exist.off"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("does-not-exist.off"), std::string::npos) << missing.err;

  const std::string nan_path = tmp_path("nan.off");
  write_file(nan_path, "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  Cli_run nan = genmesh("check " + nan_path);
  EXPECT_EQ(nan.exit_code, 2) << nan.out;
  EXPECT_NE(nan.err.find("nan.off"), std::string::npos) << nan.err;
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(genmesh("").exit_code, 2);
  EXPECT_EQ(genmesh("frobnicate").exit_code, 2);
  Cli_run r = genmesh("info --backend nonsense " + real_mesh("cube.off"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nonsense"), std::string::npos) << r.err;
  EXPECT_EQ(genmesh("info").exit_code, 2);
  EXPECT_EQ(genmesh("convert " + real_mesh("cube.off")).exit_code, 2);
}

TEST(Cli, ConvertRoundTripsThroughEveryFormat) {
  const std::string in = real_mesh("elephant.off");
  Cli_run ref = genmesh("info --json " + in);
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  std::string current = in;
  for (std::string out : {"e.ply", "e_bin.ply", "e.obj", "e.stl", "e_bin.stl", "e.off"}) {
    const std::string path = tmp_path(out);
    std::filesystem::remove(path);
    const bool binary = out.find("_bin") != std::string::npos;
    Cli_run c = genmesh("convert " + current + " " + path + (binary ? " --binary" : ""));
    ASSERT_EQ(c.exit_code, 0) << out << ": " << c.out << c.err;
    Cli_run info = genmesh("info --json " + path);
    ASSERT_EQ(info.exit_code, 0) << out << ": " << info.err;
    for (const char* key : {"vertices", "edges", "faces", "boundary_loops", "euler_characteristic"})
      EXPECT_EQ(json_int(info.out, key), json_int(ref.out, key)) << out << " " << key;
    current = path;
  }
}

TEST(Cli, FailedConvertLeavesExistingOutputIntact) {
  const std::string out = tmp_path("keep_me.off");
  write_file(out, "precious");
  const std::string bad = tmp_path("bad_index.off");
  write_file(bad, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");  // index 7 out of range
  Cli_run r = genmesh("convert " + bad + " " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_file(out), "precious");

  Cli_run nodir = genmesh("convert " + real_mesh("cube.off") + " " + tmp_path("no/such/dir/x.off"));
  EXPECT_EQ(nodir.exit_code, 2);
  EXPECT_NE(nodir.err.find("x.off"), std::string::npos) << nodir.err;
}

// convert carries the per-vertex attributes the output format can hold:
// colored_tetra.ply (normals, uchar colours, an int id) → OFF (CNOFF: the id
// has no place, a note says so) → OBJ (vn, colours in [0, 1]) → PLY, on
// every backend with the same files; an OBJ with a texture seam becomes a
// PLY with the seam's vertices split and their texture coordinates.
TEST(Cli, ConvertCarriesAttributesAcrossFormats) {
  const genmesh::Polygon_soup in = genmesh::read_soup(real_mesh("colored_tetra.ply"));
  const std::vector<double>& normal = in.vertex_attribute("normal")->values;
  const std::vector<double>& colour = in.vertex_attribute("color")->values;
  std::map<std::string, std::string> first;
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    SCOPED_TRACE(backend);
    std::string current = real_mesh("colored_tetra.ply");
    for (const std::string ext : {".off", ".obj", ".ply"}) {
      const std::string out = tmp_path(std::string("attr_") + backend + ext);
      Cli_run c = genmesh("convert " + current + " " + out + " --backend " + backend);
      ASSERT_EQ(c.exit_code, 0) << ext << ": " << c.out << c.err;
      EXPECT_EQ(c.err.find("note") != std::string::npos, ext == ".off") << ext << ": " << c.err;
      if (ext == ".off") {
        EXPECT_NE(c.err.find("attribute(s) id;"), std::string::npos) << c.err;
      }
      const genmesh::Polygon_soup s = genmesh::read_soup(out);
      ASSERT_NE(s.vertex_attribute("normal"), nullptr) << ext;
      ASSERT_NE(s.vertex_attribute("color"), nullptr) << ext;
      EXPECT_EQ(s.vertex_attribute("normal")->values, normal) << ext;
      const std::vector<double>& c2 = s.vertex_attribute("color")->values;
      ASSERT_EQ(c2.size(), colour.size()) << ext;
      const double full = ext == ".off" ? 1.0 : 255.0; // OBJ's colours are in [0, 1]
      for (std::size_t i = 0; i < colour.size(); ++i) EXPECT_NEAR(c2[i] * full, colour[i], 1e-12) << ext << " " << i;
      if (first.count(ext)) EXPECT_EQ(read_file(out), first[ext]) << ext;
      else first[ext] = read_file(out);
      current = out;
    }
  }
  const std::string seam = tmp_path("seam_cli.obj");
  write_file(seam, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 0.5\nvt 0.5 1\nvt 0 1\n"
                   "f 1/1 2/2 3/3\nf 1/4 3/5 4/6\n");
  const std::string ply = tmp_path("seam_cli.ply");
  Cli_run c = genmesh("convert " + seam + " " + ply + " --json");
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_EQ(json_int(c.out, "vertices"), 6);
  EXPECT_EQ(json_int(c.out, "boundary_loops"), 2);
  const genmesh::Polygon_soup s = genmesh::read_soup(ply);
  ASSERT_NE(s.vertex_attribute("texcoord"), nullptr);
  EXPECT_EQ(s.vertex_attribute("texcoord")->values, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 0, 0.5, 0.5, 1}));
}

// simplify --attributes: a flat grid coloured red below a slanted line and
// blue above (uchar colours in a PLY). With the colour in the quadrics the
// seam keeps narrow triangles (the faces whose corners differ in colour
// cover far less area than with plane quadrics alone, which see no cost on
// the flat grid); the output carries the colours with their type; every
// backend writes the same file; --json names the attributes used; a name the
// file lacks or another policy is refused.
TEST(Cli, SimplifyWithAttributesKeepsAColourSeam) {
  genmesh::Polygon_soup grid = genmesh::make_grid(24, 24);
  genmesh::Soup_attribute colour{"color", {"red", "green", "blue"}, genmesh::Scalar_type::uint8, {}};
  for (const auto& p : grid.points) {
    const bool above = p.y() > 0.3 + 0.35 * p.x();
    colour.values.insert(colour.values.end(), {above ? 0.0 : 255.0, 0.0, above ? 255.0 : 0.0});
  }
  grid.vertex_attributes.push_back(colour);
  const std::string in = tmp_path("seam.ply");
  genmesh::write_soup(in, grid);
  // Area of the output faces whose corners are not all of one colour.
  auto mixed_area = [](const std::string& file) {
    const genmesh::Polygon_soup s = genmesh::read_soup(file);
    const genmesh::Soup_attribute* c = s.vertex_attribute("color");
    if (!c || c->type != genmesh::Scalar_type::uint8) throw std::runtime_error("no uchar colour in " + file);
    double area = 0;
    for (std::size_t f = 0; f < s.num_faces(); ++f) {
      const auto v = s.face(f);
      const double r0 = c->of(v[0])[0], r1 = c->of(v[1])[0], r2 = c->of(v[2])[0];
      if (r0 != r1 || r0 != r2)
        area += 0.5 * (s.points[v[1]] - s.points[v[0]]).cross(s.points[v[2]] - s.points[v[0]]).norm();
    }
    return area;
  };
  std::string first;
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    SCOPED_TRACE(backend);
    const std::string out = tmp_path(std::string("seam_") + backend + ".ply");
    Cli_run r = genmesh("simplify " + in + " " + out + " --ratio 0.15 --json --attributes color=0.5 --backend " + backend);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("\"attributes\":[{\"name\":\"color\",\"width\":3,\"weight\":0.5}]"), std::string::npos) << r.out;
    EXPECT_NE(read_file(out).find("property uchar red"), std::string::npos);
    if (first.empty()) first = read_file(out);
    else EXPECT_EQ(read_file(out), first);
  }
  const std::string plain = tmp_path("seam_plain.ply");
  Cli_run p = genmesh("simplify " + in + " " + plain + " --ratio 0.15 --json");
  ASSERT_EQ(p.exit_code, 0) << p.out << p.err;
  EXPECT_NE(p.out.find("\"attributes\":[{\"name\":\"color\",\"width\":3,\"weight\":0}]"), std::string::npos) << p.out;
  const double with = mixed_area(tmp_path("seam_halfedge.ply")), without = mixed_area(plain);
  std::printf("mixed-colour area: %.4g with attributes, %.4g without\n", with, without);
  EXPECT_LT(with, 0.5 * without);
  // The whole file's attributes at one weight: the same as naming the only one.
  ASSERT_EQ(genmesh("simplify " + in + " " + tmp_path("seam_all.ply") + " --ratio 0.15 --attributes 0.5").exit_code, 0);
  EXPECT_EQ(read_file(tmp_path("seam_all.ply")), first);

  Cli_run missing = genmesh("simplify " + in + " " + tmp_path("x.ply") + " --ratio 0.5 --attributes normal=1");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("'normal', which the file does not have (its attributes: color)"), std::string::npos)
      << missing.err;
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.ply") + " --ratio 0.5 --attributes 1 --policy length").exit_code, 2);
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.ply") + " --ratio 0.5 --attributes color=").exit_code, 2);
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.ply") + " --ratio 0.5 --attributes -1").exit_code, 2);

  // Hoppe's 1999 metric keeps the seam as well, the same file on every backend.
  std::string hoppe_first;
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    SCOPED_TRACE(backend);
    const std::string out = tmp_path(std::string("seam_hoppe_") + backend + ".ply");
    Cli_run r = genmesh("simplify " + in + " " + out +
                        " --ratio 0.15 --json --attributes color=0.5 --attribute-metric hoppe --backend " + backend);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("\"attribute_metric\":\"hoppe\""), std::string::npos) << r.out;
    if (hoppe_first.empty()) hoppe_first = read_file(out);
    else EXPECT_EQ(read_file(out), hoppe_first);
  }
  const double hoppe = mixed_area(tmp_path("seam_hoppe_halfedge.ply"));
  std::printf("mixed-colour area with Hoppe's metric: %.4g\n", hoppe);
  EXPECT_LT(hoppe, 0.5 * without);
  EXPECT_NE(hoppe_first, first); // another metric, another mesh
  Cli_run bad = genmesh("simplify " + in + " " + tmp_path("x.ply") + " --ratio 0.5 --attributes 1 --attribute-metric hop");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown attribute metric 'hop' (gh98|hoppe)"), std::string::npos) << bad.err;
}

} // namespace

namespace {

// `subdivide` on both backends: the counts Loop's and Catmull-Clark's
// topology dictates, the same numbers on both, and the written file reads
// back with them.
TEST(Cli, SubdivideGivesTheSchemesCountsOnEveryBackend) {
  const std::string in = real_mesh("elephant.off");
  Cli_run ref = genmesh("info --json " + in);
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  const long long v = json_int(ref.out, "vertices"), e = json_int(ref.out, "edges"),
                  f = json_int(ref.out, "faces");
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    SCOPED_TRACE(backend);
    const std::string out = tmp_path(std::string("loop_") + backend + ".ply");
    Cli_run r = genmesh("subdivide " + in + " " + out + " --scheme loop --levels 1 --binary --json --backend " +
                        backend);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(json_int(r.out, "vertices"), v + e);  // one new vertex per edge
    EXPECT_EQ(json_int(r.out, "faces"), 4 * f);     // 1-to-4
    EXPECT_EQ(json_int(r.out, "euler_characteristic"), v - e + f);
    Cli_run back = genmesh("info --json " + out);
    ASSERT_EQ(back.exit_code, 0) << back.err;
    EXPECT_EQ(json_int(back.out, "vertices"), v + e);
  }
  // Catmull-Clark on quads: V' = V + E + F, F' = Σ deg(f) = 4F for quads.
  Cli_run cc = genmesh("subdivide " + real_mesh("cube_quad.off") + " " + tmp_path("cc.off") +
                       " --scheme catmull-clark --levels 2 --json");
  ASSERT_EQ(cc.exit_code, 0) << cc.err;
  EXPECT_EQ(json_int(cc.out, "faces"), 6 * 4 * 4);
  EXPECT_EQ(json_int(cc.out, "vertices"), 98);  // 8+12+6 = 26 after one level; 26+48+24 after two
}

TEST(Cli, SubdivideRefusesWhatTheSchemeCannotTake) {
  const std::string quads = real_mesh("cube_quad.off");
  Cli_run loop = genmesh("subdivide " + quads + " " + tmp_path("x.off") + " --scheme loop");
  EXPECT_EQ(loop.exit_code, 2);
  EXPECT_NE(loop.err.find("face 0"), std::string::npos) << loop.err;

  EXPECT_EQ(genmesh("subdivide " + quads + " " + tmp_path("x.off") + " --scheme nonsense").exit_code, 2);
  EXPECT_EQ(genmesh("subdivide " + quads + " " + tmp_path("x.off")).exit_code, 2);  // no --scheme
  EXPECT_EQ(genmesh("subdivide " + quads + " " + tmp_path("x.off") + " --scheme loop --levels x").exit_code, 2);

  const std::string creases = tmp_path("creases.txt");
  write_file(creases, "0 1 inf\n1 2 oops\n");
  Cli_run bad = genmesh("subdivide " + quads + " " + tmp_path("x.off") +
                        " --scheme catmull-clark --creases " + creases);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("creases.txt:2:"), std::string::npos) << bad.err;
}

// Infinitely sharp creases on all 12 edges of a cube make every vertex a
// corner (three crease edges): the edges stay straight, the faces flat, so
// the result is still exactly the cube's surface.
TEST(Cli, SharpCreasesKeepTheCube) {
  const std::string creases = tmp_path("cube_edges.txt");
  // The edges of cube_quad.off's faces 0374 3267 2156 1045 4765 0123.
  write_file(creases, "0 3 inf\n3 7 inf\n7 4 inf\n4 0 inf\n3 2 inf\n2 6 inf\n6 7 inf\n"
                      "2 1 inf\n1 5 inf\n5 6 inf\n1 0 inf\n4 5 inf\n");
  const std::string out = tmp_path("creased.obj");
  Cli_run r = genmesh("subdivide " + real_mesh("cube_quad.off") + " " + out +
                      " --scheme catmull-clark --levels 3 --creases " + creases);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::istringstream obj(read_file(out));
  int vertices = 0, on_cube_edges = 0;
  for (std::string line; std::getline(obj, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream ls(line.substr(2));
    double c[3];
    ls >> c[0] >> c[1] >> c[2];
    ++vertices;
    int at_one = 0;
    double max_abs = 0;
    for (double x : c) {
      at_one += std::abs(std::abs(x) - 1.0) < 1e-12;
      max_abs = std::max(max_abs, std::abs(x));
    }
    EXPECT_NEAR(max_abs, 1.0, 1e-12) << line;  // on the cube's surface
    on_cube_edges += at_one >= 2;
  }
  EXPECT_EQ(vertices, 386);            // 8 + 12·7 + 6·7² after three levels
  EXPECT_EQ(on_cube_edges, 8 + 12 * 7); // every edge cut into 8 straight segments
}

// ---- hostile use (issue 14) ----------------------------------------------------

// Single-quotes an argument for the shell.
std::string shell_quote(const std::string& a) {
  std::string q = "'";
  for (char c : a) {
    if (c == '\'') q += "'\\''";
    else q += c;
  }
  return q + "'";
}

// The regression corpus of the CLI target (tests/fuzz/regressions/cli): one
// file per finding, "# expect N", optional "# message TEXT" lines (TEXT must
// appear in the output; @in, @bad, @rep, @creases stand for the files), then
// the fuzz input (genmesh_fuzz::parse_cli_case). Each must exit N, print its
// messages, keep them short, and name a file (or give the usage) when it
// fails. Every case failed on the program before the fixes (docs/fuzzing.md).
TEST(CliHostile, RegressionCorpusGivesTheDocumentedExitCodes) {
  const std::filesystem::path dir = std::filesystem::path(GENMESH_SOURCE_DIR) / "tests/fuzz/regressions/cli";
  const genmesh_fuzz::Cli_paths paths{tmp_path("corpus_in.off"), tmp_path("corpus_bad.off"), tmp_path("corpus_rep.off"),
                                      tmp_path("corpus_creases.txt"), tmp_path("corpus_out"), tmp_path("corpus_tri.off")};
  genmesh_fuzz::write_cli_meshes(paths);
  const auto substitute = [&](std::string m) {
    for (const auto& [key, path] : {std::pair<std::string, std::string>{"@creases", paths.creases},
                                    {"@in", paths.in}, {"@bad", paths.bad}, {"@rep", paths.rep}, {"@tri", paths.tri}})
      if (const auto at = m.find(key); at != std::string::npos) m.replace(at, key.size(), path);
    return m;
  };
  std::size_t cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string text = read_file(entry.path().string());
    ASSERT_TRUE(text.starts_with("# expect ")) << entry.path();
    const int expected = std::stoi(text.substr(9));
    std::size_t body = text.find('\n') + 1;
    std::vector<std::string> messages;
    while (text.compare(body, 10, "# message ") == 0) {
      const std::size_t nl = text.find('\n', body);
      messages.push_back(substitute(text.substr(body + 10, nl - body - 10)));
      body = nl + 1;
    }
    const genmesh_fuzz::Cli_case c = genmesh_fuzz::parse_cli_case(std::string_view(text).substr(body), paths);
    ASSERT_TRUE(c.runnable) << entry.path();
    write_file(paths.creases, c.creases);
    std::string args;
    for (const auto& a : c.args) args += shell_quote(a) + " ";
    SCOPED_TRACE(entry.path().filename().string() + ": genmesh " + args);
    const Cli_run r = genmesh(args);
    EXPECT_EQ(r.exit_code, expected) << r.out << r.err;
    EXPECT_LT(r.err.size(), 4000u) << r.err.substr(0, 4000);
    EXPECT_LT(r.out.size(), 4000u);
    for (const auto& m : messages) EXPECT_NE((r.err + r.out).find(m), std::string::npos) << m << "\nnot in: " << r.err << r.out;
    if (expected != 0) {
      bool named = r.err.find("usage") != std::string::npos;
      for (const auto& f : {paths.in, paths.bad, paths.rep, paths.creases, paths.tri, std::string("/:")})
        named = named || r.err.find(f) != std::string::npos || r.out.find(f) != std::string::npos;
      EXPECT_TRUE(named) << "no file named in: " << r.err << r.out;
    }
    ++cases;
  }
  EXPECT_GE(cases, 15u);
}

// The CLI target's seed corpus (genmesh_fuzz::cli_seeds) runs as each seed
// says: the fuzzer starts from command lines that work.
TEST(CliHostile, SeedCorpusGivesItsExitCodes) {
  const genmesh_fuzz::Cli_paths paths{tmp_path("seed_in.off"), tmp_path("seed_bad.off"), tmp_path("seed_rep.off"),
                                      tmp_path("seed_creases.txt"), tmp_path("seed_out"), tmp_path("seed_tri.off")};
  genmesh_fuzz::write_cli_meshes(paths);
  for (const auto& seed : genmesh_fuzz::cli_seeds) {
    const genmesh_fuzz::Cli_case c = genmesh_fuzz::parse_cli_case(seed.text, paths);
    ASSERT_TRUE(c.runnable) << seed.name;
    write_file(paths.creases, c.creases);
    std::string args;
    for (const auto& a : c.args) args += shell_quote(a) + " ";
    const Cli_run r = genmesh(args);
    EXPECT_EQ(r.exit_code, seed.exit_code) << seed.name << ": genmesh " << args << "\n" << r.out << r.err;
  }
}

TEST(CliHostile, ErrorsNameTheFileAndTheLineAndStayShort) {
  const std::string cube = tmp_path("hostile_cube.off");
  write_file(cube, genmesh_fuzz::cli_cube_off);
  // A 1 MB crease line is not echoed whole.
  const std::string creases = tmp_path("long_creases.txt");
  write_file(creases, "0 1 inf\n0 " + std::string(1 << 20, '7') + " 1\n");
  Cli_run r = genmesh("subdivide " + cube + " " + tmp_path("x.off") + " --scheme catmull-clark --creases " + creases);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("long_creases.txt:2:"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_LT(r.err.size(), 1000u);
  // Crease errors that are not parse errors name their line too.
  write_file(creases, "# the cube's edges\n0 1 inf\n\n1 2 1\n0 6 1\n");
  r = genmesh("subdivide " + cube + " " + tmp_path("x.off") + " --scheme catmull-clark --creases " + creases);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("long_creases.txt:5: (0, 6) is not an edge"), std::string::npos) << r.err;
  // A degenerate 300k-corner face: a short report (not one number per
  // corner), exit 1, on every backend.
  std::string big = "OFF\n300000 1 0\n";
  for (int i = 0; i < 300000; ++i) big += std::to_string(i) + " 0 0\n";
  big += "300001";
  for (int i = 0; i < 300000; ++i) big += " " + std::to_string(i);
  big += " 0\n";
  const std::string huge = tmp_path("degenerate_big_face.off");
  write_file(huge, big);
  for (const char* backend : {"halfedge", "incidence"}) {
    r = genmesh(std::string("check ") + huge + " --backend " + backend);
    EXPECT_EQ(r.exit_code, 1) << backend << r.err;
    EXPECT_LT(r.out.size() + r.err.size(), 4000u) << backend;
    EXPECT_NE(r.out.find("degenerate_big_face.off"), std::string::npos);
  }
  // Not a regular file, or no end: refused naming it, at once.
  r = genmesh("info /dev/zero");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/dev/zero: is not a regular file"), std::string::npos) << r.err;
  r = genmesh("subdivide " + cube + " " + tmp_path("x.off") + " --scheme catmull-clark --creases /dev/zero");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/dev/zero: is not a regular file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos);
}

TEST(CliHostile, SubdivideRefusesWhatCannotFitWithTheFigures) {
  const std::string cube = tmp_path("fit_cube.off");
  write_file(cube, genmesh_fuzz::cli_cube_off);
  for (const char* scheme : {"catmull-clark", "doo-sabin", "midpoint"}) {
    Cli_run r = genmesh("subdivide " + cube + " " + tmp_path("x.off") + " --scheme " + scheme +
                        " --levels 12 --max-memory 4G");
    EXPECT_EQ(r.exit_code, 3) << scheme << r.out << r.err;
    EXPECT_NE(r.err.find("fit_cube.off: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("level 1:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
  }
  // The predicted counts are the real ones: Catmull-Clark on the cube, 2 levels.
  Cli_run r = genmesh("subdivide " + cube + " " + tmp_path("x.off") + " --scheme catmull-clark --levels 2 --max-memory 1K");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("level 1: 26 vertices, 48 edges, 24 faces"), std::string::npos) << r.err;
  r = genmesh("subdivide " + cube + " " + tmp_path("x.off") + " --scheme catmull-clark --levels 2 --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_int(r.out, "vertices"), 98);
  EXPECT_EQ(json_int(r.out, "faces"), 96);
}

// Ctrl-C, TERM or HUP while the output is written: the temporary is removed,
// the old output survives, the program dies of the signal.
// Out of memory (the prediction allowed it, the system did not): exit 3,
// saying while doing what and on which file (the stage is kept while the
// exception unwinds).
TEST(CliHostile, OutOfMemorySaysWhileDoingWhatOnWhichFile) {
  const std::string cube = tmp_path("oom_cube.off");
  write_file(cube, genmesh_fuzz::cli_cube_off);
  const std::string cmd = "sh -c 'ulimit -v 120000; exec " + std::string(cli_program()) + " subdivide " + cube + " " +
                          tmp_path("oom.off") + " --scheme catmull-clark --levels 9 --max-memory 1T' 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status)) << out;
  EXPECT_EQ(WEXITSTATUS(status), 3) << out;
  EXPECT_NE(out.find("genmesh: subdividing " + cube + ": out of memory"), std::string::npos) << out;
}

TEST(CliHostile, SignalsWhileWritingRemoveTheTemporary) {
  const std::filesystem::path dir = tmp_path("signals");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string cube = (dir / "cube.off").string(), out = (dir / "out.off").string();
  write_file(cube, genmesh_fuzz::cli_cube_off);
  write_file(out, "old output\n");
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    bool caught = false;
    for (int levels = 8; levels <= 10 && !caught; ++levels) {
      const pid_t pid = fork();
      ASSERT_GE(pid, 0);
      if (pid == 0) {
        std::freopen("/dev/null", "w", stdout);
        const std::string l = std::to_string(levels);
        execl(cli_program(), "genmesh", "subdivide", cube.c_str(), out.c_str(), "--scheme", "catmull-clark", "--levels",
              l.c_str(), static_cast<char*>(nullptr));
        _exit(127);
      }
      // Wait for the temporary to appear, then signal.
      int status = 0;
      for (;;) {
        bool temp = false;
        for (const auto& e : std::filesystem::directory_iterator(dir))
          temp = temp || e.path().filename().string().starts_with(".out.off.tmp");
        if (temp) {
          kill(pid, sig);
          caught = true;
          break;
        }
        if (waitpid(pid, &status, WNOHANG) == pid) break;   // done before we saw it: more levels
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
      if (!caught) {
        write_file(out, "old output\n");
        continue;
      }
      ASSERT_EQ(waitpid(pid, &status, 0), pid);
      EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << sig << " status " << status;
    }
    ASSERT_TRUE(caught) << "signal " << sig;
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 2u) << "signal " << sig << ": a temporary is left";
    EXPECT_EQ(read_file(out), "old output\n");
  }
}

// measure: the counts and quality of one mesh, and with a second mesh the
// two-way distance: a mesh against a moved copy of itself is measured apart,
// against itself at zero up to rounding; a missing file is a usage error.
TEST(Cli, MeasureReportsQualityAndDistance) {
  const std::string in = real_mesh("elephant.off");
  Cli_run one = genmesh("measure " + in + " --json");
  ASSERT_EQ(one.exit_code, 0) << one.out << one.err;
  EXPECT_EQ(json_int(one.out, "faces"), 5558);
  EXPECT_EQ(json_int(one.out, "self_intersecting_pairs"), 0);
  for (const char* key : {"\"min_angle\":", "\"angles_below_30\":", "\"valence6_share\":"})
    EXPECT_NE(one.out.find(key), std::string::npos) << key << " in " << one.out;
  EXPECT_EQ(one.out.find("\"hausdorff\""), std::string::npos) << "no B, no distance";

  Cli_run self = genmesh("measure " + in + " " + in + " --json --samples 2000");
  ASSERT_EQ(self.exit_code, 0) << self.out << self.err;
  const auto at = self.out.find("\"hausdorff\":");
  ASSERT_NE(at, std::string::npos) << self.out;
  EXPECT_LE(std::stod(self.out.substr(at + 12)), 1e-12);

  // The elephant scaled by 1.01 about the origin: a positive distance.
  genmesh::Polygon_soup soup = genmesh::read_soup(in);
  for (auto& p : soup.points) p *= 1.01;
  const std::string moved = tmp_path("elephant_scaled.off");
  genmesh::write_soup(moved, soup);
  Cli_run apart = genmesh("measure " + in + " " + moved + " --json --samples 2000");
  ASSERT_EQ(apart.exit_code, 0) << apart.out << apart.err;
  const auto at2 = apart.out.find("\"hausdorff\":");
  ASSERT_NE(at2, std::string::npos) << apart.out;
  EXPECT_GT(std::stod(apart.out.substr(at2 + 12)), 1e-4);

  EXPECT_EQ(genmesh("measure").exit_code, 2);
  EXPECT_NE(genmesh("measure " + tmp_path("missing.off")).exit_code, 0);
}

// simplify: the target is met on every backend with the same result, the
// JSON record says why it stopped, and bad targets are usage errors.
TEST(Cli, SimplifyMeetsTheTargetOnEveryBackend) {
  const std::string in = real_mesh("elephant.off");
  std::string first;
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    SCOPED_TRACE(backend);
    const std::string out = tmp_path(std::string("simplified_") + backend + ".off");
    Cli_run r = genmesh("simplify " + in + " " + out + " --faces 1000 --json --backend " + backend);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(json_int(r.out, "faces"), 1000);
    EXPECT_NE(r.out.find("\"stop_reason\":\"target_faces\""), std::string::npos) << r.out;
    EXPECT_EQ(json_int(r.out, "euler_characteristic"), -4);  // genus 3 kept
    // The quality figures of the result: no self-intersection (the guard),
    // a Hausdorff distance to the input that is small but not zero.
    EXPECT_EQ(json_int(r.out, "self_intersections"), 0) << r.out;
    const double hausdorff = json_double(r.out, "hausdorff");
    EXPECT_GT(hausdorff, 0) << r.out;
    EXPECT_LT(hausdorff, 0.05) << r.out;
    EXPECT_GT(json_double(r.out, "min_angle"), 0) << r.out;
    const double valence6 = json_double(r.out, "valence6_share");
    EXPECT_GT(valence6, 0) << r.out;
    EXPECT_LT(valence6, 1) << r.out;
    if (first.empty()) first = read_file(out);
    else EXPECT_EQ(read_file(out), first);
  }
  Cli_run lt = genmesh("simplify " + in + " " + tmp_path("lt.off") + " --faces 1000 --json --policy lindstrom-turk");
  ASSERT_EQ(lt.exit_code, 0) << lt.out << lt.err;
  EXPECT_EQ(json_int(lt.out, "faces"), 1000);
  EXPECT_NE(lt.out.find("\"policy\":\"lindstrom-turk\""), std::string::npos) << lt.out;
  Cli_run feat = genmesh("simplify " + in + " " + tmp_path("feat.off") + " --faces 1000 --json --features 60");
  ASSERT_EQ(feat.exit_code, 0) << feat.out << feat.err;
  EXPECT_EQ(json_int(feat.out, "faces"), 1000);
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.off") + " --faces 10 --features 200").exit_code, 2);
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.off")).exit_code, 2);              // no target
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.off") + " --ratio 2").exit_code, 2); // ratio > 1
  EXPECT_EQ(genmesh("simplify " + in + " " + tmp_path("x.off") + " --faces 10 --policy nope").exit_code, 2);
  Cli_run quads = genmesh("simplify " + real_mesh("cube_quad.off") + " " + tmp_path("x.off") + " --faces 4");
  EXPECT_EQ(quads.exit_code, 2);
  EXPECT_NE(quads.err.find("is not a triangle"), std::string::npos) << quads.err;
}

} // namespace

namespace {

// remesh: every backend writes the same file; the JSON record has the counts
// and the quality of the result; bad options are usage errors.
TEST(Cli, RemeshGivesTheSameResultOnEveryBackend) {
  const std::string in = real_mesh("elephant.off");
  std::string first;
  for (const char* backend : {"halfedge", "surface-mesh", "incidence"}) {
    SCOPED_TRACE(backend);
    const std::string out = tmp_path(std::string("remeshed_") + backend + ".off");
    Cli_run r = genmesh("remesh " + in + " " + out + " --iterations 3 --json --backend " + backend);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(json_int(r.out, "iterations"), 3);
    EXPECT_TRUE(json_bool(r.out, "valid"));
    EXPECT_EQ(json_int(r.out, "euler_characteristic"), -4); // genus 3 kept
    EXPECT_GT(json_int(r.out, "splits"), 0);
    EXPECT_GT(json_double(r.out, "min_angle"), 25.0);
    EXPECT_LT(json_double(r.out, "angles_below_30"), 0.01);
    EXPECT_GT(json_double(r.out, "valence6_share"), 0.7);
    EXPECT_LT(json_double(r.out, "hausdorff"), 0.05); // relative to the diagonal
    EXPECT_GE(json_double(r.out, "seconds"), 0.0);
    if (first.empty()) first = read_file(out);
    else EXPECT_EQ(read_file(out), first);
  }
  // Options: an absolute length, Delaunay flips, features, quads triangulated first.
  Cli_run cube = genmesh("remesh " + real_mesh("cube_quad.off") + " " + tmp_path("cube_remeshed.off") +
                         " --edge-length 0.6 --features 45 --flips delaunay --json");
  ASSERT_EQ(cube.exit_code, 0) << cube.out << cube.err;
  EXPECT_GT(json_int(cube.out, "faces"), 12);
  EXPECT_EQ(json_int(cube.out, "euler_characteristic"), 2);
  const std::string x = tmp_path("x.off");
  EXPECT_EQ(genmesh("remesh " + in + " " + x + " --edge-length 0").exit_code, 2);
  EXPECT_EQ(genmesh("remesh " + in + " " + x + " --edge-length 1 --relative 1").exit_code, 2);
  EXPECT_EQ(genmesh("remesh " + in + " " + x + " --flips nope").exit_code, 2);
  EXPECT_EQ(genmesh("remesh " + in + " " + x + " --iterations -1").exit_code, 2);
  EXPECT_EQ(genmesh("remesh " + in + " " + x + " --adaptive 2 1 0.1").exit_code, 2);
  EXPECT_EQ(genmesh("remesh " + in).exit_code, 2);
}

} // namespace
