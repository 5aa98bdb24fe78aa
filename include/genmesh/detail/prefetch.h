// genmesh/detail/prefetch.h — the cache hint behind every prefetch in genmesh
// (the priority queue's, Halfedge_mesh's links, simplify's walk ahead).
#pragma once

namespace genmesh::detail {

/// A hint that the memory at p will be read soon: a cache prefetch (no
/// effect on any value; nothing at all on a compiler without the builtin).
inline void prefetch([[maybe_unused]] const void* p) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#endif
}

/// The hint for every cache line of *p, for a record of up to 64 bytes (up
/// to two lines: a 40-byte record straddles two 64-byte lines at half of its
/// array positions, and the first line's hint alone leaves the second a
/// miss); for a larger one, its first line only.
template <class T>
inline void prefetch_object(const T* p) {
  prefetch(p);
  if constexpr (sizeof(T) > 1 && sizeof(T) <= 64) prefetch(reinterpret_cast<const char*>(p) + (sizeof(T) - 1));
}

} // namespace genmesh::detail
