// genmesh/adaptors/cgal.h — CGAL's meshes as genmesh graphs, and genmesh's
// meshes as CGAL graphs.
//
// Direction 1, CGAL → genmesh. CGAL::Surface_mesh<P> and CGAL::Polyhedron_3<K>
// already model CGAL's BGL concepts (their boost::graph_traits and free
// functions live in CGAL's headers, included here), hence genmesh's concepts.
// This header adds what genmesh reads through its own tags:
//   get(genmesh::vertex_point, g)              CGAL's own vertex point map
//   get(genmesh::vertex_index, g) (halfedge_, edge_, face_index alike)
//   index_bound(genmesh::vertex_index, g) …    the size of scratch arrays
// and genmesh::Point_traits<CGAL::Point_3<K>> (any kernel; coordinates are read
// through CGAL::to_double).
//
// Limits (read these before writing an algorithm):
// - CGAL's num_vertices(sm) for a Surface_mesh (and num_halfedges, num_edges,
//   num_faces) returns the *index bound*, removed elements included, as CGAL's
//   BGL documents; sm.number_of_vertices() is the live count. It equals the
//   live count only when sm has no removed elements (after collect_garbage()).
//   Iterate vertices(g) for live elements; size scratch by index_bound.
// - Polyhedron_3 has index maps only when its items carry ids
//   (CGAL::Polyhedron_items_with_id_3). get(genmesh::vertex_index, p) then
//   makes sure the ids are a valid numbering, renumbering them in iteration
//   order if not (writing to the ids of a const polyhedron, as CGAL's own
//   get_initialized_*_index_map does). The check is O(size) once after each
//   edit and O(1) after that (a per-thread stamp of sizes and last elements,
//   see detail::ensure_polyhedron_ids), so asking for the map per element
//   costs nothing; maps obtained before a later edit go stale. Code that
//   writes ids by hand behind genmesh's back between two calls, keeping
//   sizes and last elements, must renumber them validly itself. A Polyhedron_3 without ids has points but no index maps:
//   HasIndexMap is false and genmesh code must fall back to hashing
//   descriptors.
//
// Direction 2, genmesh → CGAL. genmesh::Halfedge_mesh<P> brings its own
// boost::graph_traits and CGAL's free functions (<genmesh/halfedge_mesh.h>);
// this header adds the property side CGAL's algorithms look for:
//   boost::property_map<Halfedge_mesh<P>, CGAL::vertex_point_t> and
//   get(CGAL::vertex_point, m) (also get/put(vertex_point, m, v[, p]));
//   boost::edge_weight (edge lengths, for CGAL points);
//   CGAL::halfedge_index_t and CGAL::face_index_t maps (the raw idx(), with
//   the three-argument get; also on Incidence_mesh; boost::vertex_index_t
//   and boost::edge_index_t come with the mesh headers);
//   CGAL::dynamic_{vertex,halfedge,edge,face}_property_t<T> maps, backed by
//   the mesh's own anonymous typed properties (vector speed; removed when the
//   last copy of the map goes), or for a const mesh a vector sized by the
//   index bound.
// Limits:
// - CGAL's algorithms compute with CGAL::Kernel_traits<P>, so they accept
//   Halfedge_mesh<K::Point_3> (any CGAL kernel K). Halfedge_mesh<Eigen::Vector3d>
//   (the default) models the graph concepts but not CGAL's geometric
//   requirements: CGAL::graph_has_property<…, vertex_point_t> holds only for
//   Halfedge_mesh<CGAL::Point_3<K>>. Use that with CGAL, or pass CGAL a
//   vertex_point_map (to K::Point_3) and geom_traits explicitly; purely
//   combinatorial CGAL code (is_valid_polygon_mesh, Euler operations without
//   points) works on any Halfedge_mesh.
// - Halfedge_mesh's num_vertices(m) is the *live* count (genmesh's
//   convention), while CGAL's algorithms size arrays by num_vertices(g) and
//   index them through the index map. The raw idx() is a valid CGAL index map
//   only when m has no removed elements, so CGAL::graph_has_property is left
//   false for the four index tags: CGAL then builds its own dense index map
//   (one pass, a dynamic property) whenever it needs one, which is correct
//   with or without garbage. get(boost::vertex_index, m) stays available for
//   code that asks for it by name; it is dense only without garbage.
#pragma once

