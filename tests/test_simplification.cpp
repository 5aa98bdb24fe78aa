// Simplification: every policy and stop condition on every backend (identical
// canonical soups), topological invariants after every run, refusals, and
// CGAL's Surface_mesh_simplification::edge_collapse (Garland–Heckbert plane
// policies) as the quality oracle: genmesh's symmetric Hausdorff distance to
// the input is no worse than CGAL's at the same face count.
//
// Every search of the self-intersection guard that its ring certificate
// decides is checked again here by the exact test (std::logic_error if the
// certificate ever accepts two faces that meet): each test of this file that
// runs the guard also tests the certificate.
#define GENMESH_SIMPLIFICATION_VERIFY_CERTIFICATES 1
#include "backends.h"

#include <genmesh/generators.h>
#include <genmesh/features.h>
#include <genmesh/io.h>
#include <genmesh/measures.h>
#include <genmesh/properties.h>
#include <genmesh/simplification.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <boost/property_map/property_map.hpp>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace {

using genmesh::Polygon_soup;
using genmesh_test::Backends;
using genmesh_test::mesh_of;

struct Named_soup {
  std::string name;
  Polygon_soup soup;
};

// Closed (genus 0 and 1), bordered, with a hole, and real meshes (a closed
// one and one with many holes).
const std::vector<Named_soup>& inputs() {
  static const std::vector<Named_soup> all = [] {
    std::vector<Named_soup> v;
    v.push_back({"icosphere", genmesh::make_icosphere(3)});
    v.push_back({"torus", genmesh::make_torus(32, 16, true)});
    v.push_back({"grid", genmesh::make_grid(20, 20)});
    v.push_back({"grid_with_hole", genmesh::make_grid_with_hole(16)});
    v.push_back({"elephant", genmesh::read_soup(genmesh_test::real_mesh("elephant.off"))});
    v.push_back({"mech-holes-shark", genmesh::read_soup(genmesh_test::real_mesh("mech-holes-shark.off"))});
    return v;
  }();
  return all;
}

template <class Range>
std::size_t count(const Range& r) {
  return static_cast<std::size_t>(std::distance(r.begin(), r.end()));
}

template <class G>
Polygon_soup canonical_of(const G& g) {
  return genmesh::canonical(genmesh::to_soup(g));
}

void expect_same_soup(const Polygon_soup& a, const Polygon_soup& b, const std::string& what) {
  ASSERT_EQ(a.points.size(), b.points.size()) << what;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    ASSERT_TRUE(a.points[i] == b.points[i]) << what << ": point " << i << " differs";
  ASSERT_EQ(a.offsets, b.offsets) << what;
  ASSERT_EQ(a.indices, b.indices) << what;
}

// Same genus, border loops and components as before; valid, manifold, all triangles.
template <class G>
void expect_invariants(const G& g, const genmesh::Mesh_report& before, const std::string& what) {
  const auto r = genmesh::check_mesh(g);
  ASSERT_TRUE(r.ok()) << what << ": " << (r.problems.empty() ? "" : r.problems[0].message);
  EXPECT_TRUE(r.is_triangle_mesh) << what;
  EXPECT_EQ(r.genus, before.genus) << what;
  EXPECT_EQ(r.boundary_loops, before.boundary_loops) << what;
  EXPECT_EQ(r.components, before.components) << what;
}

// No face of the result is degenerate.
template <class G>
double min_face_area(const G& g) {
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<G>;
  double m = std::numeric_limits<double>::infinity();
  for (auto f : faces(g)) {
    auto h = halfedge(f, g);
    const Eigen::Vector3d a = genmesh::to_eigen(P(get(pm, target(h, g))));
    const Eigen::Vector3d b = genmesh::to_eigen(P(get(pm, target(next(h, g), g))));
    const Eigen::Vector3d c = genmesh::to_eigen(P(get(pm, target(next(next(h, g), g), g))));
    m = std::min(m, 0.5 * (b - a).cross(c - a).norm());
  }
  return m;
}

enum class Policy { plane, plane_area, probabilistic, length, lindstrom_turk };
constexpr Policy all_policies[] = {Policy::plane, Policy::plane_area, Policy::probabilistic, Policy::length,
                                   Policy::lindstrom_turk};
const char* name(Policy p) {
  const char* n[] = {"plane", "plane_area", "probabilistic", "length", "lindstrom_turk"};
  return n[static_cast<int>(p)];
}

template <class G>
genmesh::Simplification_result run(G& g, Policy p, double ratio,
                                   genmesh::Border_mode b = genmesh::Border_mode::preserve,
                                   std::optional<double> feature_angle = std::nullopt,
                                   genmesh::Schedule schedule = genmesh::Schedule::queue) {
  auto go = [&]<class P>(P policy) {
    return genmesh::simplify(g, genmesh::Simplification_options<P>{.target_ratio = ratio,
                                                                   .policy = policy,
                                                                   .border = b,
                                                                   .feature_angle = feature_angle,
                                                                   .schedule = schedule});
  };
  switch (p) {
  case Policy::plane: return go(genmesh::Plane_quadrics{});
  case Policy::plane_area: return go(genmesh::Plane_quadrics{.area_weighted = true});
  case Policy::probabilistic: return go(genmesh::Probabilistic_quadrics{});
  case Policy::length: return go(genmesh::Edge_length{});
  case Policy::lindstrom_turk: return go(genmesh::Lindstrom_turk{});
  }
  return {};
}

template <class T>
class Simplification : public ::testing::Test {};
TYPED_TEST_SUITE(Simplification, Backends);

// Every policy and border mode: the target is met, the mesh stays valid with
// its topology, no face is degenerate, and the soup equals Halfedge_mesh's.
TYPED_TEST(Simplification, EveryPolicyKeepsTopologyAndEqualsHalfedgeMesh) {
  for (const auto& in : inputs()) {
    for (const Policy p : all_policies) {
      for (const auto b : {genmesh::Border_mode::preserve, genmesh::Border_mode::lock, genmesh::Border_mode::free}) {
        if (p != Policy::plane && b != genmesh::Border_mode::preserve) continue;
        const std::string what = in.name + " " + name(p) + " border " + std::to_string(static_cast<int>(b));
        TypeParam g = mesh_of<TypeParam>(in.soup);
        const auto before = genmesh::check_mesh(g);
        const auto r = run(g, p, 0.1, b);
        expect_invariants(g, before, what);
        EXPECT_EQ(r.faces, count(faces(g))) << what;
        EXPECT_EQ(r.vertices, count(vertices(g))) << what;
        EXPECT_EQ(r.collapses, before.vertices - r.vertices) << what;
        if (r.stop_reason == genmesh::Stop_reason::target_faces) {
          EXPECT_LE(r.faces, static_cast<std::size_t>(std::ceil(0.1 * static_cast<double>(before.faces)))) << what;
        } else {
          // Only locked borders may stop a mesh early (the grids are mostly border).
          EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::no_collapse_left) << what;
          EXPECT_EQ(b, genmesh::Border_mode::lock) << what;
        }
        EXPECT_GT(min_face_area(g), 0.0) << what;
        if constexpr (std::is_same_v<TypeParam, genmesh_test::Halfedge_mesh>) continue; // the reference itself
        genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(in.soup);
        const auto rr = run(ref, p, 0.1, b);
        EXPECT_EQ(rr.collapses, r.collapses) << what;
        EXPECT_EQ(rr.max_error, r.max_error) << what;
        expect_same_soup(canonical_of(g), canonical_of(ref), what);
      }
    }
  }
}

// Schedule::passes: every policy, a locked border and feature lines on every
// input; the target is met exactly as with the queue (the run stops at the
// first collapse that reaches it), the mesh keeps its topology, no face is
// degenerate, and the soup equals Halfedge_mesh's. The order differs from
// the queue's, so the meshes do (on the elephant at least). A .max_error run
// stops by max_error with every collapse within it.
TYPED_TEST(Simplification, PassesScheduleKeepsTopologyAndEqualsHalfedgeMesh) {
  constexpr auto passes = genmesh::Schedule::passes;
  bool differs = false;
  for (const auto& in : inputs()) {
    for (const Policy p : all_policies) {
      for (const bool variant : {false, true}) {
        if (variant && p != Policy::plane && p != Policy::lindstrom_turk) continue;
        // The variant: a locked border, and feature lines at 60°.
        const auto b = variant ? genmesh::Border_mode::lock : genmesh::Border_mode::preserve;
        const auto features = variant ? std::optional<double>(60.0) : std::nullopt;
        const std::string what = in.name + " " + name(p) + (variant ? " locked, features" : "");
        TypeParam g = mesh_of<TypeParam>(in.soup);
        const auto before = genmesh::check_mesh(g);
        const auto r = run(g, p, 0.1, b, features, passes);
        expect_invariants(g, before, what);
        EXPECT_EQ(r.faces, count(faces(g))) << what;
        EXPECT_EQ(r.collapses, before.vertices - r.vertices) << what;
        const auto target = static_cast<std::size_t>(std::ceil(0.1 * static_cast<double>(before.faces)));
        if (r.stop_reason == genmesh::Stop_reason::target_faces) {
          EXPECT_LE(r.faces, target) << what;
          EXPECT_GE(r.faces + 2, target) << what; // the last collapse removes at most two faces
        } else {
          EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::no_collapse_left) << what;
          EXPECT_EQ(b, genmesh::Border_mode::lock) << what;
        }
        EXPECT_GT(min_face_area(g), 0.0) << what;
        if (in.name == "elephant" && p == Policy::plane && !variant) {
          TypeParam q = mesh_of<TypeParam>(in.soup);
          run(q, p, 0.1, b, features);
          differs = canonical_of(q).points != canonical_of(g).points;
        }
        if constexpr (std::is_same_v<TypeParam, genmesh_test::Halfedge_mesh>) continue; // the reference itself
        genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(in.soup);
        const auto rr = run(ref, p, 0.1, b, features, passes);
        EXPECT_EQ(rr.collapses, r.collapses) << what;
        EXPECT_EQ(rr.max_error, r.max_error) << what;
        expect_same_soup(canonical_of(g), canonical_of(ref), what);
      }
    }
  }
  EXPECT_TRUE(differs) << "the passes gave the queue's mesh: is the option read?";
  const Polygon_soup elephant = genmesh::read_soup(genmesh_test::real_mesh("elephant.off"));
  TypeParam g = mesh_of<TypeParam>(elephant);
  const double limit = 0.002;
  const auto r = genmesh::simplify(g, {.max_error = limit, .max_error_relative = true, .schedule = passes});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::max_error);
  EXPECT_GT(r.collapses, 0u);
  const double diagonal = [&] {
    Eigen::AlignedBox3d box;
    for (const auto& x : elephant.points) box.extend(x);
    return box.diagonal().norm();
  }();
  EXPECT_LE(r.max_error, limit * diagonal);
  genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(elephant);
  genmesh::simplify(ref, {.max_error = limit, .max_error_relative = true, .schedule = passes});
  expect_same_soup(canonical_of(g), canonical_of(ref), "max_error");
}

