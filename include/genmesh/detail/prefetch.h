// genmesh/detail/prefetch.h — the cache hint behind every prefetch in genmesh
// (the priority queue's, Halfedge_mesh's links, simplify's walk ahead), and
// the early read (touch) behind simplify's grid walk.
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

/// A read of the byte at p whose value is dropped: brings its line in as a
/// load does (no effect on any value). Where a loop's own reads are too many
/// instructions apart for the processor to have more than a few lines in
/// flight, a first loop of these has them all in flight at once; on the
/// benchmark machine prefetch() hints in that place did not speed the loop
/// up, these reads did (simplify's grid walk; docs/benchmarks.md, session 12).
inline void touch(const void* p) {
  const unsigned char c = *static_cast<const unsigned char*>(p);
#if defined(__GNUC__) || defined(__clang__)
  asm volatile("" : : "r"(c));
#else
  static_cast<void>(*static_cast<const volatile unsigned char*>(&c));
#endif
}

} // namespace genmesh::detail
