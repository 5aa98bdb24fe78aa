// tests/test_local_operations.cpp — flip and its inverse unflip, split,
// collapse, split/join face, center vertex, add/remove face, triangulation,
// erase, bevel of a vertex, an edge and a face: golden cases with diagrams
// (every refusal leaves the mesh untouched, array for array), equality with
// CGAL::Euler element for element, the refusals that keep faces simple and
// vertices unpinched (where CGAL::Euler is looser), and seeded random stress
// tests on generated and real meshes, compared across backends (face-level
// steps too, against Incidence_mesh's native operations).
#include "backends.h"

#include <genmesh/generators.h>
#include <genmesh/io.h>
#include <genmesh/local_operations.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using genmesh::Polygon_soup;

template <class G>
using V = genmesh::vertex_descriptor_t<G>;
template <class G>
using H = genmesh::halfedge_descriptor_t<G>;
template <class G>
using E = genmesh::edge_descriptor_t<G>;
template <class G>
using F = genmesh::face_descriptor_t<G>;

template <class G>
G make(const Polygon_soup& soup) {
  G g;
  genmesh::build_mesh(soup, g);
  return g;
}

Polygon_soup soup_of(std::vector<Eigen::Vector3d> pts, std::vector<std::vector<std::uint32_t>> faces) {
  Polygon_soup s;
  for (const auto& p : pts) s.add_point(p);
  for (const auto& f : faces) s.add_face(f);
  return s;
}

template <class G>
V<G> vtx(std::size_t i) {
  return V<G>(static_cast<std::uint32_t>(i));
}

/// The halfedge u → v (vertices by index); fails the test if missing.
template <class G>
H<G> he(const G& g, std::size_t u, std::size_t v) {
  const H<G> h = genmesh::detail::lo::find_halfedge(vtx<G>(u), vtx<G>(v), g);
  EXPECT_NE(h, boost::graph_traits<G>::null_halfedge()) << u << " -> " << v;
  return h;
}

/// Every connectivity array of g, removed elements and free-list links
/// included: next, prev, target, face per halfedge; halfedge per vertex and
/// face; removed bits.
template <class G>
std::vector<std::size_t> snapshot(const G& g) {
  std::vector<std::size_t> s;
  const std::size_t nv = genmesh::index_bound(genmesh::vertex_index, g);
  const std::size_t nh = genmesh::index_bound(genmesh::halfedge_index, g);
  const std::size_t nf = genmesh::index_bound(genmesh::face_index, g);
  s.push_back(nv);
  s.push_back(nh);
  s.push_back(nf);
  for (std::size_t i = 0; i < nh; ++i) {
    const H<G> h(static_cast<std::uint32_t>(i));
    s.push_back(g.is_removed(h));
    // A removed halfedge of the incidence mesh has no entries left to read.
    if constexpr (!genmesh::MutableFaceGraph<G>)
      if (g.is_removed(h)) continue;
    s.push_back(std::size_t(next(h, g)));
    s.push_back(std::size_t(target(h, g)));
    s.push_back(std::size_t(face(h, g)));
    if (!g.is_removed(h)) s.push_back(std::size_t(prev(h, g)));
  }
  for (std::size_t i = 0; i < nv; ++i) {
    const V<G> v(static_cast<std::uint32_t>(i));
    s.push_back(g.is_removed(v));
    s.push_back(std::size_t(halfedge(v, g)));
  }
  for (std::size_t i = 0; i < nf; ++i) {
    const F<G> f(static_cast<std::uint32_t>(i));
    s.push_back(g.is_removed(f));
    s.push_back(std::size_t(halfedge(f, g)));
  }
  return s;
}

template <class G>
Polygon_soup canon(const G& g) {
  return genmesh::canonical(genmesh::to_soup(g));
}

template <class G>
void expect_ok(const G& g) {
  const auto r = genmesh::check_mesh(g);
  EXPECT_TRUE(r.ok()) << genmesh::to_string(r);
}

template <class G>
std::size_t live_vertices(const G& g) {
  return genmesh::check_mesh(g).vertices;
}

// Asserts that op() refuses and leaves g exactly as it was.
template <class G, class Op>
void expect_refused(G& g, Op op) {
  const auto before = snapshot(g);
  const auto soup = canon(g);
  EXPECT_FALSE(op(g));
  EXPECT_EQ(snapshot(g), before);
  EXPECT_EQ(canon(g), soup);
}

Eigen::Vector3d P(double x, double y) { return {x, y, 0}; }

// 3 ---- 2
// |    / |      the unit square, diagonal 0-2:
// |  /   |      faces (0,1,2) and (0,2,3)
// 0 ---- 1
Polygon_soup square() { return soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}, {{0, 1, 2}, {0, 2, 3}}); }

//      2
//     /|\        triangle (0,1,2) with center 3:
//    / 3 \       faces (0,1,3), (1,2,3), (2,0,3); 3 has degree 3
//   /_/ \_\      .
//  0 ----- 1
Polygon_soup fan3() {
  return soup_of({P(0, 0), P(2, 0), P(1, 2), P(1, 0.7)}, {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
}

// b0 ---- b1 ---- b2 ---- b0     an open tube of three quads, each split:
//  |    /  |    /  |    /  |     (a_i, a_i+1, b_i+1), (a_i, b_i+1, b_i);
// a0 ---- a1 ---- a2 ---- a0     vertices a0..a2 = 0..2, b0..b2 = 3..5
Polygon_soup tube3() {
  Polygon_soup s;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 3; ++i) {
      const double a = 2 * 3.14159265358979 * i / 3;
      s.add_point(Eigen::Vector3d(std::cos(a), std::sin(a), z));
    }
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t j = (i + 1) % 3;
    s.add_face({i, j, 3 + j});
    s.add_face({i, 3 + j, 3 + i});
  }
  return s;
}

template <class G>
class Local_operations : public ::testing::Test {};
TYPED_TEST_SUITE(Local_operations, genmesh_test::Backends);

// Tests that run CGAL::Euler on the mesh itself, or override a generic
// operation natively: only for backends with halfedge links (the incidence
// mesh has its own native operations, compared with Halfedge_mesh's in
// SameRandomSequenceSameMesh below and in test_incidence_mesh).
template <class G>
class Local_operations_links : public ::testing::Test {};
TYPED_TEST_SUITE(Local_operations_links, genmesh_test::Pointer_backends);

// ---------------------------------------------------------------------------
// flip_edge
// ---------------------------------------------------------------------------

TYPED_TEST(Local_operations, FlipRotatesTheSquareDiagonal) {
  using G = TypeParam;
  G g = make<G>(square());
  const H<G> h = he(g, 0, 2); // in face (0,2,3)
  ASSERT_TRUE(genmesh::can_flip_edge(h, g));
  const auto r = genmesh::flip_edge(h, g);
  ASSERT_TRUE(r);
  // 3 ---- 2
  // | \    |   the diagonal rotated one vertex forward: h now 3 -> 1,
  // |   \  |   faces (0,1,3) and (1,2,3)
  // 0 ---- 1
  EXPECT_EQ(*r, h);
  EXPECT_EQ(source(h, g), vtx<G>(3));
  EXPECT_EQ(target(h, g), vtx<G>(1));
  EXPECT_EQ(target(next(h, g), g), vtx<G>(2)); // face(h) = (3,1,2)
  EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}, {{0, 1, 3}, {1, 2, 3}}))));
  expect_ok(g);
}

TYPED_TEST(Local_operations, FlipRefusals) {
  using G = TypeParam;
  auto flip = [](H<G> h) { return [h](G& g) { return genmesh::flip_edge(h, g).has_value(); }; };
  {
    G g = make<G>(square()); // border edge 0-1, either side
    expect_refused(g, flip(he(g, 0, 1)));
    expect_refused(g, flip(he(g, 1, 0)));
  }
  {
    G g = make<G>(genmesh::make_cube()); // quads
    expect_refused(g, flip(H<G>(0)));
  }
  {
    G g = make<G>(genmesh::make_tetrahedron()); // the new edge exists already
    for (std::uint32_t i = 0; i < 12; ++i) expect_refused(g, flip(H<G>(i)));
  }
  {
    //        4          a pyramid over the quad (3,2,1,0): flipping 1-4 would
    //      / | \        join 0 and 2 and leave the inner vertex 1 with two
    //    0 --1-- 2      edges (the new edge does not exist: only the degree
    //     \ (3) /       check refuses it)
    G g = make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1), Eigen::Vector3d(0.5, 0.5, 1)},
                          {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {3, 2, 1, 0}}));
    expect_refused(g, flip(he(g, 1, 4)));
    expect_refused(g, flip(he(g, 4, 1)));
  }
  {
    G g = make<G>(fan3()); // would leave the centre with degree 2 (edge 1-2 exists)
    expect_refused(g, flip(he(g, 0, 3)));
    EXPECT_FALSE(genmesh::can_flip_edge(he(g, 3, 1), g));
  }
}

TYPED_TEST(Local_operations, FlipTwiceGivesTheSameMeshFourTimesTheSameArrays) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_icosphere(1));
  const auto soup = canon(g);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const H<G> h(static_cast<std::uint32_t>(rng() % genmesh::index_bound(genmesh::halfedge_index, g)));
    if (!genmesh::can_flip_edge(h, g)) continue;
    ASSERT_TRUE(genmesh::flip_edge(h, g));
    ASSERT_TRUE(genmesh::flip_edge(h, g));
    EXPECT_EQ(canon(g), soup); // the edge is back, its halfedges exchanged
    ASSERT_TRUE(genmesh::flip_edge(h, g));
    ASSERT_TRUE(genmesh::flip_edge(h, g));
    // Once the vertex and face halfedges have been moved as CGAL moves them,
    // every further cycle of four flips restores every array exactly.
    const auto arrays = snapshot(g);
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(genmesh::flip_edge(h, g));
    EXPECT_EQ(snapshot(g), arrays);
    expect_ok(g);
  }
}

