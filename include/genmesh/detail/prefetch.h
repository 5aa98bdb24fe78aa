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

} // namespace genmesh::detail
