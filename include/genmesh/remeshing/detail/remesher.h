// genmesh/remeshing/detail/remesher.h — the state shared by the remeshing
// steps (target lengths, constraint flags, projection bounds) and the steps
// themselves. Public entry points: <genmesh/remeshing.h> and the step
// headers beside it.
//
// Determinism: every decision reads element indices (get(*_index, g)),
// positions and counts only; edges are visited in edges(g) order or from
// heaps ordered by (squared length, edge index); rings around a vertex start
// at its border halfedge, else at the halfedge of its lowest-numbered edge;
// triangles are evaluated from a fixed corner. halfedge(v, g) and
// halfedge(f, g), which backends choose differently, are never a start.
// All backends allocate element indices identically, so the same input gives
// the same mesh everywhere.
//
// Termination: every loop has a bound. Splits: a heap of long edges, each
// split only if it is the longest edge of its triangles (Rivara's rule: no
// cascade of ever thinner triangles against an edge that stays), with a
// budget of 4 E + 4 Σ ⌈ℓ/L⌉ + 64 splits per call. Collapses: each removes a
// vertex, and an edge is re-queued only after a collapse at one of its ends.
// Flips: one loop (flip_passes) for the three flip steps — valence: at most
// 10 passes, each flip lowers the integer valence deviation; Delaunay: at
// most 50 passes; bad triangles: 2 passes; a pass after the first looks only
// at the edges near the previous pass's flips (the others would decide as
// before). Smoothing: fixed steps. Projection: one Aabb_tree query per
// vertex, started at the triangle it was last projected to. The final
// clean-up (improve_min_angle): at most 3 passes over the triangles still
// below 36°, each move a fixed number of candidate points.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/elements/compaction.h>
#include <genmesh/exceptions.h>
#include <genmesh/features.h>
#include <genmesh/geometry.h>
#include <genmesh/local_operations.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>
#include <genmesh/remeshing/detail/reference_surface.h>
#include <genmesh/remeshing/options.h>
#include <genmesh/renumbering.h>
#include <genmesh/visitor.h>

#include <boost/container/small_vector.hpp>
#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <queue>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace genmesh {

namespace detail::remeshing {

/// What the remeshing steps need of a mesh: face lists, points, dense
/// indices, and the local operations split_edge_and_triangulate,
/// collapse_edge, flip_edge and triangulate_faces.
template <class G>
concept Remeshable = FaceListGraph<G> && EdgeListGraph<G> && VertexListGraph<G> && HalfedgeListGraph<G> &&
                     HasVertexPoints<G> && HasIndexMap<G, vertex_index_t> && HasIndexMap<G, edge_index_t> &&
                     HasIndexMap<G, face_index_t> &&
                     requires(G& g, halfedge_descriptor_t<G> h, edge_descriptor_t<G> e) {
                       genmesh::split_edge_and_triangulate(h, g);
                       genmesh::collapse_edge(e, g);
                       genmesh::can_flip_edge(h, std::as_const(g));
                       genmesh::flip_edge(h, g);
                       genmesh::triangulate_faces(g);
                     } && Renumberable<G>;

inline constexpr std::uint32_t k_none = std::numeric_limits<std::uint32_t>::max();

// Vertex flags.
inline constexpr std::uint8_t v_constrained = 1; // on a constrained edge
inline constexpr std::uint8_t v_fixed = 2;       // never moved, never removed (corner, protected, outside the patch)
// Edge flags.
inline constexpr std::uint8_t e_constrained = 1; // border, feature, user constrained, patch border
inline constexpr std::uint8_t e_fixed = 2;       // never split, collapsed or flipped

/// A priority queue of the entries of one step, greatest first by
/// Entry::operator< (as std::priority_queue): the entries known at the
/// start sorted once, those pushed later on a heap; pop() takes the greater
/// of the two fronts. The pop order is that of one std::priority_queue of
/// all entries, up to entries equal under operator< (the steps' keys,
/// (length, edge index), are unique among live entries; a stale duplicate
/// is skipped either way). Sorting the first entries instead of sifting
/// them through the heap's random accesses: the collapse and split steps
/// ~5 % less time on armadillo and bunny (docs/benchmarks.md, session 9).
template <class Entry>
class Step_queue {
public:
  explicit Step_queue(std::vector<Entry> first) : first_(std::move(first)) {
    std::sort(first_.begin(), first_.end(), [](const Entry& a, const Entry& b) { return b < a; });
  }
  bool empty() const { return next_ == first_.size() && heap_.empty(); }
  void push(const Entry& e) { heap_.push(e); }
  /// Precondition: !empty().
  Entry pop() {
    if (heap_.empty() || (next_ < first_.size() && !(first_[next_] < heap_.top()))) return first_[next_++];
    Entry e = heap_.top();
    heap_.pop();
    return e;
  }

private:
  std::vector<Entry> first_;
  std::size_t next_ = 0;
  std::priority_queue<Entry> heap_;
};

/// The sums of the area-weighted smoothing rule over the closed ring of a
/// vertex at p whose neighbours are nb(0), …, nb(k − 1) in ring order, in
/// coordinates relative to p (see Remesher::relaxation_move): s = Σ |d|,
/// m = Σ d dᵀ / |d| (upper triangle), r = Σ (|d| a′ − d (d·a′) / |d|),
/// n = Σ d × a′, over the ring's edges d = c − a (a′ = a − p, c′ = c − p).
struct Relaxation_sums {
  double s = 0, m00 = 0, m01 = 0, m02 = 0, m11 = 0, m12 = 0, m22 = 0, r0 = 0, r1 = 0, r2 = 0, n0 = 0, n1 = 0, n2 = 0;
};

/// Relaxation_sums on plain scalars, one pass over the ring, each neighbour
/// read once (Eigen's 3-vectors cost twice the instructions here).
template <class Neighbour>
Relaxation_sums relaxation_sums_scalar(const Eigen::Vector3d& p, std::uint32_t k, Neighbour& nb) {
  Relaxation_sums o;
  const double px = p.x(), py = p.y(), pz = p.z();
  const Eigen::Vector3d& first = nb(0);
  const double fx = first.x() - px, fy = first.y() - py, fz = first.z() - pz;
  double ax = fx, ay = fy, az = fz;
  for (std::uint32_t j = 0; j < k; ++j) {
    double cx = fx, cy = fy, cz = fz;
    if (j + 1 < k) {
      const Eigen::Vector3d& c = nb(j + 1);
      cx = c.x() - px, cy = c.y() - py, cz = c.z() - pz;
    }
    const double dx = cx - ax, dy = cy - ay, dz = cz - az;
    o.n0 += dy * az - dz * ay, o.n1 += dz * ax - dx * az, o.n2 += dx * ay - dy * ax; // d × a'
    const double l2 = dx * dx + dy * dy + dz * dz;
    if (l2 > 0) {
      const double l = std::sqrt(l2), w = 1.0 / l;
      o.s += l;
      const double wx = w * dx, wy = w * dy, wz = w * dz;
      o.m00 += wx * dx, o.m01 += wx * dy, o.m02 += wx * dz;
      o.m11 += wy * dy, o.m12 += wy * dz, o.m22 += wz * dz;
      const double t = wx * ax + wy * ay + wz * az; // w (d·a')
      o.r0 += l * ax - t * dx, o.r1 += l * ay - t * dy, o.r2 += l * az - t * dz;
    }
    ax = cx, ay = cy, az = cz;
  }
  return o;
}

#if defined(__SSE2__)
/// relaxation_sums_scalar's operations, two components to a register where
/// the formulas pair up (x with y; m00 with m11, m01 with m12, m02 with m22;
/// r0 with r1; n0 with n1): each lane rounds as the scalar code does, so the
/// bits are the same (tests/test_remeshing.cpp checks it on real rings); 13
/// accumulators in 8 registers, where the compiler spilled 10 of the scalar
/// ones to the stack (armadillo: relaxation_move 287 → 249 M instructions,
/// the run −7 %; docs/benchmarks.md, session 10).
template <class Neighbour>
Relaxation_sums relaxation_sums_sse2(const Eigen::Vector3d& p, std::uint32_t k, Neighbour& nb) {
  const __m128d pxy = _mm_loadu_pd(p.data()), pz = _mm_load_sd(p.data() + 2);
  const __m128d zero = _mm_setzero_pd(), one = _mm_set_sd(1.0);
  // Lane 0 of a "z" register is the z component; (x, y) registers hold two.
  const Eigen::Vector3d& first = nb(0);
  const __m128d fxy = _mm_sub_pd(_mm_loadu_pd(first.data()), pxy);
  const __m128d fz = _mm_sub_sd(_mm_load_sd(first.data() + 2), pz);
  __m128d axy = fxy, az = fz;
  __m128d n01 = zero, n2v = zero, sv = zero, m0011 = zero, m0112 = zero, m0222 = zero, r01 = zero, r2v = zero;
  for (std::uint32_t j = 0; j < k; ++j) {
    __m128d cxy = fxy, cz = fz;
    if (j + 1 < k) {
      const Eigen::Vector3d& c = nb(j + 1);
      cxy = _mm_sub_pd(_mm_loadu_pd(c.data()), pxy);
      cz = _mm_sub_sd(_mm_load_sd(c.data() + 2), pz);
    }
    const __m128d dxy = _mm_sub_pd(cxy, axy), dz = _mm_sub_sd(cz, az);
    const __m128d dyz = _mm_shuffle_pd(dxy, dz, 1); // (dy, dz)
    // (n0, n1) += (dy az − dz ay, dz ax − dx az); n2 += dx ay − dy ax
    n01 = _mm_add_pd(n01, _mm_sub_pd(_mm_mul_pd(dyz, _mm_shuffle_pd(az, axy, 0)),
                                     _mm_mul_pd(_mm_shuffle_pd(dz, dxy, 0), _mm_shuffle_pd(axy, az, 1))));
    const __m128d cr = _mm_mul_pd(dxy, _mm_shuffle_pd(axy, axy, 1)); // (dx ay, dy ax)
    n2v = _mm_add_sd(n2v, _mm_sub_sd(cr, _mm_unpackhi_pd(cr, cr)));
    const __m128d sq = _mm_mul_pd(dxy, dxy);
    const __m128d l2 = _mm_add_sd(_mm_add_sd(sq, _mm_unpackhi_pd(sq, sq)), _mm_mul_sd(dz, dz));
    if (_mm_comigt_sd(l2, zero)) {
      const __m128d l = _mm_sqrt_sd(l2, l2), w = _mm_div_sd(one, l);
      sv = _mm_add_sd(sv, l);
      const __m128d wxy = _mm_mul_pd(_mm_unpacklo_pd(w, w), dxy), wz = _mm_mul_sd(w, dz);
      m0011 = _mm_add_pd(m0011, _mm_mul_pd(wxy, dxy));                                          // wx dx, wy dy
      m0112 = _mm_add_pd(m0112, _mm_mul_pd(wxy, dyz));                                          // wx dy, wy dz
      m0222 = _mm_add_pd(m0222, _mm_mul_pd(_mm_unpacklo_pd(wxy, wz), _mm_unpacklo_pd(dz, dz))); // wx dz, wz dz
      const __m128d ta = _mm_mul_pd(wxy, axy);
      const __m128d t = _mm_add_sd(_mm_add_sd(ta, _mm_unpackhi_pd(ta, ta)), _mm_mul_sd(wz, az)); // w (d·a')
      r01 = _mm_add_pd(r01, _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(l, l), axy), _mm_mul_pd(_mm_unpacklo_pd(t, t), dxy)));
      r2v = _mm_add_sd(r2v, _mm_sub_sd(_mm_mul_sd(l, az), _mm_mul_sd(t, dz)));
    }
    axy = cxy, az = cz;
  }
  Relaxation_sums o;
  double out[2];
  o.s = _mm_cvtsd_f64(sv);
  _mm_storeu_pd(out, m0011), o.m00 = out[0], o.m11 = out[1];
  _mm_storeu_pd(out, m0112), o.m01 = out[0], o.m12 = out[1];
  _mm_storeu_pd(out, m0222), o.m02 = out[0], o.m22 = out[1];
  _mm_storeu_pd(out, r01), o.r0 = out[0], o.r1 = out[1];
  o.r2 = _mm_cvtsd_f64(r2v);
  _mm_storeu_pd(out, n01), o.n0 = out[0], o.n1 = out[1];
  o.n2 = _mm_cvtsd_f64(n2v);
  return o;
}
#endif

