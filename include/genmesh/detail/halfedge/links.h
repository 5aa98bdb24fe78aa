// genmesh/detail/halfedge/links.h — Halfedge_mesh's per-halfedge storage
// (used through <genmesh/halfedge_mesh.h>).
#pragma once

#include <genmesh/detail/memory/huge_pages.h>
#include <genmesh/detail/prefetch.h>
#include <genmesh/elements.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>
#include <utility>

namespace genmesh::detail {

/// next, prev, target and face of every halfedge, in one allocation of 16
/// bytes per halfedge: next and target each in an array of their own (walks
/// around a vertex or a face read only those: 16 halfedges per cache line),
/// prev and face together in an 8-byte record (an edit reads and writes them
/// together: a split touches five cache lines of old halfedges instead of
/// six). All grown together: one capacity check and, when full, one
/// reallocation per added edge. The allocation has the size of
/// Surface_mesh's 16-byte halfedge records, so the allocator treats both
/// meshes alike (four separate 4-byte arrays fell below glibc's adaptive
/// mmap threshold differently and paid a page fault per 4 KiB on every
/// regrowth: 650k faults where Surface_mesh had 3k). Capacity doubles as
/// std::vector's does. Copies are exact-size.
class Halfedge_links {
public:
  Halfedge_links() = default;
  Halfedge_links(const Halfedge_links& o) { copy_from(o, o.size_); }
  Halfedge_links(Halfedge_links&& o) noexcept { steal(o); }
  Halfedge_links& operator=(const Halfedge_links& o) {
    if (this != &o) {
      Halfedge_links t(o);
      *this = std::move(t);
    }
    return *this;
  }
  Halfedge_links& operator=(Halfedge_links&& o) noexcept {
    if (this != &o) steal(o);
    return *this;
  }
  ~Halfedge_links() = default;

  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] std::size_t capacity() const { return cap_; }

  // Element access (i < size()).
  Halfedge_index& next(std::size_t i) { return next_[i]; }
  Halfedge_index& prev(std::size_t i) { return rec_[i].prev; }
  Vertex_index& target(std::size_t i) { return target_[i]; }
  Face_index& face(std::size_t i) { return rec_[i].face; }
  [[nodiscard]] Halfedge_index next(std::size_t i) const { return next_[i]; }
  [[nodiscard]] Halfedge_index prev(std::size_t i) const { return rec_[i].prev; }
  [[nodiscard]] Vertex_index target(std::size_t i) const { return target_[i]; }
  [[nodiscard]] Face_index face(std::size_t i) const { return rec_[i].face; }

  /// Hints that halfedge i's links will be read soon (a cache prefetch of
  /// its next, target and record; its opposite's share the cache lines).
  void prefetch(std::size_t i) const {
    detail::prefetch(next_ + i);
    detail::prefetch(target_ + i);
    detail::prefetch(rec_ + i);
  }

  /// Appends two halfedges with null links; returns the index of the first.
  std::size_t push_back_pair() {
    if (size_ + 2 > cap_) grow(size_ + std::max<std::size_t>(size_, 2));
    const std::size_t i = size_;
    next_[i] = next_[i + 1] = Halfedge_index();
    target_[i] = target_[i + 1] = Vertex_index();
    rec_[i] = rec_[i + 1] = Record();
    size_ += 2;
    return i;
  }
  /// New elements get null links.
  void resize(std::size_t n) {
    if (n > cap_) grow(n);
    for (std::size_t k = size_; k < n; ++k) {
      next_[k] = Halfedge_index();
      target_[k] = Vertex_index();
      rec_[k] = Record();
    }
    size_ = n;
  }
  void reserve(std::size_t n) {
    if (n > cap_) grow(n);
  }
  void shrink_to_fit() {
    if (cap_ != size_) {
      Halfedge_links t;
      t.copy_from(*this, size_);
      *this = std::move(t);
    }
  }

private:
  struct Record {
    Halfedge_index prev;
    Face_index face;
  };
  static_assert(sizeof(Record) == 8 && std::is_trivially_copyable_v<Record> &&
                std::is_trivially_copyable_v<Halfedge_index> && std::is_trivially_copyable_v<Vertex_index>);
  static constexpr std::size_t bytes_per_halfedge = sizeof(Halfedge_index) + sizeof(Vertex_index) + sizeof(Record);

  // Reallocates to capacity n >= size_, keeping the elements.
  void grow(std::size_t n) {
    Halfedge_links t;
    t.copy_from(*this, n);
    *this = std::move(t);
  }
  // Becomes a copy of o's elements with capacity cap >= o.size_. memcpy:
  // element-wise copies (what std::uninitialized_copy makes of these
  // non-trivial-default types) took 8 % of a split pass.
  void copy_from(const Halfedge_links& o, std::size_t cap) {
    allocate(cap);
    size_ = o.size_;
    if (size_ == 0) return;
    std::memcpy(next_, o.next_, size_ * sizeof(Halfedge_index));
    std::memcpy(target_, o.target_, size_ * sizeof(Vertex_index));
    std::memcpy(rec_, o.rec_, size_ * sizeof(Record));
  }
  void allocate(std::size_t cap) {
    cap_ = cap;
    size_ = 0;
    if (cap == 0) {
      buf_.reset();
      next_ = nullptr;
      target_ = nullptr;
      rec_ = nullptr;
      return;
    }
    // new std::byte[] is suitably aligned and provides storage for the
    // (implicit-lifetime, trivially copyable) index objects.
    buf_.reset(new std::byte[bytes_per_halfedge * cap]);
    // The guard's near-face reads land here at random (memory/huge_pages.h).
    advise_huge_pages(buf_.get(), bytes_per_halfedge * cap);
    next_ = reinterpret_cast<Halfedge_index*>(buf_.get());
    target_ = reinterpret_cast<Vertex_index*>(buf_.get() + sizeof(Halfedge_index) * cap);
    rec_ = reinterpret_cast<Record*>(buf_.get() + (sizeof(Halfedge_index) + sizeof(Vertex_index)) * cap);
  }
  void steal(Halfedge_links& o) {
    buf_ = std::move(o.buf_);
    next_ = std::exchange(o.next_, nullptr);
    target_ = std::exchange(o.target_, nullptr);
    rec_ = std::exchange(o.rec_, nullptr);
    size_ = std::exchange(o.size_, 0);
    cap_ = std::exchange(o.cap_, 0);
  }

  std::unique_ptr<std::byte[]> buf_;
  Halfedge_index* next_ = nullptr;
  Vertex_index* target_ = nullptr;
  Record* rec_ = nullptr;
  std::size_t size_ = 0, cap_ = 0;
};

} // namespace genmesh::detail
