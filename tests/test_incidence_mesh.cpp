// tests/test_incidence_mesh.cpp — Incidence_mesh: traversal equals Halfedge_mesh's, algebra on real
// meshes, non-manifold input, native local operations against the generic ones.
#include "backends.h"

#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>
#include <genmesh/validity.h>

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <sstream>

namespace genmesh {
// Readable soups in failure messages.
inline void PrintTo(const Polygon_soup& s, std::ostream* os) {
  *os << s.num_points() << " points, faces:";
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    *os << " (";
    for (auto c : s.face(f)) *os << c << ' ';
    *os << ')';
  }
}
} // namespace genmesh

namespace {

using genmesh::Edge_index;
using genmesh::Face_index;
using genmesh::Halfedge_index;
using genmesh::Vertex_index;
using Inc = genmesh::Incidence_mesh<>;
using Hm = genmesh::Halfedge_mesh<>;

// Every halfedge query of a and b agrees (same numbering).
template <class A>
void expect_same_traversal(const A& a, const Hm& b, bool as_built = true) {
  ASSERT_EQ(num_vertices(a), num_vertices(b));
  ASSERT_EQ(num_edges(a), num_edges(b));
  ASSERT_EQ(num_faces(a), num_faces(b));
  ASSERT_EQ(index_bound(genmesh::halfedge_index, a), index_bound(genmesh::halfedge_index, b));
  for (Halfedge_index h : halfedges(b)) {
    ASSERT_EQ(target(h, a), target(h, b)) << h;
    ASSERT_EQ(source(h, a), source(h, b)) << h;
    ASSERT_EQ(face(h, a), face(h, b)) << h;
    ASSERT_EQ(next(h, a), next(h, b)) << h;
    ASSERT_EQ(prev(h, a), prev(h, b)) << h;
    ASSERT_EQ(opposite(h, a), opposite(h, b)) << h;
  }
  for (Vertex_index v : vertices(b)) {
    const Halfedge_index ha = halfedge(v, a), hb = halfedge(v, b);
    ASSERT_EQ(ha.is_valid(), hb.is_valid()) << v;
    if (ha.is_valid()) {
      ASSERT_EQ(target(ha, a), v);
    }
    ASSERT_EQ(degree(v, a), degree(v, b)) << v;
    // A border vertex answers its border halfedge, as build_mesh sets it.
    if (as_built && hb.is_valid() && b.is_border(hb)) {
      ASSERT_EQ(ha, hb) << v;
    }
  }
  for (Face_index f : faces(b)) {
    const Halfedge_index ha = halfedge(f, a);
    ASSERT_EQ(face(ha, a), f);
    ASSERT_EQ(degree(f, a), degree(f, b));
  }
}

void expect_same_as_halfedge_mesh(const genmesh::Polygon_soup& soup) {
  Inc a;
  Hm b;
  genmesh::build_mesh(soup, a);
  genmesh::build_mesh(soup, b);
  expect_same_traversal(a, b);
  EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(b));
  EXPECT_TRUE(genmesh::check_mesh(a).ok()) << genmesh::to_string(genmesh::check_mesh(a));
  // from_soup numbers like build_mesh.
  Inc c = Inc::from_soup(soup);
  EXPECT_TRUE(c.is_manifold());
  expect_same_traversal(c, b);
  EXPECT_EQ(genmesh::to_soup(c), genmesh::to_soup(b));
}

TEST(IncidenceMesh, TraversalEqualsHalfedgeMeshOnGeneratedMeshes) {
  expect_same_as_halfedge_mesh(genmesh::make_tetrahedron());
  expect_same_as_halfedge_mesh(genmesh::make_cube());
  expect_same_as_halfedge_mesh(genmesh::make_icosphere(2));
  expect_same_as_halfedge_mesh(genmesh::make_torus(6, 5, false));
  expect_same_as_halfedge_mesh(genmesh::make_torus(6, 5, true));
  expect_same_as_halfedge_mesh(genmesh::make_grid(5, 4));
  expect_same_as_halfedge_mesh(genmesh::make_grid_with_hole(6));
}

TEST(IncidenceMesh, TraversalEqualsHalfedgeMeshOnRealMeshes) {
  for (const char* name : {"elephant.off", "cross.off", "mushroom.off"}) {
    SCOPED_TRACE(name);
    expect_same_as_halfedge_mesh(genmesh::read_soup(genmesh_test::real_mesh(name)));
  }
}


// ---- the documentation's algebra example (docs/incidence_mesh.md) ----------
// [algebra-example]
// d1 · d0 = 0 (the boundary of a boundary is empty), V − E + F = χ, and
// d0ᵀ d0 is the graph Laplacian (degree on the diagonal, −1 per edge).
struct Algebra_facts {
  bool boundary_of_boundary_vanishes = false;
  long euler_characteristic = 0;
  bool laplacian = false;
};
Algebra_facts algebra_facts(const genmesh::Incidence_mesh<>& m) {
  const Eigen::SparseMatrix<int> d0 = m.d0(), d1 = m.d1();
  Algebra_facts r;
  const Eigen::SparseMatrix<int> dd = d1 * d0;
  r.boundary_of_boundary_vanishes = dd.rows() == d1.rows() && dd.cols() == d0.cols();
  for (int k = 0; k < dd.outerSize(); ++k)
    for (Eigen::SparseMatrix<int>::InnerIterator it(dd, k); it; ++it)
      if (it.value() != 0) r.boundary_of_boundary_vanishes = false;
  r.euler_characteristic = static_cast<long>(num_vertices(m)) - static_cast<long>(num_edges(m)) +
                           static_cast<long>(num_faces(m));
  const Eigen::SparseMatrix<int> L = d0.transpose() * d0;
  r.laplacian = true;
  for (int k = 0; k < L.outerSize(); ++k)
    for (Eigen::SparseMatrix<int>::InnerIterator it(L, k); it; ++it) {
      const genmesh::Vertex_index a(static_cast<std::uint32_t>(it.row())), b(static_cast<std::uint32_t>(it.col()));
      const int expected = a == b ? static_cast<int>(m.degree(a)) : (m.halfedge(a, b).is_valid() ? -1 : 0);
      if (it.value() != expected) r.laplacian = false;
    }
  return r;
}
// [algebra-example]

// Issue 14: next() scanned the whole face past 16 sides (a 40k-gon took
// seconds to walk), and load_soup's repeated-corner test was quadratic.
TEST(IncidenceMesh, HugeFacesWalkInConstantTimePerStep) {
  // Big faces agree with Halfedge_mesh, around and across (a polygon with a
  // fan of triangles on one side and a hole).
  for (std::size_t n : {17u, 40u, 1000u}) {
    genmesh::Polygon_soup s;
    for (std::size_t i = 0; i < n; ++i)
      s.points.emplace_back(std::cos(6.283185307179586 * double(i) / double(n)), std::sin(6.283185307179586 * double(i) / double(n)), 0);
    s.points.emplace_back(0, 0, 1);
    std::vector<genmesh::Polygon_soup::Index> big;
    for (std::size_t i = 0; i < n; ++i) big.push_back(static_cast<genmesh::Polygon_soup::Index>(i));
    s.add_face(big);
    for (std::size_t i = 0; i + 1 < n / 2; ++i)   // triangles on the other side of half the rim
      s.add_face({static_cast<genmesh::Polygon_soup::Index>(i + 1), static_cast<genmesh::Polygon_soup::Index>(i),
                  static_cast<genmesh::Polygon_soup::Index>(n)});
    SCOPED_TRACE(n);
    expect_same_as_halfedge_mesh(s);
  }
  // One valid 300k-sided polygon: walking it once is 300k steps (a scan per
  // step took minutes).
  const std::size_t n = 300'000;
  genmesh::Polygon_soup s;
  std::vector<genmesh::Polygon_soup::Index> big(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.points.emplace_back(std::cos(double(i) * 6.283185307179586 / double(n)), std::sin(double(i) * 6.283185307179586 / double(n)), 0);
    big[i] = static_cast<genmesh::Polygon_soup::Index>(i);
  }
  s.add_face(big);
  Inc m;
  genmesh::build_mesh(s, m);
  const Halfedge_index h0 = halfedge(Face_index(0), m);
  Halfedge_index h = h0;
  std::size_t steps = 0, back = 0;
  do {
    ASSERT_EQ(prev(next(h, m), m), h);
    h = next(h, m);
    ++steps;
  } while (h != h0 && steps <= n);
  EXPECT_EQ(steps, n);
  for (Halfedge_index g = opposite(h0, m); back <= n; ++back) {   // the border, the other way
    g = next(g, m);
    if (g == opposite(h0, m)) break;
  }
  EXPECT_EQ(back + 1, n);
  EXPECT_TRUE(genmesh::check_mesh(m).ok());

  // load_soup: a 300k-corner face repeating its first corner at the end is
  // refused in one pass, naming the face and the point.
  std::vector<genmesh::Polygon_soup::Index> rep = big;
  rep.push_back(0);
  genmesh::Polygon_soup bad;
  bad.points = s.points;
  bad.add_face(rep);
  Inc l;
  try {
    l.load_soup(bad);
    ADD_FAILURE() << "a repeated corner was loaded";
  } catch (const genmesh::invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 visits point 0 twice"), std::string::npos) << e.what();
  }
}

TEST(IncidenceMesh, AlgebraOnRealMeshes) {
  for (const char* name : {"elephant.off", "mushroom.off", "cross_quad.off", "elephant-with-holes.off"}) {
    SCOPED_TRACE(name);
    Inc m;
    genmesh::build_mesh(genmesh::read_soup(genmesh_test::real_mesh(name)), m);
    const Algebra_facts r = algebra_facts(m);
    EXPECT_TRUE(r.boundary_of_boundary_vanishes);
    EXPECT_TRUE(r.laplacian);
    const genmesh::Mesh_report c = genmesh::check_mesh(m);
    EXPECT_TRUE(c.ok());
    EXPECT_EQ(r.euler_characteristic, c.euler_characteristic);
    // Shapes and entry counts: two per edge in d0, one per side in d1.
    EXPECT_EQ(m.d0().rows(), static_cast<long>(num_edges(m)));
    EXPECT_EQ(m.d0().nonZeros(), 2 * static_cast<long>(num_edges(m)));
    EXPECT_EQ(m.d1().cols(), static_cast<long>(num_edges(m)));
    EXPECT_EQ(m.d1().nonZeros(), static_cast<long>(num_halfedges(m) - c.border_halfedges));
  }
  // A flipped face breaks d1 · d0 = 0? No: d1 · d0 = 0 holds for any face
  // cycle; orientation shows in d1ᵀ (two equal signs on an edge).
  genmesh::Polygon_soup s = genmesh::make_cube();
  std::reverse(s.face(2).begin(), s.face(2).end());
  EXPECT_TRUE(algebra_facts(Inc::from_soup(s)).boundary_of_boundary_vanishes);
}

