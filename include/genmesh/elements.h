// genmesh/elements.h — the element layer under genmesh's own meshes: typed
// 32-bit indices, ranges of live elements, and what garbage collection reports.
//
// What it is: Vertex_index, Halfedge_index, Edge_index, Face_index (the
// descriptors of Halfedge_mesh and Incidence_mesh), Range (a pair of
// iterators that is also a range), the iterators over live elements of one
// kind, Index_map (element -> raw index) and Garbage_order /
// Garbage_collection_maps (how collect_garbage() renumbers, and its old -> new
// maps). Both backends stand on it; neither includes the other. The shared
// machinery behind it is in detail/elements/ (index iteration, compaction
// maps, the BGL free functions both meshes share).
//
// Guarantees: indices are regular, trivially copyable, totally ordered and
// hashable (std::hash and boost::hash); the null element is the
// default-constructed index. Halfedges 2e and 2e+1 belong to edge e, so
// opposite(h) = h^1 and edge(h) = h/2 on every mesh built on this layer.
#pragma once

#include <genmesh/detail/elements/index_iterator.h>

#include <boost/property_map/property_map.hpp>

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

// ---------------------------------------------------------------------------
// Index types
// ---------------------------------------------------------------------------

struct Vertex_tag {
  static constexpr char prefix = 'v';
};
struct Halfedge_tag {
  static constexpr char prefix = 'h';
};
struct Edge_tag {
  static constexpr char prefix = 'e';
};
struct Face_tag {
  static constexpr char prefix = 'f';
};

/// A typed 32-bit element index. Default-constructed = invalid (the null
/// element); regular, trivially copyable, totally ordered, hashable.
template <class Tag>
class Mesh_index {
public:
  using size_type = std::uint32_t;
  static constexpr size_type invalid_value = std::numeric_limits<size_type>::max();

  constexpr Mesh_index() = default;
  constexpr explicit Mesh_index(size_type i) : idx_(i) {}

  /// The raw index (invalid_value for the null element).
  [[nodiscard]] constexpr size_type idx() const { return idx_; }
  [[nodiscard]] constexpr bool is_valid() const { return idx_ != invalid_value; }
  /// The raw index as std::size_t (for CGAL-style `(std::size_t)v` code).
  constexpr explicit operator std::size_t() const { return idx_; }

  friend constexpr bool operator==(Mesh_index, Mesh_index) = default;
  friend constexpr auto operator<=>(Mesh_index, Mesh_index) = default;

  friend std::ostream& operator<<(std::ostream& os, Mesh_index i) {
    os << Tag::prefix;
    if (i.is_valid())
      os << i.idx_;
    else
      os << "-null";
    return os;
  }
  /// For boost::hash.
  friend std::size_t hash_value(Mesh_index i) { return i.idx_; }

private:
  size_type idx_ = invalid_value;
};

using Vertex_index = Mesh_index<Vertex_tag>;
using Halfedge_index = Mesh_index<Halfedge_tag>;
using Face_index = Mesh_index<Face_tag>;

/// An edge index that, like CGAL::Surface_mesh's, remembers the halfedge it
/// was made from: halfedge(edge(h)) == h, and source/target of the edge are
/// those of that halfedge (what Boost's out_edges needs). Equality, order and
/// hash use idx() = halfedge / 2 only; Edge_index(i) holds halfedge 2i.
/// Still 4 bytes and trivially copyable.
template <>
class Mesh_index<Edge_tag> {
public:
  using size_type = std::uint32_t;
  static constexpr size_type invalid_value = std::numeric_limits<size_type>::max();

  constexpr Mesh_index() = default;
  constexpr explicit Mesh_index(size_type i) : h_(i == invalid_value ? invalid_value : 2 * i) {}
  constexpr explicit Mesh_index(Halfedge_index h) : h_(h.idx()) {}

  [[nodiscard]] constexpr size_type idx() const { return h_ == invalid_value ? invalid_value : h_ >> 1; }
  [[nodiscard]] constexpr bool is_valid() const { return h_ != invalid_value; }
  /// The halfedge this edge index was made from (2 idx() if made from an index).
  [[nodiscard]] constexpr Halfedge_index halfedge() const { return Halfedge_index(h_); }
  constexpr explicit operator std::size_t() const { return idx(); }

