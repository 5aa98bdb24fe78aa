// Tests of <genmesh/io.h>: round trips on every format and variant,
// hand-written files of each format, every kind of bad input with its
// specific error, atomic writes, real meshes against CGAL::IO, and
// read_mesh/write_mesh on every backend.
#include <genmesh/generators.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/properties.h>

#include "backends.h"
#include "../fuzz/genmesh_fuzz.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using genmesh::File_format;
using genmesh::io_error;
using genmesh::Polygon_soup;
using genmesh::read_soup;
using genmesh::write_soup;

namespace {

std::string write_file(const std::string& name, const std::string& content) {
  const std::string p = genmesh_test::tmp_path(name);
  std::ofstream(p, std::ios::binary) << content;
  return p;
}

std::string read_bytes(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Little- or big-endian byte strings for hand-made binary files.
struct Bytes {
  std::string s;
  template <class T>
  Bytes& le(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
  template <class T>
  Bytes& be(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::little) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& t) {
    s += t;
    return *this;
  }
};

struct Expected_error {
  std::string message;                  ///< a substring of the message
  std::optional<std::uint64_t> line;    ///< for text formats
  std::optional<std::uint64_t> offset;  ///< for binary formats
};

/// Runs f, which must throw io_error about `file` with the expected message
/// and position.
void expect_io_error(const std::function<void()>& f, const std::string& file, const Expected_error& ex) {
  try {
    f();
    ADD_FAILURE() << "no io_error for " << file << " (expected: " << ex.message << ")";
  } catch (const io_error& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_NE(std::string(e.what()).find(fs::path(file).filename().string()), std::string::npos) << e.what();
    EXPECT_NE(e.message().find(ex.message), std::string::npos)
        << "message: " << e.message() << "\nexpected: " << ex.message;
    EXPECT_EQ(e.line(), ex.line) << e.what();
    EXPECT_EQ(e.byte_offset(), ex.offset) << e.what();
  }
}

void expect_read_error(const std::string& name, const std::string& content, const Expected_error& ex) {
  const std::string p = write_file(name, content);
  SCOPED_TRACE(name);
  expect_io_error([&] { (void)read_soup(p); }, p, ex);
}

/// A soup with coordinates that have no short decimal form, mixed face sizes
/// and one face of more than 255 corners (needs a wider PLY count type).
using genmesh_fuzz::awkward_soup;

std::string describe(const Polygon_soup& s) {
  return std::to_string(s.num_points()) + " points, " + std::to_string(s.num_faces()) + " faces";
}

} // namespace

// ---- round trips ---------------------------------------------------------------

struct Round_trip_case {
  std::string file;
  bool binary;
};

TEST(IoRoundTrip, OffObjPlyAreExact) {
  const Polygon_soup s = awkward_soup();
  for (const Round_trip_case& c : {Round_trip_case{"rt.off", false}, {"rt.obj", false}, {"rt.ply", false},
                                   {"rt_bin.ply", true}, {"RT_UPPER.OFF", false}}) {
    SCOPED_TRACE(c.file);
    const std::string p = genmesh_test::tmp_path(c.file);
    write_soup(p, s, {.binary = c.binary});
    const Polygon_soup r = read_soup(p);
    EXPECT_EQ(r.num_points(), s.num_points());
    EXPECT_EQ(r.num_faces(), s.num_faces());
    EXPECT_TRUE(r == s) << describe(r);
  }
}

TEST(IoRoundTrip, BinaryPlyIsLittleEndianDoubleWithUcharCounts) {
  Polygon_soup s = genmesh::make_tetrahedron();
  const std::string p = genmesh_test::tmp_path("tet_bin.ply");
  write_soup(p, s, {.binary = true});
  const std::string d = read_bytes(p);
  EXPECT_NE(d.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(d.find("property double x"), std::string::npos);
  EXPECT_NE(d.find("property list uchar int vertex_indices"), std::string::npos);
  const auto body = d.find("end_header\n") + 11;
  // 4 points * 3 doubles + 4 faces * (1 + 3 * 4) bytes.
  EXPECT_EQ(d.size() - body, 4u * 24u + 4u * 13u);
}

TEST(IoRoundTrip, StlTextIsExactAndBinaryIsFloat) {
  // A closed triangle mesh: every point is used, so welding recovers exactly
  // the points, in first-seen order.
  Polygon_soup s = genmesh::make_icosphere(2);
  for (auto& p : s.points) p = p * (1.0 / 7.0);
  for (const bool binary : {false, true}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    const std::string p = genmesh_test::tmp_path(binary ? "rt_bin.stl" : "rt.stl");
    write_soup(p, s, {.binary = binary});
    if (binary) {
      EXPECT_EQ(fs::file_size(p), 84u + 50u * s.num_faces());
    }
    const Polygon_soup r = read_soup(p);
    ASSERT_EQ(r.num_faces(), s.num_faces());
    EXPECT_EQ(r.num_points(), s.num_points());
    for (std::size_t f = 0; f < s.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& a = s.points[s.face(f)[k]];
        const Eigen::Vector3d& b = r.points[r.face(f)[k]];
        if (binary)
          for (int i = 0; i < 3; ++i) EXPECT_EQ(b[i], static_cast<double>(static_cast<float>(a[i])));
        else
          EXPECT_EQ(a, b);
      }
  }
}

TEST(IoRoundTrip, StlTriangulatesPolygonsByFans) {
  const Polygon_soup cube = genmesh::make_cube();
  const std::string p = genmesh_test::tmp_path("cube.stl");
  write_soup(p, cube);
  const Polygon_soup r = read_soup(p);
  ASSERT_EQ(r.num_faces(), 12u);
  EXPECT_EQ(r.num_points(), 8u);
  for (std::size_t f = 0; f < 6; ++f) {
    const auto q = cube.face(f);
    for (int t = 0; t < 2; ++t) {
      const auto tri = r.face(2 * f + t);
      EXPECT_EQ(r.points[tri[0]], cube.points[q[0]]);
      EXPECT_EQ(r.points[tri[1]], cube.points[q[1 + t]]);
      EXPECT_EQ(r.points[tri[2]], cube.points[q[2 + t]]);
    }
  }
}

TEST(IoRoundTrip, LowerPrecisionRoundsCoordinates) {
  Polygon_soup s = genmesh::make_tetrahedron();
  s.points[0] = Eigen::Vector3d(1.0 / 3.0, 2.0 / 3.0, 12345.678901234);
  const std::string p = genmesh_test::tmp_path("prec.obj");
  write_soup(p, s, {.precision = 6});
  const Polygon_soup r = read_soup(p);
  EXPECT_EQ(r.points[0], Eigen::Vector3d(0.333333, 0.666667, 12345.7));
  EXPECT_EQ(r.points[1], s.points[1]);
}

TEST(IoRoundTrip, FormatOptionOverridesExtension) {
  const Polygon_soup s = genmesh::make_cube();
  const std::string p = genmesh_test::tmp_path("cube_as_obj.dat");
  write_soup(p, s, {.format = File_format::obj});
  EXPECT_EQ(read_bytes(p).substr(0, 1), "#");
  EXPECT_EQ(read_soup(p, {.format = File_format::obj}), s);
  EXPECT_EQ(read_soup(p), s) << "content sniffing finds OBJ";
  const std::string q = genmesh_test::tmp_path("cube_off.txt");
  write_soup(q, s, {.format = File_format::off});
  EXPECT_EQ(read_soup(q), s) << "content sniffing finds OFF";
  const std::string b = genmesh_test::tmp_path("cube_bin.xyz");
  write_soup(b, s, {.format = File_format::ply, .binary = true});
  EXPECT_EQ(read_soup(b), s) << "content sniffing finds PLY";
}

// ---- hand-written files -----------------------------------------------------------

TEST(IoOff, CommentsColorsAndVariants) {
  const std::string p = write_file("colors.off",
                                   "# comment\n"
                                   "COFF\n"
                                   "\n"
                                   "4 2 0 # counts\n"
                                   "0 0 0 255 0 0 255\n"
                                   "# a comment between vertices\n"
                                   "1 0 0 0 255 0\n"
                                   "  1 1 0 0.5 0.5 0.5\r\n"
                                   "0 1 0\n"
                                   "3 0 1 2 1 0 0 #red\n"
                                   "3 0 2 3\n");
  const Polygon_soup s = read_soup(p);
  ASSERT_EQ(s.num_points(), 4u);
  EXPECT_EQ(s.points[2], Eigen::Vector3d(1, 1, 0));
  ASSERT_EQ(s.num_faces(), 2u);
  EXPECT_EQ(std::vector<Polygon_soup::Index>(s.face(0).begin(), s.face(0).end()),
            (std::vector<Polygon_soup::Index>{0, 1, 2}));
  EXPECT_EQ(s.face(1)[2], 3u);

  // Counts on the keyword's line, normals (NOFF), scientific notation, '+',
  // a UTF-8 byte order mark.
  const Polygon_soup t = read_soup(write_file("noff.off",
                                              "\xEF\xBB\xBFNOFF 3 1 3\n"
                                              "1e0 +2 -3.5E-1 0 0 1\n"
                                              "0 0 0 0 0 1\n"
                                              "0 1 0 0 0 1\n"
                                              "3 2 1 0\n"));
  ASSERT_EQ(t.num_points(), 3u);
  EXPECT_EQ(t.points[0], Eigen::Vector3d(1, 2, -0.35));
  EXPECT_EQ(t.face(0)[0], 2u);
}

TEST(IoObj, CornerFormsNegativeIndicesAndPolygons) {
  const std::string p = write_file("forms.obj",
                                   "# comment\n"
                                   "mtllib x.mtl\n"
                                   "o thing\n"
                                   "v 0 0 0\n"
                                   "v 1 0 0 1.0 0.5 0.5 0.5\n"
                                   "v 1 1 0\n"
                                   "v 0 1 0\n"
                                   "vt 0 0\n"
                                   "vn 0 0 1\n"
                                   "g group\n"
                                   "usemtl m\n"
                                   "s off\n"
                                   "f 1/1/1 2/1/1 3/1/1 4/1/1\n"
                                   "f 1//1 3//1 4//1\n"
                                   "f 1/1 2/1 3/1 # comment\n"
                                   "v 2 0 0\n"
                                   "f -1 -4 \\\n"
                                   "  -3\n"
                                   "l 1 2\n"
                                   "f 5 6 2\n"      // 6 is defined later
                                   "v 2 1 0\n");
  const Polygon_soup s = read_soup(p);
  ASSERT_EQ(s.num_points(), 6u);
  EXPECT_EQ(s.points[1], Eigen::Vector3d(1, 0, 0));
  ASSERT_EQ(s.num_faces(), 5u);
  using V = std::vector<Polygon_soup::Index>;
  auto face = [&](std::size_t f) { return V(s.face(f).begin(), s.face(f).end()); };
  EXPECT_EQ(face(0), (V{0, 1, 2, 3}));
  EXPECT_EQ(face(1), (V{0, 2, 3}));
  EXPECT_EQ(face(2), (V{0, 1, 2}));
  EXPECT_EQ(face(3), (V{4, 1, 2}));
  EXPECT_EQ(face(4), (V{4, 5, 1}));
}

TEST(IoPly, AsciiWithExtraPropertiesAndElements) {
  const std::string p = write_file("extra.ply",
                                   "ply\r\n"
                                   "format ascii 1.0\n"
                                   "comment hello\n"
                                   "obj_info x\n"
                                   "element material 1\n"
                                   "property list uchar float weights\n"
                                   "property int id\n"
                                   "element vertex 4\n"
                                   "property uchar red\n"
                                   "property list uchar int tags\n"
                                   "property float z\n"
                                   "property double y\n"
                                   "property short x\n"
                                   "element edge 1\n"
                                   "property int vertex1\n"
                                   "property int vertex2\n"
                                   "element face 2\n"
                                   "property uchar flags\n"
                                   "property list int uint vertex_index\n"
                                   "property float quality\n"
                                   "end_header\n"
                                   "2 0.5 0.25 7\n"
                                   "255 0 0.5 0 0\n"
                                   "255 2 1 2 0 0.25 1\n"
                                   "0 1 9 1.5 0.5 1\n"
                                   "0 0 2 3 2\n"
                                   "0 1\n"
                                   "1 3 0 1 2 0.5\n"
                                   "1 4 0 2 3 1 0.5\n");
  const Polygon_soup s = read_soup(p);
  ASSERT_EQ(s.num_points(), 4u);
  EXPECT_EQ(s.points[0], Eigen::Vector3d(0, 0, 0.5));
  EXPECT_EQ(s.points[1], Eigen::Vector3d(1, 0.25, 0));
  EXPECT_EQ(s.points[2], Eigen::Vector3d(1, 0.5, 1.5));
  EXPECT_EQ(s.points[3], Eigen::Vector3d(2, 3, 2));
  ASSERT_EQ(s.num_faces(), 2u);
  EXPECT_EQ(s.face_size(1), 4u);
  EXPECT_EQ(s.face(1)[3], 1u);
}

namespace {
// A binary PLY with float coordinates behind a double normal, a uchar color,
// a vertex list property, then faces with the given count and index types.
template <class Count, class Index, bool big_endian>
std::string binary_ply(const char* count_name, const char* index_name) {
  Bytes b;
  b.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\n"
         "element vertex 4\n"
         "property double nx\n"
         "property float x\n"
         "property uchar red\n"
         "property float y\n"
         "property list ushort int tags\n"
         "property float z\n"
         "element face 2\n"
         "property list " + count_name + " " + index_name + " vertex_indices\n"
         "property int8 flag\n"
         "end_header\n");
  auto put = [&](auto v) {
    if constexpr (big_endian) b.be(v); else b.le(v);
  };
  const float pts[4][3] = {{0.1f, 0.2f, 0.3f}, {1.1f, 0.2f, 0.3f}, {1.1f, 1.2f, 0.3f}, {0.1f, 1.2f, -0.3f}};
  for (int v = 0; v < 4; ++v) {
    put(0.5);
    put(pts[v][0]);
    put(std::uint8_t{7});
    put(pts[v][1]);
    put(std::uint16_t(v % 2));
    if (v % 2) put(std::int32_t{42});
    put(pts[v][2]);
  }
  put(Count(3)); put(Index(0)); put(Index(1)); put(Index(2)); put(std::int8_t{-1});
  put(Count(4)); put(Index(0)); put(Index(2)); put(Index(3)); put(Index(1)); put(std::int8_t{1});
  return b.s;
}

template <class Count, class Index, bool big_endian>
void check_binary_ply(const char* count_name, const char* index_name) {
  SCOPED_TRACE(std::string(count_name) + "/" + index_name + (big_endian ? " big endian" : " little endian"));
  const std::string p = write_file(std::string("bin_") + count_name + "_" + index_name + (big_endian ? "_be" : "_le") + ".ply",
                                   binary_ply<Count, Index, big_endian>(count_name, index_name));
  const Polygon_soup s = read_soup(p);
  ASSERT_EQ(s.num_points(), 4u);
  // float coordinates: exactly the float values, not their decimal spelling
  EXPECT_EQ(s.points[1], Eigen::Vector3d(double(1.1f), double(0.2f), double(0.3f)));
  EXPECT_NEAR(s.points[3].z(), -0.3, 1e-7);
  ASSERT_EQ(s.num_faces(), 2u);
  EXPECT_EQ(s.face_size(0), 3u);
  EXPECT_EQ(s.face_size(1), 4u);
  EXPECT_EQ(s.face(1)[1], 2u);
  EXPECT_EQ(s.face(1)[3], 1u);
  // The lone nx and red (no full group) are attributes of their own names,
  // read past the vertex list.
  ASSERT_EQ(s.vertex_attributes.size(), 2u);
  EXPECT_EQ(s.vertex_attributes[0].name, "nx");
  EXPECT_EQ(s.vertex_attributes[0].type, genmesh::Scalar_type::float64);
  EXPECT_EQ(s.vertex_attributes[0].values, std::vector<double>(4, 0.5));
  EXPECT_EQ(s.vertex_attributes[1].name, "red");
  EXPECT_EQ(s.vertex_attributes[1].type, genmesh::Scalar_type::uint8);
  EXPECT_EQ(s.vertex_attributes[1].values, std::vector<double>(4, 7.0));
}
} // namespace

TEST(IoPly, BinaryAnyIntegerTypesBothEndians) {
  check_binary_ply<std::uint8_t, std::int32_t, false>("uchar", "int");
  check_binary_ply<std::uint8_t, std::uint32_t, false>("uint8", "uint");
  check_binary_ply<std::int32_t, std::uint16_t, false>("int", "ushort");
  check_binary_ply<std::uint32_t, std::int8_t, false>("uint", "char");
  check_binary_ply<std::int16_t, std::uint8_t, false>("short", "uchar");
  check_binary_ply<std::uint8_t, std::int32_t, true>("uchar", "int");
  check_binary_ply<std::uint16_t, std::uint32_t, true>("ushort", "uint32");
  check_binary_ply<std::int8_t, std::int16_t, true>("int8", "int16");
}

TEST(IoStl, AsciiWeldsExactlyEqualCornersInFirstSeenOrder) {
  const std::string p = write_file("weld.stl",
                                   "solid two\n"
                                   "facet normal 0 0 1\n outer loop\n"
                                   "  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
                                   " endloop\nendfacet\n"
                                   "facet normal 0 0 1\n outer loop\n"
                                   "  vertex 0 1 0\n  vertex 1.0 0 0\n  vertex 1 1 -0.0\n"
                                   " endloop\nendfacet\n"
                                   "facet normal 0 0 1\n outer loop\n"
                                   "  vertex 1 1 0.0000000000000001\n  vertex 1 1 0\n  vertex 1 1 0\n"
                                   " endloop\nendfacet\n"
                                   "endsolid two\n");
  const Polygon_soup s = read_soup(p);
  // 0 0 0 | 1 0 0 | 0 1 0 | 1 1 0 (-0.0 welded) | 1 1 1e-16 (not equal: kept)
  ASSERT_EQ(s.num_points(), 5u);
  EXPECT_EQ(s.points[3], Eigen::Vector3d(1, 1, 0));
  ASSERT_EQ(s.num_faces(), 3u);
  using V = std::vector<Polygon_soup::Index>;
  EXPECT_EQ(V(s.face(1).begin(), s.face(1).end()), (V{2, 1, 3}));
  // the degenerate facet is kept as it is
  EXPECT_EQ(V(s.face(2).begin(), s.face(2).end()), (V{4, 3, 3}));
}

TEST(IoStl, BinaryWeldsAndAcceptsSolidInHeader) {
  Bytes b;
  std::string header = "solid this header starts like ASCII";
  header.resize(80, ' ');
  b.text(header).le(std::uint32_t{2});
  const float tris[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 0}, {1, 0, 0}, {1, 1, 0}}};
  for (auto& t : tris) {
    b.le(0.f).le(0.f).le(1.f);
    for (auto& v : t) b.le(v[0]).le(v[1]).le(v[2]);
    b.le(std::uint16_t{0});
  }
  const Polygon_soup s = read_soup(write_file("weld_bin.stl", b.s));
  ASSERT_EQ(s.num_points(), 4u);
  ASSERT_EQ(s.num_faces(), 2u);
  EXPECT_EQ(s.face(1)[0], 2u);
  EXPECT_EQ(s.face(1)[1], 1u);
  EXPECT_EQ(s.face(1)[2], 3u);
}