// ---- non-manifold input ----------------------------------------------------

// A fin: three triangles on edge 0-1 (apexes 3 and 2 in the plane, 4 above).
//        3
//       / |
//      0--1    and 0--1--4 standing up
//       | /
//        2
genmesh::Polygon_soup fin_soup() {
  genmesh::Polygon_soup s;
  s.add_point(0, 0, 0);
  s.add_point(1, 0, 0);
  s.add_point(0.5, -1, 0);
  s.add_point(0.5, 1, 0);
  s.add_point(0.5, 0, 1);
  s.add_face({0, 1, 3});
  s.add_face({1, 0, 2});
  s.add_face({0, 1, 4});
  return s;
}

// Two triangles touching at vertex 0 only (a bow-tie).
genmesh::Polygon_soup bowtie_soup() {
  genmesh::Polygon_soup s;
  s.add_point(0, 0, 0);
  s.add_point(1, 0, 0);
  s.add_point(1, 1, 0);
  s.add_point(-1, 0, 0);
  s.add_point(-1, -1, 0);
  s.add_face({0, 1, 2});
  s.add_face({0, 3, 4});
  return s;
}

TEST(IncidenceMesh, FinLoadsAndIsReported) {
  const Inc m = Inc::from_soup(fin_soup());
  EXPECT_FALSE(m.is_manifold());
  const auto r = m.manifold_report();
  ASSERT_EQ(r.fin_edges.size(), 1u);
  EXPECT_EQ(r.fin_edges[0], Edge_index(0));
  EXPECT_TRUE(r.misoriented_edges.empty());
  // The fin's ends: faces 0,1,2 are linked through edge 0 -> one fan each.
  EXPECT_TRUE(r.non_manifold_vertices.empty());
  EXPECT_EQ(num_faces(m), 3u);
  EXPECT_EQ(num_edges(m), 7u);
  try {
    (void)face(Halfedge_index(0), m);
    FAIL() << "face() on a fin must throw";
  } catch (const genmesh::invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("edge 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)next(Halfedge_index(1), m), genmesh::invalid_input);
  // Elsewhere queries work: edge 1 (1 -> 3) is an ordinary border edge.
  EXPECT_EQ(face(Halfedge_index(2), m), Face_index(0));
  // The soup read from d1 is the input; build_mesh refuses it and repairs it.
  const genmesh::Polygon_soup back = m.polygon_soup();
  EXPECT_EQ(back, genmesh::rotate_faces_to_lowest(fin_soup()));
  Hm h;
  EXPECT_THROW(genmesh::build_mesh(back, h), genmesh::invalid_input);
  Hm repaired;
  genmesh::build_mesh(back, repaired, {.repair = true});
  EXPECT_TRUE(genmesh::check_mesh(repaired).ok());
  // Local operations refuse on a non-manifold mesh.
  Inc w = m;
  EXPECT_FALSE(genmesh::can_split_edge(Halfedge_index(2), w));
  EXPECT_FALSE(genmesh::split_edge(Halfedge_index(2), w));
  EXPECT_EQ(w.polygon_soup(), back);
}

TEST(IncidenceMesh, BowTieLoadsAndIsReported) {
  const Inc m = Inc::from_soup(bowtie_soup());
  EXPECT_FALSE(m.is_manifold());
  const auto r = m.manifold_report();
  EXPECT_TRUE(r.fin_edges.empty());
  EXPECT_TRUE(r.misoriented_edges.empty());
  ASSERT_EQ(r.non_manifold_vertices.size(), 1u);
  EXPECT_EQ(r.non_manifold_vertices[0], Vertex_index(0));
  EXPECT_THROW((void)halfedge(Vertex_index(0), m), genmesh::invalid_input);
  // The border halfedge 1 -> 0 has two continuations at 0: refused.
  const Halfedge_index border_into0 = m.halfedge(Vertex_index(1), Vertex_index(0));
  ASSERT_TRUE(border_into0.is_valid());
  EXPECT_FALSE(face(border_into0, m).is_valid());
  EXPECT_THROW((void)next(border_into0, m), genmesh::invalid_input);
  const Halfedge_index into0 = m.halfedge(Vertex_index(2), Vertex_index(0));
  // Inside the faces everything works.
  EXPECT_EQ(next(next(next(into0, m), m), m), into0);
  EXPECT_EQ(halfedge(Vertex_index(1), m).is_valid(), true);
  Hm h;
  EXPECT_THROW(genmesh::build_mesh(m.polygon_soup(), h), genmesh::invalid_input);
  Hm repaired;
  genmesh::build_mesh(m.polygon_soup(), repaired, {.repair = true});
  EXPECT_TRUE(genmesh::check_mesh(repaired).ok());
}

TEST(IncidenceMesh, FlippedFaceLoadsAndIsReported) {
  genmesh::Polygon_soup s = genmesh::make_cube();
  std::reverse(s.face(2).begin(), s.face(2).end());
  const Inc m = Inc::from_soup(s);
  EXPECT_FALSE(m.is_manifold());
  const auto r = m.manifold_report();
  EXPECT_TRUE(r.fin_edges.empty());
  ASSERT_EQ(r.misoriented_edges.size(), 4u); // the four sides of face 2
  for (Edge_index e : r.misoriented_edges) {
    EXPECT_EQ(m.d1_rows().at(2, static_cast<int>(e.idx())) != 0, true) << e;
    EXPECT_THROW((void)face(halfedge(e, m), m), genmesh::invalid_input);
  }
  EXPECT_TRUE(r.non_manifold_vertices.empty());
  EXPECT_THROW(genmesh::to_soup(m), genmesh::invalid_input);
  Hm h;
  EXPECT_THROW(genmesh::build_mesh(m.polygon_soup(), h), genmesh::invalid_input);
  Hm repaired;
  genmesh::build_mesh(m.polygon_soup(), repaired, {.repair = true});
  EXPECT_TRUE(genmesh::check_mesh(repaired).ok());
  EXPECT_EQ(num_faces(repaired), 6u);
  // Bad faces are refused by the loader, with the face named.
  genmesh::Polygon_soup bad = genmesh::make_cube();
  bad.face(1)[2] = bad.face(1)[0];
  EXPECT_THROW(Inc::from_soup(bad), genmesh::invalid_input);
}

// ---- building, copying, subdividing, files ---------------------------------

// Exactly the same result as on Halfedge_mesh (the refinement numbers new
// elements independently of the backend); exact = false compares only counts,
// sorted points and validity (for a scheme whose numbering would follow a
// backend's own representatives; none does now).
template <class Options>
void expect_same_subdivision(const genmesh::Polygon_soup& soup, auto scheme, const Options& options,
                             bool exact = true) {
  Inc a;
  Hm b;
  genmesh::build_mesh(soup, a);
  genmesh::build_mesh(soup, b);
  scheme(a, options);
  scheme(b, options);
  EXPECT_TRUE(genmesh::check_mesh(a).ok());
  if (exact) {
    EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(b));
    return;
  }
  EXPECT_EQ(num_vertices(a), num_vertices(b));
  EXPECT_EQ(num_edges(a), num_edges(b));
  EXPECT_EQ(num_faces(a), num_faces(b));
  auto sorted_points = [](genmesh::Polygon_soup s) {
    std::sort(s.points.begin(), s.points.end(), [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
      return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
    });
    return s.points;
  };
  EXPECT_EQ(sorted_points(genmesh::to_soup(a)), sorted_points(genmesh::to_soup(b)));
}

// Every third edge sharp, every seventh semi-sharp (edge numbering is the
// same on both backends after build_mesh).
std::vector<double> some_creases(const genmesh::Polygon_soup& soup) {
  Hm g;
  genmesh::build_mesh(soup, g);
  std::vector<double> sharp(num_edges(g), 0.0);
  for (std::size_t i = 0; i < sharp.size(); ++i) sharp[i] = i % 3 == 0 ? 1e9 : i % 7 == 0 ? 1.5 : 0.0;
  return sharp;
}

TEST(IncidenceMesh, SubdivisionMatchesHalfedgeMesh) {
  const auto elephant = genmesh::read_soup(genmesh_test::real_mesh("elephant.off"));
  const auto loop = [](auto& g, const auto& o) { genmesh::loop_subdivision(g, o); };
  const auto catmull_clark = [](auto& g, const auto& o) { genmesh::catmull_clark_subdivision(g, o); };
  expect_same_subdivision(elephant, loop, genmesh::Loop_options{.iterations = 2});
  // creases: a crease map per mesh (sharpness in edge iteration order, the same on both)
  const auto creased = [](auto& g, const std::vector<double>& sharp, bool loop_scheme) {
    auto m = genmesh::make_crease_map(g);
    std::size_t k = 0;
    for (auto e : edges(g)) put(m, e, sharp[k++]);
    if (loop_scheme) genmesh::loop_subdivision(g, genmesh::Loop_options{.crease_map = m});
    else genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.iterations = 2, .crease_map = m});
  };
  expect_same_subdivision(elephant, [&](auto& g, const auto& s) { creased(g, s, true); }, some_creases(elephant));
  expect_same_subdivision(genmesh::make_grid_with_hole(6), loop, genmesh::Loop_options{.iterations = 2});
  expect_same_subdivision(genmesh::make_grid_with_hole(6), catmull_clark,
                          genmesh::Catmull_clark_options{.iterations = 2});
  expect_same_subdivision(elephant, catmull_clark, genmesh::Catmull_clark_options{.iterations = 2});
  expect_same_subdivision(genmesh::make_cube(), [&](auto& g, const auto& s) { creased(g, s, false); },
                          some_creases(genmesh::make_cube()));
  expect_same_subdivision(genmesh::make_icosphere(1),
                          [](auto& g, const auto& o) { genmesh::sqrt3_subdivision(g, o); },
                          genmesh::Sqrt3_options{.iterations = 2});
}

