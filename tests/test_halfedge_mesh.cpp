// tests/test_halfedge_mesh.cpp — genmesh::Halfedge_mesh: index types, concept
// proofs, hand-built meshes, traversal, properties, removal and recycling
// (compared step by step with CGAL::Surface_mesh), garbage collection, memory.
#include <genmesh/concepts.h>
#include <genmesh/halfedge_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <ranges>
#include <set>
#include <sstream>
#include <unordered_set>
#include <vector>

namespace {

using genmesh::Edge_index;
using genmesh::Face_index;
using genmesh::Halfedge_index;
using genmesh::Vertex_index;
using Mesh = genmesh::Halfedge_mesh<>;
using Mesh_f = genmesh::Halfedge_mesh<std::array<float, 3>>;

// ---- concept proofs --------------------------------------------------------

static_assert(genmesh::HalfedgeGraph<Mesh>);
static_assert(genmesh::HalfedgeListGraph<Mesh>);
static_assert(genmesh::VertexListGraph<Mesh>);
static_assert(genmesh::EdgeListGraph<Mesh>);
static_assert(genmesh::FaceGraph<Mesh>);
static_assert(genmesh::FaceListGraph<Mesh>);
static_assert(genmesh::MutableHalfedgeGraph<Mesh>);
static_assert(genmesh::MutableFaceGraph<Mesh>);
static_assert(genmesh::HasVertexPoints<Mesh>);
static_assert(genmesh::HasIndexMap<Mesh, genmesh::vertex_index_t>);
static_assert(genmesh::HasIndexMap<Mesh, genmesh::halfedge_index_t>);
static_assert(genmesh::HasIndexMap<Mesh, genmesh::edge_index_t>);
static_assert(genmesh::HasIndexMap<Mesh, genmesh::face_index_t>);
static_assert(std::is_same_v<genmesh::point_t<Mesh>, Eigen::Vector3d>);

static_assert(genmesh::MutableFaceGraph<Mesh_f>);
static_assert(genmesh::FaceListGraph<Mesh_f>);
static_assert(genmesh::HalfedgeListGraph<Mesh_f>);
static_assert(genmesh::VertexListGraph<Mesh_f>);
static_assert(genmesh::EdgeListGraph<Mesh_f>);
static_assert(genmesh::HasVertexPoints<Mesh_f>);
static_assert(std::is_same_v<genmesh::point_t<Mesh_f>, std::array<float, 3>>);

// Index types: thin, regular, trivially copyable.
static_assert(sizeof(Vertex_index) == 4 && sizeof(Halfedge_index) == 4 && sizeof(Edge_index) == 4);
static_assert(std::is_trivially_copyable_v<Vertex_index> && std::is_trivially_copyable_v<Edge_index>);
static_assert(std::regular<Face_index> && std::totally_ordered<Edge_index>);
static_assert(!std::is_convertible_v<Vertex_index, Face_index>);
static_assert(!std::is_convertible_v<std::uint32_t, Vertex_index>);

// Ranges are std::ranges ranges and CGAL-style pairs.
static_assert(std::ranges::bidirectional_range<genmesh::Range<genmesh::Vertex_iterator>>);
static_assert(std::ranges::bidirectional_range<genmesh::Range<genmesh::Halfedge_iterator>>);
static_assert(std::ranges::forward_range<genmesh::Range<genmesh::Halfedge_around_face_iterator>>);
static_assert(std::ranges::forward_range<genmesh::Range<genmesh::Face_around_target_iterator>>);
static_assert(std::ranges::sized_range<genmesh::Range<genmesh::Vertex_iterator>>);
static_assert(std::is_base_of_v<std::pair<genmesh::Face_iterator, genmesh::Face_iterator>,
                                genmesh::Range<genmesh::Face_iterator>>);

// Properties are boost lvalue property maps, bool included.
static_assert(std::is_same_v<boost::property_traits<genmesh::Vertex_property<bool>>::reference, bool&>);
static_assert(std::is_same_v<boost::property_traits<genmesh::Vertex_property<bool>>::category,
                             boost::lvalue_property_map_tag>);

// ---- negative proof: a graph without next() is not a HalfedgeGraph ----------

} // namespace

namespace fake {
/// Everything a HalfedgeGraph needs, with next() present only if HasNext.
template <bool HasNext>
struct Graph {};
template <bool N>
int edge(int, const Graph<N>&) { return 0; }
template <bool N>
int halfedge(int, const Graph<N>&) { return 0; }
template <bool N>
std::pair<int, bool> halfedge(int, int, const Graph<N>&) { return {0, false}; }
template <bool N>
int opposite(int, const Graph<N>&) { return 0; }
template <bool N>
int source(int, const Graph<N>&) { return 0; }
template <bool N>
int target(int, const Graph<N>&) { return 0; }
template <bool N>
int prev(int, const Graph<N>&) { return 0; }
template <bool N>
  requires N
int next(int, const Graph<N>&) { return 0; }
} // namespace fake

template <bool N>
struct boost::graph_traits<fake::Graph<N>> {
  using vertex_descriptor = int;
  using halfedge_descriptor = int;
  using edge_descriptor = int;
  static int null_halfedge() { return -1; }
  static int null_vertex() { return -1; }
};

static_assert(genmesh::HalfedgeGraph<fake::Graph<true>>, "the fake graph with next() is complete");
static_assert(!genmesh::HalfedgeGraph<fake::Graph<false>>, "without next() it must not model HalfedgeGraph");

namespace {

// ---- a small builder made only of the low-level edits ------------------------

/// Builds polygons on m with add_vertex/add_edge/add_face and the setters;
/// border halfedges are linked into cycles and border vertices point to an
/// incoming border halfedge (as CGAL keeps them). Assumes a manifold input.
/// Works on Surface_mesh too (same member names), to compare the two.
template <class M>
auto build(M& m, const std::vector<Eigen::Vector3d>& pts, const std::vector<std::vector<int>>& polys) {
  using V = decltype(m.add_vertex());
  using H = decltype(m.add_edge());
  using Point = typename M::Point;
  std::vector<V> v;
  for (const auto& p : pts) v.push_back(m.add_vertex(Point(p.x(), p.y(), p.z())));
  std::map<std::pair<int, int>, H> he;
  for (const auto& poly : polys) {
    const auto f = m.add_face();
    std::vector<H> hs;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const int a = poly[k], b = poly[(k + 1) % poly.size()];
      H h;
      if (auto it = he.find({a, b}); it != he.end()) {
        h = it->second;
      } else {
        h = m.add_edge(v[a], v[b]);
        he[{a, b}] = h;
        he[{b, a}] = m.opposite(h);
      }
      m.set_face(h, f);
      m.set_halfedge(v[b], h);
      hs.push_back(h);
    }
    for (std::size_t k = 0; k < hs.size(); ++k) m.set_next(hs[k], hs[(k + 1) % hs.size()]);
    m.set_halfedge(f, hs[0]);
  }
  std::map<V, H> border_out;
  for (H h : m.halfedges())
    if (m.is_border(h)) border_out[m.source(h)] = h;
  for (H h : m.halfedges())
    if (m.is_border(h)) {
      m.set_next(h, border_out.at(m.target(h)));
      m.set_halfedge(m.target(h), h);
    }
  return v;
}

