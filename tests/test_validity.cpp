// tests/test_validity.cpp — check_mesh, check_soup, repair_soup, build_mesh and to_soup,
// typed over every backend and compared with CGAL's own counts.
#include "backends.h"

#include <genmesh/adaptors/openmesh.h>

#include <genmesh/generators.h>
#include <genmesh/local_operations.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using genmesh::Polygon_soup;
using genmesh_test::Kernel;

// ---------------------------------------------------------------------------
// helpers
// ---------------------------------------------------------------------------

Polygon_soup read_real(const std::string& name) {
  std::vector<Kernel::Point_3> pts;
  std::vector<std::vector<std::size_t>> polys;
  std::string path = genmesh_test::real_mesh(name);
  if (!CGAL::IO::read_polygon_soup(path, pts, polys)) throw std::runtime_error("cannot read " + path);
  Polygon_soup s;
  for (const auto& p : pts) s.add_point(p.x(), p.y(), p.z());
  std::vector<Polygon_soup::Index> c;
  for (const auto& f : polys) {
    c.assign(f.begin(), f.end());
    s.add_face(c);
  }
  return s;
}

/// CGAL's own Surface_mesh of a soup, built by CGAL's own builder (the oracle).
genmesh_test::Surface_mesh cgal_mesh(const Polygon_soup& s) {
  std::vector<Kernel::Point_3> pts;
  for (const auto& p : s.points) pts.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::vector<std::size_t>> polys;
  for (std::size_t f = 0; f < s.num_faces(); ++f) polys.emplace_back(s.face(f).begin(), s.face(f).end());
  genmesh_test::Surface_mesh sm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, sm);
  return sm;
}

std::size_t cgal_components(genmesh_test::Surface_mesh& g) {
  auto fcc = g.add_property_map<genmesh_test::Surface_mesh::Face_index, std::size_t>("f:cc_test").first;
  std::size_t n = CGAL::Polygon_mesh_processing::connected_components(g, fcc);
  g.remove_property_map(fcc);
  return n;
}

template <class G>
std::size_t cgal_border_cycles(const G& g) {
  std::vector<typename boost::graph_traits<G>::halfedge_descriptor> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(g, std::back_inserter(cycles));
  return cycles.size();
}

bool mentions(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

template <class Report, class Kind>
std::size_t count_kind(const Report& r, Kind k) {
  return static_cast<std::size_t>(
      std::count_if(r.problems.begin(), r.problems.end(), [&](const auto& p) { return p.kind == k; }));
}

template <class Report, class Kind>
bool has_problem(const Report& r, Kind k, const std::string& element) {
  return std::any_of(r.problems.begin(), r.problems.end(),
                     [&](const auto& p) { return p.kind == k && p.element == element; });
}

/// The refusal message of build_mesh, or "" when it did not throw.
template <class G>
std::string refusal(const Polygon_soup& s) {
  G g;
  try {
    genmesh::build_mesh(s, g);
  } catch (const genmesh::invalid_input& e) {
    return e.what();
  }
  return "";
}

template <class G>
std::string hname(const G& g, genmesh::halfedge_descriptor_t<G> h) {
  return "halfedge " + std::to_string(get(get(genmesh::halfedge_index, g), h));
}
template <class G>
std::string vname(const G& g, genmesh::vertex_descriptor_t<G> v) {
  return "vertex " + std::to_string(get(get(genmesh::vertex_index, g), v));
}
template <class G>
std::string fname(const G& g, genmesh::face_descriptor_t<G> f) {
  return "face " + std::to_string(get(get(genmesh::face_index, g), f));
}

// A strip of triangles along x:  (ASCII: top row 1 3 5, bottom row 0 2 4)
//
//   1-----3-----5
//   | \ 1 | \ 3 |
//   | 0 \ | 2 \ |
//   0-----2-----4
Polygon_soup strip() {
  Polygon_soup s;
  for (int i = 0; i < 3; ++i) {
    s.add_point(i, 0, 0);
    s.add_point(i, 1, 0);
  }
  s.add_face({0, 2, 1});
  s.add_face({1, 2, 3});
  s.add_face({2, 4, 3});
  s.add_face({3, 4, 5});
  return s;
}

void flip(Polygon_soup& s, std::size_t f) {
  auto c = s.face(f);
  std::reverse(c.begin(), c.end());
}

// ---------------------------------------------------------------------------
// typed tests
// ---------------------------------------------------------------------------

template <class G>
class Validity : public ::testing::Test {};
TYPED_TEST_SUITE(Validity, genmesh_test::Backends);

// check_mesh on corrupted links: only backends that store links can be
// corrupted (Incidence_mesh derives them from its matrices).
template <class G>
class Validity_links : public ::testing::Test {};
TYPED_TEST_SUITE(Validity_links, genmesh_test::Pointer_backends);

struct Shape {
  const char* name;
  Polygon_soup soup;
  long chi;
  long genus;
  std::size_t loops;
  bool triangles;
};

std::vector<Shape> shapes() {
  return {
      {"tetrahedron", genmesh::make_tetrahedron(), 2, 0, 0, true},
      {"cube", genmesh::make_cube(), 2, 0, 0, false},
      {"icosphere(2)", genmesh::make_icosphere(2), 2, 0, 0, true},
      {"torus quads", genmesh::make_torus(10, 6, false), 0, 1, 0, false},
      {"torus triangles", genmesh::make_torus(9, 7, true), 0, 1, 0, true},
      {"grid", genmesh::make_grid(5, 4), 1, 0, 1, true},
      {"grid with hole", genmesh::make_grid_with_hole(7), 0, 0, 2, true},
  };
}

TYPED_TEST(Validity, GeneratedMeshesRoundTripAndHaveTheRightTopology) {
  for (const auto& sh : shapes()) {
    SCOPED_TRACE(sh.name);
    ASSERT_TRUE(genmesh::check_soup(sh.soup).ok()) << genmesh::to_string(genmesh::check_soup(sh.soup));
    TypeParam g;
    auto br = genmesh::build_mesh(sh.soup, g);
    EXPECT_FALSE(br.repaired);
    EXPECT_EQ(br.vertices, sh.soup.num_points());
    EXPECT_EQ(br.faces, sh.soup.num_faces());

    auto r = genmesh::check_mesh(g);
    EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
    EXPECT_EQ(r.problem_count, 0u);
    EXPECT_EQ(r.euler_characteristic, sh.chi);
    ASSERT_TRUE(r.genus.has_value());
    EXPECT_EQ(*r.genus, sh.genus);
    EXPECT_EQ(r.boundary_loops, sh.loops);
    EXPECT_EQ(r.is_closed, sh.loops == 0);
    EXPECT_EQ(r.is_triangle_mesh, sh.triangles);
    EXPECT_EQ(r.components, 1u);
    EXPECT_EQ(r.vertices, sh.soup.num_points());
    EXPECT_EQ(r.faces, sh.soup.num_faces());
    EXPECT_EQ(r.edges, br.edges);
    EXPECT_EQ(r.halfedges, 2 * r.edges);
    // CGAL's is_valid_halfedge_graph also demands halfedge(edge(h)) == h for
    // every h, which holds for Surface_mesh (its edge descriptor carries a
    // halfedge) but not for Halfedge_mesh's edge = h/2; so ask CGAL only there.
    if constexpr (std::is_same_v<TypeParam, genmesh_test::Surface_mesh>) {
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(g));
    }

    // The oracle: CGAL's builder on a Surface_mesh.
    auto sm = cgal_mesh(sh.soup);
    EXPECT_EQ(r.edges, num_edges(sm));
    EXPECT_EQ(r.border_halfedges,
              static_cast<std::size_t>(std::count_if(halfedges(sm).begin(), halfedges(sm).end(),
                                                     [&](auto h) { return CGAL::is_border(h, sm); })));
    EXPECT_EQ(r.boundary_loops, cgal_border_cycles(sm));

    // Order kept: the soup comes back, faces rotated to their lowest corner.
    EXPECT_EQ(genmesh::to_soup(g), genmesh::rotate_faces_to_lowest(sh.soup));
  }
}

