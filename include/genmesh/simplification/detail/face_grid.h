// genmesh/simplification/detail/face_grid.h — a dynamic spatial hash of face
// bounding boxes (private; the self-intersection guard of simplify).
//
// A uniform grid of cubic cells, stored sparsely (an open-addressing table
// of cell key → entries). A face is listed in every cell its box overlaps;
// each entry carries what a query needs to pass over it without reading
// the face: the part of the box inside the cell in 16 bins an axis, on
// which axes the box starts in this cell (so that a query takes each face
// once, without marking the faces it has seen), and the face's version.
// A face that changed is listed again with its new box (insert()), which
// makes its older entries stale (their version is old); queries drop the
// stale entries they walk over. The caller rebuilds the grid with a larger
// cell when faces have grown (simplify: whenever the face count quarters;
// compact() at the halvings between).
#pragma once

#include <genmesh/detail/branchless.h>
#include <genmesh/detail/memory/huge_pages.h>
#include <genmesh/detail/prefetch.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

namespace genmesh::detail::simplification {

struct Box {
  Eigen::Vector3d lo, hi;
  static Box of(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
  }
  // Without a branch (the six comparisons combined by &): the guard's
  // candidates test their boxes against each new face's, which goes either
  // way (until session 15 with &&; shark → 10 %, guarded, Halfedge_mesh:
  // 2-3 % slower, 1.2 % fewer instructions).
  bool overlaps(const Box& o) const {
    return genmesh::detail::all_true(lo.x() <= o.hi.x(), o.lo.x() <= hi.x(), lo.y() <= o.hi.y(), o.lo.y() <= hi.y(),
                                     lo.z() <= o.hi.z(), o.lo.z() <= hi.z());
  }
};

// Up to 64 boxes by coordinate: which of them a box meets, as a bit mask
// (bit i: box i), the same as Box::overlaps box by box; where SSE2 is
// there, two boxes a step (the guard's candidates against the new faces'
// boxes: until session 17 one box at a time, six scalar compares).
class Box_set {
 public:
  static constexpr std::size_t capacity = 64;
  // Boxes b[0, n), n at most capacity.
  void assign(const Box* b, std::size_t n) {
    n_ = n;
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        c_[k][i] = b[i].lo[k];
        c_[3 + k][i] = b[i].hi[k];
      }
    if (n % 2 != 0)
      for (auto& c : c_) c[n] = 0; // read, never reported (see meets)
  }
  std::size_t size() const { return n_; }
  std::uint64_t meets(const Box& b) const {
    std::uint64_t m = 0;
#if defined(__SSE2__)
    const __m128d lx = _mm_set1_pd(b.lo.x()), ly = _mm_set1_pd(b.lo.y()), lz = _mm_set1_pd(b.lo.z());
    const __m128d hx = _mm_set1_pd(b.hi.x()), hy = _mm_set1_pd(b.hi.y()), hz = _mm_set1_pd(b.hi.z());
    for (std::size_t i = 0; i < n_; i += 2) {
      const __m128d x = _mm_and_pd(_mm_cmple_pd(lx, _mm_load_pd(&c_[3][i])), _mm_cmple_pd(_mm_load_pd(&c_[0][i]), hx));
      const __m128d y = _mm_and_pd(_mm_cmple_pd(ly, _mm_load_pd(&c_[4][i])), _mm_cmple_pd(_mm_load_pd(&c_[1][i]), hy));
      const __m128d z = _mm_and_pd(_mm_cmple_pd(lz, _mm_load_pd(&c_[5][i])), _mm_cmple_pd(_mm_load_pd(&c_[2][i]), hz));
      m |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_and_pd(_mm_and_pd(x, y), z))) << i;
    }
    // The padding's bit (n odd).
    return n_ == capacity ? m : m & ((std::uint64_t{1} << n_) - 1);
#else
    for (std::size_t i = 0; i < n_; ++i)
      m |= static_cast<std::uint64_t>((b.lo.x() <= c_[3][i]) & (c_[0][i] <= b.hi.x()) & (b.lo.y() <= c_[4][i]) &
                                      (c_[1][i] <= b.hi.y()) & (b.lo.z() <= c_[5][i]) & (c_[2][i] <= b.hi.z()))
           << i;
    return m;
#endif
  }

 private:
  std::size_t n_ = 0;
  alignas(16) double c_[6][capacity]; // lo x, y, z, hi x, y, z
};

