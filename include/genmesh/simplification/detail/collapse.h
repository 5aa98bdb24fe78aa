// genmesh/simplification/detail/collapse.h — the collapse loop behind
// genmesh::simplify (private; see <genmesh/simplification.h>).
//
// Per vertex: the policy's data (a plane quadric in 10 floats relative to
// the vertex's point, Relative_quadric; nothing for a memoryless policy),
// locked / on-a-feature-line flags
// and a "has a refused edge" hint; per edge: refused and feature flags, the
// queue's entry (a float cost and the key) and position, and the descriptor
// where the mesh cannot make it from the index (HasNativeDescriptorOfIndex); per face (with the self-intersection guard): its corners,
// in a spatial hash. Collapse never adds elements, so
// these are vectors sized once by the index bounds. Points are read from the
// mesh's own array where it has one (HasNativePointArray: genmesh's meshes,
// Surface_mesh), else from a copy in double.
//
// One collapse: pop the cheapest edge; recompute its placement (the same
// numbers as when it was queued; where locks and feature lines allow it);
// refuse it if a face around it would turn by more than the allowed angle,
// flip, degenerate or fall below .min_angle, if the survivor would exceed
// .max_valence, if can_collapse_edge says no (link condition), or if a new
// face would meet another face (exact test against the faces a spatial hash
// finds near the new ones, but those the ring certificate clears); else drop
// the edges of its triangles from the queue, collapse_edge (the user's
// visitor rides along; the survivor's point is written as it moves), merge
// the policy data into the survivor, and
// requeue every edge of the survivor, plus the refused edges of its
// neighbours (their fold-over test depends on the survivor's point) — for a
// memoryless policy every edge at a neighbour of the survivor (their
// profiles hold its faces). With Schedule::passes there is no queue: see
// run_passes.
#pragma once
#ifdef GENMESH_SIMPLIFICATION_VERIFY_CERTIFICATES
#include <stdexcept>
#endif
// The guard's measurement hook (see stays_embedded): 0 (off) unless
// GENMESH_SIMPLIFICATION_GUARD_FLOOR is defined; a named 0, so that builds
// with -Wundef see no undefined macro in an #if.
#ifdef GENMESH_SIMPLIFICATION_GUARD_FLOOR
#define GENMESH_DETAIL_GUARD_FLOOR GENMESH_SIMPLIFICATION_GUARD_FLOOR
#else
#define GENMESH_DETAIL_GUARD_FLOOR 0
#endif

#include <genmesh/concepts.h>
#include <genmesh/detail/branchless.h>
#include <genmesh/detail/geometry/predicates.h>
#include <genmesh/detail/memory/huge_pages.h>
#include <genmesh/detail/prefetch.h>
#include <genmesh/exceptions.h>
#include <genmesh/features.h>
#include <genmesh/geometry.h>
#include <genmesh/simplification/detail/face_grid.h>
#include <genmesh/local_operations.h>
#include <genmesh/point_traits.h>
#include <genmesh/priority_queue.h>
#include <genmesh/property_maps.h>
#include <genmesh/simplification/profile.h>
#include <genmesh/visitor.h>

#include <boost/dynamic_bitset.hpp>
#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <tuple>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh::detail::simplification {

#ifdef GENMESH_SIMPLIFICATION_VERIFY_CERTIFICATES
// For the tests: the ring certificates verified with a link vertex on the
// border, with p or q on the border, with neither where ∂U was shown a
// simple polygon, and where it was shown seen once from a point other than
// x (see Collapser::verify_certificate).
inline std::size_t verified_border_certificates = 0;
inline std::size_t verified_border_star_certificates = 0;
inline std::size_t verified_outline_certificates = 0;
inline std::size_t verified_recentred_certificates = 0;
#endif

/// What simplify() needs of a mesh: lists, index maps, points and the
/// collapse operation (native or generic).
template <class G>
concept Simplifiable =
    FaceListGraph<G> && EdgeListGraph<G> && VertexListGraph<G> && HasIndexMap<G, vertex_index_t> &&
    HasIndexMap<G, edge_index_t> && HasIndexMap<G, face_index_t> && HasVertexPoints<G> &&
    requires(G& g, const G& cg, edge_descriptor_t<G> e) {
      genmesh::collapse_edge(e, g);
      { genmesh::can_collapse_edge(e, cg) } -> std::convertible_to<bool>;
    };

// The policy's merge and fixed placement, or the quadric defaults (merge
// always inlined, as Quadric's sum: see quadric.h).
template <class Policy, class Data>
[[gnu::always_inline]] inline Data merge(const Policy& p, const Data& x, const Data& y) {
  if constexpr (requires { p.merge(x, y); }) return p.merge(x, y);
  else return x + y;
}
template <class Policy, class Data>
Placement fixed(const Policy& p, const Data& s, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                const Eigen::Vector3d& x) {
  if constexpr (requires { p.fixed(s, a, b, x); }) return p.fixed(s, a, b, x);
  else return {s(x), x};
}

// The per-vertex data of a policy: none for a memoryless one.
struct No_vertex_data {};
template <class Policy>
struct Vertex_data_of {
  using type = No_vertex_data;
};
template <class Policy>
  requires(!is_memoryless<Policy>)
struct Vertex_data_of<Policy> {
  using type = typename Policy::Vertex_data;
};

// a and b in increasing order, with masks instead of a branch: which end of
// an edge has the lower index is a coin toss (the branches mispredicted
// ~1.5 times a collapse on the 208k armadillo, ~2M times in building its
// first queue).
template <class T>
[[gnu::always_inline]] inline void sort_two(T& a, T& b) {
  static_assert(std::is_unsigned_v<T>);
  const T swap = (a ^ b) & (T{0} - static_cast<T>(b < a));
  a ^= swap;
  b ^= swap;
}

// The sign of orient2d(a, b, c) when the floating value decides it (twice
// Shewchuk's bound for orient2d's first stage, plus the underflow term of
// predicates.h), or when every difference and product in it was exact (then
// comparing the products is exact: the collinear corners of a grid);
// `unsure` otherwise. A product counts as exact where a factor is zero, or
// where fma finds no rounding error and the product is at least 2^-969: an
// error below that may be no double, and fma would round it away.
inline constexpr int unsure = 2;
[[gnu::always_inline]] inline int sure_orient2d(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                                 const std::array<double, 2>& c) {
  const double bx = b[0] - a[0], cy = c[1] - a[1], by = b[1] - a[1], cx = c[0] - a[0];
  const double l = bx * cy, r = by * cx;
  const double det = l - r,
               bound = 2 * detail::pred::o2d_bound * (std::abs(l) + std::abs(r)) + detail::pred::underflow_bound;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  auto exact_difference = [](double x, double y, double d) {
    double s, e;
    detail::pred::two_sum(x, -y, s, e);
    return s == d && e == 0;
  };
  auto exact_product = [](double u, double v, double p) {
    return u == 0 || v == 0 || (std::abs(p) >= 0x1p-969 && std::fma(u, v, -p) == 0);
  };
  if (!exact_difference(b[0], a[0], bx) || !exact_difference(c[1], a[1], cy) || !exact_difference(b[1], a[1], by) ||
      !exact_difference(c[0], a[0], cx) || !exact_product(bx, cy, l) || !exact_product(by, cx, r))
    return unsure;
  return l > r ? 1 : l < r ? -1 : 0;
}

// Is the closed polygon q[0] → q[1] → … → q[n-1] → q[0] simple: n >= 3, no
// edge of zero length, two adjacent edges meeting only in their common
// corner (not folded back along one line), two others not at all? Exact
// (orient2d). Two corners at one point fail: their edges are adjacent (one
// is zero) or, n >= 4, two non-adjacent edges hold them both; n = 3, the
// three are on one line and an edge folds back. (The ring certificate's
// second way: see Collapser::ring_projects_one_to_one.)
inline bool is_simple_polygon(std::span<const std::array<double, 2>> q) {
  const std::size_t n = q.size();
  if (n < 3) return false;
  auto orient = [](const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
    return detail::pred::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const auto &a = q[i == 0 ? n - 1 : i - 1], &b = q[i], &c = q[i + 1 == n ? 0 : i + 1];
    if (a == b) return false;
    // a, b, c on one line (a ≠ b, c ≠ b: the next corner checks that): c
    // differs from b along a coordinate along which a does, and lies on a's
    // side of b there iff ab and bc overlap.
    if (orient(a, b, c) == 0) {
      const int k = a[0] != b[0] ? 0 : 1;
      if ((a[k] < b[k]) == (c[k] < b[k])) return false;
    }
  }
  for (std::size_t i = 0; i + 2 < n; ++i) {
    const auto &a = q[i], &b = q[i + 1];
    const double x0 = std::min(a[0], b[0]), x1 = std::max(a[0], b[0]), y0 = std::min(a[1], b[1]),
                 y1 = std::max(a[1], b[1]);
    const std::size_t end = i == 0 ? n - 1 : n;
    for (std::size_t j0 = i + 2; j0 < end; j0 += 64) {
      // The edges j0, j0 + 1, … (64 at most) whose boxes meet ab's, as bits,
      // without a branch (most are apart, unpredictably along either axis:
      // on the shark a branch a pair cost more than the arithmetic, with
      // Collapser::outline_cycle_of_ring_edges's old sorted search 2.5k
      // cycles a call against 1.5k now); then those alone.
      const std::size_t stop = std::min(end, j0 + 64);
      std::uint64_t meet = 0;
      for (std::size_t j = j0; j < stop; ++j) {
        const auto &c = q[j], &d = q[j + 1 == n ? 0 : j + 1];
        const bool apart = genmesh::detail::any_true(std::max(c[0], d[0]) < x0, std::min(c[0], d[0]) > x1,
                                                     std::max(c[1], d[1]) < y0, std::min(c[1], d[1]) > y1);
        meet |= static_cast<std::uint64_t>(!apart) << (j - j0);
      }
      for (; meet != 0; meet &= meet - 1) {
        const std::size_t j = j0 + static_cast<std::size_t>(std::countr_zero(meet));
        const auto &c = q[j], &d = q[j + 1 == n ? 0 : j + 1];
        const int o1 = orient(a, b, c), o2 = orient(a, b, d);
        if (o1 == o2 && o1 != 0) continue; // c and d strictly on one side of ab's line
        // All four on one line, their boxes meeting: the segments overlap (a
        // coordinate along which the line is one-to-one orders them).
        if (o1 == 0 && o2 == 0) return false;
        const int o3 = orient(c, d, a), o4 = orient(c, d, b);
        if (o3 == o4 && o3 != 0) continue;
        return false; // each line separates (or touches) the other segment's ends
      }
    }
  }
  return true;
}

template <class G, class Policy, class Visitor>
class Collapser {
  using V = vertex_descriptor_t<G>;
  using H = halfedge_descriptor_t<G>;
  using E = edge_descriptor_t<G>;
  using F = face_descriptor_t<G>;
  static constexpr bool memoryless = is_memoryless<Policy>;
  using Data = typename Vertex_data_of<Policy>::type;
  using Options = Simplification_options<Policy>;
  // Plane quadrics are stored in 40 bytes, relative to the vertex's point
  // (Relative_quadric): 16.6 MB less on 832k faces; summed and solved in double.
  static constexpr bool relative = std::is_same_v<Data, Quadric>;
  using Stored = std::conditional_t<relative, Relative_quadric, Data>;

 public:
  Collapser(G& g, const Options& o, Visitor& visitor)
      : g_(g), o_(o), policy_(o.policy), vis_(visitor), vindex_(get(vertex_index, std::as_const(g))),
        eindex_(get(edge_index, std::as_const(g))) {}

  Simplification_result run() {
    Simplification_result r;
    vis_.on_started(std::as_const(g_));
    prepare();
    const std::size_t faces0 = faces_;
    std::size_t target = 0;
    if (o_.target_faces) target = *o_.target_faces;
    if (o_.target_ratio) {
      const double t = *o_.target_ratio;
      if (!(t >= 0.0 && t <= 1.0))
        throw invalid_input("simplify: target_ratio " + std::to_string(t) + " is not in [0, 1]");
      target = std::max(target, static_cast<std::size_t>(std::ceil(t * static_cast<double>(faces0))));
    }
    const bool has_target = o_.target_faces || o_.target_ratio;
    double max_error = o_.max_error;
    if (o_.max_error_relative) max_error *= diagonal();
    const std::size_t total = has_target && faces0 > target ? faces0 - target : faces0;
    vis_.on_step("faces", 0, total);
    if (has_target && faces0 <= target) {
      r.stop_reason = Stop_reason::target_already_met;
      vis_.on_step("faces", total, total);
      vis_.on_finished(std::as_const(g_));
      finish(r);
      return r;
    }
    passes_ = o_.schedule == Schedule::passes;
    if (!passes_) max_error_ = max_error; // passes leave the edges above it out
    initialize();
    if (passes_) {
      r.stop_reason = run_passes(r, has_target, target, max_error, faces0, total);
    } else for (;;) {
      if (has_target && faces_ <= target) {
        r.stop_reason = Stop_reason::target_faces;
        break;
      }
      if (queue_.empty()) {
        r.stop_reason = Stop_reason::no_collapse_left;
        break;
      }
      // The queue holds costs as floats (monotone: the order only gains
      // ties; costs at 0 as negative floats, see priority()); the bound is
      // checked on the exact cost, in collapse().
      const std::size_t ei = queue_.pop();
      if (prefetch_ && !queue_.empty())
        ahead_begin(queue_.top(), queue_.size() >= 2, queue_.size() >= 2 ? queue_.second() : 0);
      if (collapse(ei)) {
        ++r.collapses;
        r.max_error = std::max(r.max_error, std::sqrt(last_cost_));
        if ((r.collapses & 16383u) == 0) vis_.on_step("faces", std::min(faces0 - faces_, total - 1), total);
      } else if (over_error_) {
        r.stop_reason = Stop_reason::max_error;
        break;
      }
    }
    vis_.on_step("faces", total, total);
    vis_.on_finished(std::as_const(g_));
    finish(r);
    return r;
  }

 private:
  std::size_t vi(V v) const { return static_cast<std::size_t>(get(vindex_, v)); }
  std::size_t ei(E e) const { return static_cast<std::size_t>(get(eindex_, e)); }
  std::size_t fi(F f) const { return static_cast<std::size_t>(get(get(face_index, g_), f)); }
  // Edge k's descriptor: made from k where the mesh can (no array: 5 MB
  // less at 832k faces), else kept from edges(g).
  static constexpr bool native_edges = HasNativeDescriptorOfIndex<G, edge_index_t>;
  E edge_of(std::size_t k) const {
    if constexpr (native_edges) return genmesh_native_descriptor(edge_index, g_, k);
    else return edesc_[k];
  }
  bool border(H h) const { return face(h, g_) == boost::graph_traits<G>::null_face(); }

  template <class Range>
  static std::size_t count(const Range& r) {
    return static_cast<std::size_t>(std::distance(r.begin(), r.end()));
  }

  void finish(Simplification_result& r) const {
    // Counted: CGAL's num_faces(Surface_mesh) is the index bound.
    r.vertices = count(vertices(g_));
    r.edges = count(edges(g_));
    r.faces = count(faces(g_));
    r.exact_intersection_tests = exact_tests_;
  }

  // Checks the input, triangulates if asked, reads the points.
  void prepare() {
    if constexpr (requires { g_.is_manifold(); }) {
      if (o_.check_input && !g_.is_manifold())
        throw invalid_input("simplify: the mesh is not manifold (run genmesh check; repair with --repair)");
    }
    std::size_t fnum = 0;
    bool polygons = false;
    for (const F f : faces(g_)) {
      const H h = halfedge(f, g_);
      if (next(next(next(h, g_), g_), g_) != h) {
        if (!o_.triangulate)
          throw invalid_input("simplify: face " + std::to_string(get(get(face_index, g_), f)) +
                              " is not a triangle (set triangulate to triangulate polygons first)");
        polygons = true;
      }
      ++fnum;
    }
    if (polygons) {
      if constexpr (requires { genmesh::triangulate_faces(g_); }) {
        if (genmesh::triangulate_faces(g_) != 0)
          throw invalid_input("simplify: a polygon could not be triangulated");
      }
      fnum = count(faces(g_));
    }
    faces_ = fnum;
    const std::size_t vb = index_bound(vertex_index, g_), eb = index_bound(edge_index, g_);
    pos_ = genmesh::detail::Point_reader<G>(g_, vb);
    for (const V v : vertices(g_))
      if (!Eigen::Vector3d(pos_[vi(v)]).allFinite())
        throw invalid_input("simplify: vertex " + std::to_string(vi(v)) + " has a non-finite coordinate");
    if (o_.check_input) check_manifold(vb, eb);
  }