TYPED_TEST(Validity, BuildConventionsHold) {
  // halfedge(f) targets the face's first corner (the incidence mesh stores
  // no halfedge: its halfedge(f) is the side along f's lowest-numbered edge);
  // a border vertex's halfedge is border.
  Polygon_soup s = genmesh::make_grid(3, 3);
  TypeParam g;
  genmesh::build_mesh(s, g);
  std::vector<genmesh::vertex_descriptor_t<TypeParam>> vs(vertices(g).begin(), vertices(g).end());
  std::size_t f = 0;
  for (auto fd : faces(g)) {
    if constexpr (std::is_same_v<TypeParam, genmesh_test::Incidence_mesh>) {
      const auto h = halfedge(fd, g);
      EXPECT_EQ(face(h, g), fd);
      for (auto x : CGAL::halfedges_around_face(h, g)) EXPECT_LE(edge(h, g).idx(), edge(x, g).idx());
    } else {
      EXPECT_EQ(target(halfedge(fd, g), g), vs[s.face(f)[0]]);
    }
    ++f;
  }
  std::size_t border_vertices = 0;
  for (auto h : halfedges(g))
    if (CGAL::is_border(h, g)) {
      EXPECT_TRUE(CGAL::is_border(halfedge(target(h, g), g), g));
      ++border_vertices;
    }
  EXPECT_EQ(border_vertices, 12u); // the 4x4 grid's border ring
  for (auto v : vertices(g)) EXPECT_EQ(target(halfedge(v, g), g), v);
}

TYPED_TEST(Validity, IsolatedPointsBecomeIsolatedVerticesAndComponents) {
  Polygon_soup s = genmesh::make_tetrahedron();
  s.add_point(5, 5, 5); // isolated: point 4
  auto sr = genmesh::check_soup(s);
  EXPECT_TRUE(sr.ok());
  EXPECT_EQ(sr.isolated_points, 1u);
  TypeParam g;
  genmesh::build_mesh(s, g);
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  EXPECT_EQ(r.vertices, 5u);
  EXPECT_EQ(r.isolated_vertices, 1u);
  EXPECT_EQ(r.components, 2u);          // documented: an isolated vertex is a component
  EXPECT_EQ(r.euler_characteristic, 3); // 2 for the sphere + 1 for the point
  ASSERT_TRUE(r.genus.has_value());
  EXPECT_EQ(*r.genus, 0);               // the point is left out of the genus
  EXPECT_EQ(genmesh::to_soup(g), genmesh::rotate_faces_to_lowest(s));
}

TYPED_TEST(Validity, RealMeshesMatchCgal) {
  // (name, genus when known from the shape, else -1): closed and open real meshes, two with holes.
  const std::vector<std::pair<std::string, long>> meshes = {
      {"elephant.off", -1}, {"double-torus-example.off", 2}, {"3torus.off", 3},
      {"mech-holes-shark.off", -1}, {"elephant-with-holes.off", -1}};
  for (const auto& [name, genus] : meshes) {
    SCOPED_TRACE(name);
    Polygon_soup s = read_real(name);
    auto sr = genmesh::check_soup(s);
    ASSERT_TRUE(sr.ok()) << genmesh::to_string(sr);
    TypeParam g;
    genmesh::build_mesh(s, g);
    auto r = genmesh::check_mesh(g);
    EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
    if constexpr (std::is_same_v<TypeParam, genmesh_test::Surface_mesh>) {
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(g));
    }
    auto sm = cgal_mesh(s);
    EXPECT_EQ(r.vertices, num_vertices(sm));
    EXPECT_EQ(r.edges, num_edges(sm));
    EXPECT_EQ(r.faces, num_faces(sm));
    std::size_t loops = cgal_border_cycles(sm), cc = cgal_components(sm);
    EXPECT_EQ(r.boundary_loops, loops);
    EXPECT_EQ(r.isolated_vertices, 0u);
    EXPECT_EQ(r.components, cc);
    // The genus from CGAL's counts alone (one component each): 2 - 2g = V - E + F + b.
    long chi = long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm));
    ASSERT_EQ(cc, 1u);
    ASSERT_TRUE(r.genus.has_value());
    EXPECT_EQ(*r.genus, (2 - chi - long(loops)) / 2);
    if (genus >= 0) {
      EXPECT_EQ(*r.genus, genus);
    }
    EXPECT_EQ(genmesh::to_soup(g), genmesh::rotate_faces_to_lowest(s));
  }
}

