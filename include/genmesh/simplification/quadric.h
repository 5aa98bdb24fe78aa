// genmesh/simplification/quadric.h — error quadrics and the cost/placement
// policies of genmesh::simplify built on them.
//
// A quadric Q(x) = xᵀAx + 2bᵀx + c (A symmetric 3×3) measures the sum of
// squared distances from x to a set of planes (Garland & Heckbert,
// "Surface simplification using quadric error metrics", SIGGRAPH 1997).
// Quadrics add, so a vertex's quadric is the sum over its faces, and a
// collapsed vertex gets the sum of its two ends' quadrics.
//
// Policies (a policy is a small type; see "Writing a policy" below):
// - Plane_quadrics: Garland–Heckbert plane quadrics, optimal placement
//   (solve A x = −b) with the fallback described at Plane_quadrics.
// - Probabilistic_quadrics: Trettner & Kobbelt, "Fast and robust QEF
//   minimization using probabilistic quadrics" (Eurographics 2020), the
//   isotropic variant: each plane's normal and point are Gaussian; A gains
//   σ_n² I, so it is always invertible and placement needs no fallback.
// - Edge_length: cost = squared edge length, placement at the midpoint.
// - Attribute_quadrics (its own header): Garland–Heckbert 1998 quadrics over
//   position and user per-vertex attributes.
//
// Writing a policy: a type with
//   using Vertex_data = ...;                         // regular, default-constructible
//   Vertex_data face(a, b, c) const;                 // a triangle's contribution to each corner
//   Vertex_data border(a, b, c, weight) const;       // a border edge a→b of triangle (a, b, c)
//   Placement place(const Vertex_data& sum, pa, pb) const;   // cost and position of collapsing a–b
// and optionally (defaults: x + y, and {sum(x), x} for a callable Vertex_data)
//   Vertex_data merge(const Vertex_data&, const Vertex_data&) const;
//   Placement fixed(const Vertex_data& sum, pa, pb, x) const; // cost of collapsing a–b onto x
//   Vertex_data face(ia, a, ib, b, ic, c) const;    // instead of face(a, b, c): with vertex indices
//   void start(const G& g);                         // once, before the first face(): read per-vertex data
//   void collapsed(survivor_index, const Vertex_data& sum, x) const; // after each collapse
// (the last three let a policy read and write per-vertex data: see
// Attribute_quadrics in <genmesh/simplification/attribute_quadrics.h>;
// points are Eigen::Vector3d; merge must be commutative bit for bit, so
// that every backend computes the same numbers.)
#pragma once

#include <genmesh/geometry.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace genmesh {

/// A symmetric error quadric Q(x) = xᵀAx + 2bᵀx + c, 10 doubles.
// The sum, Q(x), the minimizer (and Relative_quadric::absolute, Plane_quadrics::place)
// are always inlined: as calls, each wrote its 80-byte result with 8-byte stores
// that the caller read back with 16-byte loads, a store-forwarding stall per
// call (a fifth of simplify's cost evaluations on 832k faces). The same operations.
struct Quadric {
  // A = [a00 a01 a02; a01 a11 a12; a02 a12 a22]
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
  double b0 = 0, b1 = 0, b2 = 0;
  double c = 0;

  /// w · (squared distance to the plane nᵀx + d = 0), n of unit length.
  static Quadric plane(const Eigen::Vector3d& n, double d, double w = 1.0) {
    Quadric q;
    q.a00 = w * n.x() * n.x();
    q.a01 = w * n.x() * n.y();
    q.a02 = w * n.x() * n.z();
    q.a11 = w * n.y() * n.y();
    q.a12 = w * n.y() * n.z();
    q.a22 = w * n.z() * n.z();
    q.b0 = w * d * n.x();
    q.b1 = w * d * n.y();
    q.b2 = w * d * n.z();
    q.c = w * d * d;
    return q;
  }

  /// The probabilistic plane quadric of Trettner & Kobbelt 2020 (isotropic):
  /// the expected squared distance to the plane through p with normal n when
  /// p ~ N(p, σ_p² I) and n ~ N(n, σ_n² I). Times w.
  static Quadric probabilistic_plane(const Eigen::Vector3d& n, const Eigen::Vector3d& p, double sigma_p,
                                     double sigma_n, double w = 1.0) {
    const double sn2 = sigma_n * sigma_n, sp2 = sigma_p * sigma_p;
    const double d = -n.dot(p);
    Quadric q = plane(n, d, 1.0);
    q.a00 += sn2;
    q.a11 += sn2;
    q.a22 += sn2;
    q.b0 -= sn2 * p.x();
    q.b1 -= sn2 * p.y();
    q.b2 -= sn2 * p.z();
    q.c += sn2 * p.squaredNorm() + sp2 * n.squaredNorm() + 3.0 * sn2 * sp2;
    q *= w;
    return q;
  }

