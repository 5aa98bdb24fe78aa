// genmesh/halfedge_mesh.h — genmesh's own halfedge mesh: Halfedge_mesh<Point>.
//
// What it is: an index-based halfedge data structure stored as a structure of
// arrays with 32-bit indices. The two halfedges of edge e are 2e and 2e+1, so
// opposite(h) = h^1 and edge(h).idx() = h/2 are arithmetic. Per halfedge it stores
// next, prev, target vertex and face (next and target in arrays of their own,
// which walks read; prev and face paired, which edits read and write
// together; the three in one allocation); per vertex one halfedge *targeting* it
// (null if isolated); per face one of its halfedges; one removed bit per vertex,
// edge and face. Positions and any user data are typed dynamic properties
// (positions are the vertex property "v:point").
//
// Guarantees:
// - Memory is CGAL::Surface_mesh's, byte for byte: the same 4-byte indices
//   (16 bytes per halfedge, 4 per vertex and face), the same removed bits,
//   the same doubling growth, so bytes per element never exceed
//   Surface_mesh's on the same mesh (about 66 bytes per triangle with
//   double points); memory_bytes() reports the total.
// - Index allocation is CGAL::Surface_mesh's exactly: remove_* only marks and
//   pushes onto a LIFO free list (threaded through the removed element's own
//   halfedge/next slot), add_* reuses the most recently freed index when
//   recycling is on (the default), else appends; a recycled element's
//   connectivity is null and its properties get their default values again.
//   Iteration is by increasing index, skipping removed elements. So a sequence
//   of low-level edits (and every CGAL algorithm made of them) gives the same
//   indices on both meshes.
// - collect_garbage() compacts *preserving the relative order* of surviving
//   elements (Surface_mesh instead swaps the last live element into each hole;
//   collect_garbage(Garbage_order::like_surface_mesh) does that too) and
//   returns the old -> new maps. Determinism across backends is stated up
//   to canonical soups, so this deviation is harmless there, and it keeps
//   iteration order meaningful after compaction.
// - Like Surface_mesh's, an Edge_index made by edge(h) remembers h, so
//   halfedge(edge(h)) == h and CGAL code relying on that behaves identically.
//
// Limits: the low-level edits (set_next, remove_edge, ...) keep nothing
// consistent by themselves, as in CGAL; algorithms use local operations.
// num_vertices(m) & co. are *live* counts (genmesh's convention), whereas
// CGAL's BGL concept only promises an upper bound and Surface_mesh returns
// its index bound; scratch arrays must be sized by index_bound / *_size().
//
// The whole CGAL BGL free-function surface (graph_traits, next, opposite,
// add_face, set_next, ...) is at the bottom of this header, found by ADL.
// No CGAL header is needed here; <genmesh/adaptors/cgal.h> adds CGAL's
// property-map tags.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/property_array.h>
#include <genmesh/exceptions.h>
#include <genmesh/mesh_properties.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>

#include <Eigen/Core>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cassert>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
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

/// Property handles: boost lvalue property maps indexed by element.
template <class T>
using Vertex_property = detail::Property_map<Vertex_index, T>;
template <class T>
using Halfedge_property = detail::Property_map<Halfedge_index, T>;
template <class T>
using Edge_property = detail::Property_map<Edge_index, T>;
template <class T>
using Face_property = detail::Property_map<Face_index, T>;

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

namespace detail {

/// Old -> new indices for one element kind, as collect_garbage() renumbers
/// (shared by Halfedge_mesh and Incidence_mesh): removed[i] maps to the null
/// index, survivors to [0, live count) in `order`.
inline std::vector<std::uint32_t> compaction_map(const std::vector<bool>& removed, Garbage_order order) {
  constexpr std::uint32_t null = Vertex_index::invalid_value;
  const std::size_t n = removed.size();
  std::vector<std::uint32_t> map(n);
  if (order == Garbage_order::stable) {
    std::uint32_t k = 0;
    for (std::size_t i = 0; i < n; ++i) map[i] = removed[i] ? null : k++;
    return map;
  }
  // Surface_mesh's two-finger swap: i0 finds holes from the front, i1 live
  // elements from the back; i1 moves to i0.
  for (std::size_t i = 0; i < n; ++i) map[i] = removed[i] ? null : static_cast<std::uint32_t>(i);
  if (n == 0) return map;
  std::vector<bool> r = removed;
  std::size_t i0 = 0, i1 = n - 1;
  while (true) {
    while (!r[i0] && i0 < i1) ++i0;
    while (r[i1] && i0 < i1) --i1;
    if (i0 >= i1) break;
    map[i1] = static_cast<std::uint32_t>(i0);
    r[i0] = false;
    r[i1] = true;
  }
  return map;
}

/// The halfedge map of an edge compaction map: halfedges 2e and 2e + 1 go
/// with their edge e.
inline std::vector<std::uint32_t> halfedge_compaction_map(const std::vector<std::uint32_t>& emap) {
  constexpr std::uint32_t null = Vertex_index::invalid_value;
  std::vector<std::uint32_t> hmap(2 * emap.size());
  for (std::size_t e = 0; e < emap.size(); ++e) {
    hmap[2 * e] = emap[e] == null ? null : 2 * emap[e];
    hmap[2 * e + 1] = emap[e] == null ? null : 2 * emap[e] + 1;
  }
  return hmap;
}

} // namespace detail

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