/// Every halfedge invariant of a valid mesh (no removed elements referenced).
template <class M>
void expect_valid(const M& m) {
  std::size_t nh = 0;
  for (Halfedge_index h : m.halfedges()) {
    ++nh;
    ASSERT_TRUE(m.next(h).is_valid() && m.prev(h).is_valid()) << h;
    EXPECT_EQ(m.opposite(m.opposite(h)), h);
    EXPECT_NE(m.opposite(h), h);
    EXPECT_EQ(m.next(m.prev(h)), h);
    EXPECT_EQ(m.prev(m.next(h)), h);
    EXPECT_EQ(m.target(h), m.source(m.next(h)));
    EXPECT_EQ(m.face(m.next(h)), m.face(h));
    EXPECT_EQ(m.edge(m.opposite(h)), m.edge(h));
    EXPECT_FALSE(m.is_removed(m.next(h)));
    EXPECT_FALSE(m.is_removed(m.target(h)));
    if (!m.is_border(h)) {
      EXPECT_FALSE(m.is_removed(m.face(h)));
    }
  }
  EXPECT_EQ(nh, m.n_halfedges());
  EXPECT_EQ(nh, 2 * m.n_edges());
  for (Vertex_index v : m.vertices())
    if (!m.is_isolated(v)) {
      EXPECT_EQ(m.target(m.halfedge(v)), v);
    }
  for (Face_index f : m.faces()) EXPECT_EQ(m.face(m.halfedge(f)), f);
}

//        3
//       /|\          tetrahedron: faces (0,2,1) bottom, (0,1,3), (1,2,3), (2,0,3),
//      / | \         all oriented outwards (counter-clockwise seen from outside)
//     /  |  \        .
//    0---|---2
//     \  |  /
//      \ | /
//        1
const std::vector<Eigen::Vector3d> tet_points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<std::vector<int>> tet_faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};