  [[gnu::always_inline]] Quadric& operator+=(const Quadric& o) {
    a00 += o.a00; a01 += o.a01; a02 += o.a02; a11 += o.a11; a12 += o.a12; a22 += o.a22;
    b0 += o.b0; b1 += o.b1; b2 += o.b2;
    c += o.c;
    return *this;
  }
  Quadric& operator*=(double w) {
    a00 *= w; a01 *= w; a02 *= w; a11 *= w; a12 *= w; a22 *= w;
    b0 *= w; b1 *= w; b2 *= w;
    c *= w;
    return *this;
  }
  [[gnu::always_inline]] friend Quadric operator+(Quadric a, const Quadric& b) { return a += b; }

  /// Q(x), clamped at 0 (rounding can make it slightly negative).
  [[gnu::always_inline]] double operator()(const Eigen::Vector3d& x) const {
    const double ax = a00 * x.x() + a01 * x.y() + a02 * x.z();
    const double ay = a01 * x.x() + a11 * x.y() + a12 * x.z();
    const double az = a02 * x.x() + a12 * x.y() + a22 * x.z();
    const double v = x.x() * (ax + 2 * b0) + x.y() * (ay + 2 * b1) + x.z() * (az + 2 * b2) + c;
    return v > 0 ? v : 0.0;
  }

  /// The minimizer of Q, if A is well conditioned: |det A| must exceed
  /// `tolerance` times the product of A's row norms (Hadamard's bound, so the
  /// test does not depend on the scale of the mesh). False if it does not.
  [[gnu::always_inline]] bool minimizer(Eigen::Vector3d& x, double tolerance) const {
    const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
    const double det = a00 * c00 + a01 * c01 + a02 * c02;
    const double r0 = a00 * a00 + a01 * a01 + a02 * a02, r1 = a01 * a01 + a11 * a11 + a12 * a12,
                 r2 = a02 * a02 + a12 * a12 + a22 * a22;
    if (!(std::abs(det) > tolerance * std::sqrt(r0 * r1 * r2))) return false;
    const double c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
    const double inv = 1.0 / det;
    x.x() = -(c00 * b0 + c01 * b1 + c02 * b2) * inv;
    x.y() = -(c01 * b0 + c11 * b1 + c12 * b2) * inv;
    x.z() = -(c02 * b0 + c12 * b1 + c22 * b2) * inv;
    return std::isfinite(x.x()) && std::isfinite(x.y()) && std::isfinite(x.z());
  }
};

#if defined(__SSE2__)
/// Two Quadrics side by side: lane 0 one's term, lane 1 the other's (simplify
/// evaluates two edges at once: each lane does the scalar operations).
struct Quadric_lanes {
  __m128d a00, a01, a02, a11, a12, a22, b0, b1, b2, c;

  /// q in both lanes.
  [[gnu::always_inline]] static Quadric_lanes both(const Quadric& q) {
    return {_mm_set1_pd(q.a00), _mm_set1_pd(q.a01), _mm_set1_pd(q.a02), _mm_set1_pd(q.a11), _mm_set1_pd(q.a12),
            _mm_set1_pd(q.a22), _mm_set1_pd(q.b0),  _mm_set1_pd(q.b1),  _mm_set1_pd(q.b2),  _mm_set1_pd(q.c)};
  }
  /// Lane j's quadric.
  [[gnu::always_inline]] Quadric lane(int j) const {
    auto at = [j](__m128d v) { return _mm_cvtsd_f64(j == 0 ? v : _mm_unpackhi_pd(v, v)); };
    Quadric q;
    q.a00 = at(a00), q.a01 = at(a01), q.a02 = at(a02), q.a11 = at(a11), q.a12 = at(a12), q.a22 = at(a22);
    q.b0 = at(b0), q.b1 = at(b1), q.b2 = at(b2), q.c = at(c);
    return q;
  }
  /// Lane by lane, as Quadric's +.
  [[gnu::always_inline]] friend Quadric_lanes operator+(const Quadric_lanes& x, const Quadric_lanes& y) {
    return {_mm_add_pd(x.a00, y.a00), _mm_add_pd(x.a01, y.a01), _mm_add_pd(x.a02, y.a02), _mm_add_pd(x.a11, y.a11),
            _mm_add_pd(x.a12, y.a12), _mm_add_pd(x.a22, y.a22), _mm_add_pd(x.b0, y.b0),   _mm_add_pd(x.b1, y.b1),
            _mm_add_pd(x.b2, y.b2),   _mm_add_pd(x.c, y.c)};
  }
};
#endif