TEST(IncidenceMesh, CopyMoveClearAndFiles) {
  Inc a;
  genmesh::build_mesh(genmesh::make_icosphere(1), a);
  Inc b = a; // deep copy: the rows are laid out again
  Hm h;
  genmesh::build_mesh(genmesh::make_icosphere(1), h);
  expect_same_traversal(b, h);
  b.point(Vertex_index(0)).x() += 1.0;
  EXPECT_NE(a.point(Vertex_index(0)), b.point(Vertex_index(0)));
  Inc c = std::move(b);
  expect_same_traversal(c, h);
  EXPECT_EQ(num_vertices(b), 0u);
  c.clear();
  EXPECT_EQ(num_faces(c), 0u);
  EXPECT_TRUE(c.is_manifold());
  genmesh::build_mesh(genmesh::make_cube(), c); // empty again: builds
  EXPECT_EQ(num_faces(c), 6u);
  EXPECT_THROW(genmesh::build_mesh(genmesh::make_cube(), c), genmesh::invalid_input); // not empty
  const std::string path = genmesh_test::tmp_path("inc.off");
  genmesh::write_mesh(path, a);
  EXPECT_EQ(genmesh::read_soup(path).num_faces(), num_faces(a));
  EXPECT_GT(a.memory_bytes(), 0u);
}

TEST(IncidenceMesh, OtherPointTypes) {
  genmesh::Incidence_mesh<std::array<float, 3>> a;
  genmesh::Halfedge_mesh<std::array<float, 3>> b;
  genmesh::build_mesh(genmesh::make_cube(), a);
  genmesh::build_mesh(genmesh::make_cube(), b);
  EXPECT_EQ(genmesh::split_edge(Halfedge_index(0), a), genmesh::split_edge(Halfedge_index(0), b));
  EXPECT_EQ(genmesh::add_center_vertex(Halfedge_index(2), a), genmesh::add_center_vertex(Halfedge_index(2), b));
  EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(b));
}

TEST(IncidenceMesh, AllocationIsHalfedgeMeshs) {
  Inc a;
  Hm b;
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(a.add_vertex(), b.add_vertex());
  }
  a.remove_vertex(Vertex_index(1));
  b.remove_vertex(Vertex_index(1));
  a.remove_vertex(Vertex_index(3));
  b.remove_vertex(Vertex_index(3));
  EXPECT_EQ(num_vertices(a), 2u);
  EXPECT_TRUE(a.is_removed(Vertex_index(3)));
  EXPECT_EQ(a.add_vertex(), b.add_vertex()); // 3 (LIFO)
  EXPECT_EQ(a.add_vertex(), b.add_vertex()); // 1
  EXPECT_EQ(a.add_vertex(), b.add_vertex()); // 4 (appended)
  const Edge_index e = a.add_edge(Vertex_index(0), Vertex_index(2));
  EXPECT_EQ(e, b.edge(b.add_edge(Vertex_index(0), Vertex_index(2))));
  EXPECT_EQ(target(halfedge(e, a), a), Vertex_index(2));
  EXPECT_EQ(a.halfedge(Vertex_index(2)), halfedge(e, a)); // its incoming (border) halfedge
  a.set_recycle_garbage(false);
  a.remove_vertex(Vertex_index(4));
  EXPECT_EQ(a.add_vertex(), Vertex_index(5));
  std::size_t n = 0;
  for (Vertex_index v : vertices(a)) {
    EXPECT_FALSE(a.is_removed(v));
    ++n;
  }
  EXPECT_EQ(n, num_vertices(a));
}


// ---- the row store ------------------------------------------------------------

// Sets (v ≠ 0) or erases (v = 0) entry (r, c) of the store and of its dense twin.
void edit_both(genmesh::detail::Incidence_rows& rows, Eigen::MatrixXi& dense, std::uint32_t r, int c, signed char v) {
  if (v == 0) rows.erase(r, c);
  else rows.set(r, c, v);
  dense(static_cast<int>(r), c) = v;
}

// Rows that outgrow their slots move to the end of the buffer and abandoned
// slots are compacted; through all of it the Eigen matrix reads back exactly
// the entries set (checked against a dense copy), in column order.
TEST(IncidenceRows, RelocationAndCompactionKeepTheMatrix) {
  genmesh::detail::Incidence_rows rows;
  const int n = 200;
  rows.reserve_shape(n, n);
  Eigen::MatrixXi dense = Eigen::MatrixXi::Zero(n, n);
  std::mt19937 rng(5);
  for (int step = 0; step < 20000; ++step) {
    const auto r = static_cast<std::uint32_t>(rng() % n);
    const int c = static_cast<int>(rng() % n);
    if (rng() % 3 == 0) edit_both(rows, dense, r, c, 0);
    else edit_both(rows, dense, r, c, (rng() & 1u) ? 1 : -1);
    if (step % 1000 == 0) rows.clear_row(static_cast<std::uint32_t>(step / 1000)), dense.row(step / 1000).setZero();
  }
  EXPECT_GT(rows.compactions(), 0u);
  const Eigen::SparseMatrix<int, Eigen::RowMajor> out = rows.compressed(n, n);
  EXPECT_EQ(Eigen::MatrixXi(out), dense);
  // The stored (uncompressed) matrix itself is a valid Eigen matrix.
  const Eigen::SparseMatrix<int> stored = rows.matrix().cast<int>();
  EXPECT_EQ(Eigen::MatrixXi(stored).topLeftCorner(n, n), dense);
  for (std::uint32_t r = 0; r < static_cast<std::uint32_t>(n); ++r)
    EXPECT_TRUE(std::is_sorted(rows.cols(r), rows.cols(r) + rows.size(r)));
  // A copy is laid out again and reads the same.
  genmesh::detail::Incidence_rows copy = rows;
  EXPECT_EQ(Eigen::MatrixXi(copy.compressed(n, n)), dense);
  copy.set(3, 7, 1);
  EXPECT_EQ(rows.at(3, 7), dense(3, 7));
}

// `steps` seeded random flips, splits, collapses (and centre vertices when
// `centres`) at random edges.
void random_local_operations(Inc& m, unsigned seed, int steps, bool centres) {
  std::mt19937 rng(seed);
  for (int step = 0; step < steps; ++step) {
    const Edge_index e(static_cast<std::uint32_t>(rng() % m.edges_size()));
    if (m.is_removed(e)) continue;
    switch (rng() % (centres ? 4 : 3)) {
    case 0: genmesh::flip_edge(halfedge(e, m), m); break;
    case 1: genmesh::split_edge_and_triangulate(halfedge(e, m), m); break;
    case 3: genmesh::add_center_vertex(halfedge(e, m), m); break;
    default: genmesh::collapse_edge(e, m); break;
    }
  }
}

// After thousands of operations the matrices still satisfy the algebra.
TEST(IncidenceRows, AlgebraHoldsAfterOperations) {
  Inc m;
  genmesh::build_mesh(genmesh::make_icosphere(2), m);
  random_local_operations(m, 9, 3000, false);
  const Algebra_facts r = algebra_facts(m);
  EXPECT_TRUE(r.boundary_of_boundary_vanishes);
  EXPECT_TRUE(r.laplacian);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_TRUE(genmesh::check_mesh(m).ok());
  // Removed elements leave empty rows and columns.
  EXPECT_EQ(m.d0().nonZeros(), 2 * static_cast<long>(num_edges(m)));
  EXPECT_EQ(m.d1().nonZeros(), 3 * static_cast<long>(num_faces(m)));
}

// A store with home slots keeps row r at 2r, zero past its end, and reads
// as the same matrix; the first row of three entries turns it general, and
// the matrix still reads back exactly.
TEST(IncidenceRows, HomeSlotsReadAsTheMatrix) {
  EXPECT_THROW(genmesh::detail::Incidence_rows(3), genmesh::invalid_input);
  genmesh::detail::Incidence_rows rows(2);
  const int n = 150;
  rows.reserve_shape(10, n); // grows by doubling below
  Eigen::MatrixXi dense = Eigen::MatrixXi::Zero(n, n);
  std::mt19937 rng(17);
  auto expect_home_layout = [&](int bound) {
    ASSERT_TRUE(rows.homed());
    bound = std::min(bound, static_cast<int>(rows.matrix().rows())); // rows reserved so far
    for (std::uint32_t r = 0; r < static_cast<std::uint32_t>(bound); ++r) {
      const int k = rows.size(r);
      ASSERT_LE(k, 2);
      for (int j = 0; j < k; ++j) {
        ASSERT_EQ(rows.home_cols(r)[j], rows.cols(r)[j]) << r;
        ASSERT_EQ(rows.home_vals(r)[j], rows.vals(r)[j]) << r;
      }
      for (int j = k; j < 2; ++j) ASSERT_EQ(rows.home_vals(r)[j], 0) << "row " << r << " past its end";
    }
  };
  for (int step = 0; step < 20000; ++step) {
    const auto r = static_cast<std::uint32_t>(rng() % n);
    rows.reserve_shape(r + 1, n);
    const int c = static_cast<int>(rng() % n);
    if (rows.size(r) == 2 || rng() % 3 == 0)
      edit_both(rows, dense, r, rows.size(r) == 2 && rng() % 2 ? rows.cols(r)[rng() % 2] : c, 0);
    else edit_both(rows, dense, r, c, (rng() & 1u) ? 1 : -1);
    if (step % 997 == 0) rows.clear_row(r), dense.row(static_cast<int>(r)).setZero();
    if (step % 2000 == 0) expect_home_layout(n);
  }
  expect_home_layout(n);
  EXPECT_EQ(Eigen::MatrixXi(rows.compressed(n, n)), dense);
  // A copy is homed again (Eigen's copy compresses it).
  const genmesh::detail::Incidence_rows copy = rows;
  EXPECT_TRUE(copy.homed());
  EXPECT_EQ(Eigen::MatrixXi(copy.compressed(n, n)), dense);
  // A third entry: the general layout from then on, same matrix.
  std::uint32_t full = 0;
  while (rows.size(full) != 2) ++full;
  int c = 0;
  while (dense(static_cast<int>(full), c) != 0) ++c;
  rows.set(full, c, 1);
  dense(static_cast<int>(full), c) = 1;
  EXPECT_FALSE(rows.homed());
  EXPECT_EQ(Eigen::MatrixXi(rows.compressed(n, n)), dense);
  EXPECT_EQ(Eigen::MatrixXi(rows.matrix().cast<int>()).topLeftCorner(n, n), dense);
}