#include <genmesh/halfedge_mesh.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Point_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Surface_mesh.h>
#include <CGAL/boost/graph/internal/Has_member_id.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Surface_mesh.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <cstddef>
#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

// ---- points ---------------------------------------------------------------

/// CGAL points of any kernel; coordinates are read through CGAL::to_double
/// (for exact kernels that rounds to the nearest double).
template <class K>
struct Point_traits<CGAL::Point_3<K>> {
  using Point = CGAL::Point_3<K>;
  static double coord(const Point& p, int i) { return CGAL::to_double(p[i]); }
  static Point make(double x, double y, double z) { return Point(x, y, z); }
};

// ---- CGAL::Surface_mesh ----------------------------------------------------

/// The mesh's "v:point" map (an lvalue map, as CGAL's get(CGAL::vertex_point, sm)).
template <class P>
auto get(vertex_point_t, const CGAL::Surface_mesh<P>& sm) {
  return sm.points();
}

/// Surface_mesh indices are the descriptors' idx(): removed, not yet
/// collected elements keep theirs, so the bound is the member num_vertices()
/// (used + removed), not number_of_vertices().
template <class P>
auto get(vertex_index_t, const CGAL::Surface_mesh<P>& sm) {
  return get(boost::vertex_index, sm);
}
template <class P>
auto get(halfedge_index_t, const CGAL::Surface_mesh<P>& sm) {
  return get(boost::halfedge_index, sm);
}
template <class P>
auto get(edge_index_t, const CGAL::Surface_mesh<P>& sm) {
  return get(boost::edge_index, sm);
}
template <class P>
auto get(face_index_t, const CGAL::Surface_mesh<P>& sm) {
  return get(boost::face_index, sm);
}

template <class P>
std::size_t index_bound(vertex_index_t, const CGAL::Surface_mesh<P>& sm) {
  return sm.num_vertices();
}
template <class P>
std::size_t index_bound(halfedge_index_t, const CGAL::Surface_mesh<P>& sm) {
  return sm.num_halfedges();
}
template <class P>
std::size_t index_bound(edge_index_t, const CGAL::Surface_mesh<P>& sm) {
  return sm.num_edges();
}
template <class P>
std::size_t index_bound(face_index_t, const CGAL::Surface_mesh<P>& sm) {
  return sm.num_faces();
}

/// A scratch property of a Surface_mesh (genmesh::scratch_property,
/// <genmesh/properties.h>): an anonymous Surface_mesh property, which grows
/// and compacts with the mesh, removed with the last copy of this map. bool
/// is stored one per byte (detail::Bool_box) so that operator[] is a bool&.
template <class P, class Key, class T>
class Surface_mesh_scratch_property
    : public boost::put_get_helper<T&, Surface_mesh_scratch_property<P, Key, T>> {
  using Stored = typename detail::Property_storage<T>::type;
  using Map = typename CGAL::Surface_mesh<P>::template Property_map<Key, Stored>;
  struct Owner {
    CGAL::Surface_mesh<P>* mesh;
    Map map;
    Owner(CGAL::Surface_mesh<P>* m, Map p) : mesh(m), map(p) {}
    Owner(const Owner&) = delete;
    Owner& operator=(const Owner&) = delete;
    ~Owner() { mesh->remove_property_map(map); }
  };

public:
  using key_type = Key;
  using value_type = T;
  using reference = T&;
  using category = boost::lvalue_property_map_tag;

  Surface_mesh_scratch_property() = default;
  Surface_mesh_scratch_property(CGAL::Surface_mesh<P>& sm, const T& init)
      : owner_(new Owner{&sm, sm.template add_property_map<Key, Stored>(std::string(), Stored(init)).first}),
        map_(owner_->map) {}

  T& operator[](Key k) const { return detail::Property_storage<T>::ref(map_[k]); }

private:
  std::shared_ptr<Owner> owner_;
  Map map_;
};

