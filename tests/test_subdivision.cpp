// Subdivision: every scheme on every backend (identical canonical soups),
// exact counts and topological invariants, affine invariance, boundary rules,
// refusals, and CGAL's Subdivision_method_3 as the oracle for Loop,
// Catmull-Clark, √3 and Doo-Sabin on closed real meshes.
#include "backends.h"

#include <genmesh/generators.h>
#include <genmesh/io.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/subdivision.h>
#include <genmesh/validity.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>

#include <boost/property_map/vector_property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <span>
#include <type_traits>
#include <limits>
#include <string>
#include <vector>

namespace {

using genmesh::Polygon_soup;
using genmesh_test::Backends;
using genmesh_test::mesh_of;

// Loop and Catmull-Clark refine these in place with set_next & co.; the
// incidence mesh (no set_next) in place through its native local operations.
static_assert(genmesh::detail::subdivision::In_place_refinable<genmesh_test::Halfedge_mesh>);
static_assert(genmesh::detail::subdivision::In_place_refinable<genmesh_test::Surface_mesh>);
static_assert(!genmesh::detail::subdivision::In_place_refinable<genmesh_test::Incidence_mesh>);

enum class Scheme { loop, loop_warren, catmull_clark, midpoint, sqrt3, doo_sabin, butterfly };
constexpr Scheme all_schemes[] = {Scheme::loop,  Scheme::loop_warren, Scheme::catmull_clark, Scheme::midpoint,
                                  Scheme::sqrt3, Scheme::doo_sabin,   Scheme::butterfly};

bool takes_triangles_only(Scheme s) {
  return s == Scheme::loop || s == Scheme::loop_warren || s == Scheme::sqrt3 || s == Scheme::butterfly;
}

template <class G>
genmesh::Subdivision_result run(Scheme s, G& g, int levels,
                                genmesh::Boundary_rule b = genmesh::Boundary_rule::smooth) {
  switch (s) {
  case Scheme::loop: return genmesh::loop_subdivision(g, {.iterations = levels, .boundary = b});
  case Scheme::loop_warren:
    return genmesh::loop_subdivision(
        g, {.iterations = levels, .boundary = b, .weights = genmesh::Loop_weights::warren});
  case Scheme::catmull_clark: return genmesh::catmull_clark_subdivision(g, {.iterations = levels, .boundary = b});
  case Scheme::midpoint: return genmesh::midpoint_subdivision(g, {.iterations = levels});
  case Scheme::sqrt3: return genmesh::sqrt3_subdivision(g, {.iterations = levels, .boundary = b});
  case Scheme::doo_sabin: return genmesh::doo_sabin_subdivision(g, {.iterations = levels});
  case Scheme::butterfly: return genmesh::butterfly_subdivision(g, {.iterations = levels});
  }
  return {};
}

std::string name(Scheme s) {
  const char* n[] = {"loop", "loop_warren", "catmull_clark", "midpoint", "sqrt3", "doo_sabin", "butterfly"};
  return n[static_cast<int>(s)];
}

struct Named_soup {
  std::string name;
  Polygon_soup soup;
};

std::vector<Named_soup> inputs() {
  Polygon_soup wedge; // one triangle and one quad sharing an edge: a mixed open mesh
  wedge.add_point(0, 0, 0);
  wedge.add_point(1, 0, 0);
  wedge.add_point(1, 1, 0.5);
  wedge.add_point(0, 1, 0);
  wedge.add_point(2, 0.5, 0.25);
  wedge.add_face({0, 1, 2, 3});
  wedge.add_face({1, 4, 2});
  return {{"tetrahedron", genmesh::make_tetrahedron()},
          {"cube", genmesh::make_cube()},
          {"icosphere", genmesh::make_icosphere(1)},
          {"torus_quads", genmesh::make_torus(8, 6, false)},
          {"torus_triangles", genmesh::make_torus(8, 6, true)},
          {"grid", genmesh::make_grid(4, 3)},
          {"grid_with_hole", genmesh::make_grid_with_hole(6)},
          {"wedge", wedge}};
}

bool all_triangles(const Polygon_soup& s) {
  for (std::size_t f = 0; f < s.num_faces(); ++f)
    if (s.face_size(f) != 3) return false;
  return true;
}

template <class G>
std::size_t count_edges(const G& g) {
  return static_cast<std::size_t>(num_edges(g));
}

template <class G, class Pick>
std::vector<double> sharpness_where(const G& g, Pick pick, double value);

// A crease map of g (genmesh::make_crease_map) holding sharp, given in edge
// iteration order (empty: all 0).
template <class G>
auto crease_map_of(G& g, const std::vector<double>& sharp) {
  auto m = genmesh::make_crease_map(g);
  std::size_t k = 0;
  if (!sharp.empty())
    for (auto e : edges(g)) put(m, e, sharp.at(k++));
  return m;
}

// A crease map's values in edge iteration order.
template <class G, class M>
std::vector<double> sharpness_of(const G& g, const M& m) {
  std::vector<double> out;
  for (auto e : edges(g)) out.push_back(get(m, e));
  return out;
}

// A corner map of g tagging the vertices with these iteration numbers.
template <class G>
auto corner_map_of(G& g, const std::vector<std::uint32_t>& numbers) {
  auto m = genmesh::make_corner_map(g);
  std::vector<typename boost::graph_traits<std::remove_const_t<G>>::vertex_descriptor> vs;
  for (auto v : vertices(g)) vs.push_back(v);
  for (std::uint32_t n : numbers) put(m, vs.at(n), 1);
  return m;
}

template <class T>
class Subdivision : public ::testing::Test {};
TYPED_TEST_SUITE(Subdivision, Backends);

// ---------------------------------------------------------------------------
// Cross-backend: the same input gives the same canonical soup, bit for bit.

TYPED_TEST(Subdivision, EveryBackendGivesTheSameSoupAsHalfedgeMesh) {
  for (const auto& in : inputs())
    for (Scheme s : all_schemes) {
      if (takes_triangles_only(s) && !all_triangles(in.soup)) continue;
      SCOPED_TRACE(in.name + " / " + name(s));
      auto reference = mesh_of<genmesh_test::Halfedge_mesh>(in.soup);
      auto g = mesh_of<TypeParam>(in.soup);
      run(s, reference, 2);
      run(s, g, 2);
      EXPECT_EQ(genmesh::canonical(genmesh::to_soup(g)), genmesh::canonical(genmesh::to_soup(reference)));
    }
}

// ---------------------------------------------------------------------------
// Counts per level and topological invariants (Euler characteristic, border
// loops, validity).

TYPED_TEST(Subdivision, CountsPerLevelAndInvariants) {
  for (const auto& in : inputs())
    for (Scheme s : all_schemes) {
      if (takes_triangles_only(s) && !all_triangles(in.soup)) continue;
      SCOPED_TRACE(in.name + " / " + name(s));
      auto g = mesh_of<TypeParam>(in.soup);
      const genmesh::Mesh_report before = genmesh::check_mesh(g);
      for (int level = 1; level <= 2; ++level) {
        const std::size_t V = num_vertices(g), E = count_edges(g), F = num_faces(g);
        const genmesh::Mesh_report r0 = genmesh::check_mesh(g);
        std::size_t corners = 0, non_triangles = 0, border_edges = r0.border_halfedges;
        for (auto f : faces(g)) {
          std::size_t n = 0;
          auto h0 = halfedge(f, g), h = h0;
          do ++n, h = next(h, g);
          while (h != h0);
          corners += n;
          non_triangles += n != 3;
        }
        const auto res = run(s, g, 1);
        const genmesh::Mesh_report r = genmesh::check_mesh(g);
        ASSERT_TRUE(r.ok()) << "level " << level;
        EXPECT_EQ(r.border_vertices_with_inner_halfedge, 0u); // as build_mesh leaves it
        EXPECT_EQ(r.euler_characteristic, before.euler_characteristic);
        EXPECT_EQ(r.boundary_loops, before.boundary_loops);
        EXPECT_EQ(r.components, before.components);
        EXPECT_EQ(res.levels_done, 1);
        EXPECT_EQ(res.vertices, r.vertices);
        EXPECT_EQ(res.faces, r.faces);
        switch (s) {
        case Scheme::loop: case Scheme::loop_warren: case Scheme::butterfly:
          EXPECT_EQ(r.vertices, V + E);
          EXPECT_EQ(r.faces, 4 * F);
          EXPECT_EQ(r.edges, 2 * E + 3 * F);
          break;
        case Scheme::catmull_clark:
          EXPECT_EQ(r.vertices, V + E + F);
          EXPECT_EQ(r.faces, corners);
          EXPECT_TRUE(r.is_quad_mesh);
          break;
        case Scheme::midpoint:
          EXPECT_EQ(r.vertices, V + E + non_triangles);
          EXPECT_EQ(r.faces, corners + (F - non_triangles)); // 4 per triangle = 3 corners + 1
          break;
        case Scheme::sqrt3:
          EXPECT_EQ(r.vertices, V + F);
          EXPECT_EQ(r.faces, 2 * E - border_edges); // two per interior edge, one per border edge
          EXPECT_TRUE(r.is_triangle_mesh);
          break;
        case Scheme::doo_sabin: {
          EXPECT_EQ(r.vertices, corners);
          // a border loop has as many vertices as edges
          const std::size_t interior_vertices = V - border_edges;
          EXPECT_EQ(r.faces, F + (E - border_edges) + interior_vertices);
          break;
        }
        }
      }
    }
}

// ---------------------------------------------------------------------------
// Affine invariance: every mask is an affine combination, so a planar mesh
// stays in its plane — interior, border and irregular vertices alike.

TYPED_TEST(Subdivision, PlanarMeshesStayInTheirPlane) {
  auto plane = [](const Eigen::Vector3d& p) { return 0.3 * p.x() - 0.2 * p.y() + 0.1; };
  for (Polygon_soup base : {genmesh::make_grid(4, 4), genmesh::make_grid_with_hole(6)}) {
    for (auto& p : base.points) p.z() = plane(p);
    for (Scheme s : all_schemes)
      for (auto b : {genmesh::Boundary_rule::smooth, genmesh::Boundary_rule::fixed}) {
        SCOPED_TRACE(name(s));
        auto g = mesh_of<TypeParam>(base);
        run(s, g, 2, b);
        for (const auto& p : genmesh::to_soup(g).points) EXPECT_NEAR(p.z(), plane(p), 1e-12);
      }
  }
}

// ---------------------------------------------------------------------------
// Border rules.

TYPED_TEST(Subdivision, FixedBorderKeepsBorderVerticesAndSmoothBorderFollowsTheBSpline) {
  // On the unit square grid the border is four straight lines: with either
  // rule every new border point stays on the square's outline; with `fixed`
  // old border vertices do not move, with `smooth` a border vertex moves to
  // (prev + 6 v + next) / 8, which at a square corner cuts the corner.
  const Polygon_soup base = genmesh::make_grid(3, 3);
  for (Scheme s : {Scheme::loop, Scheme::catmull_clark}) {
    SCOPED_TRACE(name(s));
    auto fixed = mesh_of<TypeParam>(base);
    auto smooth = mesh_of<TypeParam>(base);
    run(s, fixed, 1, genmesh::Boundary_rule::fixed);
    run(s, smooth, 1, genmesh::Boundary_rule::smooth);
    const Polygon_soup f = genmesh::to_soup(fixed), m = genmesh::to_soup(smooth);
    // old vertex 0 is the corner (0,0): its border neighbours are (1/3,0) and (0,1/3)
    EXPECT_EQ(f.points[0], Eigen::Vector3d(0, 0, 0));
    EXPECT_TRUE(m.points[0].isApprox(Eigen::Vector3d(1.0 / 24, 1.0 / 24, 0), 1e-15));
    // old vertex 1 = (1/3, 0) sits on a straight border: B-spline keeps it
    EXPECT_TRUE(m.points[1].isApprox(base.points[1], 1e-15));
    const genmesh::Mesh_report r = genmesh::check_mesh(fixed);
    EXPECT_EQ(r.boundary_loops, 1u);
    // every border vertex of the fixed result lies on the outline of the unit square
    auto on_outline = [](const Eigen::Vector3d& p) {
      return std::abs(p.x()) < 1e-15 || std::abs(p.x() - 1) < 1e-15 || std::abs(p.y()) < 1e-15 ||
             std::abs(p.y() - 1) < 1e-15;
    };
    auto pts = get(genmesh::vertex_point, fixed);
    std::size_t border_vertices = 0;
    for (auto h : halfedges(fixed))
      if (face(h, fixed) == boost::graph_traits<TypeParam>::null_face()) {
        ++border_vertices;
        EXPECT_TRUE(on_outline(genmesh::to_eigen(get(pts, target(h, fixed)))));
      }
    EXPECT_EQ(border_vertices, 24u); // 12 old border edges, each split
  }
}

// ---------------------------------------------------------------------------
// Scheme-specific properties.

TYPED_TEST(Subdivision, InterpolatingSchemesKeepOldVertices) {
  for (const auto& in : inputs()) {
    for (Scheme s : {Scheme::butterfly, Scheme::midpoint}) {
      if (takes_triangles_only(s) && !all_triangles(in.soup)) continue;
      SCOPED_TRACE(in.name + " / " + name(s));
      auto g = mesh_of<TypeParam>(in.soup);
      run(s, g, 2);
      const Polygon_soup out = genmesh::to_soup(g);
      for (std::size_t i = 0; i < in.soup.num_points(); ++i) EXPECT_EQ(out.points[i], in.soup.points[i]);
    }
  }
}

TYPED_TEST(Subdivision, LoopWeightsAgreeAtValenceSixAndDifferElsewhere) {
  // Loop's β and Warren's 3/(8n) are both 1/16 at valence 6 (every vertex of
  // the triangulated torus), and differ at valence 5 (the icosphere).
  {
    auto a = mesh_of<TypeParam>(genmesh::make_torus(8, 6, true));
    auto b = mesh_of<TypeParam>(genmesh::make_torus(8, 6, true));
    for (auto v : vertices(a)) ASSERT_EQ(degree(v, a), 6u);
    run(Scheme::loop, a, 1);
    run(Scheme::loop_warren, b, 1);
    const Polygon_soup sa = genmesh::to_soup(a), sb = genmesh::to_soup(b);
    ASSERT_EQ(sa.num_points(), sb.num_points());
    for (std::size_t i = 0; i < sa.num_points(); ++i) EXPECT_TRUE(sa.points[i].isApprox(sb.points[i], 1e-14));
  }
  {
    auto a = mesh_of<TypeParam>(genmesh::make_icosphere(0));
    auto b = mesh_of<TypeParam>(genmesh::make_icosphere(0));
    run(Scheme::loop, a, 1);
    run(Scheme::loop_warren, b, 1);
    const Polygon_soup sa = genmesh::to_soup(a), sb = genmesh::to_soup(b);
    // vertex 0 (valence 5): Loop's β = (5/8 − (3/8 + cos(72°)/4)²)/5, Warren's 3/40
    const double c = 3.0 / 8 + std::cos(2 * std::numbers::pi / 5) / 4;
    const double beta = (5.0 / 8 - c * c) / 5;
    const Polygon_soup ico = genmesh::make_icosphere(0);
    auto g = mesh_of<genmesh_test::Halfedge_mesh>(ico);
    Eigen::Vector3d ring = Eigen::Vector3d::Zero();
    auto pts = get(genmesh::vertex_point, g);
    auto v0 = *vertices(g).begin();
    for (auto h : CGAL::halfedges_around_target(halfedge(v0, g), g)) ring += genmesh::to_eigen(get(pts, source(h, g)));
    EXPECT_TRUE(sa.points[0].isApprox((1 - 5 * beta) * ico.points[0] + beta * ring, 1e-14));
    EXPECT_TRUE(sb.points[0].isApprox((1 - 5 * 3.0 / 40) * ico.points[0] + 3.0 / 40 * ring, 1e-14));
    EXPECT_GT((sa.points[0] - sb.points[0]).norm(), 1e-6);
  }
}

TYPED_TEST(Subdivision, OneCallOfTwoLevelsEqualsTwoCallsOfOne) {
  // Inside one call the levels between the first and the last never build a
  // mesh (the next snapshot comes from the refined soup); the result must be
  // the mesh that rebuilding after every level gives. (√3 is left out: its
  // border rule counts levels within a call; on closed meshes it is included.)
  for (const auto& in : inputs())
    for (Scheme s : all_schemes) {
      if (takes_triangles_only(s) && !all_triangles(in.soup)) continue;
      auto one = mesh_of<TypeParam>(in.soup);
      if (s == Scheme::sqrt3 && !genmesh::check_mesh(one).is_closed) continue;
      SCOPED_TRACE(in.name + " / " + name(s));
      auto two = mesh_of<TypeParam>(in.soup);
      run(s, one, 2);
      run(s, two, 1);
      run(s, two, 1);
      EXPECT_EQ(genmesh::to_soup(one), genmesh::to_soup(two));
    }
  // creases carried across levels the same way
  const Polygon_soup torus = genmesh::make_torus(8, 6, true);
  auto one = mesh_of<TypeParam>(torus), two = mesh_of<TypeParam>(torus);
  const auto sharp = sharpness_where(one, [](std::size_t v) { return v < 6; }, 1.5);
  auto m1 = crease_map_of(one, sharp), m2 = crease_map_of(two, sharp);
  genmesh::loop_subdivision(one, genmesh::Loop_options{.iterations = 2, .crease_map = m1});
  // the map carries the sharpness over by itself: the same map, level after level
  genmesh::loop_subdivision(two, genmesh::Loop_options{.iterations = 1, .crease_map = m2});
  genmesh::loop_subdivision(two, genmesh::Loop_options{.iterations = 1, .crease_map = m2});
  EXPECT_EQ(genmesh::to_soup(one), genmesh::to_soup(two));
  const std::vector<double> after = sharpness_of(one, m1);
  EXPECT_EQ(after, sharpness_of(two, m2));
  EXPECT_EQ(std::count(after.begin(), after.end(), 0.0), static_cast<std::ptrdiff_t>(after.size())); // 1.5 → 0.5 → 0
}

TYPED_TEST(Subdivision, EmptyMeshStaysEmpty) {
  for (Scheme s : all_schemes) {
    TypeParam g;
    const auto r = run(s, g, 2);
    EXPECT_EQ(r.levels_done, 2);
    EXPECT_EQ(num_vertices(g), 0u);
    EXPECT_EQ(num_faces(g), 0u);
  }
}

TYPED_TEST(Subdivision, ZeroIterationsChangeNothing) {
  for (Scheme s : all_schemes) {
    auto g = mesh_of<TypeParam>(genmesh::make_icosphere(0));
    const Polygon_soup before = genmesh::to_soup(g);
    const auto r = run(s, g, 0);
    EXPECT_EQ(r.levels_done, 0);
    EXPECT_EQ(r.vertices, 12u);
    EXPECT_EQ(r.faces, 20u);
    EXPECT_EQ(genmesh::to_soup(g), before);
  }
}

// ---------------------------------------------------------------------------
// Refusals leave the mesh untouched.

TYPED_TEST(Subdivision, TriangleSchemesRefuseOtherFacesAndLeaveTheMeshUnchanged) {
  Polygon_soup mixed = genmesh::make_icosphere(0);
  mixed.add_point(5, 5, 5); // a separate quad: face 20
  mixed.add_point(6, 5, 5);
  mixed.add_point(6, 6, 5);
  mixed.add_point(5, 6, 5);
  mixed.add_face({12, 13, 14, 15});
  for (Scheme s : {Scheme::loop, Scheme::sqrt3, Scheme::butterfly}) {
    SCOPED_TRACE(name(s));
    auto g = mesh_of<TypeParam>(mixed);
    const Polygon_soup before = genmesh::to_soup(g);
    try {
      run(s, g, 1);
      ADD_FAILURE() << "not refused";
    } catch (const genmesh::invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find("face 20 has 4 sides"), std::string::npos) << e.what();
    }
    EXPECT_EQ(genmesh::to_soup(g), before);
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
  }
  auto g = mesh_of<TypeParam>(mixed);
  EXPECT_THROW(genmesh::catmull_clark_subdivision(g, {.iterations = -1}), genmesh::invalid_input);
}