/// A Quadric stored in 10 floats (40 bytes instead of 80) relative to an
/// origin o that the owner keeps anyway (simplify: the vertex's own current
/// point): Q(x) = (x−o)ᵀA(x−o) + 2b'ᵀ(x−o) + c', so b' = b + Ao (half Q's
/// gradient at o) and c' = Q(o). Near o these terms are of the size of the
/// errors themselves, so rounding them to float loses ~1e-7 of the error; the
/// absolute form (xᵀAx + 2bᵀx + c) would cancel terms of size |o|² to get the
/// error and keep nothing of it in float. Shifting and merging are done in
/// double (absolute() and of()); only the stored terms are floats.
struct Relative_quadric {
  float a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
  float b0 = 0, b1 = 0, b2 = 0;
  float c = 0;

  /// q relative to origin o, rounded to float once per term.
  static Relative_quadric of(const Quadric& q, const Eigen::Vector3d& o) {
    const double x = o.x(), y = o.y(), z = o.z();
    const double g0 = q.a00 * x + q.a01 * y + q.a02 * z + q.b0;
    const double g1 = q.a01 * x + q.a11 * y + q.a12 * z + q.b1;
    const double g2 = q.a02 * x + q.a12 * y + q.a22 * z + q.b2;
    // Q(o) = oᵀAo + 2bᵀo + c = oᵀ(Ao + b) + bᵀo + c.
    const double co = x * g0 + y * g1 + z * g2 + q.b0 * x + q.b1 * y + q.b2 * z + q.c;
    Relative_quadric r;
    r.a00 = static_cast<float>(q.a00);
    r.a01 = static_cast<float>(q.a01);
    r.a02 = static_cast<float>(q.a02);
    r.a11 = static_cast<float>(q.a11);
    r.a12 = static_cast<float>(q.a12);
    r.a22 = static_cast<float>(q.a22);
    r.b0 = static_cast<float>(g0);
    r.b1 = static_cast<float>(g1);
    r.b2 = static_cast<float>(g2);
    r.c = static_cast<float>(co);
    return r;
  }

  /// The absolute quadric (in double) of this one relative to origin o.
  [[gnu::always_inline]] Quadric absolute(const Eigen::Vector3d& o) const {
    const double x = o.x(), y = o.y(), z = o.z();
    Quadric q;
    q.a00 = a00;
    q.a01 = a01;
    q.a02 = a02;
    q.a11 = a11;
    q.a12 = a12;
    q.a22 = a22;
    const double ao0 = q.a00 * x + q.a01 * y + q.a02 * z, ao1 = q.a01 * x + q.a11 * y + q.a12 * z,
                 ao2 = q.a02 * x + q.a12 * y + q.a22 * z;
    // b = b' − Ao, c = c' − 2b'ᵀo + oᵀAo.
    q.b0 = b0 - ao0;
    q.b1 = b1 - ao1;
    q.b2 = b2 - ao2;
    q.c = static_cast<double>(c) + x * (ao0 - 2.0 * b0) + y * (ao1 - 2.0 * b1) + z * (ao2 - 2.0 * b2);
    return q;
  }

  /// p.absolute(op) + q.absolute(oq): the same operations on the same values
  /// (so the same doubles), with SSE2 the two shifts side by side in the
  /// two lanes of each register (simplify sums two ends' quadrics for every
  /// edge it evaluates).
  [[gnu::always_inline]] static Quadric absolute_sum(const Relative_quadric& p, const Eigen::Vector3d& op,
                                                     const Relative_quadric& q, const Eigen::Vector3d& oq) {
#if defined(__SSE2__)
    const Lanes l = Lanes::absolute(p, op, q, oq);
    // Two terms' lanes summed at once: (u_p + u_q, v_p + v_q).
    auto sum = [](__m128d u, __m128d v) { return _mm_add_pd(_mm_unpacklo_pd(u, v), _mm_unpackhi_pd(u, v)); };
    Quadric r;
    _mm_storeu_pd(&r.a00, sum(l.a00, l.a01));
    _mm_storeu_pd(&r.a02, sum(l.a02, l.a11));
    _mm_storeu_pd(&r.a12, sum(l.a12, l.a22));
    _mm_storeu_pd(&r.b0, sum(l.b0, l.b1));
    _mm_storeu_pd(&r.b2, sum(l.b2, l.c));
    return r;
#else
    return p.absolute(op) + q.absolute(oq);
#endif
  }

#if defined(__SSE2__)
  /// p.absolute(op) in lane 0 and q.absolute(oq) in lane 1, the same
  /// operations on the same values.
  [[gnu::always_inline]] static Quadric_lanes absolute_lanes(const Relative_quadric& p, const Eigen::Vector3d& op,
                                                             const Relative_quadric& q, const Eigen::Vector3d& oq) {
    return Lanes::absolute(p, op, q, oq); // its terms (the origins dropped)
  }
#endif

