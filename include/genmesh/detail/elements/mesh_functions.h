// genmesh/detail/elements/mesh_functions.h — the CGAL BGL free functions of genmesh's
// own meshes, written once.
//
// What it is: the part of boost::graph_traits every genmesh mesh shares
// (detail::Mesh_graph_traits: Boost's bidirectional, adjacency, vertex- and
// edge-list traversal) and num_vertices, vertices, source, target, next, prev,
// opposite, edge, halfedge, face, degree, out_edges, in_edges, out_degree,
// in_degree, adjacent_vertices, add_/remove_ elements, the index and point
// property maps (genmesh's tags, and Boost's vertex_index / edge_index with
// the two- and three-argument get of Boost's PropertyGraph concept),
// index_bound, reserve and collect_garbage for every mesh class template M
// that opts in with detail::is_genmesh_mesh<M> = true (Halfedge_mesh,
// Incidence_mesh). Each forwards to M<P>'s member of the same name; what only
// one mesh has (set_next, add_edge's return value, load_soup, ...) stays
// beside that mesh. CGAL's own index tags (halfedge_index_t, face_index_t)
// need CGAL's headers: <genmesh/adaptors/cgal.h>.
//
// Guarantees: every function takes `M<P>&`, not a bare template parameter, so
// it is more specialized than CGAL's generic helpers that take any graph
// (CGAL::degree(face, g) and the like), exactly as the per-class overloads it
// replaces were; found by ADL through genmesh's index types and the mesh.
// Included by <genmesh/halfedge_mesh.h> and <genmesh/incidence_mesh.h>; not
// for direct use.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/elements.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

namespace genmesh {

namespace detail {
/// True for genmesh's own mesh class templates (specialized beside each).
template <template <class> class M>
inline constexpr bool is_genmesh_mesh = false;

/// What boost::graph_traits says of every genmesh mesh (genmesh's index
/// types and iterators, 32-bit indices in std::size_t counts, no parallel
/// edges, Boost's bidirectional and adjacency traversal as CGAL's
/// Surface_mesh); each mesh's specialization adds its in_edge_iterator,
/// out_edge_iterator and adjacency_iterator.
template <class P>
struct Mesh_graph_traits {
  struct traversal_category : public virtual boost::bidirectional_graph_tag,
                              public virtual boost::vertex_list_graph_tag,
                              public virtual boost::edge_list_graph_tag,
                              public virtual boost::adjacency_graph_tag {};

  using vertex_descriptor = Vertex_index;
  using halfedge_descriptor = Halfedge_index;
  using edge_descriptor = Edge_index;
  using face_descriptor = Face_index;
  using vertex_property_type = P;

  using directed_category = boost::undirected_tag;
  using edge_parallel_category = boost::disallow_parallel_edge_tag;

  using vertex_iterator = Vertex_iterator;
  using halfedge_iterator = Halfedge_iterator;
  using edge_iterator = Edge_iterator;
  using face_iterator = Face_iterator;

  using vertices_size_type = std::size_t;
  using halfedges_size_type = std::size_t;
  using edges_size_type = std::size_t;
  using faces_size_type = std::size_t;
  using degree_size_type = std::size_t;