// ---------------------------------------------------------------------------
// Oracle: CGAL's Subdivision_method_3 on a Surface_mesh read by CGAL gives the
// same points (as multisets, to 1e-12 relative to the bounding box).

using Sm = genmesh_test::Surface_mesh;

std::vector<Eigen::Vector3d> points_of(Sm& sm) {
  std::vector<Eigen::Vector3d> out;
  for (auto v : vertices(sm)) out.push_back(genmesh::to_eigen(sm.point(v)));
  return out;
}

// Every point of a has a distinct partner in b within tol (greedy nearest in x-sorted order).
void expect_same_point_sets(std::vector<Eigen::Vector3d> a, std::vector<Eigen::Vector3d> b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  auto by_x = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q) { return p.x() < q.x(); };
  std::sort(b.begin(), b.end(), by_x);
  std::vector<char> used(b.size(), 0);
  std::size_t unmatched = 0;
  for (const auto& p : a) {
    auto lo = std::lower_bound(b.begin(), b.end(), Eigen::Vector3d(p.x() - tol, 0, 0), by_x);
    std::size_t best = b.size();
    double best_d = tol;
    for (auto it = lo; it != b.end() && it->x() <= p.x() + tol; ++it) {
      std::size_t i = static_cast<std::size_t>(it - b.begin());
      double d = (*it - p).lpNorm<Eigen::Infinity>();
      if (!used[i] && d <= best_d) best = i, best_d = d;
    }
    if (best == b.size()) ++unmatched;
    else used[best] = 1;
  }
  EXPECT_EQ(unmatched, 0u);
}

