// tests/test_cgal_interop.cpp — <genmesh/adaptors/cgal.h> and <genmesh/adaptors/openmesh.h>:
// CGAL's and OpenMesh's meshes read through genmesh's concepts and tags, and
// CGAL's own algorithms run on genmesh::Halfedge_mesh<K::Point_3> with results
// equal to the same calls on CGAL::Surface_mesh<K::Point_3>.
//
// Equality is checked two ways: `ordered_soup` (vertices and faces in
// iteration order: Halfedge_mesh promises Surface_mesh's index allocation,
// so every CGAL algorithm made of the same low-level edits must give the very
// same indices) and `canonical_soup` (geometry only, independent of
// numbering: what survives a garbage collection, which numbers differently).
#include "backends.h"

#include <genmesh/adaptors/openmesh.h>
#include <genmesh/concepts.h>
#include <genmesh/generators.h>
#include <genmesh/mesh_check.h>
#include <genmesh/properties.h>
#include <genmesh/remeshing.h>
#include <genmesh/simplification.h>
#include <genmesh/subdivision.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_concepts.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/graph_concepts.hpp>
#include <boost/graph/visitors.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using genmesh_test::Kernel;
using genmesh_test::real_mesh;
using Point = Kernel::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point>;
using Hmesh = genmesh::Halfedge_mesh<Point>; // what CGAL's algorithms get
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Polyhedron_with_ids = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
using Om_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
using Om_tri = OpenMesh::TriMesh_ArrayKernelT<>;

// ---- concept proofs: CGAL and OpenMesh meshes as genmesh graphs ------------

template <class G>
constexpr bool models_genmesh_graph() {
  static_assert(genmesh::HalfedgeGraph<G>);
  static_assert(genmesh::HalfedgeListGraph<G>);
  static_assert(genmesh::VertexListGraph<G>);
  static_assert(genmesh::EdgeListGraph<G>);
  static_assert(genmesh::FaceGraph<G>);
  static_assert(genmesh::FaceListGraph<G>);
  static_assert(genmesh::MutableHalfedgeGraph<G>);
  static_assert(genmesh::MutableFaceGraph<G>);
  static_assert(genmesh::HasVertexPoints<G>);
  return true;
}
template <class G>
constexpr bool has_all_index_maps() {
  return genmesh::HasIndexMap<G, genmesh::vertex_index_t> &&
         genmesh::HasIndexMap<G, genmesh::halfedge_index_t> &&
         genmesh::HasIndexMap<G, genmesh::edge_index_t> &&
         genmesh::HasIndexMap<G, genmesh::face_index_t>;
}

static_assert(models_genmesh_graph<Surface_mesh>());
static_assert(models_genmesh_graph<Polyhedron>());
static_assert(models_genmesh_graph<Polyhedron_with_ids>());
static_assert(models_genmesh_graph<Om_poly>());
static_assert(models_genmesh_graph<Om_tri>());
static_assert(models_genmesh_graph<Hmesh>());

static_assert(has_all_index_maps<Surface_mesh>());
static_assert(has_all_index_maps<Polyhedron_with_ids>());
static_assert(has_all_index_maps<Om_poly>());
static_assert(has_all_index_maps<Om_tri>());
static_assert(has_all_index_maps<Hmesh>());
// A Polyhedron_3 without ids has points but no index maps (documented).
static_assert(!genmesh::HasIndexMap<Polyhedron, genmesh::vertex_index_t>);
static_assert(!genmesh::HasIndexMap<Polyhedron, genmesh::face_index_t>);

static_assert(std::is_same_v<genmesh::point_t<Surface_mesh>, Point>);
static_assert(std::is_same_v<genmesh::point_t<Polyhedron>, Point>);
static_assert(std::is_same_v<genmesh::point_t<Om_poly>, OpenMesh::Vec3f>);
static_assert(std::is_same_v<genmesh::point_t<Hmesh>, Point>);
static_assert(genmesh::Point3<Point> && genmesh::Point3<OpenMesh::Vec3f> &&
              genmesh::Point3<OpenMesh::Vec3d>);

// ---- concept proofs: Halfedge_mesh as a CGAL graph (CGAL's own checks) -----