// A face listed in a grid cell: its slot, its version when listed (5 bits)
// and on which axes its range starts at this cell (3 bits), and per axis
// the bins of the cell (16 a side) its box covers there (lo << 4 | hi).
// (Face_grid::for_cells describes a cell of a box in one, without face or
// version.)
struct Grid_entry {
  std::uint32_t face;
  std::uint8_t flags;
  std::uint8_t x, y, z;
};
// grid_flags_and_bins reads the bytes after the face as one word, and the
// vector walk four entries as two 16-byte loads.
static_assert(sizeof(Grid_entry) == 8 && offsetof(Grid_entry, flags) == 4 && offsetof(Grid_entry, x) == 5 &&
              offsetof(Grid_entry, y) == 6 && offsetof(Grid_entry, z) == 7);

// flags | x << 8 | y << 16 | z << 24: on a little-endian machine the
// upper half of the entry's bytes, one shift (the fields one by one
// cost the walk a dozen instructions an entry).
inline std::uint32_t grid_flags_and_bins(const Grid_entry& e) {
  if constexpr (std::endian::native == std::endian::little)
    return static_cast<std::uint32_t>(std::bit_cast<std::uint64_t>(e) >> 32);
  else
    return e.flags | std::uint32_t{e.x} << 8 | std::uint32_t{e.y} << 16 | std::uint32_t{e.z} << 24;
}

// What a query asks of a cell's entries: the axes (flags) on which an
// entry's range must start in the cell (those where the query's does
// not), and the query's bins, a byte an axis, as `hi` (its upper bins |
// 0x10 each) and `lo` (its lower bins). An entry's bins meet the query's
// on every axis iff each byte of
//   (hi − entry's lower bins) & ((entry's upper bins | 0x10) − lo)
// has bit 4 set (16 + a − b ≥ 16 iff a ≥ b; no borrow crosses a byte).
struct Grid_probe {
  std::uint32_t need, hi, lo;
};

inline bool grid_meets(const Grid_entry& e, const Grid_probe& q) {
  const std::uint32_t u = grid_flags_and_bins(e), w = u >> 8;
  const std::uint32_t t = (q.hi - ((w >> 4) & 0x0f0f0fu)) & (((w & 0x0f0f0fu) | 0x101010u) - q.lo);
  return (u & q.need) == q.need && (t & 0x101010u) == 0x101010u;
}

// Copies the entries of [e, e + n) that meet q to out (room for n), in
// order; returns how many. Without a branch on the test, which goes
// either way at random (a seventh of a walk's entries meet). The
// reference; grid_select_sse2 gives the same.
inline std::size_t grid_select_scalar(const Grid_entry* e, std::size_t n, const Grid_probe& q, Grid_entry* out) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    out[k] = e[i];
    k += grid_meets(e[i], q);
  }
  return k;
}