/// next, prev, target and face of every live halfedge (the links a flip edits).
template <class G>
std::vector<std::size_t> links(const G& g) {
  std::vector<std::size_t> s;
  const std::size_t nh = genmesh::index_bound(genmesh::halfedge_index, g);
  for (std::size_t i = 0; i < nh; ++i) {
    const H<G> h(static_cast<std::uint32_t>(i));
    if (g.is_removed(h)) continue;
    for (const std::size_t x : {std::size_t(next(h, g)), std::size_t(prev(h, g)), std::size_t(target(h, g)),
                                std::size_t(face(h, g))})
      s.push_back(x);
  }
  return s;
}

template <class G>
std::vector<std::size_t> vertex_halfedges(const G& g) {
  std::vector<std::size_t> s;
  for (std::size_t i = 0; i < genmesh::index_bound(genmesh::vertex_index, g); ++i)
    s.push_back(std::size_t(halfedge(V<G>(static_cast<std::uint32_t>(i)), g)));
  return s;
}
template <class G>
std::vector<std::size_t> face_halfedges(const G& g) {
  std::vector<std::size_t> s;
  for (std::size_t i = 0; i < genmesh::index_bound(genmesh::face_index, g); ++i)
    s.push_back(std::size_t(halfedge(F<G>(static_cast<std::uint32_t>(i)), g)));
  return s;
}

TYPED_TEST(Local_operations, UnflipUndoesFlip) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_icosphere(1));
  std::mt19937 rng(9);
  int tested = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const H<G> h(static_cast<std::uint32_t>(rng() % genmesh::index_bound(genmesh::halfedge_index, g)));
    if (!genmesh::can_flip_edge(h, g)) {
      EXPECT_FALSE(genmesh::can_unflip_edge(opposite(h, g), g));
      continue;
    }
    ++tested;
    const V<G> s = source(h, g), t = target(h, g);
    const F<G> fh = face(h, g), foh = face(opposite(h, g), g);
    const auto soup0 = canon(g);
    const auto links0 = links(g);
    const auto vreps0 = vertex_halfedges(g), freps0 = face_halfedges(g);
    ASSERT_EQ(genmesh::flip_edge(h, g), h);
    const auto arrays1 = snapshot(g);
    ASSERT_TRUE(genmesh::can_unflip_edge(h, g));
    ASSERT_EQ(genmesh::unflip_edge(h, g), h);
    // Every link is back; only the representatives flip_edge overwrote
    // (halfedge of the old ends and of the two faces) may differ.
    EXPECT_EQ(links(g), links0);
    EXPECT_EQ(canon(g), soup0);
    EXPECT_EQ(source(h, g), s);
    EXPECT_EQ(target(h, g), t);
    if constexpr (genmesh::MutableFaceGraph<G>) { // stored representatives (the incidence mesh derives them)
      EXPECT_EQ(halfedge(fh, g), h);
      EXPECT_EQ(halfedge(foh, g), opposite(h, g));
    }
    auto vreps = vertex_halfedges(g), freps = face_halfedges(g);
    vreps[std::size_t(s)] = vreps0[std::size_t(s)];
    vreps[std::size_t(t)] = vreps0[std::size_t(t)];
    freps[std::size_t(fh)] = freps0[std::size_t(fh)];
    freps[std::size_t(foh)] = freps0[std::size_t(foh)];
    EXPECT_EQ(vreps, vreps0);
    EXPECT_EQ(freps, freps0);
    const auto arrays2 = snapshot(g);
    // From here on, flip/unflip pairs in either order restore every array bit for bit.
    ASSERT_TRUE(genmesh::flip_edge(h, g));
    EXPECT_EQ(snapshot(g), arrays1);
    ASSERT_TRUE(genmesh::unflip_edge(h, g));
    EXPECT_EQ(snapshot(g), arrays2);
    ASSERT_TRUE(genmesh::unflip_edge(h, g));
    ASSERT_TRUE(genmesh::flip_edge(h, g));
    EXPECT_EQ(snapshot(g), arrays2);
    expect_ok(g);
  }
  EXPECT_GE(tested, 20);
}

TYPED_TEST(Local_operations, UnflipRotatesBackward) {
  using G = TypeParam;
  G g = make<G>(square());
  const H<G> h = he(g, 0, 2); // in face (0,2,3)
  // 3 ---- 2
  // | \    |   unflip turns the diagonal one vertex backward: h now 1 -> 3
  // |   \  |   (flip_edge would make it 3 -> 1), faces (1,3,0) and (3,1,2)
  // 0 ---- 1
  ASSERT_EQ(genmesh::unflip_edge(h, g), h);
  EXPECT_EQ(source(h, g), vtx<G>(1));
  EXPECT_EQ(target(h, g), vtx<G>(3));
  EXPECT_EQ(target(next(h, g), g), vtx<G>(0)); // face(h) = (1,3,0)
  EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}, {{0, 1, 3}, {1, 2, 3}}))));
  expect_ok(g);
  // The refusals are flip_edge's.
  expect_refused(g, [](G& m) { return genmesh::unflip_edge(he(m, 0, 1), m).has_value(); });
  G t = make<G>(genmesh::make_tetrahedron());
  for (std::uint32_t i = 0; i < 12; ++i)
    expect_refused(t, [i](G& m) { return genmesh::unflip_edge(H<G>(i), m).has_value(); });
}

// ---------------------------------------------------------------------------
// split_edge, split_edge_and_triangulate
// ---------------------------------------------------------------------------

TYPED_TEST(Local_operations, SplitEdgeInsertsAMidpoint) {
  using G = TypeParam;
  G g = make<G>(square());
  const H<G> h = he(g, 0, 2);
  const auto r = genmesh::split_edge(h, g);
  ASSERT_TRUE(r);
  // 3 ---- 2
  // |    / |   w = 4 at (0.5, 0.5): faces (0,4,2,3) and (0,1,2,4)
  // |  4   |   returned: 0 -> 4, next = h (4 -> 2)
  // 0 ---- 1
  const V<G> w = target(*r, g);
  EXPECT_EQ(w, vtx<G>(4));
  EXPECT_EQ(source(*r, g), vtx<G>(0));
  EXPECT_EQ(next(*r, g), h);
  EXPECT_EQ(source(h, g), w);
  EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1), P(0.5, 0.5)},
                                            {{0, 4, 2, 3}, {0, 1, 2, 4}}))));
  expect_ok(g);
  // A border edge: one face grows, the border gets one more halfedge.
  const auto b = genmesh::split_edge(he(g, 1, 0), g); // 1 -> 0 is the border side
  ASSERT_TRUE(b);
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok());
  EXPECT_EQ(rep.border_halfedges, 5u);
  EXPECT_EQ(rep.vertices, 6u);
}

TYPED_TEST(Local_operations, SplitEdgeAndTriangulate) {
  using G = TypeParam;
  {
    G g = make<G>(square());
    const auto r = genmesh::split_edge_and_triangulate(he(g, 0, 2), g);
    ASSERT_TRUE(r);
    // 3 ---- 2
    // | \  / |   2 faces -> 4, all meeting at the midpoint 4
    // | /  \ |
    // 0 ---- 1
    EXPECT_EQ(target(*r, g), vtx<G>(4));
    EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1), P(0.5, 0.5)},
                                              {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}))));
    expect_ok(g);
  }
  {
    G g = make<G>(square());
    // The border edge 0-1: its one triangle (0,1,2) -> (0,4,2), (4,1,2).
    ASSERT_TRUE(genmesh::split_edge_and_triangulate(he(g, 1, 0), g));
    EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1), P(0.5, 0)},
                                              {{0, 4, 2}, {4, 1, 2}, {0, 2, 3}}))));
    expect_ok(g);
  }
  {
    G g = make<G>(genmesh::make_cube()); // quads: refused
    expect_refused(g, [](G& m) { return genmesh::split_edge_and_triangulate(H<G>(0), m).has_value(); });
  }
}

// ---------------------------------------------------------------------------
// collapse_edge
// ---------------------------------------------------------------------------

TYPED_TEST(Local_operations, CollapseKeepsTheTarget) {
  using G = TypeParam;
  {
    G g = make<G>(fan3());
    // The centre 3 into corner 0: the triangle (0,1,2) is left.
    const H<G> h = he(g, 3, 0);
    const V<G> t = target(h, g);
    const auto r = genmesh::collapse_edge(edge(h, g), g);
    ASSERT_TRUE(r);
    EXPECT_EQ(*r, t); // halfedge(edge(h)) == h on every backend
    EXPECT_EQ(*r, vtx<G>(0));
    EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(0, 0), P(2, 0), P(1, 2)}, {{0, 1, 2}}))));
    expect_ok(g);
  }
  {
    G g = make<G>(square());
    // The border edge 0 -> 1 into 1: face (0,1,2) goes, (0,2,3) becomes (1,2,3).
    const auto r = genmesh::collapse_edge(edge(he(g, 0, 1), g), g);
    ASSERT_TRUE(r);
    EXPECT_EQ(*r, vtx<G>(1));
    EXPECT_EQ(canon(g), canon(make<G>(soup_of({P(1, 0), P(1, 1), P(0, 1)}, {{0, 1, 2}}))));
    expect_ok(g);
  }
  {
    G g = make<G>(genmesh::make_icosphere(0)); // any edge of the icosahedron
    const auto r = genmesh::collapse_edge(E<G>(H<G>(0)), g);
    ASSERT_TRUE(r);
    const auto rep = genmesh::check_mesh(g);
    EXPECT_TRUE(rep.ok());
    EXPECT_EQ(rep.vertices, 11u);
    EXPECT_EQ(rep.edges, 27u);
    EXPECT_EQ(rep.faces, 18u);
  }
}