  // A vertex whose fan (walked from halfedge(v)) misses some of its edges is
  // where several fans meet: not manifold.
  void check_manifold(std::size_t vb, std::size_t /*eb*/) {
    std::vector<std::uint32_t> degree(vb, 0);
    for (const E e : edges(g_)) {
      const H h = halfedge(e, g_);
      ++degree[vi(target(h, g_))];
      ++degree[vi(source(h, g_))];
    }
    for (const V v : vertices(g_)) {
      const H start = halfedge(v, g_);
      if (start == boost::graph_traits<G>::null_halfedge()) continue;
      std::uint32_t n = 0;
      const std::uint32_t d = degree[vi(v)];
      H x = start;
      do {
        ++n;
        x = opposite(next(x, g_), g_);
      } while (x != start && n <= d);
      if (n != d)
        throw invalid_input("simplify: vertex " + std::to_string(vi(v)) +
                            " is not manifold (several fans meet there; repair with --repair)");
    }
  }

  // Vertex i's policy data (absolute, in double), and setting it (after its
  // point: a stored quadric is relative to the point).
  [[gnu::always_inline]] Data vertex_data(std::size_t i) const {
    if constexpr (relative) return data_[i].absolute(pos_[i]);
    else return data_[i];
  }
  // Stored plane quadrics merged by +: two vertices' are made absolute side
  // by side (Relative_quadric::absolute_sum, add_to_two).
  static constexpr bool summed = relative && !requires(const Policy& p, const Data& d) { p.merge(d, d); };
  // The merged data of vertices a and b.
  [[gnu::always_inline]] Data data_sum(std::size_t a, std::size_t b) const {
    if constexpr (summed) return Relative_quadric::absolute_sum(data_[a], pos_[a], data_[b], pos_[b]);
    else return simplification::merge(policy_, vertex_data(a), vertex_data(b));
  }
  // Edges evaluated two at a time, side by side (Plane_quadrics::place_costs,
  // with SSE2): Plane_quadrics itself only, not a type derived from it (its
  // place() may differ).
#if defined(__SSE2__)
  static constexpr bool two_at_once = summed && std::is_same_v<Policy, Plane_quadrics>;
#else
  static constexpr bool two_at_once = false;
#endif
  // Vertex i's stored quadric made absolute, out of line: collapse() calls it
  // right after set_data(i), and GCC 12 (-O2/-O3) has forwarded the doubles
  // just stored as floats to such reloads unrounded (docs/benchmarks.md,
  // session 16, "Simplification quadrics").
  [[gnu::noinline]] Quadric stored_absolute(std::size_t i) const { return data_[i].absolute(pos_[i]); }
  // The costs of collapsing edges (a0, b0) and (a1, b1) (a_i < b_i, anywhere:
  // no locks), as evaluate() gives them; s holds their ends' data summed,
  // lane by lane. Where place_costs leaves a lane, place() takes that lane's
  // sum (the same doubles as data_sum's).
  template <class Lanes>
  [[gnu::always_inline]] void costs_two(const Lanes& s, std::size_t a0, std::size_t b0, std::size_t a1,
                                        std::size_t b1, double* cost) const {
    const int done = policy_.place_costs(s, pos_[a0], pos_[b0], pos_[a1], pos_[b1], cost);
    if (done == 3) return;
    for (int j = 0; j < 2; ++j) {
      if (done >> j & 1) continue;
      const Quadric q = s.lane(j);
      cost[j] = j == 0 ? policy_.place(q, pos_[a0], pos_[b0]).cost : policy_.place(q, pos_[a1], pos_[b1]).cost;
    }
  }

  // add_data(a, d) then add_data(b, d).
  void add_data_to_two(std::size_t a, std::size_t b, const Data& d) {
    if constexpr (summed) {
      if (a != b) return Relative_quadric::add_to_two(data_[a], pos_[a], data_[b], pos_[b], d);
    }
    add_data(a, d);
    add_data(b, d);
  }
  void set_data(std::size_t i, const Data& d) {
    if constexpr (relative) data_[i] = Relative_quadric::of(d, pos_[i]);
    else data_[i] = d;
  }
  void add_data(std::size_t i, const Data& d) {
    if constexpr (summed) Relative_quadric::add_to_one(data_[i], pos_[i], d); // stored as add_to_two stores
    else set_data(i, simplification::merge(policy_, vertex_data(i), d));
  }

  // The box of the vertices' points (empty without vertices).
  Eigen::AlignedBox3d points_box() const {
    Eigen::AlignedBox3d box;
    for (const V v : vertices(g_)) box.extend(pos_[vi(v)]);
    return box;
  }

  double diagonal() const {
    const Eigen::AlignedBox3d box = points_box();
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
  }

  // Policy data, locks and the queue.
  void initialize() {
    const std::size_t vb = pos_.size(), eb = index_bound(edge_index, g_);
    // A small mesh stays in cache: its walks ahead and hints would be
    // instructions only (mech-holes-shark, 10k faces → 10 %, unguarded: 5.8
    // → 5.2 ms without the walks; the 52k-face armadillo: 34 → 35 ms).
    prefetch_ = faces_ >= 20'000;
    data_.assign(vb, Stored{});
    // Lock bytes only where something can be locked: without them where()
    // reads no per-vertex byte (a cache miss a requeued edge at 832k faces).
    locks_ = static_cast<bool>(o_.is_locked) || o_.border == Border_mode::lock || o_.feature_angle.has_value() ||
             static_cast<bool>(o_.edge_is_constrained);
    if (locks_) locked_.assign(vb, 0);
    hint_ = Bits(vb);
    refused_ = Bits(eb);
    if constexpr (!native_edges) edesc_.assign(eb, E{});
    if constexpr (memoryless) {
      stamp_.assign(eb, 0);
      link_seen_.assign(vb, 0);
    }
    if (o_.is_locked)
      for (const V v : vertices(g_))
        if (o_.is_locked(vi(v))) locked_[vi(v)] = 1;
    if constexpr (requires { policy_.mean_edge_length; }) {
      const double m = mean_edge_length();
      if (m > 0) policy_.mean_edge_length = m;
    }
    if constexpr (requires { policy_.start(std::as_const(g_)); })
      policy_.start(std::as_const(g_)); // a policy that reads per-vertex data (Attribute_quadrics)
    // Faces in index order, corners from the lowest index: the same sums on
    // every backend. The corners of the face `lag` places ahead are read,
    // and their points and data asked for, while this one's sums are made
    // (one loop's reads of scattered links, points and data were a miss
    // each).
    if constexpr (!memoryless) {
      constexpr std::size_t lag = 8;
      std::array<std::array<std::size_t, 3>, lag> ahead;
      auto read = [&](F f) {
        const H h0 = halfedge(f, g_), h1 = next(h0, g_), h2 = next(h1, g_);
        std::size_t a = vi(target(h0, g_)), b = vi(target(h1, g_)), c = vi(target(h2, g_));
        if (b < a && b < c) {
          std::tie(a, b, c) = std::make_tuple(b, c, a);
        } else if (c < a && c < b) {
          std::tie(a, b, c) = std::make_tuple(c, a, b);
        }
        if (prefetch_)
          for (const std::size_t v : {a, b, c}) {
            pos_.prefetch(v);
            genmesh::detail::prefetch_object(&data_[v]);
          }
        return std::array<std::size_t, 3>{a, b, c};
      };
      const auto fs = faces(g_);
      auto lead = fs.begin();
      const auto end = fs.end();
      std::size_t read_n = 0, done = 0;
      for (; lead != end && read_n < lag; ++lead) ahead[read_n++ % lag] = read(*lead);
      while (done < read_n) {
        // (Not a structured binding: Clang before 16 refuses one named in
        // the requires-expression below.)
        const std::array<std::size_t, 3> abc = ahead[done % lag];
        const std::size_t a = abc[0], b = abc[1], c = abc[2];
        if (lead != end) {
          ahead[read_n++ % lag] = read(*lead); // into the slot just taken
          ++lead;
        }
        ++done;
        Data q;
        if constexpr (requires { policy_.face(a, pos_[a], b, pos_[b], c, pos_[c]); })
          q = policy_.face(a, pos_[a], b, pos_[b], c, pos_[c]); // a policy that reads attributes
        else
          q = policy_.face(pos_[a], pos_[b], pos_[c]);
        add_data_to_two(a, b, q);
        add_data(c, q);
      }
    }
    for (const E e : edges(g_)) {
      if constexpr (!native_edges) edesc_[ei(e)] = e;
      H h = halfedge(e, g_);
      const bool b0 = border(h), b1 = border(opposite(h, g_));
      if (!b0 && !b1) continue;
      if (b0) h = opposite(h, g_);
      const std::size_t a = vi(source(h, g_)), b = vi(target(h, g_)), c = vi(target(next(h, g_), g_));
      if (o_.border == Border_mode::lock) {
        locked_[a] = locked_[b] = 1;
      } else if constexpr (!memoryless) if (o_.border == Border_mode::preserve) {
        const Data q = policy_.border(pos_[a], pos_[b], pos_[c], o_.border_weight);
        add_data_to_two(a, b, q);
      }
    }
    init_features(eb);
    if (o_.prevent_self_intersections) {
      const std::size_t fb = index_bound(face_index, g_);
      vflags_.assign(vb, 0);
      for (const E e : edges(g_)) {
        const H h = halfedge(e, g_);
        if (border(h) || border(opposite(h, g_))) {
          vflags_[vi(source(h, g_))] = on_border;
          vflags_[vi(target(h, g_))] = on_border;
        }
      }
      // The grid names faces by index; the descriptor is made from the index
      // where the mesh can (HasNativeDescriptorOfIndex: Halfedge_mesh,
      // Incidence_mesh, Surface_mesh, OpenMesh), else face_h_ keeps a
      // halfedge of each face.
      if constexpr (!native_faces) {
        face_h_.assign(fb, boost::graph_traits<G>::null_halfedge());
        for (const F f : faces(g_)) face_h_[fi(f)] = halfedge(f, g_);
      }
      build_grid(fb);
    }
    const double deg = std::clamp(o_.max_normal_deviation, 0.0, 180.0);
    cos_max_ = std::max(0.0, std::cos(deg * std::numbers::pi / 180.0));
    cos_min_angle_ = o_.min_angle > 0 ? std::cos(std::min(o_.min_angle, 60.0) * std::numbers::pi / 180.0) : 1.0;
    if (passes_) return;
    queue_ = Queue(eb, Order{this});
    queue_.reserve(eb);
    // The heap keeps the cheapest ~16k edges (128 KB, in L2), the rest wait
    // unordered (a sift in the whole heap was a cache miss a level below the
    // top few: 832k guard=0 0.87 → 0.75 s; none below ~44k faces).
    queue_.set_near_size(std::size_t{1} << 14);
    Placement pl;
    // The ends' points and data of the edge `lag` places ahead asked for
    // (each a miss otherwise).
    constexpr int lag = 8;
    const auto es = edges(g_);
    auto lead = es.begin();
    const auto end = es.end();
    auto ask = [&] {
      const H h = halfedge(*lead, g_);
      for (const V v : {source(h, g_), target(h, g_)}) {
        pos_.prefetch(vi(v));
        if constexpr (!memoryless) genmesh::detail::prefetch_object(&data_[vi(v)]);
      }
      ++lead;
    };
    for (int i = 0; prefetch_ && i < lag && lead != end; ++i) ask();
#if defined(__SSE2__)
    if constexpr (two_at_once) {
      if (!locks_) {
        // Two edges at a time (no locks: every edge may collapse anywhere).
        std::size_t held = 0, ha = 0, hb = 0;
        bool holding = false;
        for (const E e : es) {
          if (prefetch_ && lead != end) ask();
          const H h = halfedge(e, g_);
          std::size_t a = vi(source(h, g_)), b = vi(target(h, g_));
          sort_two(a, b);
          const std::size_t k = ei(e);
          if (!holding) {
            held = k, ha = a, hb = b;
            holding = true;
            continue;
          }
          holding = false;
          const Quadric_lanes sum = Relative_quadric::absolute_lanes(data_[ha], pos_[ha], data_[a], pos_[a]) +
                                    Relative_quadric::absolute_lanes(data_[hb], pos_[hb], data_[b], pos_[b]);
          double cost[2];
          costs_two(sum, ha, hb, a, b, cost);
          queue_.push_unordered(held, priority(cost[0], ha, hb));
          queue_.push_unordered(k, priority(cost[1], a, b));
        }
        if (holding && evaluate(halfedge(edge_of(held), g_), pl))
          queue_.push_unordered(held, priority(pl.cost, ha, hb));
        queue_.heapify();
        return;
      }
    }
#endif
    for (const E e : es) {
      if (prefetch_ && lead != end) ask();
      if (evaluate(halfedge(e, g_), pl)) queue_.push_unordered(ei(e), priority(pl.cost, halfedge(e, g_)));
    }
    queue_.heapify();
  }