/// Relaxation_sums: packed where SSE2 is available, else on scalars (the
/// same bits either way).
template <class Neighbour>
Relaxation_sums relaxation_sums(const Eigen::Vector3d& p, std::uint32_t k, Neighbour& nb) {
#if defined(__SSE2__)
  return relaxation_sums_sse2(p, k, nb);
#else
  return relaxation_sums_scalar(p, k, nb);
#endif
}

template <Remeshable G, class Visitor = Mutation_visitor>
class Remesher {
public:
  using V = vertex_descriptor_t<G>;
  using H = halfedge_descriptor_t<G>;
  using E = edge_descriptor_t<G>;
  using F = face_descriptor_t<G>;
  using Ring = boost::container::small_vector<H, 16>;

  /// The visitor's per-operation hooks see every split, collapse and flip.
  Remesher(G& g, const Remeshing_options& o, const char* who, Visitor& visitor)
      : g_(g), append_only_(g), o_(o), who_(who), vis_(&visitor), pm_(get(vertex_point, g)), vi_(get(vertex_index, g)),
        ei_(get(edge_index, g)), fi_(get(face_index, g)) {
    check_options();
    prepare_faces();
    check_manifold();
    set_length();
    set_flags();
    set_sizing();
    for ([[maybe_unused]] auto v : vertices(g_)) ++live_vertices_;
  }

  Remesher(G& g, const Remeshing_options& o, const char* who)
      : g_(g), append_only_(g), o_(o), who_(who), own_vis_(std::in_place), vis_(&*own_vis_), pm_(get(vertex_point, g)),
        vi_(get(vertex_index, g)), ei_(get(edge_index, g)), fi_(get(face_index, g)) {
    check_options();
    prepare_faces();
    check_manifold();
    set_length();
    set_flags();
    set_sizing();
    for ([[maybe_unused]] auto v : vertices(g_)) ++live_vertices_;
  }

  Remesher(const Remesher&) = delete;
  Remesher& operator=(const Remesher&) = delete;

  Remeshing_result& result() { return result_; }
  double target_length() const { return L_; }

  /// Builds the reference surface (a snapshot of the current mesh, or of
  /// the patch) and each vertex's last point on it.
  void build_reference() {
    ref_ = std::make_unique<Reference_surface<G>>(g_, o_.faces);
    if (!sizing_.empty()) ref_->attach_vertex_values(g_, sizing_);
    on_.assign(index_bound(vertex_index, g_), Eigen::Vector3d::Zero());
    // Each vertex starts on its first triangle of the tree: the first
    // projection then starts its searches there, and smoothing and the
    // projection get their spatial order from the first round on (with
    // every start unknown, both ran in vertex order there: armadillo's first
    // projection took twice the time of the later ones; session 8).
    on_triangle_ = ref_->corner_triangles(g_, on_.size());
    for (auto v : vertices(g_)) on_[vid(v)] = pt(v);
  }

  // -------------------------------------------------------------------------
  // split_long_edges
  // -------------------------------------------------------------------------

  std::size_t split_long_edges() {
    struct Entry {
      double len2;
      std::uint32_t idx;
      H h;
      bool operator<(const Entry& o) const { return len2 < o.len2 || (len2 == o.len2 && idx > o.idx); }
    };
    double budget = 64;
    std::vector<Entry> first;
    for (auto e : edges(g_)) {
      const H h = halfedge(e, g_);
      const double l2 = len2(h);
      budget += 4 + 4 * std::ceil(std::sqrt(l2) / min_length_bound());
      if (splittable(h) && l2 > hi2(h)) first.push_back({l2, eid(h), canonical(h)});
    }
    Step_queue<Entry> heap(std::move(first));
    std::size_t n = 0;
    while (!heap.empty() && static_cast<double>(n) < budget) {
      const Entry top = heap.pop();
      if (len2(top.h) != top.len2) continue; // split since
      const H h = top.h;
      if (!longest_in_triangles(h)) continue;
      const bool constrained = eflag(h) & e_constrained;
      const V u = source(h, g_);
      const auto hnew = genmesh::split_edge_and_triangulate(h, g_, *vis_);
      if (!hnew) continue;
      ++n;
      const V w = target(*hnew, g_);
      grow();
      vflag_[vid(w)] = constrained ? v_constrained : 0;
      eflag_[eid(*hnew)] = constrained ? e_constrained : 0;
      // The edges to the opposite corners are new (a backend that recycles
      // removed elements may hand out an index with a dead edge's flags).
      for_each_in_any_order(w, [&](H x) {
        const std::uint32_t i = eid(x);
        if (i != eid(h) && i != eid(*hnew)) eflag_[i] = 0;
      });
      if (ref_) {
        on_at(w) = on_at(u);
        on_triangle_[vid(w)] = on_triangle_[vid(u)];
      }
      if (!sizing_.empty()) sizing_[vid(w)] = 0.5 * (sizing_[vid(u)] + sizing_[vid(target(h, g_))]);
      // The edges at w and the far sides of its triangles (now perhaps
      // the longest of their triangles).
      for_each_in_any_order(w, [&](H x) {
        for (const H y : {x, prev(x, g_)}) {
          if (y != x && is_border(x)) continue;
          const double l2 = len2(y);
          if (splittable(y) && l2 > hi2(y)) heap.push({l2, eid(y), canonical(y)});
        }
      });
    }
    result_.splits += n;
    churn_ += n, live_vertices_ += n;
    return n;
  }

  // -------------------------------------------------------------------------
  // collapse_short_edges
  // -------------------------------------------------------------------------

  std::size_t collapse_short_edges() {
    struct Entry {
      double len2;
      std::uint32_t idx;
      std::uint32_t stamp;
      H h;
      bool operator<(const Entry& o) const { return len2 > o.len2 || (len2 == o.len2 && idx > o.idx); }
    };
    grow();
    std::vector<std::uint32_t> stamp(eflag_.size(), 0);
    std::vector<Entry> first;
    for (auto e : edges(g_)) {
      const H h = halfedge(e, g_);
      if (eflag(h) & e_fixed) continue;
      const double l2 = len2(h);
      if (l2 < lo2(h)) first.push_back({l2, eid(h), 0, h});
    }
    Step_queue<Entry> heap(std::move(first));
    std::size_t n = 0;
    while (!heap.empty()) {
      const Entry top = heap.pop();
      if (stamp[top.idx] != top.stamp) continue;
      const auto survivor = try_collapse(top.h, stamp);
      if (!survivor) continue;
      ++n;
      for_each_in_any_order(*survivor, [&](H x) {
        const std::uint32_t i = eid(x);
        ++stamp[i];
        if (eflag(x) & e_fixed) return;
        const double l2 = len2(x);
        if (l2 < lo2(x)) heap.push({l2, i, stamp[i], x});
      });
    }
    result_.collapses += n;
    churn_ += n, live_vertices_ -= n;
    return n;
  }

  // -------------------------------------------------------------------------
  // equalize_valences, make_delaunay
  // -------------------------------------------------------------------------

