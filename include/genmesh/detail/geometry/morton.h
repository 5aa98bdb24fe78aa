// genmesh/detail/geometry/morton.h — the bit spreading behind 3D Morton codes (private).
#pragma once

#include <cstdint>

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

} // namespace genmesh::detail