  // Schedule::passes. Each pass: every live edge's cost (the edges the
  // constraints allow and .max_error admits) into a compact array; the rank
  // of a quarter of the collapses the face target still needs gives a cost
  // limit, 1.5x the cost there (meshoptimizer's factor: room for the edges
  // the pass will skip; meshoptimizer's rank, all the collapses needed, cost
  // up to 1.2x CGAL's Hausdorff distance on mech-holes-shark at 10%, a
  // quarter 1.00x, a tenth 1.00x but more passes); the edges up to it, sorted by
  // (cost, vertex-index pair), are collapsed in order unless a collapse of
  // this pass touched one of their ends (then their cost or constraints may
  // have changed: they wait for the next pass). A pass that collapses
  // nothing below the limit is repeated without a limit; one that collapses
  // nothing at all ends the run (every edge refused). Each pass collapses at
  // least one edge, so the loop ends.
  Stop_reason run_passes(Simplification_result& r, bool has_target, std::size_t target_faces, double max_error,
                         std::size_t faces0, std::size_t total) {
    touched_.assign(pos_.size(), 0);
    ecost_.assign(index_bound(edge_index, g_), Cost_mark::dirty);
    // With a memoryless policy an edge's cost reads the faces at its ends'
    // neighbours; with feature lines a collapse reclassifies the apexes.
    const bool rings = memoryless || features_;
    bool unlimited = false;
    for (;;) {
      if (has_target && faces_ <= target_faces) return Stop_reason::target_faces;
      // Costs: computed again where a collapse of the last pass touched an
      // end (or the edge is new to its ends); kept otherwise, bit for bit.
      // Counted by the high half of their bits on the way, for the limit.
      bool above = false;
      Placement pl;
      std::size_t n = 0;
      high_.assign(std::size_t{1} << 12, 0);
      for (const E e : edges(g_)) {
        const std::size_t k = ei(e);
        float& c = ecost_[k];
        const H h = halfedge(e, g_);
        if (c == Cost_mark::dirty || touched_[vi(source(h, g_))] || touched_[vi(target(h, g_))]) {
          if (!evaluate(h, pl)) c = Cost_mark::none;
          else if (std::sqrt(pl.cost) > max_error) c = Cost_mark::above;
          else c = pl.cost > 0 ? static_cast<float>(pl.cost) : 0.0f; // ≥ 0: its bits order as integers
        }
        if (c >= 0) {
          ++n;
          ++high_[std::bit_cast<std::uint32_t>(c) >> 19]; // exponent and 3 bits (a non-negative float)
        } else {
          above |= c == Cost_mark::above;
        }
      }
      if (n == 0) return above ? Stop_reason::max_error : Stop_reason::no_collapse_left;
      // The limit: 1.5x the cost of rank `goal` (the same float a sort of
      // all candidates would put there), found by its top 12 bits and then
      // by 10 and 9 more; only the candidates up to it are listed, so that
      // the list holds a pass's worth of edges, not every edge (8 bytes an
      // edge: 10 MB at 832k faces, the run's largest array). The counts take
      // 20 KB (a 2^16-bucket version's 0.5 MB outweighed the list on 10k faces).
      std::uint32_t limit = ~std::uint32_t{0};
      std::size_t listed = n, rank = 0;
      std::uint32_t hi = 0;
      bool select = false;
      if (has_target && !unlimited) {
        const std::size_t goal = (faces_ - target_faces) / 8 + 1; // a quarter of the collapses still needed
        if (goal < n) {
          // The rank's top bits; listed first up to 1.5x the top of that
          // bucket (1.5f * x is monotone in x), then cut.
          std::size_t below = 0;
          while (below + high_[hi] <= goal) below += high_[hi++];
          rank = goal - below;
          limit = std::bit_cast<std::uint32_t>(1.5f * std::bit_cast<float>(hi << 19 | 0x7ffffu));
          listed = 0;
          for (std::uint32_t b = 0; b <= (limit >> 19) && b < high_.size(); ++b) listed += high_[b];
          select = true;
        }
      }
      cand_.clear();
      cand_.reserve(listed);
      // By index (the sort below orders them): every edge a collapse
      // removes was marked dirty then.
      for (std::size_t k = 0; k < ecost_.size(); ++k) {
        const float c = ecost_[k];
        if (c >= 0 && std::bit_cast<std::uint32_t>(c) <= limit)
          cand_.push_back((std::uint64_t{std::bit_cast<std::uint32_t>(c)} << 32) | k);
      }
      if (select) {
        // The rank's other bits, among the listed (they hold the whole
        // bucket): 10, then 9; then the exact limit.
        low_.assign(std::size_t{1} << 10, 0);
        for (const std::uint64_t x : cand_)
          if ((x >> 51) == hi) ++low_[(x >> 41) & 0x3ffu];
        std::uint32_t mid = 0;
        while (low_[mid] <= rank) rank -= low_[mid++];
        const std::uint64_t top = std::uint64_t{hi} << 10 | mid;
        low_.assign(std::size_t{1} << 9, 0);
        for (const std::uint64_t x : cand_)
          if ((x >> 41) == top) ++low_[(x >> 32) & 0x1ffu];
        std::uint32_t lo = 0;
        while (low_[lo] <= rank) rank -= low_[lo++];
        const std::uint32_t at = static_cast<std::uint32_t>(top << 9 | lo);
        const std::uint64_t cut_at = std::uint64_t{std::bit_cast<std::uint32_t>(1.5f * std::bit_cast<float>(at))};
        std::erase_if(cand_, [cut_at](std::uint64_t x) { return (x >> 32) > cut_at; });
      }
      const auto end = cand_.end();
      const bool cut = cand_.size() < n; // some candidates wait beyond the limit
      std::sort(cand_.begin(), end);
      order_ties(cand_.begin(), end);
      std::fill(touched_.begin(), touched_.end(), std::uint8_t{0});
      std::size_t done = 0;
      for (auto it = cand_.begin(); it != end; ++it) {
        if (has_target && faces_ <= target_faces) return Stop_reason::target_faces;
        const auto k = static_cast<std::uint32_t>(*it);
        if (ecost_[k] == Cost_mark::dirty) continue; // gone, or its ends changed, in this pass
        const H h = halfedge(edge_of(k), g_);
        const std::size_t a = vi(source(h, g_)), b = vi(target(h, g_));
        if (touched_[a] | touched_[b]) continue;
        // The next two candidates still listed (of the next four) are walked ahead.
        if (prefetch_) {
          std::uint32_t next_k[2] = {0, 0};
          int nn = 0;
          for (auto j = it + 1; j != end && nn < 2 && j - it <= 4; ++j)
            if (ecost_[static_cast<std::uint32_t>(*j)] != Cost_mark::dirty) next_k[nn++] = static_cast<std::uint32_t>(*j);
          if (nn > 0) ahead_begin(next_k[0], nn > 1, next_k[1]);
          else ahead_[0].left[0] = ahead_[0].left[1] = ahead_[1].left[0] = ahead_[1].left[1] = 0;
        }
        if (!collapse(k)) continue;
        ++done;
        ++r.collapses;
        r.max_error = std::max(r.max_error, std::sqrt(last_cost_));
        touched_[a] = touched_[b] = 1;
        if (rings) {
          const H start = halfedge(last_survivor_, g_);
          H x = start;
          do {
            touched_[vi(source(x, g_))] = 1;
            x = opposite(next(x, g_), g_);
          } while (x != start);
        }
        if ((r.collapses & 16383u) == 0) vis_.on_step("faces", std::min(faces0 - faces_, total - 1), total);
      }
      if (done == 0) {
        if (unlimited || !cut) return above ? Stop_reason::max_error : Stop_reason::no_collapse_left;
        unlimited = true; // the edges below the limit are all refused: try the rest
      } else {
        unlimited = false;
      }
    }
  }

  // Candidates of equal cost (sorted by edge index so far, which differs
  // between backends) in the order of their vertex-index pairs (see pair());
  // at cost 0 by length first.
  template <class It>
  void order_ties(It first, It last) {
    while (first != last) {
      It run = first + 1;
      while (run != last && (*run >> 32) == (*first >> 32)) ++run;
      if (run - first > 1) {
        // At cost 0 (see priority()) the shortest edge first, then by pair.
        const bool flat = (*first >> 32) == 0;
        ties_.clear();
        for (It x = first; x != run; ++x) {
          const auto k = static_cast<std::uint32_t>(*x);
          std::uint32_t length_bits = 0;
          if (flat) {
            const H h = halfedge(edge_of(k), g_);
            length_bits = std::bit_cast<std::uint32_t>(squared_length(vi(source(h, g_)), vi(target(h, g_))));
          }
          ties_.push_back({length_bits, pair(k), *x});
        }
        std::sort(ties_.begin(), ties_.end());
        for (std::size_t i = 0; i < ties_.size(); ++i) first[static_cast<std::ptrdiff_t>(i)] = std::get<2>(ties_[i]);
      }
      first = run;
    }
  }

  // Feature edges (interior edges only: borders follow .border) from
  // .feature_angle and .edge_is_constrained; what they make of each vertex.
  void init_features(std::size_t eb) {
    features_ = o_.feature_angle.has_value() || static_cast<bool>(o_.edge_is_constrained);
    if (!features_) return;
    feature_.assign(eb, 0);
    on_line_.assign(pos_.size(), 0);
    if (o_.feature_angle) {
      const double angle = std::clamp(*o_.feature_angle, 0.0, 180.0);
      const auto sharp = genmesh::sharp_edges(std::as_const(g_), angle);
      for (const E e : edges(g_))
        if (get(sharp, e)) feature_[ei(e)] = 1;
    }
    if (o_.edge_is_constrained)
      for (const E e : edges(g_))
        if (o_.edge_is_constrained(ei(e))) feature_[ei(e)] = 1;
    for (const E e : edges(g_)) {
      const H h = halfedge(e, g_);
      if (border(h) || border(opposite(h, g_))) feature_[ei(e)] = 0;
    }
    for (const V v : vertices(g_)) classify(v);
  }

  // A vertex with two feature edges, not on the border, moves along them; one
  // with one (a line's end), three or more (a corner), or any at the border
  // never moves. Locks are never lifted.
  void classify(V v) {
    const H start = halfedge(v, g_);
    if (start == boost::graph_traits<G>::null_halfedge()) return;
    int n = 0;
    bool on_border = false;
    H x = start;
    do {
      if (feature_[ei(edge(x, g_))]) ++n;
      if (border(x) || border(opposite(x, g_))) on_border = true;
      x = opposite(next(x, g_), g_);
    } while (x != start);
    const std::size_t i = vi(v);
    if (n > 0 && (n != 2 || on_border)) locked_[i] = 1;
    on_line_[i] = n == 2 && !locked_[i];
  }

  // The sorted vertex-index pair of edge k: what breaks ties of cost in the
  // queue (the same on every backend, unlike edge indices). Read from the
  // mesh when needed, not stored in the queue's entries (16 bytes instead of
  // 24): every queued edge whose ends a collapse changes is requeued after
  // it.
  std::uint64_t pair(std::size_t k) const {
    const H h = halfedge(edge_of(k), g_);
    std::uint64_t a = vi(source(h, g_)), b = vi(target(h, g_));
    sort_two(a, b);
    return (a << 32) | b;
  }

  // The squared length of the edge (a, b) as a float (a non-negative float's
  // bits order as integers), the same on every backend (from the points, the
  // ends in index order).
  float squared_length(std::size_t a, std::size_t b) const {
    sort_two(a, b);
    return static_cast<float>((pos_[b] - pos_[a]).squaredNorm());
  }

  // The queue's priority of an edge (a, b) of cost `cost`: the cost as a float
  // where that is positive (or NaN); where it is 0 (every cost of a flat
  // region: its plane quadrics vanish) a negative float that increases
  // strictly with the edge's squared length (as a float), so that such ties
  // go to the shortest edge first (the pair alone sent edge after edge into
  // one survivor: docs/simplification.md, "Flat regions"). The order is
  // kept: a positive float is above every negative one, and two positive
  // costs keep their floats; only costs whose floats tie at 0 (a double
  // below 2^-149 rounds to 0), which the pair alone ordered before, are now
  // ordered by length and then by the pair. A negative cost counts as 0, as
  // in Schedule::passes (no policy here gives one: each clamps at 0 or sums
  // squares).
  // The length's float bits u (0 to 0x7f800000) map to the negative float of
  // magnitude bits 0x7f7fffff − min(u, 0x7effffff): from −FLT_MAX (length 0)
  // to −FLT_MIN (a squared length of 2^126 or more), finite and normal (no
  // −0, which would tie with +0; no denormal, which a flush-to-zero mode
  // would read as 0).
  [[gnu::noinline]] float flat_priority(std::size_t a, std::size_t b) const {
    const std::uint32_t u = std::min(std::bit_cast<std::uint32_t>(squared_length(a, b)), 0x7effffffu);
    return std::bit_cast<float>(0x80000000u | (0x7f7fffffu - u));
  }
  float priority(double cost, std::size_t a, std::size_t b) const {
    const float f = static_cast<float>(cost);
    return f <= 0 ? flat_priority(a, b) : f;
  }
  float priority(double cost, H h) const {
    const float f = static_cast<float>(cost);
    return f <= 0 ? flat_priority(vi(source(h, g_)), vi(target(h, g_))) : f;
  }

  // The queue's order: by cost, ties by the vertex-index pair (cost 0: by
  // length first, see priority()).
  struct Order {
    static constexpr bool refines_less = true; // the pair only breaks ties (see Mutable_priority_queue)
    const Collapser* c;
    bool operator()(float a, std::size_t ka, float b, std::size_t kb) const {
      if (a < b) return true;
      if (b < a) return false;
      return ka != kb && c->pair(ka) < c->pair(kb);
    }
  };

  // Where a collapse may put its vertex (see evaluate).
  enum class Where { anywhere, at_a, at_b, on_segment, nowhere };

  // The constraints' say on the collapse of edge k with ends a < b: locked
  // ends stay; a vertex on a feature line moves only along it (it survives
  // a collapse across, staying put; a collapse along its line keeps the new
  // point on the old segment); two pinned ends across a line: refused.
  Where where(std::size_t k, std::size_t a, std::size_t b) const {
    if (!locks_) return Where::anywhere;
    if (locked_[a] && locked_[b]) return Where::nowhere;
    if (!features_) return locked_[a] ? Where::at_a : locked_[b] ? Where::at_b : Where::anywhere;
    if (feature_[k]) return locked_[a] ? Where::at_a : locked_[b] ? Where::at_b : Where::on_segment;
    const bool pa = locked_[a] || on_line_[a], pb = locked_[b] || on_line_[b];
    if (pa && pb) return Where::nowhere;
    return pa ? Where::at_a : pb ? Where::at_b : Where::anywhere;
  }

  // The placement of collapsing h's edge; false when it may not collapse at
  // all (see where(); a memoryless policy may refuse too). Independent of
  // h's direction: the ends are taken in index order.
  bool evaluate(H h, Placement& pl, [[maybe_unused]] Data* sum = nullptr) {
    std::size_t a = vi(source(h, g_)), b = vi(target(h, g_));
    sort_two(a, b);
    const Where w = where(ei(edge(h, g_)), a, b);
    if (w == Where::nowhere) return false;
    if constexpr (memoryless) {
      const Collapse_profile p = profile(h, a, b);
      auto at = [&](const Eigen::Vector3d& x) { return policy_.fixed(p, x); };
      pl = w == Where::at_a ? at(pos_[a]) : w == Where::at_b ? at(pos_[b])
           : w == Where::on_segment ? best_of_three(at, a, b) : policy_.place(p);
      return std::isfinite(pl.cost); // an infinite cost: the policy refuses for now
    } else {
      const Data s = data_sum(a, b);
      if (sum) *sum = s;
      if (w == Where::anywhere) {
        pl = policy_.place(s, pos_[a], pos_[b]);
        return true;
      }
      auto at = [&](const Eigen::Vector3d& x) { return simplification::fixed(policy_, s, pos_[a], pos_[b], x); };
      pl = w == Where::at_a ? at(pos_[a]) : w == Where::at_b ? at(pos_[b]) : best_of_three(at, a, b);
      return true;
    }
  }

  // The cheapest of a, b and their midpoint (ties in that order).
  template <class At>
  Placement best_of_three(const At& at, std::size_t a, std::size_t b) const {
    return simplification::best_of_ends_and_midpoint(at, pos_[a], pos_[b]);
  }

  // The profile of h's edge, ends a < b (vertex indices), in the canonical
  // order of Collapse_profile: the fan of a from the face left of b → a, then
  // the fan of b from the face left of a → b (rotation follows the faces'
  // orientation, the same on every backend), each element once. Valid until
  // the next call.
  Collapse_profile profile(H h, std::size_t a, std::size_t b) {
    tris_.clear();
    borders_.clear();
    link_.clear();
    if (++link_epoch_ == 0) { // the stamps wrapped
      std::fill(link_seen_.begin(), link_seen_.end(), 0u);
      link_epoch_ = 1;
    }
    const H ba = vi(target(h, g_)) == a ? h : opposite(h, g_);
    const bool borders = o_.border != Border_mode::free;
    auto add_border = [&](std::size_t s, std::size_t t) {
      for (const auto& e : border_keys_)
        if (e[0] == s && e[1] == t) return; // edge ab, seen from both ends
      border_keys_.push_back({static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(t)});
      borders_.push_back({pos_[s], pos_[t]});
    };
    border_keys_.clear();
    for (int side = 0; side < 2; ++side) {
      const H start = side == 0 ? ba : opposite(ba, g_);
      const std::size_t iv = side == 0 ? a : b;
      H x = start;
      do {
        // x: u → v.
        const std::size_t iu = vi(source(x, g_));
        if (iu != a && iu != b && link_seen_[iu] != link_epoch_) {
          link_seen_[iu] = link_epoch_;
          link_.push_back(pos_[iu]);
        }
        if (!border(x)) {
          // The face (v, w, u), from its lowest index; b's fan skips the
          // faces of the edge (they hold a).
          const std::size_t iw = vi(target(next(x, g_), g_));
          if (side == 0 || (iu != a && iw != a)) {
            if (iv < iw && iv < iu) tris_.push_back({pos_[iv], pos_[iw], pos_[iu]});
            else if (iw < iu) tris_.push_back({pos_[iw], pos_[iu], pos_[iv]});
            else tris_.push_back({pos_[iu], pos_[iv], pos_[iw]});
          }
          if (borders && border(opposite(x, g_))) add_border(iu, iv);
        } else if (borders) {
          add_border(iv, iu);
        }
        x = opposite(next(x, g_), g_);
      } while (x != start);
    }
    return {pos_[a], pos_[b], tris_, borders_, link_};
  }