// ---- bad input ------------------------------------------------------------------

TEST(IoErrors, FileLevel) {
  const std::string missing = genmesh_test::tmp_path("does_not_exist.off");
  expect_io_error([&] { (void)read_soup(missing); }, missing, {"does not exist", {}, {}});
  expect_read_error("empty.off", "", {"file is empty", {}, 0});
  expect_read_error("empty.ply", "", {"file is empty", {}, 0});
  expect_read_error("unknown.xyz", "hello world\n", {"unknown format", {}, 0});
  const std::string dir = genmesh_test::tmp_path("a_directory.off");
  fs::create_directories(dir);
  expect_io_error([&] { (void)read_soup(dir); }, dir, {"directory", {}, {}});
}

TEST(IoErrors, Off) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  expect_read_error("trunc_v.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n", {"truncated: the header says 4 vertices, the file has 2", 4, {}});
  expect_read_error("trunc_f.off", head, {"truncated: the header says 1 faces, the file has 0", 5, {}});
  expect_read_error("range.off", head + "3 0 1 3\n", {"face 0 has index 3 out of range (3 vertices)", 6, {}});
  expect_read_error("neg.off", head + "3 0 -1 2\n", {"face 0 has index -1 out of range", 6, {}});
  expect_read_error("two.off", head + "2 0 1\n", {"face 0 has 2 corners (at least 3 needed)", 6, {}});
  expect_read_error("short_face.off", head + "4 0 1 2\n", {"face 0 announces 4 corners but lists 3", 6, {}});
  expect_read_error("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",
                    {"vertex 1 has a non-finite coordinate", 4, {}});
  expect_read_error("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n",
                    {"vertex 2 has a non-finite coordinate", 5, {}});
  expect_read_error("huge.off", "OFF\n3 1 0\n0 0 0\n1 0 1e999\n0 1 0\n3 0 1 2\n",
                    {"vertex 1 has a non-finite coordinate", 4, {}});
  expect_read_error("malformed.off", "OFF\n3 1 0\n0 0 0\n1 0 1.2.3\n0 1 0\n3 0 1 2\n",
                    {"malformed z coordinate: expected a number, found '1.2.3'", 4, {}});
  expect_read_error("malformed_idx.off", head + "3 0 1 x\n", {"malformed vertex index", 6, {}});
  expect_read_error("counts.off", "OFF\n3 -1 0\n", {"negative count", 2, {}});
  expect_read_error("no_counts.off", "OFF\n# nothing else\n", {"counts line is missing", 2, {}});
  expect_read_error("header.off", "OF\n3 1 0\n", {"missing OFF header: expected 'OFF', found 'OF'", 1, {}});
  // Wrong counts: too few vertices announced makes a vertex line a face,
  // too many makes a face line a vertex and leaves the faces short.
  expect_read_error("few_v.off", "OFF\n2 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    {"face 0 has 0 corners (at least 3 needed)", 5, {}});
  expect_read_error("many_v.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    {"truncated: the header says 1 faces, the file has 0", 6, {}});
  // Too few faces announced: the rest is ignored, as CGAL does (prim.off).
  EXPECT_EQ(read_soup(write_file("more.off", head + "3 0 1 2\n3 2 1 0\n")).num_faces(), 1u);
  expect_read_error("binary.off", "OFF\n3 1 0\n0 0 0\n1 0 " + std::string("\0\x01\x02", 3) + " 0\n",
                    {"binary data where text was expected", 4, {}});
  expect_read_error("binary_off.off", "OFF BINARY\n3 1 0\n", {"binary OFF is not supported", 1, {}});
  expect_read_error("4off.off", "4OFF\n3 1 0\n", {"only 3D OFF", 1, {}});
}

TEST(IoErrors, Obj) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_read_error("zero.obj", v + "f 0 1 2\n", {"face 0 has vertex index 0 (OBJ indices start at 1)", 4, {}});
  expect_read_error("range.obj", v + "f 1 2 3\nf 1 2 9\nf 1 2 4\n", {"face 1 has vertex index 9 out of range (3 vertices)", 5, {}});
  expect_read_error("rel.obj", v + "f -1 -2 -4\n", {"face 0 has relative vertex index -4 out of range", 4, {}});
  expect_read_error("two.obj", v + "f 1 2\n", {"face 0 has 2 corners (at least 3 needed)", 4, {}});
  expect_read_error("nan.obj", "v 0 0 0\nv NaN 0 0\n", {"vertex 1 has a non-finite coordinate", 2, {}});
  expect_read_error("malformed.obj", "v 0 0 0\nv 1 0 0,5\n", {"malformed z coordinate", 2, {}});
  expect_read_error("short_v.obj", "v 0 0\n", {"line ends before z coordinate", 1, {}});
  expect_read_error("bad_corner.obj", v + "f 1 2 3x\n", {"malformed vertex index", 4, {}});
  expect_read_error("not_obj.obj", v + "1 2 3\n", {"not an OBJ statement: '1'", 4, {}});
  // Texture coordinates, normals and colours: malformed values and indices name the line.
  expect_read_error("vt_word.obj", v + "vt 0 zero\n", {"malformed texture coordinate v: expected a number, found 'zero'", 4, {}});
  expect_read_error("vt_inf.obj", v + "vt inf 0\n", {"non-finite texture coordinate u", 4, {}});
  expect_read_error("vt_none.obj", v + "vt\n", {"line ends before texture coordinate u", 4, {}});
  expect_read_error("vn_short.obj", v + "vn 0 0\n", {"line ends before normal z", 4, {}});
  expect_read_error("vn_nan.obj", v + "vn 0 nan 1\n", {"non-finite normal y", 4, {}});
  expect_read_error("rgb_word.obj", "v 0 0 0 1 0 red\n", {"malformed blue value: expected a number, found 'red'", 1, {}});
  expect_read_error("vt_range.obj", v + "vt 0 0\nf 1/1 2/2 3/1\n",
                    {"face 0 has texture coordinate index 2 out of range (1 texture coordinates)", 5, {}});
  expect_read_error("vn_range.obj", v + "vn 0 0 1\nf 1//1 2//1 3//-2\n",
                    {"face 0 has relative normal index -2 out of range (1 read so far)", 5, {}});
  expect_read_error("vt_zero.obj", v + "vt 0 0\nf 1/0 2/1 3/1\n",
                    {"face 0 has texture coordinate index 0 (OBJ indices start at 1)", 5, {}});
  for (const char* corner : {"3/", "3//", "3/1/", "3/x", "3/1/1/1"})
    expect_read_error("corner.obj", v + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 " + corner + "\n",
                      {"malformed vertex index", 6, {}});
  // Statements other than v and f are skipped, known or not.
  EXPECT_EQ(read_soup(write_file("vendor.obj", v + "vc 1 0 0\nfrobnicate 1 2\nf 1 2 3\n")).num_faces(), 1u);
  expect_read_error("binary.obj", v + std::string("\x7f\x45\x4c\x46\x02\x01\x01\0\0", 9),
                    {"binary data where text was expected", 4, {}});
}