// ----- corrupted meshes: every problem is named, no walk runs forever -----

TYPED_TEST(Validity_links, CorruptNextIsNamed) {
  TypeParam g;
  genmesh::build_mesh(genmesh::make_cube(), g);
  auto h = *halfedges(g).begin();
  auto wrong = next(next(h, g), g); // skips one halfedge: the cube's quad becomes a rho
  set_next(h, wrong, g);
  auto r = genmesh::check_mesh(g);
  EXPECT_FALSE(r.valid);
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.genus.has_value());
  // The skipped halfedge is no one's next; `wrong` is next of two.
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::next_not_unique, hname(g, wrong)));
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::next_source, hname(g, h)));
  EXPECT_GE(count_kind(r, genmesh::Mesh_problem_kind::next_prev), 1u);
  EXPECT_TRUE(mentions(genmesh::to_string(r), hname(g, h) + ": next_source"));
}

TYPED_TEST(Validity_links, CorruptFaceCycleTerminates) {
  // f: h0 -> h1 -> h2 -> h0; make h2 -> h1, so the walk from halfedge(f) = h0 never returns.
  TypeParam g;
  genmesh::build_mesh(genmesh::make_tetrahedron(), g);
  auto f = *faces(g).begin();
  auto h0 = halfedge(f, g), h1 = next(h0, g), h2 = next(h1, g);
  set_next(h2, h1, g);
  auto r = genmesh::check_mesh(g);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::face_cycle, fname(g, f))) << genmesh::to_string(r);
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::next_not_unique, hname(g, h0)));
  EXPECT_THROW(genmesh::to_soup(g), genmesh::invalid_input);
}

TYPED_TEST(Validity_links, CorruptTargetFaceAndHalfedgeLinksAreNamed) {
  {
    TypeParam g;
    genmesh::build_mesh(genmesh::make_icosphere(0), g);
    auto h = *halfedges(g).begin();
    auto v = target(next(h, g), g); // a vertex h does not end at
    set_target(h, v, g);
    auto r = genmesh::check_mesh(g);
    EXPECT_FALSE(r.valid);
    EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::next_source, hname(g, h))) << genmesh::to_string(r);
  }
  {
    TypeParam g;
    genmesh::build_mesh(genmesh::make_cube(), g);
    auto h = *halfedges(g).begin();
    auto other = face(opposite(h, g), g);
    set_face(h, other, g);
    auto r = genmesh::check_mesh(g);
    EXPECT_FALSE(r.valid);
    EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::next_face, hname(g, h))) << genmesh::to_string(r);
  }
  {
    TypeParam g;
    genmesh::build_mesh(genmesh::make_grid(2, 2), g);
    auto f = *faces(g).begin();
    set_halfedge(f, opposite(halfedge(f, g), g), g); // a halfedge of another face (or the border)
    auto r = genmesh::check_mesh(g);
    EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::face_halfedge, fname(g, f))) << genmesh::to_string(r);
  }
  {
    TypeParam g;
    genmesh::build_mesh(genmesh::make_grid(2, 2), g);
    auto v = *vertices(g).begin();
    set_halfedge(v, opposite(halfedge(v, g), g), g); // points away from v
    auto r = genmesh::check_mesh(g);
    EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::vertex_halfedge, vname(g, v))) << genmesh::to_string(r);
  }
}

// Two triangles touching only at vertex 0 (a bow-tie):
//
//   1---2
//    \ /
//     0
//    / \   .
//   3---4
Polygon_soup bow_tie_soup() {
  Polygon_soup s;
  s.add_point(0, 0, 0);
  s.add_point(-1, 1, 0);
  s.add_point(1, 1, 0);
  s.add_point(-1, -1, 0);
  s.add_point(1, -1, 0);
  s.add_face({0, 2, 1});
  s.add_face({0, 3, 4});
  return s;
}

TYPED_TEST(Validity_links, NonManifoldVertexInAValidStructureIsNotManifold) {
  // The bow-tie below, built with its vertex split (0 and 5), then merged
  // back by hand: every pointer invariant holds, but two fans meet at 0.
  //
  //   1---2
  //    \ /
  //     0
  //    / \   .
  //   3---4
  Polygon_soup s = bow_tie_soup();
  TypeParam g;
  genmesh::build_mesh(s, g, {.repair = true}); // 0 split into 0 and 5
  std::vector<genmesh::vertex_descriptor_t<TypeParam>> vs(vertices(g).begin(), vertices(g).end());
  ASSERT_EQ(vs.size(), 6u);
  // Retarget every halfedge into 5 onto 0: a valid structure with two fans at 0.
  std::vector<genmesh::halfedge_descriptor_t<TypeParam>> into5;
  for (auto h : halfedges(g))
    if (target(h, g) == vs[5]) into5.push_back(h);
  for (auto h : into5) set_target(h, vs[0], g);
  set_halfedge(vs[5], boost::graph_traits<TypeParam>::null_halfedge(), g);
  remove_vertex(vs[5], g);
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.valid) << genmesh::to_string(r);
  EXPECT_FALSE(r.manifold);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::non_manifold_vertex, vname(g, vs[0])));
  EXPECT_FALSE(CGAL::is_valid_halfedge_graph(g)); // CGAL agrees that something is wrong
}

TYPED_TEST(Validity, RemovedElementsAreSkippedUntilCollected) {
  // Removing a face leaves removed slots behind (CGAL::Euler and genmesh alike): check_mesh iterates
  // live elements and sizes its arrays by the index bound.
  TypeParam g;
  genmesh::build_mesh(genmesh::make_icosphere(1), g);
  auto f = *faces(g).begin();
  ASSERT_TRUE(genmesh::euler::remove_face(halfedge(f, g), g));
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  EXPECT_EQ(r.faces, 79u);
  EXPECT_EQ(r.edges, 120u); // a triangle removed from a closed mesh keeps its edges (now border)
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 1);
  ASSERT_TRUE(r.genus.has_value());
  EXPECT_EQ(*r.genus, 0);
}