#if defined(__SSE2__)
// grid_select_scalar four entries at a time: their words of flags and
// bins gathered from two loads into one register, tested together (shark
// → 10 %, guarded, Halfedge_mesh: 7 % faster, 5.6 % fewer instructions).
inline std::size_t grid_select_sse2(const Grid_entry* e, std::size_t n, const Grid_probe& q, Grid_entry* out) {
  static_assert(std::endian::native == std::endian::little);
  // Each entry's bins tested where they are in its word (bytes 1-3; byte
  // 0 the flags), and the start flags in the same compare (until session
  // 17 the word shifted down a byte first and two compares; shark → 10 %,
  // guarded, Surface_mesh: 0.4 % fewer instructions in all).
  const __m128i hi = _mm_set1_epi32(static_cast<int>(q.hi << 8)), lo = _mm_set1_epi32(static_cast<int>(q.lo << 8));
  const __m128i need = _mm_set1_epi32(static_cast<int>(q.need));
  const __m128i low4 = _mm_set1_epi32(0x0f0f0f00), want = _mm_set1_epi32(static_cast<int>(0x10101000u | q.need)),
                bit4 = _mm_set1_epi32(0x10101000);
  std::size_t i = 0, k = 0;
  for (; i + 4 <= n; i += 4) {
    const __m128 a = _mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(e + i)));
    const __m128 b = _mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(e + i + 2)));
    // The odd 32-bit words: each entry's flags and bins (little-endian).
    const __m128i u = _mm_castps_si128(_mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1)));
    const __m128i t = _mm_and_si128(_mm_sub_epi32(hi, _mm_and_si128(_mm_srli_epi32(u, 4), low4)),
                                    _mm_sub_epi32(_mm_or_si128(_mm_and_si128(u, low4), bit4), lo));
    const __m128i ok = _mm_cmpeq_epi32(_mm_or_si128(_mm_and_si128(t, bit4), _mm_and_si128(u, need)), want);
    const unsigned m = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(ok)));
    out[k] = e[i];
    k += m & 1;
    out[k] = e[i + 1];
    k += (m >> 1) & 1;
    out[k] = e[i + 2];
    k += (m >> 2) & 1;
    out[k] = e[i + 3];
    k += m >> 3;
  }
  return k + grid_select_scalar(e + i, n - i, q, out + k);
}
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GENMESH_GRID_SELECT_AVX512 1
// grid_select_scalar eight entries at a time, where the processor has
// AVX-512 (chosen at run time: see grid_select): each entry a 64-bit lane,
// its word of flags and bins shifted down and tested as in
// grid_select_sse2, the entries that pass packed in a register (compress)
// and written with a masked store (a compress straight to memory is slow
// on some processors); the last 0-7 entries by a masked load.
[[gnu::target("avx512f")]] inline std::size_t grid_select_avx512(const Grid_entry* e, std::size_t n,
                                                                 const Grid_probe& q, Grid_entry* out) {
  static_assert(std::endian::native == std::endian::little);
  const __m512i hi = _mm512_set1_epi64(q.hi), lo = _mm512_set1_epi64(q.lo), need = _mm512_set1_epi64(q.need);
  const __m512i low4 = _mm512_set1_epi64(0x0f0f0f), bit4 = _mm512_set1_epi64(0x101010),
                want = _mm512_set1_epi64(0x101010 | q.need), byte = _mm512_set1_epi64(0xff);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; i += 8) {
    const __mmask8 in = n - i >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << (n - i)) - 1);
    const __m512i v = _mm512_maskz_loadu_epi64(in, e + i);
    const __m512i u = _mm512_maskz_srli_epi64(0xff, v, 32); // flags | x << 8 | y << 16 | z << 24
    const __m512i w = _mm512_maskz_srli_epi64(0xff, u, 8), f = _mm512_and_si512(u, byte);
    const __m512i t = _mm512_and_si512(_mm512_sub_epi64(hi, _mm512_and_si512(_mm512_maskz_srli_epi64(0xff, w, 4), low4)),
                                       _mm512_sub_epi64(_mm512_or_si512(_mm512_and_si512(w, low4), bit4), lo));
    const __m512i ok = _mm512_or_si512(_mm512_and_si512(t, bit4), _mm512_and_si512(f, need));
    const __mmask8 m = _mm512_mask_cmpeq_epi64_mask(in, ok, want);
    const unsigned c = static_cast<unsigned>(__builtin_popcount(m));
    _mm512_mask_storeu_epi64(out + k, static_cast<__mmask8>((1u << c) - 1), _mm512_maskz_compress_epi64(m, v));
    k += c;
  }
  return k;
}
// Keeps the entries of [e, e + n) whose version (version[face] but its
// `hidden` bit 0x40) is theirs, in order, at the front; returns how many.
// Face_grid::drop_stale's loop, eight entries at a time: the versions
// gathered, each the low byte of the 8-byte word at version + face (the
// grid keeps seven bytes after the last face's). (Session 19, with the
// select above: 832k armadillo → 10 %, guarded, Halfedge_mesh: ~2-3 %
// faster; shark → 10 %, Surface_mesh: ~2 %.)
[[gnu::target("avx512f")]] inline std::size_t grid_drop_stale_avx512(Grid_entry* e, std::size_t n,
                                                                    const std::uint8_t* version) {
  const __m512i face = _mm512_set1_epi64(0xffffffff), shown = _mm512_set1_epi64(0xbf),
                five = _mm512_set1_epi64(31);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; i += 8) {
    const __mmask8 in = n - i >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << (n - i)) - 1);
    const __m512i v = _mm512_maskz_loadu_epi64(in, e + i);
    const __m512i ver =
        _mm512_and_si512(_mm512_mask_i64gather_epi64(_mm512_setzero_si512(), in, _mm512_and_si512(v, face), version, 1), shown);
    const __mmask8 live = _mm512_mask_cmpeq_epi64_mask(in, ver, _mm512_and_si512(_mm512_maskz_srli_epi64(0xff, v, 35), five));
    const unsigned c = static_cast<unsigned>(__builtin_popcount(live));
    // (Written at or below the eight just read.)
    _mm512_mask_storeu_epi64(e + kept, static_cast<__mmask8>((1u << c) - 1), _mm512_maskz_compress_epi64(live, v));
    kept += c;
  }
  return kept;
}