  /// p = of(p.absolute(op) + d, op) and q = of(q.absolute(oq) + d, oq), the
  /// same operations on the same values; with SSE2 side by side, as
  /// absolute_sum. p and q must be different objects.
  [[gnu::always_inline]] static void add_to_two(Relative_quadric& p, const Eigen::Vector3d& op, Relative_quadric& q,
                                                const Eigen::Vector3d& oq, const Quadric& d) {
#if defined(__SSE2__)
    add_lanes<true>(p, op, q, oq, d);
#else
    p = of(p.absolute(op) + d, op);
    q = of(q.absolute(oq) + d, oq);
#endif
  }

  /// p = of(p.absolute(op) + d, op), the same operations on the same values;
  /// with SSE2 in add_to_two's first lane, so that its stores are the pieces
  /// that add_to_two and absolute_lanes load (see Lanes::absolute).
  [[gnu::always_inline]] static void add_to_one(Relative_quadric& p, const Eigen::Vector3d& op, const Quadric& d) {
#if defined(__SSE2__)
    add_lanes<false>(p, op, p, op, d);
#else
    p = of(p.absolute(op) + d, op);
#endif
  }

 private:
#if defined(__SSE2__)
  // add_to_two, or (two = false) add_to_one on p with q = p read again.
  template <bool two_stored>
  [[gnu::always_inline]] static void add_lanes(Relative_quadric& p, const Eigen::Vector3d& op, Relative_quadric& q,
                                               const Eigen::Vector3d& oq, const Quadric& d) {
    Lanes l = Lanes::absolute(p, op, q, oq);
    static_cast<Quadric_lanes&>(l) = l + Quadric_lanes::both(d);
    // of(), lane by lane.
    const __m128d x = l.x, y = l.y, z = l.z;
    const __m128d g0 = _mm_add_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(l.a00, x), _mm_mul_pd(l.a01, y)), _mm_mul_pd(l.a02, z)), l.b0);
    const __m128d g1 = _mm_add_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(l.a01, x), _mm_mul_pd(l.a11, y)), _mm_mul_pd(l.a12, z)), l.b1);
    const __m128d g2 = _mm_add_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(l.a02, x), _mm_mul_pd(l.a12, y)), _mm_mul_pd(l.a22, z)), l.b2);
    __m128d co = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, g0), _mm_mul_pd(y, g1)), _mm_mul_pd(z, g2));
    co = _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_add_pd(co, _mm_mul_pd(l.b0, x)), _mm_mul_pd(l.b1, y)),
                               _mm_mul_pd(l.b2, z)),
                    l.c);
    // Rounded to float: (t_p, u_p, t_q, u_q) for each two terms, then p's
    // four and q's four.
    auto two = [](__m128d t, __m128d u) { return _mm_unpacklo_ps(_mm_cvtpd_ps(t), _mm_cvtpd_ps(u)); };
    const __m128 t0 = two(l.a00, l.a01), t2 = two(l.a02, l.a11), t4 = two(l.a12, l.a22), t6 = two(g0, g1),
                 t8 = two(g2, co);
    _mm_storeu_ps(&p.a00, _mm_movelh_ps(t0, t2));
    _mm_storeu_ps(&p.a12, _mm_movelh_ps(t4, t6)); // a12 a22 b0 b1
    _mm_storel_pi(reinterpret_cast<__m64*>(&p.b2), t8); // b2 c
    if constexpr (two_stored) {
      _mm_storeu_ps(&q.a00, _mm_movehl_ps(t2, t0));
      _mm_storeu_ps(&q.a12, _mm_movehl_ps(t6, t4));
      _mm_storeh_pi(reinterpret_cast<__m64*>(&q.b2), t8);
    }
  }

  // Two relative quadrics made absolute side by side (lane 0 p's term, lane
  // 1 q's), with the origins' coordinates.
  struct Lanes : Quadric_lanes {
    __m128d x, y, z;

    [[gnu::always_inline]] static Lanes absolute(const Relative_quadric& p, const Eigen::Vector3d& op,
                                                 const Relative_quadric& q, const Eigen::Vector3d& oq) {
      // The floats come in as (p, q) pairs: terms 0-3, 4-7 and 8-9, the
      // pieces store() writes (a load that spans two stores still in
      // flight waits for both to reach the cache: initialize() adds to a
      // vertex's quadric again a few faces later).
      const __m128 p0 = _mm_loadu_ps(&p.a00), q0 = _mm_loadu_ps(&q.a00);
      const __m128 p4 = _mm_loadu_ps(&p.a12), q4 = _mm_loadu_ps(&q.a12);
      const __m128 p8 = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&p.b2)),
                   q8 = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&q.b2));
      const __m128 l0 = _mm_unpacklo_ps(p0, q0), h0 = _mm_unpackhi_ps(p0, q0);
      const __m128 l4 = _mm_unpacklo_ps(p4, q4), l6 = _mm_unpackhi_ps(p4, q4), h6 = _mm_unpacklo_ps(p8, q8);
      Lanes r;
      r.a00 = _mm_cvtps_pd(l0);
      r.a01 = _mm_cvtps_pd(_mm_movehl_ps(l0, l0));
      r.a02 = _mm_cvtps_pd(h0);
      r.a11 = _mm_cvtps_pd(_mm_movehl_ps(h0, h0));
      r.a12 = _mm_cvtps_pd(l4);
      r.a22 = _mm_cvtps_pd(_mm_movehl_ps(l4, l4));
      const __m128d b0 = _mm_cvtps_pd(l6), b1 = _mm_cvtps_pd(_mm_movehl_ps(l6, l6));
      const __m128d b2 = _mm_cvtps_pd(h6), c = _mm_cvtps_pd(_mm_movehl_ps(h6, h6));
      const __m128d x = _mm_set_pd(oq.x(), op.x()), y = _mm_set_pd(oq.y(), op.y()), z = _mm_set_pd(oq.z(), op.z());
      r.x = x;
      r.y = y;
      r.z = z;
      // As absolute(): b = b' − Ao, c = c' − 2b'ᵀo + oᵀAo.
      const __m128d ao0 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(r.a00, x), _mm_mul_pd(r.a01, y)), _mm_mul_pd(r.a02, z));
      const __m128d ao1 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(r.a01, x), _mm_mul_pd(r.a11, y)), _mm_mul_pd(r.a12, z));
      const __m128d ao2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(r.a02, x), _mm_mul_pd(r.a12, y)), _mm_mul_pd(r.a22, z));
      const __m128d two = _mm_set1_pd(2.0);
      __m128d cs = _mm_add_pd(c, _mm_mul_pd(x, _mm_sub_pd(ao0, _mm_mul_pd(two, b0))));
      cs = _mm_add_pd(cs, _mm_mul_pd(y, _mm_sub_pd(ao1, _mm_mul_pd(two, b1))));
      r.c = _mm_add_pd(cs, _mm_mul_pd(z, _mm_sub_pd(ao2, _mm_mul_pd(two, b2))));
      r.b0 = _mm_sub_pd(b0, ao0);
      r.b1 = _mm_sub_pd(b1, ao1);
      r.b2 = _mm_sub_pd(b2, ao2);
      return r;
    }
  };
