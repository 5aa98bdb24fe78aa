// genmesh/mesh_properties.h — typed dynamic properties of genmesh's own meshes.
//
// Halfedge_mesh and Incidence_mesh both derive from Mesh_properties: one
// Property_container (detail/properties/property_array.h) per element kind, with the
// same API on both meshes:
//
//   auto w = mesh.add_property<Edge_index, double>("e:weight", 1.0);  // or add_edge_property<double>
//   w[e] = 2.0;                                   // a boost lvalue property map
//   auto again = mesh.get_edge_property<double>("e:weight");  // std::optional
//   mesh.remove_property(w);
//   genmesh::Scoped_vertex_property<int> mark(mesh, 0);       // anonymous, removed at scope end
//   genmesh::Shared_property<Face_index, int> m(mesh, -1);    // copyable; removed with its last copy
//
// Guarantees: a property has one value per element index, live or removed;
// it follows the mesh's elements — an added element gets the default value
// (a recycled one too), collect_garbage() moves values with their elements,
// copies of the mesh copy every property. Access is one indexed load (no
// check, no lookup). Limits: a handle belongs to the mesh it came from and is
// valid while that mesh lives (not moved from) and the property is not
// removed; after a copy, look the property up by name in the copy.
#pragma once

#include <genmesh/detail/properties/property_array.h>
#include <genmesh/elements.h>
#include <genmesh/exceptions.h>
#include <genmesh/property_maps.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

template <class Key, class T>
class Scoped_property;

/// The four property containers of a mesh whose element descriptors are
/// V, H, E, F (index types with .idx()), and the property API on them.
/// Not used on its own: a mesh derives from it and calls the containers'
/// push_back / reset / resize / compact as it adds, recycles and collects
/// elements.
template <class V, class H, class E, class F>
class Mesh_properties {
public:
  template <class T>
  using Vertex_property = detail::Property_map<V, T>;
  template <class T>
  using Halfedge_property = detail::Property_map<H, T>;
  template <class T>
  using Edge_property = detail::Property_map<E, T>;
  template <class T>
  using Face_property = detail::Property_map<F, T>;

  /// Adds a property of element Key (V, H, E or F) and value T, every
  /// element set to default_value. An empty name makes it anonymous. Throws
  /// invalid_input if the name is taken.
  template <class Key, class T>
  detail::Property_map<Key, T> add_property(std::string name, T default_value = T()) {
    auto m = container<Key>().add(name, std::move(default_value));
    if (!m) throw invalid_input("property \"" + name + "\" already exists");
    return m;
  }
  /// The property of that name and type, if any.
  template <class Key, class T>
  [[nodiscard]] std::optional<detail::Property_map<Key, T>> get_property(std::string_view name) const {
    return container<Key>().template get<T>(name);
  }
  /// The property of that name and type, added with default_value if missing.
  /// Throws invalid_input if the name is taken by another value type.
  template <class Key, class T>
  detail::Property_map<Key, T> property(std::string name, T default_value = T()) {
    if (auto m = get_property<Key, T>(name)) return *m;
    return add_property<Key, T>(std::move(name), std::move(default_value));
  }
  template <class Key>
  [[nodiscard]] bool has_property(std::string_view name) const {
    return container<Key>().exists(name);
  }
  /// Removes the property and nulls the handle; false if it was not here.
  /// A mesh's positions ("v:point") are never removed.
  template <class Key, class T>
  bool remove_property(detail::Property_map<Key, T>& m) {
    if (!m) return false;
    if constexpr (std::is_same_v<Key, V>)
      if (m.name() == "v:point") return false;
    return container<Key>().remove(m);
  }
  template <class Key>
  [[nodiscard]] std::vector<std::string> property_names() const {
    return container<Key>().names();
  }

