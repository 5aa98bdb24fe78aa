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
// cell when faces have grown (simplify: whenever the face count halves).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace genmesh::detail::simplification {

struct Box {
  Eigen::Vector3d lo, hi;
  static Box of(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
  }
  bool overlaps(const Box& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
           lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
};

// A box in float, rounded outwards from a Box (half the bytes; its tests
// keep every overlap of the boxes it holds).
struct Float_box {
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  static Float_box around(const Box& b) {
    Float_box r;
    for (int i = 0; i < 3; ++i) {
      r.lo[i] = static_cast<float>(b.lo[i]);
      if (static_cast<double>(r.lo[i]) > b.lo[i]) r.lo[i] = below(r.lo[i]);
      r.hi[i] = static_cast<float>(b.hi[i]);
      if (static_cast<double>(r.hi[i]) < b.hi[i]) r.hi[i] = -below(-r.hi[i]);
    }
    return r;
  }
  Box box() const { return {Eigen::Vector3d(lo[0], lo[1], lo[2]), Eigen::Vector3d(hi[0], hi[1], hi[2])}; }
  bool overlaps(const Float_box& o) const {
    return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1] && lo[2] <= o.hi[2] &&
           o.lo[2] <= hi[2];
  }
  // The next float toward −∞ (std::nextafter without the library call).
  static float below(float f) {
    if (f == 0) return -std::numeric_limits<float>::denorm_min();
    const auto u = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? u - 1 : u + 1);
  }
};

class Face_grid {
 public:
  // Cells of size `cell`; faces (slots) numbered below `faces`.
  void reset(double cell, std::size_t faces) {
    inv_ = cell > 0 ? 1.0 / cell : 1.0;
    table_ = {};
    used_ = 0;
    version_.assign(faces, 0);
    std::size_t cap = 16;
    while (cap < faces / 4) cap *= 2; // a cell holds tens of faces; load below a half
    table_.resize(cap);
  }

  // Lists f with box b in every cell b overlaps; entries listed for f
  // before become stale (queries drop them).
  void insert(std::uint32_t f, const Box& b) {
    const std::uint8_t v = bump(f);
    const Axis ax = axis(b.lo.x(), b.hi.x()), ay = axis(b.lo.y(), b.hi.y()), az = axis(b.lo.z(), b.hi.z());
    for (std::uint32_t x = ax.c0; x <= ax.c1; ++x) {
      const std::uint8_t bx = ax.bins(x), sx = x == ax.c0;
      for (std::uint32_t y = ay.c0; y <= ay.c1; ++y) {
        const std::uint8_t by = ay.bins(y), sy = y == ay.c0;
        for (std::uint32_t z = az.c0; z <= az.c1; ++z) {
          const std::uint8_t bz = az.bins(z), sz = z == az.c0;
          cell(key(x, y, z)).push_back(
              {f, static_cast<std::uint8_t>(v << 3 | sx | sy << 1 | sz << 2), bx, by, bz});
        }
      }
    }
  }

  // f is gone: its entries become stale.
  void remove(std::uint32_t f) { bump(f); }

  // Appends to `out` every face listed in a cell b overlaps whose box's
  // part in that cell may meet b's, each face once (in the cell holding the
  // lowest corner of the two boxes' intersection, where both are listed);
  // may append a face whose box misses b (the bins are conservative), never
  // misses one whose box meets b. Drops the stale entries it walks over.
  void query(const Box& b, std::vector<std::uint32_t>& out) {
    const Axis ax = axis(b.lo.x(), b.hi.x()), ay = axis(b.lo.y(), b.hi.y()), az = axis(b.lo.z(), b.hi.z());
    for (std::uint32_t x = ax.c0; x <= ax.c1; ++x) {
      const std::uint8_t bx = ax.bins(x), sx = x == ax.c0;
      for (std::uint32_t y = ay.c0; y <= ay.c1; ++y) {
        const std::uint8_t by = ay.bins(y), sy = y == ay.c0;
        for (std::uint32_t z = az.c0; z <= az.c1; ++z) {
          const std::uint8_t bz = az.bins(z), sz = z == az.c0;
          // A face may be taken here if, on each axis, its box or the
          // query's starts in this cell (see above).
          const std::uint8_t need = static_cast<std::uint8_t>(7 & ~(sx | sy << 1 | sz << 2));
          Bucket* c = find(key(x, y, z));
          if (c == nullptr) continue;
          auto& list = c->list;
          std::size_t kept = 0;
          const std::size_t n = list.size();
          for (std::size_t k = 0; k < n; ++k) {
            const Entry e = list[k];
            if (version_[e.face] != e.flags >> 3) continue; // stale: dropped
            list[kept++] = e;
            if ((e.flags & need) == need && meets(e.x, bx) && meets(e.y, by) && meets(e.z, bz)) out.push_back(e.face);
          }
          list.resize(kept);
        }
      }
    }
  }