inline bool grid_select_has_avx512() {
  static const bool has = __builtin_cpu_supports("avx512f");
  return has;
}
#endif

// grid_select_scalar, eight entries at a time where the processor has
// AVX-512, else four at a time where SSE2 is there.
inline std::size_t grid_select(const Grid_entry* e, std::size_t n, const Grid_probe& q, Grid_entry* out) {
#if defined(GENMESH_GRID_SELECT_AVX512)
  if (grid_select_has_avx512()) return grid_select_avx512(e, n, q, out);
#endif
#if defined(__SSE2__)
  return grid_select_sse2(e, n, q, out);
#else
  return grid_select_scalar(e, n, q, out);
#endif
}

class Face_grid {
 public:
  // A point in grid units: per axis its cell × 16 + its bin in the cell
  // (see Axis), 20 bits; monotone in the coordinates, so that a box's
  // corners in grid units are those of its corners.
  using Point = std::array<std::uint32_t, 3>;
  Point quantize(const Eigen::Vector3d& p) const { return {unit(p.x()), unit(p.y()), unit(p.z())}; }
  // A box's corners in grid units, the same as quantize(b.lo), quantize(b.hi):
  // where SSE2 is there, the six coordinates two at a time (session 15;
  // shark → 10 %, guarded, Halfedge_mesh: unit() took ~20 instructions a
  // coordinate; 2.6 % fewer instructions in all, the time within noise).
  void quantize(const Box& b, Point& lo, Point& hi) const {
#if defined(__SSE2__)
    const __m128i a = units(_mm_loadu_pd(b.lo.data())), c = units(_mm_set_pd(b.hi.x(), b.lo.z())),
                  d = units(_mm_loadu_pd(b.hi.data() + 1));
    alignas(16) std::uint32_t u[8];
    _mm_store_si128(reinterpret_cast<__m128i*>(u), _mm_unpacklo_epi64(a, c));
    _mm_store_si128(reinterpret_cast<__m128i*>(u + 4), d);
    lo = {u[0], u[1], u[2]};
    hi = {u[3], u[4], u[5]};
#else
    lo = quantize(b.lo);
    hi = quantize(b.hi);
#endif
  }
  // quantize(p), where SSE2 is there two coordinates at a time (what
  // simplify's update_grid asks of every corner around a survivor).
  Point units(const Eigen::Vector3d& p) const {
#if defined(__SSE2__)
    return point_of(units_of(p));
#else
    return quantize(p);
#endif
  }

  // Per axis, whether a lies below b (bit i) or above it (bit 4 + i).
  static std::uint32_t sides(const Point& a, const Point& b) {
#if defined(__SSE2__)
    return sides(lanes(a), lanes(b));
#else
    std::uint32_t m = 0;
    for (int i = 0; i < 3; ++i) m |= std::uint32_t{a[i] < b[i]} << i | std::uint32_t{a[i] > b[i]} << (4 + i);
    return m;
#endif
  }
  // units(p), and sides(a, units(p)) in `s` (scalar, sides() took ~40
  // instructions; the compares packed where SSE2 is there).
  Point units(const Eigen::Vector3d& p, const Point& a, std::uint32_t& s) const {
#if defined(__SSE2__)
    const __m128i u = units_of(p);
    s = sides(lanes(a), u);
    return point_of(u);
#else
    const Point u = quantize(p);
    s = sides(a, u);
    return u;
#endif
  }

