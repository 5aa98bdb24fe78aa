// genmesh/detail/elements/compaction.h — the old -> new index maps of
// collect_garbage(), shared by Halfedge_mesh and Incidence_mesh.
#pragma once

#include <genmesh/elements.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace genmesh::detail {

/// Old -> new indices for one element kind, as collect_garbage() renumbers
/// (shared by Halfedge_mesh and Incidence_mesh): removed[i] maps to the null
/// index, survivors to [0, live count) in `order`.
inline std::vector<std::uint32_t> compaction_map(const std::vector<bool>& removed, Garbage_order order) {
  constexpr std::uint32_t null = Vertex_index::invalid_value;
  const std::size_t n = removed.size();
  std::vector<std::uint32_t> map(n);
  if (order == Garbage_order::stable) {
    std::uint32_t k = 0;
    for (std::size_t i = 0; i < n; ++i) map[i] = removed[i] ? null : k++;
    return map;
  }
  // Surface_mesh's two-finger swap: i0 finds holes from the front, i1 live
  // elements from the back; i1 moves to i0.
  for (std::size_t i = 0; i < n; ++i) map[i] = removed[i] ? null : static_cast<std::uint32_t>(i);
  if (n == 0) return map;
  std::vector<bool> r = removed;
  std::size_t i0 = 0, i1 = n - 1;
  while (true) {
    while (!r[i0] && i0 < i1) ++i0;
    while (r[i1] && i0 < i1) --i1;
    if (i0 >= i1) break;
    map[i1] = static_cast<std::uint32_t>(i0);
    r[i0] = false;
    r[i1] = true;
  }
  return map;
}

/// The halfedge map of an edge compaction map: halfedges 2e and 2e + 1 go
/// with their edge e.
inline std::vector<std::uint32_t> halfedge_compaction_map(const std::vector<std::uint32_t>& emap) {
  constexpr std::uint32_t null = Vertex_index::invalid_value;
  std::vector<std::uint32_t> hmap(2 * emap.size());
  for (std::size_t e = 0; e < emap.size(); ++e) {
    hmap[2 * e] = emap[e] == null ? null : 2 * emap[e];
    hmap[2 * e + 1] = emap[e] == null ? null : 2 * emap[e] + 1;
  }
  return hmap;
}

/// A renumbering map completed into a permutation of [0, n): entries i with
/// map[i] null (dropped elements) take the indices no entry maps to, in
/// increasing order of both. Empty if the map is not one to one into [0, n)
/// (an entry out of range or repeated), or, given `removed` (its size
/// map.size()), if map[i] is null exactly when removed[i] does not hold, or
/// a live element maps beyond the live count.
inline std::vector<std::uint32_t> full_permutation(std::span<const std::uint32_t> map, std::size_t n,
                                                   const std::vector<bool>* removed = nullptr) {
  constexpr std::uint32_t null = Vertex_index::invalid_value;
  if (map.size() > n) return {};
  std::vector<std::uint32_t> perm(n, null);
  std::vector<std::uint8_t> used(n, 0);
  std::size_t live = 0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const std::uint32_t j = map[i];
    if (j == null) continue;
    if (j >= n || used[j]) return {};
    used[j] = 1;
    perm[i] = j;
    ++live;
  }
  if (removed) {
    if (removed->size() != map.size()) return {};
    for (std::size_t i = 0; i < map.size(); ++i)
      if ((map[i] == null) != static_cast<bool>((*removed)[i]) || (map[i] != null && map[i] >= live)) return {};
  }
  std::size_t free = 0;
  for (auto& j : perm) {
    if (j != null) continue;
    while (used[free]) ++free;
    j = static_cast<std::uint32_t>(free++);
  }
  return perm;
}

/// Moves element i to perm[i] for every i, in place, along the cycles of the
/// permutation perm of [0, n): swap(i, j) exchanges elements i and j.
template <class Swap>
void permute_in_place(std::span<const std::uint32_t> perm, Swap&& swap) {
  std::vector<std::uint8_t> done(perm.size(), 0);
  for (std::size_t i = 0; i < perm.size(); ++i) {
    if (done[i]) continue;
    done[i] = 1;
    for (std::size_t j = perm[i]; j != i; j = perm[j]) {
      swap(i, j);
      done[j] = 1;
    }
  }
}

} // namespace genmesh::detail