TEST(IoErrors, Ply) {
  const std::string h = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect_read_error("no_end.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
                    {"missing end_header", 4, {}});
  expect_read_error("type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty real x\nend_header\n",
                    {"unknown PLY type 'real'", 4, {}});
  expect_read_error("no_vertex.ply", "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
                    {"no vertex element", 5, {}});
  expect_read_error("no_x.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float y\nend_header\n",
                    {"no scalar 'x' property", 3, {}});
  expect_read_error("no_list.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 0\nproperty int vertex_indices\nend_header\n", {"is not a list", 8, {}});
  expect_read_error("format.ply", "ply\nformat binary_middle_endian 1.0\n", {"unknown PLY format", 2, {}});
  expect_read_error("magic.ply", "plx\nformat ascii 1.0\n", {"the first line must be 'ply'", 1, {}});
  expect_read_error("keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 3\n", {"unknown PLY header keyword 'elemnt'", 3, {}});
  expect_read_error("trunc.ply", h + "0 0 0\n1 0 0\n", {"truncated: the header says 3 'vertex' elements, the data ends in number 2", 11, {}});
  expect_read_error("range.ply", h + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", {"face 0 has index 3 out of range (3 vertices)", 13, {}});
  expect_read_error("two.ply", h + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", {"face 0 has 2 corners", 13, {}});
  expect_read_error("inf.ply", h + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", {"vertex 1 has a non-finite coordinate", 11, {}});
  expect_read_error("float_range.ply", h + "0 0 0\n1 1e39 0\n0 1 0\n3 0 1 2\n", {"vertex 1 has a non-finite coordinate", 11, {}});
  expect_read_error("garbage.ply", h + std::string("0 0 0\n\x01\x02\0\x03", 10), {"binary data where text was expected", 11, {}});

  // Binary: offsets are 0-based byte positions in the file.
  const std::string bh = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::uint64_t body = bh.size();
  Bytes pts;
  pts.text(bh);
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) pts.le(c);
  expect_read_error("btrunc_v.ply", pts.s.substr(0, body + 30), {"the data ends in number 2", {}, body + 24});
  expect_read_error("btrunc_f.ply", Bytes(pts).le(std::uint8_t{3}).le(0).le(1).s,
                    {"'face' elements, the data ends in number 0", {}, body + 36});
  expect_read_error("brange.ply", Bytes(pts).le(std::uint8_t{3}).le(0).le(1).le(7).s,
                    {"face 0 has index 7 out of range (3 vertices)", {}, body + 36 + 9});
  expect_read_error("btwo.ply", Bytes(pts).le(std::uint8_t{2}).le(0).le(1).s, {"face 0 has 2 corners", {}, body + 36});
  Bytes nan_pts;
  nan_pts.text(bh);
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, std::numeric_limits<float>::quiet_NaN()}) nan_pts.le(c);
  nan_pts.le(std::uint8_t{3}).le(0).le(1).le(2);
  expect_read_error("bnan.ply", nan_pts.s, {"vertex 2 has a non-finite coordinate", {}, body + 24});
}