  // Cells of size `cell`; faces (slots) numbered below `faces`.
  void reset(double cell, std::size_t faces) {
    inv_ = cell > 0 ? 1.0 / cell : 1.0;
    table_ = {};
    used_ = 0;
    // (Seven bytes more: the vector walk reads a face's version as the
    // first byte of an 8-byte word; never written.)
    faces_ = faces;
    version_.assign(faces + 7, 0);
    version_.shrink_to_fit();
    // Grown at load 1/2 from a small table: a cell lists about 80 faces at
    // the first build (832k armadillo: 15k cells), so a table sized from the
    // face count (faces / 16, until session 10) was a quarter full, 2 MB.
    table_.resize(16);
    fresh_ = true;
  }

  // Cuts every cell's list to its size (after a build: what the growth
  // policy reserved beyond it).
  void shrink_to_fit() {
    for (Bucket& b : table_)
      if (b.key != empty) b.list.shrink_to_fit();
  }

  // Drops every cell's stale entries and cuts its list to size: the memory
  // a rebuild would free, without listing the faces again.
  void compact() {
    for (Bucket& b : table_)
      if (b.key != empty) {
        drop_stale(b);
        b.list.shrink_to_fit();
      }
  }

  // Lists f with box b in every cell b overlaps; entries listed for f
  // before become stale (queries drop them).
  void insert(std::uint32_t f, const Box& b) {
    Point lo, hi;
    quantize(b, lo, hi);
    insert(f, lo, hi);
  }
  // The same for the box with corners lo, hi in grid units.
  void insert(std::uint32_t f, const Point& lo, const Point& hi) {
    const std::uint8_t v = bump(f);
    // Most boxes lie in one cell (shark → 10 %: 19.0k of 33.6k): its key
    // and entry without for_cells' loops.
    if (((lo[0] ^ hi[0]) | (lo[1] ^ hi[1]) | (lo[2] ^ hi[2])) < 16) {
      auto bins = [&](int i) { return static_cast<std::uint8_t>((lo[i] & 15) << 4 | (hi[i] & 15)); };
      append(cell(key(lo[0] >> 4, lo[1] >> 4, lo[2] >> 4)),
             {f, static_cast<std::uint8_t>(v << 3 | 7), bins(0), bins(1), bins(2)});
      return;
    }
    for_cells(lo, hi, [&](std::uint64_t k, const Entry& e) {
      append(cell(k), {f, static_cast<std::uint8_t>(v << 3 | e.flags), e.x, e.y, e.z});
    });
  }

  // f is gone for good: its entries become stale, and no query returns it
  // again (its version is `gone`, which no entry has).
  void remove(std::uint32_t f) {
    version_[f] = gone;
    fresh_ = false;
  }

  // Until show(f), queries pass over f's entries (which stay current: a
  // bit of its version that no entry has, which the stale test ignores).
  // The guard hides the faces around the collapsing edge's ends, which it
  // knows from its walk: a query dropped them as it found them, by their
  // corners, read from the mesh (until session 16; shark → 10 %, guarded,
  // a quarter of the faces found).
  void hide(std::uint32_t f) { version_[f] |= hidden; }
  void show(std::uint32_t f) { version_[f] &= static_cast<std::uint8_t>(~hidden); }

  // Whether query() reads the cells' lists ahead (see there): not where
  // the grid stays in cache, where the reads are instructions only (simplify:
  // with its walks ahead, below 20k faces; the shark → 10 %, guarded,
  // Halfedge_mesh: 1.2 % faster, 0.7 % fewer instructions without).
  void read_ahead(bool on) { read_ahead_ = on; }

  // The face indices the grid was reset for.
  std::size_t face_bound() const { return faces_; }