TYPED_TEST(Local_operations, CollapseRefusals) {
  using G = TypeParam;
  auto collapse = [](H<G> h) {
    return [h](G& g) { return genmesh::collapse_edge(edge(h, g), g).has_value(); };
  };
  {
    G g = make<G>(genmesh::make_tetrahedron()); // link condition: tetrahedron
    for (std::uint32_t i = 0; i < 12; ++i) expect_refused(g, collapse(H<G>(i)));
  }
  {
    G g = make<G>(soup_of({P(0, 0), P(1, 0), P(0, 1)}, {{0, 1, 2}})); // the lone triangle
    for (std::uint32_t i = 0; i < 6; ++i) expect_refused(g, collapse(H<G>(i)));
  }
  {
    G g = make<G>(square()); // inner edge with both ends on the border
    expect_refused(g, collapse(he(g, 0, 2)));
    expect_refused(g, collapse(he(g, 2, 0)));
  }
  {
    G g = make<G>(tube3()); // a0, a1 share the neighbour a2 outside their face
    expect_refused(g, collapse(he(g, 0, 1)));
    expect_refused(g, collapse(he(g, 1, 0)));
  }
  {
    G g = make<G>(genmesh::make_cube()); // quads
    expect_refused(g, collapse(H<G>(0)));
  }
}

// ---------------------------------------------------------------------------
// split_face, join_face, add/remove_center_vertex, add/remove_face, triangulate
// ---------------------------------------------------------------------------

TYPED_TEST(Local_operations, SplitFaceAndJoinFaceAreInverse) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_cube());
  const auto soup = canon(g);
  const H<G> h1 = halfedge(F<G>(0), g);
  const H<G> h2 = next(next(h1, g), g);
  const auto h3 = genmesh::split_face(h1, h2, g);
  ASSERT_TRUE(h3);
  EXPECT_EQ(next(h1, g), *h3);
  EXPECT_EQ(source(*h3, g), target(h1, g));
  EXPECT_EQ(target(*h3, g), target(h2, g));
  EXPECT_EQ(next(h2, g), opposite(*h3, g));
  auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok());
  EXPECT_EQ(rep.faces, 7u);
  const auto j = genmesh::join_face(*h3, g);
  ASSERT_TRUE(j);
  EXPECT_EQ(*j, h1); // join_face(split_face(h1, h2)) returns h1, as CGAL
  EXPECT_EQ(canon(g), soup);
  expect_ok(g);
}

TYPED_TEST(Local_operations, SplitFaceAndJoinFaceRefusals) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_cube());
  const H<G> h1 = halfedge(F<G>(0), g);
  auto split = [](H<G> a, H<G> b) { return [a, b](G& m) { return genmesh::split_face(a, b, m).has_value(); }; };
  expect_refused(g, split(h1, h1));                  // same halfedge
  expect_refused(g, split(h1, next(h1, g)));         // consecutive
  expect_refused(g, split(next(h1, g), h1));         // consecutive
  expect_refused(g, split(h1, opposite(h1, g)));     // different faces
  {
    G s = make<G>(square()); // border halfedges (a hole); an end of degree 2
    expect_refused(s, split(he(s, 1, 0), he(s, 3, 2)));
    expect_refused(s, [&](G& m) { return genmesh::join_face(he(m, 0, 1), m).has_value(); }); // 1 has degree 2
  }
  {
    // A closed pillow: the quad (0,1,2,3) and, behind it, the triangles
    // (0,3,2) and (0,2,1) sharing the edge 0-2. Splitting the quad along 0-2
    // would duplicate that edge.
    G p = make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}, {{0, 1, 2, 3}, {0, 3, 2}, {0, 2, 1}}));
    expect_ok(p);
    expect_refused(p, split(he(p, 3, 0), he(p, 1, 2)));
    expect_refused(p, split(he(p, 1, 2), he(p, 3, 0)));
  }
  {
    // 3 --------- 2      two faces around a square hole, sharing the edges
    // |  7 ----- 6|      0-4 and 2-6: joining across one would leave the
    // |  |  hole | |     merged face on both sides of the other (CGAL's
    // |  4 ----- 5|      join_face does that; genmesh refuses).
    // 0 --------- 1      A = (0,1,2,6,5,4), B = (0,4,7,6,2,3)
    G a = make<G>(soup_of({P(0, 0), P(3, 0), P(3, 3), P(0, 3), P(1, 1), P(2, 1), P(2, 2), P(1, 2)},
                          {{0, 1, 2, 6, 5, 4}, {0, 4, 7, 6, 2, 3}}));
    expect_ok(a);
    for (const auto& [u, v] : {std::pair{0, 4}, std::pair{4, 0}, std::pair{2, 6}, std::pair{6, 2}}) {
      const H<G> h = he(a, u, v);
      EXPECT_FALSE(genmesh::can_join_face(h, a));
      expect_refused(a, [h](G& m) { return genmesh::join_face(h, m).has_value(); });
      expect_refused(a, [h](G& m) { return genmesh::erase_edge(edge(h, m), m).has_value(); });
    }
  }
  {
    G t = make<G>(soup_of({P(0, 0), P(1, 0), P(0, 1)}, {{0, 1, 2}})); // lone triangle: all ends degree 2
    for (std::uint32_t i = 0; i < 6; ++i)
      expect_refused(t, [i](G& m) { return genmesh::join_face(H<G>(i), m).has_value(); });
  }
}

TYPED_TEST(Local_operations, CenterVertexAddAndRemove) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_cube());
  const auto soup = canon(g);
  const H<G> h = halfedge(F<G>(0), g);
  const auto c = genmesh::add_center_vertex(h, g);
  ASSERT_TRUE(c);
  EXPECT_EQ(next(h, g), *c);
  EXPECT_EQ(target(*c, g), vtx<G>(8));
  auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok());
  EXPECT_EQ(rep.vertices, 9u);
  EXPECT_EQ(rep.edges, 16u);
  EXPECT_EQ(rep.faces, 9u);
  const auto r = genmesh::remove_center_vertex(*c, g);
  ASSERT_TRUE(r);
  EXPECT_EQ(canon(g), soup);
  expect_ok(g);
  // Refusals: a border halfedge; a vertex of the tetrahedron; a border vertex.
  G s = make<G>(square());
  expect_refused(s, [&](G& m) { return genmesh::add_center_vertex(he(m, 1, 0), m).has_value(); });
  expect_refused(s, [&](G& m) { return genmesh::remove_center_vertex(he(m, 0, 2), m).has_value(); });
  G t = make<G>(genmesh::make_tetrahedron());
  for (std::uint32_t i = 0; i < 12; ++i)
    expect_refused(t, [i](G& m) { return genmesh::remove_center_vertex(H<G>(i), m).has_value(); });
}

TYPED_TEST(Local_operations, AddFaceAndRemoveFace) {
  using G = TypeParam;
  G g;
  std::vector<V<G>> v;
  for (const auto& p : {P(0, 0), P(1, 0), P(1, 1), P(0, 1), P(2, 0)})
    v.push_back(add_vertex(genmesh::from_eigen<genmesh::point_t<G>>(p), g));
  // 3 ---- 2
  // |    / | \      (0,1,2) on isolated vertices, then (0,2,3) sharing 0-2,
  // |  /   |  \     then (1,4,2) sharing 1-2.
  // 0 ---- 1 - 4
  auto add = [&](std::vector<V<G>> f) { return genmesh::euler::add_face(f, g); };
  ASSERT_TRUE(add({v[0], v[1], v[2]}));
  ASSERT_TRUE(add({v[0], v[2], v[3]}));
  ASSERT_TRUE(add({v[1], v[4], v[2]}));
  expect_ok(g);
  EXPECT_EQ(genmesh::check_mesh(g).faces, 3u);
  // Refusals.
  auto refuse = [&](std::vector<V<G>> f) {
    expect_refused(g, [f](G& m) { return genmesh::euler::add_face(f, m).has_value(); });
  };
  refuse({v[0], v[1]});             // two vertices
  refuse({v[0], v[1], v[1]});       // repeated vertex
  refuse({v[0], v[1], v[2]});       // 0 -> 1 is not a border halfedge any more
  refuse({v[3], v[4], v[0]});       // both sides at 4 are new and 4 has edges: a second fan
  {
    const V<G> w = add_vertex(genmesh::from_eigen<genmesh::point_t<G>>(P(3, 3)), g);
    const V<G> x = add_vertex(genmesh::from_eigen<genmesh::point_t<G>>(P(4, 3)), g);
    refuse({v[3], w, x}); // touches the mesh at vertex 3 only: a bow-tie
  }
  // remove_face: (1,4,2) goes with vertex 4 and edges 1-4, 4-2.
  const H<G> h14 = he(g, 1, 4);
  ASSERT_TRUE(genmesh::euler::remove_face(h14, g));
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok());
  EXPECT_EQ(rep.faces, 2u);
  EXPECT_EQ(rep.edges, 5u);
  EXPECT_EQ(rep.vertices - rep.isolated_vertices, 4u);
  expect_refused(g, [&](G& m) { return genmesh::euler::remove_face(he(m, 1, 0), m); }); // border
}

