// genmesh/detail/elements/index_iterator.h — iteration over the live
// elements of one kind (the iterators of vertices(g), halfedges(g), ... on
// genmesh's own meshes; used through <genmesh/elements.h>).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace genmesh {

template <class It>
struct Range;

namespace detail {

/// Iterates indices [i, end) skipping removed ones; removed flags are looked up
/// at index >> Shift (halfedges use their edge's flag).
template <class Index, unsigned Shift>
class Index_iterator {
public:
  using value_type = Index;
  using reference = Index;
  using pointer = void;
  using difference_type = std::ptrdiff_t;
  using iterator_category = std::bidirectional_iterator_tag;
  using iterator_concept = std::bidirectional_iterator_tag;

  Index_iterator() = default;
  Index_iterator(std::uint32_t i, std::uint32_t end, const std::vector<bool>* removed)
      : i_(i), end_(end), removed_(removed) {
    skip_forward();
  }

  Index operator*() const { return Index(i_); }
  Index_iterator& operator++() {
    ++i_;
    skip_forward();
    return *this;
  }
  Index_iterator operator++(int) {
    Index_iterator t = *this;
    ++*this;
    return t;
  }
  Index_iterator& operator--() {
    --i_;
    if (removed_ != nullptr)
      while (i_ > 0 && (*removed_)[i_ >> Shift]) --i_;
    return *this;
  }
  Index_iterator operator--(int) {
    Index_iterator t = *this;
    --*this;
    return t;
  }
  friend bool operator==(const Index_iterator& a, const Index_iterator& b) { return a.i_ == b.i_; }

private:
  void skip_forward() {
    if (removed_ != nullptr)
      while (i_ < end_ && (*removed_)[i_ >> Shift]) ++i_;
  }
  std::uint32_t i_ = 0;
  std::uint32_t end_ = 0;
  const std::vector<bool>* removed_ = nullptr;
};

/// The live elements [0, bound) of one kind, `live` of them; removed ones are
/// skipped only when the mesh has garbage (else no flag is read).
template <class It>
Range<It> live_range(std::size_t bound, std::size_t live, const std::vector<bool>& removed, bool garbage) {
  const auto n = static_cast<std::uint32_t>(bound);
  const std::vector<bool>* r = garbage ? &removed : nullptr;
  return {It(0, n, r), It(n, n, r), live};
}

} // namespace detail
} // namespace genmesh