double box_size(const std::vector<Eigen::Vector3d>& pts) {
  Eigen::Vector3d lo = pts[0], hi = pts[0];
  for (const auto& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).maxCoeff();
}

void compare_with_cgal(Sm& cgal, genmesh_test::Halfedge_mesh& g, Scheme s, int levels) {
  const auto np = CGAL::parameters::number_of_iterations(static_cast<unsigned>(levels));
  switch (s) {
  case Scheme::loop: CGAL::Subdivision_method_3::Loop_subdivision(cgal, np); break;
  case Scheme::catmull_clark: CGAL::Subdivision_method_3::CatmullClark_subdivision(cgal, np); break;
  case Scheme::sqrt3: CGAL::Subdivision_method_3::Sqrt3_subdivision(cgal, np); break;
  case Scheme::doo_sabin: CGAL::Subdivision_method_3::DooSabin_subdivision(cgal, np); break;
  default: FAIL();
  }
  cgal.collect_garbage(); // CGAL's Doo-Sabin leaves removed elements, which its num_* count
  run(s, g, levels);
  EXPECT_EQ(num_vertices(g), num_vertices(cgal));
  EXPECT_EQ(num_faces(g), num_faces(cgal));
  EXPECT_EQ(num_edges(g), num_edges(cgal));
  const auto ours = genmesh::to_soup(g).points;
  expect_same_point_sets(ours, points_of(cgal), 1e-12 * box_size(ours));
}

void oracle(const std::string& file, Scheme s, int levels) {
  SCOPED_TRACE(file + " / " + name(s));
  Sm cgal;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(genmesh_test::real_mesh(file), cgal));
  ASSERT_TRUE(CGAL::is_closed(cgal));
  genmesh_test::Halfedge_mesh g;
  genmesh::read_mesh(genmesh_test::real_mesh(file), g);
  ASSERT_TRUE(genmesh::check_mesh(g).is_closed);
  compare_with_cgal(cgal, g, s, levels);
}

TEST(SubdivisionOracle, LoopEqualsCgal) {
  oracle("sphere.off", Scheme::loop, 2);
  oracle("eight.off", Scheme::loop, 1);
}

TEST(SubdivisionOracle, CatmullClarkEqualsCgal) {
  oracle("sphere.off", Scheme::catmull_clark, 2);
  oracle("eight.off", Scheme::catmull_clark, 1);
  oracle("cube_quad.off", Scheme::catmull_clark, 3);
}

TEST(SubdivisionOracle, Sqrt3EqualsCgal) {
  oracle("sphere.off", Scheme::sqrt3, 2);
  oracle("eight.off", Scheme::sqrt3, 1);
}

TEST(SubdivisionOracle, DooSabinEqualsCgal) {
  oracle("sphere.off", Scheme::doo_sabin, 2);
  oracle("eight.off", Scheme::doo_sabin, 1);
  oracle("cube_quad.off", Scheme::doo_sabin, 2);
}

} // namespace

namespace {

// Meshes with a border: Loop and Catmull-Clark use the same border rules as
// CGAL (midpoints; 1/8, 3/4, 1/8), √3 the same Kobbelt border rule at odd
// levels, so the results agree there too. (Doo-Sabin has no border rule.)
TEST(SubdivisionOracle, LoopCatmullClarkAndSqrt3EqualCgalOnMeshesWithBorders) {
  Polygon_soup annulus = genmesh::make_grid_with_hole(9);
  for (auto& p : annulus.points) p.z() = std::sin(3 * p.x()) * std::cos(2 * p.y());
  Polygon_soup quads = genmesh::make_torus(6, 5, false);
  quads.offsets.resize(quads.offsets.size() - 5); // drop the last ring of quads: a tube, two border loops
  quads.indices.resize(quads.offsets.back());
  for (Scheme s : {Scheme::loop, Scheme::catmull_clark, Scheme::sqrt3})
    for (const Polygon_soup* in : {&annulus, &quads}) {
      if (s != Scheme::catmull_clark && in == &quads) continue;
      SCOPED_TRACE(name(s));
      auto cgal = mesh_of<Sm>(*in);
      auto g = mesh_of<genmesh_test::Halfedge_mesh>(*in);
      ASSERT_EQ(genmesh::check_mesh(g).boundary_loops, 2u);
      compare_with_cgal(cgal, g, s, s == Scheme::sqrt3 ? 4 : 2); // √3: two border refinements
    }
}

TYPED_TEST(Subdivision, Sqrt3RefinesTheBorderEverySecondLevel) {
  // grid 3 × 3: 12 border edges. Level 0 keeps them; level 1 splits each in three.
  auto g = mesh_of<TypeParam>(genmesh::make_grid(3, 3));
  genmesh::sqrt3_subdivision(g, {.iterations = 1});
  EXPECT_EQ(genmesh::check_mesh(g).border_halfedges, 12u);
  auto h = mesh_of<TypeParam>(genmesh::make_grid(3, 3));
  genmesh::sqrt3_subdivision(h, {.iterations = 2});
  const genmesh::Mesh_report r = genmesh::check_mesh(h);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.border_halfedges, 36u);
  EXPECT_EQ(r.euler_characteristic, 1);
  auto k = mesh_of<TypeParam>(genmesh::make_grid(3, 3));
  genmesh::sqrt3_subdivision(k, {.iterations = 2, .boundary = genmesh::Boundary_rule::fixed});
  EXPECT_EQ(genmesh::check_mesh(k).border_halfedges, 12u);
}

} // namespace

