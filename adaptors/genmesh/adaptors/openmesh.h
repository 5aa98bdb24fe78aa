// genmesh/adaptors/openmesh.h — OpenMesh's array-kernel meshes as genmesh graphs.
//
// OpenMesh::PolyMesh_ArrayKernelT<Traits> and TriMesh_ArrayKernelT<Traits>
// get their boost::graph_traits and CGAL's free functions from CGAL's own
// OpenMesh adaptor (included here), which already translates OpenMesh's
// outgoing halfedge(v) into CGAL's incoming convention. This header adds:
//   get(genmesh::vertex_point, m)   an lvalue map to m.point(v), in OpenMesh's
//                                   own Point type (Vec3f by default; CGAL's
//                                   get(CGAL::vertex_point, m) instead converts
//                                   to EPICK::Point_3 by value)
//   get(genmesh::vertex_index, m) … the handles' idx()
//   index_bound(genmesh::vertex_index, m) … m.n_vertices() etc.
//   genmesh::Point_traits<OpenMesh::VectorT<Scalar, 3>>
//
// Limits: OpenMesh's n_vertices() (and CGAL's num_vertices(m), which returns
// it) counts deleted, not yet garbage-collected elements; it is the index
// bound, and the live count only when nothing is deleted (vertices(m) skips
// deleted elements; CGAL's removals request OpenMesh's status attributes).
// Handles are plain ints: index_bound and the index maps go stale after
// m.garbage_collection(), like every OpenMesh handle.
#pragma once

#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <CGAL/boost/graph/graph_traits_PolyMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_PolyMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>

namespace genmesh {

/// OpenMesh vectors of dimension 3 (Vec3f, Vec3d, …).
template <class Scalar>
struct Point_traits<OpenMesh::VectorT<Scalar, 3>> {
  using Point = OpenMesh::VectorT<Scalar, 3>;
  static double coord(const Point& p, int i) { return static_cast<double>(p[i]); }
  static Point make(double x, double y, double z) {
    return Point(static_cast<Scalar>(x), static_cast<Scalar>(y), static_cast<Scalar>(z));
  }
};

namespace detail {

// The vertex point map of an OpenMesh mesh: references into its point array.
template <class Mesh>
class Openmesh_point_map {
public:
  using key_type = OpenMesh::VertexHandle;
  using value_type = typename Mesh::Point;
  using reference = value_type&;
  using category = boost::lvalue_property_map_tag;

  Openmesh_point_map() = default;
  explicit Openmesh_point_map(const Mesh& m) : mesh_(const_cast<Mesh*>(&m)) {}

  reference operator[](key_type v) const { return mesh_->point(v); }
  friend reference get(const Openmesh_point_map& m, key_type v) { return m.mesh_->point(v); }
  friend void put(const Openmesh_point_map& m, key_type v, const value_type& p) {
    m.mesh_->set_point(v, p);
  }

private:
  Mesh* mesh_ = nullptr;
};

template <class Key>
struct Openmesh_index_map {
  using key_type = Key;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;
  friend std::size_t get(Openmesh_index_map, const Key& k) {
    return static_cast<std::size_t>(k.idx());
  }
};

} // namespace detail

template <class K>
auto get(vertex_point_t, const OpenMesh::PolyMesh_ArrayKernelT<K>& m) {
  return detail::Openmesh_point_map<OpenMesh::PolyMesh_ArrayKernelT<K>>(m);
}
template <class K>
auto get(vertex_point_t, const OpenMesh::TriMesh_ArrayKernelT<K>& m) {
  return detail::Openmesh_point_map<OpenMesh::TriMesh_ArrayKernelT<K>>(m);
}

#define GENMESH_OPENMESH_INDEX(MESH, TAG, DESCRIPTOR, BOUND)                             \
  template <class K>                                                                      \
  auto get(TAG, const MESH<K>&) {                                                         \
    return detail::Openmesh_index_map<                                                    \
        typename boost::graph_traits<MESH<K>>::DESCRIPTOR>{};                             \
  }                                                                                       \
  template <class K>                                                                      \
  std::size_t index_bound(TAG, const MESH<K>& m) {                                        \
    return m.BOUND();                                                                     \
  }
#define GENMESH_OPENMESH_INDICES(MESH)                                                    \
  GENMESH_OPENMESH_INDEX(MESH, vertex_index_t, vertex_descriptor, n_vertices)             \
  GENMESH_OPENMESH_INDEX(MESH, halfedge_index_t, halfedge_descriptor, n_halfedges)        \
  GENMESH_OPENMESH_INDEX(MESH, edge_index_t, edge_descriptor, n_edges)                    \
  GENMESH_OPENMESH_INDEX(MESH, face_index_t, face_descriptor, n_faces)
GENMESH_OPENMESH_INDICES(OpenMesh::PolyMesh_ArrayKernelT)
GENMESH_OPENMESH_INDICES(OpenMesh::TriMesh_ArrayKernelT)
#undef GENMESH_OPENMESH_INDICES
#undef GENMESH_OPENMESH_INDEX

/// Face i's handle (HasNativeDescriptorOfIndex, <genmesh/property_maps.h>):
/// OpenMesh's handles are their indices. (Edges are not: CGAL's adaptor
/// wraps a halfedge handle in its edge descriptor.)
template <class K>
OpenMesh::FaceHandle genmesh_native_descriptor(face_index_t, const OpenMesh::PolyMesh_ArrayKernelT<K>&, std::size_t i) {
  return OpenMesh::FaceHandle(static_cast<int>(i));
}
template <class K>
OpenMesh::FaceHandle genmesh_native_descriptor(face_index_t, const OpenMesh::TriMesh_ArrayKernelT<K>&, std::size_t i) {
  return OpenMesh::FaceHandle(static_cast<int>(i));
}

} // namespace genmesh