  // ---- looking ahead ---------------------------------------------------------
  // The queue's top after a pop is nearly always the next edge popped (all
  // but 361 of 375k pops on the 832k armadillo → 10 %), and its collapse
  // starts by walking both fans of the edge, scattered in memory: those
  // misses were a quarter of the unguarded run (in fan_keeps_normals). So
  // ahead_begin names the top right after the pop, and each queue erase
  // before the collapse and each requeue after it walks both of its fans one
  // halfedge further (ahead_step): it reads what the last step asked for
  // and asks for the next halfedge's links (where the mesh can:
  // HasNativePrefetch) and the neighbour's point and data, overlapping those
  // misses with the queue's own. Hints and reads only, of a valid mesh
  // (before collapse_edge, and after it again from the start if the edge is
  // still queued, so that it lives): no effect on the result. Every backend
  // gains, the reads alone acting as prefetches (832k armadillo → 10 %,
  // unguarded: Halfedge_mesh 2.2 → 1.5 s, Surface_mesh 2.3 → 1.7 s,
  // Incidence_mesh 6.6 → 5.5 s; the steps before the collapse took
  // Surface_mesh, whose links cannot be hinted, from 2.07 to 1.88 s more).
  // Since session 12 two edges are walked, the top and the one that pops
  // after it (the smallest child of the root), so that a star's walk has two
  // collapses' time (one collapse's steps did not finish: the walk's own
  // reads stalled); each step also asks for its edge's queue position, and
  // for the last step's edge's queue entry. Schedule::passes walks the next
  // two candidates of its sorted list the same way (steps in the collapse's
  // marking of p's edges; unguarded 832k → 10 %: 1.92 → 1.42 s).
  struct Ahead {
    std::size_t edge = 0;
    H start[2] = {H(), H()}; // halfedge(edge) and its opposite: where the walks end
    H x[2] = {H(), H()};     // side 0: the halfedges into target(start[0]), side 1: into its source
    int left[2] = {0, 0}; // steps allowed (0: stopped)
    std::size_t last[2] = {0, 0}; // the edge of the last step's halfedge
  };
  // ahead_[0]: the queue's top; ahead_[1]: the edge that pops after it (its
  // walk goes on as ahead_[0]'s when it is the next top).
  void ahead_begin(std::size_t k, bool has_second, std::size_t second) {
    if (ahead_[1].edge == k && ahead_[1].start[0] != H()) {
      ahead_[0] = ahead_[1];
    } else {
      ahead_[0].edge = k;
      ahead_restart(ahead_[0]);
    }
    if (has_second) {
      ahead_[1].edge = second;
      ahead_restart(ahead_[1]);
    } else {
      ahead_[1].left[0] = ahead_[1].left[1] = 0;
    }
  }
  // After collapse_edge: the walks again from the start (their first steps
  // now hit the cache; the collapse may have changed the star), if the edge
  // lives; else none.
  void ahead_resume() {
    if (!prefetch_) return;
    for (Ahead& a : ahead_) {
      if (a.left[0] + a.left[1] == 0 && a.start[0] == H()) continue;
      if (passes_ ? ecost_[a.edge] != Cost_mark::dirty : queue_.contains(a.edge)) ahead_restart(a);
      else a.left[0] = a.left[1] = 0;
    }
  }
  void ahead_restart(Ahead& a) {
    const H h = halfedge(edge_of(a.edge), g_);
    genmesh::detail::prefetch_links(h, std::as_const(g_));
    a.start[0] = a.x[0] = h;
    a.start[1] = a.x[1] = opposite(h, g_);
    a.left[0] = a.left[1] = 32; // a bound for the odd vertex of high degree
  }
  void ahead_step() {
    if (!prefetch_) return;
    // One walk a call, in turn: the walks are chains of misses (each step
    // reads what the last one hinted), and stepping both at every call left
    // too little work between two steps of one walk for the hints to land
    // (832k guard=0: ~8 % of the time waited on a step's loads).
    step(ahead_[turn_]);
    turn_ ^= 1u;
  }
  void step(Ahead& a) {
    for (int s = 0; s < 2; ++s) {
      if (a.left[s] == 0) continue;
      --a.left[s];
      const H x = a.x[s];
      const V vu = source(x, g_);
      // The first step's u is an end of the edge: the collapse's fan walks
      // start at its halfedge(u) (a miss that stalled fan_keeps_normals).
      if (x == a.start[s]) {
        if constexpr (HasNativePrefetch<G>) genmesh::detail::prefetch_links(vu, std::as_const(g_));
        else sink_ = halfedge(vu, g_) == H(); // a read ahead, where no hint can be had
      }
      const std::size_t u = vi(vu);
      pos_.prefetch(u);
      if constexpr (!memoryless) genmesh::detail::prefetch_object(&data_[u]);
      // The edge's queue position, and the last step's edge's entry (its
      // position is in cache by now): the collapse erases or requeues them.
      const std::size_t k = ei(edge(x, g_));
      queue_.prefetch(k);
      if (x != a.start[s]) queue_.prefetch_entry(a.last[s]);
      a.last[s] = k;
      const H nx = opposite(next(x, g_), g_);
      genmesh::detail::prefetch_links(nx, std::as_const(g_));
      a.x[s] = nx;
      if (nx == a.start[s]) a.left[s] = 0;
    }
  }

  // The vertex that survives the collapse of h's edge to x: a locked end,
  // else the end nearer to x, else the lower index.
  bool target_survives(H h, const Eigen::Vector3d& x) const {
    const std::size_t p = vi(source(h, g_)), q = vi(target(h, g_));
    if (locks_ && locked_[p] != locked_[q]) return locked_[q] != 0;
    if (features_ && on_line_[p] != on_line_[q]) return on_line_[q] != 0;
    const double dp = (pos_[p] - x).squaredNorm(), dq = (pos_[q] - x).squaredNorm();
    if (dp != dq) return dq < dp;
    return q < p;
  }

  // The faces around v (not those holding `other`) keep their orientation
  // within the allowed angle and a non-zero area when v moves to x.
  bool fan_keeps_normals(V v, V other, const Eigen::Vector3d& x) const {
    const std::size_t iv = vi(v);
    // The options once, not at each face (read through o_, a reference, they
    // were loaded again after every store).
    const double cos2 = cos_max_ * cos_max_, max_aspect = o_.max_aspect_ratio, cos_min_angle = cos_min_angle_;
    const H start = halfedge(v, g_);
    H h = start;
    do {
      if (!border(h)) {
        // h: b → v, next(h): v → a; the face is (v, a, b).
        const H n = next(h, g_);
        const V a = target(n, g_), b = source(h, g_);
        if (a != other && b != other) {
          const std::size_t ia = vi(a), ib = vi(b);
          const Eigen::Vector3d n0 = genmesh::triangle_normal(iv, pos_[iv], ia, pos_[ia], ib, pos_[ib]);
          const Eigen::Vector3d n1 = genmesh::triangle_normal(iv, x, ia, pos_[ia], ib, pos_[ib]);
          const double l1 = n1.squaredNorm(), l0 = n0.squaredNorm();
          if (!(l1 > 0)) return false;
          if (l0 > 0) {
            const double d = n0.dot(n1);
            if (!(d > 0) || d * d < cos2 * l0 * l1) return false;
          }
          // Nor a sliver: |n1|² ≤ 1e-8 s², s = |x − a|² + |x − b|² (between
          // half and twice the longest edge's square m²: a face whose height
          // over its longest edge m is below 0.5e-4 m to 2e-4 m), unless the face
          // was one before. A tilted plane's costs are rounding noise, and its
          // arbitrary order made faces of aspect ratio 1e29
          // (docs/simplification.md, "Flat regions").
          if (const double s1 = (x - pos_[ia]).squaredNorm() + (x - pos_[ib]).squaredNorm(); l1 <= 1e-8 * s1 * s1) {
            const double s0 = (pos_[iv] - pos_[ia]).squaredNorm() + (pos_[iv] - pos_[ib]).squaredNorm();
            if (!(l0 <= 1e-8 * s0 * s0)) return false;
          }
          if (max_aspect > 0) {
            // No face above .max_aspect_ratio, unless it was as bad before.
            const double r1 = triangle_aspect_ratio(x, pos_[ia], pos_[ib]);
            if (r1 > max_aspect && r1 > triangle_aspect_ratio(pos_[iv], pos_[ia], pos_[ib])) return false;
          }
          if (cos_min_angle < 1) {
            // No corner below .min_angle, unless the face was as bad before.
            const double c1 = largest_corner_cosine(x, pos_[ia], pos_[ib]);
            if (c1 > cos_min_angle && c1 > largest_corner_cosine(pos_[iv], pos_[ia], pos_[ib])) return false;
          }
        }
      }
      h = opposite(next(h, g_), g_);
    } while (h != start);
    return true;
  }

  // ---- the self-intersection guard ----------------------------------------

  // Per new face: its normal (b − a) × (c − a) and the error scale of
  // off_plane's filter; the projection of in_projection_separated. All but
  // the normal are set by complete_plane, on the face's first test.
  struct Fresh_plane {
    Eigen::Vector3d n;
    double scale = 0;
    int axis = 0, sign = 0; // sign: of the projected orientation, 0 if uncertain (no filter)
    std::array<std::array<double, 2>, 3> q{}; // the corners projected
    bool complete = false;
  };

  // A halfedge of live face f (an index).
  H face_halfedge(std::size_t f) const {
    if constexpr (native_faces) return halfedge(genmesh_native_descriptor(face_index, g_, f), g_);
    else return face_h_[f];
  }

  // The corners of the face of h (h: a → b in face (a, b, c)), read from the
  // mesh: source, target, the target of next.
  std::array<std::uint32_t, 3> corners_of(H h) const {
    return {static_cast<std::uint32_t>(vi(source(h, g_))), static_cast<std::uint32_t>(vi(target(h, g_))),
            static_cast<std::uint32_t>(vi(target(next(h, g_), g_)))};
  }
  Mesh_triangle<std::uint32_t> face_triangle(const std::array<std::uint32_t, 3>& id) const {
    return {{pos_[id[0]], pos_[id[1]], pos_[id[2]]}, id};
  }

  // The mean length of the live edges (0 without any).
  double mean_edge_length() const {
    double sum = 0;
    std::size_t n = 0;
    for (const E e : edges(g_)) {
      const H h = halfedge(e, g_);
      sum += (pos_[vi(target(h, g_))] - pos_[vi(source(h, g_))]).norm();
      ++n;
    }
    return n > 0 ? sum / static_cast<double>(n) : 0.0;
  }

  // Every live face in the grid, with cells six times the mean edge length
  // (208k armadillo → 10%, guard time: 1x 2.9 s, 2x 2.2 s, 3x-4x 1.7 s, 8x
  // 1.9 s with the search of session 7; with the ring certificate, 832k → 10%:
  // 6x as fast as 4x and 3-4 MB less, 8x 1 MB less again but no faster).
  // The faces are by index; their corners are read from the mesh, once (the
  // mean comes from the edges: until session 10 a first pass over the faces'
  // corners gave it). The cell lists are cut to size after the build (1.3 MB
  // of 10.7 at 832k faces).
  void build_grid(std::size_t face_bound) {
    grid_.reset(1.0, 0); // frees the old cells first
    const double m = mean_edge_length();
    grid_.reset(m > 0 ? 6.0 * m : 1.0, face_bound);
    grid_.read_ahead(prefetch_);
    // In blocks: the faces' corners, then their points asked for, then the
    // boxes listed (face after face, the points' misses hardly overlapped:
    // 832k armadillo → 10 %, the builds' samples 1184 → 408).
    std::array<std::pair<std::uint32_t, std::array<std::uint32_t, 3>>, 64> block;
    std::size_t n = 0;
    auto list = [&] {
      for (std::size_t i = 0; i < n; ++i)
        for (const std::uint32_t c : block[i].second) prefetch(pos_.address(c));
      for (std::size_t i = 0; i < n; ++i) {
        const auto& v = block[i].second;
        grid_.insert(block[i].first, Box::of(pos_[v[0]], pos_[v[1]], pos_[v[2]]));
      }
      n = 0;
    };
    for (const F f : faces(g_)) {
      block[n++] = {static_cast<std::uint32_t>(fi(f)), corners_of(halfedge(f, g_))};
      if (n == block.size()) list();
    }
    list();
    grid_.shrink_to_fit();
    grid_faces_ = compact_faces_ = faces_;
  }

  // After a collapse onto q: q's faces go into the grid with their new
  // boxes; when the faces have quartered since the last build, rebuild with
  // cells fitting the grown faces; when they have halved since the last
  // build or compaction, drop the stale entries and cut the lists to size
  // (what bounds the grid's memory; until session 12 a rebuild at each
  // halving: 3-4% more instructions on the shark and the 208k armadillo).
  //
  // A face whose new box (in grid units) lies inside its box before the
  // collapse keeps its entries: each face is listed with a box holding its
  // own (true after an insert, and kept by this rule), and a query finds a
  // face wherever that box meets the query's, in one cell, as for an exact
  // listing; it may take one whose own box misses (as the bins may), which
  // the guard's tests drop. Face (s, q, w) had the corners s, w and p or q
  // before, so the test is whether q's new point lies in the box of s, w
  // and the old point (shark → 10 %: a third of the 32k listings, ~290
  // instructions each). Which old point: a face (a, q, w) or (s, q, b) was
  // q's, (b, q, w) or (s, q, a) was p's (a, b: the apexes of e's faces, top
  // and bottom; the one halfedge a → p, b → q was in the faces removed), and
  // the walk around q keeps the origin until the next such face; a border
  // gap is where the two fans meet when e was on the border (after the gap:
  // q's fan when the top face was missing, p's when the bottom one). Before
  // the first face that tells, the new point must lie in both boxes.
  void update_grid(V q) {
    const bool rebuild = 4 * faces_ < grid_faces_;
    const H start = halfedge(q, g_);
    if (rebuild) {
      if constexpr (!native_faces) { // the faces' old halfedges may be gone
        H x = start;
        do {
          if (!border(x)) face_h_[fi(face(x, g_))] = x;
          x = opposite(next(x, g_), g_);
        } while (x != start);
      }
      build_grid(grid_.face_bound());
      return;
    }
    using Point = Face_grid::Point;
    const std::uint32_t a = grid_apex_[0], b = grid_apex_[1];
    const Point uq = grid_.units(pos_[vi(q)]);
    // Where q's new point lies against a point on each axis (below, above:
    // Face_grid::sides); it lies in the box of s, w and an old point iff
    // no axis has it below all three or above all three. [2]: against both
    // old points (outside either box).
    const std::uint32_t p_sides = Face_grid::sides(uq, grid_was_[0]), q_sides = Face_grid::sides(uq, grid_was_[1]);
    const std::uint32_t was_sides[3] = {p_sides, q_sides, p_sides | q_sides};
    int from = 2; // 0: p's face, 1: q's, 2: not known
    const int after_gap = a == no_apex && b != no_apex ? 1 : b == no_apex && a != no_apex ? 0 : 2;
    std::uint32_t is = 0, s_sides = 0;
    Point us{};
    bool have_s = false; // is, us, s_sides: the last face's w (x's source)
    H x = start;
    do {
      const H n = next(x, g_);
      if (border(x)) {
        from = after_gap;
        have_s = false;
      } else {
        // x: s → q, n: q → w; the face is (s, q, w) (its corners from the
        // walk, not from halfedge(f): one miss less a face).
        const std::size_t sf = fi(face(x, g_));
        if constexpr (!native_faces) face_h_[sf] = x; // the face's old halfedge may be gone
        if (!have_s) {
          is = static_cast<std::uint32_t>(vi(source(x, g_)));
          us = grid_.units(pos_[is], uq, s_sides);
        }
        const std::uint32_t iw = static_cast<std::uint32_t>(vi(target(n, g_)));
        std::uint32_t w_sides;
        const Point uw = grid_.units(pos_[iw], uq, w_sides);
        if (is == a || iw == b) from = 1;
        else if (is == b || iw == a) from = 0;
        if ((s_sides & w_sides & was_sides[from]) != 0) {
          Point lo, hi;
          // Selects by masks: std::min and std::max compiled to branches
          // here, which go either way (shark → 10 %, guarded, Surface_mesh:
          // 29k of 0.99M mispredicted branches in callgrind's model).
          auto lesser = [](std::uint32_t x, std::uint32_t y) { return y ^ ((x ^ y) & -static_cast<std::uint32_t>(x < y)); };
          auto greater = [](std::uint32_t x, std::uint32_t y) { return y ^ ((x ^ y) & -static_cast<std::uint32_t>(x > y)); };
          for (int i = 0; i < 3; ++i) {
            lo[i] = lesser(lesser(us[i], uw[i]), uq[i]);
            hi[i] = greater(greater(us[i], uw[i]), uq[i]);
          }
          grid_.insert(static_cast<std::uint32_t>(sf), lo, hi);
        }
        is = iw;
        us = uw;
        s_sides = w_sides;
        have_s = true;
      }
      x = opposite(n, g_);
    } while (x != start);
    if (2 * faces_ < compact_faces_) {
      grid_.compact();
      compact_faces_ = faces_;
    }
  }