namespace {

// Butterfly: OpenMesh's ModifiedButterflyT has the same masks, including its
// border handling (four-point rule; eight-point with reflected wings next to
// the border), so the results agree on closed meshes and on meshes with borders.
struct Om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Om_mesh = OpenMesh::TriMesh_ArrayKernelT<Om_traits>;

void butterfly_oracle(const Polygon_soup& in, int levels) {
  Om_mesh om;
  std::vector<Om_mesh::VertexHandle> vh;
  for (const auto& p : in.points) vh.push_back(om.add_vertex(Om_mesh::Point(p.x(), p.y(), p.z())));
  for (std::size_t f = 0; f < in.num_faces(); ++f) {
    auto c = in.face(f);
    ASSERT_TRUE(om.add_face(vh[c[0]], vh[c[1]], vh[c[2]]).is_valid());
  }
  OpenMesh::Subdivider::Uniform::ModifiedButterflyT<Om_mesh> subdivider;
  subdivider.attach(om);
  subdivider(static_cast<std::size_t>(levels));
  subdivider.detach();
  std::vector<Eigen::Vector3d> theirs;
  for (auto v : om.vertices()) theirs.emplace_back(om.point(v)[0], om.point(v)[1], om.point(v)[2]);

  auto g = mesh_of<genmesh_test::Halfedge_mesh>(in);
  genmesh::butterfly_subdivision(g, {.iterations = levels});
  ASSERT_EQ(static_cast<std::size_t>(num_faces(g)), om.n_faces());
  const auto ours = genmesh::to_soup(g).points;
  expect_same_point_sets(ours, theirs, 1e-12 * box_size(ours));
}

TEST(SubdivisionOracle, ButterflyEqualsOpenMesh) {
  {
    SCOPED_TRACE("sphere.off");
    butterfly_oracle(genmesh::read_soup(genmesh_test::real_mesh("sphere.off")), 2);
  }
  {
    SCOPED_TRACE("eight.off");
    butterfly_oracle(genmesh::read_soup(genmesh_test::real_mesh("eight.off")), 1);
  }
  {
    SCOPED_TRACE("icosphere (valence 5 and 6)");
    butterfly_oracle(genmesh::make_icosphere(1), 2);
  }
  {
    SCOPED_TRACE("annulus with two borders");
    Polygon_soup annulus = genmesh::make_grid_with_hole(9);
    for (auto& p : annulus.points) p.z() = std::sin(3 * p.x()) * std::cos(2 * p.y());
    butterfly_oracle(annulus, 2);
  }
}

} // namespace

namespace {

// ---------------------------------------------------------------------------
// Creases (DeRose, Kass, Truong 1998).

constexpr double inf = std::numeric_limits<double>::infinity();

// Sharpness per edge (edge iteration order): `value` on the edges whose both
// ends satisfy `pick` (by vertex number), 0 elsewhere.
template <class G, class Pick>
std::vector<double> sharpness_where(const G& g, Pick pick, double value) {
  std::vector<double> s;
  auto vi = get(genmesh::vertex_index, g);
  for (auto e : edges(g)) {
    auto h = halfedge(e, g);
    const auto a = static_cast<std::size_t>(get(vi, source(h, g)));
    const auto b = static_cast<std::size_t>(get(vi, target(h, g)));
    s.push_back(pick(a) && pick(b) ? value : 0.0);
  }
  return s;
}

// The crease vertices of g: ends of edges whose sharpness (result order) is > 0.
template <class G>
std::vector<Eigen::Vector3d> crease_points(G& g, const std::vector<double>& sharp) {
  std::vector<Eigen::Vector3d> out;
  std::vector<char> seen(index_bound(genmesh::vertex_index, g), 0);
  auto vi = get(genmesh::vertex_index, g);
  auto pts = get(genmesh::vertex_point, g);
  std::size_t i = 0;
  for (auto e : edges(g)) {
    if (sharp.at(i++) <= 0) continue;
    for (auto v : {source(halfedge(e, g), g), target(halfedge(e, g), g)}) {
      auto k = static_cast<std::size_t>(get(vi, v));
      if (!seen[k]) seen[k] = 1, out.push_back(genmesh::to_eigen(get(pts, v)));
    }
  }
  return out;
}

// Cubic B-spline subdivision of a closed polygon, `levels` times.
std::vector<Eigen::Vector3d> bspline(std::vector<Eigen::Vector3d> p, int levels) {
  for (int l = 0; l < levels; ++l) {
    const std::size_t n = p.size();
    std::vector<Eigen::Vector3d> q;
    for (std::size_t j = 0; j < n; ++j) {
      q.push_back((p[(j + n - 1) % n] + 6 * p[j] + p[(j + 1) % n]) / 8);
      q.push_back((p[j] + p[(j + 1) % n]) / 2);
    }
    p = q;
  }
  return p;
}

TYPED_TEST(Subdivision, SharpCreasesFollowTheBSplineOfTheirControlPolygon) {
  // Ring i = 0 of the torus (vertices 0 .. sides-1, a closed polygon) made
  // infinitely sharp: its vertices then evolve by the cubic B-spline rules
  // alone, whatever the surface around them does.
  const int rings = 8, sides = 6;
  for (bool triangles : {true, false}) {
    SCOPED_TRACE(triangles ? "Loop" : "Catmull-Clark");
    const Polygon_soup torus = genmesh::make_torus(rings, sides, triangles);
    auto g = mesh_of<TypeParam>(torus);
    const auto sharp = sharpness_where(g, [&](std::size_t v) { return v < std::size_t(sides); }, inf);
    ASSERT_EQ(std::count(sharp.begin(), sharp.end(), inf), sides);
    auto m = crease_map_of(g, sharp);
    if (triangles) genmesh::loop_subdivision(g, genmesh::Loop_options{.iterations = 2, .crease_map = m});
    else genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.iterations = 2, .crease_map = m});
    const std::vector<double> after = sharpness_of(g, m);
    ASSERT_EQ(after.size(), static_cast<std::size_t>(num_edges(g)));
    EXPECT_EQ(std::count(after.begin(), after.end(), inf), 4 * sides);
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
    std::vector<Eigen::Vector3d> ring(torus.points.begin(), torus.points.begin() + sides);
    expect_same_point_sets(crease_points(g, after), bspline(ring, 2), 1e-12);
  }
}

TYPED_TEST(Subdivision, SharpCubeEdgesStayStraight) {
  // Every edge of the cube infinitely sharp: the corners (three creases) stay,
  // and every crease vertex stays on its cube edge (two coordinates at ±1).
  auto g = mesh_of<TypeParam>(genmesh::make_cube());
  const std::vector<double> sharp(12, inf);
  auto m = crease_map_of(g, sharp);
  genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.iterations = 3, .crease_map = m});
  const auto pts = crease_points(g, sharpness_of(g, m));
  EXPECT_EQ(pts.size(), 8u + 12u * 7u); // corners + 7 new points per cube edge
  for (const auto& p : pts) {
    int at_bound = 0;
    for (int i = 0; i < 3; ++i) at_bound += std::abs(std::abs(p[i]) - 1.0) < 1e-15;
    EXPECT_GE(at_bound, 2) << p.transpose();
  }
  const Polygon_soup out = genmesh::to_soup(g);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out.points[i], genmesh::make_cube().points[i]);
  // without creases the corners are cut
  auto smooth = mesh_of<TypeParam>(genmesh::make_cube());
  genmesh::catmull_clark_subdivision(smooth, {.iterations = 1});
  EXPECT_LT(genmesh::to_soup(smooth).points[0].norm(), std::sqrt(3.0) - 0.1);
}

TYPED_TEST(Subdivision, SemiSharpCreasesBlendAndDecrement) {
  // Sharpness 1/2 on the ring: after one level every point is the mean of the
  // smooth (0) and the sharp (∞) results — same numbering in all three; with
  // sharpness 3/2 the halves carry 1/2 into the next level.
  for (bool triangles : {true, false}) {
    SCOPED_TRACE(triangles ? "Loop" : "Catmull-Clark");
    const Polygon_soup torus = genmesh::make_torus(8, 6, triangles);
    std::vector<Polygon_soup> out;
    std::vector<double> first_sharp;
    for (double s : {0.0, inf, 0.5}) {
      auto g = mesh_of<TypeParam>(torus);
      const auto sharp = sharpness_where(g, [](std::size_t v) { return v < 6; }, s);
      if (triangles) genmesh::loop_subdivision(g, genmesh::Loop_options{.crease_map = crease_map_of(g, sharp)});
      else genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.crease_map = crease_map_of(g, sharp)});
      out.push_back(genmesh::to_soup(g));
    }
    std::size_t differ = 0;
    for (std::size_t i = 0; i < out[0].num_points(); ++i) {
      EXPECT_TRUE(out[2].points[i].isApprox(0.5 * (out[0].points[i] + out[1].points[i]), 1e-14));
      differ += (out[0].points[i] - out[1].points[i]).norm() > 1e-9;
    }
    EXPECT_GT(differ, 0u);
    auto g = mesh_of<TypeParam>(torus);
    const auto sharp = sharpness_where(g, [](std::size_t v) { return v < 6; }, 1.5);
    auto m = crease_map_of(g, sharp);
    if (triangles) genmesh::loop_subdivision(g, genmesh::Loop_options{.crease_map = m});
    else genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.crease_map = m});
    const std::vector<double> after = sharpness_of(g, m);
    EXPECT_EQ(std::count(after.begin(), after.end(), 0.5), 12);
    EXPECT_EQ(std::count(after.begin(), after.end(), 0.0), static_cast<std::ptrdiff_t>(after.size()) - 12);
  }
}