BOOST_CONCEPT_ASSERT((CGAL::HalfedgeGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((CGAL::HalfedgeListGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((CGAL::FaceGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((CGAL::FaceListGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((CGAL::MutableHalfedgeGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((CGAL::MutableFaceGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((boost::EdgeListGraphConcept<Hmesh>));
BOOST_CONCEPT_ASSERT((boost::ReadablePropertyMapConcept<
                      boost::property_map<Hmesh, CGAL::vertex_point_t>::type, genmesh::Vertex_index>));
BOOST_CONCEPT_ASSERT((boost::LvaluePropertyMapConcept<
                      boost::property_map<Hmesh, CGAL::vertex_point_t>::type, genmesh::Vertex_index>));

static_assert(CGAL::graph_has_property<Hmesh, CGAL::vertex_point_t>::value);
// CGAL deduces its kernel from the point map of a Halfedge_mesh<K::Point_3>.
static_assert(std::is_same_v<CGAL::GetGeomTraits<Hmesh>::type, Kernel>);
// Raw indices are not CGAL's dense index maps (num_vertices is live), so CGAL
// must build its own: see cgal.h.
static_assert(!CGAL::graph_has_property<Hmesh, boost::vertex_index_t>::value);
static_assert(!CGAL::graph_has_property<Hmesh, CGAL::face_index_t>::value);

// ---- helpers ---------------------------------------------------------------

using Coords = std::array<double, 3>;

template <class G>
Coords coords(const G& g, typename boost::graph_traits<G>::vertex_descriptor v) {
  const Eigen::Vector3d p = genmesh::to_eigen(get(get(genmesh::vertex_point, g), v));
  return {p.x(), p.y(), p.z()};
}

template <class G>
std::vector<typename boost::graph_traits<G>::vertex_descriptor> face_vertices(
    const G& g, typename boost::graph_traits<G>::face_descriptor f) {
  std::vector<typename boost::graph_traits<G>::vertex_descriptor> out;
  const auto start = halfedge(f, g);
  auto h = start;
  do {
    out.push_back(target(h, g));
    h = next(h, g);
  } while (h != start);
  return out;
}

/// Vertices and faces in iteration order; each face rotated to start at its
/// lowest vertex number (so the choice of halfedge(f) does not matter).
struct Ordered_soup {
  std::vector<Coords> points;
  std::vector<std::vector<std::size_t>> faces;
  bool operator==(const Ordered_soup&) const = default;
};

template <class G>
Ordered_soup ordered_soup(const G& g) {
  Ordered_soup s;
  std::map<typename boost::graph_traits<G>::vertex_descriptor, std::size_t> number;
  for (auto v : vertices(g)) {
    number.emplace(v, s.points.size());
    s.points.push_back(coords(g, v));
  }
  for (auto f : faces(g)) {
    std::vector<std::size_t> face;
    for (auto v : face_vertices(g, f)) face.push_back(number.at(v));
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    s.faces.push_back(std::move(face));
  }
  return s;
}

/// Geometry only: the sorted points, and the sorted faces as point sequences,
/// each rotated to start at its lexicographically smallest point.
struct Canonical_soup {
  std::vector<Coords> points;
  std::vector<std::vector<Coords>> faces;
  bool operator==(const Canonical_soup&) const = default;
};

template <class G>
Canonical_soup canonical_soup(const G& g) {
  Canonical_soup s;
  for (auto v : vertices(g)) s.points.push_back(coords(g, v));
  std::sort(s.points.begin(), s.points.end());
  for (auto f : faces(g)) {
    std::vector<Coords> face;
    for (auto v : face_vertices(g, f)) face.push_back(coords(g, v));
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    s.faces.push_back(std::move(face));
  }
  std::sort(s.faces.begin(), s.faces.end());
  return s;
}

template <class Range>
std::size_t count(const Range& r) {
  return static_cast<std::size_t>(std::distance(r.begin(), r.end()));
}

/// Live counts, whatever num_*(g) means for G.
template <class G>
std::array<std::size_t, 3> live_counts(const G& g) {
  return {count(vertices(g)), count(edges(g)), count(faces(g))};
}

/// The k-th live face in iteration order.
template <class G>
typename boost::graph_traits<G>::face_descriptor nth_face(const G& g, std::size_t k) {
  auto it = faces(g).begin();
  std::advance(it, static_cast<std::ptrdiff_t>(k % count(faces(g))));
  return *it;
}

/// The k-th live edge in iteration order.
template <class G>
typename boost::graph_traits<G>::edge_descriptor nth_edge(const G& g, std::size_t k) {
  auto it = edges(g).begin();
  std::advance(it, static_cast<std::ptrdiff_t>(k % count(edges(g))));
  return *it;
}

/// The file as a polygon soup, read by CGAL.
struct File_soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::size_t num_edges() const {
    std::set<std::pair<std::size_t, std::size_t>> e;
    for (const auto& p : polygons)
      for (std::size_t i = 0; i < p.size(); ++i)
        e.emplace(std::minmax(p[i], p[(i + 1) % p.size()]));
    return e.size();
  }
};

File_soup read_file_soup(const std::string& path) {
  File_soup s;
  if (!CGAL::IO::read_polygon_soup(path, s.points, s.polygons))
    throw std::runtime_error("CGAL cannot read " + path);
  return s;
}

template <class G>
void read_with_cgal(const std::string& path, G& g) {
  if (!CGAL::IO::read_polygon_mesh(path, g)) throw std::runtime_error("CGAL cannot read " + path);
}

/// A genmesh-style algorithm written only against genmesh's concepts and
/// tags: per-vertex valence in a scratch array sized by the index bound, and
/// the sum of positions; reported in vertex iteration order.
template <genmesh::FaceListGraph G>
  requires genmesh::VertexListGraph<G> && genmesh::HasVertexPoints<G> &&
           genmesh::HasIndexMap<G, genmesh::vertex_index_t>
std::pair<std::vector<int>, Eigen::Vector3d> valences_and_point_sum(const G& g) {
  const auto vindex = get(genmesh::vertex_index, g);
  std::vector<int> valence(index_bound(genmesh::vertex_index, g), 0);
  for (auto f : faces(g))
    for (auto v : face_vertices(g, f)) ++valence.at(get(vindex, v));
  std::vector<int> out;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const auto points = get(genmesh::vertex_point, g);
  for (auto v : vertices(g)) {
    out.push_back(valence.at(get(vindex, v)));
    sum += genmesh::to_eigen(get(points, v));
  }
  return {out, sum};
}

template <class G>
double bbox_diagonal(const G& g) {
  const CGAL::Bbox_3 b = PMP::bbox(g);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

/// Builds g from a genmesh soup through CGAL's own soup-to-mesh code.
template <class G>
void build_with_cgal(const genmesh::Polygon_soup& soup, G& g) {
  std::vector<Point> points;
  for (const auto& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::vector<std::size_t>> polygons;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    polygons.emplace_back(face.begin(), face.end());
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, g);
}

// ---- CGAL and OpenMesh meshes through genmesh's tags -----------------------

TEST(CgalToGenmesh, SurfaceMeshPointsIndicesAndBounds) {
  Surface_mesh sm;
  read_with_cgal(real_mesh("elephant.off"), sm);
  const File_soup file = read_file_soup(real_mesh("elephant.off"));

  const auto points = get(genmesh::vertex_point, sm);
  std::size_t i = 0;
  for (auto v : vertices(sm)) {
    EXPECT_EQ(get(points, v), file.points.at(i)) << "vertex " << i;
    EXPECT_EQ(get(get(genmesh::vertex_index, sm), v), i);
    ++i;
  }
  EXPECT_EQ(i, file.points.size());
  EXPECT_EQ(num_faces(sm), file.polygons.size());
  EXPECT_EQ(num_edges(sm), file.num_edges());
  // The map is CGAL's lvalue map: writing through genmesh's tag moves the point.
  const auto v0 = *vertices(sm).begin();
  put(points, v0, Point(1, 2, 3));
  EXPECT_EQ(sm.point(v0), Point(1, 2, 3));

  // After a removal the index bound keeps counting removed elements, and
  // CGAL's num_vertices(sm) *is* that bound (not the live count).
  const std::size_t nv = index_bound(genmesh::vertex_index, sm);
  const std::size_t nf = index_bound(genmesh::face_index, sm);
  CGAL::Euler::remove_center_vertex(halfedge(*std::next(vertices(sm).begin(), 10), sm), sm);
  EXPECT_EQ(index_bound(genmesh::vertex_index, sm), nv);
  EXPECT_EQ(index_bound(genmesh::face_index, sm), nf);
  EXPECT_EQ(num_vertices(sm), nv);
  EXPECT_EQ(count(vertices(sm)), nv - 1);
  EXPECT_EQ(sm.number_of_vertices(), nv - 1);
  for (auto h : halfedges(sm)) {
    EXPECT_LT(get(get(genmesh::halfedge_index, sm), h), index_bound(genmesh::halfedge_index, sm));
    EXPECT_EQ(get(get(genmesh::edge_index, sm), edge(h, sm)),
              get(get(genmesh::halfedge_index, sm), h) / 2);
  }
}

TEST(CgalToGenmesh, SameGenmeshAlgorithmOnEveryBackend) {
  const std::string path = real_mesh("elephant.off");
  Surface_mesh sm;
  Polyhedron_with_ids poly;
  Om_poly om;
  Hmesh hm;
  read_with_cgal(path, sm);
  read_with_cgal(path, poly);
  read_with_cgal(path, om);
  read_with_cgal(path, hm);

  const auto [valence_sm, sum_sm] = valences_and_point_sum(sm);
  const auto [valence_poly, sum_poly] = valences_and_point_sum(poly);
  const auto [valence_om, sum_om] = valences_and_point_sum(om);
  const auto [valence_hm, sum_hm] = valences_and_point_sum(hm);
  ASSERT_EQ(valence_sm.size(), 2775u);
  EXPECT_EQ(valence_poly, valence_sm);
  EXPECT_EQ(valence_om, valence_sm);
  EXPECT_EQ(valence_hm, valence_sm);
  // Every vertex of a closed triangle mesh has valence >= 3.
  EXPECT_GE(*std::min_element(valence_sm.begin(), valence_sm.end()), 3);
  EXPECT_EQ(sum_poly, sum_sm);
  EXPECT_EQ(sum_hm, sum_sm);
  EXPECT_LT((sum_om - sum_sm).norm(), 1e-6 * valence_sm.size()); // OpenMesh stores floats
}

TEST(CgalToGenmesh, PolyhedronCountsPointsAndIds) {
  const std::string path = real_mesh("cube_poly.off"); // mixed polygons
  const File_soup file = read_file_soup(path);
  Polyhedron plain;
  Polyhedron_with_ids poly;
  read_with_cgal(path, plain);
  read_with_cgal(path, poly);

  EXPECT_EQ(num_vertices(plain), file.points.size());
  EXPECT_EQ(num_faces(plain), file.polygons.size());
  EXPECT_EQ(num_edges(plain), file.num_edges());
  EXPECT_EQ(num_vertices(poly), file.points.size());
  EXPECT_EQ(num_faces(poly), file.polygons.size());
  EXPECT_EQ(num_halfedges(poly), 2 * file.num_edges());

  std::size_t i = 0;
  const auto plain_points = get(genmesh::vertex_point, plain);
  for (auto v : vertices(plain)) EXPECT_EQ(get(plain_points, v), file.points.at(i++));
  i = 0;
  const auto points = get(genmesh::vertex_point, std::as_const(poly));
  for (auto v : vertices(poly)) EXPECT_EQ(get(points, v), file.points.at(i++));

  // Fresh items carry id -1; get() numbers them from 0 in list order (a
  // polyhedron no element of which keeps an id is numbered densely):
  // halfedge pairs 2k/2k+1, edge id = halfedge id / 2.
  const auto vid = get(genmesh::vertex_index, poly);
  const auto hid = get(genmesh::halfedge_index, poly);
  const auto eid = get(genmesh::edge_index, poly);
  const auto fid = get(genmesh::face_index, poly);
  auto is_permutation = [](std::vector<std::size_t> ids, std::size_t bound) {
    std::sort(ids.begin(), ids.end());
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (ids[k] != k) return false;
    return ids.size() == bound;
  };
  std::vector<std::size_t> vs, hs, es, fs;
  for (auto v : vertices(poly)) vs.push_back(get(vid, v));
  for (auto h : halfedges(poly)) {
    hs.push_back(get(hid, h));
    EXPECT_EQ(get(hid, h) ^ 1u, get(hid, opposite(h, poly)));
    EXPECT_EQ(get(eid, edge(h, poly)), get(hid, h) / 2);
  }
  for (auto e : edges(poly)) es.push_back(get(eid, e));
  for (auto f : faces(poly)) fs.push_back(get(fid, f));
  EXPECT_TRUE(is_permutation(vs, index_bound(genmesh::vertex_index, poly)));
  EXPECT_TRUE(is_permutation(hs, index_bound(genmesh::halfedge_index, poly)));
  EXPECT_TRUE(is_permutation(es, index_bound(genmesh::edge_index, poly)));
  EXPECT_TRUE(is_permutation(fs, index_bound(genmesh::face_index, poly)));

  // A valid numbering of the user's is kept, sparse too (here: reversed, every
  // third id), when a polyhedron is first seen (a copy: a new address); of
  // two equal ids the first element in list order keeps it and the other
  // gets a fresh one at the bound.
  const std::size_t n = num_vertices(poly);
  Polyhedron_with_ids user = poly;
  std::size_t next_id = 3 * n;
  for (auto v : vertices(user)) v->id() = (next_id -= 3);
  EXPECT_EQ(get(get(genmesh::vertex_index, user), *vertices(user).begin()), 3 * (n - 1));
  EXPECT_EQ(index_bound(genmesh::vertex_index, user), 3 * (n - 1) + 1);
  EXPECT_EQ(get(get(genmesh::vertex_index, user), *std::prev(vertices(user).end())), 0u);
  Polyhedron_with_ids dup = poly; // ids 0..n-1 in list order, copied
  const auto v0 = *vertices(dup).begin(), v1 = *std::next(vertices(dup).begin());
  v0->id() = 1;
  EXPECT_EQ(get(get(genmesh::vertex_index, dup), v0), 1u);
  EXPECT_EQ(get(get(genmesh::vertex_index, dup), v1), n);
  EXPECT_EQ(index_bound(genmesh::vertex_index, dup), n + 1);
}

/// All four genmesh index maps of p keep the contract (cgal.h): ids unique
/// and below index_bound, halfedges paired 2k/2k+1, edge id = halfedge id / 2;
/// each map asked for per element.
template <class Poly>
::testing::AssertionResult polyhedron_ids_valid(const Poly& p) {
  auto check = [](std::vector<std::size_t> ids, std::size_t bound, const char* what) {
    std::sort(ids.begin(), ids.end());
    if (std::adjacent_find(ids.begin(), ids.end()) != ids.end())
      return ::testing::AssertionFailure() << what << " id " << *std::adjacent_find(ids.begin(), ids.end())
                                           << " taken twice";
    if (!ids.empty() && ids.back() >= bound)
      return ::testing::AssertionFailure() << what << " id " << ids.back() << " not below the bound " << bound;
    return ::testing::AssertionSuccess();
  };
  std::vector<std::size_t> vs, hs, es, fs;
  for (auto v : vertices(p)) vs.push_back(get(get(genmesh::vertex_index, p), v));
  for (auto h : halfedges(p)) {
    hs.push_back(get(get(genmesh::halfedge_index, p), h));
    if ((hs.back() ^ 1u) != get(get(genmesh::halfedge_index, p), opposite(h, p)))
      return ::testing::AssertionFailure() << "halfedge ids not paired";
    if (get(get(genmesh::edge_index, p), edge(h, p)) != hs.back() / 2)
      return ::testing::AssertionFailure() << "edge id is not halfedge id / 2";
  }
  for (auto e : edges(p)) es.push_back(get(get(genmesh::edge_index, p), e));
  for (auto f : faces(p)) fs.push_back(get(get(genmesh::face_index, p), f));
  for (auto r : {check(vs, index_bound(genmesh::vertex_index, p), "vertex"),
                 check(hs, index_bound(genmesh::halfedge_index, p), "halfedge"),
                 check(es, index_bound(genmesh::edge_index, p), "edge"),
                 check(fs, index_bound(genmesh::face_index, p), "face")})
    if (!r) return r;
  return ::testing::AssertionSuccess();
}

/// The ids of p's live elements by address, and the bounds, before an edit.
struct Polyhedron_ids_before {
  std::map<const void*, std::size_t> ids;
  std::size_t bound[3];
};
template <class Poly>
Polyhedron_ids_before ids_before(const Poly& p) {
  Polyhedron_ids_before b;
  for (auto v : vertices(p)) b.ids[&*v] = get(get(genmesh::vertex_index, p), v);
  for (auto h : halfedges(p)) b.ids[&*h] = get(get(genmesh::halfedge_index, p), h);
  for (auto f : faces(p)) b.ids[&*f] = get(get(genmesh::face_index, p), f);
  b.bound[0] = index_bound(genmesh::vertex_index, p);
  b.bound[1] = index_bound(genmesh::halfedge_index, p);
  b.bound[2] = index_bound(genmesh::face_index, p);
  return b;
}
/// Every element that survived the edit kept its id, new ones got ids at or
/// above the old bound, and the bounds did not shrink. (An element whose id
/// is below the old bound must be an old one: same address, same id.)
template <class Poly>
::testing::AssertionResult ids_survived(const Poly& p, const Polyhedron_ids_before& b) {
  auto same = [&](const void* a, std::size_t id, std::size_t bound) {
    if (id >= bound) return true;
    const auto it = b.ids.find(a);
    return it != b.ids.end() && it->second == id;
  };
  for (auto v : vertices(p))
    if (!same(&*v, get(get(genmesh::vertex_index, p), v), b.bound[0]))
      return ::testing::AssertionFailure() << "a vertex changed its id";
  for (auto h : halfedges(p))
    if (!same(&*h, get(get(genmesh::halfedge_index, p), h), b.bound[1]))
      return ::testing::AssertionFailure() << "a halfedge changed its id";
  for (auto f : faces(p))
    if (!same(&*f, get(get(genmesh::face_index, p), f), b.bound[2]))
      return ::testing::AssertionFailure() << "a face changed its id";
  if (index_bound(genmesh::vertex_index, p) < b.bound[0] || index_bound(genmesh::halfedge_index, p) < b.bound[1] ||
      index_bound(genmesh::face_index, p) < b.bound[2])
    return ::testing::AssertionFailure() << "a bound shrank";
  return ::testing::AssertionSuccess();
}

// The index maps keep the contract through every kind of edit, and a live
// element's id never changes: elements appended with fresh ids (split_edge,
// add_center_vertex), copied with an old element's id (split_vertex copies
// the vertex), removed from the middle (join_vertex), the last ones
// removed (remove_center_vertex after add_center_vertex, join_vertex of a
// new edge), and edit pairs that restore every size.
TEST(CgalToGenmesh, PolyhedronIdsFollowEveryEdit) {
  Polyhedron_with_ids poly;
  build_with_cgal(genmesh::make_icosphere(1), poly);
  ASSERT_TRUE(polyhedron_ids_valid(poly));
  const std::size_t nv = num_vertices(poly), nf = num_faces(poly);
  auto edit = [&](auto&& op, const char* what, int round) {
    const Polyhedron_ids_before b = ids_before(poly);
    const auto r = op();
    EXPECT_TRUE(polyhedron_ids_valid(poly)) << what << ", round " << round;
    EXPECT_TRUE(ids_survived(poly, b)) << what << ", round " << round;
    return r;
  };
  for (int round = 0; round < 6; ++round) {
    auto h = nth_edge(poly, 7 * round + 3).halfedge();
    h = edit([&] { return CGAL::Euler::split_edge(h, poly); }, "split_edge", round);
    const auto c = edit([&] { return CGAL::Euler::add_center_vertex(halfedge(nth_face(poly, 5 * round), poly), poly); },
                        "add_center_vertex", round);
    edit([&] { return CGAL::Euler::remove_center_vertex(c, poly); }, "remove_center_vertex", round);
    // split then join again: every size as before, last elements not.
    const auto g = edit([&] { return CGAL::Euler::split_vertex(h, opposite(next(h, poly), poly), poly); },
                        "split_vertex", round);
    edit([&] { return CGAL::Euler::join_vertex(g, poly); }, "join_vertex", round);
  }
  EXPECT_EQ(num_vertices(poly), nv + 6);
  EXPECT_EQ(num_faces(poly), nf);
  // Remove the newest halfedges (the list's last ones): split an edge and
  // join its new half away again (join_vertex removes the old end vertex).
  for (int round = 0; round < 3; ++round) {
    const auto h = edit([&] { return CGAL::Euler::split_edge(nth_edge(poly, 11 * round).halfedge(), poly); },
                        "split_edge", round);
    edit([&] { return CGAL::Euler::join_vertex(h, poly); }, "join_vertex", round);
  }
  EXPECT_EQ(num_vertices(poly), nv + 6);
  // A copy (same ids) and a fresh polyhedron: each numbered on its own.
  Polyhedron_with_ids copy = poly;
  EXPECT_TRUE(polyhedron_ids_valid(copy));
  CGAL::Euler::split_edge(*halfedges(copy).begin(), copy);
  EXPECT_TRUE(polyhedron_ids_valid(copy));
  EXPECT_TRUE(polyhedron_ids_valid(poly));
}

TEST(CgalToGenmesh, OpenMeshCountsAndPoints) {
  const std::string path = real_mesh("elephant.off");
  const File_soup file = read_file_soup(path);
  Om_poly om;
  Om_tri tri;
  read_with_cgal(path, om);
  read_with_cgal(path, tri);
  for (const std::array<std::size_t, 3>& c : {live_counts(om), live_counts(tri)}) {
    EXPECT_EQ(c[0], file.points.size());
    EXPECT_EQ(c[1], file.num_edges());
    EXPECT_EQ(c[2], file.polygons.size());
  }
  EXPECT_EQ(num_vertices(om), file.points.size());
  EXPECT_EQ(index_bound(genmesh::halfedge_index, om), 2 * file.num_edges());

  const auto points = get(genmesh::vertex_point, om);
  const auto vindex = get(genmesh::vertex_index, om);
  std::size_t i = 0;
  for (auto v : vertices(om)) {
    const Point& p = file.points.at(i);
    const OpenMesh::Vec3f expected(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z()));
    EXPECT_EQ(get(points, v), expected) << "vertex " << i;
    EXPECT_EQ(get(vindex, v), i);
    ++i;
  }
  // Writes go to OpenMesh's own point array.
  const auto v0 = *vertices(om).begin();
  put(points, v0, OpenMesh::Vec3f(1.f, 2.f, 3.f));
  EXPECT_EQ(om.point(v0), OpenMesh::Vec3f(1.f, 2.f, 3.f));
  // The genmesh view and CGAL's view (EPICK points by value) agree.
  EXPECT_EQ(get(get(CGAL::vertex_point, om), v0), Point(1, 2, 3));
}

// ---- Halfedge_mesh under CGAL's algorithms ---------------------------------

TEST(GenmeshToCgal, PropertyMapsForCgal) {
  Hmesh hm;
  read_with_cgal(real_mesh("cube_quad.off"), hm);
  ASSERT_EQ(num_vertices(hm), 8u);

  // CGAL's vertex point map is the mesh's "v:point".
  const auto v0 = *vertices(hm).begin();
  put(get(CGAL::vertex_point, hm), v0, Point(7, 8, 9));
  EXPECT_EQ(hm.point(v0), Point(7, 8, 9));
  EXPECT_EQ(get(CGAL::vertex_point, hm, v0), Point(7, 8, 9));

  // Dynamic properties live in the mesh: they follow additions and are gone
  // with the last copy of the map.
  hm.shrink_to_fit();
  const std::size_t bytes = hm.memory_bytes();
  {
    auto dist = get(CGAL::dynamic_vertex_property_t<double>(), hm);
    auto copy = dist;
    for (auto v : vertices(hm)) put(dist, v, 1.5);
    EXPECT_GT(hm.memory_bytes(), bytes);
    const auto v = add_vertex(hm);
    put(copy, v, 2.5);
    EXPECT_EQ(get(dist, v), 2.5);
    EXPECT_EQ(get(dist, v0), 1.5);
    auto flags = get(CGAL::dynamic_face_property_t<bool>(), hm);
    put(flags, *faces(hm).begin(), true);
    EXPECT_TRUE(get(flags, *faces(hm).begin()));
    remove_vertex(v, hm);
  }
  hm.collect_garbage(); // drops the added vertex and shrinks to fit
  hm.shrink_to_fit();
  EXPECT_EQ(num_vertices(hm), 8u);
  EXPECT_EQ(hm.memory_bytes(), bytes); // both dynamic properties are gone
  const Hmesh& chm = hm;
  auto const_map = get(CGAL::dynamic_halfedge_property_t<int>(), chm);
  for (auto h : halfedges(chm)) put(const_map, h, 3);
  EXPECT_EQ(get(const_map, *halfedges(chm).begin()), 3);

  // With removed elements CGAL's initialized index maps are still dense.
  CGAL::Euler::remove_face(halfedge(*faces(hm).begin(), hm), hm);
  ASSERT_LT(num_faces(hm), hm.faces_size());
  const auto fim = CGAL::get_initialized_face_index_map(hm);
  const auto vim = CGAL::get_initialized_vertex_index_map(hm);
  EXPECT_TRUE(CGAL::BGL::internal::is_index_map_valid(fim, num_faces(hm), faces(hm)));
  EXPECT_TRUE(CGAL::BGL::internal::is_index_map_valid(vim, num_vertices(hm), vertices(hm)));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm));
}

TEST(GenmeshToCgal, ReadAndCopyFaceGraphBothWays) {
  const std::string path = real_mesh("elephant-with-holes.off"); // has borders
  Surface_mesh sm;
  Hmesh hm;
  read_with_cgal(path, sm);
  read_with_cgal(path, hm);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(sm));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm));
  EXPECT_EQ(ordered_soup(hm), ordered_soup(sm));
  // Edge lengths (boost::edge_weight) agree edge by edge.
  static_assert(CGAL::graph_has_property<Hmesh, boost::edge_weight_t>::value);
  auto e_sm = edges(sm).begin();
  for (auto e : edges(hm)) {
    EXPECT_EQ(get(get(boost::edge_weight, hm), e), get(get(boost::edge_weight, sm), *e_sm));
    ++e_sm;
  }
  EXPECT_GT(get(get(boost::edge_weight, hm), *edges(hm).begin()), 0.0);
  std::size_t borders_sm = 0, borders_hm = 0;
  for (auto h : halfedges(sm)) borders_sm += CGAL::is_border(h, sm) ? 1 : 0;
  for (auto h : halfedges(hm)) borders_hm += CGAL::is_border(h, hm) ? 1 : 0;
  EXPECT_GT(borders_sm, 0u);
  EXPECT_EQ(borders_hm, borders_sm);

  // Surface_mesh -> Halfedge_mesh -> Surface_mesh, and the same copy into a
  // Surface_mesh for reference: equal, vertex order included.
  Hmesh hm2;
  Surface_mesh sm_ref, sm2;
  CGAL::copy_face_graph(sm, hm2);
  CGAL::copy_face_graph(sm, sm_ref);
  CGAL::copy_face_graph(hm2, sm2);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm2));
  EXPECT_EQ(ordered_soup(hm2), ordered_soup(sm_ref));
  EXPECT_EQ(canonical_soup(hm2), canonical_soup(sm));
  EXPECT_EQ(canonical_soup(sm2), canonical_soup(sm));
  EXPECT_EQ(live_counts(hm2), live_counts(sm));
}

TEST(GenmeshToCgal, TriangulateFacesEqualsSurfaceMesh) {
  for (const genmesh::Polygon_soup& soup : {genmesh::make_cube(), genmesh::make_torus(12, 8)}) {
    Surface_mesh sm;
    Hmesh hm;
    build_with_cgal(soup, sm);
    build_with_cgal(soup, hm);
    ASSERT_EQ(ordered_soup(hm), ordered_soup(sm));
    const std::size_t quads = num_faces(hm);
    ASSERT_TRUE(PMP::triangulate_faces(sm));
    EXPECT_TRUE(PMP::triangulate_faces(hm));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm));
    EXPECT_TRUE(CGAL::is_triangle_mesh(hm));
    EXPECT_EQ(num_faces(hm), 2 * quads);
    EXPECT_EQ(ordered_soup(hm), ordered_soup(sm));
    EXPECT_EQ(canonical_soup(hm), canonical_soup(sm));
  }
}

TEST(GenmeshToCgal, EulerOperationsEqualSurfaceMesh) {
  const std::string path = real_mesh("elephant.off");
  Surface_mesh sm;
  Hmesh hm;
  read_with_cgal(path, sm);
  read_with_cgal(path, hm);

  int flips = 0, collapses = 0, splits = 0;
  for (std::size_t round = 0; round < 60; ++round) {
    // Flip: an interior edge between two triangles.
    {
      const std::size_t k = round * 7919;
      const auto e_sm = nth_edge(sm, k);
      const auto e_hm = nth_edge(hm, k);
      ASSERT_EQ(std::size_t(e_sm), e_hm.idx());
      const auto h_sm = halfedge(e_sm, sm);
      const auto h_hm = halfedge(e_hm, hm);
      const bool ok_sm = !CGAL::is_border(e_sm, sm) && degree(face(h_sm, sm), sm) == 3 &&
                         degree(face(opposite(h_sm, sm), sm), sm) == 3 &&
                         !halfedge(target(next(h_sm, sm), sm),
                                   target(next(opposite(h_sm, sm), sm), sm), sm).second;
      const bool ok_hm = !CGAL::is_border(e_hm, hm) && degree(face(h_hm, hm), hm) == 3 &&
                         degree(face(opposite(h_hm, hm), hm), hm) == 3 &&
                         !halfedge(target(next(h_hm, hm), hm),
                                   target(next(opposite(h_hm, hm), hm), hm), hm).second;
      ASSERT_EQ(ok_sm, ok_hm);
      if (ok_sm) {
        CGAL::Euler::flip_edge(h_sm, sm);
        CGAL::Euler::flip_edge(h_hm, hm);
        ++flips;
      }
    }
    // Collapse: an edge that satisfies the link condition.
    {
      const std::size_t k = round * 104729 + 13;
      const auto e_sm = nth_edge(sm, k);
      const auto e_hm = nth_edge(hm, k);
      const bool ok_sm = CGAL::Euler::does_satisfy_link_condition(e_sm, sm);
      ASSERT_EQ(ok_sm, CGAL::Euler::does_satisfy_link_condition(e_hm, hm));
      if (ok_sm) {
        const auto kept_sm = CGAL::Euler::collapse_edge(e_sm, sm);
        const auto kept_hm = CGAL::Euler::collapse_edge(e_hm, hm);
        EXPECT_EQ(std::size_t(kept_sm), kept_hm.idx());
        ++collapses;
      }
    }
    // Split: a new vertex on an edge, moved to the edge's midpoint.
    {
      const std::size_t k = round * 1299709 + 5;
      const auto h_sm = halfedge(nth_edge(sm, k), sm);
      const auto h_hm = halfedge(nth_edge(hm, k), hm);
      const Point mid = CGAL::midpoint(sm.point(source(h_sm, sm)), sm.point(target(h_sm, sm)));
      const auto n_sm = CGAL::Euler::split_edge(h_sm, sm);
      const auto n_hm = CGAL::Euler::split_edge(h_hm, hm);
      EXPECT_EQ(std::size_t(n_sm), n_hm.idx());
      put(get(CGAL::vertex_point, sm), target(n_sm, sm), mid);
      put(get(CGAL::vertex_point, hm), target(n_hm, hm), mid);
      ++splits;
    }
  }
  // Splits recycle the collapses' indices; a few more collapses leave removed
  // elements in place for the checks below.
  for (std::size_t k = 0, more = 0; more < 5 && k < 1000; ++k) {
    const auto e_sm = nth_edge(sm, 31 * k);
    const auto e_hm = nth_edge(hm, 31 * k);
    ASSERT_EQ(CGAL::Euler::does_satisfy_link_condition(e_sm, sm),
              CGAL::Euler::does_satisfy_link_condition(e_hm, hm));
    if (!CGAL::Euler::does_satisfy_link_condition(e_sm, sm)) continue;
    EXPECT_EQ(std::size_t(CGAL::Euler::collapse_edge(e_sm, sm)),
              CGAL::Euler::collapse_edge(e_hm, hm).idx());
    ++more;
    ++collapses;
  }
  EXPECT_GT(flips, 10);
  EXPECT_GT(collapses, 15);
  EXPECT_EQ(splits, 60);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(sm));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm));
  EXPECT_EQ(live_counts(hm), live_counts(sm));
  EXPECT_EQ(hm.vertices_size(), sm.num_vertices()); // same recycling
  EXPECT_EQ(hm.faces_size(), sm.num_faces());
  EXPECT_EQ(ordered_soup(hm), ordered_soup(sm));
  EXPECT_EQ(canonical_soup(hm), canonical_soup(sm));
  // genmesh-style code sizes scratch by index_bound: right on both meshes
  // with removed elements still in place.
  ASSERT_GT(sm.number_of_removed_vertices(), 0u);
  EXPECT_EQ(valences_and_point_sum(hm), valences_and_point_sum(sm));
}