TEST(IoErrors, Stl) {
  Bytes b;
  b.text(std::string(80, 'x')).le(std::uint32_t{2});
  b.text(std::string(50, '\0'));
  expect_read_error("size.stl", b.s, {"binary STL size mismatch: the header says 2 triangles, which needs 184 bytes, the file has 134 (truncated)", {}, 80});
  expect_read_error("short.stl", std::string(40, 'x'), {"at least 84 bytes", {}, 40});
  Bytes n;
  n.text(std::string(80, ' ')).le(std::uint32_t{1}).le(0.f).le(0.f).le(1.f);
  n.le(0.f).le(0.f).le(0.f).le(1.f).le(std::numeric_limits<float>::infinity()).le(0.f).le(0.f).le(1.f).le(0.f);
  n.le(std::uint16_t{0});
  expect_read_error("inf.stl", n.s, {"corner 1 of facet 0 has a non-finite coordinate", {}, 84 + 24});
  const std::string facet = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  expect_read_error("keyword.stl", "solid s\n" + facet + "facet normal 0 0 1\n outer loop\n  vertx 0 0 0\n",
                    {"expected 'vertex' or 'endloop', found 'vertx'", 11, {}});
  expect_read_error("trunc.stl", "solid s\n" + facet + "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n",
                    {"truncated: the file ends inside facet 1", 11, {}});
  expect_read_error("noend.stl", "solid s\n" + facet, {"'endsolid' is missing", 8, {}});
  expect_read_error("nan.stl", "solid s\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex nan 0 0\n",
                    {"corner 1 of facet 0 has a non-finite coordinate", 5, {}});
  expect_read_error("num.stl", "solid s\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 zero\n",
                    {"malformed z coordinate", 5, {}});
}

TEST(IoErrors, EveryTruncationAndCorruptionIsAnIoErrorOrAValidSoup) {
  Polygon_soup soup = genmesh::make_cube();
  soup.add_point(0.125, -2.5e-3, 1e5);
  soup.add_face({8, 0, 1});
  std::mt19937 rng(12345);
  for (const Round_trip_case& c : {Round_trip_case{"fz.off", false}, {"fz.obj", false}, {"fz.ply", false},
                                   {"fz_bin.ply", true}, {"fz.stl", false}, {"fz_bin.stl", true}}) {
    SCOPED_TRACE(c.file);
    const std::string p = genmesh_test::tmp_path(c.file);
    write_soup(p, soup, {.binary = c.binary});
    const std::string full = read_bytes(p);
    const auto try_read = [&](const std::string& content) -> bool {
      std::ofstream(p, std::ios::binary | std::ios::trunc) << content;
      try {
        const Polygon_soup r = read_soup(p);
        for (std::size_t f = 0; f < r.num_faces(); ++f) {
          EXPECT_GE(r.face_size(f), 3u);
          for (auto i : r.face(f)) EXPECT_LT(i, r.num_points());
        }
        for (const auto& q : r.points) EXPECT_TRUE(q.allFinite());
        return true;
      } catch (const io_error& e) {
        EXPECT_EQ(e.file(), p);
        EXPECT_TRUE(e.line() || e.byte_offset() || e.message().find("empty") != std::string::npos ||
                    c.file.ends_with(".ply"))
            << e.what();
        return false;
      }
    };
    // About 150 cuts per format (every byte near the start, where headers are).
    const std::size_t step = std::max<std::size_t>(1, full.size() / 150);
    for (std::size_t n = 0; n < full.size(); n += (n < 100 ? 1 : step)) {
      const bool ok = try_read(full.substr(0, n));
      // Binary files have exact sizes: every cut is detected.
      if (c.binary) {
        EXPECT_FALSE(ok) << "cut at " << n;
      }
    }
    for (int k = 0; k < 150; ++k) {
      std::string bad = full;
      for (int j = 0; j < 3; ++j)
        bad[std::uniform_int_distribution<std::size_t>(0, bad.size() - 1)(rng)] =
            static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
      try_read(bad);
    }
    EXPECT_TRUE(try_read(full));
  }
}

// ---- writing -----------------------------------------------------------------------

TEST(IoWrite, MissingDirectoryAndUnknownFormat) {
  const std::string p = genmesh_test::tmp_path("no_such_dir/out.off");
  expect_io_error([&] { write_soup(p, genmesh::make_cube()); }, p, {"does not exist", {}, {}});
  EXPECT_FALSE(fs::exists(p));
  const std::string q = genmesh_test::tmp_path("out.xyz");
  expect_io_error([&] { write_soup(q, genmesh::make_cube()); }, q, {"unknown format", {}, {}});
  EXPECT_FALSE(fs::exists(q));
}

TEST(IoWrite, FailedWriteLeavesExistingFileIntactAndNoTemporary) {
  const fs::path dir = genmesh_test::tmp_path("atomic");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string p = (dir / "keep.off").string();
  write_soup(p, genmesh::make_cube());
  const std::string before = read_bytes(p);

  // A bad index in the last face: the writer has already flushed megabytes
  // of points and faces into the temporary file when it throws.
  Polygon_soup bad = genmesh::make_torus(300, 200, true);
  bad.indices.back() = static_cast<Polygon_soup::Index>(bad.num_points());
  const std::string last = std::to_string(bad.num_faces() - 1);
  for (const char* ext : {"keep.off", "keep.obj", "keep.ply", "keep.stl"}) {
    const std::string target = (dir / ext).string();
    if (!fs::exists(target)) write_soup(target, genmesh::make_cube());
    const std::string old = read_bytes(target);
    expect_io_error([&] { write_soup(target, bad); }, target,
                    {"face " + last + " has index " + std::to_string(bad.num_points()) + " out of range", {}, {}});
    EXPECT_EQ(read_bytes(target), old) << ext;
  }
  Polygon_soup nan_soup = genmesh::make_cube();
  nan_soup.points[7].x() = std::nan("");
  expect_io_error([&] { write_soup(p, nan_soup, {.format = File_format::ply, .binary = true}); }, p,
                  {"point 7 has a non-finite coordinate", {}, {}});
  EXPECT_EQ(read_bytes(p), before);
  Polygon_soup far = genmesh::make_cube();
  far.points[3].z() = 1e300;
  expect_io_error([&] { write_soup(p, far, {.format = File_format::stl, .binary = true}); }, p,
                  {"point 3 is out of the float range of binary STL", {}, {}});
  EXPECT_EQ(read_bytes(p), before);
  EXPECT_EQ(read_soup(p), genmesh::make_cube());
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 4u) << "no temporary file left behind";
}

TEST(IoWrite, OverwritesExistingFile) {
  const std::string p = genmesh_test::tmp_path("overwrite.ply");
  write_soup(p, genmesh::make_cube());
  write_soup(p, genmesh::make_tetrahedron(), {.binary = true});
  EXPECT_EQ(read_soup(p), genmesh::make_tetrahedron());
}

// ---- hostile input (issue 14) ----------------------------------------------------

TEST(IoHostile, PlyElementWithoutPropertiesAndAHugeCountIsSkippedAtOnce) {
  // Looping over the count of an element that has no data hung the reader.
  for (const char* count : {"4294967295", "9223372036854775807"}) {
    const std::string p = write_file("junk.ply", std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                                             "property float y\nproperty float z\nelement junk ") +
                                                     count + "\nelement face 1\nproperty list uchar int vertex_indices\n"
                                                             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const Polygon_soup s = read_soup(p);
    EXPECT_EQ(s.num_points(), 3u);
    EXPECT_EQ(s.num_faces(), 1u);
  }
}

namespace {
std::string with_line_ends(const std::string& lf, const std::string& end) {
  std::string out;
  for (char c : lf) {
    if (c == '\n') out += end;
    else out += c;
  }
  return out;
}
} // namespace

TEST(IoHostile, LfCrlfAndCrLineEndsReadTheSameInEveryFormat) {
  const Polygon_soup cube = genmesh::make_cube();
  for (const char* ext : {"off", "obj", "ply", "stl"}) {
    const std::string lf_path = genmesh_test::tmp_path(std::string("ends_lf.") + ext);
    write_soup(lf_path, cube);
    const std::string lf = read_bytes(lf_path);
    const Polygon_soup want = read_soup(lf_path);
    for (const char* end : {"\r\n", "\r"}) {
      SCOPED_TRACE(std::string(ext) + (end[1] ? " CRLF" : " CR"));
      const std::string p = write_file(std::string("ends.") + ext, with_line_ends(lf, end));
      EXPECT_EQ(read_soup(p), want);
      // Without the extension: the content alone tells the format.
      const std::string q = write_file("ends_noext", with_line_ends(lf, end));
      EXPECT_EQ(read_soup(q), want);
    }
  }
  // A binary PLY whose header ends in CRLF.
  const std::string bin = genmesh_test::tmp_path("ends_bin.ply");
  write_soup(bin, cube, {.binary = true});
  std::string b = read_bytes(bin);
  const std::size_t body = b.find("end_header\n") + 11;
  const std::string crlf = with_line_ends(b.substr(0, body), "\r\n") + b.substr(body);
  EXPECT_EQ(read_soup(write_file("ends_bin_crlf.ply", crlf)), cube);
}