TYPED_TEST(Subdivision, CreasesByVertexPairs) {
  // the cube's 4 edges around z = -1 (vertices 0, 1, 3, 2), named by vertex pairs
  auto g = mesh_of<TypeParam>(genmesh::make_cube());
  const std::vector<genmesh::Crease> c = {{0, 1, inf}, {3, 1, inf}, {3, 2, 2.5}, {0, 2, 0.5}};
  const auto sharp = genmesh::crease_sharpness(g, std::span<const genmesh::Crease>(c));
  ASSERT_EQ(sharp.size(), 12u);
  std::vector<double> expected(12, 0.0);
  auto vi = get(genmesh::vertex_index, g);
  std::size_t i = 0;
  for (auto e : edges(g)) {
    auto a = get(vi, source(halfedge(e, g), g)), b = get(vi, target(halfedge(e, g), g));
    for (const auto& k : c)
      if ((k.a == a && k.b == b) || (k.a == b && k.b == a)) expected[i] = k.sharpness;
    ++i;
  }
  EXPECT_EQ(sharp, expected);
  EXPECT_EQ(sharpness_of(g, genmesh::crease_map(g, std::span<const genmesh::Crease>(c))), expected);
  EXPECT_EQ(std::count(sharp.begin(), sharp.end(), 0.0), 8);
  const std::vector<genmesh::Crease> diagonal = {{0, 3, 1.0}}; // not an edge
  EXPECT_THROW(genmesh::crease_sharpness(g, std::span<const genmesh::Crease>(diagonal)), genmesh::invalid_input);
}

TYPED_TEST(Subdivision, NegativeOrNanSharpnessIsRefused) {
  for (double bad : {-1.0, std::nan("")}) {
    auto g = mesh_of<TypeParam>(genmesh::make_cube());
    const Polygon_soup before = genmesh::to_soup(g);
    auto m = genmesh::make_crease_map(g);
    put(m, *std::next(edges(g).begin(), 5), bad);
    EXPECT_THROW(genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.crease_map = m}),
                 genmesh::invalid_input);
    EXPECT_EQ(genmesh::to_soup(g), before);
  }
}

} // namespace

namespace {

// ---------------------------------------------------------------------------
// Limit positions: a vertex's limit does not change under further
// subdivision, so projecting after k + 1 levels gives, at the vertices of
// level k, the positions projecting after k levels gives.

TYPED_TEST(Subdivision, LimitPositionsAreInvariantUnderSubdivision) {
  struct Case {
    std::string name;
    Polygon_soup soup;
    bool loop;
    bool crease_ring; // ring of the torus (vertices 0..5) infinitely sharp
  };
  Polygon_soup bumpy = genmesh::make_grid_with_hole(6);
  for (auto& p : bumpy.points) p.z() = std::sin(3 * p.x()) * std::cos(2 * p.y());
  const std::vector<Case> cases = {
      {"icosphere", genmesh::make_icosphere(1), true, false},
      {"torus", genmesh::make_torus(8, 6, true), true, true},
      {"annulus", bumpy, true, false},
      {"cube", genmesh::make_cube(), false, false},
      {"torus_quads", genmesh::make_torus(8, 6, false), false, true},
      {"annulus", bumpy, false, false},
  };
  for (const auto& k : cases) {
    SCOPED_TRACE(k.name + (k.loop ? " / Loop" : " / Catmull-Clark"));
    std::vector<Polygon_soup> out;
    std::size_t old_vertices = 0;
    for (int levels : {1, 2}) {
      auto g = mesh_of<TypeParam>(k.soup);
      const auto sharp = k.crease_ring ? sharpness_where(g, [](std::size_t v) { return v < 6; }, inf)
                                       : std::vector<double>{};
      if (k.loop)
        genmesh::loop_subdivision(
            g, genmesh::Loop_options{.iterations = levels, .crease_map = crease_map_of(g, sharp), .limit = true});
      else
        genmesh::catmull_clark_subdivision(
            g, genmesh::Catmull_clark_options{.iterations = levels, .crease_map = crease_map_of(g, sharp), .limit = true});
      out.push_back(genmesh::to_soup(g));
      if (levels == 1) old_vertices = out.back().num_points();
    }
    auto plain = mesh_of<TypeParam>(k.soup);
    if (k.loop) genmesh::loop_subdivision(plain, {.iterations = 1});
    else genmesh::catmull_clark_subdivision(plain, {.iterations = 1});
    const Polygon_soup unprojected = genmesh::to_soup(plain);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < old_vertices; ++i) {
      EXPECT_TRUE(out[1].points[i].isApprox(out[0].points[i], 1e-12)) << i;
      moved += (unprojected.points[i] - out[0].points[i]).norm() > 1e-9;
    }
    EXPECT_GT(moved, old_vertices / 2); // the projection does move vertices
  }
}

} // namespace