  // pmp-style spellings.
  template <class T>
  Vertex_property<T> add_vertex_property(std::string name, T def = T()) {
    return add_property<V, T>(std::move(name), std::move(def));
  }
  template <class T>
  Halfedge_property<T> add_halfedge_property(std::string name, T def = T()) {
    return add_property<H, T>(std::move(name), std::move(def));
  }
  template <class T>
  Edge_property<T> add_edge_property(std::string name, T def = T()) {
    return add_property<E, T>(std::move(name), std::move(def));
  }
  template <class T>
  Face_property<T> add_face_property(std::string name, T def = T()) {
    return add_property<F, T>(std::move(name), std::move(def));
  }
  template <class T>
  [[nodiscard]] std::optional<Vertex_property<T>> get_vertex_property(std::string_view name) const {
    return get_property<V, T>(name);
  }
  template <class T>
  [[nodiscard]] std::optional<Halfedge_property<T>> get_halfedge_property(std::string_view name) const {
    return get_property<H, T>(name);
  }
  template <class T>
  [[nodiscard]] std::optional<Edge_property<T>> get_edge_property(std::string_view name) const {
    return get_property<E, T>(name);
  }
  template <class T>
  [[nodiscard]] std::optional<Face_property<T>> get_face_property(std::string_view name) const {
    return get_property<F, T>(name);
  }
  template <class T>
  Vertex_property<T> vertex_property(std::string name, T def = T()) {
    return property<V, T>(std::move(name), std::move(def));
  }
  template <class T>
  Halfedge_property<T> halfedge_property(std::string name, T def = T()) {
    return property<H, T>(std::move(name), std::move(def));
  }
  template <class T>
  Edge_property<T> edge_property(std::string name, T def = T()) {
    return property<E, T>(std::move(name), std::move(def));
  }
  template <class T>
  Face_property<T> face_property(std::string name, T def = T()) {
    return property<F, T>(std::move(name), std::move(def));
  }
  [[nodiscard]] bool has_vertex_property(std::string_view name) const { return has_property<V>(name); }
  [[nodiscard]] bool has_halfedge_property(std::string_view name) const { return has_property<H>(name); }
  [[nodiscard]] bool has_edge_property(std::string_view name) const { return has_property<E>(name); }
  [[nodiscard]] bool has_face_property(std::string_view name) const { return has_property<F>(name); }
  template <class T>
  bool remove_vertex_property(Vertex_property<T>& m) {
    return remove_property(m);
  }
  template <class T>
  bool remove_halfedge_property(Halfedge_property<T>& m) {
    return remove_property(m);
  }
  template <class T>
  bool remove_edge_property(Edge_property<T>& m) {
    return remove_property(m);
  }
  template <class T>
  bool remove_face_property(Face_property<T>& m) {
    return remove_property(m);
  }

protected:
  Mesh_properties() = default;

  template <class Key>
  detail::Property_container<Key>& container() {
    if constexpr (std::is_same_v<Key, V>)
      return vprops_;
    else if constexpr (std::is_same_v<Key, H>)
      return hprops_;
    else if constexpr (std::is_same_v<Key, E>)
      return eprops_;
    else {
      static_assert(std::is_same_v<Key, F>, "Key must be one of the mesh's index types");
      return fprops_;
    }
  }
  template <class Key>
  const detail::Property_container<Key>& container() const {
    return const_cast<Mesh_properties*>(this)->container<Key>();
  }

  /// Every container at once (a mesh's reserve / shrink / clear paths).
  template <class Fn>
  void for_each_container(Fn&& fn) {
    fn(vprops_);
    fn(hprops_);
    fn(eprops_);
    fn(fprops_);
  }
  [[nodiscard]] std::size_t properties_memory_bytes() const {
    return vprops_.memory_bytes() + hprops_.memory_bytes() + eprops_.memory_bytes() + fprops_.memory_bytes();
  }

  template <class, class>
  friend class Scoped_property;

  detail::Property_container<V> vprops_;
  detail::Property_container<H> hprops_;
  detail::Property_container<E> eprops_;
  detail::Property_container<F> fprops_;
};

/// An anonymous property that is removed when this object is destroyed.
/// Move-only; map() is a copyable handle to pass to algorithms (valid while
/// this object lives). Mesh is any genmesh mesh (a Mesh_properties).
template <class Key, class T>
class Scoped_property {
public:
  template <class Mesh>
    requires(!std::is_same_v<std::remove_cv_t<Mesh>, Scoped_property>)
  explicit Scoped_property(Mesh& m, T default_value = T())
      : container_(&m.template container<Key>()), map_(container_->add(std::string(), std::move(default_value))) {}
  Scoped_property(const Scoped_property&) = delete;
  Scoped_property& operator=(const Scoped_property&) = delete;
  Scoped_property(Scoped_property&& o) noexcept : container_(std::exchange(o.container_, nullptr)), map_(o.map_) {}
  Scoped_property& operator=(Scoped_property&& o) noexcept {
    if (this != &o) {
      release();
      container_ = std::exchange(o.container_, nullptr);
      map_ = o.map_;
    }
    return *this;
  }
  ~Scoped_property() { release(); }