template <class P, class Tag, class T>
  requires HasIndexMap<CGAL::Surface_mesh<P>, Tag>
auto genmesh_native_scratch_property(Tag, CGAL::Surface_mesh<P>& sm, const T& init) {
  using Key = typename boost::property_traits<decltype(get(Tag{}, sm))>::key_type;
  return Surface_mesh_scratch_property<P, Key, T>(sm, init);
}

/// The elements added by one genmesh_native_append_elements call on a
/// Surface_mesh: named by arithmetic from the first new index when they went
/// to the end of the index ranges, kept in tables only when free slots were
/// recycled.
template <class P>
struct Surface_mesh_appended {
  using Mesh = CGAL::Surface_mesh<P>;
  using V = typename Mesh::Vertex_index;
  using H = typename Mesh::Halfedge_index;
  using F = typename Mesh::Face_index;
  using size_type = typename Mesh::size_type;
  size_type first_vertex = 0, first_edge = 0, first_face = 0;
  std::vector<V> vs; ///< only when recycled slots were used
  std::vector<H> hs;
  std::vector<F> fs;

  V vertex(std::size_t k) const { return vs.empty() ? V(static_cast<size_type>(first_vertex + k)) : vs[k]; }
  /// Halfedge i (0 or 1) of the k-th new edge; the two are opposite.
  H halfedge(std::size_t k, unsigned i) const {
    const size_type h = hs.empty() ? static_cast<size_type>(2 * (first_edge + k)) : static_cast<size_type>(hs[k]);
    return H(h ^ i);
  }
  F face(std::size_t k) const { return fs.empty() ? F(static_cast<size_type>(first_face + k)) : fs[k]; }
};

/// The bulk append of the in-place subdivision (found by ADL; the generic
/// fallback is in <genmesh/subdivision/detail/in_place.h>): nv isolated
/// vertices, ne edges with null connectivity, nf faces without a halfedge,
/// as that many add_vertex()/add_edge()/add_face() calls after one reserve.
/// When nothing waits for recycling the new elements take the next indices,
/// so they are named by arithmetic and no descriptor table is kept (the
/// generic fallback keeps one per element).
template <class P>
Surface_mesh_appended<P> genmesh_native_append_elements(CGAL::Surface_mesh<P>& sm, std::size_t nv, std::size_t ne,
                                                        std::size_t nf) {
  using size_type = typename CGAL::Surface_mesh<P>::size_type;
  Surface_mesh_appended<P> a;
  a.first_vertex = sm.num_vertices();
  a.first_edge = sm.num_edges();
  a.first_face = sm.num_faces();
  sm.reserve(static_cast<size_type>(sm.num_vertices() + nv), static_cast<size_type>(sm.num_edges() + ne),
             static_cast<size_type>(sm.num_faces() + nf));
  const bool recycled = sm.does_recycle_garbage() && (sm.number_of_removed_vertices() != 0 ||
                                                      sm.number_of_removed_edges() != 0 ||
                                                      sm.number_of_removed_faces() != 0);
  if (recycled) {
    a.vs.reserve(nv);
    a.hs.reserve(ne);
    a.fs.reserve(nf);
  }
  for (std::size_t k = 0; k < nv; ++k) {
    const auto v = sm.add_vertex();
    if (recycled) a.vs.push_back(v);
  }
  for (std::size_t k = 0; k < ne; ++k) {
    const auto h = sm.add_edge();
    if (recycled) a.hs.push_back(h);
  }
  for (std::size_t k = 0; k < nf; ++k) {
    const auto f = sm.add_face();
    if (recycled) a.fs.push_back(f);
  }
  return a;
}