// A locked border keeps every border point where it was.
TYPED_TEST(Simplification, LockedBorderStays) {
  const Polygon_soup soup = genmesh::make_grid_with_hole(16);
  TypeParam g = mesh_of<TypeParam>(soup);
  auto border_points = [](const auto& m) {
    std::set<std::tuple<double, double, double>> s;
    auto pm = get(genmesh::vertex_point, m);
    using P = genmesh::point_t<std::remove_cvref_t<decltype(m)>>;
    for (auto h : halfedges(m))
      if (face(h, m) == boost::graph_traits<std::remove_cvref_t<decltype(m)>>::null_face()) {
        const Eigen::Vector3d p = genmesh::to_eigen(P(get(pm, target(h, m))));
        s.emplace(p.x(), p.y(), p.z());
      }
    return s;
  };
  const auto before = border_points(g);
  genmesh::simplify(g, {.target_ratio = 0.2, .border = genmesh::Border_mode::lock});
  EXPECT_EQ(border_points(g), before);
  // Preserve keeps the straight outer border straight (boundary quadrics).
  TypeParam g2 = mesh_of<TypeParam>(soup);
  genmesh::simplify(g2, {.target_ratio = 0.2});
  for (const auto& [x, y, z] : border_points(g2)) EXPECT_NEAR(z, 0.0, 1e-9);
}

// Locked vertices keep their index and their point.
TYPED_TEST(Simplification, LockedVerticesStay) {
  const Polygon_soup soup = genmesh::make_icosphere(3);
  TypeParam g = mesh_of<TypeParam>(soup);
  auto locked = [](std::size_t v) { return v % 7 == 0; };
  const auto r = genmesh::simplify(g, {.target_ratio = 0.1, .is_locked = locked});
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
  EXPECT_LT(r.faces, soup.num_faces() / 4);
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<TypeParam>;
  std::size_t seen = 0;
  for (auto v : vertices(g)) {
    const auto i = static_cast<std::size_t>(get(get(genmesh::vertex_index, g), v));
    if (!locked(i)) continue;
    ++seen;
    EXPECT_TRUE(genmesh::to_eigen(P(get(pm, v))) == soup.points[i]) << "vertex " << i;
  }
  EXPECT_EQ(seen, (soup.points.size() + 6) / 7);
}

TYPED_TEST(Simplification, MaxErrorStops) {
  TypeParam g = mesh_of<TypeParam>(inputs()[4].soup); // elephant
  const auto r = genmesh::simplify(g, {.max_error = 0.002, .max_error_relative = true});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::max_error);
  EXPECT_GT(r.collapses, 100u);
  // The diagonal of the elephant's box is below 2.
  EXPECT_LE(r.max_error, 0.002 * 2.0);
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
}

TYPED_TEST(Simplification, TargetAboveCountDoesNothing) {
  const Polygon_soup soup = genmesh::make_icosphere(2);
  TypeParam g = mesh_of<TypeParam>(soup);
  const auto before = canonical_of(g);
  const auto r = genmesh::simplify(g, {.target_faces = 100000});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_already_met);
  EXPECT_EQ(r.collapses, 0u);
  EXPECT_EQ(r.faces, soup.num_faces());
  expect_same_soup(canonical_of(g), before, "untouched");
  const auto r1 = genmesh::simplify(g, {.target_ratio = 1.0});
  EXPECT_EQ(r1.stop_reason, genmesh::Stop_reason::target_already_met);
}

// Target 0: the smallest mesh the constraints allow, still valid.
TYPED_TEST(Simplification, TargetZeroStopsAtSmallestValidMesh) {
  for (const auto& in : {inputs()[0], inputs()[1], inputs()[3]}) {
    TypeParam g = mesh_of<TypeParam>(in.soup);
    const auto before = genmesh::check_mesh(g);
    const auto r = genmesh::simplify(g, {.target_faces = 0});
    EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::no_collapse_left) << in.name;
    expect_invariants(g, before, in.name);
    EXPECT_GE(r.faces, 4u) << in.name;
    EXPECT_LT(r.faces, before.faces / 10) << in.name;
  }
}

TYPED_TEST(Simplification, Refusals) {
  // A polygon is refused naming the face, or triangulated on request.
  {
    TypeParam g = mesh_of<TypeParam>(genmesh::make_cube());
    try {
      genmesh::simplify(g, {.target_faces = 4});
      ADD_FAILURE() << "a quad was accepted";
    } catch (const genmesh::invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find("face 0 is not a triangle"), std::string::npos) << e.what();
    }
    EXPECT_EQ(count(faces(g)), 6u);
    const auto r = genmesh::simplify(g, {.target_faces = 4, .triangulate = true});
    EXPECT_TRUE(genmesh::check_mesh(g).ok());
    EXPECT_EQ(r.faces, 4u);
  }
  // A non-finite point is refused naming the vertex.
  {
    Polygon_soup s = genmesh::make_icosphere(1);
    s.points[7].y() = std::numeric_limits<double>::quiet_NaN();
    TypeParam g;
    genmesh::build_mesh(s, g, {.check = false});
    try {
      genmesh::simplify(g, {.target_ratio = 0.5});
      ADD_FAILURE() << "a NaN was accepted";
    } catch (const genmesh::invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos) << e.what();
    }
  }
  // A non-manifold vertex (two tetrahedra sharing a corner) is refused.
  {
    Polygon_soup s = genmesh::make_tetrahedron();
    const auto n = static_cast<Polygon_soup::Index>(s.points.size());
    for (std::size_t i = 1; i < n; ++i) s.add_point(s.points[i] + Eigen::Vector3d(0, 0, 3));
    const std::size_t nf = s.num_faces();
    for (std::size_t f = 0; f < nf; ++f) {
      std::vector<Polygon_soup::Index> c(s.face(f).begin(), s.face(f).end());
      for (auto& i : c) i = i == 0 ? 0 : i + n - 1;
      s.add_face(c);
    }
    TypeParam g;
    genmesh::build_mesh(s, g, {.check = false});
    EXPECT_THROW(genmesh::simplify(g, {.target_ratio = 0.5}), genmesh::invalid_input);
  }
  // A ratio outside [0, 1].
  {
    TypeParam g = mesh_of<TypeParam>(genmesh::make_icosphere(1));
    EXPECT_THROW(genmesh::simplify(g, {.target_ratio = 1.5}), genmesh::invalid_input);
  }
}

// The visitor (genmesh::Mutation_visitor) sees every collapse with its
// placement, the mesh's points are current in its hooks, and user data rides
// along: a per-vertex value equal to x, averaged at each (midpoint) collapse,
// still equals x at every vertex left — bit for bit.
template <class G>
struct Carry_x : genmesh::Mutation_visitor {
  std::vector<double> value; // by vertex index
  std::size_t started = 0, finished = 0, placements = 0, befores = 0, afters = 0, steps = 0;
  std::size_t first_done = 1, last_done = 0, last_total = 0;
  double pending = 0;
  static std::size_t index(genmesh::vertex_descriptor_t<G> v, const G& g) {
    return static_cast<std::size_t>(get(get(genmesh::vertex_index, g), v));
  }
  static Eigen::Vector3d point(genmesh::vertex_descriptor_t<G> v, const G& g) {
    return genmesh::to_eigen(genmesh::point_t<G>(get(get(genmesh::vertex_point, g), v)));
  }
  void on_started(const G&) { ++started; }
  void on_finished(const G&) { ++finished; }
  void on_step(std::string_view step, std::size_t done, std::size_t total) {
    EXPECT_EQ(step, "faces");
    if (steps++ == 0) first_done = done;
    EXPECT_LE(done, total);
    last_done = done;
    last_total = total;
  }
  void on_collapse_placement(genmesh::halfedge_descriptor_t<G> h, const Eigen::Vector3d& position, double cost,
                             const G& g) {
    ++placements;
    EXPECT_GE(cost, 0.0);
    const Eigen::Vector3d p = point(source(h, g), g), q = point(target(h, g), g);
    EXPECT_TRUE(position == 0.5 * (p + q)); // Edge_length: the midpoint of the current points
    pending = 0.5 * (value[index(source(h, g), g)] + value[index(target(h, g), g)]);
  }
  void before_collapse(genmesh::halfedge_descriptor_t<G>, const G&) { ++befores; }
  void on_collapse(genmesh::vertex_descriptor_t<G> v, const G& g) {
    ++afters;
    value[index(v, g)] = pending;
    EXPECT_EQ(pending, point(v, g).x()); // the survivor is at its new point already
  }
};

TYPED_TEST(Simplification, VisitorCarriesUserData) {
  TypeParam g = mesh_of<TypeParam>(genmesh::make_icosphere(3));
  Carry_x<TypeParam> vis;
  vis.value.resize(genmesh::index_bound(genmesh::vertex_index, g));
  for (auto v : vertices(g)) vis.value[vis.index(v, g)] = vis.point(v, g).x();
  const auto r = genmesh::simplify(g, genmesh::Simplification_options<genmesh::Edge_length>{.target_ratio = 0.1}, vis);
  EXPECT_GT(r.collapses, 500u);
  EXPECT_EQ(vis.started, 1u);
  EXPECT_EQ(vis.finished, 1u);
  EXPECT_EQ(vis.placements, r.collapses);
  EXPECT_EQ(vis.befores, r.collapses);
  EXPECT_EQ(vis.afters, r.collapses);
  EXPECT_EQ(vis.first_done, 0u);
  EXPECT_EQ(vis.last_done, vis.last_total);
  for (auto v : vertices(g)) EXPECT_EQ(vis.value[vis.index(v, g)], vis.point(v, g).x());
}

// The smallest angle of the faces left in the 25% of an icosphere: with
// .min_angle = 25 no collapse made a face worse than 25° (the input's
// smallest angle is about 50°), without it plane quadrics make slivers.
template <class G>
double smallest_angle(const G& g) {
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<G>;
  double m = 180;
  for (auto f : faces(g)) {
    auto h = halfedge(f, g);
    Eigen::Vector3d c[3];
    for (auto& x : c) {
      x = genmesh::to_eigen(P(get(pm, target(h, g))));
      h = next(h, g);
    }
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d u = c[(i + 1) % 3] - c[i], w = c[(i + 2) % 3] - c[i];
      m = std::min(m, std::atan2(u.cross(w).norm(), u.dot(w)) * 180 / std::numbers::pi);
    }
  }
  return m;
}

