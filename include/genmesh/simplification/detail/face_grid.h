// genmesh/simplification/detail/face_grid.h — a dynamic spatial hash of face
// bounding boxes (private; the self-intersection guard of simplify).
//
// A uniform grid of cubic cells, stored sparsely (cell key → face ids). A
// face is listed in every cell its box overlaps. A face that changed is
// inserted again with its new box (move()) into the cells of its new range
// that its old box's range did not cover — the caller keeps the box a face
// was last inserted with, so the grid keeps no per-face data. An entry may
// be stale (the face is gone or has left the cell): queries skip it, and
// the caller may drop it as it walks a cell's list; but a face is never
// missing from a cell its current box overlaps. The caller rebuilds the
// grid with a larger cell when faces have grown (simplify: whenever the
// face count halves).
#pragma once

#include <Eigen/Core>

#include <algorithm>
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
  // Cells of size `cell`; room for the cells of about expected_faces faces
  // (a cell holds tens of faces).
  void reset(double cell, std::size_t expected_faces) {
    inv_ = cell > 0 ? 1.0 / cell : 1.0;
    cells_ = {};
    cells_.reserve(expected_faces / 16);
  }

  // Lists f in every cell b overlaps.
  void insert(std::uint32_t f, const Box& b) {
    for_range(range_of(b), [&](std::int64_t x, std::int64_t y, std::int64_t z) { cells_[key(x, y, z)].push_back(f); });
  }

  // f, listed in the cells of old, now has box b: lists it in the cells of
  // b that old's cells do not cover.
  void move(std::uint32_t f, const Box& old, const Box& b) {
    const Range o = range_of(old), n = range_of(b);
    if (o.contains(n)) return;
    for_range(n, [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      if (!o.contains(x, y, z)) cells_[key(x, y, z)].push_back(f);
    });
  }

  // An inclusive range of cells (empty by default), 16 bits an axis.
  struct Range {
    std::uint16_t x0 = 1, y0 = 1, z0 = 1, x1 = 0, y1 = 0, z1 = 0;
    bool contains(std::int64_t x, std::int64_t y, std::int64_t z) const {
      return x0 <= x && x <= x1 && y0 <= y && y <= y1 && z0 <= z && z <= z1;
    }
    bool contains(const Range& o) const {
      return x0 <= o.x0 && o.x1 <= x1 && y0 <= o.y0 && o.y1 <= y1 && z0 <= o.z0 && o.z1 <= z1;
    }
  };
  struct Cell {
    std::uint16_t x, y, z;
  };

  // Is c the lowest cell (in x, y and z) that ranges a and b share? A face
  // whose box overlaps a query's box is met in every cell of the query that
  // its box's range covers; the query takes it in this one only, instead
  // of marking the faces it has seen.
  static bool first_shared(const Range& a, const Range& b, Cell c) {
    return c.x == std::max(a.x0, b.x0) && c.y == std::max(a.y0, b.y0) && c.z == std::max(a.z0, b.z0);
  }
  static bool covers(const Range& a, Cell c) { return a.contains(c.x, c.y, c.z); }

  // Calls visit(cell, range, faces) for every non-empty cell b overlaps,
  // with b's range and the list of the faces listed there (a face may come
  // in several cells, and may no longer overlap b): the caller walks it,
  // prefetching ahead, and may drop the entries of faces that are gone or
  // whose box no longer reaches the cell (never others: a face must stay
  // listed in every cell its box's range covers).
  template <class Visit>
  void query(const Box& b, Visit&& visit) {
    const Range r = range_of(b);
    for_range(r, [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      const auto it = cells_.find(key(x, y, z));
      if (it == cells_.end()) return;
      visit(Cell{static_cast<std::uint16_t>(x), static_cast<std::uint16_t>(y), static_cast<std::uint16_t>(z)}, r,
            it->second);
    });
  }

  Range range_of(const Box& b) const {
    return {coord(b.lo.x()), coord(b.lo.y()), coord(b.lo.z()), coord(b.hi.x()), coord(b.hi.y()), coord(b.hi.z())};
  }

  private:
  // 16 bits an axis, clamped (clamping keeps overlaps: a mesh wider than
  // 65,536 cells only gets longer lists in its outer cells).
  static constexpr std::int64_t half = std::int64_t{1} << 15;

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
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

} // namespace genmesh::detail::simplification