#endif
};

// Relative_quadric::absolute_sum and add_to_two load and store the terms two
// or four at a time: each struct's terms must lie in this order, unpadded.
static_assert(offsetof(Quadric, a01) == offsetof(Quadric, a00) + sizeof(double) &&
              offsetof(Quadric, a02) == offsetof(Quadric, a00) + 2 * sizeof(double) &&
              offsetof(Quadric, a11) == offsetof(Quadric, a00) + 3 * sizeof(double) &&
              offsetof(Quadric, a12) == offsetof(Quadric, a00) + 4 * sizeof(double) &&
              offsetof(Quadric, a22) == offsetof(Quadric, a00) + 5 * sizeof(double) &&
              offsetof(Quadric, b0) == offsetof(Quadric, a00) + 6 * sizeof(double) &&
              offsetof(Quadric, b1) == offsetof(Quadric, a00) + 7 * sizeof(double) &&
              offsetof(Quadric, b2) == offsetof(Quadric, a00) + 8 * sizeof(double) &&
              offsetof(Quadric, c) == offsetof(Quadric, a00) + 9 * sizeof(double));
static_assert(offsetof(Relative_quadric, a00) == 0 && offsetof(Relative_quadric, a12) == 4 * sizeof(float) &&
              offsetof(Relative_quadric, b0) == 6 * sizeof(float) &&
              offsetof(Relative_quadric, c) == 9 * sizeof(float) && sizeof(Relative_quadric) == 10 * sizeof(float));

