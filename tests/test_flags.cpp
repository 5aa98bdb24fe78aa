// test_flags — genmesh compiled with the flags a user may add: this translation
// unit is built with -march=native -ffp-contract=fast (tests/CMakeLists.txt)
// when the compiler takes them and the build machine has FMA, i.e. with
// multiply-adds the compiler may fuse. It checks what must not depend on
// that (docs: README "Compiler flags"): the exact predicates (also with the
// multiply-adds fused), the SSE2 lanes equal to the scalar operations bit for
// bit, and simplify's result equal to the default build's and the same on
// every backend. Without FMA there is nothing to fuse: the tests say so and
// are skipped. No CGAL here (build time).
#include <genmesh/detail/geometry/predicates.h>
#include <genmesh/generators.h>
#include <genmesh/halfedge_mesh.h>
#include <genmesh/incidence_mesh.h>
#include <genmesh/simplification.h>
#include <genmesh/simplification/quadric.h>
#include <genmesh/soup_to_mesh.h>

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

namespace {

using Eigen::Vector3d;

#if defined(__FMA__) || defined(__FP_FAST_FMA)
constexpr bool fma_target = true;
#else
constexpr bool fma_target = false;
#endif

#define GENMESH_SKIP_WITHOUT_FMA()                                                                              \
  if (!fma_target)                                                                                             \
  GTEST_SKIP() << "not compiled for an FMA target (tests/CMakeLists.txt found no -march=native with FMA on "   \
                  "this machine or compiler): there is no contraction to test"

// genmesh's CMake target turns contraction off for the code using it (README
// "Compiler flags"), so this translation unit's own code is not contracted;
// the predicates are to stay exact without that, and GCC can be asked to fuse
// in one function (its optimize attribute applies to what it inlines; flatten
// inlines all of orient3d). Clang cannot: only the plain calls run there.
#if defined(__GNUC__) && !defined(__clang__)
constexpr bool contracted_helpers = true;
#define GENMESH_CONTRACTED [[gnu::optimize("fp-contract=fast"), gnu::flatten, gnu::noinline]]
#else
constexpr bool contracted_helpers = false;
#define GENMESH_CONTRACTED [[gnu::noinline]]
#endif

GENMESH_CONTRACTED double contracted_madd(double a, double b, double c) { return a * b + c; }
GENMESH_CONTRACTED int contracted_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return genmesh::detail::pred::orient2d(ax, ay, bx, by, cx, cy);
}
GENMESH_CONTRACTED int contracted_orient3d(const Vector3d& a, const Vector3d& b, const Vector3d& c,
                                           const Vector3d& d) {
  return genmesh::detail::pred::orient3d(a, b, c, d);
}

// The flags reached this translation unit, and the contracted helpers fuse.
TEST(Flags, CompiledForFma) {
  GENMESH_SKIP_WITHOUT_FMA();
  // (1 + 2^-30)(1 − 2^-30) − 1 = −2^-60: 0 when the product is rounded first.
  volatile double a = 1 + 0x1p-30, b = 1 - 0x1p-30, c = -1;
  if (contracted_helpers) EXPECT_EQ(contracted_madd(a, b, c), -0x1p-60) << "the optimize attribute did not fuse";
  else std::printf("not GCC: the predicates are tested without contraction only\n");
}