//     7-------6
//    /|      /|      cube: 8 vertices, 6 quads, outward orientation
//   4-------5 |
//   | 3-----|-2
//   |/      |/
//   0-------1
const std::vector<Eigen::Vector3d> cube_points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::vector<int>> cube_faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                  {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

//   3-------2
//   |     / |        open square: two triangles (0,1,2), (0,2,3); one border loop of 4
//   |   /   |
//   | /     |
//   0-------1
const std::vector<Eigen::Vector3d> square_points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<std::vector<int>> square_faces = {{0, 1, 2}, {0, 2, 3}};

// ---- index types -----------------------------------------------------------

TEST(Index, DefaultIsInvalidAndOrdered) {
  Vertex_index v;
  EXPECT_FALSE(v.is_valid());
  EXPECT_EQ(v, Mesh::null_vertex());
  EXPECT_EQ(v, boost::graph_traits<Mesh>::null_vertex());
  EXPECT_EQ(Face_index(), boost::graph_traits<Mesh>::null_face());
  EXPECT_EQ(Halfedge_index(), boost::graph_traits<Mesh>::null_halfedge());
  Vertex_index a(3), b(7);
  EXPECT_TRUE(a.is_valid());
  EXPECT_EQ(a.idx(), 3u);
  EXPECT_LT(a, b);
  EXPECT_LE(a, a);
  EXPECT_TRUE((a <=> b) < 0);
  EXPECT_LT(b, v); // invalid sorts last
  std::unordered_set<Vertex_index> s{a, b, a};
  EXPECT_EQ(s.size(), 2u);
  EXPECT_NE(std::hash<Vertex_index>{}(a), std::hash<Vertex_index>{}(b));
  std::ostringstream os;
  os << a << ' ' << Halfedge_index(2) << ' ' << Face_index() << ' ' << Edge_index(5) << ' ' << Edge_index();
  EXPECT_EQ(os.str(), "v3 h2 f-null e5 e-null");
  EXPECT_FALSE(Edge_index().is_valid());
  EXPECT_EQ(Edge_index(), boost::graph_traits<Mesh>::edge_descriptor());
  EXPECT_EQ(Edge_index(Halfedge_index(7)), Edge_index(3));
  EXPECT_EQ(Edge_index(Halfedge_index(7)).halfedge(), Halfedge_index(7));
  EXPECT_LT(Edge_index(Halfedge_index(5)), Edge_index(Halfedge_index(6)));
}

// ---- hand-built meshes and traversal ---------------------------------------

TEST(Build, TetrahedronInvariantsAndCounts) {
  Mesh m;
  build(m, tet_points, tet_faces);
  expect_valid(m);
  EXPECT_EQ(num_vertices(m), 4u);
  EXPECT_EQ(num_edges(m), 6u);
  EXPECT_EQ(num_halfedges(m), 12u);
  EXPECT_EQ(num_faces(m), 4u);
  // Euler characteristic of a sphere.
  EXPECT_EQ(int(m.n_vertices()) - int(m.n_edges()) + int(m.n_faces()), 2);
  for (Halfedge_index h : m.halfedges()) EXPECT_FALSE(m.is_border(h));
  for (Vertex_index v : m.vertices()) {
    EXPECT_FALSE(m.is_border(v));
    EXPECT_EQ(m.degree(v), 3u);
    EXPECT_EQ(degree(v, m), 3u);
    EXPECT_EQ(out_degree(v, m), 3u);
  }
  for (Face_index f : m.faces()) EXPECT_EQ(degree(f, m), 3u);
  EXPECT_EQ(m.point(Vertex_index(3)), Eigen::Vector3d(0, 0, 1));
}

TEST(Build, CubeQuads) {
  Mesh m;
  build(m, cube_points, cube_faces);
  expect_valid(m);
  EXPECT_EQ(m.n_vertices(), 8u);
  EXPECT_EQ(m.n_edges(), 12u);
  EXPECT_EQ(m.n_faces(), 6u);
  for (Face_index f : m.faces()) EXPECT_EQ(m.degree(f), 4u);
  for (Vertex_index v : m.vertices()) EXPECT_EQ(m.degree(v), 3u);
}

TEST(Traversal, AroundFaceFollowsInputOrder) {
  Mesh m;
  const auto v = build(m, cube_points, cube_faces);
  for (std::size_t i = 0; i < cube_faces.size(); ++i) {
    const Face_index f(static_cast<std::uint32_t>(i));
    std::vector<Vertex_index> got(m.vertices_around_face(m.halfedge(f)).begin(),
                                  m.vertices_around_face(m.halfedge(f)).end());
    ASSERT_EQ(got.size(), cube_faces[i].size());
    // halfedge(f) is the first halfedge, which targets the polygon's 2nd vertex.
    for (std::size_t k = 0; k < got.size(); ++k)
      EXPECT_EQ(got[k], v[cube_faces[i][(k + 1) % got.size()]]);
    std::size_t n = 0;
    for (Halfedge_index h : m.halfedges_around_face(f)) {
      EXPECT_EQ(m.face(h), f);
      ++n;
    }
    EXPECT_EQ(n, 4u);
  }
}

TEST(Traversal, AroundTargetAndHalfedgeLookup) {
  Mesh m;
  const auto v = build(m, tet_points, tet_faces);
  for (Vertex_index x : m.vertices()) {
    std::set<Vertex_index> nbrs;
    for (Halfedge_index h : m.halfedges_around_target(x)) EXPECT_EQ(m.target(h), x);
    for (Vertex_index y : m.vertices_around_target(x)) nbrs.insert(y);
    EXPECT_EQ(nbrs.size(), 3u);
    EXPECT_FALSE(nbrs.contains(x));
    std::set<Face_index> fs;
    for (Face_index f : m.faces_around_target(x)) fs.insert(f);
    EXPECT_EQ(fs.size(), 3u);
    for (Vertex_index y : nbrs) {
      const auto [h, found] = halfedge(y, x, m);
      ASSERT_TRUE(found);
      EXPECT_EQ(m.source(h), y);
      EXPECT_EQ(m.target(h), x);
      const auto [e, efound] = edge(x, y, m);
      EXPECT_TRUE(efound);
      EXPECT_EQ(e, m.edge(h));
    }
  }
  // Vertices of a tetrahedron are all adjacent: no missing edge to find; an
  // isolated vertex has none.
  const Vertex_index lone = m.add_vertex(Eigen::Vector3d(5, 5, 5));
  EXPECT_FALSE(halfedge(v[0], lone, m).second);
  EXPECT_FALSE(edge(lone, v[0], m).second);
  EXPECT_TRUE(m.is_isolated(lone));
  EXPECT_TRUE(m.is_border(lone));
  EXPECT_EQ(m.degree(lone), 0u);
  EXPECT_TRUE(m.halfedges_around_target(lone).empty());
  EXPECT_TRUE(m.vertices_around_face(Halfedge_index()).empty());
}

TEST(Traversal, BorderOfOpenSquare) {
  Mesh m;
  const auto v = build(m, square_points, square_faces);
  expect_valid(m);
  EXPECT_EQ(m.n_edges(), 5u);
  std::size_t border = 0;
  for (Halfedge_index h : m.halfedges()) border += m.is_border(h);
  EXPECT_EQ(border, 4u);
  // The border is one cycle of 4 halfedges, each with a null face.
  Halfedge_index b;
  for (Halfedge_index h : m.halfedges())
    if (m.is_border(h)) b = h;
  std::size_t loop = 0;
  for (Halfedge_index h : m.halfedges_around_face(b)) {
    EXPECT_EQ(m.face(h), Mesh::null_face());
    ++loop;
  }
  EXPECT_EQ(loop, 4u);
  for (Vertex_index x : m.vertices()) {
    EXPECT_TRUE(m.is_border(x));
    EXPECT_TRUE(m.is_border(x, false)); // builder keeps border halfedges on border vertices
  }
  // faces_around_target reports the border as null_face(), like CGAL.
  std::vector<Face_index> around0(m.faces_around_target(v[0]).begin(), m.faces_around_target(v[0]).end());
  EXPECT_EQ(around0.size(), 3u);
  EXPECT_EQ(std::ranges::count(around0, Mesh::null_face()), 1);
  EXPECT_EQ(m.degree(v[1]), 2u);
  EXPECT_TRUE(m.is_border(m.edge(m.halfedge(v[1], v[2]))));
  EXPECT_FALSE(m.is_border(m.edge(m.halfedge(v[0], v[2]))));
}

TEST(Traversal, FreeFunctionsAgreeWithMembers) {
  Mesh m;
  build(m, cube_points, cube_faces);
  for (Halfedge_index h : halfedges(m)) {
    EXPECT_EQ(next(h, m), m.next(h));
    EXPECT_EQ(prev(h, m), m.prev(h));
    EXPECT_EQ(opposite(h, m), m.opposite(h));
    EXPECT_EQ(target(h, m), m.target(h));
    EXPECT_EQ(source(h, m), m.source(h));
    EXPECT_EQ(face(h, m), m.face(h));
    // As on Surface_mesh, an edge made from h remembers h; one made from an
    // index holds halfedge 2e. Both are the same edge.
    EXPECT_EQ(halfedge(edge(h, m), m), h);
    EXPECT_EQ(halfedge(Edge_index(h.idx() / 2), m), Halfedge_index(h.idx() & ~1u));
    EXPECT_EQ(edge(h, m), edge(opposite(h, m), m));
    EXPECT_EQ(std::hash<Edge_index>{}(edge(h, m)), std::hash<Edge_index>{}(edge(opposite(h, m), m)));
    EXPECT_EQ(source(edge(h, m), m), m.source(h));
  }
  for (Vertex_index v : vertices(m)) {
    std::size_t n_out = 0, n_in = 0;
    std::set<Vertex_index> out_targets;
    for (Edge_index e : out_edges(v, m)) {
      EXPECT_EQ(source(e, m), v);
      out_targets.insert(target(e, m));
      ++n_out;
    }
    for (Edge_index e : in_edges(v, m)) {
      EXPECT_EQ(target(e, m), v);
      ++n_in;
    }
    std::set<Vertex_index> adj(adjacent_vertices(v, m).begin(), adjacent_vertices(v, m).end());
    EXPECT_EQ(n_out, degree(v, m));
    EXPECT_EQ(n_in, in_degree(v, m));
    EXPECT_EQ(out_targets, adj);
  }
  {
    const auto [e, found] = edge(Vertex_index(0), Vertex_index(1), m);
    ASSERT_TRUE(found);
    EXPECT_EQ(source(e, m), Vertex_index(0)) << "edge(u, v) is oriented u -> v";
    EXPECT_EQ(target(e, m), Vertex_index(1));
  }
  for (Edge_index e : edges(m)) {
    EXPECT_EQ(source(e, m), m.source(halfedge(e, m)));
    EXPECT_EQ(target(e, m), m.target(halfedge(e, m)));
    EXPECT_EQ(m.halfedge(e, 1), m.opposite(m.halfedge(e, 0)));
  }
  // Pair-like ranges, as CGAL code uses them.
  auto [vb, ve] = vertices(m);
  EXPECT_EQ(std::distance(vb, ve), 8);
  boost::graph_traits<Mesh>::halfedge_iterator hb, he;
  boost::tie(hb, he) = halfedges(m);
  EXPECT_EQ(std::distance(hb, he), 24);
  std::tie(hb, he) = halfedges(m);
  EXPECT_EQ(*std::prev(he), Halfedge_index(23));
  EXPECT_EQ(std::ranges::distance(faces(m)), 6);
  EXPECT_EQ(faces(m).size(), 6u);
  EXPECT_EQ(m.halfedges_around_face(Face_index(0)).size(), 4u);
  EXPECT_EQ(m.vertices_around_target(Vertex_index(0)).size(), 3u);
  EXPECT_EQ(std::ranges::distance(edges(m)), 12);
  auto vpm = get(genmesh::vertex_point, m);
  auto vim = get(genmesh::vertex_index, m);
  for (Vertex_index x : vertices(m)) {
    EXPECT_EQ(get(vpm, x), m.point(x));
    EXPECT_EQ(get(vim, x), x.idx());
  }
  EXPECT_EQ(index_bound(genmesh::halfedge_index, m), m.halfedges_size());
  EXPECT_EQ(get(get(genmesh::face_index, m), Face_index(4)), 4u);
  put(vpm, Vertex_index(0), Eigen::Vector3d(9, 9, 9));
  EXPECT_EQ(m.point(Vertex_index(0)), Eigen::Vector3d(9, 9, 9));
}

// ---- properties ------------------------------------------------------------

TEST(Build, OtherPointTypeAndFreeAdders) {
  Mesh_f m;
  const Vertex_index a = add_vertex(m);
  const Vertex_index b = add_vertex(std::array<float, 3>{1, 2, 3}, m);
  EXPECT_EQ(m.point(a), (std::array<float, 3>{0, 0, 0})) << "default point is the origin";
  EXPECT_EQ(get(get(genmesh::vertex_point, m), b)[2], 3.0f);
  const Edge_index e = add_edge(m);
  set_target(halfedge(e, m), b, m);
  set_target(opposite(halfedge(e, m), m), a, m);
  set_next(halfedge(e, m), opposite(halfedge(e, m), m), m);
  set_next(opposite(halfedge(e, m), m), halfedge(e, m), m);
  set_halfedge(b, halfedge(e, m), m);
  set_halfedge(a, opposite(halfedge(e, m), m), m);
  // A lone edge: each halfedge is the other's next, both are border.
  expect_valid(m);
  EXPECT_EQ(m.degree(a), 1u);
  const Face_index f = add_face(m);
  set_face(halfedge(e, m), f, m);
  set_halfedge(f, halfedge(e, m), m);
  EXPECT_EQ(face(halfedge(e, m), m), f);
  EXPECT_EQ(halfedge(f, m), halfedge(e, m));
  EXPECT_EQ(degree(f, m), 2u);
  reserve(m, 100, 300, 200);
  remove_face(f, m);
  remove_edge(e, m);
  remove_vertex(a, m);
  EXPECT_EQ(num_faces(m), 0u);
  EXPECT_EQ(num_edges(m), 0u);
  EXPECT_EQ(num_halfedges(m), 0u);
  EXPECT_EQ(num_vertices(m), 1u);
  EXPECT_EQ(index_bound(genmesh::vertex_index, m), 2u);
  const auto maps = collect_garbage(m);
  EXPECT_EQ(maps.vertices[b.idx()], Vertex_index(0));
  EXPECT_EQ(m.point(Vertex_index(0)), (std::array<float, 3>{1, 2, 3}));
}

TEST(Properties, AddFindRemove) {
  Mesh m;
  build(m, tet_points, tet_faces);
  auto w = m.add_vertex_property<double>("v:weight", 1.5);
  EXPECT_TRUE(m.has_vertex_property("v:weight"));
  for (Vertex_index v : m.vertices()) EXPECT_EQ(w[v], 1.5);
  w[Vertex_index(2)] = 4.0;
  auto found = m.get_vertex_property<double>("v:weight");
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ((*found)[Vertex_index(2)], 4.0);
  EXPECT_FALSE(m.get_vertex_property<int>("v:weight").has_value()) << "wrong type is not found";
  EXPECT_FALSE(m.get_vertex_property<double>("v:nothing").has_value());
  EXPECT_THROW(m.add_vertex_property<int>("v:weight"), genmesh::invalid_input);
  // vertex_property() finds or adds.
  EXPECT_EQ(m.vertex_property<double>("v:weight")[Vertex_index(2)], 4.0);
  auto e = m.edge_property<int>("e:tag", 7);
  auto h = m.add_halfedge_property<int>("h:tag", -1);
  auto f = m.add_face_property<std::string>("f:name", "x");
  EXPECT_EQ(e[Edge_index(5)], 7);
  EXPECT_EQ(h[Halfedge_index(11)], -1);
  EXPECT_EQ(f[Face_index(3)], "x");
  EXPECT_TRUE(m.remove_vertex_property(w));
  EXPECT_FALSE(w);
  EXPECT_FALSE(m.has_vertex_property("v:weight"));
  EXPECT_FALSE(m.remove_vertex_property(w));
  // The positions cannot be removed.
  auto pts = m.points();
  EXPECT_FALSE(m.remove_vertex_property(pts));
  EXPECT_TRUE(m.has_vertex_property("v:point"));
  EXPECT_TRUE(m.remove_face_property(f));
}

TEST(Properties, ResizeWithElementsAndResetOnRecycle) {
  Mesh m;
  auto w = m.add_vertex_property<int>("v:w", 42);
  const Vertex_index a = m.add_vertex(), b = m.add_vertex();
  EXPECT_EQ(w[a], 42);
  w[b] = 1;
  EXPECT_EQ(w.size(), 2u);
  m.remove_vertex(b);
  const Vertex_index c = m.add_vertex(); // recycles b
  EXPECT_EQ(c, b);
  EXPECT_EQ(w[c], 42) << "a recycled vertex gets default property values, as in Surface_mesh";
  for (int i = 0; i < 100; ++i) m.add_vertex();
  EXPECT_EQ(w.size(), m.vertices_size());
  EXPECT_EQ(w[Vertex_index(101)], 42);
}

TEST(Properties, BoolIsReal) {
  Mesh m;
  build(m, cube_points, cube_faces);
  auto sel = m.add_edge_property<bool>("e:selected", false);
  bool& r = sel[Edge_index(3)];
  r = true;
  EXPECT_TRUE(sel[Edge_index(3)]);
  put(sel, Edge_index(4), true);
  put(sel, Edge_index(6), 0); // a value of another type converts
  EXPECT_FALSE(sel[Edge_index(6)]);
  EXPECT_TRUE(get(sel, Edge_index(4)));
  EXPECT_TRUE(boost::get(sel, Edge_index(4)));
  std::size_t n = 0;
  for (Edge_index e : m.edges()) n += sel[e];
  EXPECT_EQ(n, 2u);
  // One byte each, so the reference stays valid as an lvalue of its own.
  bool* p = &sel[Edge_index(5)];
  *p = true;
  EXPECT_TRUE(sel[Edge_index(5)]);
}

TEST(Properties, ScopedAreRemovedAtScopeEnd) {
  Mesh m;
  build(m, tet_points, tet_faces);
  m.shrink_to_fit();
  const auto names_before = m.property_names<Vertex_index>();
  const std::size_t bytes_before = m.memory_bytes();
  {
    genmesh::Scoped_vertex_property<int> s(m, 3);
    genmesh::Scoped_face_property<bool> t(m);
    EXPECT_GE(m.memory_bytes(), bytes_before + 4 * sizeof(int) + 4 * sizeof(bool));
    EXPECT_EQ(s[Vertex_index(1)], 3);
    s[Vertex_index(1)] = 5;
    EXPECT_EQ(get(s.map(), Vertex_index(1)), 5);
    EXPECT_FALSE(t[Face_index(0)]);
    EXPECT_EQ(m.property_names<Vertex_index>(), names_before) << "scoped properties are anonymous";
    genmesh::Scoped_vertex_property<int> moved = std::move(s);
    EXPECT_EQ(moved[Vertex_index(1)], 5);
    {
      genmesh::Scoped_vertex_property<int> inner(m, 1);
      moved = std::move(inner); // the old array of `moved` goes now
    }
    EXPECT_EQ(moved[Vertex_index(1)], 1);
    const Vertex_index v = m.add_vertex(); // resizes scoped properties too
    EXPECT_EQ(moved[v], 1);
    m.remove_vertex(v);
  }
  // Every scratch array is gone: memory is back to connectivity + points
  // (the removed vertex is still stored until collected).
  m.collect_garbage();
  EXPECT_EQ(m.memory_bytes(), bytes_before);
  EXPECT_EQ(m.property_names<Vertex_index>(), names_before);
  genmesh::Scoped_vertex_property<int> again(m, 8);
  EXPECT_EQ(again[Vertex_index(1)], 8);
}

TEST(Properties, CopiedWithTheMesh) {
  Mesh m;
  build(m, tet_points, tet_faces);
  auto w = m.add_vertex_property<int>("v:w", 0);
  w[Vertex_index(1)] = 9;
  Mesh c = m;
  auto cw = c.get_vertex_property<int>("v:w");
  ASSERT_TRUE(cw);
  EXPECT_EQ((*cw)[Vertex_index(1)], 9);
  (*cw)[Vertex_index(1)] = 10;
  c.point(Vertex_index(0)) = Eigen::Vector3d(7, 7, 7);
  EXPECT_EQ(w[Vertex_index(1)], 9) << "deep copy";
  EXPECT_EQ(m.point(Vertex_index(0)), Eigen::Vector3d(0, 0, 0));
  Mesh moved = std::move(c);
  EXPECT_EQ(moved.point(Vertex_index(0)), Eigen::Vector3d(7, 7, 7));
  expect_valid(moved);
  Mesh assigned;
  assigned = std::move(moved);
  EXPECT_EQ(assigned.point(Vertex_index(0)), Eigen::Vector3d(7, 7, 7));
  EXPECT_EQ(assigned.n_faces(), 4u);
  Mesh copied;
  copied = assigned;
  copied.point(Vertex_index(0)) = Eigen::Vector3d(1, 1, 1);
  EXPECT_EQ(assigned.point(Vertex_index(0)), Eigen::Vector3d(7, 7, 7));
  EXPECT_EQ((*copied.get_vertex_property<int>("v:w"))[Vertex_index(1)], 10);
  expect_valid(copied);
  m.clear();
  EXPECT_EQ(m.vertices_size(), 0u);
  EXPECT_FALSE(m.has_vertex_property("v:w"));
  EXPECT_TRUE(m.has_vertex_property("v:point"));
  EXPECT_EQ(m.point(m.add_vertex(Eigen::Vector3d(1, 2, 3))), Eigen::Vector3d(1, 2, 3));
}

// ---- removal and recycling, against CGAL::Surface_mesh -----------------------

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;

template <class It>
std::vector<std::uint32_t> raw(It b, It e) {
  std::vector<std::uint32_t> out;
  for (; b != e; ++b) out.push_back(static_cast<std::uint32_t>(std::size_t(*b)));
  return out;
}

void expect_same_state(const Mesh& m, const Surface_mesh& sm) {
  EXPECT_EQ(m.vertices_size(), sm.num_vertices());
  EXPECT_EQ(m.edges_size(), sm.num_edges());
  EXPECT_EQ(m.faces_size(), sm.num_faces());
  // Live counts. (CGAL's num_vertices(sm) is the index bound on Surface_mesh;
  // genmesh's num_vertices(m) is the live count, see concepts/descriptor.h.)
  EXPECT_EQ(m.n_vertices(), sm.number_of_vertices());
  EXPECT_EQ(m.n_edges(), sm.number_of_edges());
  EXPECT_EQ(m.n_halfedges(), sm.number_of_halfedges());
  EXPECT_EQ(m.n_faces(), sm.number_of_faces());
  EXPECT_EQ(num_vertices(m), sm.number_of_vertices());
  EXPECT_EQ(m.halfedges_size(), CGAL::num_halfedges(sm));
  EXPECT_EQ(m.number_of_removed_vertices(), sm.number_of_removed_vertices());
  EXPECT_EQ(m.number_of_removed_edges(), sm.number_of_removed_edges());
  EXPECT_EQ(m.number_of_removed_faces(), sm.number_of_removed_faces());
  EXPECT_EQ(m.has_garbage(), sm.has_garbage());
  EXPECT_EQ(raw(m.vertices().begin(), m.vertices().end()), raw(sm.vertices().begin(), sm.vertices().end()));
  EXPECT_EQ(m.vertices().size(), sm.vertices().size());
  EXPECT_EQ(m.halfedges().size(), sm.halfedges().size());
  EXPECT_EQ(m.edges().size(), sm.edges().size());
  EXPECT_EQ(m.faces().size(), sm.faces().size());
  EXPECT_EQ(raw(m.halfedges().begin(), m.halfedges().end()),
            raw(sm.halfedges().begin(), sm.halfedges().end()));
  EXPECT_EQ(raw(m.faces().begin(), m.faces().end()), raw(sm.faces().begin(), sm.faces().end()));
  std::vector<std::uint32_t> sme;
  for (auto e : sm.edges()) sme.push_back(static_cast<std::uint32_t>(std::size_t(sm.halfedge(e)) / 2));
  EXPECT_EQ(raw(m.edges().begin(), m.edges().end()), sme);
}

TEST(Recycling, SameIndicesAsSurfaceMesh) {
  Mesh m;
  Surface_mesh sm;
  for (int i = 0; i < 6; ++i) EXPECT_EQ(m.add_vertex().idx(), std::size_t(sm.add_vertex()));
  for (int i = 0; i < 5; ++i) EXPECT_EQ(m.add_edge().idx(), std::size_t(sm.add_edge()));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(m.add_face().idx(), std::size_t(sm.add_face()));
  for (std::uint32_t i : {1u, 4u, 2u}) {
    m.remove_vertex(Vertex_index(i));
    sm.remove_vertex(Surface_mesh::Vertex_index(i));
  }
  for (std::uint32_t i : {3u, 0u}) {
    m.remove_edge(Edge_index(i));
    sm.remove_edge(Surface_mesh::Edge_index(Surface_mesh::Halfedge_index(2 * i)));
  }
  m.remove_face(Face_index(2));
  sm.remove_face(Surface_mesh::Face_index(2));
  expect_same_state(m, sm);
  // Most recently freed first.
  EXPECT_EQ(m.add_vertex(), Vertex_index(2));
  EXPECT_EQ(std::size_t(sm.add_vertex()), 2u);
  EXPECT_EQ(m.add_edge(), Halfedge_index(0));
  EXPECT_EQ(std::size_t(sm.add_edge()), 0u);
  EXPECT_EQ(m.add_face(), Face_index(2));
  EXPECT_EQ(std::size_t(sm.add_face()), 2u);
  expect_same_state(m, sm);
  // Recycling off: append even though indices are free.
  m.set_recycle_garbage(false);
  sm.set_recycle_garbage(false);
  EXPECT_FALSE(m.does_recycle_garbage());
  EXPECT_EQ(m.add_vertex(), Vertex_index(6));
  EXPECT_EQ(std::size_t(sm.add_vertex()), 6u);
  expect_same_state(m, sm);
  m.set_recycle_garbage(true);
  sm.set_recycle_garbage(true);
  EXPECT_EQ(m.add_vertex().idx(), std::size_t(sm.add_vertex()));
  expect_same_state(m, sm);
}

TEST(Recycling, EdgesRememberTheirHalfedgeLikeSurfaceMesh) {
  Mesh m;
  Surface_mesh sm;
  for (int i = 0; i < 3; ++i) {
    m.add_edge();
    sm.add_edge();
  }
  for (std::uint32_t i = 0; i < 6; ++i) {
    const Halfedge_index h(i);
    const Surface_mesh::Halfedge_index sh(i);
    EXPECT_EQ(halfedge(edge(h, m), m).idx(), std::size_t(halfedge(edge(sh, sm), sm)));
    EXPECT_EQ(edge(h, m).idx(), std::size_t(edge(sh, sm)));
  }
  for (std::uint32_t i = 0; i < 3; ++i)
    EXPECT_EQ(halfedge(Edge_index(i), m).idx(), std::size_t(halfedge(Surface_mesh::Edge_index(i), sm)));
}

TEST(Recycling, RandomSequenceMatchesSurfaceMesh) {
  // A deterministic mix of adds and removes of every kind, and now and then a
  // garbage collection in Surface_mesh's order, compared after every step:
  // returned indices, counts, iteration order, links, and per-element serial
  // numbers kept in properties on both meshes (so recycling resets and
  // compaction moves are compared too). Links are kept in range, as
  // Surface_mesh's collect_garbage needs: every live halfedge has a target
  // and a next, every face points to the never-removed anchor edge, and a
  // vertex is removed only when no live halfedge targets it.
  Mesh m;
  Surface_mesh sm;
  using SV = Surface_mesh::Vertex_index;
  using SH = Surface_mesh::Halfedge_index;
  using SE = Surface_mesh::Edge_index;
  using SF = Surface_mesh::Face_index;
  auto vid = m.add_vertex_property<int>("v:id", -1);
  auto eid = m.add_edge_property<int>("e:id", -1);
  auto fid = m.add_face_property<int>("f:id", -1);
  auto svid = sm.add_property_map<SV, int>("v:id", -1).first;
  auto seid = sm.add_property_map<SE, int>("e:id", -1).first;
  auto sfid = sm.add_property_map<SF, int>("f:id", -1).first;
  int serial = 0;
  std::uint32_t state = 12345;
  auto rnd = [&](std::uint32_t n) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % n;
  };
  int removals = 0, recycled = 0;
  auto add_vertex = [&] {
    recycled += m.does_recycle_garbage() && m.number_of_removed_vertices() > 0;
    const Vertex_index v = m.add_vertex();
    const SV sv = sm.add_vertex();
    EXPECT_EQ(v.idx(), std::size_t(sv));
    EXPECT_EQ(vid[v], -1) << "recycled elements get default values";
    EXPECT_EQ(svid[sv], -1);
    vid[v] = svid[sv] = serial++;
    return std::pair{v, sv};
  };
  auto add_edge = [&](Vertex_index a, SV sa, Vertex_index b, SV sb) {
    recycled += m.does_recycle_garbage() && m.number_of_removed_edges() > 0;
    const Halfedge_index h = m.add_edge(a, b);
    const SH sh = sm.add_edge(sa, sb);
    EXPECT_EQ(h.idx(), std::size_t(sh));
    m.set_next(h, m.opposite(h));
    m.set_next(m.opposite(h), h);
    sm.set_next(sh, sm.opposite(sh));
    sm.set_next(sm.opposite(sh), sh);
    EXPECT_EQ(eid[m.edge(h)], -1);
    eid[m.edge(h)] = seid[sm.edge(sh)] = serial++;
    return h;
  };
  const auto [va, sva] = add_vertex();
  const auto [vb, svb] = add_vertex();
  Halfedge_index anchor = add_edge(va, sva, vb, svb);
  const int anchor_id = eid[m.edge(anchor)];
  int collections = 0;
  for (int step = 0; step < 800; ++step) {
    const std::uint32_t op = rnd(8);
    if (op == 0) {
      add_vertex();
    } else if (op == 1) {
      const auto [a, sa] = add_vertex();
      const auto [b, sb] = add_vertex();
      add_edge(a, sa, b, sb);
    } else if (op == 6) {
      // An edge between the anchor's vertices.
      add_edge(m.source(anchor), SV(m.source(anchor).idx()), m.target(anchor), SV(m.target(anchor).idx()));
    } else if (op == 2) {
      const Face_index f = m.add_face();
      const SF sf = sm.add_face();
      EXPECT_EQ(f.idx(), std::size_t(sf));
      EXPECT_EQ(fid[f], -1);
      fid[f] = sfid[sf] = serial++;
      m.set_halfedge(f, anchor);
      sm.set_halfedge(sf, SH(anchor.idx()));
    } else if (op == 3 && m.n_vertices() > 0) {
      auto it = m.vertices().begin();
      std::advance(it, rnd(static_cast<std::uint32_t>(m.n_vertices())));
      const Vertex_index v = *it;
      if (std::ranges::none_of(m.halfedges(), [&](Halfedge_index h) { return m.target(h) == v; })) {
        m.remove_vertex(v);
        sm.remove_vertex(SV(v.idx()));
        ++removals;
      }
    } else if (op == 4 && m.n_edges() > 0) {
      auto it = m.edges().begin();
      std::advance(it, rnd(static_cast<std::uint32_t>(m.n_edges())));
      if (eid[*it] != anchor_id) {
        m.remove_edge(*it);
        sm.remove_edge(SE(SH(2 * (*it).idx())));
        ++removals;
      }
    } else if (op == 5 && m.n_faces() > 0) {
      auto it = m.faces().begin();
      std::advance(it, rnd(static_cast<std::uint32_t>(m.n_faces())));
      m.remove_face(*it);
      sm.remove_face(SF((*it).idx()));
      ++removals;
    } else if (op == 7 && rnd(8) == 0) {
      const auto maps = m.collect_garbage(genmesh::Garbage_order::like_surface_mesh);
      sm.collect_garbage();
      anchor = maps.halfedges[anchor.idx()];
      ++collections;
    }
    if (step % 50 == 0) {
      const bool r = rnd(2) == 0;
      m.set_recycle_garbage(r);
      sm.set_recycle_garbage(r);
    }
    expect_same_state(m, sm);
    for (Vertex_index v : m.vertices()) EXPECT_EQ(vid[v], svid[SV(v.idx())]);
    for (Edge_index e : m.edges()) EXPECT_EQ(eid[e], seid[SE(e.idx())]);
    for (Face_index f : m.faces()) {
      EXPECT_EQ(fid[f], sfid[SF(f.idx())]);
      EXPECT_EQ(m.halfedge(f).idx(), std::size_t(sm.halfedge(SF(f.idx()))));
    }
    for (Halfedge_index h : m.halfedges()) {
      EXPECT_EQ(m.target(h).idx(), std::size_t(sm.target(SH(h.idx()))));
      EXPECT_EQ(m.next(h).idx(), std::size_t(sm.next(SH(h.idx()))));
    }
    if (testing::Test::HasFailure()) FAIL() << "diverged at step " << step;
  }
  EXPECT_GT(removals, 50) << "the sequence exercised removal";
  EXPECT_GT(recycled, 20) << "the sequence exercised recycling";
  EXPECT_GT(collections, 1) << "the sequence exercised garbage collection";
}