TYPED_TEST(Simplification, MinAngleAndMaxValence) {
  const Polygon_soup soup = genmesh::make_icosphere(4);
  TypeParam free_mesh = mesh_of<TypeParam>(soup);
  genmesh::simplify(free_mesh, {.target_ratio = 0.05});
  const double free_angle = smallest_angle(free_mesh);
  TypeParam g = mesh_of<TypeParam>(soup);
  const double input_angle = smallest_angle(g);
  ASSERT_GT(input_angle, 25.0);
  const auto r = genmesh::simplify(g, {.target_ratio = 0.05, .min_angle = 25.0});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces);
  EXPECT_GE(smallest_angle(g), 25.0);
  EXPECT_LT(free_angle, 25.0); // the constraint did something
  // .max_valence: no vertex of the result has more than 7 neighbours.
  auto max_degree = [](const auto& m) {
    std::size_t d = 0;
    for (auto v : vertices(m)) d = std::max<std::size_t>(d, degree(v, m));
    return d;
  };
  TypeParam h = mesh_of<TypeParam>(soup);
  genmesh::simplify(h, {.target_ratio = 0.05, .max_valence = 7});
  EXPECT_LE(max_degree(h), 7u);
  EXPECT_GT(max_degree(free_mesh), 7u);
  genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
  genmesh::simplify(ref, {.target_ratio = 0.05, .max_valence = 7});
  expect_same_soup(canonical_of(h), canonical_of(ref), "max_valence");
  // .max_aspect_ratio: no face of the result above 2 (the input's worst is
  // about 1.1); plane quadrics alone go above.
  auto worst_aspect = [](const auto& m) {
    return genmesh::triangle_quality(m).max_aspect_ratio;
  };
  ASSERT_LT(worst_aspect(mesh_of<TypeParam>(soup)), 2.0);
  TypeParam k = mesh_of<TypeParam>(soup);
  const auto rk = genmesh::simplify(k, {.target_ratio = 0.05, .max_aspect_ratio = 2.0});
  EXPECT_EQ(rk.stop_reason, genmesh::Stop_reason::target_faces);
  EXPECT_LE(worst_aspect(k), 2.0);
  EXPECT_GT(worst_aspect(free_mesh), 2.0);
}

// A flat 64 × 64 grid to 25 %: every plane quadric is 0, so every cost ties
// at exactly 0, and the shortest edge goes first (then the vertex-index
// pair). The grid is decimated evenly: a regular grid's 1-to-4 coarsening
// has valence 6 inside and 4 at the border, the run ends with at most 7
// (the bound 8 leaves one of slack); its smallest angle is the grid's
// diagonal against a coarser edge, atan(1/3) = 18.4°. Before the length
// order the pair alone collapsed edge after edge into one survivor:
// valence 114 and a smallest angle of 0.43°.
TYPED_TEST(Simplification, FlatGridDecimatedEvenly) {
  const Polygon_soup soup = genmesh::make_grid(64, 64);
  TypeParam g = mesh_of<TypeParam>(soup);
  const auto r = genmesh::simplify(g, {.target_ratio = 0.25});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces);
  std::size_t d = 0;
  for (auto v : vertices(g)) d = std::max<std::size_t>(d, degree(v, g));
  EXPECT_LE(d, 8u);
  EXPECT_GE(smallest_angle(g), 15.0);
  genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
  genmesh::simplify(ref, {.target_ratio = 0.25});
  expect_same_soup(canonical_of(g), canonical_of(ref), "flat grid");
}

// The same plane tilted (the probe's tilt:64: a 64 × 64 grid with a hole, y
// and z mixed, coordinates no longer exact): its costs are rounding noise of
// the float-stored quadrics, not 0, so the length order does not apply and
// the order is arbitrary; no collapse may make a sliver (a face whose height
// over its longest edge is below 1e-4 of it) out of a face that was not one.
// Before (session 20, the length order alone): smallest angle 0.000°,
// largest aspect ratio about 2e29.
TYPED_TEST(Simplification, TiltedFlatGridMakesNoSliver) {
  Polygon_soup soup = genmesh::make_grid_with_hole(64);
  for (auto& p : soup.points) p = Eigen::Vector3d(p.x(), p.y() * 0.6, p.y() * 0.8 + 0.3 * p.x());
  TypeParam g = mesh_of<TypeParam>(soup);
  const auto r = genmesh::simplify(g, {.target_ratio = 0.25});
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces);
  EXPECT_GE(smallest_angle(g), 0.1); // a sliver has a tiny angle (needle or cap)
  genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
  genmesh::simplify(ref, {.target_ratio = 0.25});
  expect_same_soup(canonical_of(g), canonical_of(ref), "tilted flat grid");
}

// Two concentric spheres 3% apart (the inner one facing inwards): coarse
// enough (1.5% of the faces; at 2% whether the unguarded run happens to cut
// through depends on the quadrics' rounding), either cuts through the other. .prevent_self_intersections (the
// default) refuses every collapse that would make them meet — the result is
// free of intersections (genmesh's exact test, and CGAL's on Surface_mesh) —
// while with it off the same run ends intersecting.
TYPED_TEST(Simplification, NoSelfIntersections) {
  Polygon_soup soup = genmesh::make_icosphere(3);
  const Polygon_soup inner = genmesh::make_icosphere(3);
  const auto n = static_cast<Polygon_soup::Index>(soup.points.size());
  for (const auto& p : inner.points) soup.add_point(0.97 * p);
  for (std::size_t f = 0; f < inner.num_faces(); ++f) {
    std::vector<Polygon_soup::Index> c(inner.face(f).begin(), inner.face(f).end());
    std::reverse(c.begin(), c.end());
    for (auto& i : c) i += n;
    soup.add_face(c);
  }
  TypeParam g = mesh_of<TypeParam>(soup);
  ASSERT_FALSE(genmesh::does_self_intersect(g));
  const auto r = genmesh::simplify(g, {.target_ratio = 0.015});
  EXPECT_FALSE(genmesh::does_self_intersect(g));
  EXPECT_LT(r.faces, soup.num_faces() / 4);
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
  if constexpr (std::is_same_v<TypeParam, genmesh_test::Surface_mesh>) {
    EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(g));
  }
  TypeParam unguarded = mesh_of<TypeParam>(soup);
  genmesh::simplify(unguarded, {.target_ratio = 0.015, .prevent_self_intersections = false});
  EXPECT_TRUE(genmesh::does_self_intersect(unguarded));
  genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
  genmesh::simplify(ref, {.target_ratio = 0.015});
  expect_same_soup(canonical_of(g), canonical_of(ref), "guarded");
  // The same with Schedule::passes (the guard is called per collapse alike).
  TypeParam gp = mesh_of<TypeParam>(soup);
  const auto rp = genmesh::simplify(gp, {.target_ratio = 0.015, .schedule = genmesh::Schedule::passes});
  EXPECT_FALSE(genmesh::does_self_intersect(gp));
  EXPECT_LT(rp.faces, soup.num_faces() / 4);
  genmesh_test::Halfedge_mesh refp = mesh_of<genmesh_test::Halfedge_mesh>(soup);
  genmesh::simplify(refp, {.target_ratio = 0.015, .schedule = genmesh::Schedule::passes});
  expect_same_soup(canonical_of(gp), canonical_of(refp), "guarded, passes");
}

// Guarded runs to `ratio`, on each schedule: the target reached, a valid
// mesh with the input's border loops that meets itself nowhere (genmesh's
// test, and CGAL's on Surface_mesh), the same as on Halfedge_mesh.
template <class G>
void expect_guarded_runs_embedded(const Polygon_soup& soup, double ratio) {
  const std::size_t loops = genmesh::check_mesh(mesh_of<G>(soup)).boundary_loops;
  for (const auto schedule : {genmesh::Schedule::queue, genmesh::Schedule::passes}) {
    const std::string what = schedule == genmesh::Schedule::queue ? "queue" : "passes";
    G g = mesh_of<G>(soup);
    const auto r = genmesh::simplify(g, {.target_ratio = ratio, .schedule = schedule});
    EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces) << what;
    const auto report = genmesh::check_mesh(g);
    EXPECT_TRUE(report.ok()) << what;
    EXPECT_EQ(report.boundary_loops, loops) << what;
    EXPECT_FALSE(genmesh::does_self_intersect(g)) << what;
    if constexpr (std::is_same_v<G, genmesh_test::Surface_mesh>) {
      EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(g)) << what;
    }
    genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
    genmesh::simplify(ref, {.target_ratio = ratio, .schedule = schedule});
    expect_same_soup(canonical_of(g), canonical_of(ref), what);
  }
}

// A torus flattened into a washer (z × 0.05) and twisted about the x axis
// (by x radians): its top and bottom sheets a hair apart, folding round
// tightly at the rims, where a collapse's new faces come close to faces two
// rings away, around its link — what the guard's ring certificate must not
// wave through (the certificate is verified by the exact test in this file,
// see the top). Unguarded, the run to 2% makes the sheets cut through each
// other; guarded, the result meets itself nowhere (genmesh's test, and
// CGAL's on Surface_mesh), the same on every backend and schedule.
TYPED_TEST(Simplification, TwistedWasherStaysApart) {
  Polygon_soup soup = genmesh::make_torus(128, 32, true);
  for (auto& p : soup.points) {
    p.z() *= 0.05;
    const double c = std::cos(p.x()), s = std::sin(p.x()), y = p.y(), z = p.z();
    p.y() = c * y - s * z;
    p.z() = s * y + c * z;
  }
  TypeParam g0 = mesh_of<TypeParam>(soup);
  ASSERT_FALSE(genmesh::does_self_intersect(g0));
  TypeParam unguarded = mesh_of<TypeParam>(soup);
  genmesh::simplify(unguarded, {.target_ratio = 0.02, .prevent_self_intersections = false});
  EXPECT_TRUE(genmesh::does_self_intersect(unguarded));
  expect_guarded_runs_embedded<TypeParam>(soup, 0.02);
}

// A bumpy annulus (the 32 × 32 grid with a hole, z = 0.05 sin 7x cos 5y):
// curved everywhere, so that no star is flat, with two border loops. The
// collapses next to either loop have link vertices on the border, or p or
// q, which the ring certificate decides with their border edges in the
// boundary of its faces (with p or q there, by showing that boundary a
// simple polygon, or seen once from a point other than the new one; also
// some off the border, where not every edge of it is seen from the new
// point) — each such certificate checked by the exact test (see the top):
// it must decide some of each kind, and the results must be embedded (as
// the washer's).
TYPED_TEST(Simplification, RingCertificateAtTheBorder) {
  namespace gs = genmesh::detail::simplification;
  Polygon_soup soup = genmesh::make_grid_with_hole(32);
  for (auto& p : soup.points) p.z() = 0.05 * std::sin(7 * p.x()) * std::cos(5 * p.y());
  const std::size_t before = gs::verified_border_certificates, stars = gs::verified_border_star_certificates,
                    outlines = gs::verified_outline_certificates,
                    recentred = gs::verified_recentred_certificates;
  expect_guarded_runs_embedded<TypeParam>(soup, 0.05);
  EXPECT_GT(gs::verified_border_certificates, before);
  EXPECT_GT(gs::verified_border_star_certificates, stars);
  EXPECT_GT(gs::verified_outline_certificates, outlines);
  EXPECT_GT(gs::verified_recentred_certificates, recentred);
}