  // Does the collapse of edge(h) into target(h) at x keep a flat star flat
  // and unfolded, so that it cannot make an intersection? Exact; true when
  // every corner of the faces around p and q, and x, lie in one plane; every
  // old face (around p and q) and every new face (the fan around x) has the
  // same non-zero orientation in it; and, where p or q is on the border, the
  // border path through them (a → p → b, or a → p → q → b) and the new one
  // (a → x → b) are the same curve. Why that suffices, if
  // the mesh meets itself nowhere before the collapse (what the guard
  // keeps): the old faces and the new ones are 2-chains in the plane whose
  // boundaries are the same closed curve C (the link path, and the border
  // path from b to a), so at any point off their edges each covers it (all faces
  // positive) as often as C winds around it. The old faces do not overlap:
  // C is simple and winds once around its inside R, so the new faces cover
  // R once — they meet each other only along shared edges (their rays from
  // x are in strictly increasing angular order), and their interiors and
  // their edges at x miss the link. Another face u met the old faces only
  // in link vertices and link edges it holds (not on the border path but at
  // a, b); it meets R, the new faces' union as it was the old ones', in
  // those alone, and a new face holds a link vertex only as a corner and
  // meets the link only in its own link edge: u meets each new face at most
  // in what they share. (On an input that already meets itself this may
  // accept a collapse that the search below would refuse.) Flat regions are
  // where that search is dearest: its plane filter cannot decide, and the
  // faces' boxes overlap most.
  bool stays_in_flat_star(H h, const Eigen::Vector3d& x) const {
    const H hf = border(h) ? opposite(h, g_) : h; // a face of the edge
    const Eigen::Vector3d& a = pos_[vi(source(hf, g_))];
    const Eigen::Vector3d& b = pos_[vi(target(hf, g_))];
    const Eigen::Vector3d& c = pos_[vi(target(next(hf, g_), g_))];
    // The apex of the edge's other face first (the loop below would test it,
    // a corner around p and q): off the plane of (a, b, c) wherever the
    // surface is curved or the edge is a crease, and clearly so — the floating
    // filter decides it at once. Then x: on a crease the placement lies
    // near both planes, where the exact stage must decide (on the shark,
    // this order cut the function's instructions from 1.12M to 0.69M).
    const H ho = opposite(hf, g_);
    if (!border(ho) && detail::pred::orient3d(a, b, c, pos_[vi(target(next(ho, g_), g_))]) != 0) return false;
    if (detail::pred::orient3d(a, b, c, x) != 0) return false;
    const Eigen::Vector3d n = (b - a).cross(c - a).cwiseAbs();
    const int axis = n.x() >= n.y() && n.x() >= n.z() ? 0 : n.y() >= n.z() ? 1 : 2;
    auto orient = [axis](const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
      const auto pu = project2(u, axis), pv = project2(v, axis), pw = project2(w, axis);
      return detail::pred::orient2d(pu[0], pu[1], pv[0], pv[1], pw[0], pw[1]);
    };
    const int sign = orient(a, b, c);
    if (sign == 0) return false;
    const std::size_t ip = vi(source(h, g_)), iq = vi(target(h, g_));
    std::size_t ends[2] = {0, 0}; // the border path's ends a, b
    int n_ends = 0;
    bool on_border[2] = {false, false};
    for (int k = 0; k < 2; ++k) {
      const V v = k == 0 ? source(h, g_) : target(h, g_);
      const H start = halfedge(v, g_);
      H y = start;
      do {
        // y: s → v, next(y): v → w; the face is (s, v, w).
        const std::size_t is = vi(source(y, g_));
        if (detail::pred::orient3d(a, b, c, pos_[is]) != 0) return false;
        if (border(y) || border(opposite(y, g_))) {
          on_border[k] = true;
          if (is != ip && is != iq) {
            if (n_ends == 2) return false; // p and q on the border, edge pq inside
            ends[n_ends++] = is;
          }
        }
        if (!border(y)) {
          const std::size_t iw = vi(target(next(y, g_), g_));
          if (orient(pos_[is], pos_[vi(v)], pos_[iw]) != sign) return false;
          if (is != ip && is != iq && iw != ip && iw != iq && orient(pos_[is], x, pos_[iw]) != sign) return false;
        }
        y = opposite(next(y, g_), g_);
      } while (y != start);
    }
    if (!on_border[0] && !on_border[1]) return true;
    if (n_ends != 2) return false;
    // The border path a → (p, q) → b and the new one a → x → b: the same
    // curve, each with its straight-through corners dropped.
    std::array<std::array<double, 2>, 4> before, after;
    int nb = 0, na = 0;
    before[nb++] = project2(pos_[ends[0]], axis);
    if (on_border[0]) before[nb++] = project2(pos_[ip], axis);
    if (on_border[1]) before[nb++] = project2(pos_[iq], axis);
    before[nb++] = project2(pos_[ends[1]], axis);
    after[na++] = before[0];
    after[na++] = project2(x, axis);
    after[na++] = before[nb - 1];
    straighten(before, nb);
    straighten(after, na);
    return na == nb && std::equal(before.begin(), before.begin() + nb, after.begin());
  }

  // Drops from the polyline q[0, n) every inner corner that lies strictly
  // between its neighbours on their line (exact): the same curve.
  static void straighten(std::array<std::array<double, 2>, 4>& q, int& n) {
    for (int i = 1; i + 1 < n;) {
      const auto &u = q[i - 1], &v = q[i], &w = q[i + 1];
      const int k = u[0] != w[0] ? 0 : 1;
      if (u[k] != w[k] && detail::pred::orient2d(u[0], u[1], v[0], v[1], w[0], w[1]) == 0 &&
          std::min(u[k], w[k]) < v[k] && v[k] < std::max(u[k], w[k])) {
        std::copy(q.begin() + i + 1, q.begin() + n, q.begin() + i);
        --n;
        i = 1;
      } else {
        ++i;
      }
    }
  }

  // The ring certificate (exact). U: the new faces (fresh_, around x) and
  // every other live face with a corner in the link (ring_ past p and q),
  // as the mesh will be after the collapse. Does the projection along one
  // axis take U one-to-one into the plane, so that no two faces of U meet
  // beyond what they share? Then only the faces with no corner in ring_
  // need testing; they are left in near_. p, q and link vertices may be on
  // the border (`border_star`: p or q; their border edges are in ∂U, below).
  // U's faces other than the new ones are
  // all in near_: each holds a link vertex, a corner of a new face, so its
  // box meets the new faces' union, which the grid query never misses.
  // Checked, along an axis (its two others swapped where the new faces'
  // normal sum is negative along it; the axes are tried in turn, see below):
  // (1) every face of U has a strictly positive orientation in the
  // projection (orient2d, exact); and (S) ∂U, the 1-chain boundary of U,
  // projects onto a simple closed curve, shown one of two ways:
  // (A) (p and q off the border) every edge of ∂U has a strictly positive
  // orientation seen from x, and ∂U crosses the ray from x along the first
  // projected axis exactly once (upwards; a positive edge can cross it no
  // other way). ∂U is a sum of closed loops; along each, by the first, the
  // angle around x grows strictly, so each winds at least once around x; by
  // the second, the sum winds once: ∂U is one loop, and meets every ray
  // from x once — a simple closed curve. Cheap (one pass), but it cannot
  // hold where x is on ∂U, and fails where the outline turns away from x.
  // (A') where (A) does not hold: the same from another point c (the
  // argument holds for every point not on ∂U; see projects_one_to_one_along
  // for the points tried). Where every edge is positive seen from c, (A')
  // decides as (B) would: winding once, ∂U is simple and passes each vertex
  // once; winding more often, it is not.
  // (B) where neither decides: ∂U's edges form one cycle that passes
  // each vertex once (each the source of one edge and the target of one),
  // and its projection is a simple polygon (is_simple_polygon, exact: no
  // zero edge, adjacent edges meeting only in their corner, no others
  // meeting) — a simple closed curve.
  // Why that suffices: by (1), for a point y on no projected edge, the
  // number of faces of U whose projection holds y is the winding number of
  // ∂U's projection around y (each positive triangle adds one where it
  // covers y; their boundaries sum to ∂U): at least 0, and by (S) 0 or ±1
  // (Jordan) — so 0 or 1. So the projected faces of U have disjoint
  // interiors. Then an edge e of U with a corner in the link or x has its
  // faces in U (they hold that corner): two, on either side of it (both
  // positive, they run it in opposite directions), which cover a small disc
  // around a point inside e; or, a border edge, one, on the side where the
  // winding number is 1 — e is in ∂U, across which it drops to 0: nothing
  // of U lies on the other side near e. Either way any other face through
  // a point inside e would overlap them. Likewise the star of v, x or a
  // link vertex (all in U): its faces, positive, turn around v's point one
  // way; off the border by a whole number of turns, each direction near v
  // covered that often, at least once — once, by the winding number; on
  // the border from one of v's two border edges to the other (both in ∂U,
  // which passes v once, so near v the winding number is 1 on one side of
  // them and 0 on the other), covering the wedge between them once and
  // nothing outside it. Either way a face of U through v's point holds v (it
  // would cover a point near v twice, or where the winding number is 0). A
  // new face t has only such corners and edges, so the projection of any
  // other face u of U meets t's only on edges and corners they share; a
  // common point P of t and u projects onto one, Q, of a shared edge or
  // corner, which lies in t; t projects one-to-one (1), so P = Q: t and u
  // meet in what they share. Which edges form ∂U: an edge with a corner w
  // in the link or x has its faces in U (they hold w), so it cancels unless
  // it is a border edge, which is in ∂U as its face runs it — at a link
  // vertex w on the border (add_border_edges), and at x, whose border
  // edges end at such vertices (x's neighbours are the link; w has the
  // border edge). add_border_edges reads the mesh before the collapse: a
  // border edge w–p becomes w–x, run the same way (by the face across w–q
  // where w is the apex of the edge's face and the collapse merges w–p into
  // w–q), so it reads p as q; w–q stays; p–q goes (at no link vertex). A
  // topology the collapse cannot make (x on the border twice) gives no one
  // cycle, and (B) refuses it; the link condition has refused it before.
  // An edge ab with no such corner lies in a face (a, b, w) of U with w in
  // the link (a new face has its corners there), and cancels iff
  // its twin (b, a, z) has z in the link — then both appear: the boundary
  // edges are the edges b → a of the faces with one corner w in the link
  // and its two others not (nor p, q), minus the pairs that come both ways.
  bool ring_projects_one_to_one(const Eigen::Vector3d& x, bool border_star) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Fresh_plane& pl : fresh_plane_) sum += pl.n;
    const Eigen::Vector3d m = sum.cwiseAbs();
    const int first = m.x() >= m.y() && m.x() >= m.z() ? 0 : m.y() >= m.z() ? 1 : 2;
    // Marks: the link; cleared before returning. (near_corners_ holds no
    // face around p or q.)
    // (Through local pointers: a byte store may alias anything, and the
    // vectors' bounds were loaded again at every step.)
    std::uint8_t* const flags = vflags_.data();
    const std::uint32_t* const ring_end = ring_.data() + ring_.size();
    for (const std::uint32_t* r = ring_.data() + 2; r < ring_end; ++r) flags[*r] |= link;
    // U's faces, the foreign faces and ∂U are the same along every axis:
    // found once (until session 18 along each axis tried, (1)'s test of a
    // face and its classification in one pass).
    classify_near();
    add_border_edges();
    outline_state_ = outline_unknown;
    // Any axis along which (1) and (S) hold will do; the largest component of
    // the normal sum first, then the other two. (Shark → 10 %: (1) fails on
    // 100 axes of the 4,642 searches, 31 at a new face and 69 at another
    // face of U; (B) never fails where (1) holds; 12 searches with p and q
    // inside and 3 with either on the border fail on all three axes. Where
    // (A) fails, (B) on the same axis costs less than (A) on the next: (1)
    // along another axis is a pass over every face of U again.)
    bool ok = false;
    for (int i = 0; i < 3 && !ok; ++i) {
      const int axis = (first + i) % 3;
      if (m[axis] != 0) ok = projects_one_to_one_along(x, axis, sum[axis] < 0, border_star);
    }
    for (const std::uint32_t* r = ring_.data() + 2; r < ring_end; ++r) flags[*r] &= static_cast<std::uint8_t>(~link);
    return ok;
  }

  // Checks (1) and (S) of ring_projects_one_to_one along `axis`, the
  // projection's two coordinates swapped if `swap` (U's faces and ∂U
  // found): (S) by (A) where p and q are off the border, else or where (A)
  // finds an edge of ∂U not seen from x, by (B).
  bool projects_one_to_one_along(const Eigen::Vector3d& x, int axis, bool swap, bool border_star) {
    // The projection as the two coordinates it keeps (project2's, in its
    // order unless swapped), chosen once: each pair its own instance, whose
    // `at` reads the two coordinates of a vertex by index at fixed offsets.
    // (Until session 15 a point, through project2's switch and the swap at
    // every call: shark → 10 %, guarded, Halfedge_mesh: 2 % slower, 0.8 %
    // more instructions. Until session 18 the two coordinates' indices at
    // run time: on Surface_mesh, whose point converts to a Vector3d by
    // value, each vertex went through the stack to be indexed.)
    switch (axis * 2 + swap) {
      case 0: return projects_one_to_one_along<1, 2>(x, border_star);
      case 1: return projects_one_to_one_along<2, 1>(x, border_star);
      case 2: return projects_one_to_one_along<2, 0>(x, border_star);
      case 3: return projects_one_to_one_along<0, 2>(x, border_star);
      case 4: return projects_one_to_one_along<0, 1>(x, border_star);
      default: return projects_one_to_one_along<1, 0>(x, border_star);
    }
  }
  template <int k0, int k1>
  bool projects_one_to_one_along(const Eigen::Vector3d& x, bool border_star) {
    auto at = [this](std::size_t v) -> std::array<double, 2> {
      const auto& p = pos_[v];
      return {p[k0], p[k1]};
    };
    const std::array<double, 2> px{x[k0], x[k1]};
    // (1): the new faces (their points in fresh_: p[1] is x), then U's others.
    for (const auto& t : fresh_)
      if (!positive({t.p[0][k0], t.p[0][k1]}, px, {t.p[2][k0], t.p[2][k1]})) return false;
    for (std::size_t i = 0; i < nlinked_; ++i) {
      const std::array<std::uint32_t, 3>& v = near_corners_[linked_[i]];
      if (!positive(at(v[0]), at(v[1]), at(v[2]))) return false;
    }
    if (!border_star) {
      const int a = seen_once_from(at, px);
      if (a >= 0) {
        way_ = from_x;
        return a == 1;
      }
    }
    // (A) again from other points where x does not see all of ∂U or lies
    // on it (p or q on the border): the mean of ∂U's corners, then the
    // new faces' centroids, inside U near x. Any point will do (the
    // argument of (A) holds for every point), and each decides as (B)
    // would: a curve every edge of which turns positively around c, once
    // in all, is simple, and passes each vertex once; winding more often it
    // is not. (Shark and 208k armadillo → 10 %: (B) ran in 13 % of the
    // searches, 4k instructions for the simple polygon and 1.5k for the
    // cycle; these points decide 93 % and 81 % of them, a few hundred
    // instructions each.)
    if (nring_edges_ >= 3) {
      double sx = 0, sy = 0;
      for (std::size_t i = 0; i < nring_edges_; ++i) {
        const auto a = at(ring_edges_[i] >> 32);
        sx += a[0];
        sy += a[1];
      }
      const double inv = 1.0 / static_cast<double>(nring_edges_);
      int a = seen_once_from(at, {sx * inv, sy * inv});
      for (std::size_t i = 0; a < 0 && i < fresh_.size(); ++i) {
        const auto& t = fresh_[i];
        a = seen_once_from(at, {(t.p[0][k0] + t.p[1][k0] + t.p[2][k0]) / 3, (t.p[0][k1] + t.p[1][k1] + t.p[2][k1]) / 3});
      }
      if (a >= 0) {
        way_ = from_other;
        return a == 1;
      }
    }
    const bool ok = outline_is_simple(at);
    way_ = by_outline;
    return ok;
  }

  // (A) from c: 1 where every edge of ∂U (projected by `at`) is strictly
  // positive seen from c and crosses the ray from c along the first
  // coordinate once (upwards, the only way a positive edge can), so that ∂U
  // is a simple closed curve; 0 where every edge is positive but the count
  // is another (∂U winds around c that often: no simple curve); -1 where an
  // edge is not positive (undecided).
  template <class At>
  int seen_once_from(const At& at, const std::array<double, 2>& c) const {
    int crossings = 0;
    for (std::size_t i = 0; i < nring_edges_; ++i) {
      const std::uint64_t e = ring_edges_[i];
      const auto a = at(e >> 32), b = at(e & 0xffffffffu);
      if (!positive(c, a, b)) return -1;
      crossings += genmesh::detail::all_true(a[1] < c[1], c[1] <= b[1]);
    }
    return crossings == 1 ? 1 : 0;
  }

  // ∂U (ring_edges_) projected by `at` is a simple closed polygon: its
  // edges form one cycle through distinct vertices (outline_, found once
  // a search: the edges are the same along every axis), which
  // is_simple_polygon accepts.
  template <class At>
  bool outline_is_simple(const At& at) {
    if (outline_state_ == outline_unknown) outline_state_ = outline_cycle_of_ring_edges() ? outline_cycle : outline_none;
    if (outline_state_ != outline_cycle) return false;
    outline_pts_.resize(outline_.size());
    for (std::size_t i = 0; i < outline_.size(); ++i) outline_pts_[i] = at(outline_[i]);
    return is_simple_polygon(outline_pts_);
  }

  // Do ring_edges_ form one cycle, each vertex the source of one edge and
  // the target of one? Then outline_ holds the sources in the cycle's order.
  // The walk from the first edge's source takes the one edge out of each
  // vertex (two or none: no such cycle), and must first come back after
  // all n steps: then its n sources are distinct (a repeat would go round
  // without the start), so are its n edges — all of them, each vertex the
  // target of the next's. Each step scans every edge without a branch (n ≈
  // 14: until session 17's last step, sorted by source and searched by
  // lower_bound, whose branches cost more than the scans).
  bool outline_cycle_of_ring_edges() {
    outline_.clear();
    const std::size_t n = nring_edges_;
    if (n < 3) return false;
    const std::uint64_t* const edges = ring_edges_.data();
    const std::uint64_t start = edges[0] >> 32;
    std::uint64_t v = start;
    for (std::size_t k = 0; k < n; ++k) {
      std::uint64_t to = 0;
      std::size_t out = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t e = edges[i];
        const bool from_v = e >> 32 == v;
        out += from_v;
        to = from_v ? e & 0xffffffffu : to;
      }
      if (out != 1) return false;
      outline_.push_back(static_cast<std::uint32_t>(v));
      v = to;
      if (v == start) return k + 1 == n;
    }
    return false;
  }

  // The border edges at the link vertices on the border (border_link_: a
  // halfedge into each) into ∂U, each as its face runs it, once, as they
  // will be after the collapse: an edge to p as one to q.
  void add_border_edges() {
    const std::uint64_t ip = ring_[0], iq = ring_[1];
    for (const H into : border_link_) {
      const std::uint64_t w = vi(target(into, g_));
      H y = into;
      do {
        // y: s → w.
        const bool out = border(y), in = !out && border(opposite(y, g_));
        if (out || in) {
          std::uint64_t s = vi(source(y, g_));
          if (s == ip) s = iq;
          const std::uint64_t e = out ? w << 32 | s : s << 32 | w;
          const auto end = ring_edges_.begin() + static_cast<std::ptrdiff_t>(nring_edges_);
          if (std::find(ring_edges_.begin(), end, e) == end) {
            if (nring_edges_ == ring_edges_.size()) ring_edges_.resize(2 * nring_edges_ + 8);
            ring_edges_[nring_edges_++] = e;
          }
        }
        y = opposite(next(y, g_), g_);
      } while (y != into);
    }
  }