TYPED_TEST(Local_operations, TriangulateFacesFansFromTheLowestVertex) {
  using G = TypeParam;
  const Polygon_soup cube = genmesh::make_cube();
  G g = make<G>(cube);
  EXPECT_EQ(genmesh::triangulate_faces(g), 0u);
  Polygon_soup expected;
  expected.points = cube.points;
  const Polygon_soup rotated = genmesh::canonical(cube);
  for (std::size_t f = 0; f < rotated.num_faces(); ++f) {
    const auto c = rotated.face(f); // starts at its lowest vertex
    for (std::size_t k = 1; k + 1 < c.size(); ++k) expected.add_face({c[0], c[k], c[k + 1]});
  }
  EXPECT_EQ(canon(g), genmesh::canonical(expected));
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok());
  EXPECT_TRUE(rep.is_triangle_mesh);
  EXPECT_EQ(rep.faces, 12u);
  // A face whose fan diagonal exists already is refused.
  G t = make<G>(genmesh::make_tetrahedron());
  EXPECT_TRUE(genmesh::triangulate_face(F<G>(0), t)); // a triangle: nothing to do
}

TYPED_TEST(Local_operations, EraseVertexAndEraseEdge) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_cube());
  const auto soup = canon(g);
  const auto c = genmesh::add_center_vertex(halfedge(F<G>(0), g), g);
  ASSERT_TRUE(c);
  // The centre of the split face: erasing it gives the cube back.
  const auto f = genmesh::erase_vertex(target(*c, g), g);
  ASSERT_TRUE(f);
  EXPECT_EQ(degree(*f, g), 4u);
  EXPECT_EQ(canon(g), soup);
  // Erasing an edge of the cube merges two quads into a hexagon.
  const auto m = genmesh::erase_edge(E<G>(H<G>(0)), g);
  ASSERT_TRUE(m);
  EXPECT_EQ(degree(*m, g), 6u);
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok());
  EXPECT_EQ(rep.faces, 5u);
  EXPECT_EQ(rep.edges, 11u);
  // Refusals: tetrahedron vertices (two faces would be glued back to back),
  // border vertices, the lone triangle's edges (ends of degree 2).
  G t = make<G>(genmesh::make_tetrahedron());
  for (std::uint32_t i = 0; i < 4; ++i)
    expect_refused(t, [i](G& x) { return genmesh::erase_vertex(vtx<G>(i), x).has_value(); });
  G s = make<G>(square());
  for (std::uint32_t i = 0; i < 4; ++i)
    expect_refused(s, [i](G& x) { return genmesh::erase_vertex(vtx<G>(i), x).has_value(); });
  G l = make<G>(soup_of({P(0, 0), P(1, 0), P(0, 1)}, {{0, 1, 2}}));
  for (std::uint32_t i = 0; i < 3; ++i)
    expect_refused(l, [i](G& x) { return genmesh::erase_edge(E<G>(H<G>(2 * i)), x).has_value(); });
}

// ---------------------------------------------------------------------------
// Refusals where the generic edit would leave a face through a vertex twice
// or a pinched vertex (two border gaps): the same on every backend (the
// incidence mesh cannot represent either, so it always refused them).
// ---------------------------------------------------------------------------

// True if some face's cycle passes through a vertex more than once.
template <class G>
bool some_face_visits_a_vertex_twice(const G& g) {
  for (const auto f : faces(g)) {
    std::vector<std::size_t> vs;
    for (const auto h : CGAL::halfedges_around_face(halfedge(f, g), g)) vs.push_back(std::size_t(target(h, g)));
    std::sort(vs.begin(), vs.end());
    if (std::adjacent_find(vs.begin(), vs.end()) != vs.end()) return true;
  }
  return false;
}

// True if some vertex has two or more border gaps (two border halfedges
// leave it): a pinch, not a 2-manifold. check_mesh does not see it when the
// border links join the two fans into one orbit, so count directly.
template <class G>
bool some_vertex_is_pinched(const G& g) {
  std::vector<int> gaps(genmesh::index_bound(genmesh::vertex_index, g), 0);
  for (const auto h : halfedges(g))
    if (face(h, g) == boost::graph_traits<G>::null_face() && ++gaps[std::size_t(source(h, g))] > 1) return true;
  return false;
}

// A pinched annulus: A = (0,1,2,5,4) and B = (0,4,2,3) share the edge 0-4
// and touch again at 2, around the triangle T = (4,5,2).
//
// 3 ------------- 2
// |   B        /  /|
// |         /   /  |      joining A and B across 0-4 (join_face, erase_edge)
// |      /  T  /   |      would make the face (1,2,5,4,2,3,0) pass through
// |   4 ----- 5    |      2 twice; so would removing the centre 4 (its link
// |  /    A        |      is 0,1,2,5,2,3: remove_center_vertex, erase_vertex)
// 0 ------------- 1
Polygon_soup pinched_annulus() {
  return soup_of({P(0, 0), P(4, 0), P(4, 4), P(0, 4), P(1, 2), P(3, 1)}, {{0, 1, 2, 5, 4}, {0, 4, 2, 3}, {4, 5, 2}});
}

// A triangulated square annulus: outer 0..3, inner hole 4..7.
//
// 3 ------------- 2
// | \           / |
// |   7 ----- 6   |       the triangle (0,1,5) has its side 0-1 on the outer
// |   | hole  |   |       border and its corner 5 on the hole: removing it
// |   4 ----- 5   |       (euler::remove_face), or joining it into the outer
// | /     _ /   \ |       hole (join_face of the border halfedge 1 -> 0),
// 0 ------------- 1       would leave 5 with two border gaps (a pinch).
Polygon_soup triangulated_annulus() {
  return soup_of({P(0, 0), P(4, 0), P(4, 4), P(0, 4), P(1, 1), P(3, 1), P(3, 3), P(1, 3)},
                 {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}});
}

// A hexagon F = (0,7,6,1,4,5) holding both ends of the edge 0-1 without it:
//
//   8 ----- 2
//    \    / | \           the triangles (0,1,2) on top and (1,0,3) below
//     \ /   |   \         the edge 0-1; 0 is inner. Collapsing 0-1 passes
//      0 ------- 1        the link condition (common neighbours 2 and 3 only)
//      |\  \3/  /|        but would make F = (1,7,6,1,4,5) pass through 1
//      | \ / \ / |        twice. Below 0-1: (3,4,1), (3,5,4), (3,0,5); left:
//      |  5 - 4  |        (7,0,8), (8,0,2).
//      |    F    |
//      7 ------- 6
Polygon_soup hexagon_around_an_edge() {
  return soup_of({P(0, 0), P(4, 0), P(2, 1), P(2, -1), P(3, -2), P(1, -2), P(4, -4), P(0, -4), P(-2, 0)},
                 {{0, 1, 2}, {1, 0, 3}, {3, 4, 1}, {3, 5, 4}, {3, 0, 5}, {0, 7, 6, 1, 4, 5}, {7, 0, 8}, {8, 0, 2}});
}

TYPED_TEST(Local_operations, JoinAndEraseRefuseAFaceThroughAVertexTwice) {
  using G = TypeParam;
  G g = make<G>(pinched_annulus());
  expect_ok(g);
  for (const auto& [u, v] : {std::pair{0, 4}, std::pair{4, 0}}) {
    const H<G> h = he(g, u, v);
    EXPECT_FALSE(genmesh::can_join_face(h, g));
    EXPECT_FALSE(genmesh::can_erase_edge(edge(h, g), g));
    expect_refused(g, [h](G& m) { return genmesh::join_face(h, m).has_value(); });
    expect_refused(g, [h](G& m) { return genmesh::erase_edge(edge(h, m), m).has_value(); });
  }
  for (const auto& [u, v] : {std::pair{0, 4}, std::pair{5, 4}, std::pair{2, 4}}) {
    const H<G> h = he(g, u, v);
    EXPECT_FALSE(genmesh::can_remove_center_vertex(h, g));
    expect_refused(g, [h](G& m) { return genmesh::remove_center_vertex(h, m).has_value(); });
  }
  EXPECT_FALSE(genmesh::can_erase_vertex(vtx<G>(4), g));
  expect_refused(g, [](G& m) { return genmesh::erase_vertex(vtx<G>(4), m).has_value(); });
  // Joining T into A across 4-5 is refused too (they share 5-2 as well), but
  // into B across 4-2 gives (0,4,5,2,3), each vertex once.
  expect_refused(g, [](G& m) { return genmesh::join_face(he(m, 4, 5), m).has_value(); });
  const auto j = genmesh::join_face(he(g, 2, 4), g);
  ASSERT_TRUE(j);
  expect_ok(g);
  EXPECT_FALSE(some_face_visits_a_vertex_twice(g));
  EXPECT_EQ(genmesh::check_mesh(g).faces, 2u);
}