// ---- CGAL::Polyhedron_3 ----------------------------------------------------

namespace detail {

template <class Poly>
inline constexpr bool polyhedron_has_ids =
    CGAL::internal::Has_member_id<typename Poly::Vertex>::value &&
    CGAL::internal::Has_member_id<typename Poly::Halfedge>::value &&
    CGAL::internal::Has_member_id<typename Poly::Facet>::value;

// True if id(x) for x in [first, last) is a permutation of [0, n).
template <class It, class Id>
bool ids_are_numbering(It first, It last, std::size_t n, Id id) {
  std::vector<bool> seen(n, false);
  for (; first != last; ++first) {
    const std::size_t i = id(*first);
    if (i >= n || seen[i]) return false;
    seen[i] = true;
  }
  return true;
}

// Renumbers the polyhedron's vertex/halfedge/face ids where they are not a
// valid numbering (halfedge ids paired: opposite halfedges get 2k and 2k+1,
// so edge id = halfedge id / 2), touching nothing when they already are one.
// O(size).
template <class Poly>
void number_polyhedron_ids(Poly& p) {
  if (!ids_are_numbering(p.vertices_begin(), p.vertices_end(), p.size_of_vertices(),
                         [](const auto& v) { return v.id(); })) {
    std::size_t i = 0;
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) v->id() = i++;
  }
  bool paired = ids_are_numbering(p.halfedges_begin(), p.halfedges_end(),
                                  p.size_of_halfedges(), [](const auto& h) { return h.id(); });
  for (auto h = p.halfedges_begin(); paired && h != p.halfedges_end(); ++h)
    paired = (h->id() ^ std::size_t{1}) == h->opposite()->id();
  if (!paired) {
    std::size_t i = 0;
    for (auto e : edges(p)) {
      e.halfedge()->id() = i++;
      e.halfedge()->opposite()->id() = i++;
    }
  }
  if (!ids_are_numbering(p.facets_begin(), p.facets_end(), p.size_of_facets(),
                         [](const auto& f) { return f.id(); })) {
    std::size_t i = 0;
    for (auto f = p.facets_begin(); f != p.facets_end(); ++f) f->id() = i++;
  }
}

// What a polyhedron looked like when its ids were last found to be a valid
// numbering: its address, its three sizes, and the address and id of the
// last vertex, halfedge and facet. Polyhedron_3 only appends elements (to
// the end of its lists, with the id -1 of a new item or the id copied from
// a live one) and removes them; so after any edit that could break the
// numbering, a size differs or the last element is another one, at another
// address or (memory reused) with another id. Comparing stamps is O(1).
struct Polyhedron_id_stamp {
  const void* poly = nullptr;
  std::size_t sizes[3] = {0, 0, 0};
  const void* last[3] = {nullptr, nullptr, nullptr};
  std::size_t last_id[3] = {0, 0, 0};
  bool operator==(const Polyhedron_id_stamp&) const = default;
};

template <class It>
void stamp_last(It first, It last, const void*& address, std::size_t& id) {
  if (first == last) return;
  const auto& x = *std::prev(last);
  address = &x;
  id = x.id();
}

template <class Poly>
Polyhedron_id_stamp polyhedron_id_stamp(const Poly& p) {
  Polyhedron_id_stamp s;
  s.poly = &p;
  s.sizes[0] = p.size_of_vertices();
  s.sizes[1] = p.size_of_halfedges();
  s.sizes[2] = p.size_of_facets();
  stamp_last(p.vertices_begin(), p.vertices_end(), s.last[0], s.last_id[0]);
  stamp_last(p.halfedges_begin(), p.halfedges_end(), s.last[1], s.last_id[1]);
  stamp_last(p.facets_begin(), p.facets_end(), s.last[2], s.last_id[2]);
  return s;
}

