// genmesh/detail/halfedge/bulk.h — bulk growth of a Halfedge_mesh: many
// new elements at once, for the in-place subdivision refinement.
//
// genmesh_native_append_elements(m, nv, ne, nf) is the Halfedge_mesh override
// (found by ADL) of the generic appender in
// <genmesh/subdivision/detail/in_place.h>: it adds nv isolated vertices, ne
// edges with null connectivity and nf faces without a halfedge at the end of
// the index ranges with one resize per array (instead of one push_back per
// element and property), and names the k-th new element by arithmetic.
// Guarantees: the result is the one of nv add_vertex(), ne add_edge() and
// nf add_face() calls on a mesh without removed elements (new properties
// get their defaults). Limits: when removed elements wait for recycling,
// add_* would reuse them; then it does exactly that, one element at a time,
// and keeps their descriptors in tables.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace genmesh {

template <class P>
class Halfedge_mesh;

namespace detail {

/// The elements added by one genmesh_native_append_elements call.
struct Halfedge_mesh_appended {
  std::uint32_t first_vertex = 0, first_edge = 0, first_face = 0;
  std::vector<Vertex_index> vs;  ///< only when recycled slots were used
  std::vector<Edge_index> es;
  std::vector<Face_index> fs;

  Vertex_index vertex(std::size_t k) const {
    return vs.empty() ? Vertex_index(static_cast<std::uint32_t>(first_vertex + k)) : vs[k];
  }
  /// Halfedge i (0 or 1) of the k-th new edge; the two are opposite.
  Halfedge_index halfedge(std::size_t k, unsigned i) const {
    const std::uint32_t e = es.empty() ? static_cast<std::uint32_t>(first_edge + k) : es[k].idx();
    return Halfedge_index(2 * e + i);
  }
  Face_index face(std::size_t k) const {
    return fs.empty() ? Face_index(static_cast<std::uint32_t>(first_face + k)) : fs[k];
  }
};

/// Access to Halfedge_connectivity's arrays for the bulk operations (a friend).
struct Halfedge_mesh_bulk {
  static void append(Halfedge_connectivity& m, std::size_t nv, std::size_t ne, std::size_t nf) {
    const std::size_t v = m.vhalfedge_.size() + nv, h = m.hlinks_.size() + 2 * ne, f = m.fhalfedge_.size() + nf;
    m.check_room(v);
    m.check_room(h);
    m.check_room(f);
    m.vhalfedge_.resize(v);
    m.vremoved_.resize(v, false);
    m.vprops_.resize(v);
    m.hlinks_.resize(h);
    m.hprops_.resize(h);
    m.eremoved_.resize(h / 2, false);
    m.eprops_.resize(h / 2);
    m.fhalfedge_.resize(f);
    m.fremoved_.resize(f, false);
    m.fprops_.resize(f);
  }
};

} // namespace detail

template <class P>
detail::Halfedge_mesh_appended genmesh_native_append_elements(Halfedge_mesh<P>& m, std::size_t nv, std::size_t ne,
                                                      std::size_t nf) {
  detail::Halfedge_mesh_appended a;
  a.first_vertex = static_cast<std::uint32_t>(m.vertices_size());
  a.first_edge = static_cast<std::uint32_t>(m.edges_size());
  a.first_face = static_cast<std::uint32_t>(m.faces_size());
  const bool recycled = m.does_recycle_garbage() && (m.number_of_removed_vertices() != 0 ||
                                                     m.number_of_removed_edges() != 0 ||
                                                     m.number_of_removed_faces() != 0);
  if (!recycled) {
    detail::Halfedge_mesh_bulk::append(m, nv, ne, nf);
    return a;
  }
  a.vs.reserve(nv);
  a.es.reserve(ne);
  a.fs.reserve(nf);
  for (std::size_t k = 0; k < nv; ++k) a.vs.push_back(m.add_vertex());
  for (std::size_t k = 0; k < ne; ++k) a.es.push_back(m.edge(m.add_edge()));
  for (std::size_t k = 0; k < nf; ++k) a.fs.push_back(m.add_face());
  return a;
}

} // namespace genmesh
