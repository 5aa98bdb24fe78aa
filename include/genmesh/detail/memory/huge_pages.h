// genmesh/detail/memory/huge_pages.h — transparent huge pages for the big,
// randomly read arrays (the meshes' element arrays, simplify's per-vertex and
// per-edge data, its queue and grid).
//
// Where Linux's transparent huge pages are in "madvise" mode (a common
// default), a block gets 2 MiB pages only if asked. simplify's guard reads
// faces, links and points at random over ~60 MB at 832k faces: with 4 KiB
// pages most of those reads miss the TLB as well as the cache (Zen 4's L2 TLB
// covers 12 MB). Asked for huge pages (8 madvise calls), the 832k armadillo
// simplifies ~5 % faster (median ratio 0.952 over 34 same-run pairs, 1.974 ->
// 1.866 s in the last 8), 0.96 with the guard off, the 208k 0.975; the shark,
// all below 2 MiB, is unchanged (docs/benchmarks.md, "Huge pages for the big
// arrays, session 19").
//
// (Large_allocator, large_allocator.h, rounds short-lived blocks of 1 MiB and
// more up to whole 2 MiB-aligned pages instead, for fewer first-touch faults;
// it advises through advise_huge_pages too.)
//
// Only advice: the blocks still come from operator new (programs that count
// or replace it see them; no over-allocation, no 2 MiB alignment), and only
// the whole 2 MiB pages inside a block are advised, so blocks below 2 MiB
// are left alone (no syscall): a huge page of their own would not fit. No
// higher threshold: at 832k faces the faces' halfedges (3.3 MB, read at
// random by the guard) get one huge page most of the time. Off Linux, or
// where THP is "never", this does nothing; madvise's errors are ignored (no
// value depends on it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace genmesh::detail {

inline constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;

/// Asks for transparent huge pages on the whole 2 MiB pages inside
/// [p, p + bytes), if any; best called before the block is first written
/// (its pages are then faulted in 2 MiB at a time).
inline void advise_huge_pages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < huge_page_bytes) return;
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (a + huge_page_bytes - 1) & ~(huge_page_bytes - 1);
  const std::uintptr_t last = (a + bytes) & ~(huge_page_bytes - 1);
  if (first < last) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

/// std::allocator's blocks (the same operator new calls), advised for huge
/// pages when big (advise_huge_pages). Stateless; equal to every other.
template <class T>
struct Huge_page_allocator {
  using value_type = T;

  Huge_page_allocator() = default;
  template <class U>
  constexpr Huge_page_allocator(const Huge_page_allocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    T* p = std::allocator<T>().allocate(n);
    advise_huge_pages(p, n * sizeof(T));
    return p;
  }
  void deallocate(T* p, std::size_t n) noexcept { std::allocator<T>().deallocate(p, n); }

  template <class U>
  friend constexpr bool operator==(const Huge_page_allocator&, const Huge_page_allocator<U>&) noexcept {
    return true;
  }
};

/// A std::vector whose big buffers are advised for huge pages.
template <class T>
using huge_page_vector = std::vector<T, Huge_page_allocator<T>>;

} // namespace genmesh::detail