TYPED_TEST(Local_operations, CollapseRefusesAFaceThroughAVertexTwice) {
  using G = TypeParam;
  G g = make<G>(hexagon_around_an_edge());
  expect_ok(g);
  const H<G> h = he(g, 0, 1);
  EXPECT_TRUE(genmesh::does_satisfy_link_condition(edge(h, g), g));
  EXPECT_FALSE(genmesh::can_collapse_edge(edge(h, g), g));
  expect_refused(g, [h](G& m) { return genmesh::collapse_edge(edge(h, m), m).has_value(); });
  expect_refused(g, [](G& m) {
    const H<G> x = genmesh::detail::lo::find_halfedge(vtx<G>(1), vtx<G>(0), m);
    return genmesh::collapse_edge(edge(x, m), m).has_value();
  });
  // Still allowed: 0-2 (F does not hold 2).
  ASSERT_TRUE(genmesh::collapse_edge(edge(he(g, 0, 2), g), g));
  expect_ok(g);
  EXPECT_FALSE(some_face_visits_a_vertex_twice(g));
}

TYPED_TEST(Local_operations, RemoveFaceAndJoinIntoAHoleRefuseAPinch) {
  using G = TypeParam;
  G g = make<G>(triangulated_annulus());
  expect_ok(g);
  EXPECT_FALSE(genmesh::can_remove_face(he(g, 0, 1), g));
  expect_refused(g, [](G& m) { return genmesh::euler::remove_face(he(m, 0, 1), m); });
  expect_refused(g, [](G& m) { return genmesh::euler::remove_face(he(m, 5, 0), m); });
  EXPECT_FALSE(genmesh::can_join_face(he(g, 1, 0), g));
  expect_refused(g, [](G& m) { return genmesh::join_face(he(m, 1, 0), m).has_value(); });
  expect_refused(g, [](G& m) { return genmesh::erase_edge(edge(he(m, 1, 0), m), m).has_value(); });
  // (0,5,4) has both sides at 0 inner and 0 on the outer border: a pinch too.
  expect_refused(g, [](G& m) { return genmesh::euler::remove_face(he(m, 0, 5), m); });
  // From the fan (0,1,2), (0,2,3), (0,3,4) of the border vertex 0, the end
  // triangle may go, the middle one not (0 would have two border gaps).
  G f = make<G>(soup_of({P(0, 0), P(2, 0), P(1.5, 1.5), P(0, 2), P(-1.5, 1.5)}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  expect_refused(f, [](G& m) { return genmesh::euler::remove_face(he(m, 2, 3), m); });
  expect_refused(f, [](G& m) { return genmesh::join_face(he(m, 3, 2), m).has_value(); });
  ASSERT_TRUE(genmesh::euler::remove_face(he(f, 1, 2), f));
  expect_ok(f);
  ASSERT_TRUE(genmesh::join_face(he(f, 3, 0), f)); // (0,3,4) into the hole: leaves (0,2,3)
  expect_ok(f);
  EXPECT_EQ(genmesh::check_mesh(f).faces, 1u);
}

// The edits the predicates above refuse, done raw on a pointer backend: they
// do leave a face through a vertex twice or an invalid mesh, so the refusals
// guard something real.
TYPED_TEST(Local_operations_links, RefusedEditsWouldBreakTheMesh) {
  using G = TypeParam;
  namespace lo = genmesh::detail::lo;
  {
    G g = make<G>(pinched_annulus());
    lo::join_face_raw(he(g, 0, 4), g);
    EXPECT_TRUE(some_face_visits_a_vertex_twice(g));
  }
  {
    G g = make<G>(triangulated_annulus());
    lo::remove_face_raw(he(g, 0, 1), g);
    EXPECT_TRUE(some_vertex_is_pinched(g));
  }
  {
    G g = make<G>(triangulated_annulus());
    lo::join_face_raw(he(g, 1, 0), g);
    EXPECT_TRUE(some_vertex_is_pinched(g));
  }
  {
    // CGAL::Euler::collapse_edge does it (its link condition holds).
    G g = make<G>(hexagon_around_an_edge());
    const E<G> e = edge(he(g, 0, 1), g);
    ASSERT_TRUE(CGAL::Euler::does_satisfy_link_condition(e, g));
    CGAL::Euler::collapse_edge(e, g);
    EXPECT_TRUE(some_face_visits_a_vertex_twice(g));
  }
  {
    G g = make<G>(pinched_annulus());
    CGAL::Euler::remove_center_vertex(he(g, 0, 4), g);
    EXPECT_TRUE(some_face_visits_a_vertex_twice(g));
  }
}

TYPED_TEST(Local_operations, BevelFaceInsetsAFace) {
  using G = TypeParam;
  //   3 ------- 2        a quad of the cube inset: the face keeps its index
  //   | 7 --- 6 |        and is now bounded by new vertices 8..11 (drawn
  //   | |  f  | |        4..7 here), one spoke from each old corner; four
  //   | 4 --- 5 |        quads fill the ring between.
  //   0 ------- 1
  G g = make<G>(genmesh::make_cube());
  const F<G> f(0);
  const auto r = genmesh::bevel_face(f, g);
  ASSERT_TRUE(r);
  EXPECT_EQ(*r, f);
  EXPECT_EQ(degree(f, g), 4u);
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok()) << genmesh::to_string(rep);
  EXPECT_EQ(rep.vertices, 12u);
  EXPECT_EQ(rep.edges, 20u);
  EXPECT_EQ(rep.faces, 10u);
  EXPECT_EQ(rep.genus, 0);
  // Each inner corner is new, has degree 3 and one spoke to an old corner
  // at the same point.
  auto pm = get(genmesh::vertex_point, g);
  for (const auto h : CGAL::halfedges_around_face(halfedge(f, g), g)) {
    const V<G> wv = target(h, g);
    EXPECT_GE(std::size_t(wv), 8u);
    int spokes = 0, around = 0;
    for (const auto k : CGAL::halfedges_around_target(wv, g)) {
      ++around;
      const V<G> o = source(k, g);
      if (std::size_t(o) < 8) {
        EXPECT_EQ(genmesh::to_eigen(genmesh::point_t<G>(get(pm, o))),
                  genmesh::to_eigen(genmesh::point_t<G>(get(pm, wv))));
        ++spokes;
      }
    }
    EXPECT_EQ(spokes, 1);
    EXPECT_EQ(around, 3);
  }
  // The null face is refused.
  expect_refused(g, [](G& m) { return genmesh::bevel_face(boost::graph_traits<G>::null_face(), m).has_value(); });
}

TYPED_TEST(Local_operations, BevelVertexCutsACorner) {
  using G = TypeParam;
  // A cube corner becomes a triangle; its three quads become pentagons.
  G g = make<G>(genmesh::make_cube());
  const auto nf = genmesh::bevel_vertex(vtx<G>(0), g);
  ASSERT_TRUE(nf);
  EXPECT_EQ(degree(*nf, g), 3u);
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok()) << genmesh::to_string(rep);
  EXPECT_EQ(rep.vertices, 10u);
  EXPECT_EQ(rep.edges, 15u);
  EXPECT_EQ(rep.faces, 7u);
  EXPECT_TRUE(g.is_removed(vtx<G>(0)));
  int pentagons = 0;
  for (const auto f : faces(g)) pentagons += degree(f, g) == 5;
  EXPECT_EQ(pentagons, 3);
  // Refused: border vertices.
  G s = make<G>(square());
  for (std::uint32_t i = 0; i < 4; ++i)
    expect_refused(s, [i](G& m) { return genmesh::bevel_vertex(vtx<G>(i), m).has_value(); });
}

TYPED_TEST(Local_operations, BevelEdgeOpensTheSquareDiagonal) {
  using G = TypeParam;
  G g = make<G>(square());
  const H<G> h = he(g, 0, 2); // u = 0, v = 2, L = (0,2,3), R = (0,1,2)
  const auto r = genmesh::bevel_edge(h, g);
  ASSERT_TRUE(r);
  //  3 ---- 2             3 ------ 2 _          each end has degree 3: it splits,
  //  |    / |             |      /     ` 5      the hole between its two groups of
  //  |  /   |     ->      |    /    Q    |      edges gains the new side (2-5, 0-4);
  //  0 ---- 1             0 _/          |       the ends slide 1/4 along L's sides
  //                           ` 4 ------ 1      (0 up, 2 left), the copies along R's.
  // Q = (2, 0, 4, 5) replaces the edge; L = (0,2,3) and R = (4,1,5) stay triangles.
  EXPECT_EQ(*r, opposite(h, g));
  EXPECT_EQ(source(h, g), vtx<G>(0));
  EXPECT_EQ(target(h, g), vtx<G>(2));
  EXPECT_EQ(halfedge(face(*r, g), g), *r);
  EXPECT_EQ(degree(face(*r, g), g), 4u);
  const Polygon_soup expected =
      soup_of({P(0, 0.25), P(1, 0), P(0.75, 1), P(0, 1), P(0.25, 0), P(1, 0.75)}, {{0, 2, 3}, {4, 1, 5}, {2, 0, 4, 5}});
  EXPECT_EQ(canon(g), canon(make<G>(expected)));
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok()) << genmesh::to_string(rep);
  EXPECT_EQ(rep.border_halfedges, 6u);
}

