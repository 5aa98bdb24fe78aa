// genmesh/detail/validity/union_find.h — a union-find over dense numbers
// (components in check_mesh(), vertex fans in the soup check and repair).
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace genmesh::detail {

struct Union_find {
  std::vector<std::uint32_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  // The smaller root wins, so roots are deterministic.
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent[b] = a;
    else parent[a] = b;
  }
};

} // namespace genmesh::detail