  std::size_t equalize_valences() {
    // Valences in one pass over the halfedges (sequential reads, not a walk
    // around every vertex): each halfedge counts at its target, and a
    // border halfedge makes its target a border vertex (manifold: a border
    // vertex has one incoming border halfedge).
    std::vector<int> val(index_bound(vertex_index, g_), 0), opt(val.size(), 6);
    for (auto x : halfedges(g_)) {
      const std::uint32_t v = vid(target(x, g_));
      ++val[v];
      if (is_border(x)) opt[v] = 4;
    }
    const std::size_t n = flip_passes(
        10,
        [&](H h) {
          const H oh = opposite(h, g_);
          const std::size_t v0 = vid(target(h, g_)), v1 = vid(target(oh, g_));
          const std::size_t v2 = vid(target(next(h, g_), g_)), v3 = vid(target(next(oh, g_), g_));
          auto dev = [&](std::size_t v, int d) {
            const int x = val[v] + d - opt[v];
            return x * x;
          };
          const int before = dev(v0, 0) + dev(v1, 0) + dev(v2, 0) + dev(v3, 0);
          const int after = dev(v0, -1) + dev(v1, -1) + dev(v2, 1) + dev(v3, 1);
          if (after > before) return false;
          if (after < before) return true;
          // Equal deviation: flip only to a clearly better pair of angles.
          const auto [c_before, c_after] = flip_max_cos(h);
          return c_after < c_before - 0.05;
        },
        [&](H h) { // h is the flipped edge: its old ends lose one, the new ends gain one
          const H oh = opposite(h, g_);
          ++val[vid(target(h, g_))], ++val[vid(target(oh, g_))];
          --val[vid(target(next(h, g_), g_))], --val[vid(target(next(oh, g_), g_))];
        });
    result_.flips += n;
    return n;
  }

  std::size_t make_delaunay() {
    const std::size_t n = flip_passes(50, [&](H h) { return !locally_delaunay(h); }, [](H) {});
    result_.flips += n;
    return n;
  }

  /// Flips free inner edges of triangles with an angle below 36° where the
  /// flip raises the smaller of the two triangles' smallest angles and keeps
  /// orientation (caps and slivers that the valence flips and smoothing left;
  /// pmp-library's remove_caps, widened). Two passes.
  std::size_t remove_bad_triangles() {
    // The first pass looks only at the edges of triangles with an angle
    // below 36° (found without roots), the second at what the first changed.
    return remove_bad_triangles([&](std::vector<int>& mark) {
      for (auto f : faces(g_))
        if (is_bad(f)) {
          const H h0 = detail::geom::canonical_halfedge(f, g_);
          for (const H x : {h0, next(h0, g_), prev(h0, g_)}) mark[eid(x)] = 0;
        }
    });
  }

  /// tangential_relaxation_and_project(steps), then remove_bad_triangles():
  /// the same mesh. In the one-pass case the triangles below 36° are found
  /// at the end of that pass, from its rings and its array of positions in
  /// spatial order, instead of by a scan in face order that reads every
  /// triangle's corners from scattered places (armadillo: that scan was 7 %
  /// of remeshing's time; docs/benchmarks.md, session 11). Then, given
  /// still_bad, it is set to the triangles still below 36°, by face index
  /// (bad_faces(), for improve_min_angle): among those found and those the
  /// flips changed; left empty in the other case.
  std::size_t tangential_relaxation_project_and_remove_bad_triangles(int steps,
                                                                    std::optional<std::vector<F>>* still_bad = nullptr) {
    std::vector<H> bad; // a halfedge of each triangle below 36°
    bool found = false;
    if constexpr (std::is_same_v<Visitor, Mutation_visitor>) {
      if (ref_ && o_.smoothing != Smoothing::none && steps > 0) {
        tangential_relaxation(steps, true, &bad);
        found = true;
      }
    }
    if (!found) {
      tangential_relaxation_and_project(steps);
      return remove_bad_triangles();
    }
    std::vector<F> changed;
    if (still_bad)
      for (const H x : bad) changed.push_back(face(x, g_));
    const std::size_t n = remove_bad_triangles(
        [&](std::vector<int>& mark) {
          for (const H x : bad)
            for (const H y : {x, next(x, g_), prev(x, g_)}) mark[eid(y)] = 0;
        },
        [&](H h) {
          if (still_bad) changed.insert(changed.end(), {face(h, g_), face(opposite(h, g_), g_)});
        });
    if (still_bad) {
      // Positions do not change here: a triangle below 36° now was one
      // before, or a flip made it.
      std::sort(changed.begin(), changed.end(), [&](F x, F y) { return get(fi_, x) < get(fi_, y); });
      changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
      std::erase_if(changed, [&](F f) { return !is_bad(f); });
      *still_bad = std::move(changed);
    }
    return n;
  }

  /// remove_bad_triangles() with its first pass's edges marked (0) by
  /// first_marked(mark): those of the triangles below 36°.
  /// after(h) follows each flip (h is then the new edge).
  template <class FirstMarked, class After = void (*)(H)>
  std::size_t remove_bad_triangles(FirstMarked&& first_marked, After&& after = [](H) {}) {
    const double bad = bad_cos();
    const std::size_t n = flip_passes(2, first_marked,
                                      [&](H h) {
                                        const auto [before, after] = flip_max_cos(h);
                                        return before > bad && after < before - 1e-9;
                                      },
                                      after);
    result_.flips += n;
    return n;
  }

  /// The final clean-up, after the last round's smoothing and projection:
  /// the triangles with an angle below 36° that the flips could not help
  /// (on large inputs, a tail made by the last smoothing). Each free corner
  /// of such a triangle moves to the best of a few points — the area-weighted
  /// and the uniform smoothing targets of its ring and halfway to each, in
  /// its tangent plane, then projected onto the input surface — if that
  /// raises the smallest angle of its ring and keeps every ring triangle's
  /// orientation; then the bad-triangle flips again. So the smallest angle
  /// of the mesh never drops, constrained and fixed vertices stay, and every
  /// moved vertex ends on the input surface. At most 3 passes. Returns the
  /// vertices moved.
  std::size_t improve_min_angle() { return improve_min_angle(bad_faces()); }

  /// The faces with an angle below 36° (is_bad), by face index.
  std::vector<F> bad_faces() const {
    std::vector<F> out;
    for (auto f : faces(g_))
      if (is_bad(f)) out.push_back(f);
    return out;
  }

  /// improve_min_angle() given bad_faces() (todo).
  std::size_t improve_min_angle(std::vector<F> todo) {
    const double bad = bad_cos();
    grow();
    std::vector<int> seen(index_bound(vertex_index, g_), 0);
    std::size_t moved = 0;
    for (int pass = 1; pass <= 3 && !todo.empty(); ++pass) {
      std::vector<F> touched;
      auto touch_ring = [&](V v) {
        for_each_in_any_order(v, [&](H x) {
          if (!is_border(x)) touched.push_back(face(x, g_));
        });
      };
      for (const F f : todo) {
        if (!is_bad(f)) continue;
        const H h0 = detail::geom::canonical_halfedge(f, g_);
        for (const H x : {h0, next(h0, g_), next(next(h0, g_), g_)}) {
          const V v = target(x, g_);
          if ((vflag_at(v) & (v_constrained | v_fixed)) || seen[vid(v)] == pass) continue;
          seen[vid(v)] = pass;
          if (!relocate(v)) continue;
          ++moved;
          touch_ring(v);
        }
      }
      // Then the flips of remove_bad_triangles on what is still bad.
      for (const F f : todo) {
        if (!is_bad(f)) continue;
        const H h0 = detail::geom::canonical_halfedge(f, g_);
        for (const H h : {h0, next(h0, g_), next(next(h0, g_), g_)}) {
          if (face(h, g_) != f || !free_inner(h)) continue; // f changed by a flip of this loop
          const auto [before, after] = flip_max_cos(h);
          if (!(before > bad && after < before - 1e-9)) continue;
          if (!flip_keeps_orientation(h) || !genmesh::can_flip_edge(h, std::as_const(g_))) continue;
          genmesh::flip_edge(h, g_, *vis_);
          ++result_.flips;
          for (const H y : {h, opposite(h, g_)}) {
            touched.push_back(face(y, g_));
          }
          break;
        }
      }
      // The next pass: what changed and is still bad, by face index.
      std::sort(touched.begin(), touched.end(), [&](F x, F y) { return get(fi_, x) < get(fi_, y); });
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      todo.clear();
      for (const F f : touched)
        if (is_bad(f)) todo.push_back(f);
    }
    return moved;
  }