  // Appends to `out` every face (but the hidden ones) listed in a cell b overlaps whose box's
  // part in that cell may meet b's, each face once (in the cell holding the
  // lowest corner of the two boxes' intersection, where both are listed);
  // may append a face whose box misses b (the bins are conservative), never
  // misses one whose box meets b. Drops the stale entries of a cell it walks
  // once the cell has grown by a quarter since they were last dropped
  // (reading every entry's version is a third of the walk's time).
  void query(const Box& b, std::vector<std::uint32_t>& out) {
    Point lo, hi;
    quantize(b, lo, hi);
    // The cells' lists first, a read a line: the walk below runs a dozen
    // instructions an entry and has only a few lines in flight; these reads
    // have them all (832k armadillo → 10 %: the walk took ~60 % of its time
    // waiting on its entries; prefetch hints here did not help).
    // Not where the grid stays in cache (read_ahead).
    if (read_ahead_) {
      for_keys(lo, hi, [&](std::uint64_t k) {
        const Bucket* c = find(k);
        if (c == nullptr) return;
        const char* at = reinterpret_cast<const char*>(c->list.data());
        const char* end = reinterpret_cast<const char*>(c->list.data() + c->list.size());
        for (; at < end; at += 64) genmesh::detail::touch(at);
      });
    }
    for_cells(lo, hi, [&](std::uint64_t key, const Entry& q) {
      Bucket* c = find(key);
      if (c == nullptr) return;
      // A face may be taken here if, on each axis, its box or the query's
      // starts in this cell (see above).
      const std::uint32_t qw = q.x | q.y << 8 | q.z << 16;
      const Grid_probe probe{static_cast<std::uint32_t>(7 & ~q.flags), (qw & 0x0f0f0fu) | 0x101010u,
                             (qw >> 4) & 0x0f0f0fu};
      auto& list = c->list;
      // The stale entries first, when the list has grown by a quarter since
      // they were last dropped: then the one walk below (until session 15
      // a walk of its own that dropped them as it tested the bins; shark
      // guarded, Halfedge_mesh: 2 % slower, 0.3 % fewer instructions).
      // (By an eighth until session 18: Collapser::run, shark sm 132.55M →
      // 132.18M instructions, 208k he 2.892G → 2.884G, 832k he 11.680G →
      // 11.643G, -0.3 % each; a sixteenth +1.2 % on the shark, a half
      // +0.3 %, never (append() alone) +0.5 %.)
      if (list.size() > c->clean + c->clean / 4) drop_stale(*c);
      // The entries whose bins meet the query's, then the versions of
      // those, reads that the processor overlaps.
      if (hits_.size() < list.size()) {
        hits_.resize(list.size());
        found_.resize(list.size());
      }
      const std::size_t n = grid_select(list.data(), list.size(), probe, hits_.data());
      // The current ones (not stale, not hidden), without a branch on the
      // test, which goes either way: half the hits are stale or hidden
      // (until session 16 pushed one by one after a branch; shark → 10 %,
      // guarded, Surface_mesh: 48k of the run's 1.13M mispredicted branches
      // fewer (callgrind --branch-sim), 0.3 % fewer instructions).
      std::uint32_t* const found = found_.data();
      std::size_t k = 0;
      for (std::size_t i = 0; i < n; ++i) {
        found[k] = hits_[i].face;
        k += current(hits_[i]);
      }
      out.insert(out.end(), found, found + k);
    });
  }

 private:
  using Entry = Grid_entry;
  struct Bucket {
    std::uint64_t key = empty;
    std::vector<Entry> list;
    std::uint32_t clean = 0; // the list's size when its stale entries were last dropped
  };
  static constexpr std::uint64_t empty = ~std::uint64_t{0};
  static constexpr std::uint8_t gone = 0x80; // a removed face's version: above every entry's (5 bits)
  static constexpr std::uint8_t hidden = 0x40; // or'ed into a hidden face's version (see hide)


  bool current(const Entry& e) const { return version_[e.face] == e.flags >> 3; }
  // The same, but true for a hidden face's current entries.
  bool live(const Entry& e) const { return (version_[e.face] & ~hidden) == e.flags >> 3; }

  void append(Bucket& c, const Entry& e) {
    auto& list = c.list;
    // A full list drops its stale entries before it grows: cells that no
    // query walks (where the guard decides without searching) would
    // otherwise keep every face's every listing. Then it keeps room for a
    // quarter more than its live entries, not twice (832k → 10%: 3 MB less
    // at the peak, no slower): until session 15 it grew only when no entry
    // was stale, so a drop that freed a few came again a few inserts later
    // (shark → 10 %, guarded, Halfedge_mesh: 386k entries read by these
    // drops, 1.2 % of the run's instructions, 1.5 % faster without).
    if (list.size() == list.capacity()) {
      if (!fresh_) drop_stale(c);
      list.reserve(list.size() + list.size() / 4 + 4);
    }
    list.push_back(e);
  }