// Two triangles (0,1,2) and (3,4,5); vertex 3 merged into 0 and the border
// links crossed at 0, so the walk around 0 is one closed cycle through both
// fans — complete, yet the border passes through 0 twice (a pinch):
//
//   2          5        border: 0 → 2 → 1 → 0 → 5 → 4 → 0
//   | \      / |
//   |  \    /  |
//   1 -- 0 -- 4
TYPED_TEST(Validity_links, BorderPassingTwiceThroughAVertexIsNotManifold) {
  TypeParam g;
  Polygon_soup s;
  for (double x : {0.0, -1.0, -1.0, 0.0, 1.0, 1.0}) s.add_point(Eigen::Vector3d(x, 0, 0));
  s.points[2].y() = s.points[5].y() = 1;
  s.add_face({0, 1, 2});
  s.add_face({3, 4, 5});
  genmesh::build_mesh(s, g);
  using V = genmesh::vertex_descriptor_t<TypeParam>;
  using H = genmesh::halfedge_descriptor_t<TypeParam>;
  std::vector<V> vs(vertices(g).begin(), vertices(g).end());
  std::vector<H> into3;
  for (auto h : halfedges(g))
    if (target(h, g) == vs[3]) into3.push_back(h);
  for (auto h : into3) set_target(h, vs[0], g);
  H b10{}, b40{}; // the border halfedges 1 → 0 and 4 → 0 (was 4 → 3)
  for (auto h : into3)
    if (CGAL::is_border(h, g)) b40 = h;
  for (auto h : halfedges(g))
    if (target(h, g) == vs[0] && source(h, g) == vs[1]) b10 = h;
  ASSERT_TRUE(CGAL::is_border(b10, g));
  const H out_a = next(b10, g), out_b = next(b40, g);
  set_next(b10, out_b, g);
  set_next(b40, out_a, g);
  set_halfedge(vs[3], boost::graph_traits<TypeParam>::null_halfedge(), g);
  remove_vertex(vs[3], g);
  const auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.valid) << genmesh::to_string(r);
  EXPECT_FALSE(r.manifold);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::non_manifold_vertex, vname(g, vs[0])))
      << genmesh::to_string(r);
  EXPECT_EQ(r.boundary_loops, 1u);
}

TYPED_TEST(Validity_links, LinksToRemovedElementsAreNamed) {
  TypeParam g;
  genmesh::build_mesh(genmesh::make_cube(), g);
  auto f = *faces(g).begin();
  auto h = halfedge(f, g);
  remove_face(f, g); // the primitive: f's halfedges still name it
  auto r = genmesh::check_mesh(g);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.faces, 5u);
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::invalid_reference, hname(g, h))) << genmesh::to_string(r);
  EXPECT_TRUE(mentions(genmesh::to_string(r), "face is a face that is not live"));
}

TYPED_TEST(Validity_links, BorderVertexWithInnerHalfedgeIsCountedNotFlagged) {
  TypeParam g;
  genmesh::build_mesh(genmesh::make_grid(2, 2), g);
  EXPECT_EQ(genmesh::check_mesh(g).border_vertices_with_inner_halfedge, 0u);
  // Corner vertex 1 of the 3x3 grid: point its halfedge at an incoming face halfedge.
  std::vector<genmesh::vertex_descriptor_t<TypeParam>> vs(vertices(g).begin(), vertices(g).end());
  auto v = vs[1];
  auto h = halfedge(v, g);
  ASSERT_TRUE(CGAL::is_border(h, g));
  set_halfedge(v, opposite(next(h, g), g), g); // the next incoming halfedge around v: a face's
  ASSERT_FALSE(CGAL::is_border(halfedge(v, g), g));
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  EXPECT_EQ(r.border_vertices_with_inner_halfedge, 1u);
}

TYPED_TEST(Validity_links, ManyProblemsAreCountedButTheListIsCapped) {
  // Every halfedge retargeted to one vertex: thousands of problems, bounded walks.
  TypeParam g;
  genmesh::build_mesh(genmesh::make_icosphere(3), g);
  auto v0 = *vertices(g).begin();
  std::vector<genmesh::halfedge_descriptor_t<TypeParam>> hs(halfedges(g).begin(), halfedges(g).end());
  for (auto h : hs) set_target(h, v0, g);
  auto r = genmesh::check_mesh(g);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.problems.size(), genmesh::Mesh_report::max_problems);
  EXPECT_GE(r.problem_count, hs.size()); // at least one self-loop per halfedge
  EXPECT_TRUE(mentions(genmesh::to_string(r), "more problems"));
}

// ----- soups: check, refuse, repair -----

TYPED_TEST(Validity, FinIsNamedRefusedAndRepaired) {
  //        2
  //       / \        three triangles on edge (0, 1), a fin:
  //      0---1       (0,1,2) above it, (1,0,3) below it, both in the plane,
  //       \ /        and (0,1,4) standing up out of the plane (4 = (0.5, 0, 1))
  //        3
  Polygon_soup s;
  s.add_point(0, 0, 0);
  s.add_point(1, 0, 0);
  s.add_point(0.5, 1, 0);
  s.add_point(0.5, -1, 0);
  s.add_point(0.5, 0, 1);
  s.add_face({0, 1, 2});
  s.add_face({1, 0, 3});
  s.add_face({0, 1, 4});
  auto sr = genmesh::check_soup(s);
  EXPECT_FALSE(sr.ok());
  EXPECT_EQ(sr.non_manifold_edges, 1u);
  ASSERT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::non_manifold_edge, "edge (0, 1)")) << genmesh::to_string(sr);
  auto it = std::find_if(sr.problems.begin(), sr.problems.end(),
                         [](const auto& p) { return p.kind == genmesh::Soup_problem_kind::non_manifold_edge; });
  EXPECT_EQ(it->faces, (std::vector<std::size_t>{0, 1, 2}));

  std::string why = refusal<TypeParam>(s);
  EXPECT_TRUE(mentions(why, "edge (0, 1)")) << why;
  EXPECT_TRUE(mentions(why, "3 faces")) << why;

  TypeParam g;
  auto br = genmesh::build_mesh(s, g, {.repair = true});
  EXPECT_TRUE(br.repaired);
  EXPECT_EQ(br.repair.removed_fin_faces, 1u);
  EXPECT_TRUE(std::any_of(br.repair.changes.begin(), br.repair.changes.end(),
                          [](const std::string& c) { return mentions(c, "removed face 2"); }));
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  EXPECT_EQ(r.faces, 2u);
  EXPECT_EQ(r.isolated_vertices, 1u); // point 4 lost its only face
}