// The mesh's E-row stores (d0, d1ᵀ) stay homed through local operations on
// a manifold mesh, so the fast derivations are the ones in use; a fin needs
// three faces in a d1ᵀ row and turns that store general.
TEST(IncidenceMesh, EdgeRowsStayHomedWhileManifold) {
  Inc m;
  genmesh::build_mesh(genmesh::make_icosphere(2), m);
  EXPECT_TRUE(m.d0_rows().homed());
  EXPECT_TRUE(m.d1t_rows().homed());
  EXPECT_TRUE(m.d1_rows().homed()); // faces of at most four sides
  random_local_operations(m, 23, 3000, true);
  EXPECT_TRUE(m.d0_rows().homed());
  EXPECT_TRUE(m.d1t_rows().homed());
  EXPECT_TRUE(m.d1_rows().homed());
  Hm b;
  genmesh::build_mesh(genmesh::to_soup(m), b);
  Inc again;
  genmesh::build_mesh(genmesh::to_soup(m), again);
  expect_same_traversal(again, b);
  const Inc copy = m; // copies stay homed
  EXPECT_TRUE(copy.d0_rows().homed() && copy.d1t_rows().homed());

  // A pentagon needs five entries in its d1 row: that store is general, the
  // mesh the same.
  genmesh::Polygon_soup pent;
  for (int i = 0; i < 5; ++i) pent.add_point(std::cos(1.2566 * i), std::sin(1.2566 * i), 0);
  pent.add_face({0, 1, 2, 3, 4});
  Inc p;
  genmesh::build_mesh(pent, p);
  EXPECT_FALSE(p.d1_rows().homed());
  EXPECT_TRUE(p.d0_rows().homed() && p.d1t_rows().homed());
  Hm pb;
  genmesh::build_mesh(pent, pb);
  expect_same_traversal(p, pb);

  const Inc fin = Inc::from_soup(fin_soup());
  EXPECT_TRUE(fin.d0_rows().homed());
  EXPECT_FALSE(fin.d1t_rows().homed());
  EXPECT_EQ(fin.d1t_rows().size(fin.manifold_report().fin_edges.at(0).idx()), 3);
}

// target(h), face(h) and next(h) (inside a face) read straight off the rows.
Vertex_index row_target(const Inc& m, Halfedge_index h) {
  const int c = m.d0_rows().column_of(h.idx() / 2, (h.idx() & 1u) ? -1 : 1);
  return c < 0 ? Vertex_index() : Vertex_index(static_cast<std::uint32_t>(c));
}
Face_index row_face(const Inc& m, Halfedge_index h) {
  const int c = m.d1t_rows().column_of(h.idx() / 2, (h.idx() & 1u) ? -1 : 1);
  return c < 0 ? Face_index() : Face_index(static_cast<std::uint32_t>(c));
}
Halfedge_index row_next(const Inc& m, Halfedge_index h) {
  const auto& d1 = m.d1_rows();
  const std::uint32_t f = row_face(m, h).idx();
  const Vertex_index t = row_target(m, h);
  for (int k = 0; k < d1.size(f); ++k) {
    const Halfedge_index x(2u * static_cast<std::uint32_t>(d1.cols(f)[k]) + (d1.vals(f)[k] < 0 ? 1u : 0u));
    if (x.idx() / 2 != h.idx() / 2 && row_target(m, Halfedge_index(x.idx() ^ 1u)) == t) return x;
  }
  return {};
}

// Low-level edits without update_face_orders(): next() and prev() must not
// read a stale turn record. Reversing edges (take both sides out of their
// faces, turn the edge around, put each side into the other face) moves a
// recorded side into a face already marked, which only add_side() can
// clear; swapping vertices' incidences changes cycles without touching d1.
TEST(IncidenceMesh, TurnRecordsNeverStale) {
  const genmesh::Polygon_soup soup = genmesh::make_icosphere(2);
  Inc m;
  genmesh::build_mesh(soup, m);
  std::mt19937 rng(31);
  auto expect_same_as_recomputed = [&](const char* what) {
    Inc fresh = m; // the same matrices, records recomputed from them
    fresh.update_face_orders();
    for (Halfedge_index h : halfedges(m)) {
      ASSERT_EQ(m.next(h), fresh.next(h)) << what << ' ' << h;
      ASSERT_EQ(m.prev(h), fresh.prev(h)) << what << ' ' << h;
      // Against the rows themselves, no record involved.
      ASSERT_EQ(m.target(h), row_target(m, h)) << what << ' ' << h;
      ASSERT_EQ(m.face(h), row_face(m, h)) << what << ' ' << h;
      if (row_face(m, h).is_valid()) {
        ASSERT_EQ(m.next(h), row_next(m, h)) << what << ' ' << h;
      }
      ASSERT_EQ(m.prev(m.next(h)), h) << what << ' ' << h;
      ASSERT_EQ(m.target(h), m.source(m.next(h))) << what << ' ' << h;
    }
  };
  for (int step = 0; step < 40; ++step) {
    Edge_index e(static_cast<std::uint32_t>(rng() % m.edges_size()));
    while (m.is_removed(e)) e = Edge_index(static_cast<std::uint32_t>(rng() % m.edges_size()));
    const Halfedge_index h0 = m.halfedge(e, 0), h1 = m.halfedge(e, 1);
    const Face_index fa = m.face(h0), fb = m.face(h1);
    const Vertex_index u = m.source(h0), v = m.target(h0);
    m.remove_side(fa, h0);
    m.remove_side(fb, h1);
    m.set_edge_vertices(e, v, u);
    m.add_side(fa, h1);
    m.add_side(fb, h0);
    if (step % 5 == 4 && m.degree(fa) == 3 && m.degree(fb) == 3) {
      // Join fa and fb into a quad: their sides other than e move into a new
      // face at other row positions; removing a face leaves its sides'
      // records behind, which add_side() must clear.
      m.update_face_orders(); // the sides have records now
      std::vector<Halfedge_index> sides;
      for (Halfedge_index x = m.next(h1); x != h1; x = m.next(x)) sides.push_back(x);
      for (Halfedge_index x = m.next(h0); x != h0; x = m.next(x)) sides.push_back(x);
      m.remove_face(fa);
      m.remove_face(fb);
      m.remove_edge(e);
      const Face_index q = m.add_face();
      for (Halfedge_index x : sides) m.add_side(q, x);
      ASSERT_EQ(m.degree(q), 4u);
    }
    if (step % 4 == 3) {
      const Vertex_index p(static_cast<std::uint32_t>(rng() % m.vertices_size()));
      const Vertex_index q(static_cast<std::uint32_t>(rng() % m.vertices_size()));
      if (p != q) m.swap_incidences(p, q);
    }
    expect_same_as_recomputed("before update_face_orders");
    if (step % 10 == 9) {
      m.update_face_orders();
      expect_same_as_recomputed("after update_face_orders");
    }
  }
  EXPECT_TRUE(genmesh::check_mesh(m).ok()) << genmesh::to_string(genmesh::check_mesh(m));
}

// ---- native local operations against the generic ones ---------------------

std::vector<Halfedge_index> detail_cycle(Halfedge_index h, const Inc& m) {
  std::vector<Halfedge_index> c;
  Halfedge_index x = h;
  do {
    c.push_back(x);
    x = m.next(x);
  } while (x != h);
  return c;
}

// Records every visitor call as text, on any mesh.
struct Recorder : genmesh::Mutation_visitor {
  std::vector<std::string> log;
  template <class D>
  void add(const char* what, D d) {
    std::ostringstream o;
    o << what << ' ' << d;
    log.push_back(o.str());
  }
  void on_flip(const auto& h, const auto&) { add("flip", h); }
  void on_split_edge(const auto& h, const auto&) { add("split_edge", h); }
  void before_collapse(const auto& h, const auto&) { add("before_collapse", h); }
  void on_collapse(const auto& v, const auto&) { add("collapse", v); }
  void on_split_face(const auto& h, const auto&) { add("split_face", h); }
  void before_join_face(const auto& h, const auto&) { add("before_join_face", h); }
  void on_add_center_vertex(const auto& h, const auto&) { add("add_center_vertex", h); }
  void before_remove_center_vertex(const auto& h, const auto&) { add("before_remove_center_vertex", h); }
  void on_bevel_vertex(const auto& f, const auto&) { add("bevel_vertex", f); }
  void on_bevel_face(const auto& f, const auto&) { add("bevel_face", f); }
  void on_bevel_edge(const auto& h, const auto&) { add("bevel_edge", h); }
  void on_add_face(const auto& f, const auto&) { add("add_face", f); }
  void before_remove_face(const auto& h, const auto&) { add("before_remove_face", h); }
};

// The same mesh twice: Incidence_mesh (native operations) and Halfedge_mesh
// (the generic ones, CGAL::Euler's edits).
struct Twin {
  Inc a;
  Hm b;
  Recorder ra, rb;
  std::map<std::string, int> own_counts;
  std::map<std::string, int>* counts = &own_counts; // successful operations by name
  explicit Twin(const genmesh::Polygon_soup& s) {
    genmesh::build_mesh(s, a);
    genmesh::build_mesh(s, b);
  }
  // Runs op on both; the results, the visitor calls and the soups must agree;
  // a refusal must leave both meshes as they were. Returns whether it applied.
  template <class Op>
  bool apply(Op&& op, const char* what) {
    const genmesh::Polygon_soup before = genmesh::to_soup(a);
    const std::size_t la = ra.log.size();
    const auto x = op(a, ra);
    const auto y = op(b, rb);
    EXPECT_EQ(x, y) << what;
    EXPECT_EQ(ra.log, rb.log) << what;
    genmesh::Polygon_soup sa, sb;
    try {
      sa = genmesh::to_soup(a);
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": Incidence_mesh: " << e.what();
    }
    try {
      sb = genmesh::to_soup(b);
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": Halfedge_mesh: " << e.what();
    }
    EXPECT_EQ(sa, sb) << what;
    EXPECT_EQ(index_bound(genmesh::edge_index, a), index_bound(genmesh::edge_index, b)) << what;
    EXPECT_EQ(num_edges(a), num_edges(b)) << what;
    const bool applied = static_cast<bool>(x);
    if (applied) ++(*counts)[what];
    if (!applied) {
      EXPECT_EQ(sa, before) << what << ": a refusal changed the mesh";
      EXPECT_EQ(ra.log.size(), la) << what << ": a refusal called the visitor";
    }
    return applied;
  }
  // The generic bevel_vertex/bevel_face/erase_vertex start at halfedge(v) /
  // halfedge(f), which Halfedge_mesh remembers and Incidence_mesh derives:
  // give Halfedge_mesh the incidence mesh's choice first.
  void align(Vertex_index v) {
    if (a.is_valid(v) && a.halfedge(v).is_valid()) b.set_halfedge(v, a.halfedge(v));
  }
  void align(Face_index f) {
    if (a.is_valid(f)) b.set_halfedge(f, a.halfedge(f));
  }
  void expect_valid(const char* what) {
    const auto r = genmesh::check_mesh(a);
    EXPECT_TRUE(r.ok()) << what << "\n" << genmesh::to_string(r);
    EXPECT_TRUE(genmesh::check_mesh(b).ok()) << what;
  }
};