// Makes the polyhedron's ids a valid numbering (number_polyhedron_ids) unless
// this thread found them valid since the polyhedron's last edit: a stamp
// comparison, O(1), so get(genmesh::vertex_index, p) may be called per
// element. The stamps of the last 16 polyhedra are kept per thread (a
// polyhedron that drops out is checked again, O(size), on its next use).
// Writes to the ids of a const polyhedron, as CGAL's own
// get_initialized_*_index_map does.
template <class Poly>
void ensure_polyhedron_ids(const Poly& cp) {
  constexpr std::size_t slots = 16;
  thread_local Polyhedron_id_stamp seen[slots];
  thread_local std::size_t next_slot = 0;
  const Polyhedron_id_stamp now = polyhedron_id_stamp(cp);
  std::size_t slot = slots;
  for (std::size_t i = 0; i < slots; ++i) {
    if (seen[i] == now) return;
    if (seen[i].poly == now.poly) slot = i;
  }
  Poly& p = const_cast<Poly&>(cp);
  number_polyhedron_ids(p);
  if (slot == slots) slot = next_slot++ % slots;
  seen[slot] = polyhedron_id_stamp(cp);
}

// The index map of a Polyhedron_3 whose items carry ids.
template <class Handle>
struct Polyhedron_id_map {
  using key_type = Handle;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;
  friend std::size_t get(Polyhedron_id_map, const Handle& h) { return h->id(); }
};

template <class Edge>
struct Polyhedron_edge_id_map {
  using key_type = Edge;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;
  friend std::size_t get(Polyhedron_edge_id_map, const Edge& e) {
    return e.halfedge()->id() / 2;
  }
};

// Type of the index maps above for a Polyhedron_3 (void without ids).
template <class Poly, class Tag, bool = polyhedron_has_ids<Poly>>
struct Polyhedron_index_map {
  using type = void;
};
template <class Poly>
struct Polyhedron_index_map<Poly, vertex_index_t, true> {
  using type = Polyhedron_id_map<typename boost::graph_traits<Poly>::vertex_descriptor>;
};
template <class Poly>
struct Polyhedron_index_map<Poly, halfedge_index_t, true> {
  using type = Polyhedron_id_map<typename boost::graph_traits<Poly>::halfedge_descriptor>;
};
template <class Poly>
struct Polyhedron_index_map<Poly, face_index_t, true> {
  using type = Polyhedron_id_map<typename boost::graph_traits<Poly>::face_descriptor>;
};
template <class Poly>
struct Polyhedron_index_map<Poly, edge_index_t, true> {
  using type = Polyhedron_edge_id_map<typename boost::graph_traits<Poly>::edge_descriptor>;
};

} // namespace detail

#define GENMESH_POLYHEDRON_TPARAMS                                                       \
  class Gt, class I, template <class, class, class> class HDS, class A
#define GENMESH_POLYHEDRON CGAL::Polyhedron_3<Gt, I, HDS, A>

// Both overloads: CGAL declares catch-all get(Tag, Polyhedron_3&) and
// get(Tag, const Polyhedron_3&), and ours must be the more specialized match
// for const and non-const arguments alike.
template <GENMESH_POLYHEDRON_TPARAMS>
auto get(vertex_point_t, GENMESH_POLYHEDRON& p) {
  return get(CGAL::vertex_point, p);
}
template <GENMESH_POLYHEDRON_TPARAMS>
auto get(vertex_point_t, const GENMESH_POLYHEDRON& p) {
  return get(CGAL::vertex_point, const_cast<GENMESH_POLYHEDRON&>(p));
}

// One pair per tag (not a template over the tag): a concrete first parameter
// is what makes these more specialized than CGAL's catch-all.
#define GENMESH_POLYHEDRON_INDEX_GET(TAG)                                               \
  template <GENMESH_POLYHEDRON_TPARAMS>                                                \
    requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>                            \
  auto get(TAG, const GENMESH_POLYHEDRON& p) {                                         \
    detail::ensure_polyhedron_ids(p);                                                  \
    return typename detail::Polyhedron_index_map<GENMESH_POLYHEDRON, TAG>::type{};     \
  }                                                                                    \
  template <GENMESH_POLYHEDRON_TPARAMS>                                                \
    requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>                            \
  auto get(TAG t, GENMESH_POLYHEDRON& p) {                                             \
    return get(t, std::as_const(p));                                                   \
  }