#ifdef GENMESH_SIMPLIFICATION_VERIFY_CERTIFICATES
  // For the tests: what ring_projects_one_to_one proved, checked by the
  // exact test — the new faces pairwise, and against every face the query
  // found but those around p or q (`found`, by their corners); counted in
  // verified_border_certificates where a link vertex is on the border, in
  // verified_border_star_certificates where p or q is, in
  // verified_outline_certificates where neither is and ∂U was shown a
  // simple polygon (way (B)), in verified_recentred_certificates where ∂U
  // was shown seen once from a point other than x (way (A')).
  void verify_certificate(const std::vector<std::array<std::uint32_t, 3>>& found, bool border_star) const {
    if (!border_link_.empty()) ++verified_border_certificates;
    if (border_star) ++verified_border_star_certificates;
    if (way_ == by_outline && !border_star) ++verified_outline_certificates;
    if (way_ == from_other) ++verified_recentred_certificates;
    for (std::size_t i = 0; i < fresh_.size(); ++i)
      for (std::size_t j = i + 1; j < fresh_.size(); ++j)
        if (faces_intersect(fresh_[i], fresh_[j]))
          throw std::logic_error("simplify: the ring certificate accepted two new faces that meet");
    for (const auto& v : found) {
      const auto u = face_triangle(v);
      bool in_ring = false;
      for (const std::uint32_t v : u.id) in_ring |= std::find(ring_.begin() + 2, ring_.end(), v) != ring_.end();
      if (!in_ring) continue; // tested as a foreign face
      for (const auto& t : fresh_)
        if (faces_intersect(t, u))
          throw std::logic_error("simplify: the ring certificate accepted a new face that meets a ring face");
    }
  }