// Same edge directions on both: edge e's halfedge 0 targets the same vertex.
void expect_same_edges(const Twin& t) {
  for (Edge_index e : edges(t.b)) {
    ASSERT_EQ(target(t.b.halfedge(e, 0), t.a), target(t.b.halfedge(e, 0), t.b)) << e;
    ASSERT_EQ(source(t.b.halfedge(e, 0), t.a), source(t.b.halfedge(e, 0), t.b)) << e;
  }
  for (Halfedge_index h : halfedges(t.b)) {
    ASSERT_EQ(next(h, t.a), next(h, t.b)) << h;
    ASSERT_EQ(prev(h, t.a), prev(h, t.b)) << h;
    ASSERT_EQ(face(h, t.a), face(h, t.b)) << h;
  }
  // halfedge(v) skips the scan on vertices its border count calls interior:
  // the count must be right after every edit.
  std::vector<char> on_border(t.b.vertices_size(), 0);
  for (Edge_index e : edges(t.b))
    if (t.b.is_border(e)) on_border[source(t.b.halfedge(e, 0), t.b).idx()] = on_border[target(t.b.halfedge(e, 0), t.b).idx()] = 1;
  for (Vertex_index v : vertices(t.b)) {
    if (!t.a.is_isolated(v)) {
      ASSERT_EQ(t.a.is_border(halfedge(v, t.a)), on_border[v.idx()] != 0) << v;
    }
  }
}

#define OP(expr) [&](auto& g, auto& rec) { return expr; }

//  3---4---5
//  | \ | \ |     make_grid(2, 1): two quads... triangulated by the test.
//  0---1---2
TEST(IncidenceOperations, GoldenCasesAndRefusals) {
  {
    SCOPED_TRACE("flip_edge");
    Twin t(genmesh::make_icosphere(0));
    EXPECT_TRUE(t.apply(OP(genmesh::flip_edge(Halfedge_index(0), g, rec)), "flip"));
    EXPECT_EQ(t.a.target(Halfedge_index(0)), t.b.target(Halfedge_index(0)));
    // Border edge: refused.
    Twin grid(genmesh::make_grid(2, 2));
    grid.apply(OP(genmesh::triangulate_faces(g, rec) == 0 ? std::optional<int>(1) : std::nullopt), "triangulate");
    for (Edge_index e : edges(grid.a))
      if (grid.a.is_border(e)) {
        EXPECT_FALSE(grid.apply(OP(genmesh::flip_edge(halfedge(e, g), g, rec)), "flip border"));
        break;
      }
    // Tetrahedron: both ends of degree 3: refused.
    // unflip_edge undoes flip_edge exactly.
    const genmesh::Polygon_soup before = genmesh::to_soup(t.a);
    EXPECT_TRUE(t.apply(OP(genmesh::flip_edge(Halfedge_index(6), g, rec)), "flip"));
    EXPECT_TRUE(t.apply(OP(genmesh::unflip_edge(Halfedge_index(6), g, rec)), "unflip"));
    EXPECT_EQ(genmesh::to_soup(t.a), before);
    Twin tet(genmesh::make_tetrahedron());
    EXPECT_FALSE(tet.apply(OP(genmesh::flip_edge(Halfedge_index(2), g, rec)), "flip tet"));
    EXPECT_FALSE(tet.apply(OP(genmesh::unflip_edge(Halfedge_index(2), g, rec)), "unflip tet"));
    // Quads: refused.
    Twin cube(genmesh::make_cube());
    EXPECT_FALSE(cube.apply(OP(genmesh::flip_edge(Halfedge_index(2), g, rec)), "flip quad"));
    expect_same_edges(t);
  }
  {
    SCOPED_TRACE("split_edge, split_edge_and_triangulate");
    Twin t(genmesh::make_grid(2, 2));
    const std::size_t v0 = num_vertices(t.a);
    EXPECT_TRUE(t.apply(OP(genmesh::split_edge(Halfedge_index(0), g, rec)), "split"));
    EXPECT_EQ(num_vertices(t.a), v0 + 1);
    EXPECT_TRUE(t.apply(OP(genmesh::split_edge(Halfedge_index(1), g, rec)), "split other side"));
    EXPECT_FALSE(t.apply(OP(genmesh::split_edge(Halfedge_index(), g, rec)), "split null"));
    EXPECT_FALSE(t.apply(OP(genmesh::split_edge_and_triangulate(Halfedge_index(4), g, rec)), "quads refused"));
    Twin s(genmesh::make_icosphere(1));
    EXPECT_TRUE(s.apply(OP(genmesh::split_edge_and_triangulate(Halfedge_index(7), g, rec)), "split+tri"));
    EXPECT_EQ(num_faces(s.a), 82u);
    s.expect_valid("split+tri");
    expect_same_edges(s);
  }
  {
    SCOPED_TRACE("collapse_edge");
    Twin t(genmesh::make_icosphere(1));
    EXPECT_TRUE(t.apply(OP(genmesh::collapse_edge(Edge_index(3), g, rec)), "collapse"));
    EXPECT_EQ(num_faces(t.a), 78u);
    t.expect_valid("collapse");
    for (Edge_index e : edges(t.b))
      for (unsigned side : {0u, 1u}) {
        const Edge_index es(t.b.halfedge(e, side));
        EXPECT_EQ(genmesh::does_satisfy_link_condition(es, t.a), genmesh::does_satisfy_link_condition(es, t.b)) << es;
        EXPECT_EQ(genmesh::can_collapse_edge(es, t.a), genmesh::can_collapse_edge(es, t.b)) << es;
        EXPECT_EQ(genmesh::can_flip_edge(es.halfedge(), t.a), genmesh::can_flip_edge(es.halfedge(), t.b)) << es;
      }
    Twin tet(genmesh::make_tetrahedron());
    EXPECT_FALSE(tet.apply(OP(genmesh::collapse_edge(Edge_index(0), g, rec)), "collapse tet"));
    EXPECT_FALSE(genmesh::does_satisfy_link_condition(Edge_index(0), tet.a));
    // Border collapses (one face) on a triangulated grid.
    genmesh::Polygon_soup grid = genmesh::make_grid(3, 3);
    Hm tmp;
    genmesh::build_mesh(grid, tmp);
    genmesh::triangulate_faces(tmp);
    Twin g3(genmesh::to_soup(tmp));
    for (Edge_index e : edges(g3.b)) {
      g3.apply(OP(genmesh::collapse_edge(Edge_index(e.idx()), g, rec)), "collapse grid");
      if (!g3.b.is_valid(Edge_index(e.idx() + 1))) break;
    }
    g3.expect_valid("collapse grid");
    expect_same_edges(g3);
  }
  {
    SCOPED_TRACE("split_face, join_face, erase_edge");
    Twin t(genmesh::make_cube());
    const Halfedge_index h1 = t.b.halfedge(Face_index(0));
    const Halfedge_index h2 = t.b.next(t.b.next(h1));
    EXPECT_TRUE(t.apply(OP(genmesh::split_face(h1, h2, g, rec)), "split_face"));
    EXPECT_EQ(num_faces(t.a), 7u);
    EXPECT_FALSE(t.apply(OP(genmesh::split_face(h1, t.b.next(h1), g, rec)), "consecutive"));
    EXPECT_FALSE(t.apply(OP(genmesh::split_face(h1, h1, g, rec)), "same"));
    const Halfedge_index diag = t.b.next(h1);
    EXPECT_TRUE(t.apply(OP(genmesh::join_face(diag, g, rec)), "join_face"));
    EXPECT_EQ(num_faces(t.a), 6u);
    EXPECT_TRUE(t.apply(OP(genmesh::erase_edge(Edge_index(0), g, rec)), "erase_edge"));
    t.expect_valid("join");
    // Joining a face into a hole it touches at another vertex too would make
    // a face through that vertex twice (a row of d1 cannot hold it): both
    // backends refuse (local_operations.h's contract) and keep the mesh.
    Twin grid(genmesh::make_grid(2, 1)); // four triangles
    EXPECT_FALSE(genmesh::can_join_face(Halfedge_index(0), grid.b));
    EXPECT_FALSE(genmesh::can_join_face(Halfedge_index(0), grid.a));
    EXPECT_FALSE(grid.apply(OP(genmesh::join_face(Halfedge_index(0), g, rec)), "join into a hole"));
  }
  {
    SCOPED_TRACE("add/remove_center_vertex, erase_vertex");
    Twin t(genmesh::make_cube());
    EXPECT_TRUE(t.apply(OP(genmesh::add_center_vertex(Halfedge_index(0), g, rec)), "add_center"));
    EXPECT_EQ(num_faces(t.a), 9u);
    const Halfedge_index in_c = t.b.next(Halfedge_index(0)); // targets the centre
    EXPECT_TRUE(t.apply(OP(genmesh::remove_center_vertex(in_c, g, rec)), "remove_center"));
    EXPECT_EQ(num_faces(t.a), 6u);
    Twin tet(genmesh::make_tetrahedron());
    EXPECT_FALSE(tet.apply(OP(genmesh::remove_center_vertex(Halfedge_index(0), g, rec)), "tet"));
    Twin s(genmesh::make_icosphere(1));
    s.align(Vertex_index(3));
    EXPECT_TRUE(s.apply(OP(genmesh::erase_vertex(Vertex_index(3), g, rec)), "erase_vertex"));
    s.expect_valid("erase_vertex");
    Twin grid(genmesh::make_grid(2, 2));
    EXPECT_FALSE(grid.apply(OP(genmesh::erase_vertex(Vertex_index(0), g, rec)), "border vertex"));
    EXPECT_FALSE(grid.apply(OP(genmesh::add_center_vertex(grid.b.opposite(Halfedge_index(0)), g, rec)), "hole"));
  }
  {
    SCOPED_TRACE("euler::add_face, euler::remove_face");
    //  6---7---8
    //  | / | / |    make_grid(2, 2): faces 0 (0 1 4), 1 (0 4 3), 2 (1 2 5), 3 (1 5 4), ...
    //  3---4---5
    //  | / | / |
    //  0---1---2
    Twin t(genmesh::make_grid(2, 2));
    // Face 3 touches the border at vertex 1 only through inner sides: removing
    // it would pinch vertex 1 (two border gaps). Both backends refuse.
    EXPECT_FALSE(genmesh::euler::can_remove_face(t.b.halfedge(Face_index(3)), t.b));
    EXPECT_FALSE(t.apply(OP(genmesh::euler::remove_face(t.b.halfedge(Face_index(3)), g, rec)), "pinch"));
    EXPECT_TRUE(t.apply(OP(genmesh::euler::remove_face(t.b.halfedge(Face_index(0)), g, rec)), "remove corner face"));
    EXPECT_TRUE(t.apply(OP(genmesh::euler::remove_face(t.b.halfedge(Face_index(2)), g, rec)), "remove other corner"));
    EXPECT_EQ(num_faces(t.a), 6u);
    EXPECT_FALSE(t.apply(OP(genmesh::euler::remove_face(t.b.opposite(Halfedge_index(0)), g, rec)), "border"));
    t.expect_valid("remove");
    const std::vector<Vertex_index> tri{Vertex_index(0), Vertex_index(1), Vertex_index(4)};
    EXPECT_TRUE(genmesh::euler::can_add_face(tri, t.a));
    EXPECT_TRUE(t.apply(OP(genmesh::euler::add_face(tri, g, rec)), "add back"));
    const std::vector<Vertex_index> dup{Vertex_index(0), Vertex_index(4), Vertex_index(3)};
    EXPECT_FALSE(t.apply(OP(genmesh::euler::add_face(dup, g, rec)), "existing face"));
    const std::vector<Vertex_index> two{Vertex_index(0), Vertex_index(4)};
    EXPECT_FALSE(t.apply(OP(genmesh::euler::add_face(two, g, rec)), "two corners"));
    t.expect_valid("add");
    // From nothing: isolated vertices, then faces.
    Inc a;
    Hm b;
    for (int i = 0; i < 4; ++i) {
      a.add_vertex(Eigen::Vector3d(i, i * i, 0));
      b.add_vertex(Eigen::Vector3d(i, i * i, 0));
    }
    const std::vector<Vertex_index> f0{Vertex_index(0), Vertex_index(1), Vertex_index(2)};
    const std::vector<Vertex_index> f1{Vertex_index(0), Vertex_index(2), Vertex_index(3)};
    EXPECT_EQ(genmesh::euler::add_face(f0, a), genmesh::euler::add_face(f0, b));
    EXPECT_EQ(genmesh::euler::add_face(f1, a), genmesh::euler::add_face(f1, b));
    EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(b));
    EXPECT_TRUE(genmesh::check_mesh(a).ok());
  }
  {
    SCOPED_TRACE("triangulate_face(s), bevel_face, bevel_vertex");
    Twin t(genmesh::make_torus(6, 5, false));
    EXPECT_TRUE(t.apply(OP(genmesh::triangulate_face(Face_index(0), g, rec) ? std::optional<int>(1) : std::nullopt), "tri"));
    EXPECT_TRUE(t.apply(OP(std::optional<std::size_t>(genmesh::triangulate_faces(g, rec))), "tri all"));
    EXPECT_TRUE(genmesh::check_mesh(t.a).is_triangle_mesh);
    Twin c(genmesh::make_cube());
    c.align(Face_index(1));
    EXPECT_TRUE(c.apply(OP(genmesh::bevel_face(Face_index(1), g, rec)), "bevel_face"));
    EXPECT_EQ(num_faces(c.a), 10u);
    c.align(Vertex_index(2));
    EXPECT_TRUE(c.apply(OP(genmesh::bevel_vertex(Vertex_index(2), g, rec)), "bevel_vertex"));
    c.expect_valid("bevel");
    // bevel_edge: a quad (both ends split) on a closed mesh, a triangle at a border corner.
    Twin s(genmesh::make_icosphere(1));
    EXPECT_TRUE(s.apply(OP(genmesh::bevel_edge(Halfedge_index(4), g, {}, rec)), "bevel_edge"));
    EXPECT_EQ(num_faces(s.a), 81u);
    EXPECT_EQ(num_vertices(s.a), 44u);
    EXPECT_EQ(s.a.degree(face(Halfedge_index(5), s.a)), 4u); // the new face Q holds opposite(h)
    s.expect_valid("bevel_edge");
    EXPECT_THROW(genmesh::bevel_edge(Halfedge_index(8), s.a, {.fraction = 1.0}), genmesh::invalid_input);
    Twin grid(genmesh::make_grid(2, 2));
    EXPECT_FALSE(grid.apply(OP(genmesh::bevel_vertex(Vertex_index(0), g, rec)), "border vertex"));
    EXPECT_TRUE(grid.apply(OP(genmesh::bevel_edge(Halfedge_index(0), g, {}, rec)), "bevel border edge"));
    grid.expect_valid("bevel border edge");
    EXPECT_FALSE(grid.apply(OP(genmesh::bevel_face(Face_index(), g, rec)), "null face"));
    expect_same_edges(c);
  }
}