  void drop_stale(Bucket& c) const {
#if defined(GENMESH_GRID_SELECT_AVX512)
    if (grid_select_has_avx512()) {
      const std::size_t kept = grid_drop_stale_avx512(c.list.data(), c.list.size(), version_.data());
      c.list.resize(kept);
      c.clean = static_cast<std::uint32_t>(kept);
      return;
    }
#endif
    // Without a branch on the version test, which goes either way.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < c.list.size(); ++i) {
      const Entry e = c.list[i];
      c.list[kept] = e;
      kept += live(e);
    }
    c.list.resize(kept);
    c.clean = static_cast<std::uint32_t>(kept);
  }

  std::uint8_t bump(std::uint32_t f) {
    fresh_ &= version_[f] == 0;
    return version_[f] = static_cast<std::uint8_t>((version_[f] + 1) & 31);
  }

  // Calls f(key, cell) for every cell the box [lo, hi] (grid units)
  // overlaps, where cell.flags says on which axes its range starts at this
  // cell (bit 0: x, 1: y, 2: z) and cell.x, .y, .z are the bins of the cell
  // it covers (see Axis).
  template <class F>
  void for_cells(const Point& lo, const Point& hi, F&& f) const {
    const Axis ax = axis(lo[0], hi[0]), ay = axis(lo[1], hi[1]), az = axis(lo[2], hi[2]);
    Entry e{};
    for (std::uint32_t x = ax.c0; x <= ax.c1; ++x) {
      e.x = ax.bins(x);
      const int sx = x == ax.c0;
      for (std::uint32_t y = ay.c0; y <= ay.c1; ++y) {
        e.y = ay.bins(y);
        const int sy = y == ay.c0;
        for (std::uint32_t z = az.c0; z <= az.c1; ++z) {
          e.z = az.bins(z);
          e.flags = static_cast<std::uint8_t>(sx | sy << 1 | (z == az.c0) << 2);
          f(key(x, y, z), e);
        }
      }
    }
  }

  // Calls f(key) for every cell the box [lo, hi] (grid units) overlaps.
  template <class F>
  void for_keys(const Point& lo, const Point& hi, F&& f) const {
    const Axis ax = axis(lo[0], hi[0]), ay = axis(lo[1], hi[1]), az = axis(lo[2], hi[2]);
    for (std::uint32_t x = ax.c0; x <= ax.c1; ++x)
      for (std::uint32_t y = ay.c0; y <= ay.c1; ++y)
        for (std::uint32_t z = az.c0; z <= az.c1; ++z) f(key(x, y, z));
  }

  // One axis of a box: its cells [c0, c1] (16 bits, clamped: a mesh wider
  // than 65,536 cells only gets longer lists in its outer cells) and the
  // bins (16 a cell) of its ends in them. bins(c): the bins [lo, hi] of
  // cell c that the box covers, lo << 4 | hi; monotone in the coordinates,
  // so that the bins of two intervals that meet meet.
  struct Axis {
    std::uint32_t c0, c1;
    std::uint8_t b0, b1;
    std::uint8_t bins(std::uint32_t c) const {
      return static_cast<std::uint8_t>((c == c0 ? b0 : 0) << 4 | (c == c1 ? b1 : 15));
    }
  };
  static Axis axis(std::uint32_t lo, std::uint32_t hi) {
    return {lo >> 4, hi >> 4, static_cast<std::uint8_t>(lo & 15), static_cast<std::uint8_t>(hi & 15)};
  }