TYPED_TEST(Validity, BowTieIsNamedRefusedAndSplit) {
  //   1---2
  //    \ /        two triangles touching only at vertex 0
  //     0
  //    / \        .
  //   3---4
  Polygon_soup s = bow_tie_soup();
  auto sr = genmesh::check_soup(s);
  EXPECT_EQ(sr.non_manifold_vertices, 1u);
  EXPECT_EQ(sr.non_manifold_edges + sr.inconsistent_edges + sr.degenerate_faces, 0u);
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::non_manifold_vertex, "vertex 0"));
  EXPECT_TRUE(mentions(genmesh::to_string(sr), "2 fans"));
  EXPECT_TRUE(mentions(refusal<TypeParam>(s), "vertex 0"));

  TypeParam g;
  auto br = genmesh::build_mesh(s, g, {.repair = true});
  EXPECT_EQ(br.repair.split_vertices, 1u);
  EXPECT_EQ(br.repair.added_points, 1u);
  EXPECT_EQ(br.repair.point_origin, (std::vector<std::size_t>{0}));
  EXPECT_EQ(br.vertices, 6u);
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.boundary_loops, 2u);
  // The fan with the lowest corner keeps vertex 0; the other gets the new point 5 at the same place.
  Polygon_soup back = genmesh::to_soup(g);
  ASSERT_EQ(back.num_points(), 6u);
  EXPECT_EQ(back.points[5], s.points[0]);
  EXPECT_EQ(std::vector<Polygon_soup::Index>(back.face(0).begin(), back.face(0).end()),
            (std::vector<Polygon_soup::Index>{0, 2, 1}));
  EXPECT_EQ(std::vector<Polygon_soup::Index>(back.face(1).begin(), back.face(1).end()),
            (std::vector<Polygon_soup::Index>{3, 4, 5}));
}

TYPED_TEST(Validity, FlippedFaceIsNamedAndReoriented) {
  {
    // The cube with its face 3 turned inside out: its four edges disagree with the neighbours.
    Polygon_soup cube = genmesh::make_cube();
    Polygon_soup s = cube;
    flip(s, 3);
    auto sr = genmesh::check_soup(s);
    EXPECT_EQ(sr.inconsistent_edges, 4u);
    for (const auto& p : sr.problems) {
      ASSERT_EQ(p.kind, genmesh::Soup_problem_kind::inconsistent_orientation);
      EXPECT_TRUE(std::find(p.faces.begin(), p.faces.end(), 3u) != p.faces.end()) << p.message;
    }
    EXPECT_TRUE(mentions(refusal<TypeParam>(s), "face"));
    TypeParam g;
    auto br = genmesh::build_mesh(s, g, {.repair = true});
    EXPECT_EQ(br.repair.reoriented_faces, 1u);
    EXPECT_EQ(br.repair.changes, (std::vector<std::string>{"reversed the orientation of face 3"}));
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
    EXPECT_EQ(genmesh::to_soup(g), genmesh::rotate_faces_to_lowest(cube));
  }
  {
    // The strip with its middle triangle 1 flipped: faces 0, 2, 3 agree, so 1 is reversed.
    Polygon_soup s = strip();
    flip(s, 1);
    auto sr = genmesh::check_soup(s);
    EXPECT_EQ(sr.inconsistent_edges, 2u);
    EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::inconsistent_orientation, "edge (1, 2)"));
    EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::inconsistent_orientation, "edge (2, 3)"));
    Polygon_soup fixed = s;
    auto rep = genmesh::repair_soup(fixed);
    EXPECT_TRUE(rep.ok());
    EXPECT_EQ(rep.reoriented_faces, 1u);
    EXPECT_EQ(genmesh::rotate_faces_to_lowest(fixed), genmesh::rotate_faces_to_lowest(strip()));
  }
}

TYPED_TEST(Validity, ShuffledRealMeshesAreReorientedLikeCgal) {
  // libcgal-demo's *-shuffled meshes have randomly flipped faces. A closed
  // connected orientable surface has exactly two consistent orientations, so
  // the repair must agree with CGAL's orient_polygon_soup up to a global flip.
  for (const char* name : {"cube-shuffled.off", "blobby-shuffled.off"}) {
    SCOPED_TRACE(name);
    Polygon_soup s = read_real(name);
    auto sr = genmesh::check_soup(s);
    ASSERT_GT(sr.inconsistent_edges, 0u);
    EXPECT_EQ(sr.non_manifold_edges + sr.non_manifold_vertices, 0u);
    TypeParam g;
    auto br = genmesh::build_mesh(s, g, {.repair = true});
    EXPECT_GT(br.repair.reoriented_faces, 0u);
    EXPECT_EQ(br.repair.reoriented_faces, br.repair.changes.size());
    EXPECT_EQ(br.vertices, s.num_points());
    EXPECT_EQ(br.faces, s.num_faces());
    auto r = genmesh::check_mesh(g);
    EXPECT_TRUE(r.ok()) << genmesh::to_string(r);

    std::vector<Kernel::Point_3> pts;
    for (const auto& p : s.points) pts.emplace_back(p.x(), p.y(), p.z());
    std::vector<std::vector<std::size_t>> polys;
    for (std::size_t f = 0; f < s.num_faces(); ++f) polys.emplace_back(s.face(f).begin(), s.face(f).end());
    ASSERT_TRUE(CGAL::Polygon_mesh_processing::orient_polygon_soup(pts, polys));
    ASSERT_EQ(pts.size(), s.num_points()); // CGAL did not need to duplicate points either
    Polygon_soup cgal, cgal_flipped;
    cgal.points = cgal_flipped.points = s.points;
    for (const auto& f : polys) {
      std::vector<Polygon_soup::Index> c(f.begin(), f.end());
      cgal.add_face(c);
      std::reverse(c.begin(), c.end());
      cgal_flipped.add_face(c);
    }
    Polygon_soup ours = genmesh::canonical(genmesh::to_soup(g));
    EXPECT_TRUE(ours == genmesh::canonical(cgal) || ours == genmesh::canonical(cgal_flipped));
  }
}