/// Where a collapse puts the surviving vertex and what it costs there.
struct Placement {
  double cost = std::numeric_limits<double>::infinity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

namespace detail::simplification {
// The cheapest placement of a, b and their midpoint (ties in that order),
// `at` giving the placement at a point: the fallback when an optimal point
// is refused, and the placement on a segment.
template <class At>
Placement best_of_ends_and_midpoint(const At& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Placement r = at(a);
  const Placement pb = at(b);
  if (pb.cost < r.cost) r = pb;
  const Placement pm = at(0.5 * (a + b));
  if (pm.cost < r.cost) r = pm;
  return r;
}
} // namespace detail::simplification

namespace detail::simplification {

// The quadric of triangle (a, b, c): its supporting plane, unit normal,
// weighted by area·area_factor + (1 − area_factor) (area_factor 0 or 1).
// Degenerate triangles contribute nothing.
inline Quadric triangle_plane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                              bool area_weighted) {
  Eigen::Vector3d n = triangle_normal(a, b, c);
  const double len = n.norm();
  if (!(len > 0)) return {};
  n /= len;
  return Quadric::plane(n, -n.dot(a), area_weighted ? 0.5 * len : 1.0);
}

// The plane through border edge a→b perpendicular to triangle (a, b, c).
inline Quadric border_plane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                            double weight, bool area_weighted) {
  const Eigen::Vector3d e = b - a;
  const Eigen::Vector3d fn = triangle_normal(a, b, c);
  Eigen::Vector3d n = e.cross(fn);
  const double len = n.norm();
  if (!(len > 0)) return {};
  n /= len;
  // Area weighting: as a face of the edge's length squared, so that the
  // border term keeps its relative strength in both modes.
  return Quadric::plane(n, -n.dot(a), weight * (area_weighted ? e.squaredNorm() : 1.0));
}

// The best of the endpoints, the midpoint and the minimizer of q on the
// segment (ties: a, then b, then the midpoint, then the segment's).
template <class Q>
Placement best_of_ends(const Q& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Placement r{q(a), a};
  const double cb = q(b);
  if (cb < r.cost) r = {cb, b};
  const Eigen::Vector3d m = 0.5 * (a + b);
  const double cm = q(m);
  if (cm < r.cost) r = {cm, m};
  if constexpr (requires { q.a00; }) {
    // Q(a + t d) = t² dᵀAd + 2t dᵀ(Aa + b) + Q(a): the minimum at t = −dᵀ(Aa + b) / dᵀAd.
    const Eigen::Vector3d d = b - a;
    const Eigen::Vector3d ad(q.a00 * d.x() + q.a01 * d.y() + q.a02 * d.z(), q.a01 * d.x() + q.a11 * d.y() + q.a12 * d.z(),
                             q.a02 * d.x() + q.a12 * d.y() + q.a22 * d.z());
    const double dad = d.dot(ad);
    if (dad > 0) {
      const double g = ad.dot(a) + q.b0 * d.x() + q.b1 * d.y() + q.b2 * d.z();
      const double t = -g / dad;
      if (t > 0 && t < 1) {
        const Eigen::Vector3d x = a + t * d;
        const double cx = q(x);
        if (cx < r.cost) r = {cx, x};
      }
    }
  }
  return r;
}

} // namespace detail::simplification

/// Garland–Heckbert plane quadrics (1997): each triangle contributes the
/// squared distance to its plane to its three corners; a collapse goes to
/// the minimizer of the summed quadric. When A is ill conditioned — |det A|
/// ≤ `conditioning` × ‖row₀‖‖row₁‖‖row₂‖ (flat or creased neighbourhoods,
/// where the minimizer is a plane or a line) — or the minimizer lies farther
/// than `max_distance_factor` edge lengths from the edge's midpoint, the
/// collapse goes to the best of the two endpoints and the midpoint instead.
/// The error reported is sqrt(Q(x)) (unweighted: a distance, the root of a
/// sum of squared distances to the original planes).
struct Plane_quadrics {
  /// Weight each plane by its triangle's area (then the cost is an area
  /// times a squared distance; .max_error compares its square root anyway).
  bool area_weighted = false;
  /// The conditioning threshold on the Hadamard ratio |det A| / ∏‖rowᵢ‖ ∈ [0, 1].
  double conditioning = 1e-6;
  /// The optimal point may be at most this many edge lengths from the midpoint.
  double max_distance_factor = 2.0;