// Picks a live element index at random (the next live one from a random start).
template <class Index>
Index pick(std::mt19937& rng, std::size_t bound, const Inc& m) {
  std::uniform_int_distribution<std::size_t> d(0, bound - 1);
  std::size_t i = d(rng);
  for (std::size_t k = 0; k < bound; ++k, i = (i + 1) % bound)
    if (!m.is_removed(Index(static_cast<std::uint32_t>(i)))) return Index(static_cast<std::uint32_t>(i));
  return Index();
}

// The native join/erase/remove-centre predicates are stricter than the
// generic ones exactly where the generic operation would make a face through
// a vertex twice (documented); such steps are skipped on both meshes.
bool stricter(bool native, bool generic) {
  EXPECT_FALSE(native && !generic) << "a native predicate accepts what the generic one refuses";
  return !native && generic;
}

// Runs up to `steps` random operations on both meshes of t, comparing them
// after each; returns how many applied.
std::size_t random_steps(Twin& t, std::mt19937& rng, int steps) {
  std::uniform_int_distribution<int> op(0, 99);
  std::size_t applied = 0;
  for (int step = 0; step < steps && !::testing::Test::HasFailure(); ++step) {
    if (num_faces(t.a) < 8) break;
    const Edge_index e = pick<Edge_index>(rng, t.a.edges_size(), t.a);
    const Halfedge_index h = t.a.halfedge(e, static_cast<unsigned>(rng() & 1u));
    const int k = op(rng);
    bool ok = false;
    if (k < 25) {
      ok = t.apply(OP(genmesh::flip_edge(h, g, rec)), "flip");
    } else if (k < 30) {
      ok = t.apply(OP(genmesh::unflip_edge(h, g, rec)), "unflip");
    } else if (k < 50) {
      ok = t.apply(OP(genmesh::split_edge_and_triangulate(h, g, rec)), "split_edge_and_triangulate");
    } else if (k < 75) {
      if (stricter(genmesh::can_collapse_edge(Edge_index(h), t.a), genmesh::can_collapse_edge(Edge_index(h), t.b)))
        continue;
      ok = t.apply(OP(genmesh::collapse_edge(Edge_index(h), g, rec)), "collapse");
    } else if (k < 78) {
      ok = t.apply(OP(genmesh::split_edge(h, g, rec)), "split_edge");
    } else if (k < 81) {
      ok = t.apply(OP(genmesh::add_center_vertex(h, g, rec)), "add_center_vertex");
    } else if (k < 84) {
      if (stricter(genmesh::can_remove_center_vertex(h, t.a), genmesh::can_remove_center_vertex(h, t.b))) continue;
      ok = t.apply(OP(genmesh::remove_center_vertex(h, g, rec)), "remove_center_vertex");
    } else if (k < 86) {
      if (stricter(genmesh::can_join_face(h, t.a), genmesh::can_join_face(h, t.b))) continue;
      ok = t.apply(OP(genmesh::join_face(h, g, rec)), "join_face");
    } else if (k < 88) {
      if (stricter(genmesh::can_erase_edge(Edge_index(h), t.a), genmesh::can_erase_edge(Edge_index(h), t.b))) continue;
      ok = t.apply(OP(genmesh::erase_edge(Edge_index(h), g, rec)), "erase_edge");
    } else if (k < 90) {
      const Vertex_index v = t.a.target(h);
      t.align(v);
      if (stricter(genmesh::can_erase_vertex(v, t.a), genmesh::can_erase_vertex(v, t.b))) continue;
      ok = t.apply(OP(genmesh::erase_vertex(v, g, rec)), "erase_vertex");
    } else if (k < 92) {
      // A face with four sides or more, if one turns up in a few tries.
      Face_index f;
      for (int tries = 0; tries < 20 && !f.is_valid(); ++tries) {
        const Face_index c = pick<Face_index>(rng, t.a.faces_size(), t.a);
        if (c.is_valid() && t.a.degree(c) >= 4) f = c;
      }
      if (f.is_valid()) {
        const Halfedge_index h1 = t.a.halfedge(f), h2 = t.a.next(t.a.next(h1));
        ok = t.apply(OP(genmesh::split_face(h1, h2, g, rec)), "split_face");
      }
    } else if (k < 94) {
      // Remove a face and put it back.
      if (!t.a.is_border(h)) {
        std::vector<Vertex_index> corners;
        for (Halfedge_index x : detail_cycle(h, t.a)) corners.push_back(t.a.target(x));
        if (stricter(genmesh::euler::can_remove_face(h, t.a), genmesh::euler::can_remove_face(h, t.b))) continue;
        ok = t.apply(OP(genmesh::euler::remove_face(h, g, rec) ? std::optional<int>(1) : std::nullopt), "remove_face");
        // remove_face may free a corner left without edges: re-add only a live cycle.
        const bool live = std::ranges::all_of(corners, [&](Vertex_index v) { return t.a.is_valid(v); });
        if (ok && live) {
          EXPECT_TRUE(t.apply(OP(genmesh::euler::add_face(corners, g, rec)), "add_face"));
        }
      }
    } else if (k < 96) {
      const Face_index f = pick<Face_index>(rng, t.a.faces_size(), t.a);
      t.align(f);
      ok = t.apply(OP(genmesh::bevel_face(f, g, rec)), "bevel_face");
    } else if (k < 97) {
      const Vertex_index v = t.a.source(h);
      t.align(v);
      ok = t.apply(OP(genmesh::bevel_vertex(v, g, rec)), "bevel_vertex");
    } else if (k < 98) {
      ok = t.apply(OP(genmesh::bevel_edge(h, g, {.fraction = 0.2}, rec)), "bevel_edge");
    } else {
      ok = t.apply(OP(std::optional<std::size_t>(genmesh::triangulate_faces(g, rec))), "triangulate_faces");
    }
    applied += ok ? 1 : 0;
    if (step % 10 == 0 || (ok && k >= 78)) t.expect_valid(("random step " + std::to_string(k)).c_str());
    if (step % 500 == 0) expect_same_edges(t);
  }
  t.expect_valid("end");
  expect_same_edges(t);
  return applied;
}