#endif

  // Is orient2d(a, b, c) positive? (Exact: orient2d's filter decides almost
  // every call inline. Until session 15 sure_orient2d first, with twice the
  // bound and its exactness checks, then orient2d; shark → 10 %, guarded,
  // Halfedge_mesh: 3 % slower, 4.6 % more instructions.)
  [[gnu::always_inline]] static bool positive(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                              const std::array<double, 2>& c) {
    return detail::pred::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]) > 0;
  }

  // ring_projects_one_to_one's pass over near_corners_ (the faces the query
  // found, but p's and q's; the link marked): the faces with no corner in
  // the link to foreign_, the others (U's but the new ones) to linked_ (by
  // their index in near_corners_: until session 18's last step their
  // corners, two copies a face), and ∂U's edges to ring_edges_ (first
  // nforeign_, nlinked_, nring_edges_; written through pointers, each array
  // as long as near_corners_ at least: a push_back was a call once the
  // instances of projects_one_to_one_along had grown the function).
  void classify_near() {
    const std::size_t n = near_corners_.size();
    if (foreign_.size() < n) {
      foreign_.resize(2 * n);
      linked_.resize(2 * n);
    }
    if (ring_edges_.size() < n) ring_edges_.resize(2 * n);
    std::uint32_t* const foreign = foreign_.data();
    std::uint32_t* const linked = linked_.data();
    std::uint64_t* const edges = ring_edges_.data();
    std::size_t nforeign = 0, nlinked = 0, nedges = 0;
    // A bit per unordered vertex pair (a hash of the two), set for every
    // edge kept: a twin is searched for only where its bit is set. (Shark →
    // 10 %: 2 of 60k searches found one; each scanned all ~7 edges kept.)
    std::uint64_t kept = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::array<std::uint32_t, 3>& v = near_corners_[k];
      const std::uint8_t m0 = vflags_[v[0]], m1 = vflags_[v[1]], m2 = vflags_[v[2]];
      // (Shifts and masks, not `?:` and `% 3` as until session 16: shark →
      // 10 %, guarded, Surface_mesh: 0.3 % fewer instructions; selects such
      // as `w == 2 ? 0 : w + 1` became branches, 33k more mispredicted.)
      static_assert(link == 4);
      const unsigned l = (m0 & link) >> 2 | (m1 & link) >> 1 | (m2 & link);
      // Written to both, kept in one (the test goes either way).
      foreign[nforeign] = static_cast<std::uint32_t>(k);
      linked[nlinked] = static_cast<std::uint32_t>(k);
      nforeign += l == 0;
      nlinked += l != 0;
      // With one corner in the link, the edge opposite it, unless its twin
      // came already: written always, kept where `single`, without a branch
      // on it, which goes either way. (l | 8: an index for l = 0 too.)
      const bool single = (l != 0) & ((l & (l - 1)) == 0);
      const int w = std::countr_zero(l | 8u);
      const std::uint64_t from = v[(0x021u >> 4 * w) & 3], to = v[(0x102u >> 4 * w) & 3]; // (w + 1) % 3, (w + 2) % 3
      const std::uint64_t keep = std::uint64_t{0} - single; // all ones where single
      const std::uint64_t bit = (std::uint64_t{1} << (((from ^ to) * 0x9e3779b97f4a7c15u) >> 58)) & keep;
      if ((kept & bit) != 0) {
        const std::uint64_t twin = to << 32 | from;
        std::size_t i = 0;
        while (i < nedges && edges[i] != twin) ++i;
        if (i < nedges) {
          edges[i] = edges[--nedges];
          continue;
        }
      }
      kept |= bit;
      edges[nedges] = from << 32 | to;
      nedges += single;
    }
    nforeign_ = nforeign;
    nlinked_ = nlinked;
    nring_edges_ = nedges;
  }

  // Would the faces the collapse of edge(h) into target(h) at x makes meet
  // any other face, or each other, beyond what they share? (Exact.)
  //
  // GENMESH_SIMPLIFICATION_GUARD_FLOOR: a measurement hook, not an option
  // (docs/benchmarks.md, "what it costs at least", session 20). Defined to
  // N, the search stops after part N and allows the collapse; for timing
  // inputs on which the guard refuses nothing (then the same meshes).
  // 1: at once (the grid's upkeep alone), 2: after the walk (flat-star
  // test, star hidden and shown, new faces listed), 3: after the query
  // (new faces' normals and boxes, grid_.query), 4: after the near faces'
  // corners (points and flags asked for, as below), 5: after the ring
  // certificate (classify_near and the axes tried), 6: as 4, and every
  // near face's points read (what any exact test of them reads).
  bool stays_embedded(H h, const Eigen::Vector3d& x) {
#if GENMESH_DETAIL_GUARD_FLOOR == 1
    return true;
#endif
    if (stays_in_flat_star(h, x)) return true;
    const std::uint32_t ip = static_cast<std::uint32_t>(vi(source(h, g_))),
                        iq = static_cast<std::uint32_t>(vi(target(h, g_)));
    // The faces around p and q but the two of the edge: the new ones, their
    // corners from the walk (no slot read: p's and q's neighbourhoods are in
    // cache from the fold-over test).
    // The link (p and q's neighbours but p and q, each once) is gathered on
    // the way for ring_projects_one_to_one.
    fresh_.clear();
    border_link_.clear();
    // The link and the star in scratch written through a pointer (a
    // push_back a vertex and a face was a call: 83k a run on the shark);
    // ring_ takes the link at once. The faces around p and q are hidden from
    // the grid's query as they come (shown again after it).
    std::size_t nring = 2, nstar = 0;
    // Around q, the sources that came around p already are the apexes of
    // the edge's faces, and only they (the link condition holds).
    const std::uint32_t apex0 = border(h) ? ip : static_cast<std::uint32_t>(vi(target(next(h, g_), g_)));
    const std::uint32_t apex1 =
        border(opposite(h, g_)) ? ip : static_cast<std::uint32_t>(vi(target(next(opposite(h, g_), g_), g_)));
    if (link_buf_.size() < 64) link_buf_.resize(64);
    if (star_.size() < 64) star_.resize(64);
    link_buf_[0] = ip;
    link_buf_[1] = iq;
    bool border_star = false;
    bool around_q = false;
    for (const V v : {source(h, g_), target(h, g_)}) {
      const H start = halfedge(v, g_);
      H y = start;
      do {
        // y: s → v, next(y): v → w; the face is (s, v, w).
        const std::uint32_t is = static_cast<std::uint32_t>(vi(source(y, g_)));
        if (is != ip && is != iq && !(around_q && (is == apex0 || is == apex1))) {
          if (nring == link_buf_.size()) link_buf_.resize(2 * nring);
          link_buf_[nring++] = is;
          if (vflags_[is] & on_border) border_link_.push_back(opposite(y, g_));
        }
        const F fy = face(y, g_);
        if (fy != boost::graph_traits<G>::null_face()) {
          const std::uint32_t f = static_cast<std::uint32_t>(fi(fy));
          if (nstar == star_.size()) star_.resize(2 * nstar);
          star_[nstar++] = f;
          grid_.hide(f);
          const std::uint32_t iw = static_cast<std::uint32_t>(vi(target(next(y, g_), g_)));
          // (One branch, not four: the faces at p or q come at the walk's ends.)
          if ((is != ip) & (is != iq) & (iw != ip) & (iw != iq)) fresh_.push_back({{pos_[is], x, pos_[iw]}, {is, iq, iw}});
        } else {
          border_star = true;
        }
        if (border(opposite(y, g_))) border_star = true;
        y = opposite(next(y, g_), g_);
      } while (y != start);
      around_q = true;
    }
    ring_.assign(link_buf_.data(), link_buf_.data() + nring);
    auto show_star = [&] {
      for (std::size_t i = 0; i < nstar; ++i) grid_.show(star_[i]);
    };
#if GENMESH_DETAIL_GUARD_FLOOR == 2
    show_star();
    return true;
#endif
    if (fresh_.empty()) {
      show_star();
      return true;
    }
    // The new faces' normals (the ring certificate sums them); the rest of
    // their planes when a test first needs it: 43-48 % of the certified
    // searches test no face (shark, armadillo 208k and 832k → 10 %;
    // callgrind, Collapser::run: -1.2 % on the shark, -1.3 % on the 208k).
    fresh_plane_.resize(fresh_.size());
    for (std::size_t i = 0; i < fresh_.size(); ++i) {
      fresh_plane_[i].n = triangle_normal(fresh_[i].p[0], fresh_[i].p[1], fresh_[i].p[2]);
      fresh_plane_[i].complete = false;
    }
    // Against the live faces near the new ones (one query for the union of
    // their boxes; a candidate is tested exactly against each new face whose
    // box its box meets; faces around p or q are skipped: their corners say
    // so). The grid reports each face once.
    fresh_box_.resize(fresh_.size());
    Box all = Box::of(fresh_[0].p[0], fresh_[0].p[1], fresh_[0].p[2]);
    for (std::size_t i = 0; i < fresh_.size(); ++i) {
      const Box b = Box::of(fresh_[i].p[0], fresh_[i].p[1], fresh_[i].p[2]);
      fresh_box_[i] = b;
      all.lo = all.lo.cwiseMin(b.lo);
      all.hi = all.hi.cwiseMax(b.hi);
    }
    fresh_set_.assign(fresh_box_.data(), std::min(fresh_.size(), Box_set::capacity));
    // The grid's entries pick the faces whose box may meet the new ones'
    // (without reading them); the ring certificate (most searches) leaves
    // those with no corner in the ring; their points give the candidates.
    // Not the faces around p or q (star_, from the walk; the two of the
    // edge twice): the grid passes over them.
    near_.clear();
    grid_.query(all, near_);
    show_star();
#if GENMESH_DETAIL_GUARD_FLOOR == 3
    return true;
#endif
    // Their corners, read from the mesh. Where the mesh is large (prefetch_),
    // in stages, each a loop of independent reads (a face's halfedge, then
    // its corners, then their points and flags asked for): nearly every read
    // is a cache miss, one loop per face chains three dependent misses, and
    // the processor overlaps only a few faces' chains. Where it stays in
    // cache, in one loop without the hints (until session 16 staged there
    // too; shark → 10 %, guarded, Surface_mesh: 1 % fewer instructions).
    // (The grid lists live faces only. Until session 16 the query found the
    // faces around p or q too, a quarter of them on the shark, and they went
    // as their corners were read, without a branch; before session 15 by
    // their indices, with a 64-bit filter.)
    near_corners_.resize(near_.size());
    if (prefetch_) {
      if constexpr (!native_faces)
        for (const std::uint32_t f : near_) prefetch(&face_h_[f]);
      // (Written through a pointer: a push_back's capacity check a face.)
      if (near_h_.size() < near_.size()) near_h_.resize(2 * near_.size());
      H* const nh = near_h_.data();
      for (std::size_t i = 0; i < near_.size(); ++i) nh[i] = face_halfedge(near_[i]);
      for (std::size_t i = 0; i < near_.size(); ++i) near_corners_[i] = corners_of(nh[i]);
      for (const auto& v : near_corners_)
        for (const std::uint32_t c : v) {
          prefetch(pos_.address(c));
          prefetch(&vflags_[c]);
        }
    } else {
      for (std::size_t i = 0; i < near_.size(); ++i) near_corners_[i] = corners_of(face_halfedge(near_[i]));
    }
#if GENMESH_DETAIL_GUARD_FLOOR == 4
    return true;
#elif GENMESH_DETAIL_GUARD_FLOOR == 6
    for (const auto& v : near_corners_) floor_sum_ += (pos_[v[0]] + pos_[v[1]] + pos_[v[2]]).sum();
    return true;
#endif
    // With the ring certified, the new faces meet each other and every face
    // at a link vertex only in what they share: only the faces with no
    // corner in ring_ (p, q and the link) are left to test.
    const bool certified = ring_projects_one_to_one(x, border_star);
#if GENMESH_DETAIL_GUARD_FLOOR == 5
    return true;
#endif
    if (certified) {
#ifdef GENMESH_SIMPLIFICATION_VERIFY_CERTIFICATES
      verify_certificate(near_corners_, border_star);
#endif
    } else {
      for (std::size_t i = 0; i < fresh_.size(); ++i) complete_plane(i);
      for (std::size_t i = 0; i < fresh_.size(); ++i)
        for (std::size_t j = i + 1; j < fresh_.size(); ++j)
          if (!off_plane(i, fresh_[j]) && !off_plane(j, fresh_[i]) && !in_projection_separated(i, fresh_[j]) &&
              exact_test(fresh_[i], fresh_[j]))
            return false;
    }
    // The candidates: the faces left (not around p or q; their points were
    // asked for above) with the new faces their boxes meet (bit i: new face
    // i; from the 64th on always tested). Each is written, and kept where
    // its mask is not empty, without a branch on that test, which goes
    // either way, nor a test against the new faces' union first (until
    // session 17 a push_back after both: shark → 10 %, guarded, 1.4 % more
    // instructions now, 1 % faster). (Nor near_corners_.swap(foreign_) as
    // until session 17: near_corners_ then took foreign_'s smaller size, and
    // its resize above zero-filled the difference, out of line, each search.)
    // (The pool by index: foreign_, or every near face, listed there.)
    if (!certified) {
      for (std::size_t k = 0; k < near_corners_.size(); ++k) foreign_[k] = static_cast<std::uint32_t>(k);
      nforeign_ = near_corners_.size();
    }
    if (candidates_.size() < nforeign_) candidates_.resize(nforeign_);
    std::size_t ncand = 0;
    const bool always = fresh_.size() > Box_set::capacity; // new faces beyond the mask: tested below
    for (std::size_t k = 0; k < nforeign_; ++k) {
      const std::array<std::uint32_t, 3>& v = near_corners_[foreign_[k]];
      const std::uint64_t mask = fresh_set_.meets(Box::of(pos_[v[0]], pos_[v[1]], pos_[v[2]]));
      candidates_[ncand] = {v, mask};
      ncand += (mask != 0) | always;
    }
    const std::size_t nf = fresh_.size();
    for (std::size_t ci = 0; ci < ncand; ++ci) {
      const auto& [v, mask] = candidates_[ci];
      const Mesh_triangle<std::uint32_t> u = face_triangle(v);
      // u's own plane, for the new faces off_plane leaves undecided (where
      // the surface curves both ways, u's far corners straddle a new face's
      // plane while its corners lie on one side of u's): computed once, when
      // needed.
      Eigen::Vector3d un = Eigen::Vector3d::Zero(); // set with uscale (zeroed: -Wmaybe-uninitialized)
      double uscale = 0;
      // The new faces u's box meets, in order: the mask's set bits, then
      // those from the 64th on by their boxes. (Until session 17 a test of
      // each bit in turn, a branch that went either way: shark → 10 %,
      // guarded, Surface_mesh: 2.3 % faster, 0.6 % fewer instructions.)
      std::uint64_t bits = mask;
      for (std::size_t i = 0; i < nf; ++i) {
        if (i < Box_set::capacity) {
          if (bits == 0) {
            i = Box_set::capacity - 1; // on to the 64th, if any
            continue;
          }
          i = static_cast<std::size_t>(std::countr_zero(bits));
          bits &= bits - 1;
        } else if (!Box::of(u.p[0], u.p[1], u.p[2]).overlaps(fresh_box_[i])) {
          continue;
        }
        complete_plane(i);
        if (off_plane(i, u)) continue;
        if (uscale == 0) {
          un = triangle_normal(u.p[0], u.p[1], u.p[2]);
          uscale = plane_scale(u);
        }
        if (!corners_off_plane(un, uscale, u, fresh_[i]) && !in_projection_separated(i, u) &&
            exact_test(fresh_[i], u))
          return false;
      }
    }
    return true;
  }

  // faces_intersect, counted.
  bool exact_test(const Mesh_triangle<std::uint32_t>& t, const Mesh_triangle<std::uint32_t>& u) {
    ++exact_tests_;
    return faces_intersect(t, u);
  }

  // New face i's plane (its normal set) completed for the filters below:
  // the error scale and the projection, once.
  void complete_plane(std::size_t i) {
    Fresh_plane& pl = fresh_plane_[i];
    if (pl.complete) return;
    pl.complete = true;
    const Mesh_triangle<std::uint32_t>& t = fresh_[i];
    pl.scale = plane_scale(t);
    // The axis t projects along: its normal's largest component, if the
    // projected triangle's orientation is certain (it is that component,
    // computed as orient2d computes it, so Shewchuk's bound applies).
    const Eigen::Vector3d a = pl.n.cwiseAbs();
    pl.axis = a.x() >= a.y() && a.x() >= a.z() ? 0 : a.y() >= a.z() ? 1 : 2;
    pl.sign = orientation(t, pl.axis);
    for (int c = 0; c < 3; ++c) pl.q[c] = project2(t.p[c], pl.axis);
  }

  // A point projected along axis (the axes of detail::tri::project: the
  // result's orientation is the sign of the normal's component).
  static std::array<double, 2> project2(const Eigen::Vector3d& p, int axis) {
    switch (axis) {
      case 0: return {p.y(), p.z()};
      case 1: return {p.z(), p.x()};
      default: return {p.x(), p.y()};
    }
  }

  static int orientation(const Mesh_triangle<std::uint32_t>& t, int axis) {
    const int s = sure_orient2d(project2(t.p[0], axis), project2(t.p[1], axis), project2(t.p[2], axis));
    return s == unsure ? 0 : s;
  }

  // Projected along new face t's axis (one-to-one on t's plane), is there an
  // edge line ab of t or of u with its own triangle on one side and the
  // other triangle on the other, touching the line only in shared corners
  // or beyond the segment ab (see splits)? Then t ∩ u projects into the
  // projection of what they share, and t, projected one-to-one, meets u only
  // there (a shared vertex or edge): what faces_intersect calls no
  // intersection. Exactly coplanar input (a flat region, where off_plane
  // can never decide) is the case it is for: each line costs three
  // floating orientations instead of the exact 2D tests of all three
  // projections.
  bool in_projection_separated(std::size_t i, const Mesh_triangle<std::uint32_t>& u) const {
    const Fresh_plane& pl = fresh_plane_[i];
    if (pl.sign == 0) return false;
    const auto& t = fresh_[i];
    std::array<std::array<double, 2>, 3> uq;
    for (int c = 0; c < 3; ++c) uq[c] = project2(u.p[c], pl.axis);
    for (int j = 0; j < 3; ++j) {
      const int k = (j + 1) % 3, l = (j + 2) % 3;
      if (splits(uq, u.id, pl.q[j], pl.q[k], t.id[j], t.id[k], t.id[l], -pl.sign)) return true;
    }
    const int su = sure_orient2d(uq[0], uq[1], uq[2]);
    if (su == 0 || su == unsure) return false;
    for (int j = 0; j < 3; ++j) {
      const int k = (j + 1) % 3, l = (j + 2) % 3;
      if (splits(pl.q, t.id, uq[j], uq[k], u.id[j], u.id[k], u.id[l], -su)) return true;
    }
    return false;
  }

  // Does the line a → b (the edge ia → ib of a triangle whose third corner
  // `apex` lies on side −side) keep the triangle q on side `side`, but for
  // corners on the line that are shared (ia, ib) or lie beyond the segment
  // ab — all on one end, and beyond that end only if it is not shared —, so
  // that the two triangles' common points on the line are shared corners?
  static bool splits(const std::array<std::array<double, 2>, 3>& q, const std::array<std::uint32_t, 3>& qid,
                     const std::array<double, 2>& a, const std::array<double, 2>& b, std::uint32_t ia,
                     std::uint32_t ib, std::uint32_t apex, int side) {
    // Positions along the line by the coordinate in which a and b differ
    // (exact comparisons of exactly collinear points).
    const int k = a[0] != b[0] ? 0 : 1;
    const bool up = b[k] > a[k];
    bool has_a = false, has_b = false;
    int end = 0; // the end (−1: a's, +1: b's) the collinear corners lie beyond
    for (int c = 0; c < 3; ++c) {
      if (qid[c] == ia) { has_a = true; continue; }
      if (qid[c] == ib) { has_b = true; continue; }
      if (qid[c] == apex) return false;
      const int o = sure_orient2d(a, b, q[c]);
      if (o == side) continue;
      if (o != 0) return false;
      const double x = q[c][k];
      const int e = (up ? x < a[k] : x > a[k]) ? -1 : (up ? x > b[k] : x < b[k]) ? 1 : 0;
      if (e == 0 || (end != 0 && e != end)) return false;
      end = e;
    }
    return end == 0 || (end < 0 ? !has_b : !has_a);
  }

  // Are the corners of u that new face i does not share all strictly on one
  // side of its plane? Then they meet at most in what they share. A floating
  // filter, certain beyond its error bound (about 8ε times the permanent of
  // the 3×3 determinant, taken 20 times larger); faces_intersect decides
  // whatever it does not.
  bool off_plane(std::size_t i, const Mesh_triangle<std::uint32_t>& u) const {
    return corners_off_plane(fresh_plane_[i].n, fresh_plane_[i].scale, fresh_[i], u);
  }

  // The same for the corners of u that t does not share and t's plane
  // with normal n (triangle_normal of t) and filter scale `scale` (see
  // plane_scale).
  static bool corners_off_plane(const Eigen::Vector3d& n, double scale, const Mesh_triangle<std::uint32_t>& t,
                                const Mesh_triangle<std::uint32_t>& u) {
    int side = 0;
    for (int c = 0; c < 3; ++c) {
      // (`|` and a difference of comparisons, not `||` and `?:` as until
      // session 16: branches that go either way. Shark → 10 %, guarded,
      // Surface_mesh: 36k of 1.04M mispredicted branches fewer (callgrind
      // --branch-sim), 0.9 % more instructions, 3 % faster (pair ratio
      // 0.970, 15 rounds); either change alone no faster in the model.)
      if (genmesh::detail::any_true(u.id[c] == t.id[0], u.id[c] == t.id[1], u.id[c] == t.id[2])) continue;
      const Eigen::Vector3d d = u.p[c] - t.p[0];
      const double s = n.dot(d), bound = scale * d.cwiseAbs().maxCoeff();
      const int sc = static_cast<int>(s > bound) - static_cast<int>(s < -bound);
      if (sc == 0 || (side != 0 && sc != side)) return false;
      side = sc;
    }
    return side != 0;
  }

  // off_plane's error scale for triangle t (about 8ε times the permanent of
  // the 3×3 determinant, taken 20 times larger; infinite where the bound
  // itself could underflow: no filtering).
  static double plane_scale(const Mesh_triangle<std::uint32_t>& t) {
    const double scale = 1e-13 * (t.p[1] - t.p[0]).cwiseAbs().maxCoeff() * (t.p[2] - t.p[0]).cwiseAbs().maxCoeff();
    return scale > 1e-250 ? scale : std::numeric_limits<double>::infinity();
  }

  // The cosine of the triangle's smallest angle.
  static double largest_corner_cosine(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    auto cosine = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
      const double l = std::sqrt(u.squaredNorm() * v.squaredNorm());
      return l > 0 ? u.dot(v) / l : 1.0;
    };
    return std::max({cosine(b - a, c - a), cosine(c - b, a - b), cosine(a - c, b - c)});
  }

  // Requeues the edge of h (any of its two halfedges) with a fresh cost.
  void requeue(E e) {
    if (passes_) return; // the next pass computes every cost again
    ahead_step();
    const std::size_t k = ei(e);
    if constexpr (memoryless) {
      if (stamp_[k] == epoch_) return; // already requeued after this collapse
      stamp_[k] = epoch_;
    }
    refused_[k] = 0;
    const H h = halfedge(e, g_);
    Placement pl;
    if (evaluate(h, pl)) queue_.update(k, priority(pl.cost, h));
    else queue_.erase(k);
  }

  bool collapse(std::size_t k) {
    const E e0 = edge_of(k);
    H h = halfedge(e0, g_);
    Placement pl;
    // The survivor's data: the ends' data merged, as evaluate merges them
    // (merge is commutative bit for bit), before the collapse removes p and
    // moves q (a stored quadric is relative to its vertex's point).
    [[maybe_unused]] Data merged_data{};
    if (!evaluate(h, pl, &merged_data)) return false; // never queued so
    last_cost_ = pl.cost;
    if (std::sqrt(pl.cost) > max_error_) {
      over_error_ = true;
      return false;
    }
    if (!target_survives(h, pl.position)) h = opposite(h, g_);
    // collapse_edge(edge(h)) keeps target(h) (edge descriptors remember
    // their halfedge on every backend).
    const E e = edge(h, g_);
    const H oh = opposite(h, g_);
    const V p = source(h, g_), q = target(h, g_);
    if (!allowed(h, pl.position)) {
      refused_[k] = 1;
      hint_[vi(p)] = hint_[vi(q)] = 1;
      return false;
    }
    const bool top = !border(h), bottom = !border(oh);
    last_survivor_ = q;
    if (passes_) {
      // The edges of e's faces and of p go or change ends: not candidates
      // for the rest of this pass (their indices may not stay edges).
      for (const H side : {h, oh}) {
        if (border(side)) continue;
        ecost_[ei(edge(next(side, g_), g_))] = Cost_mark::dirty;
        ecost_[ei(edge(prev(side, g_), g_))] = Cost_mark::dirty;
      }
      const H start = halfedge(p, g_);
      H x = start;
      do {
        ecost_[ei(edge(x, g_))] = Cost_mark::dirty;
        ahead_step();
        x = opposite(next(x, g_), g_);
      } while (x != start);
    } else {
      if (top) queue_.erase(ei(edge(next(h, g_), g_)));
      if (bottom) queue_.erase(ei(edge(prev(oh, g_), g_)));
      // p's edges (with those of e's faces at p) leave the queue before the
      // collapse changes their vertex pairs, which order ties (see pair());
      // as q's edges they are queued again after it.
      const H start = halfedge(p, g_);
      H x = start;
      do {
        queue_.erase(ei(edge(x, g_)));
        ahead_step();
        x = opposite(next(x, g_), g_);
      } while (x != start);
    }
    const std::size_t ip = vi(p), iq = vi(q);
    // The two edges (p, apex), (q, apex) of each face of e become one: a
    // feature if either was.
    V apex[2];
    std::uint8_t merged[2] = {0, 0};
    int apexes = 0;
    if (features_) {
      if (top) {
        apex[apexes] = target(next(h, g_), g_);
        merged[apexes++] = feature_[ei(edge(next(h, g_), g_))] | feature_[ei(edge(prev(h, g_), g_))];
      }
      if (bottom) {
        apex[apexes] = target(next(oh, g_), g_);
        merged[apexes++] = feature_[ei(edge(next(oh, g_), g_))] | feature_[ei(edge(prev(oh, g_), g_))];
      }
    }
    if (o_.prevent_self_intersections) {
      vflags_[iq] |= vflags_[ip]; // on_border: no other vertex joins or leaves the border
      // e's faces leave the grid; update_grid is told the ends' old points
      // (grid units) and the apexes (see there).
      for (int s = 0; s < 2; ++s) {
        const H side = s == 0 ? h : oh;
        grid_apex_[s] = no_apex;
        if (border(side)) continue;
        grid_.remove(static_cast<std::uint32_t>(fi(face(side, g_))));
        grid_apex_[s] = static_cast<std::uint32_t>(vi(target(next(side, g_), g_)));
      }
      grid_was_[0] = grid_.units(pos_[ip]);
      grid_was_[1] = grid_.units(pos_[iq]);
    }
    vis_.on_collapse_placement(h, std::as_const(pl.position), pl.cost, std::as_const(g_));
    Point_writer writer{{}, this, pl.position};
    // allowed() has tested can_collapse_edge: not again.
    if (!genmesh::detail::lo::collapse_tested_edge(e, g_, writer)) return false; // never happens
    ahead_resume();
    pos_.set(iq, pl.position); // the mesh has it (Point_writer); a private copy follows
    if constexpr (!memoryless) {
      set_data(iq, merged_data); // relative to the new point
      if constexpr (requires { policy_.collapsed(iq, merged_data, pl.position); })
        policy_.collapsed(iq, merged_data, pl.position); // the survivor's attribute values
    }
    faces_ -= static_cast<std::size_t>(top) + static_cast<std::size_t>(bottom);
    if constexpr (memoryless) ++epoch_;
    if (apexes > 0) merge_features(q, apex, merged, apexes);
    if (o_.prevent_self_intersections) update_grid(q);
    if (passes_) return true; // no queue to update
    if constexpr (memoryless) {
      // The profile of every edge at a neighbour of q holds a face at q.
      const H start = halfedge(q, g_);
      H x = start;
      do {
        const V n = source(x, g_);
        const H s2 = halfedge(n, g_);
        H y = s2;
        do {
          requeue(edge(y, g_));
          y = opposite(next(y, g_), g_);
        } while (y != s2);
        x = opposite(next(x, g_), g_);
      } while (x != start);
      return true;
    }
    // Every edge of the survivor changes cost; the refused edges of its
    // neighbours may pass their fold-over test now.
    const H start = halfedge(q, g_);
    H x = start;
    // The queue entries and neighbours' data the requeue reads are scattered:
    // ask for all of them first, so that their misses overlap.
    around_.clear();
    do {
      around_.push_back(x);
      if (prefetch_) {
        queue_.prefetch(ei(edge(x, g_)));
        genmesh::detail::prefetch_object(&data_[vi(source(x, g_))]);
      }
      x = opposite(next(x, g_), g_);
    } while (x != start);
    if (prefetch_)
      for (const H y : around_) queue_.prefetch_entry(ei(edge(y, g_)));
#if defined(__SSE2__)
    if constexpr (two_at_once) {
      if (!locks_) {
        // q's edges two at a time: q's data made absolute once, its
        // neighbours' two by two (+ is commutative bit for bit).
        const Quadric_lanes at_q = Quadric_lanes::both(stored_absolute(iq));
        std::size_t i = 0;
        for (; i + 1 < around_.size(); i += 2) {
          std::size_t k[2], n[2];
          for (int j = 0; j < 2; ++j) {
            ahead_step();
            const H x = around_[i + static_cast<std::size_t>(j)];
            k[j] = ei(edge(x, g_));
            n[j] = vi(source(x, g_));
            refused_[k[j]] = 0;
          }
          const Quadric_lanes sum =
              Relative_quadric::absolute_lanes(data_[n[0]], pos_[n[0]], data_[n[1]], pos_[n[1]]) + at_q;
          double cost[2];
          std::size_t a0 = iq, b0 = n[0], a1 = iq, b1 = n[1];
          sort_two(a0, b0);
          sort_two(a1, b1);
          costs_two(sum, a0, b0, a1, b1, cost);
          queue_.update(k[0], priority(cost[0], a0, b0));
          queue_.update(k[1], priority(cost[1], a1, b1));
        }
        if (i < around_.size()) requeue(edge(around_[i], g_));
      }
    }
#endif
    for (const H x : around_) {
      if (!two_at_once || locks_) requeue(edge(x, g_));
      const V n = source(x, g_);
      if (hint_[vi(n)]) {
        hint_[vi(n)] = 0;
        const H s2 = halfedge(n, g_);
        H y = s2;
        do {
          const E ey = edge(y, g_);
          if (refused_[ei(ey)]) requeue(ey);
          y = opposite(next(y, g_), g_);
        } while (y != s2);
      }
    }
    hint_[iq] = 0;
    return true;
  }

  // After a collapse onto q: the merged edges (q, apex) take their flags;
  // q and the apexes are classified again, and the edges of an apex whose
  // class changed are requeued.
  void merge_features(V q, const V* apex, const std::uint8_t* merged, int apexes) {
    const H start = halfedge(q, g_);
    H x = start;
    do {
      for (int i = 0; i < apexes; ++i)
        if (source(x, g_) == apex[i]) feature_[ei(edge(x, g_))] = merged[i];
      x = opposite(next(x, g_), g_);
    } while (x != start);
    classify(q);
    for (int i = 0; i < apexes; ++i) {
      const std::size_t k = vi(apex[i]);
      const std::uint8_t before = static_cast<std::uint8_t>(locked_[k] * 2 + on_line_[k]);
      classify(apex[i]);
      if (before == locked_[k] * 2 + on_line_[k]) continue;
      const H s2 = halfedge(apex[i], g_);
      H y = s2;
      do {
        requeue(edge(y, g_));
        y = opposite(next(y, g_), g_);
      } while (y != s2);
    }
  }

  // The constraints' tests of collapsing edge(h) into target(h) at x, the
  // cheapest first: no face turns too far (fold-over, .min_angle,
  // .max_aspect_ratio), .max_valence, the link condition, the
  // self-intersection guard.
  bool allowed(H h, const Eigen::Vector3d& x) {
    const V p = source(h, g_), q = target(h, g_);
    if (!fan_keeps_normals(p, q, x)) return false;
    if (!fan_keeps_normals(q, p, x)) return false;
    if (o_.max_valence > 0 && valence_after(h) > o_.max_valence) return false;
    if (!genmesh::can_collapse_edge(edge(h, g_), std::as_const(g_))) return false;
    return !o_.prevent_self_intersections || stays_embedded(h, x);
  }

  // Forwards collapse_edge's hooks to the user's visitor, writing the
  // survivor's new point first (so that the mesh's points are current in
  // every hook: before_collapse sees the old ones, on_collapse the new).
  struct Point_writer : Mutation_visitor {
    Collapser* c;
    const Eigen::Vector3d& position;
    void before_collapse(const H& h, const G& g) { c->vis_.before_collapse(h, g); }
    void on_collapse(const V& v, const G& g) {
      put(get(vertex_point, c->g_), v, from_eigen<point_t<G>>(position));
      c->vis_.on_collapse(v, g);
    }
  };

  // The valence of the survivor of collapsing edge(h): both ends' neighbours
  // but the ends, the apexes counted once.
  std::size_t valence_after(H h) const {
    const std::size_t faces = static_cast<std::size_t>(!border(h)) + static_cast<std::size_t>(!border(opposite(h, g_)));
    return static_cast<std::size_t>(degree(source(h, g_), g_) + degree(target(h, g_), g_)) - 2 - faces;
  }


  G& g_;
  const Options& o_;
  Policy policy_;
  Visitor& vis_;
  decltype(get(vertex_index, std::declval<const G&>())) vindex_;
  decltype(get(edge_index, std::declval<const G&>())) eindex_;
  std::size_t faces_ = 0;
  double cos_max_ = 0.5;
  double cos_min_angle_ = 1.0; // cos(.min_angle); 1: no limit
  // The points by vertex index: the mesh's own array, or a copy in double
  // where the mesh has none (genmesh::detail::Point_reader).
  genmesh::detail::Point_reader<G> pos_;
  genmesh::detail::huge_page_vector<Stored> data_; // per vertex; big ones on huge pages (memory/huge_pages.h)
  // Schedule::passes: per pass, the candidate edges (float cost bits « 32 |
  // edge index, ties then ordered by vertex-index pair) and the vertices a
  // collapse of the pass touched.
  bool passes_ = false;
  std::vector<std::uint64_t> cand_;
  std::vector<std::uint32_t> high_, low_; // per pass: candidates by the top bits of their cost, then by the others
  // (at cost 0 the squared length's float bits, else 0; vertex-index pair; candidate)
  std::vector<std::tuple<std::uint32_t, std::uint64_t, std::uint64_t>> ties_;
  // Per edge, its cost at the last pass that computed it (kept while no
  // collapse touches its ends), or a mark.
  struct Cost_mark {
    static constexpr float none = -1.0f;  // the constraints refuse it
    static constexpr float above = -2.0f; // beyond .max_error
    static constexpr float dirty = -3.0f; // to compute (in a pass: gone or changed, skip)
  };
  genmesh::detail::huge_page_vector<float> ecost_;
  std::vector<std::uint8_t> touched_;
  double last_cost_ = 0; // of the last collapse() that got as far as the placement
  // The queue's error bound (a distance), and whether collapse() stopped at it.
  double max_error_ = std::numeric_limits<double>::infinity();
  bool over_error_ = false;
  V last_survivor_{};    // its survivor, once it collapsed
  // Per vertex: never moves nor disappears (empty unless locks_: .is_locked,
  // Border_mode::lock or feature lines).
  bool locks_ = false;
  std::vector<std::uint8_t> locked_;
  // Per vertex, "has a refused edge"; per edge, "refused". Bits (Boost's
  // dynamic_bitset): 1.4 MB less than bytes at 832k faces.
  using Bits = boost::dynamic_bitset<std::uint64_t>;
  Bits hint_, refused_;
  // Feature lines: per edge, is it one; per vertex, does it move along one.
  bool features_ = false;
  // The self-intersection guard: the grid, which lists each live face (by
  // index) with its exact box; the ring certificate and the candidates'
  // tests read the corners of the faces it returns from the mesh. Where the
  // mesh cannot make a face descriptor from its index (native_faces), face_h_
  // holds a halfedge of each face
  // (update_grid resets it for every face a collapse changes: the collapse
  // may remove the one it had). Until session 10 a 12-byte slot per face
  // held the corners (10 MB at 832k faces), for one read a face instead of
  // the mesh's few.
  static constexpr bool native_faces = HasNativeDescriptorOfIndex<G, face_index_t>;
  genmesh::detail::huge_page_vector<H> face_h_;
  std::vector<std::array<std::uint32_t, 3>> near_corners_; // near_'s faces not around p or q (corners)
  std::vector<Mesh_triangle<std::uint32_t>> fresh_;
  std::vector<std::uint32_t> ring_;   // p, q, then the link vertices (indices)
  std::vector<H> border_link_;        // a halfedge into each link vertex on the border
  std::vector<std::uint32_t> foreign_; // near faces with no corner in ring_ (indices into near_corners_), the first nforeign_
  std::vector<std::uint32_t> linked_;  // near faces with a corner in the link (indices into near_corners_), the first nlinked_
  std::size_t nforeign_ = 0, nlinked_ = 0;
  // Per vertex: has a border edge; for ring_projects_one_to_one, is p or q,
  // is in the link.
  static constexpr std::uint8_t on_border = 1, link = 4;
  std::vector<std::uint8_t> vflags_;
  std::vector<std::uint64_t> ring_edges_; // ∂U (see ring_projects_one_to_one), from << 32 | to; the first nring_edges_
  std::size_t nring_edges_ = 0;
  std::vector<std::uint32_t> outline_;           // ∂U's vertices in its cycle's order
  std::vector<std::array<double, 2>> outline_pts_; // projected
  static constexpr std::uint8_t outline_unknown = 0, outline_cycle = 1, outline_none = 2;
  std::uint8_t outline_state_ = outline_unknown; // this search's outline_
  // How the last certificate showed (S): (A) from x, (A) from another point, (B).
  static constexpr std::uint8_t from_x = 0, from_other = 1, by_outline = 2;
  std::uint8_t way_ = from_x;
  std::vector<H> around_;           // the survivor's incoming halfedges
  Ahead ahead_[2];                  // the next edges' fans, walked ahead (see ahead_begin)
  unsigned turn_ = 0;               // the walk ahead_step steps next
  bool prefetch_ = true; // whether walks ahead and hints pay (not on a mesh that stays in cache)
  volatile bool sink_ = false;      // a read's use, so that the compiler keeps it (ahead_step)
  std::vector<Box> fresh_box_;
  Box_set fresh_set_; // the first 64 of fresh_box_, by coordinate
  std::vector<std::uint32_t> near_; // faces a grid query found
  std::vector<std::uint32_t> star_; // the faces around p and q (indices; the two of the edge twice), a prefix
  std::vector<std::uint32_t> link_buf_; // stays_embedded's scratch for ring_