namespace {

// ---------------------------------------------------------------------------
// Attribute transport: a per-vertex scalar equal to a linear function of the
// position, blended with the masks the visitor reports, equals that function
// of the new positions after every level — on the border, on creases, at
// tagged corners too (every rule is an affine combination), for √3 on its
// refined border and for Doo-Sabin's corner points — and is the same on every
// backend.

double linear(const Eigen::Vector3d& p) { return 2.0 * p.x() - 3.0 * p.y() + 0.5 * p.z() + 1.0; }

struct Scalar_transport : genmesh::Mutation_visitor {
  std::vector<double> value, next;
  std::size_t calls = 0, steps = 0;
  int started = 0, finished = 0;
  double worst_weight_sum = 0;
  void on_started(const auto&) { ++started; }
  void on_finished(const auto&) { ++finished; }
  void on_step(std::string_view step, std::size_t done, std::size_t total) {
    EXPECT_EQ(step, "level");
    EXPECT_EQ(done, steps++);
    EXPECT_LE(done, total);
    if (done > 0) value.swap(next); // level done - 1 is complete
    next.clear();
  }
  void on_vertex_mask(std::uint32_t v, std::span<const std::uint32_t> src, std::span<const double> w) {
    double x = 0, sum = 0;
    for (std::size_t i = 0; i < src.size(); ++i) x += w[i] * value.at(src[i]), sum += w[i];
    worst_weight_sum = std::max(worst_weight_sum, std::abs(sum - 1.0));
    if (next.size() <= v) next.resize(v + 1, std::nan(""));
    next[v] = x;
    ++calls;
  }
};
static_assert(genmesh::visits_vertex_masks<Scalar_transport&>);
static_assert(!genmesh::visits_vertex_masks<genmesh::Mutation_visitor>);

TYPED_TEST(Subdivision, VisitorMasksCarryAttributesLikePositions) {
  Polygon_soup bumpy = genmesh::make_grid_with_hole(5);
  for (auto& p : bumpy.points) p.z() = std::sin(3 * p.x()) * std::cos(2 * p.y());
  const std::vector<std::pair<std::string, Polygon_soup>> cases = {{"icosphere", genmesh::make_icosphere(1)},
                                                                   {"bumpy annulus", bumpy},
                                                                   {"torus", genmesh::make_torus(8, 6, true)},
                                                                   {"quad torus", genmesh::make_torus(8, 6, false)}};
  for (const auto& [label, soup] : cases)
    for (Scheme scheme : {Scheme::loop, Scheme::catmull_clark, Scheme::butterfly, Scheme::midpoint, Scheme::sqrt3,
                          Scheme::doo_sabin})
      for (bool creases : {false, true}) {
        const bool smoothing = scheme == Scheme::loop || scheme == Scheme::catmull_clark;
        if ((creases && !smoothing) || (takes_triangles_only(scheme) && !all_triangles(soup))) continue;
        SCOPED_TRACE(label + " / " + name(scheme) + (creases ? " / creases + corner" : ""));
        auto run_on = [&](auto& g) {
          Scalar_transport t;
          for (const auto& p : soup.points) t.value.push_back(linear(p));
          const auto sharp = creases ? sharpness_where(g, [](std::size_t v) { return v < 6; }, 0.5)
                                     : std::vector<double>{};
          const std::vector<std::uint32_t> corners = creases ? std::vector<std::uint32_t>{7} : std::vector<std::uint32_t>{};
          switch (scheme) {
          case Scheme::loop:
            genmesh::loop_subdivision(g,
                                      genmesh::Loop_options{.iterations = 2,
                                                            .crease_map = crease_map_of(g, sharp),
                                                            .corner_map = corner_map_of(g, corners)},
                                      t);
            break;
          case Scheme::catmull_clark:
            genmesh::catmull_clark_subdivision(g,
                                               genmesh::Catmull_clark_options{.iterations = 2,
                                                                              .crease_map = crease_map_of(g, sharp),
                                                                              .corner_map = corner_map_of(g, corners)},
                                               t);
            break;
          case Scheme::butterfly: genmesh::butterfly_subdivision(g, {.iterations = 2}, t); break;
          // two levels: the second refines √3's border (the (16, 10, 1) and (4, 19, 4) masks)
          case Scheme::sqrt3: genmesh::sqrt3_subdivision(g, {.iterations = 2}, t); break;
          case Scheme::doo_sabin: genmesh::doo_sabin_subdivision(g, {.iterations = 2}, t); break;
          default: genmesh::midpoint_subdivision(g, {.iterations = 2}, t); break;
          }
          return t;
        };
        auto g = mesh_of<TypeParam>(soup);
        const Scalar_transport t = run_on(g);
        EXPECT_EQ(t.started, 1);
        EXPECT_EQ(t.finished, 1);
        EXPECT_EQ(t.steps, 3u); // done = 0, 1, 2
        const Polygon_soup out = genmesh::to_soup(g);
        ASSERT_EQ(t.value.size(), out.num_points());
        EXPECT_GT(t.calls, out.num_points());
        EXPECT_LT(t.worst_weight_sum, 1e-12);
        for (std::size_t v = 0; v < out.num_points(); ++v)
          ASSERT_NEAR(t.value[v], linear(out.points[v]), 1e-12) << "vertex " << v;
        auto reference = mesh_of<genmesh_test::Halfedge_mesh>(soup);
        EXPECT_EQ(run_on(reference).value, t.value); // identical on every backend
      }
}

// ---------------------------------------------------------------------------
// Tagged corners stay where they are at every level, interior or on the
// border; an untagged vertex of the corner map moves as without the map.

TYPED_TEST(Subdivision, TaggedCornersStay) {
  for (bool loop : {true, false}) {
    SCOPED_TRACE(loop ? "Loop" : "Catmull-Clark");
    const Polygon_soup soup = loop ? genmesh::make_grid_with_hole(6) : genmesh::make_torus(8, 6, false);
    Polygon_soup bumpy = soup;
    for (auto& p : bumpy.points) p.z() += std::sin(3 * p.x()) * std::cos(2 * p.y());
    const std::vector<std::uint32_t> corners = {0, 9, 20};
    auto g = mesh_of<TypeParam>(bumpy);
    auto plain = mesh_of<TypeParam>(bumpy);
    if (loop) {
      genmesh::loop_subdivision(g, genmesh::Loop_options{.iterations = 2, .corner_map = corner_map_of(g, corners)});
      genmesh::loop_subdivision(plain, {.iterations = 2});
    } else {
      genmesh::catmull_clark_subdivision(
          g, genmesh::Catmull_clark_options{.iterations = 2, .corner_map = corner_map_of(g, corners)});
      genmesh::catmull_clark_subdivision(plain, {.iterations = 2});
    }
    const Polygon_soup out = genmesh::to_soup(g), moved = genmesh::to_soup(plain);
    for (std::uint32_t c : corners) {
      EXPECT_EQ(out.points[c], bumpy.points[c]) << c;
      EXPECT_NE(moved.points[c], bumpy.points[c]) << c; // they would move untagged
    }
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
    auto h = mesh_of<TypeParam>(bumpy);
    if (loop) genmesh::loop_subdivision(h, genmesh::Loop_options{.iterations = 2, .corner_map = corner_map_of(h, {})});
    else genmesh::catmull_clark_subdivision(h, genmesh::Catmull_clark_options{.iterations = 2, .corner_map = corner_map_of(h, {})});
    EXPECT_EQ(genmesh::to_soup(h), moved);
  }
}

// ---------------------------------------------------------------------------
// A mesh with removed elements (here an isolated vertex removed, not yet
// collected) is refined through the local operations on the mesh itself (no
// copy), with the same result as the mesh without that vertex, creases
// included; every scheme reports live counts (with iterations = 0 too).

// The mesh of soup plus one isolated vertex, removed (not collected).
template <class G>
G mesh_with_a_removed_vertex(const Polygon_soup& soup) {
  Polygon_soup extra = soup;
  extra.add_point(9, 9, 9);
  auto g = mesh_of<G>(extra);
  typename boost::graph_traits<G>::vertex_descriptor last{};
  for (auto v : vertices(g)) last = v;
  remove_vertex(last, g);
  return g;
}

TYPED_TEST(Subdivision, EverySchemeOnAMeshWithARemovedVertexCountsLiveElements) {
  for (Scheme scheme : all_schemes)
    for (int levels : {0, 2}) {
      SCOPED_TRACE(name(scheme) + " x" + std::to_string(levels));
      const Polygon_soup soup =
          takes_triangles_only(scheme) ? genmesh::make_grid_with_hole(5) : genmesh::make_torus(8, 6, false);
      auto g = mesh_with_a_removed_vertex<TypeParam>(soup);
      auto clean = mesh_of<TypeParam>(soup);
      const genmesh::Subdivision_result a = run(scheme, g, levels), b = run(scheme, clean, levels);
      std::size_t live = 0;
      for (auto v : vertices(g)) (void)v, ++live;
      EXPECT_EQ(a.vertices, live);
      EXPECT_EQ(a.vertices, b.vertices);
      EXPECT_EQ(a.faces, b.faces);
      EXPECT_EQ(a.levels_done, levels);
      EXPECT_TRUE(genmesh::check_mesh(g).ok());
      EXPECT_EQ(genmesh::canonical(genmesh::to_soup(g)), genmesh::canonical(genmesh::to_soup(clean)));
    }
}

TYPED_TEST(Subdivision, MeshWithRemovedElementsKeepsItsCreases) {
  for (bool loop : {true, false}) {
    SCOPED_TRACE(loop ? "Loop" : "Catmull-Clark");
    const Polygon_soup soup = loop ? genmesh::make_grid_with_hole(5) : genmesh::make_torus(8, 6, false);
    auto g = mesh_with_a_removed_vertex<TypeParam>(soup);
    auto clean = mesh_of<TypeParam>(soup);
    const auto sharp = sharpness_where(clean, [](std::size_t v) { return v < 6; }, 3.5);
    genmesh::Subdivision_result a, b;
    auto mg = crease_map_of(g, sharp), mc = crease_map_of(clean, sharp);
    if (loop) {
      a = genmesh::loop_subdivision(g, genmesh::Loop_options{.iterations = 2, .crease_map = mg});
      b = genmesh::loop_subdivision(clean, genmesh::Loop_options{.iterations = 2, .crease_map = mc});
    } else {
      a = genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.iterations = 2, .crease_map = mg});
      b = genmesh::catmull_clark_subdivision(clean, genmesh::Catmull_clark_options{.iterations = 2, .crease_map = mc});
    }
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.faces, b.faces);
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
    EXPECT_EQ(genmesh::canonical(genmesh::to_soup(g)), genmesh::canonical(genmesh::to_soup(clean)));
    // the sharpness follows the edges of each result: same multiset of crease edges by their end points
    auto creased = [](const auto& m, const std::vector<double>& s) {
      std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> out;
      auto pts = get(genmesh::vertex_point, const_cast<std::remove_cvref_t<decltype(m)>&>(m));
      std::size_t i = 0;
      for (auto e : edges(m)) {
        if (s.at(i++) <= 0) continue;
        Eigen::Vector3d p = genmesh::to_eigen(get(pts, source(halfedge(e, m), m)));
        Eigen::Vector3d q = genmesh::to_eigen(get(pts, target(halfedge(e, m), m)));
        if (std::lexicographical_compare(q.data(), q.data() + 3, p.data(), p.data() + 3)) std::swap(p, q);
        out.emplace_back(p, q);
      }
      std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
        return std::lexicographical_compare(x.first.data(), x.first.data() + 3, y.first.data(), y.first.data() + 3) ||
               (x.first == y.first &&
                std::lexicographical_compare(x.second.data(), x.second.data() + 3, y.second.data(), y.second.data() + 3));
      });
      return out;
    };
    EXPECT_EQ(creased(g, sharpness_of(g, mg)), creased(clean, sharpness_of(clean, mc)));
    EXPECT_FALSE(creased(g, sharpness_of(g, mg)).empty());
  }
}

// ---------------------------------------------------------------------------
// .vertex_point_map: the positions are read and written through the given map
// (an external map over the vertex index holding twice the mesh's own
// points), for every scheme, on the in-place paths and the rebuild path: the
// map ends with exactly twice the positions of a run on the mesh's own points
// (scaling by 2 is exact), on every backend.

