// genmesh/detail/geometry/predicates.h — exact orientation predicates on double input.
//
// orient3d and orient2d return the exact sign of their determinant for every
// finite double input, from the subnormals to the largest doubles (0 for
// input that is not finite). A floating-point evaluation with Shewchuk's
// static error bound (Shewchuk 1997, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates"), widened by an absolute
// term for products that underflow, answers almost every call. The rest,
// nearly degenerate input only, is decided in integer arithmetic: a double
// is m·2^e with an integer m of at most 53 bits and −1074 ≤ e ≤ 971, so all
// coordinates along one axis are integers times the least of their 2^e, of
// at most 2098 bits; each term of the determinant takes one coordinate
// difference from every axis, so scaling the axes apart keeps the sign. The
// integers are fixed-size word arrays (a few words for mesh coordinates, 99
// at most): no allocation, no overflow, no underflow.
#pragma once

// The filters' error bounds and two_sum hold for IEEE double arithmetic as
// written; a multiply-add the compiler fuses only leaves out a product's
// rounding, which the bounds allow for, so the signs stay exact with
// -ffp-contract=fast (tests/test_flags.cpp). -ffast-math
// breaks them: reassociation turns two_sum's error term into 0 and moves
// roundings the bounds count, and finite-math-only folds the tests for NaN
// and infinity that predicates and placements rely on. geometry.h, and so
// every algorithm's header, includes this one. (README "Compiler flags".)
#if defined(__FAST_MATH__) || defined(_M_FP_FAST)
#error "genmesh needs IEEE floating point: -ffast-math (/fp:fast) is not supported (exact predicates, deterministic results; README \"Compiler flags\")"
#elif defined(__ASSOCIATIVE_MATH__)
#error "genmesh needs IEEE floating point: -fassociative-math (-funsafe-math-optimizations) is not supported: it breaks the exact predicates' error-free sums (README \"Compiler flags\")"
#elif defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "genmesh needs IEEE floating point: -ffinite-math-only is not supported: genmesh tests for NaN and infinity (README \"Compiler flags\")"
#endif

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace genmesh::detail::pred {

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline constexpr double eps = std::numeric_limits<double>::epsilon() / 2; // 2^-53
inline constexpr double o3d_bound = (7.0 + 56.0 * eps) * eps;
inline constexpr double o2d_bound = (3.0 + 16.0 * eps) * eps;
// A product that underflows is off by up to 2^-1075 however small it is,
// which no relative bound covers: the filters add 2^-1070 (32 such errors)
// per unit of the factors that multiply such a product afterwards, and per
// product itself.
inline constexpr double underflow_bound = 0x1p-1070;

namespace exact {

__extension__ using U128 = unsigned __int128;

// A signed integer of at most N 64-bit words: magnitude w[0, n) (least
// significant first, w[n − 1] ≠ 0), and sign; zero is n = 0. Words from n
// on are unset.
template <std::size_t N>
struct Int {
  std::array<std::uint64_t, N> w;
  std::size_t n = 0;
  bool negative = false;
};

// Words: a coordinate below 2^1024 in units of 2^-1074 is below 2^2098, a
// difference of two below 2^2099; a 2×2 minor below 2^4199; the 3×3
// determinant below 2^6300.
inline constexpr std::size_t difference_words = 33, minor_words = 66, determinant_words = 99;
static_assert(2099 <= 64 * difference_words && 4199 <= 64 * minor_words && 6300 <= 64 * determinant_words);

// |a| compared with |b|: −1, 0 or 1.
template <std::size_t A, std::size_t B>
int compare_magnitudes(const Int<A>& a, const Int<B>& b) {
  if (a.n != b.n) return a.n < b.n ? -1 : 1;
  for (std::size_t i = a.n; i-- > 0;)
    if (a.w[i] != b.w[i]) return a.w[i] < b.w[i] ? -1 : 1;
  return 0;
}

// r = a + b, or a − b if `subtract` (signed). R must hold the result (the
// callers' bounds above).
template <std::size_t R, std::size_t A, std::size_t B>
void add(const Int<A>& a, const Int<B>& b, Int<R>& r, bool subtract = false) {
  const bool b_negative = b.negative != subtract;
  if (a.negative == b_negative || a.n == 0 || b.n == 0) {
    const bool a_longer = a.n >= b.n;
    const std::uint64_t* lw = a_longer ? a.w.data() : b.w.data();
    const std::uint64_t* sw = a_longer ? b.w.data() : a.w.data();
    const std::size_t ln = a_longer ? a.n : b.n, sn = a_longer ? b.n : a.n;
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < ln; ++i) {
      const U128 s = static_cast<U128>(lw[i]) + (i < sn ? sw[i] : 0) + carry;
      r.w[i] = static_cast<std::uint64_t>(s);
      carry = static_cast<std::uint64_t>(s >> 64);
    }
    r.n = ln;
    if (carry != 0) r.w[r.n++] = carry;
    r.negative = a.n != 0 ? a.negative : b_negative;
    if (r.n == 0) r.negative = false;
    return;
  }
  // Opposite signs: the larger magnitude minus the smaller, with its sign.
  const int c = compare_magnitudes(a, b);
  if (c == 0) {
    r.n = 0;
    r.negative = false;
    return;
  }
  const std::uint64_t* lw = c > 0 ? a.w.data() : b.w.data();
  const std::uint64_t* sw = c > 0 ? b.w.data() : a.w.data();
  const std::size_t ln = c > 0 ? a.n : b.n, sn = c > 0 ? b.n : a.n;
  std::uint64_t borrow = 0;
  for (std::size_t i = 0; i < ln; ++i) {
    const std::uint64_t x = lw[i], y = i < sn ? sw[i] : 0;
    const std::uint64_t d = x - y - borrow;
    borrow = (x < y || (x == y && borrow != 0)) ? 1 : 0;
    r.w[i] = d;
  }
  r.n = ln;
  while (r.n > 0 && r.w[r.n - 1] == 0) --r.n;
  r.negative = c > 0 ? a.negative : b_negative;
}

// r = a · b; R ≥ A + B.
template <std::size_t R, std::size_t A, std::size_t B>
void multiply(const Int<A>& a, const Int<B>& b, Int<R>& r) {
  static_assert(R >= A + B);
  if (a.n == 0 || b.n == 0) {
    r.n = 0;
    r.negative = false;
    return;
  }
  std::fill(r.w.begin(), r.w.begin() + static_cast<std::ptrdiff_t>(a.n + b.n), std::uint64_t{0});
  for (std::size_t i = 0; i < a.n; ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.n; ++j) {
      const U128 t = static_cast<U128>(a.w[i]) * b.w[j] + r.w[i + j] + carry;
      r.w[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    r.w[i + b.n] = carry;
  }
  r.n = a.n + b.n;
  while (r.w[r.n - 1] == 0) --r.n;
  r.negative = a.negative != b.negative;
}

// A finite double as ±m·2^e, m odd (or 0); false if not finite.
struct Unpacked {
  std::uint64_t m = 0;
  int e = 0;
  bool negative = false;
};
inline bool unpack(double x, Unpacked& u) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0x7ff) return false;
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  u.negative = (bits >> 63) != 0;
  u.m = biased == 0 ? fraction : fraction | std::uint64_t{1} << 52;
  u.e = biased == 0 ? -1074 : biased - 1075;
  if (u.m == 0) return true;
  const int z = std::countr_zero(u.m);
  u.m >>= z;
  u.e += z;
  return true;
}