TEST(GenmeshToCgal, IsotropicRemeshingEqualsSurfaceMesh) {
  const std::string path = real_mesh("blobby.off");
  Surface_mesh sm;
  Hmesh hm;
  read_with_cgal(path, sm);
  read_with_cgal(path, hm);
  const double target = 0.02 * bbox_diagonal(sm);
  EXPECT_EQ(bbox_diagonal(hm), bbox_diagonal(sm));

  PMP::isotropic_remeshing(faces(sm), target, sm, CGAL::parameters::number_of_iterations(3));
  PMP::isotropic_remeshing(faces(hm), target, hm, CGAL::parameters::number_of_iterations(3));

  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm));
  EXPECT_TRUE(CGAL::is_triangle_mesh(hm));
  EXPECT_EQ(live_counts(hm), live_counts(sm));
  EXPECT_NE(live_counts(hm)[0], 2027u); // remeshing did change the mesh
  EXPECT_EQ(ordered_soup(hm), ordered_soup(sm));

  // Garbage collection: by default Halfedge_mesh keeps the survivors' order
  // while Surface_mesh fills holes from the back, so only the canonical soups
  // agree; Garbage_order::like_surface_mesh renumbers exactly as Surface_mesh.
  Hmesh hm_like = hm;
  sm.collect_garbage();
  hm.collect_garbage();
  hm_like.collect_garbage(genmesh::Garbage_order::like_surface_mesh);
  EXPECT_EQ(hm.vertices_size(), sm.num_vertices());
  EXPECT_EQ(hm.halfedges_size(), sm.num_halfedges());
  EXPECT_EQ(canonical_soup(hm), canonical_soup(sm));
  EXPECT_NE(ordered_soup(hm), ordered_soup(sm));
  EXPECT_EQ(ordered_soup(hm_like), ordered_soup(sm));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(hm_like));
}