  /// Moves the free vertex v as improve_min_angle() says; whether it moved.
  bool relocate(V v) {
    boost::container::small_vector<Eigen::Vector3d, 16> nb;
    for_each_in(v, [&](H x) { nb.push_back(pt(source(x, g_))); });
    const auto k = static_cast<std::uint32_t>(nb.size());
    if (k < 3) return false;
    const Eigen::Vector3d p = pt(v);
    auto at = [&](std::uint32_t j) -> const Eigen::Vector3d& { return nb[j]; };
    // Face j is (nb[j], v, nb[j + 1]).
    auto worst = [&](const Eigen::Vector3d& q) {
      double c = -1;
      for (std::uint32_t j = 0; j < k; ++j) c = std::max(c, max_cos(nb[j], q, nb[j + 1 == k ? 0 : j + 1]));
      return c;
    };
    auto oriented = [&](const Eigen::Vector3d& q) {
      for (std::uint32_t j = 0; j < k; ++j) {
        const Eigen::Vector3d& a = nb[j];
        const Eigen::Vector3d& c = nb[j + 1 == k ? 0 : j + 1];
        if (!(triangle_normal(a, q, c).dot(triangle_normal(a, p, c)) > 0)) return false;
      }
      return true;
    };
    const double before = worst(p);
    double best = before - 1e-9; // a clear gain only
    Eigen::Vector3d best_q = p;
    std::size_t best_triangle = 0;
    double best_value = 0;
    bool found = false;
    auto candidate = [&](const Eigen::Vector3d& c) {
      if (!c.allFinite()) return false;
      Eigen::Vector3d q = c;
      std::size_t triangle = ref_ ? on_triangle_[vid(v)] : 0;
      double value = sizing_.empty() ? 0 : sizing_[vid(v)];
      if (ref_) q = ref_->project(c, on_[vid(v)], triangle, sizing_.empty() ? nullptr : &value);
      const double w = worst(q);
      if (!(w < best) || !oriented(q)) return false;
      best = w, best_q = q, best_triangle = triangle, best_value = value, found = true;
      return true;
    };
    // The smoothing targets, then a pattern search towards and away from
    // each neighbour with a shrinking step (the smallest angle of the ring
    // is not smooth in the position: no gradient to follow).
    const Eigen::Vector3d ua = relaxation_move(p, k, at, Smoothing::area_weighted);
    const Eigen::Vector3d uu = relaxation_move(p, k, at, Smoothing::uniform);
    for (const Eigen::Vector3d& c : {Eigen::Vector3d(p + ua), Eigen::Vector3d(p + 0.5 * ua), Eigen::Vector3d(p + uu),
                                     Eigen::Vector3d(p + 0.5 * uu)})
      candidate(c);
    double step = 0.1;
    for (int round = 0; round < 8; ++round) {
      const Eigen::Vector3d base = best_q;
      bool better = false;
      for (std::uint32_t j = 0; j < k; ++j)
        for (const double t : {step, -step}) better = candidate(base + t * (nb[j] - base)) || better;
      if (!better) step *= 0.5;
    }
    if (!found) return false;
    set_pt(v, best_q);
    if (ref_) on_[vid(v)] = best_q, on_triangle_[vid(v)] = best_triangle;
    if (!sizing_.empty()) sizing_[vid(v)] = best_value;
    vis_->on_vertex_moved(v, std::as_const(g_));
    return true;
  }

  /// The cosine of the smallest angle remove_bad_triangles and
  /// improve_min_angle keep. 36°, the quality aimed at (issue 13): on
  /// armadillo after two Loop levels (832k faces) a threshold of 30° left 39
  /// triangles below 36°, 36° leaves 20, at no measurable cost, valence 6
  /// share unchanged (±0.1 %); which triangle is the worst stays chaotic
  /// (docs/benchmarks.md, session 4).
  static double bad_cos() { return std::cos(36.0 * std::numbers::pi / 180.0); }

  /// Whether triangle f has an angle below 36°, tested from its canonical
  /// corner (the test's rounding must not depend on the backend):
  /// has_angle_below(p0, p1, p2) with p0 at the corner of the lowest vertex
  /// index and p1, p2 after it in f's order.
  bool is_bad(F f) const {
    const H h0 = detail::geom::canonical_halfedge(f, g_), h1 = next(h0, g_), h2 = next(h1, g_);
    const double bad = bad_cos();
    return has_angle_below(pt(target(h0, g_)), pt(target(h1, g_)), pt(target(h2, g_)), bad * bad);
  }

  /// Whether triangle (a, b, c) has an angle below the one whose squared
  /// cosine is cos2: cos² > cos2 at an acute corner, compared without roots.
  static bool has_angle_below(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double cos2) {
    const Eigen::Vector3d ab = b - a, bc = c - b, ca = a - c;
    const double lab = ab.squaredNorm(), lbc = bc.squaredNorm(), lca = ca.squaredNorm();
    auto small = [cos2](double d, double l1, double l2) { return d > 0 && d * d > cos2 * l1 * l2; };
    return small(-ab.dot(ca), lab, lca) || small(-ab.dot(bc), lab, lbc) || small(-bc.dot(ca), lbc, lca);
  }

  /// The one flip loop of the flip steps: passes over the edges in
  /// edges(g) order flipping every free inner edge h for which want(h)
  /// holds, the flip keeps both triangles' orientation and can_flip_edge
  /// agrees; after(h) follows each flip (h is then the new edge). The first
  /// pass looks at every edge, or at those first_marked(mark) marks with 0;
  /// each later pass only at the edges whose want() a flip of the pass
  /// before may have changed (neighbourhood_of_flip). Ends after a pass
  /// without flips or after max_passes passes. Returns the flips.
  template <class Want, class After>
  std::size_t flip_passes(int max_passes, Want&& want, After&& after) {
    return flip_passes(max_passes, [](std::vector<int>& mark) { std::fill(mark.begin(), mark.end(), 0); }, want,
                       after);
  }

  template <class FirstMarked, class Want, class After>
  std::size_t flip_passes(int max_passes, FirstMarked&& first_marked, Want&& want, After&& after) {
    std::vector<H> all;
    for (auto e : edges(g_)) all.push_back(halfedge(e, g_));
    std::vector<int> mark(index_bound(edge_index, g_), -1); // the last pass that must look at the edge
    first_marked(mark);
    std::size_t n = 0;
    for (int pass = 0; pass < max_passes; ++pass) {
      std::size_t flipped = 0;
      for (const H h : all) {
        if (mark[eid(h)] < pass) continue; // marked for this pass, or by a flip of it (then for the next too)
        if (!free_inner(h) || !want(h)) continue;
        if (!flip_keeps_orientation(h) || !genmesh::can_flip_edge(h, std::as_const(g_))) continue;
        genmesh::flip_edge(h, g_, *vis_);
        after(h);
        ++flipped;
        neighbourhood_of_flip(h, [&](std::uint32_t i) { mark[i] = pass + 1; });
      }
      n += flipped;
      if (flipped == 0) break;
    }
    return n;
  }

  /// Calls mark(edge index) for the edges whose flip decision a flip of h
  /// may change: those at the four corners of h's two triangles (their
  /// valences, their triangles) and those opposite these corners in their
  /// triangles (the valences of the opposite corners).
  template <class Mark>
  void neighbourhood_of_flip(H h, Mark&& mark) const {
    const H oh = opposite(h, g_);
    for (const V v : {target(h, g_), target(oh, g_), target(next(h, g_), g_), target(next(oh, g_), g_)})
      for_each_in_any_order(v, [&](H x) {
        mark(eid(x));
        if (!is_border(x)) mark(eid(next(next(x, g_), g_)));
      });
  }

  /// Neither constrained nor fixed, with a face on both sides.
  bool free_inner(H h) const {
    return !(eflag(h) & (e_constrained | e_fixed)) && !is_border(h) && !is_border(opposite(h, g_));
  }

  /// The largest cosine of the angles of h's two triangles, before and after flipping h.
  std::pair<double, double> flip_max_cos(H h) const {
    const H oh = opposite(h, g_);
    const Eigen::Vector3d p0 = pt(target(h, g_)), p1 = pt(target(oh, g_));
    const Eigen::Vector3d p2 = pt(target(next(h, g_), g_)), p3 = pt(target(next(oh, g_), g_));
    // Before: (p1, p0, p2) and (p0, p1, p3); after: (p0, p2, p3) and (p2, p1, p3).
    return {std::max(max_cos(p1, p0, p2), max_cos(p0, p1, p3)), std::max(max_cos(p0, p2, p3), max_cos(p2, p1, p3))};
  }