// A flat annulus (the 32 × 32 grid with a hole, dyadic coordinates), in
// z = 0 and tilted into z = x/2 + y/4: every face coplanar with its
// neighbours exactly, where the guard's plane filter can decide nothing. In
// z = 0 the in-projection filter must decide almost every candidate (before
// it, each collapse ran ~100 exact coplanar tests: 170x the unguarded time;
// the tilted run makes slivers off the grid that only exact tests decide),
// and the guard must change nothing: a flat fan that passes the fold-over
// test cannot overlap anything, so guarded and unguarded runs agree, on
// every backend, without self-intersections.
TYPED_TEST(Simplification, FlatRegionsKeepTheGuardCheap) {
  for (const bool tilted : {false, true}) {
    Polygon_soup soup = genmesh::make_grid_with_hole(32);
    if (tilted)
      for (auto& p : soup.points) p.z() = 0.5 * p.x() + 0.25 * p.y();
    const std::string what = tilted ? "tilted" : "flat";
    TypeParam g = mesh_of<TypeParam>(soup);
    const auto r = genmesh::simplify(g, {.target_ratio = 0.25});
    ASSERT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces) << what;
    EXPECT_GT(r.collapses, 500u) << what;
    if (!tilted) {
      EXPECT_LE(r.exact_intersection_tests, r.collapses / 10) << what;
    }
    EXPECT_TRUE(genmesh::check_mesh(g).ok()) << what;
    EXPECT_FALSE(genmesh::does_self_intersect(g)) << what;
    TypeParam unguarded = mesh_of<TypeParam>(soup);
    const auto ru = genmesh::simplify(unguarded, {.target_ratio = 0.25, .prevent_self_intersections = false});
    EXPECT_EQ(ru.exact_intersection_tests, 0u) << what;
    expect_same_soup(canonical_of(g), canonical_of(unguarded), what + ": guarded vs unguarded");
    genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
    genmesh::simplify(ref, {.target_ratio = 0.25});
    expect_same_soup(canonical_of(g), canonical_of(ref), what + ": backend vs Halfedge_mesh");
  }
}

// A flat island in the hole of the flat annulus, in the same plane, a hair
// (2^-12) inside the hole's border: most collapses keep a flat star flat and
// unfolded with its border paths (what the guard accepts without
// searching), but a collapse that cuts a corner of the hole's border moves
// it towards the island, and only the search can say whether it touches.
// Down to 2% of the faces the result stays embedded, in one plane, and the
// same on every backend.
TYPED_TEST(Simplification, FlatIslandNextToTheBorderStaysApart) {
  Polygon_soup soup = genmesh::make_grid_with_hole(32); // hole [10/32, 22/32]^2
  const Polygon_soup island = genmesh::make_grid(4, 4);
  const auto n = static_cast<Polygon_soup::Index>(soup.points.size());
  const double lo = 10.0 / 32 + 1.0 / 4096, side = 12.0 / 32 - 2.0 / 4096;
  for (const auto& p : island.points) soup.add_point(lo + side * p.x(), lo + side * p.y(), 0.0);
  for (std::size_t f = 0; f < island.num_faces(); ++f) {
    std::vector<Polygon_soup::Index> c(island.face(f).begin(), island.face(f).end());
    for (auto& i : c) i += n;
    soup.add_face(c);
  }
  TypeParam g = mesh_of<TypeParam>(soup);
  ASSERT_FALSE(genmesh::does_self_intersect(g));
  const auto r = genmesh::simplify(g, {.target_ratio = 0.02});
  EXPECT_GT(r.collapses, 700u);
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
  EXPECT_FALSE(genmesh::does_self_intersect(g));
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<TypeParam>;
  for (const auto v : vertices(g)) EXPECT_EQ(genmesh::to_eigen(P(get(pm, v))).z(), 0.0);
  genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
  genmesh::simplify(ref, {.target_ratio = 0.02});
  expect_same_soup(canonical_of(g), canonical_of(ref), "island");
}

// The cube [-1,1]^3, each face an n × n grid of cells split in two triangles,
// outward: sharp features (12 lines, 8 corners) on a fine mesh.
Polygon_soup fine_cube(int n) {
  Polygon_soup s;
  std::map<std::tuple<int, int, int>, Polygon_soup::Index> index;
  auto vertex = [&](int i, int j, int k) {
    auto [it, fresh] = index.try_emplace({i, j, k}, static_cast<Polygon_soup::Index>(s.points.size()));
    if (fresh) s.add_point(Eigen::Vector3d(2.0 * i / n - 1, 2.0 * j / n - 1, 2.0 * k / n - 1));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= n; side += n)
      for (int u = 0; u < n; ++u)
        for (int w = 0; w < n; ++w) {
          auto at = [&](int du, int dw) {
            int c[3];
            c[axis] = side;
            c[(axis + 1) % 3] = u + du;
            c[(axis + 2) % 3] = w + dw;
            return vertex(c[0], c[1], c[2]);
          };
          Polygon_soup::Index q[4] = {at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
          // (axis+1, axis+2, axis) is right-handed: counter-clockwise seen from +axis.
          if (side == 0) std::swap(q[1], q[3]);
          s.add_face(std::vector<Polygon_soup::Index>{q[0], q[1], q[2]});
          s.add_face(std::vector<Polygon_soup::Index>{q[0], q[2], q[3]});
        }
  return s;
}

// On a cube's edge: at least two coordinates at ±1.
int coordinates_on_faces(const Eigen::Vector3d& p) {
  int n = 0;
  for (int i = 0; i < 3; ++i) n += std::abs(std::abs(p[i]) - 1.0) < 1e-12;
  return n;
}

// .feature_angle keeps a cube a cube on every policy: every vertex on the
// surface, the 8 corners in place, every sharp edge of the result on one of
// the 12 lines, and their total length the lines' (24): no line cut short,
// no vertex pulled off one.
TYPED_TEST(Simplification, FeatureLinesStayOnTheirLines) {
  const Polygon_soup soup = fine_cube(10);
  for (const Policy p : all_policies) {
    TypeParam g = mesh_of<TypeParam>(soup);
    const auto before = genmesh::check_mesh(g);
    const double ratio = 0.05;
    const auto r = run(g, p, ratio, genmesh::Border_mode::preserve, 60.0);
    const std::string what = name(p);
    expect_invariants(g, before, what);
    EXPECT_GT(r.collapses, soup.points.size() / 2) << what;
    auto pm = get(genmesh::vertex_point, g);
    using P = genmesh::point_t<TypeParam>;
    auto pt = [&](auto v) { return genmesh::to_eigen(P(get(pm, v))); };
    int corners = 0;
    for (auto v : vertices(g)) {
      const Eigen::Vector3d x = pt(v);
      EXPECT_NEAR(x.cwiseAbs().maxCoeff(), 1.0, 1e-12) << what << ": a vertex left the surface";
      corners += coordinates_on_faces(x) == 3;
    }
    EXPECT_EQ(corners, 8) << what;
    const auto sharp = genmesh::sharp_edges(g, 60.0);
    double length = 0;
    for (auto e : edges(g)) {
      if (!get(sharp, e)) continue;
      const Eigen::Vector3d a = pt(source(halfedge(e, g), g)), b = pt(target(halfedge(e, g), g));
      int shared = 0; // coordinates at the same ±1 on both ends
      for (int i = 0; i < 3; ++i) shared += std::abs(std::abs(a[i]) - 1.0) < 1e-12 && a[i] == b[i];
      EXPECT_EQ(shared, 2) << what << ": a sharp edge off the cube's lines";
      length += (b - a).norm();
    }
    EXPECT_NEAR(length, 24.0, 1e-9) << what;
    genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(soup);
    run(ref, p, ratio, genmesh::Border_mode::preserve, 60.0);
    expect_same_soup(canonical_of(g), canonical_of(ref), what);
  }
}

// .edge_is_constrained: a user line (the grid's middle row, y = 0.5) stays
// a line from x = 0 to x = 1, its vertices on it, under a free border.
TYPED_TEST(Simplification, ConstrainedEdgesStay) {
  const Polygon_soup soup = genmesh::make_grid(20, 20);
  TypeParam g = mesh_of<TypeParam>(soup);
  auto pm = get(genmesh::vertex_point, g);
  using P = genmesh::point_t<TypeParam>;
  auto pt = [&](auto v) { return genmesh::to_eigen(P(get(pm, v))); };
  std::set<std::size_t> line;
  for (auto e : edges(g)) {
    const auto h = halfedge(e, g);
    if (pt(source(h, g)).y() == 0.5 && pt(target(h, g)).y() == 0.5)
      line.insert(static_cast<std::size_t>(get(get(genmesh::edge_index, g), e)));
  }
  ASSERT_EQ(line.size(), 20u);
  const auto r = genmesh::simplify(g, {.target_ratio = 0.05,
                                       .edge_is_constrained = [&](std::size_t e) { return line.count(e) > 0; }});
  EXPECT_TRUE(genmesh::check_mesh(g).ok());
  EXPECT_LE(r.faces, 40u);
  double length = 0;
  for (auto e : edges(g)) {
    const auto h = halfedge(e, g);
    const Eigen::Vector3d a = pt(source(h, g)), b = pt(target(h, g));
    if (a.y() == 0.5 && b.y() == 0.5) length += (b - a).norm();
  }
  EXPECT_NEAR(length, 1.0, 1e-12);
}

// A per-vertex colour carried by linear interpolation along each collapsed
// edge (what a user does without attribute-aware quadrics).
template <class G>
struct Carry_colour : genmesh::Mutation_visitor {
  std::vector<double>* colour; // by vertex index
  double pending = 0;
  static std::size_t index(genmesh::vertex_descriptor_t<G> v, const G& g) {
    return static_cast<std::size_t>(get(get(genmesh::vertex_index, g), v));
  }
  static Eigen::Vector3d point(genmesh::vertex_descriptor_t<G> v, const G& g) {
    return genmesh::to_eigen(genmesh::point_t<G>(get(get(genmesh::vertex_point, g), v)));
  }
  void on_collapse_placement(genmesh::halfedge_descriptor_t<G> h, const Eigen::Vector3d& x, double, const G& g) {
    const Eigen::Vector3d a = point(source(h, g), g), b = point(target(h, g), g);
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    pending = (1 - t) * (*colour)[index(source(h, g), g)] + t * (*colour)[index(target(h, g), g)];
  }
  void on_collapse(genmesh::vertex_descriptor_t<G> v, const G& g) { (*colour)[index(v, g)] = pending; }
};

// The RMS difference between the colour of each input vertex and the colour
// the simplified flat mesh g (in z = 0) interpolates at its point (in the
// face that holds it: the one whose smallest barycentric coordinate is
// largest, clamped).
template <class G>
double colour_rms(const G& g, const std::vector<double>& colour, const Polygon_soup& in,
                  const std::vector<double>& colour_in) {
  struct Tri {
    Eigen::Vector2d p[3];
    double c[3];
  };
  std::vector<Tri> tris;
  for (auto f : faces(g)) {
    Tri t;
    auto h = halfedge(f, g);
    for (int i = 0; i < 3; ++i, h = next(h, g)) {
      t.p[i] = Carry_colour<G>::point(target(h, g), g).template head<2>();
      t.c[i] = colour[Carry_colour<G>::index(target(h, g), g)];
    }
    tris.push_back(t);
  }
  double sum = 0;
  for (std::size_t v = 0; v < in.points.size(); ++v) {
    const Eigen::Vector2d p(in.points[v][0], in.points[v][1]);
    double best = -std::numeric_limits<double>::infinity(), value = 0;
    for (const Tri& t : tris) {
      const Eigen::Vector2d e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0], d = p - t.p[0];
      const double det = e1.x() * e2.y() - e1.y() * e2.x();
      const double u = (d.x() * e2.y() - d.y() * e2.x()) / det, w = (e1.x() * d.y() - e1.y() * d.x()) / det;
      const double l[3] = {1 - u - w, u, w};
      const double m = std::min({l[0], l[1], l[2]});
      if (m > best) {
        best = m;
        double c[3], s = 0;
        for (int i = 0; i < 3; ++i) s += c[i] = std::max(l[i], 0.0);
        value = (c[0] * t.c[0] + c[1] * t.c[1] + c[2] * t.c[2]) / s;
      }
    }
    sum += (value - colour_in[v]) * (value - colour_in[v]);
  }
  return std::sqrt(sum / static_cast<double>(in.points.size()));
}