// The exact predicates with the filters' multiply-adds fused: the same signs
// as without (and the right ones: fixed cases checked with rationals), on
// input where the fused rounding matters to the bound (extremes: overflow,
// subnormals; cancellation).
TEST(Flags, PredicatesStayExact) {
  GENMESH_SKIP_WITHOUT_FMA();
  using genmesh::detail::pred::orient2d;
  using genmesh::detail::pred::orient3d;
  std::size_t n2 = 0, n3 = 0, zero = 0;
  auto o2 = [&](double ax, double ay, double bx, double by, double cx, double cy) {
    const int s = contracted_orient2d(ax, ay, bx, by, cx, cy);
    EXPECT_EQ(s, orient2d(ax, ay, bx, by, cx, cy)) << ax << ' ' << ay << " | " << bx << ' ' << by << " | " << cx
                                                   << ' ' << cy;
    ++n2, zero += s == 0;
    return s;
  };
  auto o3 = [&](const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
    const int s = contracted_orient3d(a, b, c, d);
    EXPECT_EQ(s, orient3d(a, b, c, d)) << a.transpose() << " | " << b.transpose() << " | " << c.transpose()
                                       << " | " << d.transpose();
    ++n3, zero += s == 0;
    return s;
  };
  const double max = std::numeric_limits<double>::max(), least = std::numeric_limits<double>::min(),
               tiny = std::numeric_limits<double>::denorm_min();
  // (CGAL 5.5's Epick says −1 here when compiled with -msse4.1 or later.)
  EXPECT_EQ(o3({-max, -least, 0}, {-least, -least, tiny}, {-tiny, tiny, -least}, {least, -tiny, -tiny}), 1);
  // Collinear as reals, not as doubles (the filter cannot decide these).
  EXPECT_EQ(o2(0, 0, 1, 1, 3, 3), 0);
  EXPECT_EQ(o2(0.1, 0.3, 0.2, 0.6, 0.3, 0.9), 1);
  EXPECT_EQ(o2(1, 1 + 0x1p-52, 2, 2, 3, 3), 1);
  EXPECT_EQ(o3({0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}, {0.7, 0.8, 0.9}, {1.0, 1.1, 1.2}), -1);
  EXPECT_EQ(o3({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0}), 0);
  EXPECT_EQ(o3({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0x1p-1074}), 1);
  std::mt19937_64 rng(19);
  // The extremes mixed: differences and products overflow or vanish.
  const std::array<double, 9> pool{0, tiny, -tiny, 3 * tiny, least, -least, 1, max, -max};
  std::uniform_int_distribution<std::size_t> from(0, pool.size() - 1);
  auto any = [&] { return pool[from(rng)]; };
  auto any3 = [&] { return Vector3d(any(), any(), any()); };
  for (int i = 0; i < 4000; ++i) {
    o2(any(), any(), any(), any(), any(), any());
    o3(any3(), any3(), any3(), any3());
  }
  // Lattices, scaled from subnormal to huge: on a line 0, just off it the
  // side the offset says; coplanar points in 3D.
  std::uniform_int_distribution<int> k(-1074, 960), small(-8, 8);
  for (int i = 0; i < 4000; ++i) {
    const int e = i % 2 ? k(rng) : -1074 + i % 8;
    auto at = [e](int v) { return std::ldexp(double(v), e); };
    const int ix = small(rng), iy = small(rng), jx = small(rng), jy = small(rng);
    EXPECT_EQ(o2(at(ix), at(iy), at(jx), at(jy), at(2 * jx - ix), at(2 * jy - iy)), 0);
    const Vector3d a(at(ix), at(iy), at(small(rng))), b(at(jx), at(jy), at(small(rng))),
        c(at(small(rng)), at(small(rng)), at(small(rng)));
    EXPECT_EQ(o3(a, b, c, a + (b - a) - (c - a)), 0);
    o3(a, b, c, Vector3d(at(small(rng)), at(small(rng)), at(small(rng))));
  }
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 4000; ++i) {
    const double ix = std::round(u(rng) * 1024), iy = std::round(u(rng) * 1024), jx = std::round(u(rng) * 1024),
                 jy = std::round(u(rng) * 1024);
    EXPECT_EQ(o2(ix, iy, jx, jy, 2 * jx - ix, 2 * jy - iy + 0x1p-40), ix == jx ? 0 : (jx > ix ? 1 : -1));
  }
  // Hard, not trivial: zeros are frequent, but not everything.
  EXPECT_GT(zero, (n2 + n3) / 10);
  EXPECT_LT(zero, (n2 + n3) * 9 / 10);
}