#if defined(__SSE2__)
  // p in four 32-bit lanes, z twice.
  static __m128i lanes(const Point& p) {
    return _mm_setr_epi32(static_cast<int>(p[0]), static_cast<int>(p[1]), static_cast<int>(p[2]), static_cast<int>(p[2]));
  }
  // sides() of a point in four lanes as lanes() gives them: grid units are
  // below 2^20, so that the signed compares order them; lane 3 repeats
  // lane 2 (z), and its bits (3, 7) are cleared.
  static std::uint32_t sides(__m128i a, __m128i b) {
    const __m128i below = _mm_cmplt_epi32(a, b), above = _mm_cmpgt_epi32(a, b);
    return static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_packs_epi16(_mm_packs_epi32(below, above), _mm_setzero_si128()))) & 0x77u;
  }
  // p in grid units in four lanes as lanes() gives them (z twice), and back.
  __m128i units_of(const Eigen::Vector3d& p) const {
    return _mm_unpacklo_epi64(units(_mm_loadu_pd(p.data())), units(_mm_set1_pd(p.z())));
  }
  static Point point_of(__m128i u) {
    alignas(16) std::uint32_t w[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(w), u);
    return {w[0], w[1], w[2]};
  }
  // unit() of the two lanes of x, in the low two 32-bit lanes.
  __m128i units(__m128d x) const {
    // floor(s) + 16 half clamped into [0, 32 half) is floor(s') + 16 half
    // with s' = s clamped into [−16 half, 16 half − 1] (int32 range); max
    // first, which takes the bound where s is NaN (as unit() ends at 0).
    const __m128d least = _mm_set1_pd(-16.0 * half), most = _mm_set1_pd(16.0 * half - 1);
    const __m128d s = _mm_min_pd(_mm_max_pd(_mm_mul_pd(_mm_mul_pd(x, _mm_set1_pd(inv_)), _mm_set1_pd(16.0)), least), most);
    const __m128i t = _mm_cvttpd_epi32(s); // toward zero, in the low two lanes
    // −1 where the truncation rounded up (s < 0, not whole): the 64-bit
    // masks' low halves into the low two lanes.
    const __m128i up = _mm_shuffle_epi32(_mm_castpd_si128(_mm_cmpgt_pd(_mm_cvtepi32_pd(t), s)), _MM_SHUFFLE(3, 3, 2, 0));
    return _mm_add_epi32(_mm_add_epi32(t, up), _mm_set1_epi32(static_cast<int>(16 * half)));
  }
#endif
  // x in grid units: ⌊16 x / cell⌋ offset by half the cells' range,
  // clamped into it (the cell ⌊x / cell⌋ and the bin ⌊16 (x / cell −
  // cell)⌋ in one; until session 13 computed apart, as a floor and a
  // difference, with the same results).
  std::uint32_t unit(double x) const {
    // floor without the library call (s clamped into int64's range first).
    const double s = std::clamp(x * inv_ * 16.0, -32.0 * half, 32.0 * half);
    std::int64_t t = static_cast<std::int64_t>(s);
    t -= static_cast<double>(t) > s;
    return static_cast<std::uint32_t>(std::clamp<std::int64_t>(t + 16 * half, 0, 32 * half - 1));
  }
  static constexpr std::int64_t half = std::int64_t{1} << 15;

  static std::uint64_t key(std::uint64_t x, std::uint64_t y, std::uint64_t z) { return x << 32 | y << 16 | z; }

  static std::size_t hash(std::uint64_t k) { return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 32); }

  // Open addressing, linear probing.
  Bucket* find(std::uint64_t k) { return const_cast<Bucket*>(std::as_const(*this).find(k)); }
  const Bucket* find(std::uint64_t k) const {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(k) & mask;; i = (i + 1) & mask) {
      if (table_[i].key == k) return &table_[i];
      if (table_[i].key == empty) return nullptr;
    }
  }
  Bucket& cell(std::uint64_t k) {
    std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(k) & mask;; i = (i + 1) & mask) {
      if (table_[i].key == k) return table_[i];
      if (table_[i].key == empty) {
        if (2 * (used_ + 1) > table_.size()) {
          grow();
          return cell(k);
        }
        ++used_;
        table_[i].key = k;
        return table_[i];
      }
    }
  }
  void grow() {
    huge_page_vector<Bucket> old(table_.size() * 2);
    old.swap(table_);
    const std::size_t mask = table_.size() - 1;
    for (auto& b : old) {
      if (b.key == empty) continue;
      std::size_t i = hash(b.key) & mask;
      while (table_[i].key != empty) i = (i + 1) & mask;
      table_[i].key = b.key;
      table_[i].list = std::move(b.list);
      table_[i].clean = b.clean;
    }
  }

  double inv_ = 1.0;
  huge_page_vector<Bucket> table_; // big ones on huge pages (memory/huge_pages.h)
  std::size_t used_ = 0;
  huge_page_vector<std::uint8_t> version_; // per face, 5 bits (and 7 bytes of padding)
  std::size_t faces_ = 0;             // the face indices the grid was reset for
  std::vector<Entry> hits_;           // query()'s
  std::vector<std::uint32_t> found_;  // query()'s: the current hits' faces
  bool read_ahead_ = true;
  // No entry is stale: since reset() no face was listed twice nor removed
  // (a build), so a full list grows without reading its entries for stale
  // ones (shark → 10 %, Surface_mesh: the two builds 6.56M → 5.89M
  // instructions).
  bool fresh_ = true;
};

} // namespace genmesh::detail::simplification