TEST(IoHostile, AStrayCrEndsALineInsteadOfDroppingData) {
  // "v 1 0 0\rv 9 9 9" was one line: the second vertex vanished.
  const Polygon_soup s = read_soup(write_file("stray.obj", "v 0 0 0\nv 1 0 0\rv 9 9 9\nv 0 1 0\nf 1 2 4\n"));
  ASSERT_EQ(s.num_points(), 4u);
  EXPECT_EQ(s.points[2], Eigen::Vector3d(9, 9, 9));
  // Lines are counted the same way: the error is on line 3 in all three.
  for (const char* end : {"\n", "\r\n", "\r"}) {
    const std::string text = with_line_ends("OFF\n3 1 0\n0 0 x\n1 0 0\n0 1 0\n3 0 1 2\n", end);
    expect_read_error("lines.off", text, {"malformed", 3, {}});
  }
  // OBJ line continuation works with every line end.
  for (const char* end : {"\n", "\r\n", "\r"}) {
    const std::string text = with_line_ends("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n 2 3\n", end);
    EXPECT_EQ(read_soup(write_file("cont.obj", text)).num_faces(), 1u) << end;
  }
}

TEST(IoHostile, NumbersAreWholeTokens) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n";
  expect_read_error("plusminus.off", head + "0 +-1 0\n3 0 1 2\n", {"malformed", 5, {}});
  expect_read_error("plusplus.off", head + "0 ++1 0\n3 0 1 2\n", {"malformed", 5, {}});
  expect_read_error("tinyjunk.off", head + "0 1e-400junk 0\n3 0 1 2\n", {"malformed", 5, {}});
  expect_read_error("hugejunk.off", head + "0 1e400junk 0\n3 0 1 2\n", {"malformed", 5, {}});
  expect_read_error("intpm.off", head + "0 1 0\n3 0 +-1 2\n", {"malformed", 6, {}});
  // What is a number stays one: +1, underflow to 0.
  const Polygon_soup s = read_soup(write_file("plus.off", head + "0 +1 1e-400\n3 0 +1 2\n"));
  EXPECT_EQ(s.points[2], Eigen::Vector3d(0, 1, 0));
}