class Halfedge_connectivity;
namespace detail {
struct Halfedge_mesh_bulk;
}

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

/// Walks a halfedge cycle from an anchor (CGAL's iterator-over-circulator
/// scheme: begin = (anchor, winding 0), end = (anchor, winding 1)).
/// Step provides next(m, h) and value(m, h).
template <class Step>
class Cycle_iterator {
public:
  using value_type = typename Step::value_type;
  using reference = value_type;
  using pointer = void;
  using difference_type = std::ptrdiff_t;
  using iterator_category = std::forward_iterator_tag;
  using iterator_concept = std::forward_iterator_tag;

  Cycle_iterator() = default;
  Cycle_iterator(const Halfedge_connectivity* m, Halfedge_index anchor, int winding)
      : m_(m), pos_(anchor), anchor_(anchor), winding_(anchor.is_valid() ? winding : 1) {}

  value_type operator*() const { return Step::value(*m_, pos_); }
  Cycle_iterator& operator++() {
    pos_ = Step::next(*m_, pos_);
    if (pos_ == anchor_) ++winding_;
    return *this;
  }
  Cycle_iterator operator++(int) {
    Cycle_iterator t = *this;
    ++*this;
    return t;
  }
  friend bool operator==(const Cycle_iterator& a, const Cycle_iterator& b) {
    return a.pos_ == b.pos_ && a.winding_ == b.winding_;
  }

private:
  const Halfedge_connectivity* m_ = nullptr;
  Halfedge_index pos_;
  Halfedge_index anchor_;
  int winding_ = 1;
};

// Steps are templates on the mesh so they can precede Halfedge_connectivity.
struct Step_face {
  using value_type = Halfedge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next(h); }
  template <class M>
  static Halfedge_index value(const M&, Halfedge_index h) { return h; }
};
struct Step_face_vertex {
  using value_type = Vertex_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next(h); }
  template <class M>
  static Vertex_index value(const M& m, Halfedge_index h) { return m.target(h); }
};
struct Step_target {
  using value_type = Halfedge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Halfedge_index value(const M&, Halfedge_index h) { return h; }
};
struct Step_target_vertex {
  using value_type = Vertex_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Vertex_index value(const M& m, Halfedge_index h) { return m.source(h); }
};
struct Step_target_in_edge {
  using value_type = Edge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Edge_index value(const M&, Halfedge_index h) { return Edge_index(h); }
};
struct Step_target_out_edge {
  using value_type = Edge_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Edge_index value(const M&, Halfedge_index h) { return Edge_index(Halfedge_index(h.idx() ^ 1u)); }
};
struct Step_target_face {
  using value_type = Face_index;
  template <class M>
  static Halfedge_index next(const M& m, Halfedge_index h) { return m.next_around_target(h); }
  template <class M>
  static Face_index value(const M& m, Halfedge_index h) { return m.face(h); }
};

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

template <class P>
P default_point() {
  if constexpr (Point3<P>)
    return Point_traits<P>::make(0.0, 0.0, 0.0);
  else
    return P{};
}

} // namespace detail

using Vertex_iterator = detail::Index_iterator<Vertex_index, 0>;
using Halfedge_iterator = detail::Index_iterator<Halfedge_index, 1>;
using Edge_iterator = detail::Index_iterator<Edge_index, 0>;
using Face_iterator = detail::Index_iterator<Face_index, 0>;

namespace detail {
/// The live elements [0, bound) of one kind, `live` of them; removed ones are
/// skipped only when the mesh has garbage (else no flag is read).
template <class It>
Range<It> live_range(std::size_t bound, std::size_t live, const std::vector<bool>& removed, bool garbage) {
  const auto n = static_cast<std::uint32_t>(bound);
  const std::vector<bool>* r = garbage ? &removed : nullptr;
  return {It(0, n, r), It(n, n, r), live};
}
} // namespace detail

using Halfedge_around_face_iterator = detail::Cycle_iterator<detail::Step_face>;
using Vertex_around_face_iterator = detail::Cycle_iterator<detail::Step_face_vertex>;
using Halfedge_around_target_iterator = detail::Cycle_iterator<detail::Step_target>;
using Vertex_around_target_iterator = detail::Cycle_iterator<detail::Step_target_vertex>;
using Face_around_target_iterator = detail::Cycle_iterator<detail::Step_target_face>;
/// Edges e around a vertex v with target(e) == v (in) or source(e) == v (out).
using In_edge_iterator = detail::Cycle_iterator<detail::Step_target_in_edge>;
using Out_edge_iterator = detail::Cycle_iterator<detail::Step_target_out_edge>;

// ---------------------------------------------------------------------------
// Connectivity (everything but the point type)
// ---------------------------------------------------------------------------

/// The connectivity and properties of a Halfedge_mesh; the point type is added
/// by Halfedge_mesh<Point>. Not used on its own.
class Halfedge_connectivity : public Mesh_properties<Vertex_index, Halfedge_index, Edge_index, Face_index> {
public:
  using size_type = std::size_t;

