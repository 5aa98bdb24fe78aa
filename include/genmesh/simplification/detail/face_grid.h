// genmesh/simplification/detail/face_grid.h — a dynamic spatial hash of face
// bounding boxes (private; the self-intersection guard of simplify).
//
// A uniform grid of cubic cells, stored sparsely (cell key → entries: a
// face id and its box quantized in the cell). A face is listed in every
// cell its box overlaps. Entries are never removed: a face that changed is
// inserted again with its new box — a new entry in the cells of its new
// cell range that its last range did not cover, the box updated in the
// cells both ranges cover, so that a face re-inserted many times is not
// listed many times — and queries return what may overlap (the caller
// checks the current box). An entry may be stale, but a face is never
// missing from a cell its current box overlaps, with a box that holds its
// current one. The caller rebuilds the grid with a larger cell when faces
// have grown (simplify: whenever the face count halves).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
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

class Face_grid {
 public:
  void reset(double cell, std::size_t expected_faces) {
    inv_ = cell > 0 ? 1.0 / cell : 1.0;
    cells_.clear();
    cells_.reserve(expected_faces / 8);
    for (auto& r : range_) r = Range{};
  }

  // Lists face f with box b: a new entry in the cells of b's range that f's
  // last range did not cover; the entries of the cells both cover get b.
  void insert(std::uint32_t f, const Box& b) {
    if (f >= range_.size()) range_.resize(f + 1);
    const Range n = range_of(b), old = range_[f];
    const std::array<double, 3> lo = scaled(b.lo), hi = scaled(b.hi);
    for_range(n, [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      auto& list = cells_[key(x, y, z)];
      const Entry e = entry(f, lo, hi, x, y, z);
      if (old.contains(x, y, z)) {
        for (Entry& d : list)
          if (d.f == f) d = e;
      } else {
        list.push_back(e);
      }
    });
    range_[f] = n;
  }

  // Calls visit(f) for every entry of a cell b overlaps whose box (as
  // quantized in that cell) meets b: every face whose current box meets b,
  // some more than once, and some whose box no longer does (the caller
  // checks the current box).
  template <class Visit>
  void query(const Box& b, Visit&& visit) const {
    const std::array<double, 3> lo = scaled(b.lo), hi = scaled(b.hi);
    for_range(range_of(b), [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      const auto it = cells_.find(key(x, y, z));
      if (it == cells_.end()) return;
      const Entry q = entry(0, lo, hi, x, y, z);
      for (const Entry& e : it->second)
        if (e.lo[0] <= q.hi[0] && q.lo[0] <= e.hi[0] && e.lo[1] <= q.hi[1] && q.lo[1] <= e.hi[1] &&
            e.lo[2] <= q.hi[2] && q.lo[2] <= e.hi[2])
          visit(e.f);
    });
  }

 private:
  // 16 bits an axis, clamped (clamping keeps overlaps: a mesh wider than
  // 65,536 cells only gets longer lists in its outer cells).
  static constexpr std::int64_t half = std::int64_t{1} << 15;

  // A listed face and its box in the cell, quantized to 1/256 of the cell
  // (clamped to the cell) by a monotone map, the same for entries and
  // queries: boxes that meet have quantized boxes that meet. A query reads
  // a cell's entries in sequence and touches only the faces whose box may
  // meet its own (12 bytes an entry).
  struct Entry {
    std::uint32_t f;
    std::uint8_t lo[3], hi[3];
  };

  std::array<double, 3> scaled(const Eigen::Vector3d& p) const { return {p.x() * inv_, p.y() * inv_, p.z() * inv_}; }

  static std::uint8_t quantize(double u, std::int64_t c) {
    const double t = std::floor((u - static_cast<double>(c - half)) * 256.0);
    return static_cast<std::uint8_t>(std::clamp(t, 0.0, 255.0));
  }

  static Entry entry(std::uint32_t f, const std::array<double, 3>& lo, const std::array<double, 3>& hi, std::int64_t x,
                     std::int64_t y, std::int64_t z) {
    return {f, {quantize(lo[0], x), quantize(lo[1], y), quantize(lo[2], z)},
            {quantize(hi[0], x), quantize(hi[1], y), quantize(hi[2], z)}};
  }

  // An inclusive range of cells (empty by default); 12 bytes, as the
  // per-face array is read at random on every insertion.
  struct Range {
    std::uint16_t x0 = 1, y0 = 1, z0 = 1, x1 = 0, y1 = 0, z1 = 0;
    bool contains(std::int64_t x, std::int64_t y, std::int64_t z) const {
      return x0 <= x && x <= x1 && y0 <= y && y <= y1 && z0 <= z && z <= z1;
    }
  };

  Range range_of(const Box& b) const {
    return {coord(b.lo.x()), coord(b.lo.y()), coord(b.lo.z()), coord(b.hi.x()), coord(b.hi.y()), coord(b.hi.z())};
  }

  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return (static_cast<std::uint64_t>(x) << 32) | (static_cast<std::uint64_t>(y) << 16) | static_cast<std::uint64_t>(z);
  }

  std::uint16_t coord(double x) const {
    const double c = std::floor(x * inv_);
    return static_cast<std::uint16_t>(static_cast<std::int64_t>(std::clamp(c, -double(half), double(half - 1))) + half);
  }

  template <class F>
  static void for_range(const Range& r, F&& f) {
    for (std::int64_t x = r.x0; x <= r.x1; ++x)
      for (std::int64_t y = r.y0; y <= r.y1; ++y)
        for (std::int64_t z = r.z0; z <= r.z1; ++z) f(x, y, z);
  }

  double inv_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<Entry>> cells_;
  std::vector<Range> range_; // by face: the cells it was last inserted into
};

} // namespace genmesh::detail::simplification