  using Vertex_data = Quadric;

  Quadric face(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) const {
    return detail::simplification::triangle_plane(a, b, c, area_weighted);
  }
  Quadric border(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 double weight) const {
    return detail::simplification::border_plane(a, b, c, weight, area_weighted);
  }
  [[gnu::always_inline]] Placement place(const Quadric& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    Eigen::Vector3d x;
    if (q.minimizer(x, conditioning)) {
      // The midpoint m = 0.5 * (a + b) and |x − m|² written out in scalars,
      // the same operations in the same order as Eigen's ((d0² + d1²) + d2²):
      // GCC called an out-of-line Eigen loop for m and read x, just
      // written component by component, with 16-byte loads (a
      // store-forwarding stall in every evaluation).
      const double dx = x.x() - 0.5 * (a.x() + b.x()), dy = x.y() - 0.5 * (a.y() + b.y()),
                   dz = x.z() - 0.5 * (a.z() + b.z());
      const double limit = max_distance_factor * max_distance_factor * (b - a).squaredNorm();
      if (dx * dx + dy * dy + dz * dz <= limit) return {q(x), x};
    }
    return detail::simplification::best_of_ends(q, a, b);
  }
#if defined(__SSE2__)
  /// place(q_i, a_i, b_i).cost of two edges at once, q_i in lane i of q:
  /// where the minimizer is taken (the same operations as place(), lane by
  /// lane), cost[i] is set and bit i of the result; the other lanes (the
  /// fallback of place(), a few percent of the edges) are left to place().
  [[gnu::always_inline]] int place_costs(const Quadric_lanes& q, const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                                         const Eigen::Vector3d& a1, const Eigen::Vector3d& b1, double* cost) const {
    auto mul = [](__m128d x, __m128d y) { return _mm_mul_pd(x, y); };
    auto add = [](__m128d x, __m128d y) { return _mm_add_pd(x, y); };
    auto sub = [](__m128d x, __m128d y) { return _mm_sub_pd(x, y); };
    const __m128d sign = _mm_set1_pd(-0.0);
    // Quadric::minimizer.
    const __m128d c00 = sub(mul(q.a11, q.a22), mul(q.a12, q.a12)), c01 = sub(mul(q.a02, q.a12), mul(q.a01, q.a22)),
                  c02 = sub(mul(q.a01, q.a12), mul(q.a02, q.a11));
    const __m128d det = add(add(mul(q.a00, c00), mul(q.a01, c01)), mul(q.a02, c02));
    const __m128d r0 = add(add(mul(q.a00, q.a00), mul(q.a01, q.a01)), mul(q.a02, q.a02)),
                  r1 = add(add(mul(q.a01, q.a01), mul(q.a11, q.a11)), mul(q.a12, q.a12)),
                  r2 = add(add(mul(q.a02, q.a02), mul(q.a12, q.a12)), mul(q.a22, q.a22));
    __m128d ok = _mm_cmpgt_pd(_mm_andnot_pd(sign, det),
                              mul(_mm_set1_pd(conditioning), _mm_sqrt_pd(mul(mul(r0, r1), r2))));
    if (_mm_movemask_pd(ok) == 0) return 0;
    const __m128d c11 = sub(mul(q.a00, q.a22), mul(q.a02, q.a02)), c12 = sub(mul(q.a01, q.a02), mul(q.a00, q.a12)),
                  c22 = sub(mul(q.a00, q.a11), mul(q.a01, q.a01));
    const __m128d inv = _mm_div_pd(_mm_set1_pd(1.0), det);
    const __m128d x = mul(_mm_xor_pd(add(add(mul(c00, q.b0), mul(c01, q.b1)), mul(c02, q.b2)), sign), inv);
    const __m128d y = mul(_mm_xor_pd(add(add(mul(c01, q.b0), mul(c11, q.b1)), mul(c12, q.b2)), sign), inv);
    const __m128d z = mul(_mm_xor_pd(add(add(mul(c02, q.b0), mul(c12, q.b1)), mul(c22, q.b2)), sign), inv);
    const __m128d big = _mm_set1_pd(std::numeric_limits<double>::max());
    ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_andnot_pd(sign, x), big));
    ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_andnot_pd(sign, y), big));
    ok = _mm_and_pd(ok, _mm_cmple_pd(_mm_andnot_pd(sign, z), big));
    // place(): the distance to the midpoint (the limit's squared length by
    // the same Eigen expression).
    const __m128d half = _mm_set1_pd(0.5);
    const __m128d dx = sub(x, mul(half, add(_mm_set_pd(a1.x(), a0.x()), _mm_set_pd(b1.x(), b0.x())))),
                  dy = sub(y, mul(half, add(_mm_set_pd(a1.y(), a0.y()), _mm_set_pd(b1.y(), b0.y())))),
                  dz = sub(z, mul(half, add(_mm_set_pd(a1.z(), a0.z()), _mm_set_pd(b1.z(), b0.z()))));
    const double f = max_distance_factor * max_distance_factor;
    const __m128d limit = _mm_set_pd(f * (b1 - a1).squaredNorm(), f * (b0 - a0).squaredNorm());
    ok = _mm_and_pd(ok, _mm_cmple_pd(add(add(mul(dx, dx), mul(dy, dy)), mul(dz, dz)), limit));
    const int done = _mm_movemask_pd(ok);
    if (done == 0) return 0;
    // Quadric::operator().
    const __m128d ax = add(add(mul(q.a00, x), mul(q.a01, y)), mul(q.a02, z));
    const __m128d ay = add(add(mul(q.a01, x), mul(q.a11, y)), mul(q.a12, z));
    const __m128d az = add(add(mul(q.a02, x), mul(q.a12, y)), mul(q.a22, z));
    const __m128d two = _mm_set1_pd(2.0);
    const __m128d v = add(add(add(mul(x, add(ax, mul(two, q.b0))), mul(y, add(ay, mul(two, q.b1)))),
                              mul(z, add(az, mul(two, q.b2)))),
                          q.c);
    _mm_storeu_pd(cost, _mm_and_pd(_mm_cmpgt_pd(v, _mm_setzero_pd()), v)); // v > 0 ? v : 0
    return done;
  }