TYPED_TEST(Validity, MoebiusStripIsReportedNotRepaired) {
  // Five quads around a loop; the last one joins column 4 to column 0 upside
  // down, so no orientation of the faces agrees on every edge.
  //
  //   t0--t1--t2--t3--t4--(b0)
  //   |   |   |   |   |    |     bottom row b0..b4, the last quad twisted
  //   b0--b1--b2--b3--b4--(t0)
  Polygon_soup s;
  const int n = 5;
  for (int i = 0; i < n; ++i) {
    double a = 2 * std::numbers::pi * i / n;
    s.add_point(std::cos(a), std::sin(a), -0.3); // b_i = 2i
    s.add_point(std::cos(a), std::sin(a), 0.3);  // t_i = 2i+1
  }
  auto b = [](int i) { return static_cast<Polygon_soup::Index>(2 * i); };
  auto t = [](int i) { return static_cast<Polygon_soup::Index>(2 * i + 1); };
  for (int i = 0; i + 1 < n; ++i) s.add_face({b(i), b(i + 1), t(i + 1), t(i)});
  s.add_face({b(n - 1), t(0), b(0), t(n - 1)});
  auto sr = genmesh::check_soup(s);
  EXPECT_FALSE(sr.ok());
  EXPECT_EQ(sr.inconsistent_edges, 1u);
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::inconsistent_orientation, "edge (0, 1)"));
  EXPECT_EQ(sr.non_manifold_vertices + sr.non_manifold_edges, 0u);

  Polygon_soup copy = s;
  auto rep = genmesh::repair_soup(copy);
  EXPECT_EQ(rep.unorientable_components, 1u);
  EXPECT_EQ(rep.reoriented_faces, 0u);
  EXPECT_FALSE(rep.ok());
  EXPECT_EQ(copy, s);

  TypeParam g;
  try {
    genmesh::build_mesh(s, g, {.repair = true});
    ADD_FAILURE() << "a Möbius strip was built";
  } catch (const genmesh::invalid_input& e) {
    EXPECT_TRUE(mentions(e.what(), "not orientable")) << e.what();
  }
}

TYPED_TEST(Validity, DegenerateAndDuplicateFacesAreNamedAndRemoved) {
  Polygon_soup tet = genmesh::make_tetrahedron();
  Polygon_soup s = tet;
  s.add_face({0, 1, 1}); // face 4: a corner repeated
  s.add_face({2, 3});    // face 5: two corners
  auto c0 = tet.face(0);
  s.add_face(std::vector<Polygon_soup::Index>(c0.begin(), c0.end())); // face 6: a copy of face 0
  auto sr = genmesh::check_soup(s);
  EXPECT_EQ(sr.degenerate_faces, 2u);
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::degenerate_face, "face 4"));
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::degenerate_face, "face 5"));
  EXPECT_EQ(sr.duplicate_faces, 1u);
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::duplicate_face, "face 6"));
  std::string why = refusal<TypeParam>(s);
  EXPECT_TRUE(mentions(why, "face 4") && mentions(why, "face 5") && mentions(why, "face 6")) << why;

  TypeParam g;
  auto br = genmesh::build_mesh(s, g, {.repair = true});
  EXPECT_EQ(br.repair.removed_degenerate_faces, 2u);
  EXPECT_EQ(br.repair.merged_corners, 1u); // (0,1,1) became (0,1) first
  EXPECT_EQ(br.repair.removed_duplicate_faces, 1u);
  EXPECT_EQ(br.repair.removed_fin_faces, 0u);
  EXPECT_EQ(br.repair.face_origin, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(genmesh::to_soup(g), genmesh::rotate_faces_to_lowest(tet));
}

// Issue 14: duplicate detection compared every pair of faces around an edge
// (200k triangles on one edge took minutes); messages listed every face.
TEST(ValidityHostile, ManyFacesOnOneEdgeAndHugeFacesStayLinearAndShort) {
  Polygon_soup fan;
  const std::size_t n = 200'000;
  fan.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)};
  for (std::size_t i = 0; i < n; ++i) {
    fan.points.emplace_back(0.5, double(i + 1), 1.0);
    fan.add_face({0, 1, static_cast<Polygon_soup::Index>(i + 2)});
  }
  fan.add_face({1, 0, 2});   // the same corners as face 0, the other way round
  fan.add_face({2, 1, 0});   // and again, rotated
  const auto r = genmesh::check_soup(fan);
  EXPECT_EQ(r.duplicate_faces, 2u);
  EXPECT_EQ(r.non_manifold_edges, 3u);   // (0, 1) in n + 2 faces; (0, 2) and (1, 2) in 3
  EXPECT_TRUE(has_problem(r, genmesh::Soup_problem_kind::duplicate_face, "face 200000"));
  EXPECT_TRUE(has_problem(r, genmesh::Soup_problem_kind::duplicate_face, "face 200001"));
  for (const auto& p : r.problems) EXPECT_LT(p.message.size(), 300u) << p.element;
  for (const auto& p : r.problems) {
    if (p.kind == genmesh::Soup_problem_kind::non_manifold_edge && p.element == "edge (0, 1)") {
      EXPECT_EQ(p.faces.size(), n + 2);
    }
  }
  EXPECT_LT(genmesh::to_string(r).size(), 20'000u);

  // Same corner set in another cyclic order, sharing no edge: still a duplicate.
  Polygon_soup five;
  for (int i = 0; i < 5; ++i) five.points.emplace_back(std::cos(i), std::sin(i), 0);
  five.add_face({0, 1, 2, 3, 4});
  five.add_face({0, 2, 4, 1, 3});
  EXPECT_EQ(genmesh::check_soup(five).duplicate_faces, 1u);

  // A 1M-corner face repeating a corner: named in a short message.
  Polygon_soup big;
  const std::size_t m = 1'000'000;
  for (std::size_t i = 0; i < m; ++i) big.points.emplace_back(std::cos(i * 1e-6), std::sin(i * 1e-6), 0);
  std::vector<Polygon_soup::Index> corners(m + 1);
  for (std::size_t i = 0; i < m; ++i) corners[i] = static_cast<Polygon_soup::Index>(i);
  big.add_face(corners);   // the last corner is 0 again
  const auto b = genmesh::check_soup(big);
  EXPECT_EQ(b.degenerate_faces, 1u);
  EXPECT_LT(genmesh::to_string(b).size(), 1000u) << genmesh::to_string(b).substr(0, 2000);
}

