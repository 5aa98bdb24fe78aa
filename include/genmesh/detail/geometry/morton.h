// genmesh/detail/geometry/morton.h — the bit spreading behind 3D Morton codes (private).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

namespace genmesh::detail {

// The low 21 bits of x spread to every third bit (bit i to bit 3i): a
// Morton code is spread(x) | spread(y) << 1 | spread(z) << 2.
inline std::uint64_t morton_spread(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// Sorts v by the `bits` low bits of key(element) >> shift, stably (LSD radix
// sort, 11 bits a pass; tmp is scratch of v's size): Morton orders without a
// comparison sort.
template <class Vector, class Key>
void radix_sort(Vector& v, Vector& tmp, int shift, int bits, Key key) {
  tmp.resize(v.size());
  for (int s = shift; s < shift + bits; s += 11) {
    std::size_t hist[2048] = {};
    for (const auto& x : v) ++hist[(key(x) >> s) & 2047];
    std::size_t sum = 0;
    for (auto& h : hist) sum += std::exchange(h, sum);
    for (const auto& x : v) tmp[hist[(key(x) >> s) & 2047]++] = x;
    v.swap(tmp);
  }
}

} // namespace genmesh::detail