// Attribute-aware quadrics keep a colour seam: on a flat grid coloured 0
// below a slanted line and 1 above it, plane quadrics see no cost anywhere
// and smear the seam (colours carried by interpolation); Attribute_quadrics
// keeps vertices along it and gives the survivors their best colours. Same
// soup and colours on every backend.
TYPED_TEST(Simplification, AttributeQuadricsKeepAColourSeam) {
  const Polygon_soup in = genmesh::make_grid(24, 24);
  std::vector<double> colour_in(in.points.size());
  for (std::size_t v = 0; v < in.points.size(); ++v)
    colour_in[v] = in.points[v][1] > 0.3 + 0.35 * in.points[v][0] ? 1.0 : 0.0;
  // The colour as a property map over a vector by vertex index; Hoppe's
  // 1999 metric (Hoppe_quadrics) or Garland–Heckbert's 1998 one.
  auto with_attributes = [&]<class G>(G& g, std::vector<double>& colour, bool hoppe) {
    colour = colour_in;
    const auto map = boost::make_iterator_property_map(colour.begin(), get(genmesh::vertex_index, std::as_const(g)));
    if (hoppe)
      return genmesh::simplify(g, genmesh::Simplification_options<genmesh::Hoppe_quadrics<G>>{
                                      .target_ratio = 0.15, .policy = {.attributes = {genmesh::vertex_attribute(map, 0.2)}}});
    return genmesh::simplify(g, genmesh::Simplification_options<genmesh::Attribute_quadrics<G>>{
                                    .target_ratio = 0.15, .policy = {.attributes = {genmesh::vertex_attribute(map, 0.2)}}});
  };
  TypeParam h = mesh_of<TypeParam>(in);
  std::vector<double> carried = colour_in;
  Carry_colour<TypeParam> carry;
  carry.colour = &carried;
  genmesh::simplify(h, {.target_ratio = 0.15}, carry);
  const double blind = colour_rms(h, carried, in, colour_in);

  // Every backend: the same soup and the same colour at each point.
  auto coloured_points = [](const auto& m, const std::vector<double>& c) {
    std::vector<std::tuple<double, double, double, double>> v;
    for (auto x : vertices(m)) {
      const Eigen::Vector3d p = Carry_colour<std::remove_cvref_t<decltype(m)>>::point(x, m);
      v.emplace_back(p.x(), p.y(), p.z(), c[Carry_colour<std::remove_cvref_t<decltype(m)>>::index(x, m)]);
    }
    std::sort(v.begin(), v.end());
    return v;
  };
  for (const bool hoppe : {false, true}) {
    const char* label = hoppe ? "Hoppe quadrics" : "attribute quadrics";
    TypeParam g = mesh_of<TypeParam>(in);
    const auto before = genmesh::check_mesh(g);
    std::vector<double> colour;
    const auto r = with_attributes(g, colour, hoppe);
    expect_invariants(g, before, label);
    EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces) << label;
    const double ours = colour_rms(g, colour, in, colour_in);
    EXPECT_LT(ours, 0.6 * blind) << label << " " << ours << ", plane quadrics " << blind;

    genmesh_test::Halfedge_mesh ref = mesh_of<genmesh_test::Halfedge_mesh>(in);
    std::vector<double> ref_colour;
    with_attributes(ref, ref_colour, hoppe);
    expect_same_soup(canonical_of(g), canonical_of(ref), label);
    EXPECT_EQ(coloured_points(g, colour), coloured_points(ref, ref_colour)) << label;
  }
}

// Several attributes of different value types, each a vertex property map
// with its weight: a colour (Eigen::Vector3d) red above the equator of a
// sphere and blue below, texture coordinates (std::array<double, 2>) equal
// to (x, y), and a float equal to z; simplified to 10% with them
// (Attribute_quadrics) or without (Plane_quadrics).
struct Coloured_run {
  Polygon_soup soup;
  // Per survivor: point, colour, uv, height; sorted.
  std::vector<std::tuple<double, double, double, double, double, double, double, double, float>> values;
  std::size_t near_equator = 0; // survivors with |z| < 0.1
  double colour_error = 0;      // largest deviation from the pure colour at |z| > 0.15
  double uv_error = 0;          // largest |uv - (x, y)|, |height - z| at the survivors' new points
  double moved = 0;             // largest distance of a survivor from its input point
};

template <class G, class Policy = genmesh::Attribute_quadrics<G>>
Coloured_run simplify_coloured(const Polygon_soup& in, bool with_attributes) {
  using V = genmesh::vertex_descriptor_t<G>;
  G g = mesh_of<G>(in);
  const auto before = genmesh::check_mesh(g);
  auto colour = genmesh::scratch_property<Eigen::Vector3d>(genmesh::vertex_index, g, Eigen::Vector3d::Zero());
  auto uv = genmesh::scratch_property<std::array<double, 2>>(genmesh::vertex_index, g);
  auto height = genmesh::scratch_property<float>(genmesh::vertex_index, g, 0.0f);
  std::map<std::size_t, Eigen::Vector3d> input_point; // by vertex index
  for (const V v : vertices(g)) {
    const Eigen::Vector3d p = Carry_colour<G>::point(v, g);
    input_point[Carry_colour<G>::index(v, g)] = p;
    colour[v] = p.z() > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
    uv[v] = {p.x(), p.y()};
    height[v] = static_cast<float>(p.z());
  }
  genmesh::Simplification_result r;
  if (with_attributes) {
    r = genmesh::simplify(g, genmesh::Simplification_options<Policy>{
                                 .target_ratio = 0.1,
                                 .policy = {.attributes = {genmesh::vertex_attribute(colour, 0.2, "colour"),
                                                           genmesh::vertex_attribute(uv, 0.5, "uv"),
                                                           genmesh::vertex_attribute(height, 0.5, "height")}}});
  } else {
    r = genmesh::simplify(g, {.target_ratio = 0.1});
  }
  EXPECT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces);
  expect_invariants(g, before, "attribute quadrics, several maps");
  Coloured_run out;
  out.soup = canonical_of(g);
  for (const V v : vertices(g)) {
    const Eigen::Vector3d p = Carry_colour<G>::point(v, g);
    const Eigen::Vector3d c = colour[v];
    if (std::abs(p.z()) < 0.1) ++out.near_equator;
    if (std::abs(p.z()) > 0.15) {
      const Eigen::Vector3d pure = p.z() > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
      out.colour_error = std::max(out.colour_error, (c - pure).cwiseAbs().maxCoeff());
    }
    const Eigen::Vector2d t(uv[v][0], uv[v][1]);
    out.uv_error = std::max({out.uv_error, (t - p.head<2>()).norm(), std::abs(static_cast<double>(height[v]) - p.z())});
    out.moved = std::max(out.moved, (input_point[Carry_colour<G>::index(v, g)] - p).norm());
    out.values.emplace_back(p.x(), p.y(), p.z(), c.x(), c.y(), c.z(), uv[v][0], uv[v][1], height[v]);
  }
  std::sort(out.values.begin(), out.values.end());
  return out;
}

// The colour seam keeps its vertices (more survivors near the equator than
// plane quadrics leave there), vertices away from it keep pure colours, and
// the survivors' written texture coordinates and heights fit their new
// points far better than their input values would (the maps were written).
// The same soup and the same values on every backend.
TYPED_TEST(Simplification, AttributeQuadricsOverSeveralPropertyMaps) {
  const Polygon_soup in = genmesh::make_icosphere(4);
  const Coloured_run ours = simplify_coloured<TypeParam>(in, true);
  const Coloured_run blind = simplify_coloured<TypeParam>(in, false);
  std::printf("near the equator: %zu with attributes, %zu without; colour error %.3g; uv error %.3g (survivors "
              "moved up to %.3g)\n",
              ours.near_equator, blind.near_equator, ours.colour_error, ours.uv_error, ours.moved);
  EXPECT_GT(ours.near_equator, 2 * blind.near_equator);
  EXPECT_LT(ours.colour_error, 0.05);
  EXPECT_LT(ours.uv_error, 0.25 * ours.moved);

  const Coloured_run ref = simplify_coloured<genmesh_test::Halfedge_mesh>(in, true);
  expect_same_soup(ours.soup, ref.soup, "attribute quadrics, several maps");
  EXPECT_EQ(ours.values, ref.values);

  // The inline-storage quadrics (3 + 6 values fit in 9) give the same bits.
  const Coloured_run inline_storage = simplify_coloured<TypeParam, genmesh::Attribute_quadrics<TypeParam, 9>>(in, true);
  expect_same_soup(inline_storage.soup, ours.soup, "attribute quadrics, inline storage");
  EXPECT_EQ(inline_storage.values, ours.values);

  // Hoppe's 1999 metric: the same properties, the same results on every
  // backend and with inline storage (6 values).
  const Coloured_run hoppe = simplify_coloured<TypeParam, genmesh::Hoppe_quadrics<TypeParam>>(in, true);
  std::printf("Hoppe: near the equator %zu; colour error %.3g; uv error %.3g (moved up to %.3g)\n",
              hoppe.near_equator, hoppe.colour_error, hoppe.uv_error, hoppe.moved);
  EXPECT_GT(hoppe.near_equator, 2 * blind.near_equator);
  EXPECT_LT(hoppe.colour_error, 0.05);
  EXPECT_LT(hoppe.uv_error, 0.25 * hoppe.moved);
  const Coloured_run hoppe_ref =
      simplify_coloured<genmesh_test::Halfedge_mesh, genmesh::Hoppe_quadrics<genmesh_test::Halfedge_mesh>>(in, true);
  expect_same_soup(hoppe.soup, hoppe_ref.soup, "Hoppe quadrics, several maps");
  EXPECT_EQ(hoppe.values, hoppe_ref.values);
  const Coloured_run hoppe_inline = simplify_coloured<TypeParam, genmesh::Hoppe_quadrics<TypeParam, 6>>(in, true);
  expect_same_soup(hoppe_inline.soup, hoppe.soup, "Hoppe quadrics, inline storage");
  EXPECT_EQ(hoppe_inline.values, hoppe.values);
  // A bound the attributes do not fit is refused before any change.
  TypeParam g = mesh_of<TypeParam>(in);
  auto uv = genmesh::scratch_property<std::array<double, 2>>(genmesh::vertex_index, g);
  const auto faces = num_faces(g);
  try {
    genmesh::simplify(g, genmesh::Simplification_options<genmesh::Attribute_quadrics<TypeParam, 4>>{
                             .target_ratio = 0.1, .policy = {.attributes = {genmesh::vertex_attribute(uv, 1.0, "uv")}}});
    ADD_FAILURE() << "2 values accepted by Attribute_quadrics<G, 4>";
  } catch (const genmesh::invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("holds at most 1"), std::string::npos) << e.what();
  }
  try {
    genmesh::simplify(g, genmesh::Simplification_options<genmesh::Hoppe_quadrics<TypeParam, 1>>{
                             .target_ratio = 0.1, .policy = {.attributes = {genmesh::vertex_attribute(uv, 1.0, "uv")}}});
    ADD_FAILURE() << "2 values accepted by Hoppe_quadrics<G, 1>";
  } catch (const genmesh::invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("Hoppe_quadrics<G, 1> holds at most 1"), std::string::npos) << e.what();
  }
  EXPECT_EQ(num_faces(g), faces);
}