#if GENMESH_DETAIL_GUARD_FLOOR == 6
  double floor_sum_ = 0; // the measurement hook's reads (see stays_embedded)
#endif
  std::vector<H> near_h_;           // a halfedge of each
  std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint64_t>> candidates_; // corners, new faces its box meets
  std::vector<Fresh_plane> fresh_plane_;
  std::size_t exact_tests_ = 0; // faces_intersect calls (the filters decided the rest)
  Face_grid grid_;
  // The last collapse's ends' old points in grid units (p, q) and the apexes
  // of its faces (top, bottom; no_apex where missing): see update_grid.
  static constexpr std::uint32_t no_apex = ~std::uint32_t{0};
  std::array<Face_grid::Point, 2> grid_was_{};
  std::uint32_t grid_apex_[2] = {no_apex, no_apex};
  std::size_t grid_faces_ = 0, compact_faces_ = 0; // faces at the last build, at the last build or compaction
  std::vector<std::uint8_t> feature_, on_line_; // empty without features_
  std::vector<E> edesc_; // empty with native_edges
  // 32-bit keys and positions: edge indices fit (the mesh's own indices are
  // 32-bit). Entries of a float cost (rounded to nearest, which keeps the
  // order of the doubles but for new ties, broken by vertex-index pair as
  // before) and a key: 8 bytes, against 16 with a double (10 MB less at
  // 832k faces).
  // 8-ary: a node's children are 64 bytes, and the heap of 1.25M edges is 7
  // levels deep instead of 10 (832k → 10 %, unguarded: 3-4 % faster than
  // 4-ary; 16-ary no faster again; the children aligned to cache lines
  // measured slower, 4 %).
  using Queue = Mutable_priority_queue<float, Order, std::uint32_t, 8>;
  Queue queue_;
  // Memoryless policies: the profile's scratch, and the collapse count at
  // which each edge was last requeued.
  std::vector<std::array<std::uint32_t, 2>> border_keys_;
  std::vector<std::uint32_t> link_seen_; // per vertex: the profile that listed it last
  std::uint32_t link_epoch_ = 0;
  std::vector<Profile_triangle> tris_;
  std::vector<Profile_border_edge> borders_;
  std::vector<Eigen::Vector3d> link_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
};

} // namespace genmesh::detail::simplification
