// genmesh/property_maps.h — the property maps every algorithm reads through.
//
// Algorithms never name a backend's storage. They ask for
//   get(genmesh::vertex_point, g)   a read/write boost property map vertex → point
//   get(genmesh::vertex_index, g)   vertex → std::size_t in [0, index_bound(vertex_index, g))
//   (and halfedge_index, edge_index, face_index alike)
// found by argument-dependent lookup through the tag, which lives in namespace
// genmesh. A backend supplies these overloads next to its graph traits:
// <genmesh/halfedge_mesh.h> for the own mesh, <genmesh/adaptors/cgal.h> and
// <genmesh/adaptors/openmesh.h> for the others.
//
// index_bound(tag, g) is the size a scratch array indexed by that index map
// needs (it counts removed, not yet collected elements too); it is *not* the
// live count num_vertices(g) (see concepts/genmesh/concepts/descriptor.h).
//
// Every backend's index maps keep a live element's index unchanged across
// edits, so algorithms may keep index-keyed tables while they edit (simplify,
// isotropic_remeshing): removed elements leave holes (or have their index
// recycled by a later new element), and new elements take an index no live
// element holds. (CGAL::Polyhedron_3 too: its adaptor keeps valid item ids and
// numbers only new items, see <genmesh/adaptors/cgal.h>.)
#pragma once

#include <genmesh/detail/prefetch.h>
#include <genmesh/point_traits.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <concepts>
#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

struct vertex_point_t {};
inline constexpr vertex_point_t vertex_point{};

struct vertex_index_t {};
inline constexpr vertex_index_t vertex_index{};
struct halfedge_index_t {};
inline constexpr halfedge_index_t halfedge_index{};
struct edge_index_t {};
inline constexpr edge_index_t edge_index{};
struct face_index_t {};
inline constexpr face_index_t face_index{};

/// The type of g's vertex point map.
template <class G>
using vertex_point_map_t = decltype(get(vertex_point, std::declval<G&>()));

/// The point type stored in g.
template <class G>
using point_t = typename boost::property_traits<vertex_point_map_t<G>>::value_type;

/// A graph whose vertex positions genmesh can read and write.
template <class G>
concept HasVertexPoints = requires(G& g) {
  get(vertex_point, g);
} && Point3<point_t<G>>;

/// A graph whose points lie in one array indexed by vertex index, which it
/// hands out through the native hook
///   genmesh_native_point_array(vertex_point, g)   // const g, found by ADL
/// returning std::span<const point_t<G>> of index_bound(vertex_index, g)
/// points (removed vertices' slots included), valid until a vertex is added
/// or the garbage is collected; writes still go through the point map.
/// genmesh's meshes and CGAL::Surface_mesh (<genmesh/adaptors/cgal.h>) do.
template <class G>
concept HasNativePointArray = HasVertexPoints<G> && requires(const G& g) {
  { genmesh_native_point_array(vertex_point, g) } -> std::same_as<std::span<const point_t<G>>>;
};

/// A graph with integer indices for Tag's elements (unique, below the bound, not
/// necessarily dense), and their bound.
template <class G, class Tag>
concept HasIndexMap = requires(const G& g) {
  get(Tag{}, g);
  { index_bound(Tag{}, g) } -> std::convertible_to<std::size_t>;
};

/// The descriptor type whose indices Tag names (the tags the hook below
/// serves): edge_index_t → the edge_descriptor, face_index_t → the
/// face_descriptor.
template <class G, class Tag>
struct descriptor_of_index;
template <class G>
struct descriptor_of_index<G, edge_index_t> {
  using type = typename boost::graph_traits<G>::edge_descriptor;
};
template <class G>
struct descriptor_of_index<G, face_index_t> {
  using type = typename boost::graph_traits<G>::face_descriptor;
};
template <class G, class Tag>
using descriptor_of_index_t = typename descriptor_of_index<G, Tag>::type;

/// A graph whose Tag descriptors (Tag: edge_index_t or face_index_t) are
/// made from their indices, through the native hook
///   genmesh_native_descriptor(tag, g, i)   // const g, found by ADL
/// returning the descriptor of index i (a live element's index, below
/// index_bound(tag, g)): the one edges(g) / faces(g) yields for it.
/// An algorithm that keeps elements by index then needs no array of
/// descriptors (4 bytes or more an element). genmesh's meshes and
/// CGAL::Surface_mesh (<genmesh/adaptors/cgal.h>) do for edges and faces,
/// OpenMesh's (<genmesh/adaptors/openmesh.h>) for faces.
template <class G, class Tag>
concept HasNativeDescriptorOfIndex = HasIndexMap<G, Tag> && requires(const G& g, std::size_t i) {
  { genmesh_native_descriptor(Tag{}, g, i) } -> std::same_as<descriptor_of_index_t<G, Tag>>;
};