  static constexpr Vertex_index null_vertex() { return {}; }
  static constexpr Halfedge_index null_halfedge() { return {}; }
  static constexpr Edge_index null_edge() { return {}; }
  static constexpr Face_index null_face() { return {}; }

  // ---- counts -------------------------------------------------------------

  /// Live (not removed) elements.
  [[nodiscard]] size_type n_vertices() const { return vertices_size() - removed_vertices_; }
  [[nodiscard]] size_type n_halfedges() const { return halfedges_size() - 2 * removed_edges_; }
  [[nodiscard]] size_type n_edges() const { return edges_size() - removed_edges_; }
  [[nodiscard]] size_type n_faces() const { return faces_size() - removed_faces_; }
  [[nodiscard]] bool is_empty() const { return n_vertices() == 0; }
  /// Surface_mesh's spellings of the live counts.
  [[nodiscard]] size_type number_of_vertices() const { return n_vertices(); }
  [[nodiscard]] size_type number_of_halfedges() const { return n_halfedges(); }
  [[nodiscard]] size_type number_of_edges() const { return n_edges(); }
  [[nodiscard]] size_type number_of_faces() const { return n_faces(); }

  /// Index bounds: live plus removed, not yet collected, elements.
  [[nodiscard]] size_type vertices_size() const { return vhalfedge_.size(); }
  [[nodiscard]] size_type halfedges_size() const { return hlinks_.size(); }
  [[nodiscard]] size_type edges_size() const { return hlinks_.size() / 2; }
  [[nodiscard]] size_type faces_size() const { return fhalfedge_.size(); }

  [[nodiscard]] size_type number_of_removed_vertices() const { return removed_vertices_; }
  [[nodiscard]] size_type number_of_removed_halfedges() const { return 2 * removed_edges_; }
  [[nodiscard]] size_type number_of_removed_edges() const { return removed_edges_; }
  [[nodiscard]] size_type number_of_removed_faces() const { return removed_faces_; }

  // ---- validity -----------------------------------------------------------

  [[nodiscard]] bool is_removed(Vertex_index v) const { return vremoved_[v.idx()]; }
  [[nodiscard]] bool is_removed(Halfedge_index h) const { return eremoved_[h.idx() >> 1]; }
  [[nodiscard]] bool is_removed(Edge_index e) const { return eremoved_[e.idx()]; }
  [[nodiscard]] bool is_removed(Face_index f) const { return fremoved_[f.idx()]; }

  /// Index within the current bounds (removed or not), as CGAL's has_valid_index.
  [[nodiscard]] bool has_valid_index(Vertex_index v) const { return v.idx() < vertices_size(); }
  [[nodiscard]] bool has_valid_index(Halfedge_index h) const { return h.idx() < halfedges_size(); }
  [[nodiscard]] bool has_valid_index(Edge_index e) const { return e.idx() < edges_size(); }
  [[nodiscard]] bool has_valid_index(Face_index f) const { return f.idx() < faces_size(); }

  /// Within bounds and not removed.
  [[nodiscard]] bool is_valid(Vertex_index v) const { return has_valid_index(v) && !is_removed(v); }
  [[nodiscard]] bool is_valid(Halfedge_index h) const { return has_valid_index(h) && !is_removed(h); }
  [[nodiscard]] bool is_valid(Edge_index e) const { return has_valid_index(e) && !is_removed(e); }
  [[nodiscard]] bool is_valid(Face_index f) const { return has_valid_index(f) && !is_removed(f); }

  // ---- connectivity -------------------------------------------------------

  [[nodiscard]] Halfedge_index next(Halfedge_index h) const { return hlinks_.next(h.idx()); }
  [[nodiscard]] Halfedge_index prev(Halfedge_index h) const { return hlinks_.prev(h.idx()); }
  [[nodiscard]] Vertex_index target(Halfedge_index h) const { return hlinks_.target(h.idx()); }
  [[nodiscard]] Vertex_index source(Halfedge_index h) const { return hlinks_.target(h.idx() ^ 1u); }
  [[nodiscard]] Face_index face(Halfedge_index h) const { return hlinks_.face(h.idx()); }
  [[nodiscard]] static constexpr Halfedge_index opposite(Halfedge_index h) {
    return Halfedge_index(h.idx() ^ 1u);
  }
  /// The edge of h, remembering h (see Edge_index).
  [[nodiscard]] static constexpr Edge_index edge(Halfedge_index h) { return Edge_index(h); }
  /// The halfedge e was made from: h for edge(h), 2e for Edge_index(e) and
  /// for the edges of edges() (as Surface_mesh).
  [[nodiscard]] static constexpr Halfedge_index halfedge(Edge_index e) { return e.halfedge(); }
  /// Halfedge i (0 or 1) of e: 2e + i.
  [[nodiscard]] static constexpr Halfedge_index halfedge(Edge_index e, unsigned i) {
    return Halfedge_index((e.idx() << 1) + i);
  }
  /// Vertex i (0 or 1) of e: target(halfedge(e, i)).
  [[nodiscard]] Vertex_index vertex(Edge_index e, unsigned i) const { return target(halfedge(e, i)); }
  /// A halfedge with target v; null if v is isolated.
  [[nodiscard]] Halfedge_index halfedge(Vertex_index v) const { return vhalfedge_[v.idx()]; }
  [[nodiscard]] Halfedge_index halfedge(Face_index f) const { return fhalfedge_[f.idx()]; }
  /// The halfedge from u to v, or null (searches around v).
  [[nodiscard]] Halfedge_index halfedge(Vertex_index u, Vertex_index v) const {
    const Halfedge_index start = halfedge(v);
    if (!start.is_valid()) return {};
    Halfedge_index h = start;
    do {
      if (source(h) == u) return h;
      h = next_around_target(h);
    } while (h != start);
    return {};
  }