GENMESH_POLYHEDRON_INDEX_GET(vertex_index_t)
GENMESH_POLYHEDRON_INDEX_GET(halfedge_index_t)
GENMESH_POLYHEDRON_INDEX_GET(edge_index_t)
GENMESH_POLYHEDRON_INDEX_GET(face_index_t)
#undef GENMESH_POLYHEDRON_INDEX_GET

template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(vertex_index_t, const GENMESH_POLYHEDRON& p) {
  return p.size_of_vertices();
}
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(halfedge_index_t, const GENMESH_POLYHEDRON& p) {
  return p.size_of_halfedges();
}
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(edge_index_t, const GENMESH_POLYHEDRON& p) {
  return p.size_of_halfedges() / 2;
}
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(face_index_t, const GENMESH_POLYHEDRON& p) {
  return p.size_of_facets();
}

} // namespace genmesh

// CGAL's catch-all get(Tag, Polyhedron_3) instantiates
// boost::property_map<Polyhedron_3, Tag> for *any* tag, genmesh's included, and
// that is a hard error unless CGAL::Polyhedron_property_map<Tag> has a bind_.
// These give it one, so overload resolution can reach genmesh's overloads.
// (Without ids the bound type is void: get(genmesh::vertex_index, p) then
// still compiles, via CGAL's catch-all, but yields nothing, and there is no
// index_bound, so HasIndexMap is false.)
namespace CGAL {
template <>
struct Polyhedron_property_map<genmesh::vertex_point_t>
    : Polyhedron_property_map<CGAL::vertex_point_t> {};

#define GENMESH_POLYHEDRON_INDEX_BIND(TAG)                                              \
  template <>                                                                          \
  struct Polyhedron_property_map<genmesh::TAG> {                                       \
    template <class Gt, class I, template <class, class, class> class HDS, class A>    \
    struct bind_ {                                                                     \
      using type = typename genmesh::detail::Polyhedron_index_map<                     \
          CGAL::Polyhedron_3<Gt, I, HDS, A>, genmesh::TAG>::type;                      \
      using const_type = type;                                                         \
    };                                                                                 \
  };
GENMESH_POLYHEDRON_INDEX_BIND(vertex_index_t)
GENMESH_POLYHEDRON_INDEX_BIND(halfedge_index_t)
GENMESH_POLYHEDRON_INDEX_BIND(edge_index_t)
GENMESH_POLYHEDRON_INDEX_BIND(face_index_t)
#undef GENMESH_POLYHEDRON_INDEX_BIND
} // namespace CGAL

#undef GENMESH_POLYHEDRON_TPARAMS
#undef GENMESH_POLYHEDRON

// ===========================================================================
// Direction 2: genmesh::Halfedge_mesh<P> as a CGAL graph
// ===========================================================================

namespace genmesh::detail {

/// CGAL's dynamic property on a mutable Halfedge_mesh: an anonymous typed
/// property of the mesh (so it grows with the mesh and is recycled and
/// compacted with it), removed when the last copy of this map is destroyed
/// (genmesh::Shared_property, <genmesh/mesh_properties.h>). The mesh must
/// outlive the map, as for CGAL's own dynamic maps.
template <class Key, class T>
using Cgal_dynamic_property = Shared_property<Key, T>;

/// Edge lengths of a Halfedge_mesh of CGAL points (boost::edge_weight, as
/// Surface_mesh's).
template <class K>
struct Cgal_edge_length_map {
  using key_type = Edge_index;
  using value_type = typename K::FT;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  const Halfedge_mesh<CGAL::Point_3<K>>* mesh = nullptr;