TYPED_TEST(Validity, BadIndicesAndPointsAreRefused) {
  Polygon_soup s = genmesh::make_tetrahedron();
  s.add_face({0, 1, 9});
  auto sr = genmesh::check_soup(s);
  EXPECT_EQ(sr.out_of_range_faces, 1u);
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::index_out_of_range, "face 4"));
  EXPECT_TRUE(mentions(refusal<TypeParam>(s), "face 4"));

  Polygon_soup n = genmesh::make_tetrahedron();
  n.points[2].y() = std::numeric_limits<double>::quiet_NaN();
  auto nr = genmesh::check_soup(n);
  EXPECT_EQ(nr.non_finite_points, 1u);
  EXPECT_TRUE(has_problem(nr, genmesh::Soup_problem_kind::non_finite_point, "point 2"));
  TypeParam g;
  EXPECT_THROW(genmesh::build_mesh(n, g, {.repair = true}), genmesh::invalid_input); // cannot be repaired
  EXPECT_EQ(num_vertices(g), 0u);
}

TYPED_TEST(Validity, ZeroAreaFaceIsAWarningOnly) {
  Polygon_soup s;
  s.add_point(0, 0, 0);
  s.add_point(1, 0, 0);
  s.add_point(2, 0, 0); // collinear
  s.add_face({0, 1, 2});
  auto sr = genmesh::check_soup(s);
  EXPECT_TRUE(sr.ok());
  EXPECT_EQ(sr.zero_area_faces, 1u);
  TypeParam g;
  auto br = genmesh::build_mesh(s, g);
  EXPECT_EQ(br.zero_area_faces, 1u);
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
}

TYPED_TEST(Validity, BuildWithoutCheckStillRefusesWhatWouldCorruptTheMesh) {
  Polygon_soup flipped = strip();
  flip(flipped, 1);
  Polygon_soup bowtie;
  for (int i = 0; i < 5; ++i) bowtie.add_point(i, i % 2, 0);
  bowtie.add_face({0, 1, 2});
  bowtie.add_face({0, 3, 4});
  for (const auto& s : {flipped, bowtie}) {
    TypeParam g;
    EXPECT_THROW(genmesh::build_mesh(s, g, {.check = false}), genmesh::invalid_input);
    EXPECT_EQ(num_vertices(g), 0u); // refused before g was touched
  }
  TypeParam g;
  genmesh::build_mesh(strip(), g, {.check = false});
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
}

TYPED_TEST(Validity, TwoTetrahedraSharingAVertex) {
  // Two closed fans at vertex 0 (two tetrahedra touching at a tip): no border
  // gap betrays it, so only the fan count does.
  Polygon_soup tet = genmesh::make_tetrahedron();
  Polygon_soup s = tet;
  for (int i = 1; i < 4; ++i) s.add_point(2 * s.points[0] - tet.points[i]); // mirror through point 0
  for (std::size_t f = 0; f < 4; ++f) {
    std::vector<Polygon_soup::Index> c(tet.face(f).begin(), tet.face(f).end());
    for (auto& i : c)
      if (i != 0) i += 3;
    s.add_face(c); // inside out after the reflection; only the topology matters here
  }
  auto sr = genmesh::check_soup(s);
  EXPECT_EQ(sr.non_manifold_vertices, 1u);
  EXPECT_TRUE(has_problem(sr, genmesh::Soup_problem_kind::non_manifold_vertex, "vertex 0"));
  EXPECT_EQ(sr.errors(), 1u);

  {
    TypeParam g; // unchecked: the structure is built, and check_mesh finds the vertex
    genmesh::build_mesh(s, g, {.check = false});
    auto r = genmesh::check_mesh(g);
    EXPECT_TRUE(r.valid) << genmesh::to_string(r);
    EXPECT_FALSE(r.manifold);
    EXPECT_EQ(r.non_manifold_vertices, 1u);
    EXPECT_FALSE(r.genus.has_value());
  }
  TypeParam g;
  auto br = genmesh::build_mesh(s, g, {.repair = true});
  EXPECT_EQ(br.repair.added_points, 1u);
  auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.euler_characteristic, 4);
  EXPECT_EQ(*r.genus, 0);
}

TYPED_TEST(Validity, BuildRefusesANonEmptyMesh) {
  TypeParam g;
  genmesh::build_mesh(genmesh::make_tetrahedron(), g);
  EXPECT_THROW(genmesh::build_mesh(genmesh::make_tetrahedron(), g), genmesh::invalid_input);
}

// ---------------------------------------------------------------------------
// across backends
// ---------------------------------------------------------------------------

// The coarsest tori have strongly non-planar quads: their winding must come
// from the parametrization (an orientation test on the corners once flipped
// some faces of the 4 × 3 torus).
TEST(Generators, EveryTorusIsAConsistentlyOrientedClosedSurface) {
  for (int rings = 3; rings <= 7; ++rings)
    for (int sides = 3; sides <= 7; ++sides)
      for (bool tri : {false, true}) {
        SCOPED_TRACE(std::to_string(rings) + " x " + std::to_string(sides) + (tri ? " triangles" : " quads"));
        const Polygon_soup soup = genmesh::make_torus(rings, sides, tri);
        const auto r = genmesh::check_soup(soup);
        ASSERT_TRUE(r.ok()) << genmesh::to_string(r);
        genmesh::Halfedge_mesh<> g;
        genmesh::build_mesh(soup, g);
        const auto m = genmesh::check_mesh(g);
        EXPECT_TRUE(m.ok());
        EXPECT_EQ(m.euler_characteristic, 0);
        EXPECT_EQ(m.boundary_loops, 0u);
        // outward normals: the enclosed signed volume (divergence theorem, faces as fans) is positive
        double volume = 0;
        for (std::size_t fi = 0; fi < soup.num_faces(); ++fi) {
          const auto f = soup.face(fi);
          for (std::size_t k = 1; k + 1 < f.size(); ++k)
            volume += soup.points[f[0]].dot(soup.points[f[k]].cross(soup.points[f[k + 1]])) / 6.0;
        }
        EXPECT_GT(volume, 0.0);
      }
}