#if defined(__SSE2__)
// Relative_quadric::absolute_sum (two lanes) is p.absolute(op) + q.absolute(oq)
// bit for bit, and Plane_quadrics::place_costs is place() lane by lane.
TEST(Flags, LanesEqualScalars) {
  GENMESH_SKIP_WITHOUT_FMA();
  using genmesh::Quadric;
  using genmesh::Relative_quadric;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  auto point = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
  auto quadric = [&] {
    Quadric q;
    for (int k = 0; k < 3; ++k) q += Quadric::plane(point().normalized(), u(rng), 1 + u(rng));
    return q;
  };
  const genmesh::Plane_quadrics policy;
  std::size_t sums = 0, costs = 0, sum_differ = 0, cost_differ = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vector3d op = point(), oq = point();
    const Relative_quadric p = Relative_quadric::of(quadric(), op), q = Relative_quadric::of(quadric(), oq);
    const Quadric lanes = Relative_quadric::absolute_sum(p, op, q, oq);
    const Quadric scalar = p.absolute(op) + q.absolute(oq);
    ++sums;
    sum_differ += std::memcmp(&lanes, &scalar, sizeof(Quadric)) != 0;
    const Vector3d a0 = point(), b0 = point(), a1 = point(), b1 = point();
    const Quadric s0 = quadric(), s1 = quadric();
    genmesh::Quadric_lanes l = genmesh::Quadric_lanes::both(s0);
    const genmesh::Quadric_lanes l1 = genmesh::Quadric_lanes::both(s1);
    auto blend = [](__m128d x, __m128d y) { return _mm_move_sd(y, x); }; // lane 0 of x, lane 1 of y
    l = {blend(l.a00, l1.a00), blend(l.a01, l1.a01), blend(l.a02, l1.a02), blend(l.a11, l1.a11),
         blend(l.a12, l1.a12), blend(l.a22, l1.a22), blend(l.b0, l1.b0),   blend(l.b1, l1.b1),
         blend(l.b2, l1.b2),   blend(l.c, l1.c)};
    double cost[2];
    const int done = policy.place_costs(l, a0, b0, a1, b1, cost);
    for (int j = 0; j < 2; ++j)
      if (done & (1 << j)) {
        ++costs;
        const double c = j == 0 ? policy.place(s0, a0, b0).cost : policy.place(s1, a1, b1).cost;
        cost_differ += std::bit_cast<std::uint64_t>(c) != std::bit_cast<std::uint64_t>(cost[j]);
      }
  }
  EXPECT_EQ(sum_differ, 0u) << "of " << sums << " sums";
  EXPECT_EQ(cost_differ, 0u) << "of " << costs << " costs";
  EXPECT_GT(costs, sums / 4);
}
#endif

std::uint64_t fnv1a(const genmesh::Polygon_soup& s) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto add = [&h](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  };
  for (const auto& p : s.points) add(p.data(), 3 * sizeof(double));
  add(s.indices.data(), s.indices.size() * sizeof(s.indices[0]));
  add(s.offsets.data(), s.offsets.size() * sizeof(s.offsets[0]));
  return h;
}

// simplify gives the default build's mesh, on every backend: the hash is simplify_probe's for
// "tilt:64 he ratio=0.25" (docs/benchmarks.md), which every change to
// simplify is held to; with contraction it was cd3e22f7acfc447a, before
// costs tied at 0 went to the shortest edge first (session 20)
// 2284fe07c4b71daa, before collapses making slivers were refused (session
// 20) 0ea353475469a4f7. Update both together when simplify's result changes
// on purpose.
TEST(Flags, SimplifyEqualsDefaultBuild) {
  GENMESH_SKIP_WITHOUT_FMA();
  genmesh::Polygon_soup s = genmesh::make_grid_with_hole(64);
  for (auto& p : s.points) p = Vector3d(p.x(), p.y() * 0.6, p.y() * 0.8 + 0.3 * p.x());
  auto run = [&s]<class G>(G g) {
    genmesh::build_mesh(s, g, {.check = false});
    genmesh::simplify(g, genmesh::Simplification_options<>{
                             .target_faces = static_cast<std::size_t>(std::ceil(0.25 * double(s.num_faces())))});
    return fnv1a(genmesh::canonical(genmesh::to_soup(g)));
  };
  const std::uint64_t he = run(genmesh::Halfedge_mesh<>{});
  EXPECT_EQ(he, 0xeca337431bf38a30ull);
  // Every backend the same mesh (with contraction they were not: each
  // instantiation fused other products).
  EXPECT_EQ(run(genmesh::Incidence_mesh<>{}), he);
}

} // namespace