TEST(GenmeshToCgal, EigenPointsThroughCgalPointMap) {
  // The default Halfedge_mesh<> (Eigen points) is not a CGAL point mesh, but
  // CGAL's algorithms run on it given genmesh::cgal_point_map: same results.
  using Eigen_mesh = genmesh_test::Halfedge_mesh;
  static_assert(!CGAL::graph_has_property<Eigen_mesh, CGAL::vertex_point_t>::value);
  Surface_mesh sm;
  build_with_cgal(genmesh::make_torus(10, 6), sm);
  Eigen_mesh em;
  CGAL::copy_face_graph(sm, em, CGAL::parameters::default_values(),
                        CGAL::parameters::vertex_point_map(genmesh::cgal_point_map<Kernel>(em)));
  Surface_mesh sm_ref; // the same copy into a Surface_mesh, for the vertex order
  CGAL::copy_face_graph(sm, sm_ref);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(em));
  EXPECT_EQ(ordered_soup(em), ordered_soup(sm_ref));

  const auto vpm = CGAL::parameters::vertex_point_map(genmesh::cgal_point_map<Kernel>(em));
  ASSERT_TRUE(PMP::triangulate_faces(sm_ref));
  EXPECT_TRUE(PMP::triangulate_faces(em, vpm));
  EXPECT_EQ(ordered_soup(em), ordered_soup(sm_ref));

  const double target = 0.05 * bbox_diagonal(sm_ref);
  PMP::isotropic_remeshing(faces(sm_ref), target, sm_ref, CGAL::parameters::number_of_iterations(2));
  PMP::isotropic_remeshing(faces(em), target, em, vpm.number_of_iterations(2));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(em));
  EXPECT_NE(live_counts(em)[2], 2u * 60u); // remeshing did change the mesh
  EXPECT_EQ(ordered_soup(em), ordered_soup(sm_ref));
}

} // namespace