// ---- garbage collection ----------------------------------------------------

TEST(GarbageCollection, MapsAndPropertiesCompacted) {
  // Two disjoint cubes; the first is removed entirely, the second survives.
  Mesh m;
  build(m, cube_points, cube_faces);
  std::vector<Eigen::Vector3d> shifted = cube_points;
  for (auto& p : shifted) p += Eigen::Vector3d(5, 0, 0);
  std::vector<std::vector<int>> faces2 = cube_faces;
  build(m, shifted, faces2);
  auto vw = m.add_vertex_property<int>("v:w");
  auto hw = m.add_halfedge_property<std::uint32_t>("h:w");
  auto ew = m.add_edge_property<std::uint32_t>("e:w");
  auto fw = m.add_face_property<std::uint32_t>("f:w");
  auto fb = m.add_face_property<bool>("f:b");
  for (Vertex_index v : m.vertices()) vw[v] = 100 + int(v.idx());
  for (Halfedge_index h : m.halfedges()) hw[h] = h.idx();
  for (Edge_index e : m.edges()) ew[e] = e.idx();
  for (Face_index f : m.faces()) {
    fw[f] = f.idx();
    fb[f] = f.idx() % 2 == 1;
  }
  // The first cube's elements are the 8 first vertices, 12 first edges, 6 first faces.
  for (std::uint32_t i = 0; i < 8; ++i) m.remove_vertex(Vertex_index(i));
  for (std::uint32_t i = 0; i < 12; ++i) m.remove_edge(Edge_index(i));
  for (std::uint32_t i = 0; i < 6; ++i) m.remove_face(Face_index(i));
  const Mesh before = m;
  EXPECT_TRUE(m.has_garbage());
  const auto maps = m.collect_garbage();
  EXPECT_FALSE(m.has_garbage());
  ASSERT_EQ(maps.vertices.size(), 16u);
  ASSERT_EQ(maps.halfedges.size(), 48u);
  ASSERT_EQ(maps.edges.size(), 24u);
  ASSERT_EQ(maps.faces.size(), 12u);
  EXPECT_EQ(m.vertices_size(), 8u);
  EXPECT_EQ(m.edges_size(), 12u);
  EXPECT_EQ(m.faces_size(), 6u);
  EXPECT_EQ(m.n_vertices(), m.vertices_size());
  EXPECT_EQ(m.number_of_removed_vertices(), 0u);
  expect_valid(m);
  // Removed map to invalid; survivors keep their relative order.
  auto check_map = [](const auto& map, const auto& removed) {
    std::uint32_t last = 0;
    bool first = true;
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (removed(i)) {
        EXPECT_FALSE(map[i].is_valid()) << i;
        continue;
      }
      ASSERT_TRUE(map[i].is_valid()) << i;
      if (!first) {
        EXPECT_GT(map[i].idx(), last);
      }
      last = map[i].idx();
      first = false;
    }
  };
  check_map(maps.vertices, [&](std::size_t i) { return before.is_removed(Vertex_index(std::uint32_t(i))); });
  check_map(maps.halfedges, [&](std::size_t i) { return before.is_removed(Halfedge_index(std::uint32_t(i))); });
  check_map(maps.edges, [&](std::size_t i) { return before.is_removed(Edge_index(std::uint32_t(i))); });
  check_map(maps.faces, [&](std::size_t i) { return before.is_removed(Face_index(std::uint32_t(i))); });
  // Connectivity, points and properties follow the maps.
  for (Halfedge_index h : before.halfedges()) {
    const Halfedge_index n = maps.halfedges[h.idx()];
    EXPECT_EQ(m.next(n), maps.halfedges[before.next(h).idx()]);
    EXPECT_EQ(m.target(n), maps.vertices[before.target(h).idx()]);
    EXPECT_EQ(m.face(n), maps.faces[before.face(h).idx()]);
    EXPECT_EQ(hw[n], h.idx());
  }
  for (Vertex_index v : before.vertices()) {
    const Vertex_index n = maps.vertices[v.idx()];
    EXPECT_EQ(m.point(n), before.point(v));
    EXPECT_EQ(vw[n], 100 + int(v.idx()));
  }
  for (Edge_index e : before.edges()) EXPECT_EQ(ew[maps.edges[e.idx()]], e.idx());
  for (Face_index f : before.faces()) {
    EXPECT_EQ(fw[maps.faces[f.idx()]], f.idx());
    EXPECT_EQ(fb[maps.faces[f.idx()]], f.idx() % 2 == 1);
  }
  EXPECT_EQ(vw.size(), 8u);
  EXPECT_EQ(hw.size(), 24u);
  // Collecting a clean mesh changes nothing and maps identically.
  const auto again = m.collect_garbage();
  for (std::size_t i = 0; i < again.vertices.size(); ++i) EXPECT_EQ(again.vertices[i].idx(), i);
  EXPECT_EQ(again.faces.size(), 6u);
}