TYPED_TEST(Local_operations, BevelEdgeOfTheCube) {
  using G = TypeParam;
  G g = make<G>(genmesh::make_cube());
  //      3 ------- 7           the edge 0-1 (x from -1 to 1 at y = z = -1),
  //     /|        /|           L = y=-1 face (0,1,5,4), R = z=-1 face (0,2,3,1):
  //    2 ------- 6 |           0 and 1 split; the third face at each end
  //    | 1 ------|-5           (x=-1 and x=+1) becomes a pentagon; the new
  //    |/        |/            quad Q = (1, 0, 8, 9) is the chamfer; 0 and 1
  //    0 ------- 4             slide along z, 8 and 9 (their copies) along y.
  // (z up the page, y into it; vertex i has coordinates from its bits x, y, z.)
  const H<G> h = he(g, 0, 1);
  ASSERT_EQ(face(h, g), face(he(g, 1, 5), g)); // L is the y = -1 face
  const auto r = genmesh::bevel_edge(h, g, {.fraction = 0.25});
  ASSERT_TRUE(r);
  Polygon_soup expected = genmesh::make_cube();
  expected.points[0] = Eigen::Vector3d(-1, -1, -0.5);
  expected.points[1] = Eigen::Vector3d(1, -1, -0.5);
  Polygon_soup e2;
  e2.points = expected.points;
  e2.add_point(Eigen::Vector3d(-1, -0.5, -1)); // 8 = 0'
  e2.add_point(Eigen::Vector3d(1, -0.5, -1));  // 9 = 1'
  for (const auto& f : std::vector<std::vector<std::uint32_t>>{
           {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {8, 2, 3, 9}, {8, 0, 4, 6, 2}, {1, 9, 3, 7, 5}, {1, 0, 8, 9}})
    e2.add_face(f);
  EXPECT_EQ(canon(g), genmesh::canonical(e2));
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok()) << genmesh::to_string(rep);
  EXPECT_EQ(rep.vertices, 10u);
  EXPECT_EQ(rep.edges, 15u);
  EXPECT_EQ(rep.faces, 7u);
  EXPECT_EQ(rep.genus, 0);
}

TYPED_TEST(Local_operations, BevelEdgeOnTheBorderMakesATriangle) {
  using G = TypeParam;
  G g = make<G>(square());
  // 3 ---- 2          3 ---- 2       the border edge 0-1: 1 has degree 2 and
  // |    / |          |  _ / |       stays; 0 splits: 0 keeps 0-1, 0-2 and
  // |  /   |    ->    4 -0   |       slides toward 2, its copy 4 takes 0-3
  // 0 ---- 1           ` - - 1       and slides up; Q = (1, 0, 4) is a triangle,
  //                                  (0,2,3) gains the side 4-0: (4,0,2,3).
  const H<G> h = he(g, 0, 1);
  const auto r = genmesh::bevel_edge(h, g);
  ASSERT_TRUE(r);
  EXPECT_EQ(degree(face(*r, g), g), 3u);
  const Polygon_soup expected = soup_of({P(0.25, 0.25), P(1, 0), P(1, 1), P(0, 1), P(0, 0.25)},
                                        {{0, 1, 2}, {4, 0, 2, 3}, {1, 0, 4}});
  EXPECT_EQ(canon(g), canon(make<G>(expected)));
  const auto rep = genmesh::check_mesh(g);
  EXPECT_TRUE(rep.ok()) << genmesh::to_string(rep);
  EXPECT_EQ(rep.border_halfedges, 4u);
  // The same edge from its border side: the new face lies in the hole's
  // place instead, and the mesh stays valid.
  G b = make<G>(square());
  ASSERT_TRUE(genmesh::bevel_edge(he(b, 1, 0), b));
  expect_ok(b);
  EXPECT_EQ(genmesh::check_mesh(b).faces, 3u);
}

TYPED_TEST(Local_operations, BevelEdgeRefusals) {
  using G = TypeParam;
  auto bevel = [](H<G> h) { return [h](G& g) { return genmesh::bevel_edge(h, g).has_value(); }; };
  {
    //  2          the lone triangle: both ends of every edge have degree 2,
    //  | \        the new face would have two sides
    //  0 - 1
    G g = make<G>(soup_of({P(0, 0), P(1, 0), P(0, 1)}, {{0, 1, 2}}));
    for (std::uint32_t i = 0; i < 6; ++i) {
      EXPECT_FALSE(genmesh::can_bevel_edge(H<G>(i), g));
      expect_refused(g, bevel(H<G>(i)));
    }
    expect_refused(g, bevel(boost::graph_traits<G>::null_halfedge()));
  }
  {
    // A lone quad: same.
    G g = make<G>(soup_of({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}, {{0, 1, 2, 3}}));
    for (std::uint32_t i = 0; i < 8; ++i) expect_refused(g, bevel(H<G>(i)));
  }
  {
    // A fraction outside [0, 1) throws before any change.
    G g = make<G>(genmesh::make_cube());
    const auto before = snapshot(g);
    EXPECT_THROW(genmesh::bevel_edge(H<G>(0), g, {.fraction = 1.0}), genmesh::invalid_input);
    EXPECT_THROW(genmesh::bevel_edge(H<G>(0), g, {.fraction = -0.1}), genmesh::invalid_input);
    EXPECT_EQ(snapshot(g), before);
  }
}

// Random bevel_edge (with flips and face splits/joins between, so that
// degrees, borders and polygon sizes vary), check_mesh after each; the same
// sequence on Halfedge_mesh gives the same mesh, element for element.
template <class G>
G random_bevels(const Polygon_soup& soup, unsigned seed, int steps, int* bevels) {
  G g = make<G>(soup);
  std::mt19937 rng(seed);
  for (int i = 0; i < steps; ++i) {
    const std::size_t nh = genmesh::index_bound(genmesh::halfedge_index, g);
    const H<G> h(static_cast<std::uint32_t>(rng() % nh));
    const unsigned pick = rng() % 4;
    if (g.is_removed(h)) continue;
    const auto rep_before = genmesh::check_mesh(g);
    if (pick < 2) {
      const bool can = genmesh::can_bevel_edge(h, g);
      const auto r = genmesh::bevel_edge(h, g, {.fraction = 0.2});
      EXPECT_EQ(can, r.has_value());
      if (r) {
        ++*bevels;
        const auto rep = genmesh::check_mesh(g);
        EXPECT_TRUE(rep.ok()) << "step " << i << ": " << genmesh::to_string(rep);
        if (!rep.ok()) return g;
        EXPECT_EQ(rep.euler_characteristic, rep_before.euler_characteristic);
        EXPECT_EQ(rep.faces, rep_before.faces + 1);
        EXPECT_LE(rep.vertices, rep_before.vertices + 2);
        EXPECT_NE(face(*r, g), boost::graph_traits<G>::null_face());
      }
    } else if (pick == 2) {
      (void)genmesh::flip_edge(h, g);
    } else {
      (void)genmesh::erase_edge(edge(h, g), g);
    }
    const auto rep = genmesh::check_mesh(g);
    EXPECT_TRUE(rep.ok()) << "step " << i << ", operation " << pick << ": " << genmesh::to_string(rep);
    if (!rep.ok()) return g;
  }
  return g;
}

TYPED_TEST(Local_operations, BevelEdgeRandomSequenceMatchesHalfedgeMesh) {
  using G = TypeParam;
  for (const auto& soup : {genmesh::make_grid_with_hole(6), genmesh::make_torus(8, 6, true), genmesh::make_cube()}) {
    int n = 0, m = 0;
    const G g = random_bevels<G>(soup, 5u, 400, &n);
    const auto ref = random_bevels<genmesh_test::Halfedge_mesh>(soup, 5u, 400, &m);
    EXPECT_GE(n, 50);
    EXPECT_EQ(n, m);
    if constexpr (genmesh::MutableFaceGraph<G>) {
      EXPECT_EQ(snapshot(g), snapshot(ref));
    } else {
      EXPECT_EQ(links(g), links(ref)); // the incidence mesh derives halfedge(v), halfedge(f)
    }
    EXPECT_EQ(canon(g), canon(ref));
  }
}

struct Counting_visitor : genmesh::Mutation_visitor {
  int flips = 0, splits = 0, collapses = 0, before = 0, split_faces = 0, bevels = 0;
  void on_bevel_edge(const auto&, const auto&) { ++bevels; }
  void on_flip(const auto&, const auto&) { ++flips; }
  void on_split_edge(const auto&, const auto&) { ++splits; }
  void before_collapse(const auto&, const auto&) { ++before; }
  void on_collapse(const auto&, const auto&) { ++collapses; }
  void on_split_face(const auto&, const auto&) { ++split_faces; }
};

TYPED_TEST(Local_operations, VisitorSeesSuccessesOnly) {
  using G = TypeParam;
  G g = make<G>(square());
  Counting_visitor vis;
  EXPECT_FALSE(genmesh::flip_edge(he(g, 0, 1), g, vis));
  EXPECT_FALSE(genmesh::collapse_edge(edge(he(g, 0, 2), g), g, vis));
  EXPECT_EQ(vis.flips + vis.before + vis.collapses, 0);
  EXPECT_TRUE(genmesh::flip_edge(he(g, 0, 2), g, vis));
  EXPECT_TRUE(genmesh::split_edge_and_triangulate(he(g, 0, 1), g, vis));
  EXPECT_TRUE(genmesh::collapse_edge(edge(he(g, 4, 0), g), g, vis));
  EXPECT_EQ(vis.flips, 1);
  EXPECT_EQ(vis.splits, 1);
  EXPECT_EQ(vis.before, 1);
  EXPECT_EQ(vis.collapses, 1);
  EXPECT_FALSE(genmesh::bevel_edge(boost::graph_traits<G>::null_halfedge(), g, {}, vis));
  EXPECT_EQ(vis.bevels, 0);
  EXPECT_TRUE(genmesh::bevel_edge(he(g, 3, 1), g, {}, vis));
  EXPECT_EQ(vis.bevels, 1);
  expect_ok(g);
}