/// A graph that can hint a halfedge's links into the cache ahead of a walk,
/// through the native hook
///   genmesh_native_prefetch_links(h, g)   // const g, found by ADL
/// (and genmesh_native_prefetch_links(v, g) for halfedge(v)): a prefetch of
/// next(h), target(h), face(h) and opposite(h)'s, with no other effect; h
/// may be any halfedge below the index bound, removed or not. An algorithm
/// that knows which star it will walk next (simplify's queue) asks for it
/// while it still works on the current one. Halfedge_mesh does.
template <class G>
concept HasNativePrefetch = requires(const G& g, typename boost::graph_traits<G>::halfedge_descriptor h,
                                     typename boost::graph_traits<G>::vertex_descriptor v) {
  genmesh_native_prefetch_links(h, g);
  genmesh_native_prefetch_links(v, g);
};

namespace detail {

/// Hints x's links into the cache (a halfedge's, or a vertex's halfedge)
/// where g can (HasNativePrefetch); nothing otherwise.
template <class G, class X>
void prefetch_links([[maybe_unused]] X x, [[maybe_unused]] const G& g) {
  if constexpr (HasNativePrefetch<G>) genmesh_native_prefetch_links(x, g);
}

/// g's points by vertex index as Eigen::Vector3d, for algorithms that read
/// them in inner loops: the mesh's own array when it has one
/// (HasNativePointArray; no copy, a reference when the points are
/// Eigen::Vector3d), else a copy in double made at construction, which
/// set() keeps current (the caller writes the mesh through its point map
/// as well). Valid while no vertex is added; reads of live vertices only.
template <class G>
class Point_reader {
public:
  static constexpr bool native = HasNativePointArray<G>;

  Point_reader() = default;
  explicit Point_reader(const G& g, std::size_t bound) {
    if constexpr (native) {
      points_ = genmesh_native_point_array(vertex_point, g);
    } else {
      using P = point_t<G>;
      copy_.assign(bound, Eigen::Vector3d::Zero());
      auto pm = get(vertex_point, g);
      auto index = get(vertex_index, g);
      for (const auto v : vertices(g)) copy_[static_cast<std::size_t>(get(index, v))] = to_eigen(P(get(pm, v)));
    }
  }

  decltype(auto) operator[](std::size_t i) const {
    if constexpr (!native) return static_cast<const Eigen::Vector3d&>(copy_[i]);
    else if constexpr (std::is_same_v<point_t<G>, Eigen::Vector3d>) return static_cast<const Eigen::Vector3d&>(points_[i]);
    else return to_eigen(points_[i]);
  }
  /// Where point i lies (for prefetching).
  const void* address(std::size_t i) const {
    if constexpr (native) return &points_[i];
    else return &copy_[i];
  }
  /// Hints that point i will be read soon (every cache line it lies on).
  void prefetch(std::size_t i) const {
    if constexpr (native) detail::prefetch_object(&points_[i]);
    else detail::prefetch_object(&copy_[i]);
  }
  /// After the mesh's point i became p.
  void set(std::size_t i, const Eigen::Vector3d& p) {
    if constexpr (!native) copy_[i] = p;
    else (void)i, (void)p;
  }
  std::size_t size() const {
    if constexpr (native) return points_.size();
    else return copy_.size();
  }

private:
  std::span<const point_t<G>> points_;
  std::vector<Eigen::Vector3d> copy_; // empty when native
};

} // namespace detail

/// While alive, new elements of g get fresh indices (appended) instead of
/// reusing the indices of removed ones, on every mesh that recycles
/// (Halfedge_mesh, Incidence_mesh, Surface_mesh: set_recycle_garbage);
/// restores the mesh's setting when it dies. Meshes that never recycle
/// (OpenMesh, Polyhedron_3's adaptor) need nothing. An algorithm that both
/// removes and adds elements and orders its work by index (remeshing) holds
/// one, so that the numbering of what it creates, and therefore its result,
/// is the same on every backend.
template <class G>
class Append_only_indices {
public:
  explicit Append_only_indices(G& g) : g_(g) {
    if constexpr (recycles) {
      was_ = g_.does_recycle_garbage();
      g_.set_recycle_garbage(false);
    }
  }
  ~Append_only_indices() {
    if constexpr (recycles) g_.set_recycle_garbage(was_);
  }
  Append_only_indices(const Append_only_indices&) = delete;
  Append_only_indices& operator=(const Append_only_indices&) = delete;

private:
  static constexpr bool recycles = requires(G& g) {
    { g.does_recycle_garbage() } -> std::convertible_to<bool>;
    g.set_recycle_garbage(false);
  };
  G& g_;
  bool was_ = false;
};

} // namespace genmesh