TEST(GarbageCollection, LikeSurfaceMeshOrderMatchesCgal) {
  // Same edits on both meshes: cube A, 3 isolated vertices, cube B; then cube
  // A and one isolated vertex are removed, so survivors must move down.
  Mesh m;
  Surface_mesh sm;
  std::vector<Eigen::Vector3d> shifted = cube_points;
  for (auto& p : shifted) p += Eigen::Vector3d(5, 0, 0);
  auto edit = [&](auto& g) {
    using P = typename std::remove_reference_t<decltype(g)>::Point;
    build(g, cube_points, cube_faces);
    for (int i = 0; i < 3; ++i) g.add_vertex(P(-1, -1, double(i)));
    build(g, shifted, cube_faces);
    using V = decltype(g.add_vertex());
    using E = decltype(g.edge(g.add_edge()));
    using F = decltype(g.add_face());
    for (std::uint32_t i = 0; i < 8; ++i) g.remove_vertex(V(i));
    g.remove_vertex(V(9));
    for (std::uint32_t i = 0; i < 12; ++i) g.remove_edge(E(i));
    for (std::uint32_t i = 0; i < 6; ++i) g.remove_face(F(i));
  };
  edit(m);
  edit(sm);
  const auto maps = m.collect_garbage(genmesh::Garbage_order::like_surface_mesh);
  sm.collect_garbage();
  ASSERT_EQ(m.vertices_size(), sm.num_vertices());
  ASSERT_EQ(m.halfedges_size(), sm.num_halfedges());
  ASSERT_EQ(m.faces_size(), sm.num_faces());
  expect_valid(m);
  using SV = Surface_mesh::Vertex_index;
  using SH = Surface_mesh::Halfedge_index;
  using SF = Surface_mesh::Face_index;
  for (std::uint32_t i = 0; i < m.vertices_size(); ++i) {
    const auto& p = m.point(Vertex_index(i));
    const auto& q = sm.point(SV(i));
    EXPECT_EQ(p, Eigen::Vector3d(q.x(), q.y(), q.z())) << i;
    EXPECT_EQ(m.halfedge(Vertex_index(i)).idx(), std::size_t(sm.halfedge(SV(i))));
  }
  for (std::uint32_t i = 0; i < m.halfedges_size(); ++i) {
    EXPECT_EQ(m.next(Halfedge_index(i)).idx(), std::size_t(sm.next(SH(i))));
    EXPECT_EQ(m.target(Halfedge_index(i)).idx(), std::size_t(sm.target(SH(i))));
    EXPECT_EQ(m.face(Halfedge_index(i)).idx(), std::size_t(sm.face(SH(i))));
  }
  for (std::uint32_t i = 0; i < m.faces_size(); ++i)
    EXPECT_EQ(m.halfedge(Face_index(i)).idx(), std::size_t(sm.halfedge(SF(i))));
  // Not order-preserving: the last live vertex fills the first hole.
  EXPECT_EQ(maps.vertices[18], Vertex_index(0));
}