TYPED_TEST(Subdivision, VertexPointMapIsReadAndWritten) {
  for (Scheme scheme : all_schemes) {
    if (scheme == Scheme::loop_warren) continue;
    SCOPED_TRACE(name(scheme));
    const Polygon_soup soup =
        takes_triangles_only(scheme) ? genmesh::make_grid_with_hole(5) : genmesh::make_torus(8, 6, false);
    auto g = mesh_of<TypeParam>(soup), reference = mesh_of<TypeParam>(soup);
    auto vi = get(genmesh::vertex_index, g);
    boost::vector_property_map<Eigen::Vector3d, decltype(vi)> twice(
        static_cast<unsigned>(index_bound(genmesh::vertex_index, g)), vi);
    auto own = get(genmesh::vertex_point, g);
    for (auto v : vertices(g)) put(twice, v, Eigen::Vector3d(2.0 * genmesh::to_eigen(get(own, v))));
    switch (scheme) {
    case Scheme::loop: genmesh::loop_subdivision(g, genmesh::Loop_options{.iterations = 2, .vertex_point_map = twice}); break;
    case Scheme::catmull_clark:
      genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.iterations = 2, .vertex_point_map = twice});
      break;
    case Scheme::butterfly:
      genmesh::butterfly_subdivision(g, genmesh::Butterfly_options{.iterations = 2, .vertex_point_map = twice});
      break;
    case Scheme::sqrt3: genmesh::sqrt3_subdivision(g, genmesh::Sqrt3_options{.iterations = 2, .vertex_point_map = twice}); break;
    case Scheme::doo_sabin:
      genmesh::doo_sabin_subdivision(g, genmesh::Doo_sabin_options{.iterations = 2, .vertex_point_map = twice});
      break;
    default: genmesh::midpoint_subdivision(g, genmesh::Midpoint_options{.iterations = 2, .vertex_point_map = twice}); break;
    }
    run(scheme, reference, 2);
    const Polygon_soup ref = genmesh::to_soup(reference);
    std::size_t k = 0;
    for (auto v : vertices(g)) {
      ASSERT_LT(k, ref.num_points());
      EXPECT_EQ(get(twice, v), Eigen::Vector3d(2.0 * ref.points[k])) << k;
      ++k;
    }
    EXPECT_EQ(k, ref.num_points());
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
  }
}

// ---------------------------------------------------------------------------
// Incidence_mesh refines with its own operations, not on a copy. With
// removed elements waiting (here one removed vertex, whose slot the first new
// vertex reuses) it takes the local operations: its native split_edge /
// split_face report to the visitor with Incidence_mesh descriptors (a copy of
// another type would report nothing), once per old edge and per cut, and the
// result's incidence matrices still compose to zero. (Without removed
// elements it takes its native bulk relink: next test.)

/// g with one removed vertex at the end of the index range: not dense, so
/// the in-place schemes take the local operations, and the first new vertex
/// recycles the slot, so elements get the indices a dense g would give them.
genmesh_test::Incidence_mesh with_free_vertex_slot(genmesh_test::Incidence_mesh g) {
  g.remove_vertex(g.add_vertex());
  return g;
}

struct Count_incidence_operations : genmesh::Mutation_visitor {
  std::size_t splits = 0, cuts = 0;
  void on_split_edge(genmesh::Halfedge_index, const genmesh_test::Incidence_mesh&) { ++splits; }
  void on_split_face(genmesh::Halfedge_index, const genmesh_test::Incidence_mesh&) { ++cuts; }
};

TEST(SubdivisionNative, IncidenceMeshRefinesWithItsOwnOperations) {
  for (Scheme scheme : {Scheme::loop, Scheme::catmull_clark, Scheme::butterfly, Scheme::midpoint}) {
    SCOPED_TRACE(name(scheme));
    const Polygon_soup soup = scheme == Scheme::catmull_clark ? genmesh::make_torus(8, 6, false)
                                                              : genmesh::make_grid_with_hole(5);
    auto g = with_free_vertex_slot(mesh_of<genmesh_test::Incidence_mesh>(soup));
    std::size_t splits = 0, cuts = 0; // expected: per level, every edge split; every face cut
    {
      auto h = mesh_of<genmesh_test::Halfedge_mesh>(soup);
      for (int level = 0; level < 2; ++level) {
        splits += static_cast<std::size_t>(num_edges(h));
        for (auto f : faces(h)) {
          std::size_t n = 0;
          auto x = halfedge(f, h);
          do ++n, x = next(x, h);
          while (x != halfedge(f, h));
          if (scheme == Scheme::catmull_clark) splits += 1, cuts += n - 1; // face point on the first cut
          else cuts += 3;
        }
        run(scheme, h, 1);
      }
    }
    Count_incidence_operations c;
    switch (scheme) {
    case Scheme::loop: genmesh::loop_subdivision(g, {.iterations = 2}, c); break;
    case Scheme::catmull_clark: genmesh::catmull_clark_subdivision(g, {.iterations = 2}, c); break;
    case Scheme::butterfly: genmesh::butterfly_subdivision(g, {.iterations = 2}, c); break;
    default: genmesh::midpoint_subdivision(g, {.iterations = 2}, c); break;
    }
    EXPECT_EQ(c.splits, splits);
    EXPECT_EQ(c.cuts, cuts);
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
    const Eigen::SparseMatrix<int> d0 = g.d0(), d1 = g.d1();
    EXPECT_EQ(Eigen::SparseMatrix<int>(d1 * d0).norm(), 0);
    EXPECT_EQ(static_cast<std::size_t>(d0.rows()), static_cast<std::size_t>(num_edges(g)));
  }
}

/// Every edge's ends by edge index and every face's vertex cycle (from its
/// lowest vertex) by face index: the element numbering, edge directions
/// included.
struct Numbered_elements {
  std::vector<std::array<std::size_t, 2>> edge_ends;
  std::vector<std::vector<std::size_t>> face_cycles;
  bool operator==(const Numbered_elements&) const = default;
};
template <class G>
Numbered_elements numbered_elements(const G& g) {
  Numbered_elements n;
  auto vi = get(genmesh::vertex_index, g);
  for (auto e : edges(g)) {
    const auto h = halfedge(e, g);
    n.edge_ends.push_back({get(vi, source(h, g)), get(vi, target(h, g))});
  }
  for (auto f : faces(g)) {
    std::vector<std::size_t> c;
    auto h = halfedge(f, g);
    do c.push_back(get(vi, target(h, g)));
    while ((h = next(h, g)) != halfedge(f, g));
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    n.face_cycles.push_back(std::move(c));
  }
  return n;
}

// Without removed elements, Incidence_mesh takes the in-place schemes' bulk
// path in its own form: the level's result computed from the old mesh and
// written into its four matrices in one pass (genmesh_native_relink), no
// local operation called. It numbers every element exactly as the bulk path
// of Halfedge_mesh (the generic append, linked with set_next) does: the same
// edge ends (directions included) and face cycles at every index, the same
// points, the same crease sharpness per edge. Its local operations (taken
// when an element was removed) give the same points at the same indices and
// the same soup, but their split_face gives an inner edge the other
// direction, so after two levels the edge numbering differs.
TEST(SubdivisionNative, IncidenceMeshBulkRelinkNumbersLikeTheBulkPath) {
  namespace ds = genmesh::detail::subdivision;
  static_assert(ds::Has_native_relink<genmesh_test::Incidence_mesh>);
  for (Scheme scheme : {Scheme::loop, Scheme::catmull_clark, Scheme::butterfly, Scheme::midpoint}) {
    for (const Polygon_soup& soup : {genmesh::make_grid_with_hole(5), genmesh::make_icosphere(1),
                                     scheme == Scheme::catmull_clark ? genmesh::make_torus(8, 6, false)
                                                                     : genmesh::make_torus(8, 6, true)}) {
      SCOPED_TRACE(name(scheme) + " on " + std::to_string(soup.num_faces()) + " faces");
      auto dense = mesh_of<genmesh_test::Incidence_mesh>(soup);
      auto local = with_free_vertex_slot(dense);
      auto bulk = mesh_of<genmesh_test::Halfedge_mesh>(soup);
      auto dc = genmesh::make_crease_map(dense);
      auto lc = genmesh::make_crease_map(local);
      auto bc = genmesh::make_crease_map(bulk);
      std::size_t k = 0;
      for (auto e : edges(dense)) put(dc, e, (k++ % 5) * 0.75);
      k = 0;
      for (auto e : edges(local)) put(lc, e, (k++ % 5) * 0.75);
      k = 0;
      for (auto e : edges(bulk)) put(bc, e, (k++ % 5) * 0.75);
      Count_incidence_operations on_dense, on_local;
      auto subdivide = [&](auto& g, auto crease, auto&& visitor) {
        switch (scheme) {
        case Scheme::loop:
          genmesh::loop_subdivision(g, genmesh::Loop_options{.iterations = 2, .crease_map = crease}, visitor);
          break;
        case Scheme::catmull_clark:
          genmesh::catmull_clark_subdivision(g, genmesh::Catmull_clark_options{.iterations = 2, .crease_map = crease},
                                             visitor);
          break;
        case Scheme::butterfly: genmesh::butterfly_subdivision(g, {.iterations = 2}, visitor); break;
        default: genmesh::midpoint_subdivision(g, {.iterations = 2}, visitor); break;
        }
      };
      subdivide(dense, dc, on_dense);
      subdivide(local, lc, on_local);
      subdivide(bulk, bc, genmesh::Mutation_visitor{});
      EXPECT_EQ(on_dense.splits + on_dense.cuts, 0u); // the bulk relink ran, no local operation
      EXPECT_GT(on_local.splits, 0u);                 // the local operations ran
      EXPECT_EQ(numbered_elements(dense), numbered_elements(bulk));
      ASSERT_EQ(num_vertices(dense), num_vertices(bulk));
      for (auto v : vertices(dense)) {
        EXPECT_EQ(dense.point(v), genmesh::to_eigen(bulk.point(genmesh::Vertex_index(v.idx())))) << v.idx();
        EXPECT_EQ(dense.point(v), local.point(v)) << v.idx();
      }
      for (auto e : edges(dense)) EXPECT_EQ(get(dc, e), get(bc, genmesh::Edge_index(e.idx()))) << e.idx();
      EXPECT_EQ(Eigen::SparseMatrix<int>(dense.d1() * dense.d0()).norm(), 0);
      EXPECT_TRUE(genmesh::check_mesh(dense).ok());
      EXPECT_EQ(genmesh::canonical(genmesh::to_soup(dense)), genmesh::canonical(genmesh::to_soup(local)));
    }
  }
}

