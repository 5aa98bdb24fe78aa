// genmesh/detail/memory/large_allocator.h — an allocator for large, short-lived
// arrays: blocks of 1 MiB and more are 2 MiB-aligned and marked for
// transparent huge pages (madvise MADV_HUGEPAGE where the system offers it),
// so that touching them for the first time costs one page fault per 2 MiB
// instead of one per 4 KiB. On virtual machines a fault costs ~10 µs
// (measured: 100 MB first touched in 0.37 s with 4 KiB pages, 0.01–0.24 s
// with huge pages), which dominated building an Aabb_tree. From 1 MiB (was 4
// MiB): armadillo's remeshing tree (3.7 MB of triangles, 2 MB of nodes) then
// faults ~2 500 times less, at the price of rounding each such block up to
// whole 2 MiB pages (peak heap 15.5 -> 17.4 MB there; docs/benchmarks.md,
// "Isotropic remeshing, session 8"). Smaller blocks go through operator new.
// Stateless; equal to every other instance. (For long-lived arrays that
// must not grow, huge_pages.h's Huge_page_allocator only advises, without
// the rounding; both advise through advise_huge_pages.)
#pragma once

#include <genmesh/detail/memory/huge_pages.h>

#include <cstddef>
#include <new>
#include <vector>

namespace genmesh::detail {

template <class T>
struct Large_allocator {
  using value_type = T;
  static constexpr std::size_t huge_page = huge_page_bytes;
  static constexpr std::size_t threshold = std::size_t(1) << 20;

  Large_allocator() = default;
  template <class U>
  constexpr Large_allocator(const Large_allocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < threshold) return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
    const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
    // Aligned operator new (not aligned_alloc), so that programs that count
    // or replace operator new see these blocks too.
    void* p = ::operator new(rounded, std::align_val_t(huge_page));
    advise_huge_pages(p, rounded); // the whole block: p and rounded are whole pages
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    ::operator delete(p, std::align_val_t(n * sizeof(T) < threshold ? alignof(T) : huge_page));
  }
  template <class U>
  friend constexpr bool operator==(const Large_allocator&, const Large_allocator<U>&) noexcept {
    return true;
  }
};

/// A std::vector whose large buffers use huge pages (see above).
template <class T>
using large_vector = std::vector<T, Large_allocator<T>>;

} // namespace genmesh::detail