TEST(GarbageCollection, InterleavedRemovalKeepsOrder) {
  Mesh m;
  for (int i = 0; i < 10; ++i) m.add_vertex(Eigen::Vector3d(i, 0, 0));
  for (std::uint32_t i : {0u, 3u, 4u, 9u}) m.remove_vertex(Vertex_index(i));
  // Iteration skips removed elements both ways.
  std::vector<std::uint32_t> fwd, bwd;
  for (Vertex_index v : m.vertices()) fwd.push_back(v.idx());
  for (Vertex_index v : m.vertices() | std::views::reverse) bwd.push_back(v.idx());
  EXPECT_EQ(fwd, (std::vector<std::uint32_t>{1, 2, 5, 6, 7, 8}));
  std::ranges::reverse(bwd);
  EXPECT_EQ(bwd, fwd);
  EXPECT_EQ(m.vertices().size(), 6u);
  const auto maps = m.collect_garbage();
  std::vector<double> xs;
  for (Vertex_index v : m.vertices()) xs.push_back(m.point(v).x());
  EXPECT_EQ(xs, (std::vector<double>{1, 2, 5, 6, 7, 8}));
  EXPECT_EQ(maps.vertices[5], Vertex_index(2));
  EXPECT_FALSE(maps.vertices[9].is_valid());
  // After collection, new elements append (the free list is empty).
  EXPECT_EQ(m.add_vertex(), Vertex_index(6));
}