  /// opposite(next(h)): the next halfedge clockwise around target(h).
  [[nodiscard]] Halfedge_index next_around_target(Halfedge_index h) const { return opposite(next(h)); }
  /// prev(opposite(h)).
  [[nodiscard]] Halfedge_index prev_around_target(Halfedge_index h) const { return prev(opposite(h)); }
  /// next(opposite(h)).
  [[nodiscard]] Halfedge_index next_around_source(Halfedge_index h) const { return next(opposite(h)); }
  /// opposite(prev(h)).
  [[nodiscard]] Halfedge_index prev_around_source(Halfedge_index h) const { return opposite(prev(h)); }

  /// next(h) = nh and, if nh is not null, prev(nh) = h (as Surface_mesh).
  void set_next(Halfedge_index h, Halfedge_index nh) {
    hlinks_.next(h.idx()) = nh;
    if (nh.is_valid()) hlinks_.prev(nh.idx()) = h;
  }
  void set_next_only(Halfedge_index h, Halfedge_index nh) { hlinks_.next(h.idx()) = nh; }
  void set_prev_only(Halfedge_index h, Halfedge_index ph) {
    if (h.is_valid()) hlinks_.prev(h.idx()) = ph;
  }
  void set_target(Halfedge_index h, Vertex_index v) { hlinks_.target(h.idx()) = v; }
  void set_face(Halfedge_index h, Face_index f) { hlinks_.face(h.idx()) = f; }
  void set_halfedge(Vertex_index v, Halfedge_index h) { vhalfedge_[v.idx()] = h; }
  void set_halfedge(Face_index f, Halfedge_index h) { fhalfedge_[f.idx()] = h; }

  // ---- borders and degrees ------------------------------------------------

  /// face(h) is null.
  [[nodiscard]] bool is_border(Halfedge_index h) const { return !face(h).is_valid(); }
  /// Either halfedge of e is a border halfedge.
  [[nodiscard]] bool is_border(Edge_index e) const {
    return is_border(halfedge(e, 0)) || is_border(halfedge(e, 1));
  }
  /// v is isolated or incident to a border halfedge. With check_all = false,
  /// only halfedge(v) is looked at (O(1) if border vertices keep a border
  /// halfedge, as Surface_mesh's flag does).
  [[nodiscard]] bool is_border(Vertex_index v, bool check_all = true) const {
    const Halfedge_index start = halfedge(v);
    if (!start.is_valid()) return true;
    if (!check_all) return is_border(start);
    Halfedge_index h = start;
    do {
      if (is_border(h)) return true;
      h = next_around_target(h);
    } while (h != start);
    return false;
  }
  [[nodiscard]] bool is_isolated(Vertex_index v) const { return !halfedge(v).is_valid(); }

  /// Number of halfedges targeting v (0 if isolated).
  [[nodiscard]] size_type degree(Vertex_index v) const {
    const Halfedge_index start = halfedge(v);
    if (!start.is_valid()) return 0;
    size_type n = 0;
    Halfedge_index h = start;
    do {
      ++n;
      h = next_around_target(h);
    } while (h != start);
    return n;
  }
  /// Number of halfedges around f (0 if f has no halfedge).
  [[nodiscard]] size_type degree(Face_index f) const {
    const Halfedge_index start = halfedge(f);
    if (!start.is_valid()) return 0;
    size_type n = 0;
    Halfedge_index h = start;
    do {
      ++n;
      h = next(h);
    } while (h != start);
    return n;
  }

  // ---- adding and removing ------------------------------------------------

  /// A new isolated vertex (recycled if possible); its properties have their defaults.
  Vertex_index add_vertex() {
    if (recycle_ && vertices_freelist_ != invalid) [[unlikely]]
      return recycle_vertex();
    check_room(vhalfedge_.size());
    vhalfedge_.push_back(Halfedge_index());
    vremoved_.push_back(false);
    vprops_.push_back();
    return Vertex_index(static_cast<std::uint32_t>(vhalfedge_.size() - 1));
  }

  /// A new edge (recycled if possible) with null connectivity; returns its
  /// halfedge 0 (2e).
  Halfedge_index add_edge() {
    if (recycle_ && edges_freelist_ != invalid) [[unlikely]]
      return recycle_edge();
    check_room(hlinks_.size() + 1);
    const auto h = static_cast<std::uint32_t>(hlinks_.push_back_pair());
    hprops_.push_back();
    hprops_.push_back();
    eremoved_.push_back(false);
    eprops_.push_back();
    return Halfedge_index(h);
  }