// r = u as an integer in units of 2^e0 (e0 ≤ u.e).
inline void integer(const Unpacked& u, int e0, Int<difference_words>& r) {
  r.n = 0;
  r.negative = false;
  if (u.m == 0) return;
  const int shift = u.e - e0, word = shift / 64, bit = shift % 64;
  std::fill(r.w.begin(), r.w.begin() + word, std::uint64_t{0});
  r.w[static_cast<std::size_t>(word)] = u.m << bit;
  r.n = static_cast<std::size_t>(word) + 1;
  if (bit != 0 && (u.m >> (64 - bit)) != 0) r.w[r.n++] = u.m >> (64 - bit);
  r.negative = u.negative;
}

// The differences x[i] − x[0] (i = 1 … K−1) of one axis's coordinates, as
// integers in the units of the finest of them; false if one is not finite.
template <std::size_t K>
bool axis_differences(const std::array<double, K>& x, std::array<Int<difference_words>, K - 1>& d) {
  std::array<Unpacked, K> u;
  int e0 = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < K; ++i) {
    if (!unpack(x[i], u[i])) return false;
    if (u[i].m != 0) e0 = std::min(e0, u[i].e);
  }
  Int<difference_words> origin, v;
  integer(u[0], e0, origin);
  for (std::size_t i = 1; i < K; ++i) {
    integer(u[i], e0, v);
    add(v, origin, d[i - 1], true);
  }
  return true;
}