// ---------------------------------------------------------------------------
// The bulk append of the in-place refinement is native on Halfedge_mesh and
// Surface_mesh (Polyhedron_3 and OpenMesh use the generic one:
// test_cgal_interop.cpp). A native append must name exactly the elements the
// generic one makes, in the same order — also when removed elements wait
// for recycling, where both reuse the free slots first.

template <class G>
void expect_native_append_is_generic(G g, bool with_free_slots) {
  namespace ds = genmesh::detail::subdivision;
  static_assert(ds::Has_native_append<G>);
  typename boost::graph_traits<G>::vertex_descriptor freed{};
  typename boost::graph_traits<G>::face_descriptor freed_face{};
  if (with_free_slots) {
    freed = add_vertex(g);
    freed_face = add_face(g);
    remove_vertex(freed, g);
    remove_edge(add_edge(g), g);
    remove_face(freed_face, g);
  }
  G copy = g;
  const auto a = ds::append_elements(g, 3, 4, 2);
  const auto b = ds::generic_append_elements(copy, 3, 4, 2);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(a.vertex(k), b.vertex(k)) << k;
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(a.halfedge(k, 0), b.halfedge(k, 0)) << k;
    EXPECT_EQ(a.halfedge(k, 1), b.halfedge(k, 1)) << k;
    EXPECT_EQ(a.halfedge(k, 1), opposite(a.halfedge(k, 0), g)) << k;
  }
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(a.face(k), b.face(k)) << k;
  EXPECT_EQ(index_bound(genmesh::vertex_index, g), index_bound(genmesh::vertex_index, copy));
  EXPECT_EQ(index_bound(genmesh::halfedge_index, g), index_bound(genmesh::halfedge_index, copy));
  EXPECT_EQ(index_bound(genmesh::face_index, g), index_bound(genmesh::face_index, copy));
  if (with_free_slots) { // the freed slots are reused first
    EXPECT_EQ(a.vertex(0), freed);
    EXPECT_EQ(a.face(0), freed_face);
  }
}

TEST(SubdivisionNative, NativeAppendGivesTheGenericElements) {
  for (bool free_slots : {false, true}) {
    SCOPED_TRACE(free_slots ? "with free slots" : "dense");
    expect_native_append_is_generic(mesh_of<genmesh_test::Halfedge_mesh>(genmesh::make_cube()), free_slots);
    expect_native_append_is_generic(mesh_of<genmesh_test::Surface_mesh>(genmesh::make_cube()), free_slots);
  }
}

// √3, Doo-Sabin and midpoint on polygons build each level's mesh from a soup
// (detail::link_soup into a fresh mesh of the same type). Incidence_mesh has
// no set_next for the generic linking, so on it that can only be its own
// genmesh_native_link_soup: the schemes run on its own code, not on a copy,
// and give Halfedge_mesh's soups.
TEST(SubdivisionNative, RebuildingSchemesLinkNativelyOnIncidenceMesh) {
  static_assert(genmesh::detail::Has_native_link_soup<genmesh_test::Incidence_mesh> &&
                !genmesh::MutableFaceGraph<genmesh_test::Incidence_mesh>);
  for (Scheme scheme : {Scheme::sqrt3, Scheme::doo_sabin, Scheme::midpoint}) {
    SCOPED_TRACE(name(scheme));
    const Polygon_soup soup = scheme == Scheme::sqrt3 ? genmesh::make_icosphere(1) : genmesh::make_cube();
    auto i = mesh_of<genmesh_test::Incidence_mesh>(soup);
    auto h = mesh_of<genmesh_test::Halfedge_mesh>(soup);
    run(scheme, i, 2);
    run(scheme, h, 2);
    EXPECT_EQ(genmesh::canonical(genmesh::to_soup(i)), genmesh::canonical(genmesh::to_soup(h)));
    EXPECT_GT(num_faces(i), soup.num_faces());
    EXPECT_TRUE(genmesh::check_mesh(i).ok());
    const Eigen::SparseMatrix<int> d0 = i.d0(), d1 = i.d1();
    EXPECT_EQ(Eigen::SparseMatrix<int>(d1 * d0).norm(), 0);
  }
}

// Crease and corner maps are scratch properties of the mesh: on genmesh's
// meshes and Surface_mesh they live in the mesh's own property system (so
// they grow and are compacted with it), and leave it with their last copy.
TEST(SubdivisionNative, CreaseMapsLiveInTheMeshsPropertySystem) {
  auto h = mesh_of<genmesh_test::Halfedge_mesh>(genmesh::make_cube());
  auto i = mesh_of<genmesh_test::Incidence_mesh>(genmesh::make_cube());
  auto s = mesh_of<genmesh_test::Surface_mesh>(genmesh::make_cube());
  // anonymous properties are not named: their bytes show them
  const std::size_t hb = h.memory_bytes(), ib = i.memory_bytes();
  const std::size_t se = s.properties<genmesh_test::Surface_mesh::Edge_index>().size();
  {
    auto hc = genmesh::make_crease_map(h);
    auto ic = genmesh::make_crease_map(i);
    auto sc = genmesh::make_crease_map(s);
    auto hk = genmesh::make_corner_map(h);
    EXPECT_GE(h.memory_bytes(), hb + 12 * sizeof(double) + 8);
    EXPECT_GE(i.memory_bytes(), ib + 12 * sizeof(double));
    EXPECT_EQ(s.properties<genmesh_test::Surface_mesh::Edge_index>().size(), se + 1);
    for (auto e : edges(h)) put(hc, e, 2.0);
    genmesh::catmull_clark_subdivision(h, genmesh::Catmull_clark_options{.crease_map = hc, .corner_map = hk});
    std::size_t sharp = 0, other = 0; // the halves of the 12 old edges get 2 − 1, new edges 0
    for (auto e : edges(h)) {
      const double x = get(hc, e);
      if (x == 1.0) ++sharp;
      else if (x != 0.0) ++other;
    }
    EXPECT_EQ(sharp, 24u);
    EXPECT_EQ(other, 0u);
    (void)ic, (void)sc;
  }
  EXPECT_EQ(i.memory_bytes(), ib);
  EXPECT_EQ(s.properties<genmesh_test::Surface_mesh::Edge_index>().size(), se);
}

} // namespace

namespace {

// In place: the old vertices keep their descriptors and their user
// properties; the new ones get the property's default.
TEST(SubdivisionInPlace, OldVerticesKeepTheirPropertiesNewOnesGetTheDefault) {
  for (bool loop : {true, false}) {
    SCOPED_TRACE(loop ? "Loop" : "Catmull-Clark");
    auto g = mesh_of<genmesh_test::Halfedge_mesh>(loop ? genmesh::make_icosphere(1) : genmesh::make_cube());
    auto tag = g.add_vertex_property<int>("v:tag", -1);
    std::vector<genmesh::Vertex_index> old;
    for (auto v : g.vertices()) tag[v] = static_cast<int>(old.size()), old.push_back(v);
    if (loop) genmesh::loop_subdivision(g, {.iterations = 2});
    else genmesh::catmull_clark_subdivision(g, {.iterations = 2});
    for (std::size_t i = 0; i < old.size(); ++i) EXPECT_EQ(tag[old[i]], static_cast<int>(i));
    std::size_t fresh = 0;
    for (auto v : g.vertices()) fresh += tag[v] == -1;
    EXPECT_EQ(fresh, g.n_vertices() - old.size());
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
  }
}

} // namespace
