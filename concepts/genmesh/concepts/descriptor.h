// genmesh/concepts/descriptor.h — what every descriptor of a genmesh graph is.
//
// Conventions pinned for every graph concept in this folder (written once):
// - Descriptors are regular (default-constructible, copyable, equality
//   comparable), ordered by operator< (a strict total order, as std::map and
//   std::sort need; CGAL's Polyhedron_3 and OpenMesh handles provide only <)
//   and hashable with std::hash, so they can key std::map,
//   std::unordered_map and sorted vectors alike.
// - halfedge(v, g) is a halfedge whose *target* is v (CGAL's convention;
//   OpenMesh and pmp store outgoing halfedges and their CGAL adaptors
//   translate).
// - null_halfedge(), null_face(), null_vertex() come from
//   boost::graph_traits<G>; a border halfedge has face(h, g) == null_face().
// - Live count and index bound are two functions. Scratch arrays are sized by
//   index_bound(genmesh::vertex_index, g) and indexed through
//   get(genmesh::vertex_index, g) (<genmesh/property_maps.h>); never infer one
//   from the other (a mesh with removed, not yet collected elements has
//   indices >= its live count). num_vertices(g) (and num_edges, num_halfedges,
//   num_faces) count live elements on genmesh's meshes, but CGAL's
//   Surface_mesh and OpenMesh return their index bound there (CGAL's BGL only
//   promises an upper bound), so generic genmesh code uses num_* for neither:
//   it counts by iterating vertices(g) when it needs the live count.
#pragma once

#include <concepts>
#include <cstddef>
#include <functional>

namespace genmesh {

/// A vertex, halfedge, edge or face descriptor.
template <class D>
concept Descriptor = std::regular<D> && requires(const D& a, const D& b) {
  { a < b } -> std::convertible_to<bool>;
  { std::hash<D>{}(a) } -> std::convertible_to<std::size_t>;
};

} // namespace genmesh