TEST(ValidityAcrossBackends, ToSoupIsIdentical) {
  std::vector<Polygon_soup> soups;
  for (auto& sh : shapes()) soups.push_back(sh.soup);
  soups.push_back(read_real("elephant-with-holes.off"));
  for (const auto& s : soups) {
    genmesh_test::Halfedge_mesh a;
    genmesh_test::Surface_mesh b;
    genmesh::build_mesh(s, a);
    genmesh::build_mesh(s, b);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(b));
    Polygon_soup sa = genmesh::to_soup(a), sb = genmesh::to_soup(b);
    EXPECT_EQ(sa, sb);
    EXPECT_EQ(genmesh::canonical(sa), genmesh::canonical(s));
    // Same halfedge structure, not only the same faces: the same check report.
    auto ra = genmesh::check_mesh(a), rb = genmesh::check_mesh(b);
    EXPECT_EQ(genmesh::to_string(ra), genmesh::to_string(rb));
  }
}

/// Each halfedge as (its index, next's, opposite's, target's, face's or -1), by index maps.
template <class G>
std::vector<std::array<long, 5>> structure(const G& g) {
  std::vector<std::array<long, 5>> out;
  auto hi = get(genmesh::halfedge_index, g);
  auto vi = get(genmesh::vertex_index, g);
  auto fi = get(genmesh::face_index, g);
  for (auto h : halfedges(g)) {
    auto f = face(h, g);
    out.push_back({long(get(hi, h)), long(get(hi, next(h, g))), long(get(hi, opposite(h, g))),
                   long(get(vi, target(h, g))),
                   f == boost::graph_traits<G>::null_face() ? -1L : long(get(fi, f))});
  }
  return out;
}

TEST(ValidityAcrossBackends, BuiltStructureIsIdentical) {
  // Not only the same faces: the same halfedge numbering and links, element by element.
  for (const auto& s : {genmesh::make_grid_with_hole(5), genmesh::make_torus(6, 5, false), strip()}) {
    genmesh_test::Halfedge_mesh a;
    genmesh_test::Surface_mesh b;
    genmesh::build_mesh(s, a);
    genmesh::build_mesh(s, b);
    EXPECT_EQ(structure(a), structure(b));
  }
}

TEST(ValidityAcrossBackends, PolyhedronWithoutIdsUsesHashedDescriptors) {
  // Polyhedron_3 without ids has no index maps: check_mesh and to_soup number
  // elements in iteration order instead, with the same results.
  using Polyhedron = CGAL::Polyhedron_3<Kernel>;
  static_assert(!genmesh::HasIndexMap<Polyhedron, genmesh::vertex_index_t>);
  for (const auto& sh : shapes()) {
    SCOPED_TRACE(sh.name);
    Polyhedron p;
    genmesh::build_mesh(sh.soup, p);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(p));
    auto r = genmesh::check_mesh(p);
    EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
    EXPECT_EQ(r.euler_characteristic, sh.chi);
    EXPECT_EQ(r.boundary_loops, sh.loops);
    ASSERT_TRUE(r.genus.has_value());
    EXPECT_EQ(*r.genus, sh.genus);
    EXPECT_EQ(genmesh::to_soup(p), genmesh::rotate_faces_to_lowest(sh.soup));
  }
  // A corrupt Polyhedron is named by iteration order and does not hang.
  Polyhedron p;
  genmesh::build_mesh(genmesh::make_tetrahedron(), p);
  auto h = *halfedges(p).begin();
  set_next(h, h, p);
  auto r = genmesh::check_mesh(p);
  EXPECT_TRUE(has_problem(r, genmesh::Mesh_problem_kind::self_loop, "halfedge 0")) << genmesh::to_string(r);
}

struct Double_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using Open_mesh = OpenMesh::PolyMesh_ArrayKernelT<Double_traits>;

TEST(ValidityAcrossBackends, OpenMeshBuildsAndChecksTheSame) {
  // OpenMesh stores outgoing halfedges; CGAL's adaptor translates, and the
  // results must not show it.
  for (const auto& sh : shapes()) {
    SCOPED_TRACE(sh.name);
    Open_mesh m;
    genmesh::build_mesh(sh.soup, m);
    auto r = genmesh::check_mesh(m);
    EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
    EXPECT_EQ(r.euler_characteristic, sh.chi);
    EXPECT_EQ(r.boundary_loops, sh.loops);
    ASSERT_TRUE(r.genus.has_value());
    EXPECT_EQ(*r.genus, sh.genus);
    EXPECT_EQ(genmesh::to_soup(m), genmesh::rotate_faces_to_lowest(sh.soup));
    genmesh_test::Surface_mesh sm;
    genmesh::build_mesh(sh.soup, sm);
    EXPECT_EQ(genmesh::to_string(r), genmesh::to_string(genmesh::check_mesh(sm)));
  }
}

TEST(ValidityAcrossBackends, CanonicalSortsFacesAndKeepsOrientation) {
  Polygon_soup s;
  for (int i = 0; i < 4; ++i) s.add_point(i, i * i, 0);
  s.add_face({3, 1, 2});
  s.add_face({2, 0, 1});
  Polygon_soup c = genmesh::canonical(s);
  EXPECT_EQ(c.points, s.points);
  EXPECT_EQ(c.indices, (std::vector<Polygon_soup::Index>{0, 1, 2, 1, 2, 3}));
  Polygon_soup flipped = s;
  flip(flipped, 0);
  EXPECT_NE(genmesh::canonical(flipped), c);
}

} // namespace