 private:
  // A face listed in a cell: its slot, its version when listed (5 bits)
  // and on which axes its range starts at this cell (3 bits), and per axis
  // the bins of the cell (16 a side) its box covers there (lo << 4 | hi).
  struct Entry {
    std::uint32_t face;
    std::uint8_t flags;
    std::uint8_t x, y, z;
  };
  struct Bucket {
    std::uint64_t key = empty;
    std::vector<Entry> list;
  };
  static constexpr std::uint64_t empty = ~std::uint64_t{0};

  static bool meets(std::uint8_t a, std::uint8_t b) { return (a >> 4) <= (b & 15) && (b >> 4) <= (a & 15); }

  std::uint8_t bump(std::uint32_t f) { return version_[f] = static_cast<std::uint8_t>((version_[f] + 1) & 31); }

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
  Axis axis(double lo, double hi) const {
    Axis a;
    place(lo, a.c0, a.b0);
    place(hi, a.c1, a.b1);
    return a;
  }
  void place(double x, std::uint32_t& c, std::uint8_t& b) const {
    const double s = x * inv_, f = std::floor(s);
    if (f < -static_cast<double>(half)) {
      c = 0;
      b = 0;
    } else if (f > static_cast<double>(half - 1)) {
      c = 2 * half - 1;
      b = 15;
    } else {
      c = static_cast<std::uint32_t>(static_cast<std::int64_t>(f) + half);
      b = static_cast<std::uint8_t>(std::min(15.0, (s - f) * 16.0));
    }
  }
  static constexpr std::int64_t half = std::int64_t{1} << 15;

  static std::uint64_t key(std::uint64_t x, std::uint64_t y, std::uint64_t z) { return x << 32 | y << 16 | z; }

  static std::size_t hash(std::uint64_t k) { return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 32); }

  // Open addressing, linear probing.
  Bucket* find(std::uint64_t k) {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(k) & mask;; i = (i + 1) & mask) {
      if (table_[i].key == k) return &table_[i];
      if (table_[i].key == empty) return nullptr;
    }
  }
  std::vector<Entry>& cell(std::uint64_t k) {
    std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(k) & mask;; i = (i + 1) & mask) {
      if (table_[i].key == k) return table_[i].list;
      if (table_[i].key == empty) {
        if (2 * (used_ + 1) > table_.size()) {
          grow();
          return cell(k);
        }
        ++used_;
        table_[i].key = k;
        return table_[i].list;
      }
    }
  }
  void grow() {
    std::vector<Bucket> old(table_.size() * 2);
    old.swap(table_);
    const std::size_t mask = table_.size() - 1;
    for (auto& b : old) {
      if (b.key == empty) continue;
      std::size_t i = hash(b.key) & mask;
      while (table_[i].key != empty) i = (i + 1) & mask;
      table_[i].key = b.key;
      table_[i].list = std::move(b.list);
    }
  }

  double inv_ = 1.0;
  std::vector<Bucket> table_;
  std::size_t used_ = 0;
  std::vector<std::uint8_t> version_; // per face, 5 bits
};

} // namespace genmesh::detail::simplification