  /// A new edge from v0 to v1: returns the halfedge targeting v1 (its opposite
  /// targets v0). halfedge(v0)/halfedge(v1) are not changed.
  Halfedge_index add_edge(Vertex_index v0, Vertex_index v1) {
    const Halfedge_index h = add_edge();
    set_target(h, v1);
    set_target(opposite(h), v0);
    return h;
  }

  /// A new face (recycled if possible) with no halfedge.
  Face_index add_face() {
    if (recycle_ && faces_freelist_ != invalid) [[unlikely]]
      return recycle_face();
    check_room(fhalfedge_.size());
    fhalfedge_.push_back(Halfedge_index());
    fremoved_.push_back(false);
    fprops_.push_back();
    return Face_index(static_cast<std::uint32_t>(fhalfedge_.size() - 1));
  }

  /// Marks v removed and frees its index; adjusts nothing else. Removing an
  /// element twice is a precondition violation (asserted in debug builds).
  void remove_vertex(Vertex_index v) {
    assert(!vremoved_[v.idx()] && "removed twice");
    vremoved_[v.idx()] = true;
    ++removed_vertices_;
    garbage_ = true;
    vhalfedge_[v.idx()] = Halfedge_index(vertices_freelist_);
    vertices_freelist_ = v.idx();
  }
  /// Marks e (both halfedges) removed and frees its index; adjusts nothing else.
  void remove_edge(Edge_index e) {
    assert(!eremoved_[e.idx()] && "removed twice");
    eremoved_[e.idx()] = true;
    ++removed_edges_;
    garbage_ = true;
    hlinks_.next(e.idx() << 1) = Halfedge_index(edges_freelist_);
    edges_freelist_ = e.idx() << 1;
  }
  /// Marks f removed and frees its index; adjusts nothing else.
  void remove_face(Face_index f) {
    assert(!fremoved_[f.idx()] && "removed twice");
    fremoved_[f.idx()] = true;
    ++removed_faces_;
    garbage_ = true;
    fhalfedge_[f.idx()] = Halfedge_index(faces_freelist_);
    faces_freelist_ = f.idx();
  }

  /// Some element was removed since the last collect_garbage() (stays true
  /// when removed indices were recycled, as in Surface_mesh).
  [[nodiscard]] bool has_garbage() const { return garbage_; }
  /// Whether add_* reuses removed indices (default true).
  void set_recycle_garbage(bool b) { recycle_ = b; }
  [[nodiscard]] bool does_recycle_garbage() const { return recycle_; }

  /// Drops removed elements, updates connectivity and compacts every
  /// property; returns the old -> new maps (identity if there was no
  /// garbage). Links to removed elements become null. Shrinks storage to fit,
  /// as Surface_mesh does. With Garbage_order::stable (the default) survivors
  /// keep their relative order; with Garbage_order::like_surface_mesh they are
  /// renumbered exactly as CGAL::Surface_mesh::collect_garbage() does (the
  /// last live element fills the first hole, repeatedly).
  Garbage_collection_maps collect_garbage(Garbage_order order = Garbage_order::stable) {
    const std::uint32_t nv = static_cast<std::uint32_t>(vertices_size());
    const std::uint32_t ne = static_cast<std::uint32_t>(edges_size());
    const std::uint32_t nf = static_cast<std::uint32_t>(faces_size());
    const std::vector<std::uint32_t> vmap = detail::compaction_map(vremoved_, order);
    const std::vector<std::uint32_t> emap = detail::compaction_map(eremoved_, order);
    const std::vector<std::uint32_t> fmap = detail::compaction_map(fremoved_, order);
    const std::vector<std::uint32_t> hmap = detail::halfedge_compaction_map(emap);
    auto kept = [](const std::vector<std::uint32_t>& map) {
      return static_cast<std::uint32_t>(std::ranges::count_if(map, [](std::uint32_t i) { return i != invalid; }));
    };
    const std::uint32_t kv = kept(vmap), ke = kept(emap), kf = kept(fmap);

    if (garbage_) {
      auto map_h = [&](Halfedge_index h) {
        return h.is_valid() && h.idx() < hmap.size() ? Halfedge_index(hmap[h.idx()]) : Halfedge_index();
      };
      auto map_v = [&](Vertex_index v) {
        return v.is_valid() && v.idx() < nv ? Vertex_index(vmap[v.idx()]) : Vertex_index();
      };
      auto map_f = [&](Face_index f) {
        return f.is_valid() && f.idx() < nf ? Face_index(fmap[f.idx()]) : Face_index();
      };
      // Every destination is the source itself or a removed slot (whose old
      // content is never read), so moving in place in any order is safe.
      for (std::uint32_t i = 0; i < nv; ++i)
        if (vmap[i] != invalid) vhalfedge_[vmap[i]] = map_h(vhalfedge_[i]);
      for (std::uint32_t i = 0; i < 2 * ne; ++i) {
        if (hmap[i] == invalid) continue;
        const std::uint32_t j = hmap[i];
        hlinks_.next(j) = map_h(hlinks_.next(i));
        hlinks_.prev(j) = map_h(hlinks_.prev(i));
        hlinks_.target(j) = map_v(hlinks_.target(i));
        hlinks_.face(j) = map_f(hlinks_.face(i));
      }
      for (std::uint32_t i = 0; i < nf; ++i)
        if (fmap[i] != invalid) fhalfedge_[fmap[i]] = map_h(fhalfedge_[i]);

      vhalfedge_.resize(kv);
      hlinks_.resize(2 * std::size_t(ke));
      fhalfedge_.resize(kf);
      vremoved_.assign(kv, false);
      eremoved_.assign(ke, false);
      fremoved_.assign(kf, false);
      vprops_.compact(vmap, kv);
      hprops_.compact(hmap, 2 * std::size_t(ke));
      eprops_.compact(emap, ke);
      fprops_.compact(fmap, kf);
      shrink_to_fit();

      removed_vertices_ = removed_edges_ = removed_faces_ = 0;
      vertices_freelist_ = edges_freelist_ = faces_freelist_ = invalid;
      garbage_ = false;
    }

    Garbage_collection_maps maps;
    maps.vertices.reserve(nv);
    for (auto i : vmap) maps.vertices.emplace_back(i);
    maps.halfedges.reserve(hmap.size());
    for (auto i : hmap) maps.halfedges.emplace_back(i);
    maps.edges.reserve(ne);
    for (auto i : emap) maps.edges.emplace_back(i);
    maps.faces.reserve(nf);
    for (auto i : fmap) maps.faces.emplace_back(i);
    return maps;
  }