void random_sequence(const genmesh::Polygon_soup& soup, unsigned seed, int steps,
                     std::map<std::string, int>& counts) {
  Twin t(soup);
  t.counts = &counts;
  std::mt19937 rng(seed);
  EXPECT_GT(random_steps(t, rng, steps), static_cast<std::size_t>(steps) / 4);
}

TEST(IncidenceOperations, RandomSequencesEqualHalfedgeMesh) {
  std::map<std::string, int> counts;
  random_sequence(genmesh::make_icosphere(2), 1, 3000, counts);
  random_sequence(genmesh::read_soup(genmesh_test::real_mesh("elephant-with-holes.off")), 2, 800, counts);
  Hm tmp;
  genmesh::build_mesh(genmesh::make_grid_with_hole(9), tmp);
  genmesh::triangulate_faces(tmp);
  random_sequence(genmesh::to_soup(tmp), 3, 2000, counts);
  // Every operation was exercised (and compared) many times.
  for (const char* op : {"flip", "split_edge_and_triangulate", "collapse", "split_edge", "add_center_vertex",
                         "remove_center_vertex", "join_face", "erase_edge", "erase_vertex", "split_face",
                         "remove_face", "add_face", "bevel_face", "bevel_vertex", "bevel_edge", "unflip",
                         "triangulate_faces"})
    EXPECT_GE(counts[op], 20) << op;
  EXPECT_GE(counts["flip"] + counts["collapse"] + counts["split_edge_and_triangulate"], 1500);
  std::string summary;
  for (const auto& [op, n] : counts) summary += op + " " + std::to_string(n) + ", ";
  RecordProperty("operations", summary);
}

// ---- collect_garbage ---------------------------------------------------------

// The maps of one element kind: as long as the old bound, removed elements to
// null, the live ones onto [0, live count) one to one.
template <class Index>
void expect_compaction(const std::vector<Index>& map, std::size_t old_bound, std::size_t live,
                       const auto& is_removed_before) {
  ASSERT_EQ(map.size(), old_bound);
  std::vector<char> hit(live, 0);
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (is_removed_before(i)) {
      EXPECT_FALSE(map[i].is_valid()) << i;
      continue;
    }
    ASSERT_TRUE(map[i].is_valid()) << i;
    ASSERT_LT(map[i].idx(), live) << i;
    EXPECT_FALSE(hit[map[i].idx()]) << i;
    hit[map[i].idx()] = 1;
  }
}

// now = old after collect_garbage with maps m: every live element of old is
// in now under its new index with the same incidences (matrix entries with
// the same signs), points and, on a manifold mesh, the same next/prev/face.
void expect_renumbered(const Inc& old, const Inc& now, const genmesh::Garbage_collection_maps& m) {
  ASSERT_EQ(now.vertices_size(), num_vertices(old));
  ASSERT_EQ(now.edges_size(), num_edges(old));
  ASSERT_EQ(now.faces_size(), num_faces(old));
  EXPECT_EQ(num_vertices(now), now.vertices_size());
  EXPECT_EQ(num_edges(now), now.edges_size());
  EXPECT_EQ(num_faces(now), now.faces_size());
  EXPECT_FALSE(now.has_garbage());
  expect_compaction(m.vertices, old.vertices_size(), num_vertices(old),
                    [&](std::size_t i) { return old.is_removed(Vertex_index(static_cast<std::uint32_t>(i))); });
  expect_compaction(m.edges, old.edges_size(), num_edges(old),
                    [&](std::size_t i) { return old.is_removed(Edge_index(static_cast<std::uint32_t>(i))); });
  expect_compaction(m.faces, old.faces_size(), num_faces(old),
                    [&](std::size_t i) { return old.is_removed(Face_index(static_cast<std::uint32_t>(i))); });
  ASSERT_EQ(m.halfedges.size(), old.halfedges_size());
  auto mv = [&](Vertex_index v) { return v.is_valid() ? m.vertices[v.idx()] : v; };
  auto mf = [&](Face_index f) { return f.is_valid() ? m.faces[f.idx()] : f; };
  for (Vertex_index v : vertices(old)) {
    ASSERT_EQ(now.point(mv(v)), old.point(v)) << v;
    ASSERT_EQ(now.degree(mv(v)), old.degree(v)) << v;
  }
  for (Edge_index e : edges(old)) {
    const Edge_index ne = m.edges[e.idx()];
    for (unsigned s : {0u, 1u}) {
      const Halfedge_index h = old.halfedge(e, s);
      ASSERT_EQ(m.halfedges[h.idx()], now.halfedge(ne, s)) << h; // directions kept
    }
    const auto& r = old.d0_rows();
    ASSERT_EQ(now.d0_rows().size(ne.idx()), r.size(e.idx())) << e;
    for (int k = 0; k < r.size(e.idx()); ++k)
      ASSERT_EQ(now.d0_rows().at(ne.idx(), static_cast<int>(mv(Vertex_index(static_cast<std::uint32_t>(r.cols(e.idx())[k]))).idx())),
                r.vals(e.idx())[k]) << e;
  }
  for (Face_index f : faces(old)) {
    const Face_index nf = mf(f);
    const auto& r = old.d1_rows();
    ASSERT_EQ(now.d1_rows().size(nf.idx()), r.size(f.idx())) << f;
    for (int k = 0; k < r.size(f.idx()); ++k)
      ASSERT_EQ(now.d1_rows().at(nf.idx(), static_cast<int>(m.edges[static_cast<std::size_t>(r.cols(f.idx())[k])].idx())),
                r.vals(f.idx())[k]) << f;
    std::vector<Vertex_index> a, b = now.face_vertices(nf);
    for (Vertex_index v : old.face_vertices(f)) a.push_back(mv(v));
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    std::rotate(b.begin(), std::min_element(b.begin(), b.end()), b.end());
    ASSERT_EQ(a, b) << f;
  }
  // The transposes were rebuilt too: d0ᵀ and d1ᵀ rows are those of d0 and d1.
  auto same = [](Eigen::SparseMatrix<int> x, const Eigen::SparseMatrix<int>& y) {
    x -= y;
    x.prune([](Eigen::Index, Eigen::Index, int v) { return v != 0; });
    return x.nonZeros() == 0;
  };
  const Eigen::SparseMatrix<int> d0 = now.d0(), d1 = now.d1();
  EXPECT_TRUE(same(Eigen::SparseMatrix<int>(now.d0t_rows().compressed(now.vertices_size(), now.edges_size())),
                   Eigen::SparseMatrix<int>(d0.transpose())));
  EXPECT_TRUE(same(Eigen::SparseMatrix<int>(now.d1t_rows().compressed(now.edges_size(), now.faces_size())),
                   Eigen::SparseMatrix<int>(d1.transpose())));
  EXPECT_EQ(now.is_manifold(), old.is_manifold());
  if (!old.is_manifold()) return;
  for (Halfedge_index h : halfedges(old)) {
    const Halfedge_index nh = m.halfedges[h.idx()];
    ASSERT_EQ(now.target(nh), mv(old.target(h))) << h;
    ASSERT_EQ(now.face(nh), mf(old.face(h))) << h;
    ASSERT_EQ(now.next(nh), m.halfedges[old.next(h).idx()]) << h;
    ASSERT_EQ(now.prev(nh), m.halfedges[old.prev(h).idx()]) << h;
  }
}

void expect_identity(const genmesh::Garbage_collection_maps& m, const Inc& g) {
  ASSERT_EQ(m.vertices.size(), g.vertices_size());
  ASSERT_EQ(m.halfedges.size(), g.halfedges_size());
  ASSERT_EQ(m.edges.size(), g.edges_size());
  ASSERT_EQ(m.faces.size(), g.faces_size());
  for (std::uint32_t i = 0; i < m.vertices.size(); ++i) ASSERT_EQ(m.vertices[i], Vertex_index(i));
  for (std::uint32_t i = 0; i < m.halfedges.size(); ++i) ASSERT_EQ(m.halfedges[i], Halfedge_index(i));
  for (std::uint32_t i = 0; i < m.edges.size(); ++i) ASSERT_EQ(m.edges[i], Edge_index(i));
  for (std::uint32_t i = 0; i < m.faces.size(); ++i) ASSERT_EQ(m.faces[i], Face_index(i));
}

// Collects a copy of t's meshes with `order`: the same maps and the same mesh
// on both backends, each survivor renumbered with its incidences, a valid
// compact result, identity on a second call. Returns the maps.
genmesh::Garbage_collection_maps collect_both(const Twin& t, genmesh::Garbage_order order) {
  Inc a = t.a;
  Hm b = t.b;
  const std::size_t bytes_before = t.a.memory_bytes();
  const auto ma = a.collect_garbage(order);
  const auto mb = genmesh::collect_garbage(b, order);
  EXPECT_EQ(ma.vertices, mb.vertices);
  EXPECT_EQ(ma.halfedges, mb.halfedges);
  EXPECT_EQ(ma.edges, mb.edges);
  EXPECT_EQ(ma.faces, mb.faces);
  EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(b));
  if (order == genmesh::Garbage_order::stable) {
    EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(t.a)); // relative order kept
  }
  expect_same_traversal(a, b, false);
  expect_renumbered(t.a, a, ma);
  const auto r = genmesh::check_mesh(a);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
  const Algebra_facts alg = algebra_facts(a);
  EXPECT_TRUE(alg.boundary_of_boundary_vanishes);
  EXPECT_TRUE(alg.laplacian);
  EXPECT_LE(a.memory_bytes(), bytes_before);
  expect_identity(a.collect_garbage(order), a);
  return ma;
}