// ---- memory ----------------------------------------------------------------

TEST(Memory, NotMoreThanSurfaceMeshPerTriangle) {
  // A closed triangulated torus (40 x 30 quads, each split in two): V, E, F
  // in the proportions of any large closed triangle mesh (E = 3F/2, V = F/2).
  const int nu = 40, nv_ring = 30;
  std::vector<Eigen::Vector3d> pts;
  std::vector<std::vector<int>> tris;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv_ring; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, w = 2 * std::numbers::pi * j / nv_ring;
      pts.emplace_back((2 + std::cos(w)) * std::cos(u), (2 + std::cos(w)) * std::sin(u), std::sin(w));
    }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv_ring + (j + nv_ring) % nv_ring; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv_ring; ++j) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  Mesh m;
  build(m, pts, tris);
  expect_valid(m);
  const std::size_t nv = m.n_vertices(), ne = m.n_edges(), nf = m.n_faces();
  ASSERT_EQ(nf, tris.size());
  EXPECT_EQ(int(nv) - int(ne) + int(nf), 0) << "a torus";
  // CGAL::Surface_mesh<Point_3> holds at least: per vertex a 4-byte halfedge
  // and the point; per halfedge next, prev, vertex, face (4 bytes each); per
  // face a halfedge; removed flags one bit each (std::vector<bool>). That is
  // its exact footprint after shrink_to_fit, up to one 8-byte word per flag
  // array.
  const std::size_t cgal_bytes =
      nv * (4 + sizeof(Kernel::Point_3)) + 2 * ne * 16 + nf * 4 + (nv + 7) / 8 + (ne + 7) / 8 + (nf + 7) / 8;
  m.shrink_to_fit();
  const std::size_t ours = m.memory_bytes();
  RecordProperty("bytes_per_triangle", std::to_string(double(ours) / double(nf)));
  RecordProperty("surface_mesh_bytes_per_triangle", std::to_string(double(cgal_bytes) / double(nf)));
  EXPECT_LE(ours, cgal_bytes + 3 * 8);
  // And no less than the data itself (memory_bytes counts everything).
  EXPECT_GE(ours, nv * (4 + sizeof(Eigen::Vector3d)) + 2 * ne * 16 + nf * 4);
  // A property adds at least its payload, and removing it gives it back.
  auto w = m.add_face_property<double>("f:area");
  EXPECT_GE(m.memory_bytes(), ours + nf * sizeof(double));
  m.remove_face_property(w);
  EXPECT_EQ(m.memory_bytes(), ours);
  // Growing by push_back can only add capacity, never more than doubling.
  Mesh grown;
  build(grown, pts, tris);
  EXPECT_GE(grown.memory_bytes(), ours);
  EXPECT_LE(grown.memory_bytes(), 2 * ours);
}