// ---- Boost's and CGAL's generic graph code on every backend -----------------
// (issue 10, point 7: Boost's PropertyGraph concept wants the three-argument
// get(boost::vertex_index, g, v); graph code that walks a vertex's edges wants
// out_edges / in_edges / degrees and the bidirectional traversal category.)

namespace {

/// The concept checks Boost's and CGAL's graph algorithms rely on, for G.
template <class G>
struct Generic_graph_checks {
  using V = typename boost::graph_traits<G>::vertex_descriptor;
  using H = typename boost::graph_traits<G>::halfedge_descriptor;
  using E = typename boost::graph_traits<G>::edge_descriptor;
  using F = typename boost::graph_traits<G>::face_descriptor;
  BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((boost::EdgeListGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((boost::IncidenceGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((boost::BidirectionalGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((boost::AdjacencyGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((boost::ReadablePropertyGraphConcept<G, V, boost::vertex_index_t>));
  BOOST_CONCEPT_ASSERT((boost::ReadablePropertyGraphConcept<G, E, boost::edge_index_t>));
  BOOST_CONCEPT_ASSERT((boost::ReadablePropertyGraphConcept<G, H, CGAL::halfedge_index_t>));
  BOOST_CONCEPT_ASSERT((boost::ReadablePropertyGraphConcept<G, F, CGAL::face_index_t>));
  BOOST_CONCEPT_ASSERT((CGAL::HalfedgeGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((CGAL::HalfedgeListGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((CGAL::FaceGraphConcept<G>));
  BOOST_CONCEPT_ASSERT((CGAL::FaceListGraphConcept<G>));
  static_assert(std::is_convertible_v<typename boost::graph_traits<G>::traversal_category,
                                      boost::bidirectional_graph_tag>);
  static_assert(std::is_convertible_v<typename boost::graph_traits<G>::traversal_category,
                                      boost::adjacency_graph_tag>);
};
static_assert(sizeof(Generic_graph_checks<Hmesh>) > 0);
static_assert(sizeof(Generic_graph_checks<genmesh::Halfedge_mesh<>>) > 0);
static_assert(sizeof(Generic_graph_checks<genmesh::Incidence_mesh<>>) > 0);
static_assert(sizeof(Generic_graph_checks<genmesh::Incidence_mesh<Point>>) > 0);
static_assert(sizeof(Generic_graph_checks<Surface_mesh>) > 0);

/// Two components: a grid with a hole (border, valences 2 to 6) and a
/// tetrahedron beside it.
genmesh::Polygon_soup two_component_soup() {
  genmesh::Polygon_soup s = genmesh::make_grid_with_hole(6);
  const genmesh::Polygon_soup t = genmesh::make_tetrahedron();
  const auto base = static_cast<genmesh::Polygon_soup::Index>(s.num_points());
  for (const auto& p : t.points) s.add_point(p.x() + 10, p.y(), p.z());
  for (std::size_t f = 0; f < t.num_faces(); ++f) {
    std::vector<genmesh::Polygon_soup::Index> c;
    for (auto i : t.face(f)) c.push_back(i + base);
    s.add_face(c);
  }
  return s;
}

/// What generic graph code computes on g, per vertex in index order: its
/// component (boost::connected_components), hop distance from vertex 0
/// (boost::breadth_first_search), edge-length distance from vertex 0
/// (boost::dijkstra_shortest_paths), sorted neighbours through out_edges,
/// in_edges and adjacent_vertices, and the degrees.
struct Graph_walk {
  std::vector<int> component;
  std::vector<std::size_t> hops;
  std::vector<double> distance;
  std::vector<std::vector<std::size_t>> out_neighbours, in_neighbours, adjacent;
  std::vector<std::size_t> out_degree, in_degree;
};

template <class G>
Graph_walk walk_graph(const G& g) {
  using V = typename boost::graph_traits<G>::vertex_descriptor;
  using E = typename boost::graph_traits<G>::edge_descriptor;
  const auto vindex = get(boost::vertex_index, g);
  const std::size_t n = num_vertices(g);
  Graph_walk w;
  w.component.assign(n, -1);
  const auto component = boost::make_iterator_property_map(w.component.begin(), vindex);
  boost::connected_components(g, component, boost::vertex_index_map(vindex));

  const V start = *vertices(g).begin();
  w.hops.assign(n, 0);
  const auto hops = boost::make_iterator_property_map(w.hops.begin(), vindex);
  boost::breadth_first_search(
      g, start,
      boost::visitor(boost::make_bfs_visitor(boost::record_distances(hops, boost::on_tree_edge())))
          .vertex_index_map(vindex));

  w.distance.assign(n, 0.0);
  const auto length = boost::make_function_property_map<E, double>([&g](E e) {
    return (genmesh::to_eigen(get(get(genmesh::vertex_point, g), source(e, g))) -
            genmesh::to_eigen(get(get(genmesh::vertex_point, g), target(e, g))))
        .norm();
  });
  std::vector<V> pred(n);
  boost::dijkstra_shortest_paths(
      g, start,
      boost::weight_map(length)
          .vertex_index_map(vindex)
          .predecessor_map(boost::make_iterator_property_map(pred.begin(), vindex))
          .distance_map(boost::make_iterator_property_map(w.distance.begin(), vindex)));

  for (V v : vertices(g)) {
    std::vector<std::size_t> out, in, adj;
    for (E e : boost::make_iterator_range(out_edges(v, g))) {
      EXPECT_EQ(source(e, g), v);
      out.push_back(get(boost::vertex_index, g, target(e, g)));
    }
    for (E e : boost::make_iterator_range(in_edges(v, g))) {
      EXPECT_EQ(target(e, g), v);
      in.push_back(get(boost::vertex_index, g, source(e, g)));
    }
    for (V u : boost::make_iterator_range(adjacent_vertices(v, g))) adj.push_back(get(vindex, u));
    std::sort(out.begin(), out.end());
    std::sort(in.begin(), in.end());
    std::sort(adj.begin(), adj.end());
    w.out_neighbours.push_back(out);
    w.in_neighbours.push_back(in);
    w.adjacent.push_back(adj);
    w.out_degree.push_back(out_degree(v, g));
    w.in_degree.push_back(in_degree(v, g));
  }
  return w;
}

template <class T>
class Generic_graph_code : public ::testing::Test {};
TYPED_TEST_SUITE(Generic_graph_code, genmesh_test::Backends);

TYPED_TEST(Generic_graph_code, BoostSearchesOverOutEdgesAgreeWithHalfedgeMesh) {
  const genmesh::Polygon_soup soup = two_component_soup();
  TypeParam g;
  genmesh::build_mesh(soup, g);
  genmesh::Halfedge_mesh<> reference;
  genmesh::build_mesh(soup, reference);

  const Graph_walk w = walk_graph(g), r = walk_graph(reference);
  ASSERT_EQ(w.component.size(), soup.num_points());
  EXPECT_EQ(*std::max_element(w.component.begin(), w.component.end()), 1);
  EXPECT_EQ(w.component, r.component);
  EXPECT_EQ(w.hops, r.hops);
  ASSERT_EQ(w.distance.size(), r.distance.size());
  for (std::size_t i = 0; i < w.distance.size(); ++i) EXPECT_NEAR(w.distance[i], r.distance[i], 1e-12) << i;
  EXPECT_EQ(w.out_neighbours, r.out_neighbours);
  EXPECT_EQ(w.in_neighbours, w.out_neighbours); // undirected: the same neighbours both ways
  EXPECT_EQ(w.adjacent, w.out_neighbours);
  EXPECT_EQ(w.out_degree, r.out_degree);
  EXPECT_EQ(w.in_degree, r.in_degree);
  // The tetrahedron is unreachable from vertex 0: BFS leaves it at 0 hops,
  // Dijkstra at infinity.
  EXPECT_EQ(w.hops.back(), 0u);
  EXPECT_GT(w.distance.back(), 1e300);
  std::size_t degree_sum = 0;
  for (auto d : w.out_degree) degree_sum += d;
  EXPECT_EQ(degree_sum, 2 * static_cast<std::size_t>(num_edges(g)));
}

} // namespace

// ---- every subdivision scheme on Polyhedron_3 and OpenMesh -----------------
// (issue 10, point 9: same canonical soups as Halfedge_mesh, through the
// public subdivision API and each mesh's own index maps.)

namespace {

struct Om_double_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Om_poly_d = OpenMesh::PolyMesh_ArrayKernelT<Om_double_traits>;
using Om_tri_d = OpenMesh::TriMesh_ArrayKernelT<Om_double_traits>;

enum class Scheme { loop, catmull_clark, midpoint, sqrt3, doo_sabin, butterfly };
constexpr Scheme all_schemes[] = {Scheme::loop, Scheme::catmull_clark, Scheme::midpoint,
                                  Scheme::sqrt3, Scheme::doo_sabin, Scheme::butterfly};
const char* scheme_name(Scheme s) {
  const char* n[] = {"loop", "catmull_clark", "midpoint", "sqrt3", "doo_sabin", "butterfly"};
  return n[static_cast<int>(s)];
}
bool triangles_only(Scheme s) { return s == Scheme::loop || s == Scheme::sqrt3 || s == Scheme::butterfly; }

template <class G>
void subdivide(Scheme s, G& g, int levels) {
  switch (s) {
  case Scheme::loop: genmesh::loop_subdivision(g, {.iterations = levels}); return;
  case Scheme::catmull_clark: genmesh::catmull_clark_subdivision(g, {.iterations = levels}); return;
  case Scheme::midpoint: genmesh::midpoint_subdivision(g, {.iterations = levels}); return;
  case Scheme::sqrt3: genmesh::sqrt3_subdivision(g, {.iterations = levels}); return;
  case Scheme::doo_sabin: genmesh::doo_sabin_subdivision(g, {.iterations = levels}); return;
  case Scheme::butterfly: genmesh::butterfly_subdivision(g, {.iterations = levels}); return;
  }
}

template <class G>
Canonical_soup subdivided(const genmesh::Polygon_soup& soup, Scheme s, int levels) {
  G g;
  genmesh::build_mesh(soup, g);
  subdivide(s, g, levels);
  return canonical_soup(g);
}

struct Subdivision_input {
  const char* name;
  genmesh::Polygon_soup soup;
};

std::vector<Subdivision_input> subdivision_inputs() {
  return {{"tetrahedron", genmesh::make_tetrahedron()},
          {"cube", genmesh::make_cube()},
          {"icosphere", genmesh::make_icosphere(1)},
          {"torus_triangles", genmesh::make_torus(8, 6, true)},
          {"grid_with_hole", genmesh::make_grid_with_hole(6)}};
}

bool all_triangles(const genmesh::Polygon_soup& s) {
  for (std::size_t f = 0; f < s.num_faces(); ++f)
    if (s.face_size(f) != 3) return false;
  return true;
}

// Loop, Catmull-Clark, butterfly and midpoint refine these in place through
// the generic bulk append (no genmesh_native_append_elements): this test is
// what runs that fallback.
static_assert(genmesh::detail::subdivision::In_place_refinable<Polyhedron_with_ids> &&
              !genmesh::detail::subdivision::Has_native_append<Polyhedron_with_ids>);
static_assert(genmesh::detail::subdivision::In_place_refinable<Om_poly_d> &&
              !genmesh::detail::subdivision::Has_native_append<Om_poly_d>);

TEST(CgalToGenmesh, EverySchemeOnPolyhedronAndOpenMeshEqualsHalfedgeMesh) {
  for (const auto& in : subdivision_inputs()) {
    for (Scheme s : all_schemes) {
      if (triangles_only(s) && !all_triangles(in.soup)) continue;
      SCOPED_TRACE(std::string(in.name) + " " + scheme_name(s));
      const Canonical_soup expected = subdivided<genmesh::Halfedge_mesh<>>(in.soup, s, 2);
      ASSERT_GT(expected.faces.size(), in.soup.num_faces());
      EXPECT_EQ(subdivided<Polyhedron_with_ids>(in.soup, s, 2), expected);
      EXPECT_EQ(subdivided<Om_poly_d>(in.soup, s, 2), expected);
      if (all_triangles(in.soup) && triangles_only(s)) {
        EXPECT_EQ(subdivided<Om_tri_d>(in.soup, s, 2), expected);
      }
    }
  }
}

// Simplification and isotropic remeshing run on OpenMesh's TriMesh and on
// Polyhedron_3 through the same generic code (their local operations and
// the generic scratch properties), keeping index-keyed tables across edits:
// both adaptors keep a live element's index (Polyhedron_3: its item ids,
// see cgal.h). They give Halfedge_mesh's mesh.
template <class G>
Canonical_soup simplified(const genmesh::Polygon_soup& soup, double ratio) {
  G g;
  genmesh::build_mesh(soup, g);
  const auto r = genmesh::simplify(g, {.target_ratio = ratio});
  EXPECT_GT(r.collapses, 0u);
  EXPECT_TRUE(genmesh::check_mesh(g).valid);
  return canonical_soup(g);
}

template <class G>
Canonical_soup remeshed(const genmesh::Polygon_soup& soup) {
  G g;
  genmesh::build_mesh(soup, g);
  const auto r = genmesh::isotropic_remeshing(g, {.relative_edge_length = 0.8, .iterations = 3});
  EXPECT_GT(r.splits, 0u);
  if constexpr (requires { g.does_recycle_garbage(); }) {
    EXPECT_TRUE(g.does_recycle_garbage()); // Append_only_indices gave the setting back
  }
  EXPECT_TRUE(genmesh::check_mesh(g).valid);
  return canonical_soup(g);
}

TEST(CgalToGenmesh, SimplifyAndRemeshOnOpenMeshAndPolyhedronEqualHalfedgeMesh) {
  genmesh::Polygon_soup bumpy = genmesh::make_grid_with_hole(12);
  for (auto& p : bumpy.points) p.z() = 0.2 * std::sin(3 * p.x()) * std::cos(2 * p.y());
  const std::pair<const char*, genmesh::Polygon_soup> inputs[] = {
      {"icosphere(3)", genmesh::make_icosphere(3)},
      {"bumpy grid with a hole", bumpy},
      {"torus", genmesh::make_torus(24, 12, true)}};
  for (const auto& [name, soup] : inputs) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(all_triangles(soup));
    const Canonical_soup s = simplified<genmesh::Halfedge_mesh<>>(soup, 0.3);
    EXPECT_LT(s.faces.size(), soup.num_faces());
    EXPECT_EQ(simplified<Om_tri_d>(soup, 0.3), s);
    EXPECT_EQ(simplified<Polyhedron_with_ids>(soup, 0.3), s);
    // Remeshing gives Halfedge_mesh's mesh too: OpenMesh never recycles
    // removed elements, Polyhedron_3's adaptor gives new items fresh ids, and
    // the remesher makes the recycling meshes append while it runs
    // (Append_only_indices), so new elements are numbered alike on all.
    const Canonical_soup r = remeshed<genmesh::Halfedge_mesh<>>(soup);
    EXPECT_FALSE(r.faces.empty());
    EXPECT_EQ(remeshed<Om_tri_d>(soup), r);
    EXPECT_EQ(remeshed<Polyhedron_with_ids>(soup), r);
  }
}

// Attribute_quadrics over a vertex property map (a scratch property: the
// generic storage on these two) on an icosphere painted red above the
// equator and blue below: the survivors' points and written colours, sorted.
template <class G>
std::vector<std::array<double, 6>> simplified_with_colour(const genmesh::Polygon_soup& soup) {
  G g;
  genmesh::build_mesh(soup, g);
  auto colour = genmesh::scratch_property<Eigen::Vector3d>(genmesh::vertex_index, g, Eigen::Vector3d::Zero());
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<G>;
  for (auto v : vertices(g))
    colour[v] = genmesh::to_eigen(P(get(pm, v))).z() > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
  const auto r = genmesh::simplify(g, genmesh::Simplification_options<genmesh::Attribute_quadrics<G>>{
                                          .target_ratio = 0.2, .policy = {.attributes = {genmesh::vertex_attribute(colour, 0.2)}}});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces);
  EXPECT_TRUE(genmesh::check_mesh(g).valid);
  std::vector<std::array<double, 6>> out;
  for (auto v : vertices(g)) {
    const Eigen::Vector3d p = genmesh::to_eigen(P(get(pm, v)));
    const Eigen::Vector3d c = colour[v];
    out.push_back({p.x(), p.y(), p.z(), c.x(), c.y(), c.z()});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(CgalToGenmesh, AttributeQuadricsOnOpenMeshAndPolyhedronEqualHalfedgeMesh) {
  const genmesh::Polygon_soup sphere = genmesh::make_icosphere(3);
  const auto expected = simplified_with_colour<genmesh::Halfedge_mesh<>>(sphere);
  ASSERT_LT(expected.size(), sphere.num_points());
  double worst = 0; // survivors away from the equator keep their pure colour
  for (const auto& x : expected)
    if (std::abs(x[2]) > 0.25)
      worst = std::max(worst, (Eigen::Vector3d(x[3], x[4], x[5]) -
                               (x[2] > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1)))
                                  .cwiseAbs()
                                  .maxCoeff());
  EXPECT_LT(worst, 0.05);
  EXPECT_EQ(simplified_with_colour<Om_tri_d>(sphere), expected);
  EXPECT_EQ(simplified_with_colour<Polyhedron_with_ids>(sphere), expected);
}

} // namespace