  /// Whether h's opposite angles sum to at most π (up to 1e-12 in cotangents).
  bool locally_delaunay(H h) const {
    const H oh = opposite(h, g_);
    const Eigen::Vector3d p0 = pt(target(h, g_)), p1 = pt(target(oh, g_));
    const Eigen::Vector3d p2 = pt(target(next(h, g_), g_)), p3 = pt(target(next(oh, g_), g_));
    // cot α + cot β < 0 ⇔ α + β > π (α at p2, β at p3).
    auto cot = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      const double s = a.cross(b).norm();
      return s > 0 ? a.dot(b) / s : (a.dot(b) >= 0 ? 1e300 : -1e300);
    };
    return !(cot(p0 - p2, p1 - p2) + cot(p0 - p3, p1 - p3) < -1e-12);
  }

  /// Whether make_delaunay would flip h: a free inner edge whose opposite
  /// angles sum to more than π, flippable, and the flip keeps orientation.
  bool delaunay_flippable(H h) const {
    return free_inner(h) && !locally_delaunay(h) && flip_keeps_orientation(h) && genmesh::can_flip_edge(h, g_);
  }

  // -------------------------------------------------------------------------
  // tangential_relaxation, projection
  // -------------------------------------------------------------------------

  std::size_t tangential_relaxation_and_project() { return tangential_relaxation_and_project(o_.smoothing_steps); }

  /// tangential_relaxation(steps), then project(). Without an observing
  /// visitor (Mutation_visitor), in one pass: each vertex is projected from
  /// the smoothing's own array of positions, in its order, and written once
  /// (armadillo: one pass over the vertices in a spatial order, with its
  /// random reads and writes of the mesh's points, less a round; session 8).
  /// The same points either way: every query is independent of the others,
  /// and it starts from the point as the mesh stores it (rounded to its point
  /// type, as set_pt then pt would give it).
  std::size_t tangential_relaxation_and_project(int steps) {
    if constexpr (std::is_same_v<Visitor, Mutation_visitor>) {
      if (ref_ && o_.smoothing != Smoothing::none && steps > 0) return tangential_relaxation(steps, true);
    }
    const std::size_t n = tangential_relaxation(steps);
    project();
    return n;
  }

  /// Returns the number of free vertices (moved at each step).
  std::size_t tangential_relaxation() { return tangential_relaxation(o_.smoothing_steps); }

  /// As tangential_relaxation(), with `steps` steps instead of
  /// options.smoothing_steps; with and_project (only without an observing
  /// visitor), projects as well (tangential_relaxation_and_project), and
  /// then, given bad, appends to it a halfedge of each triangle below 36°.
  std::size_t tangential_relaxation(int steps, bool and_project = false, std::vector<H>* bad = nullptr) {
    if (o_.smoothing == Smoothing::none || steps <= 0) return 0;
    grow();
    // The topology does not change while smoothing: read each free vertex's
    // ring once (canonical order, compressed rows), the positions into one
    // array, and write the positions back at the end. Vertices are numbered
    // here in spatial_order, so that a ring's positions lie near each other
    // and near the previous vertex's in memory (in vertex order, split
    // vertices appended at the end scatter every ring); Jacobi steps, so the
    // order changes no result.
    const std::vector<V> order = spatial_order([&](V v) { return halfedge(v, g_) != null_h(); });
    std::vector<std::uint32_t> local(index_bound(vertex_index, g_), k_none);
    std::vector<Eigen::Vector3d> pos(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      local[vid(order[i])] = static_cast<std::uint32_t>(i);
      pos[i] = pt(order[i]);
    }
    std::vector<std::uint32_t> free_id, offset{0}, ring;
    free_id.reserve(order.size()), offset.reserve(order.size() + 1), ring.reserve(7 * order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      if (!(vflag_at(order[i]) & (v_constrained | v_fixed))) free_id.push_back(static_cast<std::uint32_t>(i));
    for (std::size_t i = 0; i < free_id.size(); i += ring_batch) {
      const std::size_t n = std::min(ring_batch, free_id.size() - i);
      V batch[ring_batch];
      for (std::size_t b = 0; b < n; ++b) batch[b] = order[free_id[i + b]];
      const std::size_t first = ring.size();
      append_rings(std::span<const V>(batch, n), ring, offset, true);
      for (std::size_t j = first; j < ring.size(); ++j) ring[j] = local[ring[j]];
    }
    std::vector<Eigen::Vector3d> moved(free_id.size());
    const double lambda = o_.smoothing_step_size;
    for (int step = 0; step < steps; ++step) {
      for (std::size_t i = 0; i < free_id.size(); ++i) {
        const Eigen::Vector3d p = pos[free_id[i]];
        const std::uint32_t b = offset[i], k = offset[i + 1] - b;
        const std::uint32_t* r = ring.data() + b;
        const Eigen::Vector3d u = relaxation_move(p, k, [&](std::uint32_t j) -> const Eigen::Vector3d& { return pos[r[j]]; },
                                                  o_.smoothing);
        moved[i] = p + lambda * u;
      }
      for (std::size_t i = 0; i < free_id.size(); ++i)
        if (moved[i].allFinite()) pos[free_id[i]] = moved[i];
    }
    if (and_project) {
      // The queries' start triangles a few vertices ahead: they follow the
      // tree's leaf order.
      // Projected a batch at a time: the tree interleaves the batch's
      // searches (each independent of the others, so the same points).
      constexpr std::size_t ahead = 8, batch = 16;
      V bv[batch];
      std::uint32_t bl[batch]; // their positions in order
      Eigen::Vector3d bq[batch], bon[batch], bout[batch];
      std::size_t btri[batch];
      double* bval[batch];
      std::size_t m = 0;
      auto flush = [&] {
        ref_->project(std::span<const Eigen::Vector3d>(bq, m), std::span<const Eigen::Vector3d>(bon, m),
                      std::span<std::size_t>(btri, m), std::span<double* const>(bval, m),
                      std::span<Eigen::Vector3d>(bout, m));
        for (std::size_t j = 0; j < m; ++j) {
          on_triangle_[vid(bv[j])] = btri[j]; // known now: on_ is no longer read (Reference_surface::project)
          set_pt(bv[j], bout[j]);
          pos[bl[j]] = pt(bv[j]);
        }
        m = 0;
      };
      for (std::size_t i = 0; i < order.size(); ++i) {
        if (i + ahead < order.size()) {
          const std::uint32_t w = vid(order[i + ahead]);
          ref_->prefetch(on_triangle_[w]);
        }
        const V v = order[i];
        if (vflag_at(v) & v_fixed) continue;
        bv[m] = v;
        bl[m] = static_cast<std::uint32_t>(i);
        bq[m] = to_eigen(from_eigen<point_t<G>>(pos[i])); // as the mesh stores it
        btri[m] = on_triangle_[vid(v)];
        bon[m] = btri[m] < ref_->triangle_count() ? bq[m] : on_[vid(v)]; // read only for an unknown triangle
        bval[m] = sizing_.empty() ? nullptr : &sizing_[vid(v)];
        if (++m == batch) flush();
      }
      flush();
      // Vertices without edges are not smoothed, but project() moves them.
      for (auto v : vertices(g_))
        if (halfedge(v, g_) == null_h() && !(vflag_at(v) & v_fixed)) project_vertex(v);
      if (bad) append_bad_triangles(order, pos, free_id, offset, ring, *bad);
      return free_id.size();
    }
    for (const std::uint32_t i : free_id) {
      set_pt(order[i], pos[i]);
      vis_->on_vertex_moved(order[i], std::as_const(g_));
    }
    return free_id.size();
  }

  /// A halfedge of each triangle below 36° (is_bad) onto out, each triangle
  /// tested once, at the corner of its lowest vertex index, with the same
  /// arguments is_bad gives has_angle_below: for a free vertex from its ring
  /// and the positions of tangential_relaxation (order, pos: every vertex
  /// with edges in spatial order and its position as the mesh stores it;
  /// free_id, offset, ring: the free vertices' closed rings, face j being
  /// (ring[j], v, ring[j + 1])); for the others from the mesh. The halfedge
  /// of a bad triangle is looked up in the mesh (few are bad).
  void append_bad_triangles(const std::vector<V>& order, const std::vector<Eigen::Vector3d>& pos,
                            const std::vector<std::uint32_t>& free_id, const std::vector<std::uint32_t>& offset,
                            const std::vector<std::uint32_t>& ring, std::vector<H>& out) const {
    const double bad = bad_cos(), bad2 = bad * bad;
    auto add = [&](H x) { out.push_back(x); };
    std::size_t f = 0; // free_id[f]: the next free vertex in order
    for (std::size_t i = 0; i < order.size(); ++i) {
      const V v = order[i];
      const std::uint32_t vi = vid(v);
      if (f < free_id.size() && free_id[f] == i) {
        const std::uint32_t* r = ring.data() + offset[f];
        const std::uint32_t k = offset[f + 1] - offset[f];
        ++f;
        for (std::uint32_t j = 0; j < k; ++j) {
          const std::uint32_t a = r[j], c = r[j + 1 == k ? 0 : j + 1];
          if (vid(order[a]) < vi || vid(order[c]) < vi || !has_angle_below(pos[i], pos[c], pos[a], bad2)) continue;
          for_each_in_any_order(v, [&](H x) {
            if (source(x, g_) == order[a]) add(x);
          });
        }
        continue;
      }
      for_each_in_any_order(v, [&](H x) {
        if (is_border(x)) return;
        const V a = source(x, g_), c = target(next(x, g_), g_);
        if (vid(a) < vi || vid(c) < vi || !has_angle_below(pt(v), pt(c), pt(a), bad2)) return;
        add(x);
      });
    }
  }

  /// The tangential move of a free (inner) vertex at p whose ring
  /// neighbours, in the canonical order, are nb(0), …, nb(k − 1): to the
  /// point the smoothing rule asks for, minus its component along the ring's
  /// normal. Zero for Smoothing::none.
  template <class Neighbour>
  static Eigen::Vector3d relaxation_move(const Eigen::Vector3d& p, std::uint32_t k, Neighbour&& nb, Smoothing rule) {
    const bool uniform = rule == Smoothing::uniform;
    const bool squared_areas = rule == Smoothing::area_weighted;
    if (rule == Smoothing::none) return Eigen::Vector3d::Zero();
    // Inner vertex: the ring is closed, face j is (a, v, c) with
    // a = r[j], c = r[j + 1]; its normal (c − p) × (a − p) = d × (a − p),
    // d = c − a. The normal (their sum) is the tangent plane's.
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    bool solved = false;
    if (squared_areas) {
      // The point minimizing the sum of the squared areas of v's
      // triangles (pmp-library's rule): A x = rhs with
      // A = Σ w (|d|² I − d dᵀ), rhs = Σ w (|d|² a − d (d·a)),
      // w = 1/|d|; A symmetric, solved by its adjugate. In coordinates
      // relative to p (a' = a − p; A does not change, and x is the move
      // itself): one pass over the ring for the normal and the system
      // (relaxation_sums).
      const Relaxation_sums sums = relaxation_sums(p, k, nb);
      const double s = sums.s, m00 = sums.m00, m01 = sums.m01, m02 = sums.m02, m11 = sums.m11, m12 = sums.m12,
                   m22 = sums.m22, r0 = sums.r0, r1 = sums.r1, r2 = sums.r2;
      normal = Eigen::Vector3d(sums.n0, sums.n1, sums.n2);
      const double a00 = s - m00, a11 = s - m11, a22 = s - m22, a01 = -m01, a02 = -m02, a12 = -m12;
      const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
      const double det = a00 * c00 + a01 * c01 + a02 * c02;
      const double scale2 = a00 * a00 + a11 * a11 + a22 * a22 + 2 * (a01 * a01 + a02 * a02 + a12 * a12);
      if (std::abs(det) > 1e-12 * scale2 * std::sqrt(scale2)) {
        const double c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
        const double inv = 1.0 / det;
        u = Eigen::Vector3d((c00 * r0 + c01 * r1 + c02 * r2) * inv, (c01 * r0 + c11 * r1 + c12 * r2) * inv,
                            (c02 * r0 + c12 * r1 + c22 * r2) * inv);
        solved = true;
      }
    } else {
      for (std::uint32_t j = 0; j < k; ++j)
        normal += triangle_normal(p, nb(j + 1 == k ? 0 : j + 1), nb(j));
    }
    if (!solved) {
      // Uniform: the mean of the neighbours; area-weighted fallback
      // (singular system): the area-weighted centroid of v's triangles.
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double weight = 0;
      for (std::uint32_t j = 0; j < k; ++j) {
        const Eigen::Vector3d& a = nb(j);
        if (uniform) {
          sum += a;
          weight += 1;
        } else {
          const Eigen::Vector3d& c = nb(j + 1 == k ? 0 : j + 1);
          const double area = triangle_normal(p, c, a).norm();
          sum += area * (a + c + p);
          weight += 3 * area;
        }
      }
      if (weight > 0) u = sum / weight - p;
    }
    const double nn = normal.squaredNorm();
    if (nn > 0) u -= normal * (u.dot(normal) / nn);
    return u;
  }

  /// Projects every vertex that may move onto the reference surface.
  void project() {
    if (!ref_) return;
    grow();
    // In the tree's order (spatial_order): consecutive queries walk the
    // same tree nodes and triangles while they are in cache. The queries
    // wait for memory more than they compute: in vertex order, halving their
    // instructions (the 4-wide tree) left their time unchanged; sorted, their
    // L1 misses halve (armadillo: 2.3M -> 1.2M) and the step takes ~25 % less
    // time. Each query is independent of the others.
    for (const V v : spatial_order([&](V x) { return !(vflag_at(x) & v_fixed); })) project_vertex(v);
  }

  /// Projects v onto the reference surface (project()'s step for one vertex).
  void project_vertex(V v) {
    Eigen::Vector3d& on = on_[vid(v)];
    const Eigen::Vector3d p = pt(v);
    on = ref_->project(p, on, on_triangle_[vid(v)], sizing_.empty() ? nullptr : &sizing_[vid(v)]);
    if (on == p) return;
    set_pt(v, on);
    vis_->on_vertex_moved(v, std::as_const(g_));
  }

  /// The vertices for which keep(v) holds, bucketed by the reference
  /// triangle each was last projected to (leaf order is Morton order, so
  /// this is a spatial order; without a reference surface, vertex order);
  /// stable: vertex order within a bucket, then the vertices with no
  /// triangle yet. The same on every backend. A counting sort.
  template <class Keep>
  std::vector<V> spatial_order(Keep&& keep) {
    std::vector<V> todo;
    for (auto v : vertices(g_))
      if (keep(v)) todo.push_back(v);
    if (!ref_) return todo;
    grow();
    const std::size_t nt = ref_->triangle_count();
    auto key = [&](V v) { return std::min<std::size_t>(on_triangle_[vid(v)], nt); };
    std::vector<std::uint32_t> bucket(nt + 2, 0);
    for (const V v : todo) ++bucket[key(v) + 1];
    for (std::size_t t = 1; t < bucket.size(); ++t) bucket[t] += bucket[t - 1];
    std::vector<V> order(todo.size());
    for (const V v : todo) order[bucket[key(v)]++] = v;
    return order;
  }

  /// With options.renumber: renumber() when the splits and collapses since the last renumbering
  /// (or the start) changed more than a tenth of the vertices: on armadillo
  /// and bunny, after the first round's splits and after its collapses
  /// (they add ~45 % new vertices and remove ~40 %; the later rounds under
  /// 3 %, whose renumbering would cost more than it saves). Counts only,
  /// so the same on every backend. Whether it renumbered.
  bool renumber_if_scattered() {
    if (!o_.renumber || 10 * churn_ <= live_vertices_) return false;
    renumber();
    return true;
  }

  /// Renumbers g's live elements (genmesh::renumber) in a spatial order:
  /// vertices in spatial_order (the reference tree's leaf order, a Morton
  /// order), edges and faces after their lowest vertex (spatial_orders);
  /// the remesher's per-element state follows. Splits append their
  /// vertices, edges and faces at the end in the order of a length heap
  /// (spatially random) and collapses leave holes: afterwards the steps
  /// read neighbours near each other in memory again. The visitor's
  /// on_renumbered(maps, g) sees the old -> new indices.
  void renumber() {
    churn_ = 0;
    grow();
    const Spatial_orders<G> o = spatial_orders(g_, spatial_order([](V) { return true; }));
    const Renumbering_maps maps = genmesh::renumber(g_, std::span<const V>(o.vertices), std::span<const E>(o.edges),
                                                    std::span<const F>(o.faces));
    // In place: a[i] moves to map[i] (map completed into a permutation).
    const std::size_t vb = index_bound(vertex_index, g_), eb = index_bound(edge_index, g_);
    const std::vector<std::uint32_t> vp = detail::full_permutation(maps.vertices, vflag_.size()),
                                     ep = detail::full_permutation(maps.edges, eflag_.size());
    auto follow = [](auto& a, const std::vector<std::uint32_t>& perm, std::size_t n, auto fill) {
      if (a.empty()) return;
      a.resize(perm.size(), fill);
      detail::permute_in_place(perm, [&](std::size_t i, std::size_t j) { std::swap(a[i], a[j]); });
      a.resize(n, fill);
    };
    follow(vflag_, vp, vb, std::uint8_t{0});
    follow(on_, vp, vb, Eigen::Vector3d::Zero().eval());
    follow(on_triangle_, vp, vb, Reference_surface<G>::npos);
    follow(sizing_, vp, vb, L_);
    follow(eflag_, ep, eb, std::uint8_t{0});
    vis_->on_renumbered(maps, std::as_const(g_));
  }

  void finish() {
    std::size_t nv = 0, nf = 0;
    for ([[maybe_unused]] auto v : vertices(g_)) ++nv;
    for ([[maybe_unused]] auto f : faces(g_)) ++nf;
    result_.vertices = nv;
    result_.faces = nf;
    result_.target_edge_length = L_;
  }

private:
  // --- element access ------------------------------------------------------

  static constexpr H null_h() { return boost::graph_traits<G>::null_halfedge(); }
  static constexpr F null_f() { return boost::graph_traits<G>::null_face(); }
  std::uint32_t vid(V v) const { return static_cast<std::uint32_t>(get(vi_, v)); }
  std::uint32_t eid(H h) const { return static_cast<std::uint32_t>(get(ei_, edge(h, g_))); }
  bool is_border(H h) const { return face(h, g_) == null_f(); }
  /// The halfedge of h's edge leaving its lower-numbered end: the same on
  /// every backend (an edge may be queued from either side; which side is
  /// split decides which half keeps the edge's index).
  H canonical(H h) const { return vid(source(h, g_)) < vid(target(h, g_)) ? h : opposite(h, g_); }
  Eigen::Vector3d pt(V v) const { return to_eigen(get(pm_, v)); }
  void set_pt(V v, const Eigen::Vector3d& p) { put(pm_, v, from_eigen<point_t<G>>(p)); }
  double len2(H h) const { return (pt(target(h, g_)) - pt(source(h, g_))).squaredNorm(); }

  void grow() {
    const std::size_t vb = index_bound(vertex_index, g_), eb = index_bound(edge_index, g_);
    if (vflag_.size() < vb) vflag_.resize(vb, 0);
    if (!on_.empty() && on_.size() < vb) on_.resize(vb, Eigen::Vector3d::Zero());
    if (!on_.empty() && on_triangle_.size() < vb) on_triangle_.resize(vb, Reference_surface<G>::npos);
    if (!sizing_.empty() && sizing_.size() < vb) sizing_.resize(vb, L_);
    if (eflag_.size() < eb) eflag_.resize(eb, 0);
  }
  std::uint8_t eflag(H h) const { return eflag_[eid(h)]; }
  std::uint8_t vflag_at(V v) const { return vflag_[vid(v)]; }
  Eigen::Vector3d& on_at(V v) {
    if (vid(v) >= on_.size()) {
      if (on_.empty()) on_.resize(index_bound(vertex_index, g_), Eigen::Vector3d::Zero());
      grow();
    }
    return on_[vid(v)];
  }

  /// Calls f(x) for every halfedge x into v, from halfedge(v): only for
  /// what does not depend on the order (counts, flags, yes/no checks).
  template <class Fn>
  void for_each_in_any_order(V v, Fn&& f) const {
    all_in_any_order(v, [&](H x) {
      f(x);
      return true;
    });
  }

  /// Whether pred(x) holds for every halfedge x into v, from halfedge(v);
  /// stops at the first that fails (the rest of the walk is a chain of
  /// loads that decides nothing: collapse attempts, most of which fail on
  /// their first lengths, spent a third of their time there).
  template <class Pred>
  bool all_in_any_order(V v, Pred&& pred) const {
    const H start = halfedge(v, g_);
    if (start == null_h()) return true;
    H x = start;
    do {
      if (!pred(x)) return false;
      x = opposite(next(x, g_), g_);
    } while (x != start);
    return true;
  }

  /// Calls f(x) for every halfedge x into v, from the canonical start: v's
  /// border halfedge if it has one, else the one of its lowest-numbered edge.
  template <class Fn>
  void for_each_in(V v, Fn&& f) const {
    Ring ring;
    for_each_in_any_order(v, [&](H x) { ring.push_back(x); });
    const std::size_t first = canonical_first(ring), k = ring.size();
    for (std::size_t i = 0; i < k; ++i) f(ring[(first + i) % k]);
  }

  /// How many rings append_rings walks side by side.
  static constexpr std::size_t ring_batch = 8;

  /// Appends, for each v of vs (at most ring_batch), the vertex numbers of
  /// v's neighbours (the sources of the halfedges into v) in for_each_in's
  /// order, then out.size() onto offsets. The rings are walked side
  /// by side, a step of each in turn: a walk is a chain of dependent loads
  /// (next, then opposite's next, …) that misses the cache where vertex and
  /// halfedge indices are scattered, and the chains of different vertices
  /// overlap (one ring at a time, this was ~5 % of remeshing's time on
  /// armadillo; docs/benchmarks.md, session 9).
  /// With closed (every v of vs is free: no border halfedge comes into it),
  /// the canonical start is looked for without reading faces.
  void append_rings(std::span<const V> vs, std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& offsets,
                    bool closed = false) const {
    Ring rings[ring_batch];
    H start[ring_batch], at[ring_batch];
    std::size_t live = 0;
    for (std::size_t b = 0; b < vs.size(); ++b) {
      start[b] = at[b] = halfedge(vs[b], g_);
      if (start[b] != null_h()) ++live;
    }
    while (live != 0) {
      for (std::size_t b = 0; b < vs.size(); ++b) {
        if (at[b] == null_h()) continue;
        rings[b].push_back(at[b]);
        at[b] = opposite(next(at[b], g_), g_);
        if (at[b] == start[b]) at[b] = null_h(), --live;
      }
    }
    for (std::size_t b = 0; b < vs.size(); ++b) {
      const Ring& r = rings[b];
      const std::size_t first = closed ? lowest_edge_first(r) : canonical_first(r), k = r.size(), base = out.size();
      // One resize per ring (a push_back per neighbour was 2 % of
      // remeshing's instructions, not inlined).
      out.resize(base + k);
      for (std::size_t j = 0; j < k; ++j) out[base + j] = vid(source(r[(first + j) % k], g_));
      offsets.push_back(static_cast<std::uint32_t>(out.size()));
    }
  }

  /// The canonical start (see for_each_in) among the halfedges of a ring in
  /// walk order: its first border halfedge, else the one of its lowest edge.
  std::size_t canonical_first(const Ring& r) const {
    for (std::size_t i = 0; i < r.size(); ++i)
      if (is_border(r[i])) return i;
    return lowest_edge_first(r);
  }

  /// canonical_first(r) of a ring without a border halfedge: the one of its
  /// lowest edge.
  std::size_t lowest_edge_first(const Ring& r) const {
    std::size_t first = 0;
    std::uint32_t lowest = k_none;
    for (std::size_t i = 0; i < r.size(); ++i)
      if (const std::uint32_t e = eid(r[i]); e < lowest) lowest = e, first = i;
    return first;
  }

  // --- sizing ----------------------------------------------------------------

  double size_at(V v) const { return sizing_.empty() ? L_ : sizing_[vid(v)]; }
  // An edge's target: the mean of its ends' targets (pmp-library's rule).
  double hi2(H h) const { return hi2(source(h, g_), target(h, g_)); }
  double hi2(V a, V b) const {
    if (sizing_.empty()) return hi2_;
    const double s = (4.0 / 3.0) * 0.5 * (size_at(a) + size_at(b));
    return s * s;
  }
  double lo2(H h) const {
    if (sizing_.empty()) return lo2_;
    const double s = (4.0 / 5.0) * 0.5 * (size_at(source(h, g_)) + size_at(target(h, g_)));
    return s * s;
  }
  double min_length_bound() const { return o_.adaptive ? o_.adaptive->min_length : L_; }

  // --- predicates --------------------------------------------------------------

  /// Rivara's longest-edge rule: h is split only if no edge of its
  /// triangles comes before it in the split order (longer, or as long with
  /// a lower index). Such an edge was either split already (then h's
  /// triangle is gone) or stays (fixed, protected, refused): splitting h
  /// beside it would only make ever thinner triangles against it, a cascade
  /// of splits converging on a point (seen on a patch's fixed border and on
  /// random constraints: 10^5 splits per round). Bisecting triangles across
  /// their longest edge keeps their angles bounded below (Rivara 1984).
  bool longest_in_triangles(H h) const {
    const double l2 = len2(h);
    const std::uint32_t i = eid(h);
    for (const H s : {h, opposite(h, g_)}) {
      if (is_border(s)) continue;
      for (const H x : {next(s, g_), prev(s, g_)}) {
        const double lx = len2(x);
        if (lx > l2 || (lx == l2 && eid(x) < i)) return false;
      }
    }
    return true;
  }

  bool splittable(H h) const {
    const std::uint8_t f = eflag(h);
    if (f & e_fixed) return false;
    return !(f & e_constrained) || o_.constraints == Constraints::resample;
  }

  /// The largest cosine of triangle (a, b, c)'s angles (its smallest angle's).
  static double max_cos(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    auto cosine = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
      const double d = std::sqrt(u.squaredNorm() * v.squaredNorm());
      return d > 0 ? u.dot(v) / d : 1.0;
    };
    return std::max({cosine(b - a, c - a), cosine(a - b, c - b), cosine(a - c, b - c)});
  }

  /// Whether flipping h keeps the two triangles oriented as before (no fold,
  /// no degenerate triangle).
  bool flip_keeps_orientation(H h) const {
    const H oh = opposite(h, g_);
    const Eigen::Vector3d p0 = pt(target(h, g_)), p1 = pt(target(oh, g_));
    const Eigen::Vector3d p2 = pt(target(next(h, g_), g_)), p3 = pt(target(next(oh, g_), g_));
    // Before: (p1, p0, p2) and (p0, p1, p3); after: (p0, p2, p3) and (p2, p1, p3).
    const Eigen::Vector3d old_n = triangle_normal(p1, p0, p2) + triangle_normal(p0, p1, p3);
    const Eigen::Vector3d n1 = triangle_normal(p0, p2, p3), n2 = triangle_normal(p2, p1, p3);
    return n1.dot(n2) > 0 && n1.dot(old_n) > 0 && n2.dot(old_n) > 0;
  }

  /// Whether x may disappear into y along h (x → y).
  bool removable(H h) const {
    const V x = source(h, g_);
    const std::uint8_t fx = vflag_at(x);
    if (fx & v_fixed) return false;
    if (!(fx & v_constrained)) return true;
    // x lies on a constrained polyline: only along it, and the edges the
    // collapse merges away must be free.
    if (!(eflag(h) & e_constrained) || o_.constraints != Constraints::resample) return false;
    const H oh = opposite(h, g_);
    if (!is_border(h) && (eflag(prev(h, g_)) & e_constrained)) return false;  // x–t
    if (!is_border(oh) && (eflag(next(oh, g_)) & e_constrained)) return false; // x–b
    return true;
  }

  /// The geometric checks of collapsing x = source(h) into y = target(h):
  /// no edge longer than 4/3 L appears, no triangle turns over.
  bool collapse_geometry_ok(H h) const {
    const V x = source(h, g_), y = target(h, g_);
    const Eigen::Vector3d px = pt(x), py = pt(y);
    // The lengths first, around the whole ring: most attempts that fail,
    // fail here, before any of the normals below is computed.
    if (!all_in_any_order(x, [&](H in) {
          const V a = source(in, g_);
          return a == y || !((pt(a) - py).squaredNorm() > hi2(a, y));
        }))
      return false;
    return all_in_any_order(x, [&](H in) {
      const V a = source(in, g_);
      if (a == y || is_border(in)) return true;
      const V b = target(next(in, g_), g_);
      if (b == y) return true;
      // face(in) = (a, x, b) becomes (a, y, b).
      const Eigen::Vector3d pa = pt(a), pb = pt(b);
      const Eigen::Vector3d before = triangle_normal(pa, px, pb), after = triangle_normal(pa, py, pb);
      return before.dot(after) > 0;
    });
  }

  int valence(V v) const {
    int n = 0;
    const H start = halfedge(v, g_);
    H x = start;
    do {
      ++n;
      x = opposite(next(x, g_), g_);
    } while (x != start);
    return n;
  }

  /// Collapses the edge of h in the better allowed direction; returns the
  /// surviving vertex. Bumps the stamps of the edges that change.
  std::optional<V> try_collapse(H h, std::vector<std::uint32_t>& stamp) {
    const H oh = opposite(h, g_);
    const bool ab = removable(h), ba = removable(oh); // ab: source(h) disappears
    // The direction: of the allowed ones that pass the geometric test, the
    // one whose disappearing end has the lower valence (pmp-library's rule;
    // h's on a tie). Valences are counted only when both pass: most
    // attempts fail (armadillo, rounds 2-5: ~10 000 short edges a round,
    // 24-523 collapses), and a failing test usually stops early.
    H c = null_h();
    if (ab && collapse_geometry_ok(h)) {
      c = h;
      if (ba && valence(source(oh, g_)) < valence(source(h, g_)) && collapse_geometry_ok(oh)) c = oh;
    } else if (ba && collapse_geometry_ok(oh)) {
      c = oh;
    }
    if (c == null_h()) return std::nullopt;
    // collapse_edge removes x = source(c), c's edge, x–t on top and y–b at
    // the bottom (x–b survives as y–b): y–b's flags move to x–b's index.
    const H oc = opposite(c, g_);
    const bool bottom = !is_border(oc);
    const std::uint32_t kept = bottom ? eid(next(oc, g_)) : 0;
    const std::uint8_t kept_flag = bottom ? eflag(prev(oc, g_)) : 0;
    // The edges at both ends change (their stamps are bumped once the
    // collapse is done). collapse_edge tests the link condition (symmetric)
    // and refuses without a change; testing it here first as well was a
    // second walk of the rings and their neighbours per collapse.
    boost::container::small_vector<std::uint32_t, 32> changed;
    for_each_in_any_order(source(c, g_), [&](H in) { changed.push_back(eid(in)); });
    for_each_in_any_order(target(c, g_), [&](H in) { changed.push_back(eid(in)); });
    const auto q = genmesh::collapse_edge(edge(c, g_), g_, *vis_);
    if (!q) return std::nullopt;
    for (const std::uint32_t i : changed) ++stamp[i];
    if (bottom) eflag_[kept] = kept_flag;
    return *q;
  }

  // --- set-up --------------------------------------------------------------

  void check_options() {
    const std::string w = who_;
    if (o_.target_edge_length) {
      const double l = *o_.target_edge_length;
      if (!(std::isfinite(l) && l > 0))
        throw invalid_input(w + ": target_edge_length " + std::to_string(l) + " is not a positive finite length");
    } else if (!(std::isfinite(o_.relative_edge_length) && o_.relative_edge_length > 0)) {
      throw invalid_input(w + ": relative_edge_length " + std::to_string(o_.relative_edge_length) +
                          " is not a positive finite factor");
    }
    if (o_.iterations < 0) throw invalid_input(w + ": iterations " + std::to_string(o_.iterations) + " < 0");
    if (o_.smoothing_steps < 0)
      throw invalid_input(w + ": smoothing_steps " + std::to_string(o_.smoothing_steps) + " < 0");
    if (!(o_.smoothing_step_size > 0 && o_.smoothing_step_size <= 1))
      throw invalid_input(w + ": smoothing_step_size " + std::to_string(o_.smoothing_step_size) +
                          " is not in (0, 1]");
    if (!std::isfinite(o_.feature_angle)) throw invalid_input(w + ": feature_angle is not finite");
    if (o_.adaptive) {
      const auto& a = *o_.adaptive;
      if (!(std::isfinite(a.min_length) && a.min_length > 0 && std::isfinite(a.max_length) &&
            a.max_length >= a.min_length && std::isfinite(a.approximation_error) && a.approximation_error > 0))
        throw invalid_input(w + ": adaptive sizing needs 0 < min_length <= max_length and approximation_error > 0");
    }
  }

  /// Triangulates or refuses polygons, before any other change.
  void prepare_faces() {
    bool polygons = false;
    for (auto f : faces(g_)) {
      const H h = halfedge(f, g_);
      if (next(next(next(h, g_), g_), g_) == h) continue;
      if (o_.polygons == Polygons::refuse)
        throw invalid_input(std::string(who_) + ": face " + std::to_string(get(fi_, f)) +
                            " is not a triangle (Polygons::refuse)");
      polygons = true;
    }
    if (polygons && genmesh::triangulate_faces(g_) != 0)
      throw invalid_input(std::string(who_) + ": a face could not be triangulated");
  }

  /// Refuses a vertex whose incoming halfedges do not form one fan, and an
  /// edge with a hole on both sides.
  void check_manifold() {
    std::vector<std::uint32_t> count(index_bound(vertex_index, g_), 0);
    for (auto h : halfedges(g_)) ++count[vid(target(h, g_))];
    for (auto e : edges(g_)) {
      const H h = halfedge(e, g_);
      if (is_border(h) && is_border(opposite(h, g_)))
        throw invalid_input(std::string(who_) + ": edge " + std::to_string(get(ei_, e)) +
                            " has no face on either side");
    }
    for (auto v : vertices(g_)) {
      const H start = halfedge(v, g_);
      if (start == null_h()) continue;
      std::uint32_t n = 0;
      H x = start;
      do {
        ++n;
        x = opposite(next(x, g_), g_);
      } while (x != start && n <= count[vid(v)]);
      if (n != count[vid(v)])
        throw invalid_input(std::string(who_) + ": vertex " + std::to_string(vid(v)) +
                            " is not manifold (its faces form more than one fan)");
    }
  }

  void set_length() {
    if (o_.target_edge_length) {
      L_ = *o_.target_edge_length;
    } else {
      double sum = 0;
      std::size_t n = 0;
      for (auto e : edges(g_)) {
        sum += std::sqrt(len2(halfedge(e, g_)));
        ++n;
      }
      if (n == 0 || !(sum > 0))
        throw invalid_input(std::string(who_) + ": the mesh has no edge of positive length to scale L by");
      L_ = o_.relative_edge_length * (sum / static_cast<double>(n));
      if (!(std::isfinite(L_) && L_ > 0))
        throw invalid_input(std::string(who_) + ": the target edge length is not a positive finite length");
    }
    if (o_.adaptive) L_ = o_.adaptive->max_length;
    hi2_ = (4.0 / 3.0 * L_) * (4.0 / 3.0 * L_);
    lo2_ = (4.0 / 5.0 * L_) * (4.0 / 5.0 * L_);
  }

  void set_flags() {
    vflag_.assign(index_bound(vertex_index, g_), 0);
    eflag_.assign(index_bound(edge_index, g_), 0);
    const bool patch = !o_.faces.empty();
    auto in_patch = [&](F f) {
      if (f == null_f()) return false;
      const std::size_t i = get(fi_, f);
      return !patch || (i < o_.faces.size() && o_.faces[i]);
    };
    // Feature edges: the geometry layer's detect_sharp_edges (CGAL's rule).
    std::optional<Edge_flag_map<G>> sharp;
    if (o_.feature_angle > 0) sharp.emplace(sharp_edges(g_, o_.feature_angle));
    for (auto e : edges(g_)) {
      const H h = halfedge(e, g_), oh = opposite(h, g_);
      const std::size_t i = get(ei_, e);
      std::uint8_t f = 0;
      const bool in_h = in_patch(face(h, g_)), in_oh = in_patch(face(oh, g_));
      if (!in_h && !in_oh) f = e_fixed;
      else if (in_h != in_oh) // border of the mesh, or of the patch (then its outer face must not change)
        f = face(h, g_) != null_f() && face(oh, g_) != null_f() ? e_constrained | e_fixed : e_constrained;
      else if (i < o_.constrained_edges.size() && o_.constrained_edges[i]) f = e_constrained;
      else if (sharp && get(*sharp, e)) f = e_constrained;
      eflag_[i] = f;
    }
    // Vertices: constrained edges counted; corners (not 0 or 2) fixed; a
    // vertex touching a fixed edge (outside the patch) fixed.
    for (auto v : vertices(g_)) {
      int constrained = 0;
      bool touches_fixed = false;
      const H start = halfedge(v, g_);
      if (start == null_h()) continue;
      H x = start;
      do {
        const std::uint8_t f = eflag(x);
        if (f & e_constrained) ++constrained;
        if (f & e_fixed) touches_fixed = true;
        x = opposite(next(x, g_), g_);
      } while (x != start);
      std::uint8_t& fv = vflag_[vid(v)];
      if (constrained) fv |= v_constrained;
      if (touches_fixed || (constrained != 0 && constrained != 2)) fv |= v_fixed;
      if (constrained && o_.constraints == Constraints::protect) fv |= v_fixed;
    }
    // Protected constrained edges, and edges at fixed vertices whose faces
    // are partly outside, stay as they are.
    if (o_.constraints == Constraints::protect)
      for (auto& f : eflag_)
        if (f & e_constrained) f |= e_fixed;
  }

  /// Adaptive sizing (pmp-library's Remeshing::preprocessing): each
  /// vertex's largest principal curvature κ (vertex_curvature; not on
  /// constrained edges), smoothed twice over its neighbours with clamped
  /// cotangent weights, then the length whose equilateral triangles deviate
  /// approximation_error e from a sphere of radius 1/κ: √(6e/κ − 3e²)
  /// (e ≥ 1/κ: √3 e), clamped to [min_length, max_length].
  void set_sizing() {
    if (!o_.adaptive) return;
    const Adaptive_sizing& a = *o_.adaptive;
    const std::size_t vb = index_bound(vertex_index, g_);
    std::vector<double> c(vb, -1.0), next_c(vb, 0.0);
    for (auto v : vertices(g_))
      if (!(vflag_at(v) & v_constrained)) c[vid(v)] = vertex_curvature(v, g_, pm_).max_abs();
    for (int iter = 0; iter < 2; ++iter) {
      for (auto v : vertices(g_)) {
        double ww = 0, cc = 0;
        for_each_in(v, [&](H x) {
          const double cj = c[vid(source(x, g_))];
          if (!(cj > 0)) return;
          const Eigen::Vector3d p = pt(v), q = pt(source(x, g_));
          double w = 0;
          for (const H y : {x, opposite(x, g_)})
            if (!is_border(y)) {
              const Eigen::Vector3d r = pt(target(next(y, g_), g_));
              w += cotangent_between(p - r, q - r);
            }
          w = std::max(0.0, w);
          ww += w;
          cc += w * cj;
        });
        next_c[vid(v)] = ww > 0 ? cc / ww : 0.0;
      }
      std::swap(c, next_c);
    }
    sizing_.assign(vb, a.max_length);
    const double e = a.approximation_error;
    for (auto v : vertices(g_)) {
      const double k = c[vid(v)];
      double h = a.max_length;
      if (k > 0) h = e < 1 / k ? std::sqrt(6 * e / k - 3 * e * e) : e * std::sqrt(3.0);
      sizing_[vid(v)] = std::clamp(h, a.min_length, a.max_length);
    }
  }

  G& g_;
  // New elements get fresh indices while the remesher lives: its work is
  // ordered by index, and recycled indices (LIFO free lists) are not what
  // OpenMesh or Polyhedron_3 give, so the result would differ there.
  Append_only_indices<G> append_only_;
  const Remeshing_options& o_;
  const char* who_;
  std::optional<std::remove_cvref_t<Visitor>> own_vis_;
  Visitor* vis_;
  vertex_point_map_t<G> pm_;
  decltype(get(vertex_index, std::declval<const G&>())) vi_;
  decltype(get(edge_index, std::declval<const G&>())) ei_;
  decltype(get(face_index, std::declval<const G&>())) fi_;
  double L_ = 0, hi2_ = 0, lo2_ = 0;
  std::vector<std::uint8_t> vflag_, eflag_;
  std::vector<Eigen::Vector3d> on_; // a vertex's last point on the reference surface (read while on_triangle_ is npos)
  std::vector<std::size_t> on_triangle_; // and the reference triangle it lies in (npos: unknown)
  std::vector<double> sizing_;
  std::unique_ptr<Reference_surface<G>> ref_;
  Remeshing_result result_;
  std::size_t live_vertices_ = 0; // kept by the splits and collapses
  std::size_t churn_ = 0;         // splits and collapses since the last renumbering
};

} // namespace detail::remeshing

} // namespace genmesh