// A visitor whose namespace supplies a native flip that always refuses: it
// proves the operation objects dispatch to genmesh_native_<operation> found
// by argument-dependent lookup (as a backend's own is found through its mesh
// type) instead of running the generic code.
namespace native_probe {
struct Probe : genmesh::Mutation_visitor {
  int native_flips = 0;
};
template <class H, class G>
std::optional<H> genmesh_native_flip_edge(H, G&, Probe& probe) {
  ++probe.native_flips;
  return std::nullopt;
}
} // namespace native_probe

TYPED_TEST(Local_operations_links, NativeOperationsOverrideTheGenericOnes) {
  using G = TypeParam;
  G g = make<G>(square());
  const Polygon_soup before = genmesh::canonical(genmesh::to_soup(g));
  native_probe::Probe probe;
  EXPECT_TRUE(genmesh::can_flip_edge(he(g, 0, 2), g));       // the generic flip would succeed,
  EXPECT_FALSE(genmesh::flip_edge(he(g, 0, 2), g, probe));    // the native one refuses
  EXPECT_EQ(probe.native_flips, 1);
  EXPECT_EQ(genmesh::canonical(genmesh::to_soup(g)), before);
  EXPECT_TRUE(genmesh::split_edge_and_triangulate(he(g, 0, 1), g, probe));  // no native split: generic
  EXPECT_EQ(probe.native_flips, 1);
  expect_ok(g);
}

// ---------------------------------------------------------------------------
// Equality with CGAL::Euler and across backends; random stress
// ---------------------------------------------------------------------------

enum class Op { flip, split, split_tri, collapse, center, uncenter };
constexpr int op_count = 6;

// Applies one random operation (op) to a with genmesh and, if it succeeded,
// the same to b with CGAL::Euler (b == nullptr: genmesh only; always so on
// a backend without halfedge links). Returns whether it succeeded.
template <class G>
bool random_step_once(std::mt19937& rng, G& a, G* b, Op& op) {
  const std::size_t ne = genmesh::index_bound(genmesh::edge_index, a);
  const E<G> e(H<G>(static_cast<std::uint32_t>(2 * (rng() % ne) + (rng() % 2))));
  const unsigned pick = rng() % 12;
  op = pick < 4   ? Op::flip
       : pick < 6 ? Op::split_tri
       : pick < 7 ? Op::split
       : pick < 10 ? Op::collapse
       : pick < 11 ? Op::center
                   : Op::uncenter;
  if (a.is_removed(e)) return false;
  const H<G> h = halfedge(e, a);
  switch (op) {
  case Op::flip: {
    if (!genmesh::flip_edge(h, a)) return false;
    if constexpr (genmesh::MutableFaceGraph<G>) {
      if (b) CGAL::Euler::flip_edge(h, *b);
    }
    return true;
  }
  case Op::split: {
    // Plain split then triangulation by split_face, to stay a triangle mesh.
    if (!genmesh::can_split_edge_and_triangulate(h, a)) return false;
    const H<G> oh = opposite(h, a);
    const bool sh = face(h, a) != boost::graph_traits<G>::null_face();
    const bool soh = face(oh, a) != boost::graph_traits<G>::null_face();
    const auto r = genmesh::split_edge(h, a);
    if (!r) return false;
    if (sh) {
      EXPECT_TRUE(genmesh::split_face(*r, next(h, a), a));
    }
    if (soh) {
      EXPECT_TRUE(genmesh::split_face(oh, next(opposite(*r, a), a), a));
    }
    if constexpr (genmesh::MutableFaceGraph<G>) {
      if (b) {
        const H<G> rb = CGAL::Euler::split_edge(h, *b);
        EXPECT_EQ(rb, *r);
        if (sh) CGAL::Euler::split_face(rb, next(h, *b), *b);
        if (soh) CGAL::Euler::split_face(oh, next(opposite(rb, *b), *b), *b);
        put(get(genmesh::vertex_point, *b), target(rb, *b), get(get(genmesh::vertex_point, a), target(*r, a)));
      }
    }
    return true;
  }
  case Op::split_tri: {
    const H<G> oh = opposite(h, a);
    const bool sh = face(h, a) != boost::graph_traits<G>::null_face();
    const bool soh = face(oh, a) != boost::graph_traits<G>::null_face();
    const auto r = genmesh::split_edge_and_triangulate(h, a);
    if (!r) return false;
    if constexpr (genmesh::MutableFaceGraph<G>) {
      if (b) {
        const H<G> rb = CGAL::Euler::split_edge(h, *b);
        if (sh) CGAL::Euler::split_face(rb, next(h, *b), *b);
        if (soh) CGAL::Euler::split_face(oh, next(opposite(rb, *b), *b), *b);
        put(get(genmesh::vertex_point, *b), target(rb, *b), get(get(genmesh::vertex_point, a), target(*r, a)));
      }
    }
    return true;
  }
  case Op::center: {
    const auto r = genmesh::add_center_vertex(h, a);
    if (!r) return false;
    if constexpr (genmesh::MutableFaceGraph<G>) {
      if (b) {
        EXPECT_EQ(CGAL::Euler::add_center_vertex(h, *b), *r);
        put(get(genmesh::vertex_point, *b), target(*r, *b), get(get(genmesh::vertex_point, a), target(*r, a)));
      }
    }
    return true;
  }
  case Op::uncenter: {
    // Only degree-3 vertices, so that the mesh stays a triangle mesh.
    if (genmesh::detail::lo::vertex_degree(target(h, a), a) != 3) return false;
    const auto r = genmesh::remove_center_vertex(h, a);
    if (!r) return false;
    if constexpr (genmesh::MutableFaceGraph<G>) {
      if (b) {
        EXPECT_EQ(CGAL::Euler::remove_center_vertex(h, *b), *r);
      }
    }
    return true;
  }
  case Op::collapse: {
    const bool cgal_link = CGAL::Euler::does_satisfy_link_condition(e, a);
    const auto r = genmesh::collapse_edge(e, a);
    if (!cgal_link) {
      EXPECT_FALSE(r) << "collapse accepted against CGAL's link condition";
    }
    if (!r) return false;
    if constexpr (genmesh::MutableFaceGraph<G>) {
      if (b) {
        EXPECT_EQ(CGAL::Euler::collapse_edge(e, *b), *r);
      }
    }
    return true;
  }
  }
  return false;
}

// random_step_once, counting successes per operation in done[op].
template <class G>
bool random_step(std::mt19937& rng, G& a, G* b, int* done) {
  Op op{};
  const bool ok = random_step_once(rng, a, b, op);
  if (ok) ++done[static_cast<int>(op)];
  return ok;
}

template <class G>
void run_against_cgal(const Polygon_soup& soup, int steps, int check_every, unsigned seed) {
  G a = make<G>(soup);
  G b = make<G>(soup);
  std::mt19937 rng(seed);
  int done = 0, per_op[op_count] = {};
  for (int i = 0; i < steps; ++i) {
    done += random_step(rng, a, &b, per_op);
    if ((i + 1) % check_every == 0) {
      const auto rep = genmesh::check_mesh(a);
      ASSERT_TRUE(rep.ok()) << "step " << i << ": " << genmesh::to_string(rep);
      ASSERT_EQ(snapshot(a), snapshot(b)) << "step " << i;
    }
  }
  EXPECT_GT(done, steps / 4);
  for (int k = 0; k < op_count; ++k) EXPECT_GE(per_op[k], 5) << "operation " << k;
  EXPECT_EQ(snapshot(a), snapshot(b));
  EXPECT_EQ(canon(a), canon(b));
}

TYPED_TEST(Local_operations_links, EqualToCgalEulerOnIcosphere) {
  run_against_cgal<TypeParam>(genmesh::make_icosphere(1), 1500, 1, 1u);
}
TYPED_TEST(Local_operations_links, EqualToCgalEulerOnGridWithHole) {
  run_against_cgal<TypeParam>(genmesh::make_grid_with_hole(6), 1500, 1, 2u);
}
TYPED_TEST(Local_operations_links, EqualToCgalEulerOnTorus) {
  run_against_cgal<TypeParam>(genmesh::make_torus(8, 6, true), 1500, 1, 3u);
}
TYPED_TEST(Local_operations_links, EqualToCgalEulerOnElephant) {
  run_against_cgal<TypeParam>(genmesh::read_soup(genmesh_test::real_mesh("elephant.off")), 20000, 100, 4u);
}