// Hoppe's face quadric is what the paper defines: at any point x and values
// s, the squared distance of x to the face's plane plus, per value, the
// squared difference between s and the face's linear interpolation of its
// corners' values at x's projection (area-weighted: times the area); zero
// at the corners with their own values; its best values at a point are that
// interpolation.
TEST(HoppeQuadric, MeasuresPlaneDistanceAndInterpolationError) {
  using G = genmesh_test::Halfedge_mesh;
  const std::array<Eigen::Vector3d, 3> p{Eigen::Vector3d(0.2, 0.1, 0.3), Eigen::Vector3d(1.7, 0.4, -0.2),
                                         Eigen::Vector3d(0.5, 1.3, 0.6)};
  Polygon_soup tri;
  for (const auto& x : p) tri.add_point(x);
  tri.add_face({0, 1, 2});
  G g = mesh_of<G>(tri);
  std::vector<std::array<double, 2>> uv{{{0.1, 5.0}}, {{0.9, 4.0}}, {{0.3, 7.5}}};
  const auto map = boost::make_iterator_property_map(uv.begin(), get(genmesh::vertex_index, std::as_const(g)));
  for (const bool area : {false, true}) {
    genmesh::Hoppe_quadrics<G> policy{.attributes = {genmesh::vertex_attribute(map, 2.0, "uv")}, .area_weighted = area};
    policy.start(g);
    const auto q = policy.face(0, p[0], 1, p[1], 2, p[2]);
    const Eigen::Vector3d n2 = (p[1] - p[0]).cross(p[2] - p[0]);
    const Eigen::Vector3d n = n2.normalized();
    const double w = area ? 0.5 * n2.norm() : 1.0;
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(q(p[i], Eigen::Vector2d(2.0 * uv[i][0], 2.0 * uv[i][1])), 0.0, 1e-12) << "corner " << i;
    const Eigen::Vector3d x(0.9, 0.2, 1.4);
    // x's projection in barycentric coordinates, then the interpolation.
    const Eigen::Vector3d y = x - n.dot(x - p[0]) * n;
    const double total = n2.norm();
    const double l1 = n.dot((p[2] - y).cross(p[0] - y)) / total, l2 = n.dot((p[0] - y).cross(p[1] - y)) / total;
    const double l0 = 1 - l1 - l2;
    Eigen::Vector2d interp;
    for (int j = 0; j < 2; ++j) interp[j] = 2.0 * (l0 * uv[0][j] + l1 * uv[1][j] + l2 * uv[2][j]);
    const Eigen::Vector2d s(3.0, 9.0);
    const double plane = n.dot(x - p[0]);
    EXPECT_NEAR(q(x, s), w * (plane * plane + (s - interp).squaredNorm()), 1e-9);
    const Eigen::Vector2d best = q.best_values(x);
    EXPECT_NEAR((best - interp).norm(), 0.0, 1e-9);
  }
}

// ---------------------------------------------------------------------------
// CGAL's edge_collapse with Garland–Heckbert plane policies as the oracle.
// ---------------------------------------------------------------------------

// Stops CGAL's edge_collapse at a face count (CGAL 5.5 counts edges only).
struct Face_count_stop {
  const genmesh_test::Surface_mesh* mesh;
  std::size_t target;
  template <class FT, class Profile>
  bool operator()(const FT&, const Profile&, std::size_t, std::size_t) const {
    return mesh->number_of_faces() <= target;
  }
};

// genmesh's seeded measure (tested against CGAL's in test_geometry): CGAL's
// approximate_symmetric_Hausdorff_distance drew different face samples from
// run to run despite random_seed, which made these comparisons flaky.
double hausdorff(const genmesh_test::Surface_mesh& a, const genmesh_test::Surface_mesh& b) {
  genmesh::Hausdorff_options o;
  o.samples = 40000;
  o.seed = 7;
  return genmesh::hausdorff_distance(a, b, o).hausdorff;
}

// Runs CGAL's edge_collapse (with the cost and placement `cgal_policies`
// gives for a mesh) and genmesh's simplify (`ours`) to the same face count on
// three real meshes at 10% and 2% of the faces, and compares their symmetric
// Hausdorff distances to the input: genmesh's at most `margin10` / `margin2`
// times CGAL's.
template <class CgalPolicies, class Ours>
void expect_no_worse_than_cgal(const char* label, const CgalPolicies& cgal_policies, const Ours& ours_run,
                               double margin10, double margin2) {
  using SM = genmesh_test::Surface_mesh;
  for (const char* file : {"elephant.off", "mech-holes-shark.off", "armadillo.off"}) {
    const Polygon_soup soup = genmesh::read_soup(genmesh_test::real_mesh(file));
    const SM input = mesh_of<SM>(soup);
    for (const double ratio : {0.1, 0.02}) {
      const auto target = static_cast<std::size_t>(std::ceil(ratio * static_cast<double>(soup.num_faces())));
      SM cgal = input;
      const Face_count_stop stop{&cgal, target};
      cgal_policies(cgal, stop);
      SM ours = input;
      const genmesh::Simplification_result r = ours_run(ours, target);
      ASSERT_EQ(r.stop_reason, genmesh::Stop_reason::target_faces) << file;
      SM ours_compact = ours;
      ours_compact.collect_garbage();
      cgal.collect_garbage();
      const double d_ours = hausdorff(input, ours_compact), d_cgal = hausdorff(input, cgal);
      std::printf("%s %s ratio %.2f: faces genmesh %zu CGAL %zu; Hausdorff genmesh %.6g CGAL %.6g (%.3f)\n", label,
                  file, ratio, r.faces, static_cast<std::size_t>(cgal.number_of_faces()), d_ours, d_cgal,
                  d_ours / d_cgal);
      EXPECT_LE(r.faces, static_cast<std::size_t>(cgal.number_of_faces()) + 1) << file;
      EXPECT_LE(d_ours, (ratio < 0.05 ? margin2 : margin10) * d_cgal) << file << " ratio " << ratio;
    }
  }
}

// CGAL's edge_collapse with its Garland–Heckbert plane policies.
void cgal_garland_heckbert(genmesh_test::Surface_mesh& m, const Face_count_stop& stop) {
  namespace SMS = CGAL::Surface_mesh_simplification;
  SMS::GarlandHeckbert_plane_policies<genmesh_test::Surface_mesh, genmesh_test::Kernel> gh(m);
  SMS::edge_collapse(m, stop, CGAL::parameters::get_cost(gh.get_cost()).get_placement(gh.get_placement()));
}

// simplify shifts two vertices' stored quadrics side by side
// (Relative_quadric::absolute_sum, add_to_two, add_to_one: SSE2 lanes where
// available);
// the meshes stay the same only if every term equals the one-at-a-time form
// bit for bit. Random planes and origins at several scales.
TEST(SimplificationQuadric, PairsEqualTheScalarFormsBitForBit) {
  using genmesh::Quadric;
  using genmesh::Relative_quadric;
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto unit = [&] {
    Eigen::Vector3d n(u(rng), u(rng), u(rng));
    return Eigen::Vector3d(n / std::max(n.norm(), 1e-3));
  };
  auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::array<double, 4>{1e-3, 1.0, 1e2, 1e5}[i % 4];
    const Eigen::Vector3d op(scale * u(rng), scale * u(rng), u(rng)), oq(u(rng), scale * u(rng), scale * u(rng));
    Quadric qp = Quadric::plane(unit(), scale * u(rng), 1.0 + i % 3);
    qp += Quadric::plane(unit(), u(rng));
    const Quadric qq = Quadric::plane(unit(), scale * u(rng), 0.25);
    const Relative_quadric p = Relative_quadric::of(qp, op), q = Relative_quadric::of(qq, oq);
    const Quadric sum = Relative_quadric::absolute_sum(p, op, q, oq);
    const Quadric expected = p.absolute(op) + q.absolute(oq);
    ASSERT_TRUE(same(sum, expected)) << "absolute_sum, case " << i;
    const Quadric d = Quadric::plane(unit(), u(rng), 0.5 + i % 2);
    Relative_quadric p2 = p, q2 = q;
    Relative_quadric::add_to_two(p2, op, q2, oq, d);
    ASSERT_TRUE(same(p2, Relative_quadric::of(p.absolute(op) + d, op))) << "add_to_two p, case " << i;
    ASSERT_TRUE(same(q2, Relative_quadric::of(q.absolute(oq) + d, oq))) << "add_to_two q, case " << i;
    Relative_quadric p3 = p;
    Relative_quadric::add_to_one(p3, op, d);
    ASSERT_TRUE(same(p3, p2)) << "add_to_one, case " << i;
  }
}

#if defined(__SSE2__)
// simplify evaluates edges two at a time (Relative_quadric::absolute_lanes,
// Quadric_lanes, Plane_quadrics::place_costs); each lane's cost must equal
// place()'s bit for bit where place_costs takes it. Random sums of planes,
// some nearly parallel (ill conditioned: the fallback, left to place()),
// edges at several scales and lengths (some minimizers beyond the distance
// limit).
TEST(SimplificationQuadric, LaneCostsEqualPlaceBitForBit) {
  using genmesh::Quadric;
  using genmesh::Relative_quadric;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto unit = [&](const Eigen::Vector3d& near, double spread) {
    Eigen::Vector3d n = near + spread * Eigen::Vector3d(u(rng), u(rng), u(rng));
    return Eigen::Vector3d(n / std::max(n.norm(), 1e-3));
  };
  const genmesh::Plane_quadrics policy;
  std::size_t taken = 0, left = 0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::array<double, 4>{1e-3, 1.0, 1e2, 1e5}[i % 4];
    const double spread = std::array<double, 3>{1.0, 1e-2, 1e-5}[i % 3];
    Relative_quadric r[4];
    Eigen::Vector3d o[4];
    for (int j = 0; j < 4; ++j) {
      o[j] = scale * Eigen::Vector3d(u(rng), u(rng), u(rng));
      const Eigen::Vector3d n0 = unit(Eigen::Vector3d::Zero(), 1.0);
      Quadric q;
      for (int k = 0; k < 2 + j % 3; ++k) {
        const Eigen::Vector3d n = unit(n0, spread);
        q += Quadric::plane(n, -n.dot(o[j]) + scale * 1e-2 * u(rng), 1.0 + k % 2);
      }
      r[j] = Relative_quadric::of(q, o[j]);
    }
    // Edges (0, 1) and (2, 3).
    const genmesh::Quadric_lanes s =
        Relative_quadric::absolute_lanes(r[0], o[0], r[2], o[2]) + Relative_quadric::absolute_lanes(r[1], o[1], r[3], o[3]);
    double cost[2];
    const int done = policy.place_costs(s, o[0], o[1], o[2], o[3], cost);
    for (int j = 0; j < 2; ++j) {
      // Each lane's sum is absolute_sum's (simplify hands a lane left to place() its sum).
      const Quadric sum = Relative_quadric::absolute_sum(r[2 * j], o[2 * j], r[2 * j + 1], o[2 * j + 1]);
      const Quadric lane = s.lane(j);
      ASSERT_EQ(std::memcmp(&lane, &sum, sizeof(Quadric)), 0) << "case " << i << " lane " << j;
      if (!(done >> j & 1)) {
        ++left;
        continue;
      }
      ++taken;
      const genmesh::Placement expected = policy.place(sum, o[2 * j], o[2 * j + 1]);
      ASSERT_EQ(std::memcmp(&cost[j], &expected.cost, sizeof(double)), 0) << "case " << i << " lane " << j;
    }
  }
  EXPECT_GT(taken, 1000u);
  EXPECT_GT(left, 1000u);
}
#endif