  /// Capacity for nv vertices, ne edges (2 ne halfedges) and nf faces, in
  /// connectivity and every property.
  void reserve(size_type nv, size_type ne, size_type nf) {
    vhalfedge_.reserve(nv);
    vremoved_.reserve(nv);
    vprops_.reserve(nv);
    hlinks_.reserve(2 * ne);
    hprops_.reserve(2 * ne);
    eremoved_.reserve(ne);
    eprops_.reserve(ne);
    fhalfedge_.reserve(nf);
    fremoved_.reserve(nf);
    fprops_.reserve(nf);
  }

  /// Releases unused capacity of every array.
  void shrink_to_fit() {
    vhalfedge_.shrink_to_fit();
    hlinks_.shrink_to_fit();
    fhalfedge_.shrink_to_fit();
    vremoved_.shrink_to_fit();
    eremoved_.shrink_to_fit();
    fremoved_.shrink_to_fit();
    vprops_.shrink_to_fit();
    hprops_.shrink_to_fit();
    eprops_.shrink_to_fit();
    fprops_.shrink_to_fit();
  }

  /// Bytes held by all arrays (capacities: connectivity, removed bits, every
  /// property including the points); excludes the fixed-size object itself.
  [[nodiscard]] size_type memory_bytes() const {
    auto bits = [](const std::vector<bool>& b) { return (b.capacity() + 7) / 8; };
    return sizeof(Halfedge_index) * (vhalfedge_.capacity() + 2 * hlinks_.capacity() + fhalfedge_.capacity()) +
           (sizeof(Vertex_index) + sizeof(Face_index)) * hlinks_.capacity() +
           bits(vremoved_) + bits(eremoved_) + bits(fremoved_) + vprops_.memory_bytes() +
           hprops_.memory_bytes() + eprops_.memory_bytes() + fprops_.memory_bytes();
  }

  // ---- ranges -------------------------------------------------------------

  /// Live vertices by increasing index (also halfedges(), edges(), faces()).
  [[nodiscard]] Range<Vertex_iterator> vertices() const {
    return detail::live_range<Vertex_iterator>(vertices_size(), n_vertices(), vremoved_, garbage_);
  }
  [[nodiscard]] Range<Halfedge_iterator> halfedges() const {
    return detail::live_range<Halfedge_iterator>(halfedges_size(), n_halfedges(), eremoved_, garbage_);
  }
  [[nodiscard]] Range<Edge_iterator> edges() const {
    return detail::live_range<Edge_iterator>(edges_size(), n_edges(), eremoved_, garbage_);
  }
  [[nodiscard]] Range<Face_iterator> faces() const {
    return detail::live_range<Face_iterator>(faces_size(), n_faces(), fremoved_, garbage_);
  }