  friend value_type get(const Cgal_edge_length_map& m, Edge_index e) {
    const Halfedge_index h = m.mesh->halfedge(e);
    return CGAL::approximate_sqrt(
        CGAL::squared_distance(m.mesh->point(m.mesh->source(h)), m.mesh->point(m.mesh->target(h))));
  }
};

} // namespace genmesh::detail

namespace boost {

template <class K>
struct property_map<genmesh::Halfedge_mesh<CGAL::Point_3<K>>, boost::edge_weight_t> {
  using type = genmesh::detail::Cgal_edge_length_map<K>;
  using const_type = type;
};

template <class P>
struct property_map<genmesh::Halfedge_mesh<P>, CGAL::vertex_point_t> {
  using type = genmesh::Vertex_property<P>;
  using const_type = type;
};

// CGAL's halfedge and face index tags on every genmesh mesh (Boost's
// vertex_index and edge_index: <genmesh/detail/elements/mesh_functions.h>).
template <template <class> class M, class P>
  requires genmesh::detail::is_genmesh_mesh<M>
struct property_map<M<P>, CGAL::halfedge_index_t> {
  using type = genmesh::Index_map<genmesh::Halfedge_index>;
  using const_type = type;
};
template <template <class> class M, class P>
  requires genmesh::detail::is_genmesh_mesh<M>
struct property_map<M<P>, CGAL::face_index_t> {
  using type = genmesh::Index_map<genmesh::Face_index>;
  using const_type = type;
};

#define GENMESH_HM_DYNAMIC_PROPERTY_MAP(TAG, INDEX)                                      \
  template <class P, class T>                                                          \
  struct property_map<genmesh::Halfedge_mesh<P>, CGAL::TAG<T>> {                       \
    using type = genmesh::detail::Cgal_dynamic_property<genmesh::INDEX, T>;            \
    using const_type = CGAL::internal::Dynamic_with_index<genmesh::INDEX, T>;          \
  };
GENMESH_HM_DYNAMIC_PROPERTY_MAP(dynamic_vertex_property_t, Vertex_index)
GENMESH_HM_DYNAMIC_PROPERTY_MAP(dynamic_halfedge_property_t, Halfedge_index)
GENMESH_HM_DYNAMIC_PROPERTY_MAP(dynamic_edge_property_t, Edge_index)
GENMESH_HM_DYNAMIC_PROPERTY_MAP(dynamic_face_property_t, Face_index)
#undef GENMESH_HM_DYNAMIC_PROPERTY_MAP

} // namespace boost

namespace CGAL {
// Only CGAL points count as CGAL's internal point map: for any other point
// type CGAL must be given a vertex_point_map (and geom_traits) explicitly,
// which is how CGAL treats meshes without usable points.
template <class K>
struct graph_has_property<genmesh::Halfedge_mesh<CGAL::Point_3<K>>, boost::vertex_point_t>
    : CGAL::Tag_true {};
template <class K>
struct graph_has_property<genmesh::Halfedge_mesh<CGAL::Point_3<K>>, boost::edge_weight_t>
    : CGAL::Tag_true {};
// The index tags are deliberately left false: see the top of this header.
} // namespace CGAL