// The guard's quick 2D orientation (a sign, or `unsure`) never gives a
// wrong sign, down to the subnormals: collinear lattices nudged by an ulp
// or not, and nearly collinear points, scaled by 2^k across the whole range,
// against the exact orient2d. Before session 15 its filter had no underflow
// term and it took an fma residual that rounded to zero for an exact
// product: 2377 of these 16600 wrong.
TEST(SimplificationGuard, SureOrientationNeverWrong) {
  using genmesh::detail::simplification::sure_orient2d;
  using genmesh::detail::simplification::unsure;
  using P = std::array<double, 2>;
  // 2^-540 · 2^-540 rounds to zero, and so does the fma residual.
  EXPECT_EQ(sure_orient2d({0, 0}, {0x1p-540, 0}, {0, 0x1p-540}), unsure);
  EXPECT_EQ(genmesh::detail::pred::orient2d(0, 0, 0x1p-540, 0, 0, 0x1p-540), 1);
  EXPECT_EQ(sure_orient2d({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(sure_orient2d({0, 0}, {2, 2}, {1, 1}), 0); // a grid's collinear corners
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> small(-8, 8), coin(0, 3);
  std::uniform_real_distribution<double> unit(-1, 1), t01(0, 1);
  std::size_t wrong = 0, sure = 0, n = 0;
  for (int k = -1074; k <= 1000; ++k)
    for (int r = 0; r < 8; ++r) {
      std::array<double, 6> q;
      if (r % 2) {
        const double ox = small(rng), oy = small(rng), ux = small(rng), uy = small(rng);
        for (int i = 0; i < 3; ++i) {
          const double s = small(rng);
          q[2 * i] = ox + s * ux;
          q[2 * i + 1] = oy + s * uy;
        }
        if (coin(rng) < 2) q[4] = std::nextafter(q[4], coin(rng) ? INFINITY : -INFINITY);
      } else {
        for (int i = 0; i < 4; ++i) q[i] = unit(rng);
        const double t = t01(rng);
        q[4] = q[0] + t * (q[2] - q[0]);
        q[5] = q[1] + t * (q[3] - q[1]);
      }
      for (double& x : q) x = std::ldexp(x, k);
      const P a{q[0], q[1]}, b{q[2], q[3]}, c{q[4], q[5]};
      const int s = sure_orient2d(a, b, c);
      ++n;
      if (s == unsure) continue;
      ++sure;
      if (s != genmesh::detail::pred::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]) && ++wrong <= 5)
        ADD_FAILURE() << "k = " << k << ": " << a[0] << ' ' << a[1] << " | " << b[0] << ' ' << b[1] << " | " << c[0]
                      << ' ' << c[1];
    }
  EXPECT_EQ(wrong, 0u) << "of " << n;
  EXPECT_GT(sure, n / 10);
}

// The ring certificate's simple-polygon test on hand-made polygons, each
// also reversed and from every starting corner (the answer depends on
// neither): simple ones (a square, an L, corners straight between their
// neighbours, a corner an ulp off an edge's line and off its end), and every
// way of not being simple the certificate must catch: crossing edges, a
// corner on a non-adjacent edge, an edge folding back onto its neighbour
// (also upright), two loops through one point, two corners at one point
// (adjacent or not), three corners on a line, overlapping collinear edges,
// a corner an ulp across an edge, fewer than three corners.
TEST(SimplificationGuard, SimplePolygonTest) {
  using genmesh::detail::simplification::is_simple_polygon;
  using P = std::array<double, 2>;
  auto check = [](std::vector<P> q, bool simple, const char* what) {
    for (int dir = 0; dir < 2; ++dir) {
      for (std::size_t s = 0; s < q.size(); ++s) {
        std::vector<P> r(q.begin() + static_cast<std::ptrdiff_t>(s), q.end());
        r.insert(r.end(), q.begin(), q.begin() + static_cast<std::ptrdiff_t>(s));
        EXPECT_EQ(is_simple_polygon(r), simple) << what << ", from corner " << s << (dir ? ", reversed" : "");
      }
      std::reverse(q.begin(), q.end());
    }
  };
  const double above = std::nextafter(1.0, 2.0), below = std::nextafter(1.0, 0.0);
  check({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, true, "square");
  check({{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}}, true, "L");
  check({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}, true, "a corner straight between its neighbours");
  check({{0, 0}, {1, 0}, {3, 0}, {1, 1}}, true, "two corners straight between their neighbours");
  check({{0, 0}, {3, 1}, {6, 2}, {6, 6}, {3, above}, {0, 6}}, true, "a corner an ulp above a corner and an edge");
  check({{0, 0}, {1, 0}, {0, 1}, {1, 1}}, false, "bow tie");
  check({{0, 0}, {4, 0}, {4, 4}, {2, 4}, {1, 0}, {0, 4}}, false, "a corner on a non-adjacent edge");
  check({{0, 0}, {3, 1}, {6, 2}, {6, 6}, {3, below}, {0, 6}}, false, "a corner an ulp across an edge");
  check({{0, 0}, {2, 0}, {1, 0}, {1, 1}}, false, "an edge folding back");
  check({{0, 0}, {2, 0}, {2, 1}, {2, -1}, {3, 3}}, false, "an edge folding back, upright");
  check({{0, 0}, {1, 1}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}, false, "two loops through one point");
  check({{0, 0}, {1, 0}, {1, 0}, {1, 1}}, false, "adjacent corners at one point");
  check({{0, 0}, {1, 0}, {1, 1}, {0, 0}}, false, "the first corner again last");
  check({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {-1, 0}, {-1, -1}}, false, "non-adjacent corners at one point");
  check({{0, 0}, {1, 1}, {2, 2}}, false, "three corners on a line");
  check({{0, 0}, {3, 0}, {3, 1}, {2, 0}, {1, 0}, {0, 1}}, false, "non-adjacent edges overlapping on a line");
  check({{0, 0}, {1, 0}}, false, "two corners");
}

// Symmetric Hausdorff distance to the input at the same face count, at 10%
// of the faces: within 10% of CGAL's or better (the distance is estimated
// from 40000 random samples per side: the estimate of CGAL's own armadillo
// result moved by 7% between two builds of this test, and the
// self-intersection guard moved genmesh's by 8%, to 1.06x CGAL's). At 2%
// (100-1000 faces left) one collapse decides the maximum and both
// algorithms swing by ±30% with their parameters (measured: CGAL's is not
// better on all three meshes either), so the margin there is 40%: the test
// still fails on a real loss (a border or a limb torn off).
TEST(SimplificationOracle, HausdorffNoWorseThanCgalGarlandHeckbert) {
  namespace SMS = CGAL::Surface_mesh_simplification;
  using SM = genmesh_test::Surface_mesh;
  expect_no_worse_than_cgal(
      "GH", cgal_garland_heckbert,
      [](SM& m, std::size_t target) { return genmesh::simplify(m, {.target_faces = target}); }, 1.1, 1.4);
}

// Schedule::passes against CGAL's GH, with the same margins as the queue.
TEST(SimplificationOracle, PassesHausdorffNoWorseThanCgalGarlandHeckbert) {
  namespace SMS = CGAL::Surface_mesh_simplification;
  using SM = genmesh_test::Surface_mesh;
  expect_no_worse_than_cgal(
      "GH passes", cgal_garland_heckbert,
      [](SM& m, std::size_t target) {
        return genmesh::simplify(m, {.target_faces = target, .schedule = genmesh::Schedule::passes});
      },
      1.1, 1.4);
}

// The same against CGAL's default, Lindstrom–Turk, with genmesh's
// Lindstrom_turk (same weights, flips-only fold test as CGAL). On the
// elephant and the shark at 10% both give the same Hausdorff distance to the
// last digit (measured); on the armadillo the two runs part at some near-tie
// and genmesh's lands at 1.38x CGAL's at 10% (0.98x at 5%, 0.82x at 2%): LT
// places vertices off the surface (it preserves volume, not distance), so
// which collapse happens first decides the maximum. Margin 40% at both
// ratios: it still fails on a real loss (a limb or a border torn off).
TEST(SimplificationOracle, HausdorffNoWorseThanCgalLindstromTurk) {
  namespace SMS = CGAL::Surface_mesh_simplification;
  using SM = genmesh_test::Surface_mesh;
  expect_no_worse_than_cgal(
      "LT",
      [](SM& m, const Face_count_stop& stop) {
        SMS::edge_collapse(m, stop,
                           CGAL::parameters::get_cost(SMS::LindstromTurk_cost<SM>())
                               .get_placement(SMS::LindstromTurk_placement<SM>()));
      },
      [](SM& m, std::size_t target) {
        return genmesh::simplify(m, genmesh::Simplification_options<genmesh::Lindstrom_turk>{.target_faces = target});
      },
      1.4, 1.4);
}

} // namespace

// The FaceGrid tests' random numbers: xorshift64, the same sequence on
// every platform (std's distributions are not).
namespace {
struct Xorshift64 {
  std::uint64_t state;
  std::uint64_t operator()() {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
  }
};

// Two grid entries equal in every field (face, flags, bins).
bool same_entry(const genmesh::detail::simplification::Grid_entry& a,
                const genmesh::detail::simplification::Grid_entry& b) {
  return a.face == b.face && a.flags == b.flags && a.x == b.x && a.y == b.y && a.z == b.z;
}
} // namespace

// The grid's walk over a cell: the SSE2 path (four entries at a time) and
// the scalar reference pick the same entries, and an entry is picked iff,
// on every axis, its bins meet the query's and its range or the query's
// starts in the cell.
TEST(FaceGrid, VectorWalkEqualsScalarWalk) {
  namespace ds = genmesh::detail::simplification;
  Xorshift64 next{0x2545F4914F6CDD1Dull};
  auto bins = [&next] {
    const auto a = static_cast<std::uint8_t>(next() & 15), b = static_cast<std::uint8_t>(next() & 15);
    return static_cast<std::uint8_t>(std::min(a, b) << 4 | std::max(a, b));
  };
  auto meet = [](std::uint8_t a, std::uint8_t b) { return (a >> 4) <= (b & 15) && (b >> 4) <= (a & 15); };
  std::vector<ds::Grid_entry> entries(64), scalar(64), vector(64);
  for (int round = 0; round < 2000; ++round) {
    const std::size_t n = static_cast<std::size_t>(round % 41);
    for (std::size_t i = 0; i < n; ++i)
      entries[i] = {static_cast<std::uint32_t>(next()), static_cast<std::uint8_t>(next()), bins(), bins(), bins()};
    const std::uint8_t qf = static_cast<std::uint8_t>(next() & 7), qx = bins(), qy = bins(), qz = bins();
    const std::uint32_t qw = qx | qy << 8 | qz << 16;
    const ds::Grid_probe probe{static_cast<std::uint32_t>(7 & ~qf), (qw & 0x0f0f0fu) | 0x101010u,
                               (qw >> 4) & 0x0f0f0fu};
    const std::size_t k = ds::grid_select_scalar(entries.data(), n, probe, scalar.data());
    std::size_t expected = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& e = entries[i];
      const bool picked = ((e.flags | qf) & 7) == 7 && meet(e.x, qx) && meet(e.y, qy) && meet(e.z, qz);
      ASSERT_EQ(picked, ds::grid_meets(e, probe));
      if (picked) {
        ASSERT_EQ(scalar[expected++].face, e.face);
      }
    }
    ASSERT_EQ(k, expected);
#if defined(__SSE2__)
    ASSERT_EQ(ds::grid_select_sse2(entries.data(), n, probe, vector.data()), k);
    for (std::size_t i = 0; i < k; ++i) ASSERT_TRUE(same_entry(vector[i], scalar[i])) << "entry " << i;
#endif
#if defined(GENMESH_GRID_SELECT_AVX512)
    if (ds::grid_select_has_avx512()) {
      std::fill(vector.begin(), vector.end(), ds::Grid_entry{});
      ASSERT_EQ(ds::grid_select_avx512(entries.data(), n, probe, vector.data()), k);
      for (std::size_t i = 0; i < k; ++i) ASSERT_TRUE(same_entry(vector[i], scalar[i])) << "entry " << i;
      // Nothing written past the entries picked.
      for (std::size_t i = k; i < vector.size(); ++i) ASSERT_EQ(vector[i].face, 0u);
    }
#endif
  }
}