// Every link of every halfedge and the vertex and face halfedges, as numbers.
std::vector<std::uint32_t> all_links(const Mesh& m) {
  std::vector<std::uint32_t> s;
  for (std::uint32_t i = 0; i < m.halfedges_size(); ++i) {
    const genmesh::Halfedge_index h(i);
    for (const std::uint32_t x : {m.next(h).idx(), m.prev(h).idx(), m.target(h).idx(), m.face(h).idx()})
      s.push_back(x);
  }
  for (std::uint32_t i = 0; i < m.vertices_size(); ++i) s.push_back(m.halfedge(genmesh::Vertex_index(i)).idx());
  for (std::uint32_t i = 0; i < m.faces_size(); ++i) s.push_back(m.halfedge(genmesh::Face_index(i)).idx());
  return s;
}

// The halfedge links share one block (next | target | prev and face): growth,
// copies, moves, reserve and shrink_to_fit keep every link.
TEST(Memory, HalfedgeLinksSurviveGrowthCopyMoveAndShrink) {
  Mesh m;
  std::vector<Eigen::Vector3d> pts;
  std::vector<std::vector<int>> quads;
  const int n = 12;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) pts.emplace_back(i, j, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      quads.push_back({j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i});
  build(m, pts, quads); // grows from empty, through many doublings
  expect_valid(m);
  const auto links = all_links(m);
  const Mesh copy = m;
  EXPECT_EQ(all_links(copy), links);
  m.reserve(4 * m.n_vertices(), 4 * m.n_edges(), 4 * m.n_faces());
  EXPECT_EQ(all_links(m), links);
  const std::size_t reserved = m.memory_bytes();
  m.shrink_to_fit();
  EXPECT_EQ(all_links(m), links);
  EXPECT_LT(m.memory_bytes(), reserved);
  EXPECT_EQ(m.memory_bytes(), copy.memory_bytes()); // copies are exact-size
  Mesh moved = std::move(m);
  EXPECT_EQ(all_links(moved), links);
  EXPECT_EQ(m.n_halfedges(), 0u); // NOLINT: the moved-from mesh is empty and usable
  m = moved;
  EXPECT_EQ(all_links(m), links);
  // New edges get null links.
  const genmesh::Halfedge_index h = m.add_edge();
  EXPECT_FALSE(m.next(h).is_valid());
  EXPECT_FALSE(m.prev(m.opposite(h)).is_valid());
  EXPECT_FALSE(m.target(h).is_valid());
  EXPECT_FALSE(m.face(m.opposite(h)).is_valid());
}

} // namespace
