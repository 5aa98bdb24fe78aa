// genmesh/detail/validity/soup_edges.h — the one edge table of a polygon
// soup that the soup check, the repair and build_mesh() share: the usable
// faces and their directed edges grouped by undirected edge, and what is
// derived from it (vertex fans, duplicate faces).
#pragma once

#include <genmesh/detail/validity/union_find.h>
#include <genmesh/polygon_soup.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

namespace genmesh::detail {

/// One directed edge of a face: corner `corner` (global position in
/// soup.indices) goes from `from` to `to`.
struct Soup_half {
  std::uint32_t lo, hi;   // the undirected edge, lo < hi
  std::uint32_t face;
  std::uint32_t corner;
  bool forward;           // from == lo
};

/// Which faces a soup analysis uses (not out of range, not degenerate) and
/// their directed edges grouped by undirected edge, in (lo, hi, face, corner)
/// order.
struct Soup_edges {
  std::vector<char> usable;                 // per face
  std::vector<Soup_half> halves;            // sorted
  std::vector<std::uint32_t> group_begin;   // groups of equal (lo, hi); last entry = halves.size()
};

inline bool face_in_range(const Polygon_soup& soup, std::size_t f) {
  for (auto i : soup.face(f))
    if (i >= soup.num_points()) return false;
  return true;
}

inline bool face_has_repeat(std::span<const Polygon_soup::Index> c) {
  if (c.size() <= 8) {
    for (std::size_t a = 0; a < c.size(); ++a)
      for (std::size_t b = a + 1; b < c.size(); ++b)
        if (c[a] == c[b]) return true;
    return false;
  }
  std::vector<Polygon_soup::Index> s(c.begin(), c.end());
  std::sort(s.begin(), s.end());
  return std::adjacent_find(s.begin(), s.end()) != s.end();
}

inline Soup_edges soup_edges(const Polygon_soup& soup) {
  Soup_edges e;
  const std::size_t nf = soup.num_faces(), np = soup.num_points();
  e.usable.assign(nf, 0);
  std::size_t total = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    auto c = soup.face(f);
    bool ok = c.size() >= 3 && face_in_range(soup, f) && !face_has_repeat(c);
    e.usable[f] = ok;
    if (ok) total += c.size();
  }
  // Bucket by the lower vertex (counting sort), then sort each small bucket.
  std::vector<std::uint32_t> start(np + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (!e.usable[f]) continue;
    auto c = soup.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) ++start[std::min(c[k], c[(k + 1) % c.size()]) + 1];
  }
  for (std::size_t v = 0; v < np; ++v) start[v + 1] += start[v];
  e.halves.resize(total);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < nf; ++f) {
    if (!e.usable[f]) continue;
    auto c = soup.face(f);
    for (std::size_t k = 0; k < c.size(); ++k) {
      std::uint32_t a = c[k], b = c[(k + 1) % c.size()];
      e.halves[fill[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(f),
                                          static_cast<std::uint32_t>(soup.offsets[f] + k), a < b};
    }
  }
  for (std::size_t v = 0; v < np; ++v) {
    auto first = e.halves.begin() + start[v], last = e.halves.begin() + start[v + 1];
    if (last - first > 1)
      std::sort(first, last, [](const Soup_half& x, const Soup_half& y) {
        return std::tie(x.hi, x.corner) < std::tie(y.hi, y.corner);
      });
  }
  for (std::size_t i = 0; i < e.halves.size(); ++i)
    if (i == 0 || e.halves[i].lo != e.halves[i - 1].lo || e.halves[i].hi != e.halves[i - 1].hi)
      e.group_begin.push_back(static_cast<std::uint32_t>(i));
  e.group_begin.push_back(static_cast<std::uint32_t>(e.halves.size()));
  return e;
}

/// The corner after `corner` in its face.
inline std::uint32_t next_corner(const Polygon_soup& soup, std::uint32_t face, std::uint32_t corner) {
  return corner + 1 == soup.offsets[face + 1] ? soup.offsets[face] : corner + 1;
}

/// Union-find over corners joining, across every edge used by exactly two
/// faces, the corners of the same vertex; each root is one fan.
inline Union_find soup_fans(const Polygon_soup& soup, const Soup_edges& e) {
  Union_find uf(soup.indices.size());
  for (std::size_t g = 0; g + 1 < e.group_begin.size(); ++g) {
    if (e.group_begin[g + 1] - e.group_begin[g] != 2) continue;
    const Soup_half& x = e.halves[e.group_begin[g]];
    const Soup_half& y = e.halves[e.group_begin[g] + 1];
    std::uint32_t x0 = x.corner, x1 = next_corner(soup, x.face, x.corner);
    std::uint32_t y0 = y.corner, y1 = next_corner(soup, y.face, y.corner);
    // x0 and x1 are x's source and target corners; match them by vertex.
    if (soup.indices[x0] == soup.indices[y0]) {
      uf.unite(x0, y0);
      uf.unite(x1, y1);
    } else {
      uf.unite(x0, y1);
      uf.unite(x1, y0);
    }
  }
  return uf;
}

/// Faces (among `usable`) whose corner set equals an earlier face's, with the
/// first face of that corner set. O(corners · log): faces are sorted by
/// (size, an order-independent hash of the corners), and only runs of equal
/// keys compare their sorted corners — however many faces share an edge.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_faces(const Polygon_soup& soup,
                                                                             const Soup_edges& e) {
  const std::size_t nf = soup.num_faces();
  std::vector<std::uint64_t> key(nf, 0);
  std::vector<std::uint32_t> order;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!e.usable[f]) continue;
    for (auto i : soup.face(f)) {
      std::uint64_t x = i + 0x9e3779b97f4a7c15ull;
      x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
      x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
      key[f] += x ^ (x >> 31);
    }
    order.push_back(static_cast<std::uint32_t>(f));
  }
  const auto by_key = [&](std::uint32_t x, std::uint32_t y) {
    return std::tuple(soup.face_size(x), key[x], x) < std::tuple(soup.face_size(y), key[y], y);
  };
  std::sort(order.begin(), order.end(), by_key);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> dups;
  std::vector<std::vector<Polygon_soup::Index>> sorted;
  std::vector<std::uint32_t> run;
  for (std::size_t b = 0; b < order.size();) {
    std::size_t end = b + 1;
    while (end < order.size() && key[order[end]] == key[order[b]] &&
           soup.face_size(order[end]) == soup.face_size(order[b]))
      ++end;
    if (end - b > 1) {
      // Equal keys: group by the sorted corners themselves (a hash collision
      // costs a sort of the run, never a wrong answer); each group's first
      // face (lowest index) is the original.
      sorted.clear();
      run.clear();
      for (std::size_t i = b; i < end; ++i) {
        auto c = soup.face(order[i]);
        sorted.emplace_back(c.begin(), c.end());
        std::sort(sorted.back().begin(), sorted.back().end());
        run.push_back(static_cast<std::uint32_t>(i - b));
      }
      std::stable_sort(run.begin(), run.end(), [&](std::uint32_t x, std::uint32_t y) { return sorted[x] < sorted[y]; });
      for (std::size_t i = 1, first = 0; i < run.size(); ++i) {
        if (sorted[run[i]] != sorted[run[first]]) first = i;
        else dups.emplace_back(order[b + run[i]], order[b + run[first]]);
      }
    }
    b = end;
  }
  std::sort(dups.begin(), dups.end());
  return dups;
}

} // namespace genmesh::detail