TEST(IncidenceGarbage, RandomSequencesThenCollectEqualHalfedgeMesh) {
  Hm grid;
  genmesh::build_mesh(genmesh::make_grid_with_hole(9), grid);
  genmesh::triangulate_faces(grid);
  const std::vector<std::pair<genmesh::Polygon_soup, unsigned>> cases{{genmesh::make_icosphere(2), 11u},
                                                                      {genmesh::to_soup(grid), 12u}};
  for (const auto& [soup, seed] : cases) {
    SCOPED_TRACE(seed);
    Twin t(soup);
    std::mt19937 rng(seed);
    EXPECT_GT(random_steps(t, rng, 400), 100u);
    // End on a few collapses and a face removal, so that garbage of every
    // kind is left unrecycled.
    int collapsed = 0;
    for (std::uint32_t i = 0; i < t.a.edges_size() && collapsed < 3; i += 7)
      if (t.a.is_valid(Edge_index(i)) && t.apply(OP(genmesh::collapse_edge(Edge_index(i), g, rec)), "collapse"))
        ++collapsed;
    for (std::uint32_t i = 0; i < t.a.halfedges_size(); i += 5) {
      const Halfedge_index h(i);
      if (t.a.is_valid(h) && !t.a.is_border(h) && genmesh::euler::can_remove_face(h, t.a) &&
          t.apply(OP(genmesh::euler::remove_face(h, g, rec) ? std::optional<int>(1) : std::nullopt), "remove_face"))
        break;
    }
    // Garbage in every kind, not all of it recycled.
    ASSERT_TRUE(t.a.has_garbage());
    ASSERT_LT(num_vertices(t.a), t.a.vertices_size());
    ASSERT_LT(num_edges(t.a), t.a.edges_size());
    ASSERT_LT(num_faces(t.a), t.a.faces_size());
    const auto stable = collect_both(t, genmesh::Garbage_order::stable);
    const auto like_sm = collect_both(t, genmesh::Garbage_order::like_surface_mesh);
    EXPECT_NE(stable.vertices, like_sm.vertices); // the two orders really differ
    EXPECT_NE(stable.faces, like_sm.faces);
  }
}

TEST(IncidenceGarbage, OperationsKeepWorkingAfterCollection) {
  for (const auto order : {genmesh::Garbage_order::stable, genmesh::Garbage_order::like_surface_mesh}) {
    Twin t(genmesh::make_icosphere(2));
    std::mt19937 rng(21);
    random_steps(t, rng, 300);
    for (int round = 0; round < 3; ++round) {
      SCOPED_TRACE(round);
      ASSERT_TRUE(t.a.has_garbage());
      const auto ma = t.a.collect_garbage(order);
      const auto mb = t.b.collect_garbage(order);
      ASSERT_EQ(ma.halfedges, mb.halfedges);
      ASSERT_EQ(t.a.vertices_size(), num_vertices(t.a));
      expect_same_edges(t);
      EXPECT_EQ(genmesh::to_soup(t.a), genmesh::to_soup(t.b));
      // New elements are appended (the free lists are empty) on both.
      const std::size_t ne = t.a.edges_size();
      EXPECT_GT(random_steps(t, rng, 300), 75u); // compares both meshes at every step
      EXPECT_GT(t.a.edges_size(), ne);
      EXPECT_EQ(genmesh::to_soup(t.a), genmesh::to_soup(t.b));
    }
  }
}

// A fin and a bow-tie, plus faces that are removed (with their edges and
// vertices) before collecting: the fin, the bow-tie and everything else
// survive, renumbered.
//   faces 0..2: the fin on edge 0-1 (fin_soup); 3, 4: a bow-tie at vertex 5;
//   5: 1 2 10 (next to face 1), 6: 11 12 13 (apart), 7: 3 1 14 (next to face 0)
TEST(IncidenceGarbage, NonManifoldMeshKeepsItsReport) {
  genmesh::Polygon_soup s = fin_soup();
  for (int i = 5; i < 15; ++i) s.add_point(i, i % 3, i % 5);
  s.add_face({5, 6, 7});
  s.add_face({5, 8, 9});
  s.add_face({1, 2, 10});
  s.add_face({11, 12, 13});
  s.add_face({3, 1, 14});
  for (const auto order : {genmesh::Garbage_order::stable, genmesh::Garbage_order::like_surface_mesh}) {
    Inc m = Inc::from_soup(s);
    // Remove faces 5 and 6 with the edges and vertices only they used.
    for (Face_index f : {Face_index(5), Face_index(6)}) {
      const std::vector<Vertex_index> corners = m.face_vertices(f);
      std::vector<Edge_index> sides;
      for (int k = 0; k < m.d1_rows().size(f.idx()); ++k)
        sides.emplace_back(static_cast<std::uint32_t>(m.d1_rows().cols(f.idx())[k]));
      m.remove_face(f);
      for (Edge_index e : sides)
        if (m.d1t_rows().size(e.idx()) == 0) m.remove_edge(e);
      for (Vertex_index v : corners)
        if (m.is_isolated(v)) m.remove_vertex(v);
    }
    ASSERT_EQ(num_faces(m), 6u);
    ASSERT_EQ(num_vertices(m), 11u); // 10, 11, 12, 13 removed
    const Inc old = m;
    const auto r0 = old.manifold_report();
    ASSERT_EQ(r0.fin_edges.size(), 1u);
    ASSERT_EQ(r0.non_manifold_vertices.size(), 1u);
    const genmesh::Polygon_soup soup0 = old.polygon_soup();

    const auto maps = collect_garbage(m, order);
    expect_renumbered(old, m, maps);
    const auto r = m.manifold_report();
    auto mapped = [](auto list, const auto& map) {
      for (auto& x : list) x = map[x.idx()];
      std::sort(list.begin(), list.end());
      return list;
    };
    EXPECT_EQ(r.fin_edges, mapped(r0.fin_edges, maps.edges));
    EXPECT_EQ(r.misoriented_edges, mapped(r0.misoriented_edges, maps.edges));
    EXPECT_EQ(r.non_manifold_vertices, mapped(r0.non_manifold_vertices, maps.vertices));
    EXPECT_FALSE(m.is_manifold());
    // Queries on the renumbered bad elements still refuse; the rest work.
    EXPECT_THROW((void)m.face(m.halfedge(r.fin_edges[0])), genmesh::invalid_input);
    EXPECT_THROW((void)m.halfedge(r.non_manifold_vertices[0]), genmesh::invalid_input);
    const Halfedge_index from14 = m.halfedge(maps.vertices[1], maps.vertices[14]);
    ASSERT_TRUE(from14.is_valid());
    EXPECT_EQ(m.face(from14), maps.faces[7]);
    EXPECT_TRUE(m.is_border(m.opposite(from14)));
    if (order == genmesh::Garbage_order::stable) {
      EXPECT_EQ(m.polygon_soup(), soup0);
    } else {
      EXPECT_EQ(maps.vertices[14], Vertex_index(10)); // the last vertex fills the first hole
    }
    EXPECT_TRUE(algebra_facts(m).boundary_of_boundary_vanishes);
    expect_identity(m.collect_garbage(order), m);
  }
}

TEST(IncidenceGarbage, NoGarbageGivesIdentityAndKeepsTheMesh) {
  Inc a;
  genmesh::build_mesh(genmesh::make_torus(6, 5, true), a);
  const Inc before = a;
  ASSERT_FALSE(a.has_garbage());
  expect_identity(a.collect_garbage(), a);
  expect_identity(a.collect_garbage(genmesh::Garbage_order::like_surface_mesh), a);
  EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(before));
  EXPECT_EQ(a.d1_rows().compressed(a.faces_size(), a.edges_size()).toDense(),
            before.d1_rows().compressed(before.faces_size(), before.edges_size()).toDense());
  EXPECT_EQ(a.d0_rows().compressed(a.edges_size(), a.vertices_size()).toDense(),
            before.d0_rows().compressed(before.edges_size(), before.vertices_size()).toDense());
  // Garbage that was all recycled: identity maps too, and has_garbage() is
  // cleared as on Halfedge_mesh.
  Twin t(genmesh::make_grid(2, 2));
  ASSERT_TRUE(t.apply(OP(genmesh::euler::remove_face(t.b.halfedge(Face_index(0)), g, rec) ? std::optional<int>(1) : std::nullopt), "remove"));
  const std::vector<Vertex_index> tri{Vertex_index(0), Vertex_index(1), Vertex_index(4)};
  ASSERT_TRUE(t.apply(OP(genmesh::euler::add_face(tri, g, rec)), "add back"));
  ASSERT_TRUE(t.a.has_garbage());
  ASSERT_EQ(t.a.faces_size(), num_faces(t.a));
  const genmesh::Polygon_soup soup = genmesh::to_soup(t.a);
  const auto ma = t.a.collect_garbage();
  expect_identity(ma, t.a);
  EXPECT_EQ(ma.halfedges, t.b.collect_garbage().halfedges);
  EXPECT_FALSE(t.a.has_garbage());
  EXPECT_FALSE(t.b.has_garbage());
  EXPECT_EQ(genmesh::to_soup(t.a), soup);
  expect_same_edges(t);
  // A live edge without ends is refused, leaving the mesh as it was.
  Inc c;
  genmesh::build_mesh(genmesh::make_cube(), c);
  c.remove_face(Face_index(0));
  const Edge_index loose = c.add_edge();
  const genmesh::Polygon_soup cube_soup = c.polygon_soup();
  EXPECT_THROW(c.collect_garbage(), genmesh::invalid_input);
  EXPECT_EQ(c.polygon_soup(), cube_soup);
  EXPECT_TRUE(c.has_garbage());
  EXPECT_EQ(c.faces_size(), 6u);
  c.set_edge_vertices(loose, Vertex_index(0), Vertex_index(6));
  const auto mc = c.collect_garbage();
  EXPECT_EQ(c.faces_size(), 5u);
  EXPECT_EQ(c.target(c.halfedge(mc.edges[loose.idx()], 0)), mc.vertices[6]);
}

// The example of docs/incidence_mesh.md ("collect_garbage").
TEST(IncidenceGarbage, DocumentationExample) {
  genmesh::Incidence_mesh<> m;
  genmesh::build_mesh(genmesh::make_icosphere(2), m);
  const std::size_t nv = num_vertices(m), ne = num_edges(m), nf = num_faces(m);
  ASSERT_TRUE(genmesh::collapse_edge(genmesh::Edge_index(7), m).has_value());
  EXPECT_EQ(num_vertices(m), nv - 1);
  EXPECT_EQ(num_edges(m), ne - 3);
  EXPECT_EQ(num_faces(m), nf - 2);
  const genmesh::Garbage_collection_maps maps = m.collect_garbage();
  EXPECT_TRUE(m.vertices_size() == num_vertices(m) && !m.has_garbage());
  EXPECT_TRUE(maps.vertices[100].is_valid());
  EXPECT_EQ(m.edges_size(), ne - 3);
}

} // namespace