namespace genmesh {

/// The positions (the "v:point" property), for CGAL.
template <class P>
Vertex_property<P> get(CGAL::vertex_point_t, const Halfedge_mesh<P>& m) {
  return m.points();
}
template <class P>
P& get(CGAL::vertex_point_t, const Halfedge_mesh<P>& m, Vertex_index v) {
  return m.points()[v];
}
template <class P>
void put(CGAL::vertex_point_t, Halfedge_mesh<P>& m, Vertex_index v, const P& p) {
  m.point(v) = p;
}

/// Edge lengths (boost::edge_weight), for Halfedge_mesh<CGAL::Point_3<K>>.
template <class K>
detail::Cgal_edge_length_map<K> get(boost::edge_weight_t, const Halfedge_mesh<CGAL::Point_3<K>>& m) {
  return {&m};
}

/// CGAL's halfedge and face index maps of any genmesh mesh (Halfedge_mesh,
/// Incidence_mesh), two- and three-argument get as Boost's PropertyGraph
/// concept asks: raw indices, dense only when m has no removed elements.
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Halfedge_index> get(CGAL::halfedge_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(CGAL::halfedge_index_t, const M<P>&, Halfedge_index h) {
  return h.idx();
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
Index_map<Face_index> get(CGAL::face_index_t, const M<P>&) {
  return {};
}
template <template <class> class M, class P>
  requires detail::is_genmesh_mesh<M>
std::size_t get(CGAL::face_index_t, const M<P>&, Face_index f) {
  return f.idx();
}

// Dynamic properties. The by-value tag and the Halfedge_mesh parameter make
// these more specialized than CGAL's generic hash-map fallback.
#define GENMESH_HM_DYNAMIC_GET(TAG, INDEX, BOUND)                                        \
  template <class T, class P>                                                          \
  detail::Cgal_dynamic_property<INDEX, T> get(CGAL::TAG<T>, Halfedge_mesh<P>& m) {     \
    return detail::Cgal_dynamic_property<INDEX, T>(m);                                 \
  }                                                                                    \
  template <class T, class P>                                                          \
  CGAL::internal::Dynamic_with_index<INDEX, T> get(CGAL::TAG<T>, const Halfedge_mesh<P>& m) { \
    return CGAL::internal::Dynamic_with_index<INDEX, T>(m.BOUND());                    \
  }
GENMESH_HM_DYNAMIC_GET(dynamic_vertex_property_t, Vertex_index, vertices_size)
GENMESH_HM_DYNAMIC_GET(dynamic_halfedge_property_t, Halfedge_index, halfedges_size)
GENMESH_HM_DYNAMIC_GET(dynamic_edge_property_t, Edge_index, edges_size)
GENMESH_HM_DYNAMIC_GET(dynamic_face_property_t, Face_index, faces_size)
#undef GENMESH_HM_DYNAMIC_GET

// ---- CGAL points over any genmesh point map --------------------------------

/// A CGAL view of a genmesh point map whose points are not CGAL points (e.g.
/// Halfedge_mesh<Eigen::Vector3d>): reads and writes K::Point_3 by value
/// through Point_traits, so CGAL's algorithms can run on such a mesh:
///   PMP::triangulate_faces(m, CGAL::parameters::vertex_point_map(
///                                 genmesh::cgal_point_map<K>(m)));
/// (CGAL deduces the kernel K from the map's value type.) Exact for double
/// coordinates and an inexact kernel such as EPICK.
template <class K, class Map>
class Cgal_point_map {
public:
  using key_type = typename boost::property_traits<Map>::key_type;
  using value_type = typename K::Point_3;
  using reference = value_type;
  using category = boost::read_write_property_map_tag;

  Cgal_point_map() = default;
  explicit Cgal_point_map(Map map) : map_(std::move(map)) {}

  friend value_type get(const Cgal_point_map& m, const key_type& k) {
    using T = Point_traits<typename boost::property_traits<Map>::value_type>;
    const auto& p = get(m.map_, k);
    return value_type(T::coord(p, 0), T::coord(p, 1), T::coord(p, 2));
  }
  friend void put(const Cgal_point_map& m, const key_type& k, const value_type& p) {
    using T = Point_traits<typename boost::property_traits<Map>::value_type>;
    put(m.map_, k, T::make(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }

private:
  Map map_;
};

/// g's vertex points seen as K::Point_3 (see Cgal_point_map).
template <class K, HasVertexPoints G>
Cgal_point_map<K, vertex_point_map_t<G>> cgal_point_map(G& g) {
  return Cgal_point_map<K, vertex_point_map_t<G>>(get(vertex_point, g));
}

} // namespace genmesh
