// genmesh/properties.h — scratch properties on every backend.
//
// An algorithm that needs per-element data for its own duration (marks,
// costs, a crease map it builds) asks for a scratch property:
//
//   auto cost = genmesh::scratch_property<double>(genmesh::edge_index, g, 0.0);
//   cost[e] = 1.5;  put(cost, e, 2.0);  double c = get(cost, e);
//
// indexed by the descriptors of the tag's element kind (vertex_index →
// vertex_descriptor, halfedge_index, edge_index, face_index). The result is
// a boost LvaluePropertyMap (operator[] and get return T&), cheap to copy:
// every copy shares one storage, released with the last copy.
//
// Guarantees:
// - Works on every graph with get(tag, g) and index_bound(tag, g)
//   (HasIndexMap, <genmesh/property_maps.h>): genmesh's meshes,
//   CGAL::Surface_mesh, Polyhedron_3 with ids, OpenMesh.
// - Keeps working while the algorithm adds elements: a descriptor whose
//   index is at or above the current size gets room (the generic storage
//   grows on access to index_bound(tag, g); new slots hold init). It needs
//   an index map under which an element keeps its index while others are
//   added (every backend's does); an index at or above index_bound throws
//   genmesh::invalid_input rather than allocating without bound.
// - The native hook: a backend whose own property system grows with the mesh
//   (no check per access) provides
//     genmesh_native_scratch_property(tag, g, init)   // g non-const, found by ADL
//   returning such a map with the same contract (every element, present and
//   future, reads init until written). genmesh's meshes do (an anonymous
//   typed property, genmesh::Shared_property: one indexed load per access),
//   and so does CGAL::Surface_mesh (<genmesh/adaptors/cgal.h>: an anonymous
//   Surface_mesh property). On a const graph the generic storage is used.
//
// Limits: the generic storage is indexed by the index map, not attached to
// the mesh: after collect_garbage() its values no longer follow their
// elements (native ones do); write scratch data after the last
// collect_garbage of the algorithm. The graph must outlive every copy.
#pragma once

#include <genmesh/detail/properties/property_array.h>
#include <genmesh/exceptions.h>
#include <genmesh/property_maps.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

template <class G, class Tag>
  requires HasIndexMap<G, Tag>
using index_map_t = decltype(get(Tag{}, std::declval<const G&>()));

/// The descriptor type a tag's index map takes (vertex_descriptor for vertex_index, ...).
template <class G, class Tag>
using index_key_t = typename boost::property_traits<index_map_t<G, Tag>>::key_type;

namespace detail {

// The generic storage: one vector indexed through g's index map.
template <class T, class Tag, class G>
struct Scratch_storage {
  using Stored = typename Property_storage<T>::type;
  const G* graph;
  index_map_t<G, Tag> index;
  T init;
  std::vector<Stored> data;

  Scratch_storage(const G& g, T x)
      : graph(&g), index(get(Tag{}, g)), init(std::move(x)), data(index_bound(Tag{}, g), Stored(init)) {}

  // The slow path of operator[]: k's index is beyond the storage. Takes the
  // index map again (an adaptor may number new elements on demand), then
  // grows to the graph's index bound (std::vector's growth is geometric, so
  // adding elements one by one costs amortized O(1)).
  [[gnu::noinline]] std::size_t make_room(const index_key_t<G, Tag>& k) {
    index = get(Tag{}, *graph);
    const auto i = static_cast<std::size_t>(get(index, k));
    const auto bound = static_cast<std::size_t>(index_bound(Tag{}, *graph));
    if (i >= bound)
      throw invalid_input("scratch_property: element index " + std::to_string(i) + " is not below index_bound " +
                          std::to_string(bound) + " (a stale index map?)");
    if (i >= data.size()) data.resize(bound, Stored(init));
    return i;
  }
};

} // namespace detail

/// The generic scratch property: a vector indexed through g's index map for
/// Tag that grows on access. See the top of this header.
template <class T, class Tag, class G>
class Scratch_property : public boost::put_get_helper<T&, Scratch_property<T, Tag, G>> {
public:
  using key_type = index_key_t<G, Tag>;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;

  Scratch_property() = default;
  Scratch_property(const G& g, T init)
      : storage_(std::make_shared<detail::Scratch_storage<T, Tag, G>>(g, std::move(init))) {}

  T& operator[](key_type k) const {
    auto i = static_cast<std::size_t>(get(storage_->index, k));
    if (i >= storage_->data.size()) [[unlikely]]
      i = storage_->make_room(k);
    return detail::Property_storage<T>::ref(storage_->data[i]);
  }

private:
  std::shared_ptr<detail::Scratch_storage<T, Tag, G>> storage_;
};

/// A backend that provides its own scratch property (see the top of this header).
template <class G, class Tag, class T>
concept HasNativeScratchProperty = requires(G& g, const T& init) {
  genmesh_native_scratch_property(Tag{}, g, init);
};

/// A scratch property of T for Tag's elements of g (vertex_index,
/// halfedge_index, edge_index or face_index), every element reading init
/// until written, new elements included. See the top of this header.
template <class T, class Tag, class G>
  requires HasIndexMap<std::remove_const_t<G>, Tag>
auto scratch_property(Tag, G& g, const T& init = T{}) {
  if constexpr (HasNativeScratchProperty<G, Tag, T>)
    return genmesh_native_scratch_property(Tag{}, g, init);
  else
    return Scratch_property<T, Tag, std::remove_const_t<G>>(g, init);
}

} // namespace genmesh