  friend constexpr bool operator==(Mesh_index a, Mesh_index b) { return a.idx() == b.idx(); }
  friend constexpr std::strong_ordering operator<=>(Mesh_index a, Mesh_index b) { return a.idx() <=> b.idx(); }

  friend std::ostream& operator<<(std::ostream& os, Mesh_index e) {
    os << 'e';
    if (e.is_valid())
      os << e.idx();
    else
      os << "-null";
    return os;
  }
  friend std::size_t hash_value(Mesh_index e) { return e.idx(); }

private:
  size_type h_ = invalid_value;
};

using Edge_index = Mesh_index<Edge_tag>;

template <class It>
struct Range;

} // namespace genmesh

template <class It>
struct std::tuple_size<genmesh::Range<It>> : std::integral_constant<std::size_t, 2> {};
template <std::size_t I, class It>
struct std::tuple_element<I, genmesh::Range<It>> {
  using type = It;
};

template <class Tag>
struct std::hash<genmesh::Mesh_index<Tag>> {
  std::size_t operator()(genmesh::Mesh_index<Tag> i) const noexcept {
    return std::hash<std::uint32_t>{}(i.idx());
  }
};

namespace genmesh {

/// How collect_garbage() renumbers the surviving elements.
enum class Garbage_order {
  stable,            ///< survivors keep their relative order (the default)
  like_surface_mesh  ///< exactly CGAL::Surface_mesh's renumbering (swap from the back)
};

/// Old -> new indices made by collect_garbage(); removed elements map to the
/// invalid index. Each vector is as long as the index bound before collection.
struct Garbage_collection_maps {
  std::vector<Vertex_index> vertices;
  std::vector<Halfedge_index> halfedges;
  std::vector<Edge_index> edges;
  std::vector<Face_index> faces;
};

/// A range that is also a std::pair of iterators (CGAL::Iterator_range
/// style: .first/.second, begin()/end(), size(), empty()). size() is O(1) for
/// the element ranges (vertices(), faces(), ...), a walk for the ranges
/// around a face or vertex.
template <class It>
struct Range : std::pair<It, It> {
  using iterator = It;
  using const_iterator = It;
  Range() = default;
  Range(It b, It e) : std::pair<It, It>(b, e) {}
  Range(It b, It e, std::size_t n) : std::pair<It, It>(b, e), size_(n) {}
  [[nodiscard]] It begin() const { return this->first; }
  [[nodiscard]] It end() const { return this->second; }
  [[nodiscard]] bool empty() const { return this->first == this->second; }
  [[nodiscard]] std::size_t size() const {
    if (size_ != unknown) return size_;
    return static_cast<std::size_t>(std::distance(this->first, this->second));
  }
  /// For `auto [b, e] = range;`.
  template <std::size_t I>
  [[nodiscard]] It get() const {
    static_assert(I < 2);
    if constexpr (I == 0)
      return this->first;
    else
      return this->second;
  }

private:
  static constexpr std::size_t unknown = static_cast<std::size_t>(-1);
  std::size_t size_ = unknown;
};

// ---------------------------------------------------------------------------
// Iterators over the live elements of one kind
// ---------------------------------------------------------------------------

using Vertex_iterator = detail::Index_iterator<Vertex_index, 0>;
using Halfedge_iterator = detail::Index_iterator<Halfedge_index, 1>;
using Edge_iterator = detail::Index_iterator<Edge_index, 0>;
using Face_iterator = detail::Index_iterator<Face_index, 0>;

// ---------------------------------------------------------------------------
// Property maps for algorithms
// ---------------------------------------------------------------------------

/// A readable property map element -> its raw index as std::size_t.
template <class Key>
struct Index_map : boost::put_get_helper<std::size_t, Index_map<Key>> {
  using key_type = Key;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;
  std::size_t operator[](Key k) const { return k.idx(); }
};


} // namespace genmesh