// The exact signs, for the filters' undecided calls.
inline int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& d) {
  // dif[k][i]: axis k of (b, c, d)[i] − a.
  std::array<std::array<Int<difference_words>, 3>, 3> dif;
  for (int k = 0; k < 3; ++k)
    if (!axis_differences<4>({a[k], b[k], c[k], d[k]}, dif[k])) return 0;
  const auto &bx = dif[0][0], &cx = dif[0][1], &dx = dif[0][2];
  const auto &by = dif[1][0], &cy = dif[1][1], &dy = dif[1][2];
  const auto &bz = dif[2][0], &cz = dif[2][1], &dz = dif[2][2];
  // Cofactors along d, as the filter computes them.
  Int<minor_words> p, q, m;
  Int<determinant_words> t, s0, s1;
  multiply(by, cz, p);
  multiply(bz, cy, q);
  add(p, q, m, true);
  multiply(dx, m, s0);
  multiply(bz, cx, p);
  multiply(bx, cz, q);
  add(p, q, m, true);
  multiply(dy, m, t);
  add(s0, t, s1);
  multiply(bx, cy, p);
  multiply(by, cx, q);
  add(p, q, m, true);
  multiply(dz, m, t);
  add(s1, t, s0);
  return s0.n == 0 ? 0 : s0.negative ? -1 : 1;
}

inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  std::array<Int<difference_words>, 2> x, y;
  if (!axis_differences<3>({ax, bx, cx}, x) || !axis_differences<3>({ay, by, cy}, y)) return 0;
  Int<minor_words> l, r, det;
  multiply(x[0], y[1], l);
  multiply(y[0], x[1], r);
  add(l, r, det, true);
  return det.n == 0 ? 0 : det.negative ? -1 : 1;
}

} // namespace exact

/// Sign of (b − a) × (c − a) · (d − a): +1 when d lies on the side the
/// normal of the counter-clockwise triangle a, b, c points to. Exact for
/// finite input; 0 if a coordinate is not finite.
inline int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& d) {
  const double bx = b.x() - a.x(), by = b.y() - a.y(), bz = b.z() - a.z();
  const double cx = c.x() - a.x(), cy = c.y() - a.y(), cz = c.z() - a.z();
  const double dx = d.x() - a.x(), dy = d.y() - a.y(), dz = d.z() - a.z();
  const double m1 = by * cz - bz * cy, m2 = bz * cx - bx * cz, m3 = bx * cy - by * cx;
  const double det = dx * m1 + dy * m2 + dz * m3;
  const double adx = std::abs(dx), ady = std::abs(dy), adz = std::abs(dz);
  const double perm = adx * (std::abs(by * cz) + std::abs(bz * cy)) + ady * (std::abs(bz * cx) + std::abs(bx * cz)) +
                      adz * (std::abs(bx * cy) + std::abs(by * cx));
  // Each minor's two products may underflow (2^-1075 each), then be
  // multiplied by d's difference; the outer three products may too.
  const double bound = o3d_bound * perm + (adx + ady + adz + 1) * underflow_bound;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // Exactly zero when every monomial of the determinant has a zero factor
  // (a difference is zero only where the coordinates are equal): repeated
  // points and shared corners, the common degenerate calls.
  auto zero = [](double u, double v) { return u == 0 || v == 0; };
  if ((dx == 0 || (zero(by, cz) && zero(bz, cy))) && (dy == 0 || (zero(bz, cx) && zero(bx, cz))) &&
      (dz == 0 || (zero(bx, cy) && zero(by, cx))))
    return 0;
  return exact::orient3d(a, b, c, d);
}

/// Sign of (b − a) × (c − a) for 2D points (x, y): +1 counter-clockwise.
/// Exact for finite input; 0 if a coordinate is not finite. Inlined: the
/// filter is a few instructions, and the guard calls it in its inner loops.
[[gnu::always_inline]] inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
  const double l = ux * vy, r = uy * vx;
  const double det = l - r;
  const double bound = o2d_bound * (std::abs(l) + std::abs(r)) + underflow_bound;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  if ((ux == 0 || vy == 0) && (uy == 0 || vx == 0)) return 0;
  return exact::orient2d(ax, ay, bx, by, cx, cy);
}

} // namespace genmesh::detail::pred