// grid_drop_stale_avx512 (Face_grid::drop_stale eight entries at a time,
// the versions gathered) keeps, in order, exactly the entries whose
// version is their face's (its hidden bit ignored): at random, for every
// count, the versions read from an array with the seven bytes of padding
// Face_grid keeps.
TEST(FaceGrid, VectorDropKeepsTheLiveEntries) {
#if defined(GENMESH_GRID_SELECT_AVX512)
  namespace ds = genmesh::detail::simplification;
  if (!ds::grid_select_has_avx512()) GTEST_SKIP() << "no AVX-512";
  Xorshift64 next{0x9E3779B97F4A7C15ull};
  const std::size_t faces = 37;
  std::vector<std::uint8_t> version(faces + 7, 0xff);
  std::vector<ds::Grid_entry> entries(64), expected(64);
  for (int round = 0; round < 2000; ++round) {
    for (std::size_t f = 0; f < faces; ++f) {
      const std::uint64_t r = next();
      // Mostly 0-3 (entries match often); hidden (0x40) or gone (0x80) at times.
      version[f] = static_cast<std::uint8_t>((r & 3) | ((r >> 8) % 5 == 0 ? 0x40 : 0) | ((r >> 16) % 11 == 0 ? 0x80 : 0));
    }
    const std::size_t n = static_cast<std::size_t>(round % 61);
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t r = next();
      const auto face = static_cast<std::uint32_t>(r % faces);
      const auto flags = static_cast<std::uint8_t>(((r >> 8) & 3) << 3 | ((r >> 12) & 7));
      entries[i] = {face, flags, static_cast<std::uint8_t>(r >> 16), static_cast<std::uint8_t>(r >> 24),
                    static_cast<std::uint8_t>(r >> 32)};
      if ((version[face] & ~0x40) == flags >> 3) expected[k++] = entries[i];
    }
    ASSERT_EQ(ds::grid_drop_stale_avx512(entries.data(), n, version.data()), k);
    for (std::size_t i = 0; i < k; ++i) ASSERT_TRUE(same_entry(entries[i], expected[i])) << "entry " << i;
  }
#else
  GTEST_SKIP() << "no AVX-512 path";
#endif
}

// Box_set::meets (two boxes at a time where SSE2 is there) says of each of
// up to 64 boxes what Box::overlaps says: at random, with coordinates from
// a few values so that boxes touch on faces, edges and corners, for every
// count (odd ones leave a padding lane).
TEST(FaceGrid, BoxSetMeetsAsOverlaps) {
  namespace ds = genmesh::detail::simplification;
  Xorshift64 next{0xBB67AE8584CAA73Bull};
  auto box = [&next] {
    auto c = [&next] { return static_cast<double>(next() % 7) * 0.5 - 1.5; };
    const Eigen::Vector3d a{c(), c(), c()}, b{c(), c(), c()};
    return ds::Box{a.cwiseMin(b), a.cwiseMax(b)};
  };
  std::vector<ds::Box> boxes(ds::Box_set::capacity);
  ds::Box_set set;
  for (int round = 0; round < 3000; ++round) {
    const std::size_t n = static_cast<std::size_t>(round) % (ds::Box_set::capacity + 1);
    for (std::size_t i = 0; i < n; ++i) boxes[i] = box();
    set.assign(boxes.data(), n);
    ASSERT_EQ(set.size(), n);
    const ds::Box b = box();
    std::uint64_t expected = 0;
    for (std::size_t i = 0; i < n; ++i) expected |= static_cast<std::uint64_t>(b.overlaps(boxes[i])) << i;
    ASSERT_EQ(set.meets(b), expected) << "round " << round;
  }
}

// A box's corners in grid units, all six coordinates at once (SSE2), and a
// point's (units(), two coordinates at once) are those of quantize() point
// by point: at random, on bin and cell borders
// (whole and just off), far out of the grid's range, infinite and NaN.
TEST(FaceGrid, BoxCornersEqualPointwise) {
  namespace ds = genmesh::detail::simplification;
  Xorshift64 next{0x6A09E667F3BCC909ull};
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double special[] = {0.0, -0.0, 1.0 / 16, -1.0 / 16, 0.3, -0.3, 2048.0, -2048.0, 2047.99, -2048.01,
                            2047.9375, -2047.9375, 32768.0, -32768.0, 32767.9375, 32767.99, -32768.01, 1e9, -1e9, 1e300, -1e300, inf, -inf, nan, 5e-324};
  for (const double cell : {1.0, 0.37, 1e-6}) {
    ds::Face_grid grid;
    grid.reset(cell, 0);
    auto coordinate = [&] {
      const std::uint64_t r = next();
      if (r % 4 == 0) return special[(r >> 8) % std::size(special)] * cell;
      if (r % 4 == 1) return static_cast<double>(static_cast<std::int64_t>(r >> 20) % 1100000 - 550000) / 16 * cell;
      return (static_cast<double>(r >> 11) * 0x1.0p-53 - 0.5) * 8192 * cell;
    };
    for (int round = 0; round < 20000; ++round) {
      const ds::Box b{{coordinate(), coordinate(), coordinate()}, {coordinate(), coordinate(), coordinate()}};
      ds::Face_grid::Point lo, hi;
      grid.quantize(b, lo, hi);
      ASSERT_EQ(lo, grid.quantize(b.lo)) << b.lo.transpose();
      ASSERT_EQ(hi, grid.quantize(b.hi)) << b.hi.transpose();
      ASSERT_EQ(grid.units(b.lo), lo) << b.lo.transpose();
      std::uint32_t sides = 0;
      ASSERT_EQ(grid.units(b.hi, lo, sides), hi) << b.hi.transpose();
      std::uint32_t expected = 0; // bit i: lo below hi on axis i, bit 4 + i: above
      for (int i = 0; i < 3; ++i) expected |= std::uint32_t{lo[i] < hi[i]} << i | std::uint32_t{lo[i] > hi[i]} << (4 + i);
      ASSERT_EQ(sides, expected) << b.lo.transpose() << " / " << b.hi.transpose();
      ASSERT_EQ(ds::Face_grid::sides(lo, hi), expected);
    }
  }
}

// A grid query returns every face whose box meets the query box, each once,
// also after faces moved (stale entries), were removed, or shrank without
// being listed again (listed with a box holding their own, as simplify's
// update_grid leaves them).
TEST(FaceGrid, QueryFindsEveryMeetingFaceOnce) {
  namespace ds = genmesh::detail::simplification;
  Xorshift64 next{0x9E3779B97F4A7C15ull};
  auto uniform = [&next] { return static_cast<double>(next() >> 11) * 0x1.0p-53; };
  auto box = [&uniform] {
    const Eigen::Vector3d c(10 * uniform(), 10 * uniform(), 10 * uniform());
    const Eigen::Vector3d r(1.5 * uniform(), 1.5 * uniform(), 1.5 * uniform());
    return ds::Box{c - r, c + r};
  };
  constexpr std::size_t faces = 400;
  std::vector<ds::Box> boxes(faces);
  std::vector<bool> live(faces, true);
  ds::Face_grid grid;
  grid.reset(1.0, faces);
  for (std::uint32_t f = 0; f < faces; ++f) grid.insert(f, boxes[f] = box());
  std::vector<std::uint32_t> found;
  for (int round = 0; round < 300; ++round) {
    const std::uint32_t f = static_cast<std::uint32_t>(uniform() * faces);
    if (round % 7 == 0) {
      grid.remove(f);
      live[f] = false;
    } else if (live[f] && round % 3 == 0) {
      // A box inside the one f is listed with, not listed again.
      const ds::Box was = boxes[f];
      const Eigen::Vector3d d = was.hi - was.lo;
      const Eigen::Vector3d u(uniform(), uniform(), uniform()), v(uniform(), uniform(), uniform());
      boxes[f].lo = (was.lo + d.cwiseProduct(u.cwiseMin(v))).cwiseMax(was.lo).cwiseMin(was.hi);
      boxes[f].hi = (was.lo + d.cwiseProduct(u.cwiseMax(v))).cwiseMin(was.hi).cwiseMax(boxes[f].lo);
    } else if (live[f]) {
      grid.insert(f, boxes[f] = box());
    }
    const ds::Box q = box();
    found.clear();
    grid.query(q, found);
    std::vector<int> times(faces, 0);
    for (const std::uint32_t g : found) ++times[g];
    for (std::uint32_t g = 0; g < faces; ++g) {
      ASSERT_LE(times[g], 1) << "face " << g;
      if (!live[g]) {
        ASSERT_EQ(times[g], 0) << "face " << g;
      } else if (boxes[g].overlaps(q)) {
        ASSERT_EQ(times[g], 1) << "face " << g;
      }
    }
  }
}