  T& operator[](Key k) const { return map_[k]; }
  [[nodiscard]] detail::Property_map<Key, T> map() const { return map_; }

  friend T& get(const Scoped_property& s, Key k) { return s.map_[k]; }
  friend void put(const Scoped_property& s, Key k, const T& v) { s.map_[k] = v; }

private:
  void release() {
    if (container_ != nullptr) container_->remove(map_);
    container_ = nullptr;
  }
  detail::Property_container<Key>* container_;
  detail::Property_map<Key, T> map_;
};

/// An anonymous property shared by all copies of this handle and removed
/// with the last one: a copyable boost lvalue property map that owns its
/// storage (what CGAL's dynamic property maps and genmesh's scratch
/// properties are on genmesh's meshes). The mesh must outlive every copy.
template <class Key, class T>
class Shared_property : public boost::put_get_helper<T&, Shared_property<Key, T>> {
public:
  using key_type = Key;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;

  Shared_property() = default;
  // Constrained so that copying from a non-const lvalue stays a copy (CGAL
  // copies maps that way: fimap_(fimap)).
  template <class Mesh>
    requires(!std::is_same_v<std::remove_cv_t<Mesh>, Shared_property>)
  explicit Shared_property(Mesh& m, T default_value = T())
      : owner_(std::make_shared<Scoped_property<Key, T>>(m, std::move(default_value))), map_(owner_->map()) {}

  T& operator[](Key k) const { return map_[k]; }
  /// The mesh's own handle (valid while a copy of this object lives).
  [[nodiscard]] detail::Property_map<Key, T> map() const { return map_; }

private:
  std::shared_ptr<Scoped_property<Key, T>> owner_;
  detail::Property_map<Key, T> map_;
};

/// genmesh's meshes' scratch properties (genmesh::scratch_property,
/// <genmesh/properties.h>): an anonymous Shared_property, which grows,
/// recycles and compacts with the mesh at no cost per access.
template <class V, class H, class E, class F, class T>
Shared_property<V, T> genmesh_native_scratch_property(vertex_index_t, Mesh_properties<V, H, E, F>& m, const T& init) {
  return Shared_property<V, T>(m, init);
}
template <class V, class H, class E, class F, class T>
Shared_property<H, T> genmesh_native_scratch_property(halfedge_index_t, Mesh_properties<V, H, E, F>& m, const T& init) {
  return Shared_property<H, T>(m, init);
}
template <class V, class H, class E, class F, class T>
Shared_property<E, T> genmesh_native_scratch_property(edge_index_t, Mesh_properties<V, H, E, F>& m, const T& init) {
  return Shared_property<E, T>(m, init);
}
template <class V, class H, class E, class F, class T>
Shared_property<F, T> genmesh_native_scratch_property(face_index_t, Mesh_properties<V, H, E, F>& m, const T& init) {
  return Shared_property<F, T>(m, init);
}

/// Property handles: boost lvalue property maps indexed by element.
template <class T>
using Vertex_property = detail::Property_map<Vertex_index, T>;
template <class T>
using Halfedge_property = detail::Property_map<Halfedge_index, T>;
template <class T>
using Edge_property = detail::Property_map<Edge_index, T>;
template <class T>
using Face_property = detail::Property_map<Face_index, T>;

/// Anonymous RAII properties of genmesh's meshes, by element kind.
template <class T>
using Scoped_vertex_property = Scoped_property<Vertex_index, T>;
template <class T>
using Scoped_halfedge_property = Scoped_property<Halfedge_index, T>;
template <class T>
using Scoped_edge_property = Scoped_property<Edge_index, T>;
template <class T>
using Scoped_face_property = Scoped_property<Face_index, T>;

} // namespace genmesh