  /// h, next(h), next(next(h)), ... once around the cycle (empty for null h).
  [[nodiscard]] Range<Halfedge_around_face_iterator> halfedges_around_face(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Halfedge_around_face_iterator> halfedges_around_face(Face_index f) const {
    return halfedges_around_face(halfedge(f));
  }
  /// target of each halfedge of halfedges_around_face(h).
  [[nodiscard]] Range<Vertex_around_face_iterator> vertices_around_face(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Vertex_around_face_iterator> vertices_around_face(Face_index f) const {
    return vertices_around_face(halfedge(f));
  }
  /// h, opposite(next(h)), ...: every halfedge targeting target(h), clockwise.
  [[nodiscard]] Range<Halfedge_around_target_iterator> halfedges_around_target(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Halfedge_around_target_iterator> halfedges_around_target(Vertex_index v) const {
    return halfedges_around_target(halfedge(v));
  }
  /// source of each halfedge of halfedges_around_target(h): the neighbours.
  [[nodiscard]] Range<Vertex_around_target_iterator> vertices_around_target(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Vertex_around_target_iterator> vertices_around_target(Vertex_index v) const {
    return vertices_around_target(halfedge(v));
  }
  /// face of each halfedge of halfedges_around_target(h). As in CGAL, border
  /// halfedges give null_face() (not skipped), and a face may repeat on a
  /// non-manifold configuration.
  [[nodiscard]] Range<Face_around_target_iterator> faces_around_target(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Face_around_target_iterator> faces_around_target(Vertex_index v) const {
    return faces_around_target(halfedge(v));
  }
  /// The sources of the halfedges around v (Boost adjacent_vertices).
  [[nodiscard]] Range<Vertex_around_target_iterator> adjacent_vertices(Vertex_index v) const {
    return vertices_around_target(v);
  }
  /// The edges targeting v, each oriented towards v (Boost in_edges).
  [[nodiscard]] Range<In_edge_iterator> in_edges(Vertex_index v) const {
    return {{this, halfedge(v), 0}, {this, halfedge(v), 1}};
  }
  /// The edges leaving v, each oriented away from v (Boost out_edges).
  [[nodiscard]] Range<Out_edge_iterator> out_edges(Vertex_index v) const {
    return {{this, halfedge(v), 0}, {this, halfedge(v), 1}};
  }

protected:
  static constexpr std::uint32_t invalid = Vertex_index::invalid_value;

  Halfedge_connectivity() = default;

  /// Back to empty, every property removed (the derived mesh re-adds points).
  void clear_connectivity() {
    *this = Halfedge_connectivity();
  }

  friend struct detail::Halfedge_mesh_bulk; // bulk growth (detail/halfedge_mesh_bulk.h)

  static void check_room(std::size_t size) {
    // Two indices per edge must stay below the null value.
    if (size + 2 >= std::size_t(invalid)) [[unlikely]]
      too_many();
  }
  [[noreturn]] static void too_many() { throw invalid_input("Halfedge_mesh: more than 2^32-2 elements"); }

  // The recycling halves of add_vertex/add_edge/add_face, kept out of the
  // appending path so that it stays small enough to inline.
  Vertex_index recycle_vertex() {
    const std::uint32_t i = vertices_freelist_;
    vertices_freelist_ = vhalfedge_[i].idx();
    --removed_vertices_;
    vremoved_[i] = false;
    vhalfedge_[i] = Halfedge_index();
    vprops_.reset(i);
    return Vertex_index(i);
  }
  Halfedge_index recycle_edge() {
    const std::uint32_t h = edges_freelist_;
    edges_freelist_ = hlinks_.next(h).idx();
    --removed_edges_;
    eremoved_[h >> 1] = false;
    for (std::uint32_t k : {h, h ^ 1u}) {
      hlinks_.next(k) = hlinks_.prev(k) = Halfedge_index();
      hlinks_.target(k) = Vertex_index();
      hlinks_.face(k) = Face_index();
      hprops_.reset(k);
    }
    eprops_.reset(h >> 1);
    return Halfedge_index(h);
  }
  Face_index recycle_face() {
    const std::uint32_t i = faces_freelist_;
    faces_freelist_ = fhalfedge_[i].idx();
    --removed_faces_;
    fremoved_[i] = false;
    fhalfedge_[i] = Halfedge_index();
    fprops_.reset(i);
    return Face_index(i);
  }

  detail::Halfedge_links hlinks_;
  std::vector<Halfedge_index> vhalfedge_;
  std::vector<Halfedge_index> fhalfedge_;
  std::vector<bool> vremoved_, eremoved_, fremoved_;
  std::size_t removed_vertices_ = 0, removed_edges_ = 0, removed_faces_ = 0;
  std::uint32_t vertices_freelist_ = invalid, edges_freelist_ = invalid, faces_freelist_ = invalid;
  bool garbage_ = false;
  bool recycle_ = true;
};


// ---------------------------------------------------------------------------
// Halfedge_mesh<Point>
// ---------------------------------------------------------------------------

/// genmesh's own halfedge mesh; see the top of this header for the layout and
/// the guarantees. Point is any copyable type (Eigen::Vector3d by default);
/// genmesh algorithms need Point_traits<Point> (point_traits.h), CGAL's need
/// a CGAL point (Halfedge_mesh<K::Point_3>, see <genmesh/adaptors/cgal.h>).
///
/// Copies are deep (properties included). A property handle belongs to the
/// mesh it came from: after a copy, look the property up by name in the copy.
/// Handles give mutable access even when obtained from a const mesh, as in
/// CGAL and pmp.
template <class P = Eigen::Vector3d>
class Halfedge_mesh : public Halfedge_connectivity {
public:
  using Point = P;

  Halfedge_mesh() { points_ = vprops_.add<P>("v:point", detail::default_point<P>()); }
  Halfedge_mesh(const Halfedge_mesh& o) : Halfedge_connectivity(o) { rebind_points(); }
  Halfedge_mesh(Halfedge_mesh&& o) noexcept : Halfedge_connectivity(std::move(o)), points_(o.points_) {
    o.reset_after_move();
  }
  Halfedge_mesh& operator=(const Halfedge_mesh& o) {
    if (this != &o) {
      Halfedge_connectivity::operator=(o);
      rebind_points();
    }
    return *this;
  }
  Halfedge_mesh& operator=(Halfedge_mesh&& o) noexcept {
    if (this != &o) {
      Halfedge_connectivity::operator=(std::move(o));
      points_ = o.points_;
      o.reset_after_move();
    }
    return *this;
  }
  ~Halfedge_mesh() = default;

  using Halfedge_connectivity::add_vertex;
  /// A new isolated vertex at p.
  Vertex_index add_vertex(const Point& p) {
    const Vertex_index v = add_vertex();
    points_[v] = p;
    return v;
  }

  Point& point(Vertex_index v) { return points_[v]; }
  const Point& point(Vertex_index v) const { return points_[v]; }
  /// The positions, as a vertex property (a boost lvalue property map).
  [[nodiscard]] Vertex_property<Point> points() const { return points_; }

  /// Back to a new, empty mesh: every element and every property but the
  /// positions is gone; recycling is on again.
  void clear() {
    clear_connectivity();
    points_ = vprops_.add<P>("v:point", detail::default_point<P>());
  }

private:
  void rebind_points() { points_ = *vprops_.template get<P>("v:point"); }
  void reset_after_move() {
    clear_connectivity();
    points_ = vprops_.add<P>("v:point", detail::default_point<P>());
  }

  Vertex_property<Point> points_;
};

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

// get(vertex_point_t / *_index_t, m) and index_bound(tag, m): see
// <genmesh/detail/mesh_functions.h>.

// ---------------------------------------------------------------------------
// Scoped (RAII) properties
// ---------------------------------------------------------------------------

template <class T>
using Scoped_vertex_property = Scoped_property<Vertex_index, T>;
template <class T>
using Scoped_halfedge_property = Scoped_property<Halfedge_index, T>;
template <class T>
using Scoped_edge_property = Scoped_property<Edge_index, T>;
template <class T>
using Scoped_face_property = Scoped_property<Face_index, T>;

} // namespace genmesh

#include <genmesh/detail/mesh_functions.h>

// ---------------------------------------------------------------------------
// boost::graph_traits (choices copied from CGAL's Surface_mesh traits; the
// part every genmesh mesh shares: detail::Mesh_graph_traits)
// ---------------------------------------------------------------------------

namespace boost {

template <class P>
struct graph_traits<genmesh::Halfedge_mesh<P>> : genmesh::detail::Mesh_graph_traits<P> {
  using in_edge_iterator = genmesh::In_edge_iterator;
  using out_edge_iterator = genmesh::Out_edge_iterator;
  using adjacency_iterator = genmesh::Vertex_around_target_iterator;
};

template <class P>
struct graph_traits<const genmesh::Halfedge_mesh<P>> : graph_traits<genmesh::Halfedge_mesh<P>> {};

} // namespace boost

// ---------------------------------------------------------------------------
// CGAL BGL free functions (found by ADL through Halfedge_mesh)
// ---------------------------------------------------------------------------

namespace genmesh {

namespace detail {
template <>
inline constexpr bool is_genmesh_mesh<Halfedge_mesh> = true;
} // namespace detail

// What only Halfedge_mesh has; the rest: <genmesh/detail/mesh_functions.h>.

// MutableHalfedgeGraph
template <class P>
void set_target(Halfedge_index h, Vertex_index v, Halfedge_mesh<P>& m) {
  m.set_target(h, v);
}
template <class P>
void set_next(Halfedge_index h, Halfedge_index nh, Halfedge_mesh<P>& m) {
  m.set_next(h, nh);
}
template <class P>
void set_halfedge(Vertex_index v, Halfedge_index h, Halfedge_mesh<P>& m) {
  m.set_halfedge(v, h);
}
/// A new edge; returns it as an edge (its halfedges are halfedge(e, 0/1)).
template <class P>
Edge_index add_edge(Halfedge_mesh<P>& m) {
  return m.edge(m.add_edge());
}

// MutableFaceGraph
template <class P>
void set_face(Halfedge_index h, Face_index f, Halfedge_mesh<P>& m) {
  m.set_face(h, f);
}
template <class P>
void set_halfedge(Face_index f, Halfedge_index h, Halfedge_mesh<P>& m) {
  m.set_halfedge(f, h);
}

// The claims of this header, checked where it is compiled.
static_assert(HalfedgeListGraph<Halfedge_mesh<>> && VertexListGraph<Halfedge_mesh<>> &&
              EdgeListGraph<Halfedge_mesh<>> && FaceListGraph<Halfedge_mesh<>> &&
              MutableFaceGraph<Halfedge_mesh<>>);
static_assert(HasVertexPoints<Halfedge_mesh<>> && HasIndexMap<Halfedge_mesh<>, vertex_index_t> &&
              HasIndexMap<Halfedge_mesh<>, halfedge_index_t> && HasIndexMap<Halfedge_mesh<>, edge_index_t> &&
              HasIndexMap<Halfedge_mesh<>, face_index_t>);

} // namespace genmesh

#include <genmesh/detail/halfedge_mesh_bulk.h>