#endif
};

/// Probabilistic plane quadrics (Trettner & Kobbelt 2020, isotropic
/// Gaussian noise on each plane's point and normal). A = Σ(nnᵀ + σ_n² I) is
/// positive definite, so the minimizer always exists and is unique; it
/// stays close to the edge in flat regions where plane quadrics have none.
/// σ_p and σ_n are relative: σ_p = position_sigma × the mean edge length of
/// the input (set by simplify before the first face), σ_n = normal_sigma.
struct Probabilistic_quadrics {
  double position_sigma = 0.05; ///< × the input's mean edge length
  double normal_sigma = 0.05;   ///< radians, roughly: the normals' standard deviation
  bool area_weighted = false;
  double mean_edge_length = 1.0; ///< set by simplify from the input

  using Vertex_data = Quadric;

  Quadric face(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) const {
    Eigen::Vector3d n = triangle_normal(a, b, c);
    const double len = n.norm();
    if (!(len > 0)) return {};
    n /= len;
    return Quadric::probabilistic_plane(n, (a + b + c) / 3.0, position_sigma * mean_edge_length, normal_sigma,
                                        area_weighted ? 0.5 * len : 1.0);
  }
  Quadric border(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 double weight) const {
    return detail::simplification::border_plane(a, b, c, weight, area_weighted);
  }
  Placement place(const Quadric& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    Eigen::Vector3d x;
    if (q.minimizer(x, 1e-12)) return {q(x), x};
    return detail::simplification::best_of_ends(q, a, b);
  }
};

/// The shortest edge first, collapsed to its midpoint (cost: squared length).
/// Fast and shape-blind: a baseline, and the policy of uniform coarsening.
struct Edge_length {
  struct Vertex_data {};
  Vertex_data face(const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&) const { return {}; }
  Vertex_data border(const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&, double) const {
    return {};
  }
  Vertex_data merge(const Vertex_data&, const Vertex_data&) const { return {}; }
  Placement place(const Vertex_data&, const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return {(b - a).squaredNorm(), 0.5 * (a + b)};
  }
  Placement fixed(const Vertex_data&, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  const Eigen::Vector3d& x) const {
    return {(b - a).squaredNorm(), x};
  }
};

} // namespace genmesh