TEST(IoHostile, AsciiStlWithAByteOrderMarkIsAscii) {
  const std::string text = "\xEF\xBB\xBFsolid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                           "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
  EXPECT_EQ(read_soup(write_file("bom.stl", text)).num_faces(), 1u);
  EXPECT_EQ(read_soup(write_file("bom_noext", text)).num_faces(), 1u);
  EXPECT_EQ(read_soup(write_file("bom.off", "\xEF\xBB\xBFOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).num_faces(), 1u);
}

TEST(IoHostile, DevicesHugeFilesAndEndlessPipesAreRefusedNamingTheFile) {
  for (const char* dev : {"/dev/zero", "/dev/urandom", "/dev/null"})
    expect_io_error([&] { (void)read_soup(dev); }, dev, {"is not a regular file (a character device)", {}, {}});
  // A 10 GB sparse file: refused from its size, before a byte is read.
  const std::string sparse = genmesh_test::tmp_path("sparse.off");
  {
    std::ofstream(sparse, std::ios::binary) << "OFF\n";
  }
  fs::resize_file(sparse, std::uint64_t{10} << 30);
  expect_io_error([&] { (void)read_soup(sparse); }, sparse, {"the file is 10.0 GiB, larger than the limit of 8.0 GiB", {}, {}});
  fs::remove(sparse);
  const std::string small = write_file("limit.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_io_error([&] { (void)read_soup(small, {.max_file_size = 10}); }, small, {"larger than the limit of 10 bytes", {}, {}});
  EXPECT_EQ(read_soup(small, {.max_file_size = 1000}).num_faces(), 1u);
  // A pipe that gives more than the limit is cut off with an error (the
  // writer gets EPIPE, not SIGPIPE).
  const std::string fifo = genmesh_test::tmp_path("endless.fifo");
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto old = std::signal(SIGPIPE, SIG_IGN);
  std::thread writer([&] {
    std::FILE* w = std::fopen(fifo.c_str(), "wb");
    if (!w) return;
    const std::string chunk(1 << 16, ' ');
    for (int i = 0; i < 64 && std::fwrite(chunk.data(), 1, chunk.size(), w) == chunk.size(); ++i) {}
    std::fclose(w);
  });
  expect_io_error([&] { (void)read_soup(fifo, {.format = File_format::off, .max_file_size = 1 << 20}); }, fifo,
                  {"more than 1.0 MiB read", {}, {}});
  // Should the reader have failed before opening, release the writer's open().
  const int unblock = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  if (unblock >= 0) ::close(unblock);
  writer.join();
  std::signal(SIGPIPE, old);
  fs::remove(fifo);
}

TEST(IoHostile, WritesKeepModeFollowSymlinksAndRefuseReadOnlyAndHardLinkedTargets) {
  const fs::path dir = genmesh_test::tmp_path("write_semantics");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string p = (dir / "private.off").string();
  write_soup(p, genmesh::make_cube());
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write);
  write_soup(p, genmesh::make_tetrahedron());
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(read_soup(p), genmesh::make_tetrahedron());

  // Through a symlink: the link stays a link, its target gets the data.
  const std::string real = (dir / "real.off").string(), link = (dir / "link.off").string();
  write_soup(real, genmesh::make_cube());
  fs::create_symlink("real.off", link);
  write_soup(link, genmesh::make_tetrahedron());
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(read_soup(real), genmesh::make_tetrahedron());

  // Read-only: refused, untouched.
  const std::string ro = (dir / "readonly.off").string();
  write_soup(ro, genmesh::make_cube());
  fs::permissions(ro, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const std::string before = read_bytes(ro);
  expect_io_error([&] { write_soup(ro, genmesh::make_tetrahedron()); }, ro, {"read-only", {}, {}});
  EXPECT_EQ(read_bytes(ro), before);

  // Hard links: refused (replacing would split them), untouched.
  const std::string a = (dir / "a.off").string(), b = (dir / "b.off").string();
  write_soup(a, genmesh::make_cube());
  fs::create_hard_link(a, b);
  expect_io_error([&] { write_soup(b, genmesh::make_tetrahedron()); }, b, {"2 hard links", {}, {}});
  EXPECT_EQ(fs::hard_link_count(a), 2u);
  EXPECT_EQ(read_soup(a), genmesh::make_cube());
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 6u) << "no temporary left behind";
}

TEST(IoHostile, RemovePendingTemporariesRemovesAWriteInProgress) {
  const fs::path dir = genmesh_test::tmp_path("pending");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string p = (dir / "out.off").string();
  write_soup(p, genmesh::make_cube());
  {
    genmesh::detail::io::Atomic_file out(p);
    out.buffer = "partial";
    out.flush();
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 2u);
    genmesh::remove_pending_temporaries();   // what the CLI's signal handler calls
    entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1u);
  }
  EXPECT_EQ(read_soup(p), genmesh::make_cube());
}

// ---- fuzz corpora ------------------------------------------------------------

// Writes the seed corpus of the fuzz targets (genmesh_fuzz::write_seed_corpus:
// every generated mesh in every format and encoding, and command lines) and
// replays the readers' part with the regression corpus through the targets'
// bodies: each input is read or refused the documented way.
TEST(FuzzCorpus, SeedsAreWrittenAndEveryCorpusInputIsReadOrRefused) {
  const fs::path seeds = GENMESH_FUZZ_SEED_DIR;
  genmesh_fuzz::write_seed_corpus(seeds);
  std::size_t inputs = 0;
  for (const fs::path& dir : {seeds / "off", seeds / "obj", seeds / "ply", seeds / "stl"}) {
    for (const auto& e : fs::directory_iterator(dir)) {
      SCOPED_TRACE(e.path().string());
      const std::string data = read_bytes(e.path().string());
      genmesh_fuzz::read_one(genmesh_fuzz::format_of(e.path().string()), reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
      // The generated meshes read back.
      EXPECT_GT(read_soup(e.path()).num_faces(), 0u);
      ++inputs;
    }
  }
  EXPECT_EQ(inputs, 7u * 6u);
  EXPECT_EQ(std::distance(fs::directory_iterator(seeds / "cli"), fs::directory_iterator()),
            static_cast<std::ptrdiff_t>(genmesh_fuzz::cli_seeds.size()));
}

// The regression corpus of the reader targets: each input, one per reader
// finding of issue 14, reads as its line in expected.txt says (the counts, or
// an io_error with that text) — each line failed before the fix — and goes
// through the target's body unharmed.
TEST(FuzzCorpus, RegressionInputsReadAsExpected) {
  const fs::path dir = fs::path(GENMESH_SOURCE_DIR) / "tests/fuzz/regressions/reader";
  std::istringstream expected(read_bytes((dir / "expected.txt").string()));
  std::set<std::string> listed;
  for (std::string line; std::getline(expected, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::string name, what;
    in >> name >> what;
    SCOPED_TRACE(line);
    listed.insert(name);
    const fs::path p = dir / name;
    const std::string data = read_bytes(p.string());
    genmesh_fuzz::read_one(genmesh_fuzz::format_of(name), reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
    if (what == "error") {
      std::string text;
      std::getline(in >> std::ws, text);
      try {
        (void)read_soup(p);
        ADD_FAILURE() << "read without an error";
      } catch (const io_error& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
      }
    } else {
      std::size_t faces = 0;
      in >> faces;
      try {
        const Polygon_soup s = read_soup(p);
        EXPECT_EQ(s.num_points(), std::stoul(what));
        EXPECT_EQ(s.num_faces(), faces);
      } catch (const io_error& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename() == "expected.txt") continue;
    EXPECT_TRUE(listed.contains(e.path().filename().string())) << e.path() << " has no line in expected.txt";
    ++files;
  }
  EXPECT_GE(files, 9u);
}

// ---- real meshes against CGAL::IO ----------------------------------------------------

namespace {
void expect_same_as_cgal(const std::string& path, bool exact = true) {
  SCOPED_TRACE(path);
  std::vector<genmesh_test::Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(path, points, polygons));
  const Polygon_soup s = read_soup(path);
  ASSERT_EQ(s.num_points(), points.size());
  ASSERT_EQ(s.num_faces(), polygons.size());
  if (!exact) return;
  for (std::size_t v = 0; v < points.size(); ++v)
    ASSERT_EQ(s.points[v], Eigen::Vector3d(points[v].x(), points[v].y(), points[v].z())) << "vertex " << v;
  for (std::size_t f = 0; f < polygons.size(); ++f)
    ASSERT_TRUE(std::equal(polygons[f].begin(), polygons[f].end(), s.face(f).begin(), s.face(f).end()))
        << "face " << f;
}
} // namespace

TEST(IoRealMeshes, SameAsCgal) {
  for (const char* name : {"elephant.off", "mesh_with_colors.off", "cube_quad.off", "polygon_mesh.off",
                           "blobby-shuffled.off", "b9.ply", "colored_tetra.ply", "sphere.ply", "sphere.stl",
                           "pig.stl"})
    expect_same_as_cgal(genmesh_test::real_mesh(name));
}

TEST(IoRealMeshes, EveryOffFileHasCgalCounts) {
  const fs::path dir = fs::path(genmesh_test::real_mesh("elephant.off")).parent_path();
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".off") continue;
    expect_same_as_cgal(e.path().string());
    ++n;
  }
  EXPECT_GE(n, 100u);
}

// ---- per-vertex attributes ------------------------------------------------------------

namespace {
std::vector<std::string> components(const genmesh::Soup_attribute& a) { return a.components; }
} // namespace

// PLY vertex properties beyond x y z become named channels (colour, normal,
// texture coordinates grouped; others alone; lists skipped), keep their
// types, and are written back: ascii and binary PLY give the same soup, OFF
// keeps what it has a place for (colour, normal, texture coordinates).
TEST(IoAttributes, PlyChannelsRoundTrip) {
  const std::string p = write_file("attributes.ply",
                                   "ply\nformat ascii 1.0\n"
                                   "element vertex 3\n"
                                   "property float quality\n"
                                   "property double x\nproperty double y\nproperty double z\n"
                                   "property float nx\nproperty float ny\nproperty float nz\n"
                                   "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                                   "property list uchar int tags\n"
                                   "property double u\nproperty double v\n"
                                   "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                   "0.5 0 0 0 0 0 1 255 0 0 255 2 7 8 0.25 0.75\n"
                                   "1.5 1 0 0 0 0 1 0 255 0 128 0 1 0\n"
                                   "2.5 0 1 0 0 0 1 0 0 255 0 1 9 0.125 1\n"
                                   "3 0 1 2\n");
  const Polygon_soup s = read_soup(p);
  ASSERT_EQ(s.num_points(), 3u);
  EXPECT_EQ(s.points[1], Eigen::Vector3d(1, 0, 0));
  ASSERT_EQ(s.vertex_attributes.size(), 4u);
  const auto& quality = s.vertex_attributes[0];
  const auto& normal = s.vertex_attributes[1];
  const auto& colour = s.vertex_attributes[2];
  const auto& uv = s.vertex_attributes[3];
  EXPECT_EQ(quality.name, "quality");
  EXPECT_EQ(quality.type, genmesh::Scalar_type::float32);
  EXPECT_EQ(quality.values, (std::vector<double>{0.5, 1.5, 2.5}));
  EXPECT_EQ(normal.name, "normal");
  EXPECT_EQ(components(normal), (std::vector<std::string>{"nx", "ny", "nz"}));
  EXPECT_EQ(colour.name, "color");
  EXPECT_EQ(colour.type, genmesh::Scalar_type::uint8);
  EXPECT_EQ(components(colour), (std::vector<std::string>{"red", "green", "blue", "alpha"}));
  EXPECT_EQ(std::vector<double>(colour.of(1).begin(), colour.of(1).end()), (std::vector<double>{0, 255, 0, 128}));
  EXPECT_EQ(uv.name, "texcoord");
  EXPECT_EQ(std::vector<double>(uv.of(2).begin(), uv.of(2).end()), (std::vector<double>{0.125, 1}));
  ASSERT_NE(s.vertex_attribute("color"), nullptr);
  EXPECT_EQ(s.vertex_attribute("colour"), nullptr);

  for (const bool binary : {false, true}) {
    const std::string q = genmesh_test::tmp_path(binary ? "attributes_bin.ply" : "attributes_out.ply");
    write_soup(q, s, {.binary = binary});
    EXPECT_EQ(read_soup(q), s) << (binary ? "binary" : "ascii");
    if (binary) {
      EXPECT_NE(read_bytes(q).find("property uchar alpha"), std::string::npos);
    }
  }
  // OFF: STCNOFF with normal, colour and texture coordinates; no quality.
  const std::string o = genmesh_test::tmp_path("attributes_out.off");
  write_soup(o, s);
  EXPECT_EQ(read_bytes(o).substr(0, 8), "STCNOFF\n");
  const Polygon_soup t = read_soup(o);
  ASSERT_EQ(t.vertex_attributes.size(), 3u);
  EXPECT_EQ(t.vertex_attribute("normal")->values, normal.values);
  EXPECT_EQ(t.vertex_attribute("color")->values, colour.values);
  EXPECT_EQ(t.vertex_attribute("color")->type, genmesh::Scalar_type::uint8);
  EXPECT_EQ(t.vertex_attribute("texcoord")->values, uv.values);
  EXPECT_EQ(t.points, s.points);
}

// OFF variants: [ST][C][N]OFF extras in Geomview's order; colours as CGAL
// reads them (3 or 4 values or none per line; float colours stay doubles).
TEST(IoAttributes, OffVariants) {
  const Polygon_soup s = read_soup(write_file("stcn.off",
                                              "STCNOFF\n3 1 0\n"
                                              "0 0 0  0 0 1  255 0 0 255  0 0\n"
                                              "1 0 0  0 0 1  0 255 0 128  1 0 # comment\n"
                                              "0 1 0  0 0 1  0 0 255 0  0 1\n"
                                              "3 0 1 2\n"));
  ASSERT_EQ(s.vertex_attributes.size(), 3u);
  EXPECT_EQ(s.vertex_attributes[0].name, "normal");
  EXPECT_EQ(s.vertex_attributes[1].name, "color");
  EXPECT_EQ(s.vertex_attributes[1].width(), 4u);
  EXPECT_EQ(s.vertex_attributes[1].type, genmesh::Scalar_type::uint8);
  EXPECT_EQ(s.vertex_attributes[2].name, "texcoord");
  EXPECT_EQ(s.vertex_attributes[2].values, (std::vector<double>{0, 0, 1, 0, 0, 1}));
  const std::string o = genmesh_test::tmp_path("stcn_out.off");
  write_soup(o, s);
  EXPECT_EQ(read_soup(o), s);
  const std::string q = genmesh_test::tmp_path("stcn_out.ply");
  write_soup(q, s, {.binary = true});
  EXPECT_EQ(read_soup(q).vertex_attribute("color")->values, s.vertex_attributes[1].values);

  // Float colours, one line without colour (0 0 0), one without alpha (opaque).
  const Polygon_soup c = read_soup(write_file("coff_float.off",
                                              "COFF\n3 1 0\n0 0 0 0.5 0.25 1 0.5\n1 0 0\n0 1 0 1 1 1\n3 0 1 2\n"));
  ASSERT_EQ(c.vertex_attributes.size(), 1u);
  EXPECT_EQ(c.vertex_attributes[0].type, genmesh::Scalar_type::float64);
  EXPECT_EQ(c.vertex_attributes[0].values, (std::vector<double>{0.5, 0.25, 1, 0.5, 0, 0, 0, 1, 1, 1, 1, 1}));
  // NOFF: normals only.
  const Polygon_soup n = read_soup(write_file("noff_attr.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -1\n3 0 1 2\n"));
  ASSERT_EQ(n.vertex_attributes.size(), 1u);
  EXPECT_EQ(n.vertex_attributes[0].values, (std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, -1}));
}

// The real file with normals, colours and an integer id per vertex.
TEST(IoAttributes, ColoredTetra) {
  const Polygon_soup s = read_soup(genmesh_test::real_mesh("colored_tetra.ply"));
  ASSERT_EQ(s.num_points(), 4u);
  ASSERT_NE(s.vertex_attribute("normal"), nullptr);
  ASSERT_NE(s.vertex_attribute("color"), nullptr);
  ASSERT_NE(s.vertex_attribute("id"), nullptr);
  EXPECT_EQ(s.vertex_attribute("color")->type, genmesh::Scalar_type::uint8);
  EXPECT_EQ(s.vertex_attribute("id")->type, genmesh::Scalar_type::int32);
  for (const double v : s.vertex_attribute("color")->values) EXPECT_TRUE(v >= 0 && v <= 255 && v == std::trunc(v));
  const std::string q = genmesh_test::tmp_path("colored_tetra_out.ply");
  write_soup(q, s);
  EXPECT_EQ(read_soup(q), s);
}

TEST(IoAttributes, MalformedValuesAreErrorsNamingTheLine) {
  const std::string h = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nproperty uchar red\nproperty float nx\nelement face 1\n"
                        "property list uchar int vertex_indices\nend_header\n";
  expect_read_error("red_range.ply", h + "0 0 0 0 0\n1 0 0 300 0\n0 1 0 0 0\n3 0 1 2\n",
                    {"malformed value of vertex property 'red': 300 is not a uchar (vertex 1)", 13, {}});
  expect_read_error("red_frac.ply", h + "0 0 0 1.5 0\n1 0 0 3 0\n0 1 0 0 0\n3 0 1 2\n",
                    {"'red': 1.5 is not a uchar", 12, {}});
  expect_read_error("nx_nan.ply", h + "0 0 0 0 0\n1 0 0 0 0\n0 1 0 0 nan\n3 0 1 2\n",
                    {"non-finite value of vertex property 'nx' (vertex 2)", 14, {}});
  expect_read_error("nx_word.ply", h + "0 0 0 0 0\n1 0 0 0 up\n0 1 0 0 0\n3 0 1 2\n",
                    {"malformed vertex property value: expected a number, found 'up'", 13, {}});
  // Binary: the byte offset of the value.
  const std::string bh = "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                         "property float z\nproperty float quality\nelement face 0\n"
                         "property list uchar int vertex_indices\nend_header\n";
  Bytes b;
  b.text(bh).le(0.f).le(0.f).le(0.f).le(std::numeric_limits<float>::infinity());
  expect_read_error("bquality.ply", b.s, {"non-finite value of vertex property 'quality' (vertex 0)", {}, bh.size() + 12});

  const std::string off = "3 1 0\n";
  expect_read_error("noff_short.off", "NOFF\n" + off + "0 0 0 0 0 1\n1 0 0 0 0\n0 1 0 0 0 1\n3 0 1 2\n",
                    {"vertex 1 has no normal value 'nz' (the keyword 'NOFF' announces it)", 4, {}});
  expect_read_error("coff_two.off", "COFF\n" + off + "0 0 0 1 0 0\n1 0 0 1 0\n0 1 0 1 0 0\n3 0 1 2\n",
                    {"vertex 1 has 2 colour values (3 or 4 expected)", 4, {}});
  expect_read_error("coff_word.off", "COFF\n" + off + "0 0 0 1 0 red\n1 0 0 1 0 0\n0 1 0 1 0 0\n3 0 1 2\n",
                    {"malformed colour value: expected a number, found 'red'", 3, {}});
  expect_read_error("stoff_inf.off", "STOFF\n" + off + "0 0 0 0 0\n1 0 0 inf 0\n0 1 0 0 1\n3 0 1 2\n",
                    {"vertex 1 has a non-finite texture coordinate value", 4, {}});
}

// OBJ: vn, vertex colours and vt become "normal", "color" and "texcoord".
// A square cut along its diagonal in texture space (a UV seam): corners 1
// and 3 have other texture coordinates in the second triangle, so the
// default split_seams appends two points (copies of 1 and 3) and the mesh
// has a border along the seam; equal normals under different vn indices are
// no seam. first_corner keeps four points, none reads geometry only.
//
//   4 ------ 3        vt: triangle 1 2 3 at (0,0) (1,0) (1,1);
//   |      / |            triangle 1 3 4 at (0,0.5) (0.5,1) (0,1)
//   |    /   |
//   |  /     |
//   1 ------ 2
TEST(IoAttributes, ObjTexcoordsNormalsColoursAndSeams) {
  const std::string text = "v 0 0 0 1 0 0\n"
                           "v 1 0 0 0 1 0\n"
                           "v 1 1 0 0 0 1\n"
                           "v 0 1 0 0.5 0.5 0.5\n"
                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 0.5\nvt 0.5 1\nvt 0 1\n"
                           "vn 0 0 1\nvn 0 0 1\n"
                           "f 1/1/1 2/2/1 3/3/2\n"
                           "f 1/4/2 3/5/1 4/6/2\n";
  const std::string p = write_file("seam.obj", text);
  const Polygon_soup s = read_soup(p);
  using V = std::vector<Polygon_soup::Index>;
  using D = std::vector<double>;
  ASSERT_EQ(s.num_points(), 6u);
  EXPECT_EQ(s.points[4], s.points[0]);
  EXPECT_EQ(s.points[5], s.points[2]);
  EXPECT_EQ(V(s.face(0).begin(), s.face(0).end()), (V{0, 1, 2}));
  EXPECT_EQ(V(s.face(1).begin(), s.face(1).end()), (V{4, 5, 3}));
  ASSERT_EQ(s.vertex_attributes.size(), 3u);
  EXPECT_EQ(s.vertex_attributes[0].name, "normal");
  EXPECT_EQ(s.vertex_attributes[0].values, (D{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(s.vertex_attributes[1].name, "color");
  EXPECT_EQ(s.vertex_attributes[1].values, (D{1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0.5, 0.5, 1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(s.vertex_attributes[2].name, "texcoord");
  EXPECT_EQ(components(s.vertex_attributes[2]), (std::vector<std::string>{"u", "v"}));
  EXPECT_EQ(s.vertex_attributes[2].values, (D{0, 0, 1, 0, 1, 1, 0, 1, 0, 0.5, 0.5, 1}));
  {
    genmesh::Halfedge_mesh g;
    EXPECT_EQ(genmesh::build_mesh(s, g).border_halfedges, 6u) << "the seam is a border";
  }
  // Written back (OBJ: v r g b, vt and vn per point, f a/a/a) it reads as the same soup.
  const std::string q = genmesh_test::tmp_path("seam_out.obj");
  write_soup(q, s);
  EXPECT_NE(read_bytes(q).find("f 5/5/5 6/6/6 4/4/4"), std::string::npos);
  EXPECT_EQ(read_soup(q), s);
  // To PLY and OFF and back: the same values.
  for (const char* out : {"seam_out.ply", "seam_out.off"}) {
    const std::string o = genmesh_test::tmp_path(out);
    write_soup(o, s);
    const Polygon_soup t = read_soup(o);
    for (const char* name : {"normal", "color", "texcoord"}) {
      ASSERT_NE(t.vertex_attribute(name), nullptr) << out << " " << name;
      EXPECT_EQ(t.vertex_attribute(name)->values, s.vertex_attribute(name)->values) << out << " " << name;
    }
  }

  const Polygon_soup first = read_soup(p, {.obj_attributes = genmesh::Obj_attributes::first_corner});
  ASSERT_EQ(first.num_points(), 4u);
  EXPECT_EQ(V(first.face(1).begin(), first.face(1).end()), (V{0, 2, 3}));
  EXPECT_EQ(first.vertex_attribute("texcoord")->values, (D{0, 0, 1, 0, 1, 1, 0, 1}));
  const Polygon_soup none = read_soup(p, {.obj_attributes = genmesh::Obj_attributes::none});
  EXPECT_EQ(none.num_points(), 4u);
  EXPECT_TRUE(none.vertex_attributes.empty());
  // A corner without vt or vn takes its vertex's: no split.
  const Polygon_soup partial = read_soup(write_file("partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.5\n"
                                                                     "f 1/1 2 3\nf 3 2 1\n"));
  EXPECT_EQ(partial.num_points(), 3u);
  EXPECT_EQ(partial.vertex_attribute("texcoord")->values, (D{0.25, 0.5, 0, 0, 0, 0}));
  // Flat shading (a normal per face) never splits: the fold stays connected,
  // each point with its first corner's normal.
  const Polygon_soup flat = read_soup(write_file("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                             "vn 0 0 -1\nvn -1 0 0\n"
                                                             "f 1//1 3//1 2//1\nf 1//2 4//2 3//2\n"));
  ASSERT_EQ(flat.num_points(), 4u);
  EXPECT_EQ(V(flat.face(1).begin(), flat.face(1).end()), (V{0, 3, 2}));
  EXPECT_EQ(flat.vertex_attribute("normal")->values, (D{0, 0, -1, 0, 0, -1, 0, 0, -1, -1, 0, 0}));
}

// A uchar colour goes to OBJ in [0, 1] and comes back as doubles.
TEST(IoAttributes, ObjColoursAreWrittenInUnitRange) {
  Polygon_soup s = genmesh::make_tetrahedron();
  s.vertex_attributes.push_back({"color", {"red", "green", "blue", "alpha"}, genmesh::Scalar_type::uint8,
                                 {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 51, 102, 0, 255}});
  s.vertex_attributes.push_back({"quality", {"quality"}, genmesh::Scalar_type::float32, {1, 2, 3, 4}});
  const std::string p = genmesh_test::tmp_path("colours.obj");
  write_soup(p, s);
  const Polygon_soup t = read_soup(p);
  ASSERT_EQ(t.vertex_attributes.size(), 1u) << "OBJ has no place for quality or alpha";
  EXPECT_EQ(t.vertex_attributes[0].values, (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.4, 0}));
  EXPECT_EQ(t.points, s.points);
  EXPECT_TRUE(genmesh::format_stores(genmesh::File_format::obj, s.vertex_attributes[0]));
  EXPECT_FALSE(genmesh::format_stores(genmesh::File_format::obj, s.vertex_attributes[1]));
  EXPECT_TRUE(genmesh::format_stores(genmesh::File_format::ply, s.vertex_attributes[1]));
  EXPECT_FALSE(genmesh::format_stores(genmesh::File_format::stl, s.vertex_attributes[0]));
}

// A channel that does not fit its soup is refused before the target changes.
TEST(IoAttributes, WriterRefusesInconsistentChannels) {
  Polygon_soup s = genmesh::make_tetrahedron();
  s.vertex_attributes.push_back({"quality", {"quality"}, genmesh::Scalar_type::float32, {1, 2, 3}});
  const std::string p = genmesh_test::tmp_path("bad_channel.ply");
  write_soup(p, genmesh::make_tetrahedron());
  const std::string before = read_bytes(p);
  expect_io_error([&] { write_soup(p, s); }, p, {"attribute 'quality' has 3 values for 4 points", {}, {}});
  s.vertex_attributes[0].values.push_back(std::numeric_limits<double>::quiet_NaN());
  expect_io_error([&] { write_soup(p, s); }, p, {"point 3 has a non-finite 'quality' value", {}, {}});
  EXPECT_EQ(read_bytes(p), before);
  // add_point keeps channels the size of the points.
  s.vertex_attributes[0].values.back() = 4;
  s.add_point(2, 2, 2);
  EXPECT_EQ(s.vertex_attributes[0].values.size(), 5u);
}

// ---- meshes ------------------------------------------------------------------------

template <class G>
class IoMesh : public ::testing::Test {};
TYPED_TEST_SUITE(IoMesh, genmesh_test::Backends);

TYPED_TEST(IoMesh, RoundTripKeepsOrder) {
  const Polygon_soup torus = genmesh::make_torus(8, 5);
  const std::string in = genmesh_test::tmp_path("mesh_in.off");
  write_soup(in, torus);
  TypeParam g;
  genmesh::read_mesh(in, g);
  EXPECT_EQ(num_vertices(g), torus.num_points());
  EXPECT_EQ(num_faces(g), torus.num_faces());
  for (const auto& [file, binary] : {std::pair{"mesh_out.ply", true}, {"mesh_out.obj", false}}) {
    const std::string out = genmesh_test::tmp_path(file);
    genmesh::write_mesh(out, g, {.binary = binary});
    const Polygon_soup back = read_soup(out);
    EXPECT_EQ(back, genmesh::to_soup(g));
    EXPECT_EQ(genmesh::canonical(back), genmesh::canonical(torus));
  }
}

// write_mesh streams from the mesh (no to_soup copy) and writes exactly what
// write_soup(to_soup(g)) writes, in every format, also after removals that
// leave holes in the element numbering (Surface_mesh counts removed faces in
// num_faces()).
TYPED_TEST(IoMesh, WriteMeshWritesWhatToSoupGivesAfterRemovals) {
  TypeParam g;
  genmesh::build_mesh(genmesh::make_torus(8, 5, true), g);
  for (int k = 0; k < 5; ++k) {
    auto e = *std::next(edges(g).begin(), 7 * k);
    if (genmesh::can_collapse_edge(e, std::as_const(g))) genmesh::collapse_edge(e, g);
  }
  const Polygon_soup soup = genmesh::to_soup(g);
  ASSERT_LT(soup.num_faces(), 80u);
  for (const auto& [file, binary] : {std::pair{"stream.off", false}, {"stream.obj", false}, {"stream.ply", false},
                                     {"stream_bin.ply", true}, {"stream.stl", false}, {"stream_bin.stl", true}}) {
    SCOPED_TRACE(file);
    const std::string from_mesh = genmesh_test::tmp_path(std::string("mesh_") + file);
    const std::string from_soup = genmesh_test::tmp_path(std::string("soup_") + file);
    genmesh::write_mesh(from_mesh, g, {.binary = binary});
    write_soup(from_soup, soup, {.binary = binary});
    EXPECT_EQ(read_bytes(from_mesh), read_bytes(from_soup));
  }
}

TYPED_TEST(IoMesh, RealMeshesHaveCgalCounts) {
  for (const char* name : {"elephant.off", "cube_quad.off", "mech-holes-shark.off", "sphere.ply", "sphere.stl"}) {
    SCOPED_TRACE(name);
    const std::string p = genmesh_test::real_mesh(name);
    genmesh_test::Surface_mesh expected;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(p, expected));
    TypeParam g;
    genmesh::read_mesh(p, g);
    EXPECT_EQ(num_vertices(g), num_vertices(expected));
    EXPECT_EQ(num_edges(g), num_edges(expected));
    EXPECT_EQ(num_faces(g), num_faces(expected));
  }
}

TYPED_TEST(IoMesh, RefusedSoupIsAnIoErrorNamingTheFile) {
  // Three triangles on one edge (a fin): no halfedge mesh can hold it.
  const std::string p = write_file("fin.off",
                                   "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  TypeParam g;
  try {
    genmesh::read_mesh(p, g);
    ADD_FAILURE() << "fin accepted";
  } catch (const io_error& e) {
    EXPECT_EQ(e.file(), p);
    EXPECT_FALSE(e.message().empty());
  }
}

TYPED_TEST(IoMesh, MissingFile) {
  TypeParam g;
  const std::string p = genmesh_test::tmp_path("no_mesh_here.ply");
  expect_io_error([&] { genmesh::read_mesh(p, g); }, p, {"does not exist", {}, {}});
}

// A soup's channels go into vertex property maps of the mesh built from it
// and come back out of the mesh, following the vertices: after collapses
// (holes in the numbering) every point of to_soup(g) still has its colour.
// read_mesh returns the file's channels in the mesh's vertex order and
// write_mesh writes them with the mesh: the same bytes as write_soup of
// to_soup(g) with them; with .repair, a split vertex's copy gets its values; a channel of the
// wrong size is refused before the target changes.
TYPED_TEST(IoMesh, ReadMeshAndWriteMeshCarryChannels) {
  Polygon_soup soup = genmesh::make_torus(6, 4);
  genmesh::Soup_attribute quality{"quality", {"quality"}, genmesh::Scalar_type::float32, {}};
  genmesh::Soup_attribute uv{"texcoord", {"u", "v"}, genmesh::Scalar_type::float64, {}};
  for (std::size_t i = 0; i < soup.num_points(); ++i) {
    quality.values.push_back(static_cast<double>(i) + 0.5);
    uv.values.insert(uv.values.end(), {soup.points[i].x(), soup.points[i].y()});
  }
  soup.vertex_attributes = {quality, uv};
  const std::string in = genmesh_test::tmp_path("channels_in.ply");
  write_soup(in, soup);
  TypeParam g;
  const std::vector<genmesh::Soup_attribute> channels = genmesh::read_mesh(in, g);
  EXPECT_EQ(channels, soup.vertex_attributes);
  Polygon_soup expected = genmesh::to_soup(g);
  expected.vertex_attributes = channels;
  for (const char* out : {"channels_out.ply", "channels_out.obj", "channels_out.off"}) {
    const std::string from_mesh = genmesh_test::tmp_path(std::string("mesh_") + out);
    const std::string from_soup = genmesh_test::tmp_path(std::string("soup_") + out);
    genmesh::write_mesh(from_mesh, g, channels);
    write_soup(from_soup, expected);
    EXPECT_EQ(read_bytes(from_mesh), read_bytes(from_soup)) << out;
  }
  EXPECT_EQ(read_soup(genmesh_test::tmp_path("mesh_channels_out.obj")).vertex_attribute("texcoord")->values, uv.values);
  const std::string p = genmesh_test::tmp_path("mesh_channels_out.ply");
  const std::string before = read_bytes(p);
  std::vector<genmesh::Soup_attribute> bad = channels;
  bad[0].values.pop_back();
  expect_io_error([&] { genmesh::write_mesh(p, g, bad); }, p, {"attribute 'quality' has", {}, {}});
  EXPECT_EQ(read_bytes(p), before);

  // Two fans meeting at point 0 (a bow-tie): the repair splits it.
  const std::string bow = write_file("bowtie_quality.ply",
                                     "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                                     "property float z\nproperty float quality\nelement face 2\n"
                                     "property list uchar int vertex_indices\nend_header\n"
                                     "0 0 0 7\n1 0 0 1\n1 1 0 2\n-1 0 0 3\n-1 -1 0 4\n3 0 1 2\n3 0 3 4\n");
  TypeParam r;
  const auto repaired = genmesh::read_mesh(bow, r, {.repair = true});
  ASSERT_EQ(num_vertices(r), 6u);
  ASSERT_EQ(repaired.size(), 1u);
  EXPECT_EQ(repaired[0].values, (std::vector<double>{7, 1, 2, 3, 4, 7}));
}

TYPED_TEST(IoMesh, AttributesFollowTheirVertices) {
  Polygon_soup soup = genmesh::make_torus(8, 5, true);
  genmesh::Soup_attribute colour{"color", {"red", "green", "blue"}, genmesh::Scalar_type::uint8, {}};
  for (const auto& p : soup.points)
    for (int k = 0; k < 3; ++k) colour.values.push_back(std::round(128 + 90 * p[k]));
  soup.vertex_attributes.push_back(colour);
  TypeParam g;
  genmesh::build_mesh(soup, g);
  auto map = genmesh::scratch_property<std::array<std::uint8_t, 3>>(genmesh::vertex_index, g);
  genmesh::read_vertex_attribute(soup.vertex_attributes[0], g, map);
  EXPECT_EQ(genmesh::make_soup_attribute(g, map, "color", {}, genmesh::Scalar_type::uint8), colour);
  for (int k = 0; k < 5; ++k) {
    auto e = *std::next(edges(g).begin(), 7 * k);
    if (genmesh::can_collapse_edge(e, std::as_const(g))) genmesh::collapse_edge(e, g);
  }
  Polygon_soup out = genmesh::to_soup(g);
  ASSERT_LT(out.num_points(), soup.num_points());
  out.vertex_attributes.push_back(genmesh::make_soup_attribute(g, map, "color", {}, genmesh::Scalar_type::uint8));
  EXPECT_EQ(out.vertex_attributes[0].components, colour.components);
  for (std::size_t i = 0; i < out.num_points(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(out.vertex_attributes[0].of(i)[static_cast<std::size_t>(k)], std::round(128 + 90 * out.points[i][k]));
  const std::string p = genmesh_test::tmp_path("mesh_colours.ply");
  write_soup(p, out);
  EXPECT_EQ(read_soup(p), out);
  // A map that cannot hold the channel's width.
  TypeParam h;
  genmesh::build_mesh(soup, h);
  auto scalar_h = genmesh::scratch_property<double>(genmesh::vertex_index, h);
  EXPECT_THROW(genmesh::read_vertex_attribute(soup.vertex_attributes[0], h, scalar_h), genmesh::invalid_input);
}