TYPED_TEST(Local_operations_links, CgalEulerOnOtherOperations) {
  using G = TypeParam;
  G a = make<G>(genmesh::make_cube());
  G b = make<G>(genmesh::make_cube());
  // add_center_vertex on face 0, remove it again, split/join faces, remove a face.
  const H<G> h = halfedge(F<G>(0), a);
  const auto c = genmesh::add_center_vertex(h, a);
  ASSERT_TRUE(c);
  EXPECT_EQ(CGAL::Euler::add_center_vertex(h, b), *c);
  put(get(genmesh::vertex_point, b), target(*c, b), get(get(genmesh::vertex_point, a), target(*c, a)));
  EXPECT_EQ(snapshot(a), snapshot(b));
  const auto r = genmesh::remove_center_vertex(*c, a);
  ASSERT_TRUE(r);
  EXPECT_EQ(CGAL::Euler::remove_center_vertex(*c, b), *r);
  EXPECT_EQ(snapshot(a), snapshot(b));
  const H<G> h1 = halfedge(F<G>(2), a), h2 = next(next(h1, a), a);
  const auto s = genmesh::split_face(h1, h2, a);
  ASSERT_TRUE(s);
  EXPECT_EQ(CGAL::Euler::split_face(h1, h2, b), *s);
  EXPECT_EQ(snapshot(a), snapshot(b));
  const auto j = genmesh::join_face(opposite(*s, a), a);
  ASSERT_TRUE(j);
  EXPECT_EQ(CGAL::Euler::join_face(opposite(*s, b), b), *j);
  EXPECT_EQ(snapshot(a), snapshot(b));
  ASSERT_TRUE(genmesh::euler::remove_face(halfedge(F<G>(3), a), a));
  CGAL::Euler::remove_face(halfedge(F<G>(3), b), b);
  EXPECT_EQ(snapshot(a), snapshot(b));
  ASSERT_TRUE(genmesh::euler::remove_face(halfedge(F<G>(4), a), a));
  CGAL::Euler::remove_face(halfedge(F<G>(4), b), b);
  EXPECT_EQ(snapshot(a), snapshot(b));
  expect_ok(a);
  // add_face back into the holes, as CGAL.
  std::vector<V<G>> corners;
  {
    const Polygon_soup cube = genmesh::make_cube();
    for (auto i : cube.face(3)) corners.push_back(vtx<G>(i));
  }
  const auto f = genmesh::euler::add_face(corners, a);
  ASSERT_TRUE(f);
  EXPECT_EQ(CGAL::Euler::add_face(corners, b), *f);
  EXPECT_EQ(snapshot(a), snapshot(b));
  expect_ok(a);
}

TEST(LocalOperationsAcrossBackends, SameRandomSequenceSameMesh) {
  for (const auto& soup : {genmesh::make_grid_with_hole(8), genmesh::make_torus(10, 8, true),
                           genmesh::read_soup(genmesh_test::real_mesh("elephant.off"))}) {
    genmesh_test::Halfedge_mesh a = make<genmesh_test::Halfedge_mesh>(soup);
    genmesh_test::Surface_mesh b = make<genmesh_test::Surface_mesh>(soup);
    std::mt19937 ra(11), rb(11);
    int na[op_count] = {}, nb[op_count] = {};
    for (int i = 0; i < 10000; ++i) {
      const bool da = random_step(ra, a, static_cast<genmesh_test::Halfedge_mesh*>(nullptr), na);
      const bool db = random_step(rb, b, static_cast<genmesh_test::Surface_mesh*>(nullptr), nb);
      ASSERT_EQ(da, db) << "step " << i;
    }
    for (int k = 0; k < op_count; ++k) EXPECT_GE(na[k], 20) << "operation " << k;
    expect_ok(a);
    expect_ok(b);
    EXPECT_EQ(snapshot(a), snapshot(b));
    EXPECT_EQ(canon(a), canon(b));

    // The incidence mesh, with its native operations: the same successes and
    // refusals, the same elements and links. (Its halfedge(v) and halfedge(f)
    // are derived canonically from the matrices, so those two representatives
    // are not compared.)
    genmesh_test::Incidence_mesh c = make<genmesh_test::Incidence_mesh>(soup);
    std::mt19937 rc(11);
    int nc[op_count] = {};
    std::mt19937 ra2(11);
    genmesh_test::Halfedge_mesh a2 = make<genmesh_test::Halfedge_mesh>(soup);
    int na2[op_count] = {};
    for (int i = 0; i < 10000; ++i) {
      const bool da = random_step(ra2, a2, static_cast<genmesh_test::Halfedge_mesh*>(nullptr), na2);
      const bool dc = random_step(rc, c, static_cast<genmesh_test::Incidence_mesh*>(nullptr), nc);
      ASSERT_EQ(da, dc) << "step " << i;
      if (i % 1000 == 999) {
        ASSERT_EQ(genmesh::to_soup(a2), genmesh::to_soup(c)) << "step " << i;
      }
    }
    expect_ok(c);
    EXPECT_EQ(links(a2), links(c)); // next, prev, target, face of every halfedge: the same indices
    EXPECT_EQ(genmesh::to_soup(a), genmesh::to_soup(c));
  }
}

// The face-level operations (join_face, split_face, euler::remove_face,
// euler::add_face as an ear or a whole hole, erase_edge,
// remove_center_vertex, with add_center_vertex, split_edge and collapse_edge
// to keep the mesh varied) on polygon meshes with borders and holes. Every
// step is drawn with the same number of draws, so two meshes in the same
// state take the same step. Returns the operation and whether it succeeded.
enum class Face_op { join, erase_edge, split_face, remove_face, add_ear, fill_hole, uncenter, center, split_edge, collapse };
constexpr int face_op_count = 10;

template <class G>
std::pair<Face_op, bool> face_step(std::mt19937& rng, G& g) {
  const std::size_t ne = genmesh::index_bound(genmesh::edge_index, g);
  const std::uint32_t r_edge = rng(), r_side = rng(), r_pick = rng(), r_k = rng();
  const E<G> e(H<G>(static_cast<std::uint32_t>(2 * (r_edge % ne))));
  const unsigned pick = r_pick % 20;
  const Face_op op = pick < 3    ? Face_op::join
                     : pick < 5  ? Face_op::erase_edge
                     : pick < 9  ? Face_op::split_face
                     : pick < 11 ? Face_op::remove_face
                     : pick < 13 ? Face_op::add_ear
                     : pick < 14 ? Face_op::fill_hole
                     : pick < 16 ? Face_op::uncenter
                     : pick < 17 ? Face_op::center
                     : pick < 18 ? Face_op::split_edge
                                 : Face_op::collapse;
  if (g.is_removed(e)) return {op, false};
  const H<G> h = r_side % 2 ? opposite(halfedge(e, g), g) : halfedge(e, g);
  const auto null_f = boost::graph_traits<G>::null_face();
  // A border halfedge of e, if any.
  const H<G> b = face(h, g) == null_f ? h : face(opposite(h, g), g) == null_f ? opposite(h, g) : H<G>();
  switch (op) {
  case Face_op::join: return {op, genmesh::join_face(h, g).has_value()};
  case Face_op::erase_edge: return {op, genmesh::erase_edge(e, g).has_value()};
  case Face_op::split_face: {
    H<G> h2 = h;
    for (std::uint32_t i = 0; i < 2 + r_k % 3; ++i) h2 = next(h2, g);
    return {op, genmesh::split_face(h, h2, g).has_value()};
  }
  case Face_op::remove_face: return {op, genmesh::euler::remove_face(h, g)};
  case Face_op::add_ear: {
    if (b == H<G>()) return {op, false};
    const std::vector<V<G>> ear{source(b, g), target(b, g), target(next(b, g), g)};
    return {op, genmesh::euler::add_face(ear, g).has_value()};
  }
  case Face_op::fill_hole: {
    if (b == H<G>()) return {op, false};
    std::vector<V<G>> hole;
    H<G> x = b;
    do {
      hole.push_back(source(x, g));
      x = next(x, g);
    } while (x != b && hole.size() <= 8);
    if (x != b) return {op, false};
    return {op, genmesh::euler::add_face(hole, g).has_value()};
  }
  case Face_op::uncenter: return {op, genmesh::remove_center_vertex(h, g).has_value()};
  case Face_op::center: return {op, genmesh::add_center_vertex(h, g).has_value()};
  case Face_op::split_edge: return {op, genmesh::split_edge(h, g).has_value()};
  case Face_op::collapse: return {op, genmesh::collapse_edge(e, g).has_value()};
  }
  return {op, false};
}

// Halfedge_mesh (generic operations) and Incidence_mesh (native ones) take
// the same random face-level steps: the same success or refusal at every
// step, the same soup, and a valid manifold mesh with simple faces and no
// pinched vertex after every step.
TEST(LocalOperationsAcrossBackends, FaceOperationsSameRefusalsSameMesh) {
  int done[face_op_count] = {}, refused[face_op_count] = {};
  unsigned seed = 21;
  for (const auto& soup : {genmesh::make_grid_with_hole(6), genmesh::make_torus(6, 5, false), genmesh::make_grid(5, 4)}) {
    genmesh_test::Halfedge_mesh a = make<genmesh_test::Halfedge_mesh>(soup);
    genmesh_test::Incidence_mesh c = make<genmesh_test::Incidence_mesh>(soup);
    std::mt19937 ra(seed), rc(seed);
    ++seed;
    for (int i = 0; i < 1500; ++i) {
      const auto [op, da] = face_step(ra, a);
      const auto [opc, dc] = face_step(rc, c);
      ASSERT_EQ(op, opc);
      ASSERT_EQ(da, dc) << "step " << i << ", operation " << static_cast<int>(op);
      ++(da ? done : refused)[static_cast<int>(op)];
      const auto ra_rep = genmesh::check_mesh(a), rc_rep = genmesh::check_mesh(c);
      ASSERT_TRUE(ra_rep.ok()) << "step " << i << ": " << genmesh::to_string(ra_rep);
      ASSERT_TRUE(rc_rep.ok()) << "step " << i << ": " << genmesh::to_string(rc_rep);
      ASSERT_FALSE(some_face_visits_a_vertex_twice(a)) << "step " << i;
      ASSERT_FALSE(some_vertex_is_pinched(a)) << "step " << i;
      ASSERT_EQ(genmesh::to_soup(a), genmesh::to_soup(c)) << "step " << i;
    }
  }
  for (int k = 0; k < face_op_count; ++k) {
    EXPECT_GE(done[k], 10) << "operation " << k;
    EXPECT_GE(refused[k], 1) << "operation " << k;
  }
}

} // namespace
