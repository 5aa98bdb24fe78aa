// genmesh/detail/validity/dense_index.h — dense numbers for the live
// elements of one kind of any graph (the backend's index map when it has
// one, else the iteration order), and the two sentinels they use.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/property_maps.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace genmesh::detail {

inline constexpr std::uint32_t k_null = 0xffffffffu; // the null descriptor
inline constexpr std::uint32_t k_bad = 0xfffffffeu;  // a descriptor that is not live

inline bool is_ref(std::uint32_t i) { return i < k_bad; }

template <class G, class Tag, bool Indexed>
struct Index_map_of {
  using type = int;
};
template <class G, class Tag>
struct Index_map_of<G, Tag, true> {
  using type = decltype(get(Tag{}, std::declval<const G&>()));
};

/// Dense numbers for the live elements of one kind: the backend's index map
/// when it has one, else the iteration order. Maps the null descriptor to
/// k_null and anything not live to k_bad.
template <class G, class Tag, class D>
class Dense_index {
  static constexpr bool indexed = HasIndexMap<G, Tag>;
  using Map = typename Index_map_of<G, Tag, indexed>::type;

public:
  template <class Range>
  Dense_index(const G& g, const Range& live, D null) : null_(null) {
    if constexpr (indexed) {
      map_.emplace(get(Tag{}, g));
      bound_ = static_cast<std::size_t>(index_bound(Tag{}, g));
      alive_.assign(bound_, 0);
      for (D d : live) {
        std::size_t i = static_cast<std::size_t>(get(*map_, d));
        if (i < bound_) alive_[i] = 1;
      }
    } else {
      for (D d : live) numbers_.emplace(d, static_cast<std::uint32_t>(numbers_.size()));
      bound_ = numbers_.size();
    }
  }

  std::size_t bound() const noexcept { return bound_; }
  /// Whether dense number i (< bound()) is a live element's.
  bool is_live(std::size_t i) const {
    if constexpr (indexed) return alive_[i] != 0;
    else return i < bound_;
  }

  std::uint32_t operator()(D d) const {
    if (d == null_) return k_null;
    if constexpr (indexed) {
      std::size_t i = static_cast<std::size_t>(get(*map_, d));
      return i < bound_ && alive_[i] ? static_cast<std::uint32_t>(i) : k_bad;
    } else {
      auto it = numbers_.find(d);
      return it == numbers_.end() ? k_bad : it->second;
    }
  }

private:
  D null_;
  std::size_t bound_ = 0;
  std::optional<Map> map_;
  std::vector<char> alive_;
  std::unordered_map<D, std::uint32_t> numbers_;
};

} // namespace genmesh::detail