  static vertex_descriptor null_vertex() { return {}; }
  static halfedge_descriptor null_halfedge() { return {}; }
  static face_descriptor null_face() { return {}; }
};
} // namespace detail

// ---- property maps (HasVertexPoints, HasIndexMap) -------------------------

template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
auto get(vertex_point_t, const M<P>& m) -> decltype(m.points()) {
  return m.points();
}
/// The points' own array (HasNativePointArray, <genmesh/property_maps.h>).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::span<const P> genmesh_native_point_array(vertex_point_t, const M<P>& m) {
  return m.point_array();
}
/// Edge and face i's descriptors (HasNativeDescriptorOfIndex,
/// <genmesh/property_maps.h>).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Edge_index genmesh_native_descriptor(edge_index_t, const M<P>&, std::size_t i) {
  return Edge_index(static_cast<Edge_index::size_type>(i));
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Face_index genmesh_native_descriptor(face_index_t, const M<P>&, std::size_t i) {
  return Face_index(static_cast<Face_index::size_type>(i));
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Vertex_index> get(vertex_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Halfedge_index> get(halfedge_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Edge_index> get(edge_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Face_index> get(face_index_t, const M<P>&) {
  return {};
}
/// The three-argument get of Boost's PropertyGraph concept: x's index.
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(vertex_index_t, const M<P>&, Vertex_index v) {
  return v.idx();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(halfedge_index_t, const M<P>&, Halfedge_index h) {
  return h.idx();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(edge_index_t, const M<P>&, Edge_index e) {
  return e.idx();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(face_index_t, const M<P>&, Face_index f) {
  return f.idx();
}

/// Boost's vertex_index and edge_index (two- and three-argument get), what
/// Boost's graph algorithms default to: raw indices, dense only when m has
/// no removed elements (size scratch by index_bound, not num_vertices).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Vertex_index> get(boost::vertex_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(boost::vertex_index_t, const M<P>&, Vertex_index v) {
  return v.idx();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Edge_index> get(boost::edge_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(boost::edge_index_t, const M<P>&, Edge_index e) {
  return e.idx();
}

template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t index_bound(vertex_index_t, const M<P>& m) {
  return m.vertices_size();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t index_bound(halfedge_index_t, const M<P>& m) {
  return m.halfedges_size();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t index_bound(edge_index_t, const M<P>& m) {
  return m.edges_size();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t index_bound(face_index_t, const M<P>& m) {
  return m.faces_size();
}

// ---- VertexListGraph, EdgeListGraph, HalfedgeListGraph, FaceListGraph -----
// num_* are live counts (genmesh's convention; see halfedge_mesh.h).

template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t num_vertices(const M<P>& m) {
  return m.n_vertices();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t num_halfedges(const M<P>& m) {
  return m.n_halfedges();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t num_edges(const M<P>& m) {
  return m.n_edges();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t num_faces(const M<P>& m) {
  return m.n_faces();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Range<Vertex_iterator> vertices(const M<P>& m) {
  return m.vertices();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Range<Halfedge_iterator> halfedges(const M<P>& m) {
  return m.halfedges();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Range<Edge_iterator> edges(const M<P>& m) {
  return m.edges();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Range<Face_iterator> faces(const M<P>& m) {
  return m.faces();
}

// ---- HalfedgeGraph ----------------------------------------------------------

template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Vertex_index source(Halfedge_index h, const M<P>& m) {
  return m.source(h);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Vertex_index target(Halfedge_index h, const M<P>& m) {
  return m.target(h);
}
/// source(halfedge(e, g), g).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Vertex_index source(Edge_index e, const M<P>& m) {
  return m.source(m.halfedge(e));
}
/// target(halfedge(e, g), g).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Vertex_index target(Edge_index e, const M<P>& m) {
  return m.target(m.halfedge(e));
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Halfedge_index next(Halfedge_index h, const M<P>& m) {
  return m.next(h);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Halfedge_index prev(Halfedge_index h, const M<P>& m) {
  return m.prev(h);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Halfedge_index opposite(Halfedge_index h, const M<P>& m) {
  return m.opposite(h);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Edge_index edge(Halfedge_index h, const M<P>& m) {
  return m.edge(h);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Halfedge_index halfedge(Edge_index e, const M<P>& m) {
  return m.halfedge(e);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Halfedge_index halfedge(Vertex_index v, const M<P>& m) {
  return m.halfedge(v);
}
/// The halfedge u -> v and whether it exists.
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::pair<Halfedge_index, bool> halfedge(Vertex_index u, Vertex_index v, const M<P>& m) {
  const Halfedge_index h = m.halfedge(u, v);
  return {h, h.is_valid()};
}
/// The edge between u and v, oriented u -> v, and whether it exists.
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::pair<Edge_index, bool> edge(Vertex_index u, Vertex_index v, const M<P>& m) {
  const Halfedge_index h = m.halfedge(u, v);
  return {Edge_index(h), h.is_valid()};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t degree(Vertex_index v, const M<P>& m) {
  return m.degree(v);
}

// ---- IncidenceGraph, BidirectionalGraph, AdjacencyGraph (Boost) ------------
// The order of the edges around v is each mesh's (see its out_edges member).

/// Edges leaving v, oriented so that source(e, m) == v.
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
auto out_edges(Vertex_index v, const M<P>& m) {
  return m.out_edges(v);
}
/// Edges entering v, oriented so that target(e, m) == v.
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
auto in_edges(Vertex_index v, const M<P>& m) {
  return m.in_edges(v);
}
/// The neighbours of v (the other ends of its edges).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
auto adjacent_vertices(Vertex_index v, const M<P>& m) {
  return m.adjacent_vertices(v);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t out_degree(Vertex_index v, const M<P>& m) {
  return m.degree(v);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t in_degree(Vertex_index v, const M<P>& m) {
  return m.degree(v);
}

// ---- FaceGraph --------------------------------------------------------------

template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Face_index face(Halfedge_index h, const M<P>& m) {
  return m.face(h);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Halfedge_index halfedge(Face_index f, const M<P>& m) {
  return m.halfedge(f);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t degree(Face_index f, const M<P>& m) {
  return m.degree(f);
}

// ---- adding and removing elements ------------------------------------------

template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Vertex_index add_vertex(M<P>& m) {
  return m.add_vertex();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Vertex_index add_vertex(const std::type_identity_t<P>& p, M<P>& m) {
  return m.add_vertex(p);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
void remove_vertex(Vertex_index v, M<P>& m) {
  m.remove_vertex(v);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
void remove_edge(Edge_index e, M<P>& m) {
  m.remove_edge(e);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Face_index add_face(M<P>& m) {
  return m.add_face();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
void remove_face(Face_index f, M<P>& m) {
  m.remove_face(f);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
void reserve(M<P>& m, std::size_t nv, std::size_t ne, std::size_t nf) {
  m.reserve(nv, ne, nf);
}
/// genmesh::renumber's native path (<genmesh/renumbering.h>): maps old ->
/// new index, the live elements onto [0, live count).
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
void genmesh_native_renumber(M<P>& m, std::span<const std::uint32_t> vmap, std::span<const std::uint32_t> emap,
                             std::span<const std::uint32_t> fmap) {
  m.renumber(vmap, emap, fmap);
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Garbage_collection_maps collect_garbage(M<P>& m, Garbage_order order = Garbage_order::stable) {
  return m.collect_garbage(order);
}

} // namespace genmesh

// Boost's property_map for its own index tags (the type the two-argument get
// above returns), on every genmesh mesh.
namespace boost {
template <template <class> class M, class P>
  requires genmesh::detail::is_genmesh_mesh<M>
struct property_map<M<P>, boost::vertex_index_t> {
  using type = genmesh::Index_map<genmesh::Vertex_index>;
  using const_type = type;
};
template <template <class> class M, class P>
  requires genmesh::detail::is_genmesh_mesh<M>
struct property_map<M<P>, boost::edge_index_t> {
  using type = genmesh::Index_map<genmesh::Edge_index>;
  using const_type = type;
};
} // namespace boost
