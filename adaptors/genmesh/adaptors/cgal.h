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
//   (CGAL::Polyhedron_items_with_id_3); the index of an element is its id.
//   Contract: the ids genmesh reads are unique and below index_bound (for
//   halfedges, opposite ones are 2k and 2k+1, and an edge's id is k), and an
//   element's id never changes while it lives, so index-keyed tables stay
//   valid across edits (simplify and isotropic_remeshing keep such tables).
//   Removed elements leave holes (ids are sparse); an element that has no
//   valid id — a new one (CGAL gives new items the id -1), one whose id an
//   earlier element in list order holds (items copied by Polyhedron_3's
//   member functions), one at or above the bound — gets a fresh id from the
//   bound up, which then grows (it only grows, restarting at 0 only when no
//   element keeps an id). This happens when genmesh next looks:
//   get(genmesh::vertex_index, p), index_bound(…, p), or a map's get on an
//   element whose id is still -1 (writing to the ids of a const polyhedron,
//   as CGAL's own get_initialized_*_index_map does). A look is O(1) after
//   removals that spared each list's last element (the last element's
//   address and id, recorded at the previous look, are still at the end),
//   O(added) when elements were appended behind it, and O(size) otherwise
//   (that last element removed, items copied with their ids, a polyhedron
//   the thread has not seen): a per-thread record of the last 16 polyhedra,
//   see detail::ensure_polyhedron_ids. Ids a user
//   writes by hand are kept if valid, except ones at or above the bound the
//   thread recorded. A polyhedron without ids has points but no index maps:
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

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <span>
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

/// The "v:point" array itself (HasNativePointArray, <genmesh/property_maps.h>).
template <class P>
std::span<const P> genmesh_native_point_array(vertex_point_t, const CGAL::Surface_mesh<P>& sm) {
  return {sm.points().data(), static_cast<std::size_t>(sm.num_vertices())};
}

/// Edge and face i's descriptors (HasNativeDescriptorOfIndex,
/// <genmesh/property_maps.h>): Surface_mesh's edge index i (made of
/// halfedge 2i) and face index i, as edges(sm) and faces(sm) yield them.
template <class P>
typename boost::graph_traits<CGAL::Surface_mesh<P>>::edge_descriptor
genmesh_native_descriptor(edge_index_t, const CGAL::Surface_mesh<P>&, std::size_t i) {
  using E = typename boost::graph_traits<CGAL::Surface_mesh<P>>::edge_descriptor;
  return E(static_cast<typename E::size_type>(i));
}
template <class P>
typename boost::graph_traits<CGAL::Surface_mesh<P>>::face_descriptor
genmesh_native_descriptor(face_index_t, const CGAL::Surface_mesh<P>&, std::size_t i) {
  using F = typename boost::graph_traits<CGAL::Surface_mesh<P>>::face_descriptor;
  return F(static_cast<typename F::size_type>(i));
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

// The id CGAL gives a new item (Polyhedron_items_with_id_3's default):
// "missing", numbered at the next look.
inline constexpr std::size_t polyhedron_no_id = static_cast<std::size_t>(-1);

// Without a record of a polyhedron, an id at or above this many times the
// list's size counts as missing too: a scratch array is sized by the bound,
// so one stray huge id must not allocate gigabytes. (Sparse ids of a mesh
// simplified to 1/64 of its size are still kept.)
inline constexpr std::size_t polyhedron_max_sparsity = 64;

// What this thread last knew of a polyhedron's ids: per list (0 vertices,
// 1 halfedges, 2 facets) the bound (one above the largest id; even for
// halfedges), and the list's size and last element (address and id) just
// after the last numbering.
struct Polyhedron_id_record {
  const void* poly = nullptr;
  std::size_t bound[3] = {0, 0, 0};
  std::size_t size[3] = {0, 0, 0};
  const void* last[3] = {nullptr, nullptr, nullptr};
  std::size_t last_id[3] = {0, 0, 0};
};

template <int K, class Poly>
auto polyhedron_list(Poly& p) {
  if constexpr (K == 0) return std::pair(p.vertices_begin(), p.vertices_end());
  else if constexpr (K == 1) return std::pair(p.halfedges_begin(), p.halfedges_end());
  else return std::pair(p.facets_begin(), p.facets_end());
}
template <int K, class Poly>
std::size_t polyhedron_list_size(const Poly& p) {
  if constexpr (K == 0) return p.size_of_vertices();
  else if constexpr (K == 1) return p.size_of_halfedges();
  else return p.size_of_facets();
}

template <int K, class Poly>
void record_list(Poly& p, Polyhedron_id_record& r) {
  const auto [first, last] = polyhedron_list<K>(p);
  r.size[K] = polyhedron_list_size<K>(p);
  r.last[K] = nullptr;
  r.last_id[K] = 0;
  if (first == last) return;
  const auto& x = *std::prev(last);
  r.last[K] = &x;
  r.last_id[K] = x.id();
}

template <int K, class Poly>
bool list_unchanged(Poly& p, const Polyhedron_id_record& r) {
  const auto [first, last] = polyhedron_list<K>(p);
  if (polyhedron_list_size<K>(p) != r.size[K]) return false;
  if (first == last) return r.last[K] == nullptr;
  const auto& x = *std::prev(last);
  return &x == r.last[K] && x.id() == r.last_id[K];
}

// The O(new) path. Polyhedron_3 appends new items at the end of its lists
// and removes items from anywhere, and removing leaves the other ids valid.
// So if, walking back from the end over missing ids (at or above the bound),
// one reaches the element recorded as last (same address, same id), then
// every element before it is an old one with its old, valid id, and only the
// walked-over ones need ids: fresh ones from the bound up, in list order
// (halfedges: 2k to the first of a new pair, 2k+1 to its opposite). Returns
// false, changing nothing the full numbering would not, when that is not so
// (the recorded last was removed, or an item was appended with a copied id).
template <int K, class Poly>
bool number_appended(Poly& p, Polyhedron_id_record& r) {
  const auto [first, last] = polyhedron_list<K>(p);
  std::size_t bound = r.bound[K], appended = 0;
  auto it = last;
  while (it != first && std::prev(it)->id() >= bound) {
    --it;
    ++appended;
  }
  if (it == first) {
    bound = 0; // no element keeps an id: a fresh numbering from 0
  } else {
    const auto& kept = *std::prev(it);
    if (&kept != r.last[K] || kept.id() != r.last_id[K]) return false;
    if (polyhedron_list_size<K>(p) - appended > r.size[K]) return false;
  }
  if constexpr (K == 1) {
    for (auto h = it; h != last; ++h) h->id() = polyhedron_no_id;
    for (auto h = it; h != last; ++h) {
      if (h->id() != polyhedron_no_id) continue;
      if (h->opposite()->id() != polyhedron_no_id) return false;
      h->id() = bound++;
      h->opposite()->id() = bound++;
    }
  } else {
    for (auto x = it; x != last; ++x) x->id() = bound++;
  }
  r.bound[K] = bound;
  record_list<K>(p, r);
  return true;
}

// The O(size) path: keeps every id that is below the limit and not taken by
// an earlier element in list order (halfedges: pairs 2k/2k+1 with their
// opposites), and gives the others fresh ids from the bound up, in list
// order. The bound only grows, except that it restarts at 0 when no element
// keeps an id (a polyhedron cleared and rebuilt, or a new one at a recorded
// address).
template <int K, class Poly>
void number_list(Poly& p, Polyhedron_id_record& r, bool known) {
  const std::size_t n = polyhedron_list_size<K>(p);
  const std::size_t limit = known ? r.bound[K] : polyhedron_max_sparsity * (n + 1);
  std::size_t kept_bound = 0;
  if constexpr (K == 1) {
    auto pair_kept = [limit](const auto& h) {
      const std::size_t i = h->id(), j = h->opposite()->id();
      return i < limit && j < limit && (i ^ std::size_t{1}) == j;
    };
    for (auto e : edges(p))
      if (pair_kept(e.halfedge())) kept_bound = std::max(kept_bound, (e.halfedge()->id() | 1) + 1);
    std::vector<bool> seen(kept_bound / 2, false);
    std::size_t next = kept_bound == 0 ? 0 : (known ? std::max(r.bound[K], kept_bound) : kept_bound);
    for (auto e : edges(p)) {
      const auto h = e.halfedge();
      if (pair_kept(h) && !seen[h->id() / 2]) {
        seen[h->id() / 2] = true;
      } else {
        h->id() = next++;
        h->opposite()->id() = next++;
      }
    }
    r.bound[K] = next;
  } else {
    const auto [first, last] = polyhedron_list<K>(p);
    for (auto x = first; x != last; ++x)
      if (x->id() < limit) kept_bound = std::max(kept_bound, x->id() + 1);
    std::vector<bool> seen(kept_bound, false);
    std::size_t next = kept_bound == 0 ? 0 : (known ? std::max(r.bound[K], kept_bound) : kept_bound);
    for (auto x = first; x != last; ++x) {
      if (x->id() < limit && !seen[x->id()]) {
        seen[x->id()] = true;
      } else {
        x->id() = next++;
      }
    }
    r.bound[K] = next;
  }
  record_list<K>(p, r);
}

template <int K, class Poly>
void ensure_list(Poly& p, Polyhedron_id_record& r, bool known) {
  if (known && list_unchanged<K>(p, r)) return;
  if (known && number_appended<K>(p, r)) return;
  number_list<K>(p, r, known);
}

// Makes the polyhedron's ids valid — unique, below the bound, halfedge
// pairs 2k/2k+1 — without changing a valid id (see the header's comment).
// Returns this thread's record of the polyhedron, whose bounds are the index
// bounds. O(1) when each list's recorded last element is still its last
// (removals elsewhere), O(appended) when elements were only appended behind
// it, O(size) otherwise (the last element removed, items copied with their
// ids, a polyhedron this thread has not seen). Records of the last 16 polyhedra are kept per
// thread; one that drops out is numbered as unknown on its next use (valid
// ids kept). Writes to the ids of a const polyhedron, as CGAL's own
// get_initialized_*_index_map does.
template <class Poly>
const Polyhedron_id_record& ensure_polyhedron_ids(const Poly& cp) {
  constexpr std::size_t slots = 16;
  thread_local Polyhedron_id_record records[slots];
  thread_local std::size_t last_used = 0, next_slot = 0;
  std::size_t slot = last_used;
  if (records[slot].poly != &cp) {
    slot = slots;
    for (std::size_t i = 0; i < slots; ++i)
      if (records[i].poly == &cp) slot = i;
  }
  const bool known = slot != slots;
  if (!known) {
    slot = next_slot++ % slots;
    records[slot] = Polyhedron_id_record{};
    records[slot].poly = &cp;
  }
  last_used = slot;
  Poly& p = const_cast<Poly&>(cp);
  Polyhedron_id_record& r = records[slot];
  ensure_list<0>(p, r, known);
  ensure_list<1>(p, r, known);
  ensure_list<2>(p, r, known);
  return r;
}

// The index map of a Polyhedron_3 whose items carry ids: the item's id. An
// element added since the ids were last made valid (its id still CGAL's
// missing -1) gets its id here, so maps kept across edits stay usable.
template <class Poly, class Handle>
struct Polyhedron_id_map {
  using key_type = Handle;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;
  const Poly* poly = nullptr;
  friend std::size_t get(const Polyhedron_id_map& m, const Handle& h) {
    if (h->id() == polyhedron_no_id && m.poly != nullptr) [[unlikely]]
      ensure_polyhedron_ids(*m.poly);
    return h->id();
  }
};

template <class Poly, class Edge>
struct Polyhedron_edge_id_map {
  using key_type = Edge;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::readable_property_map_tag;
  const Poly* poly = nullptr;
  friend std::size_t get(const Polyhedron_edge_id_map& m, const Edge& e) {
    if (e.halfedge()->id() == polyhedron_no_id && m.poly != nullptr) [[unlikely]]
      ensure_polyhedron_ids(*m.poly);
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
  using type = Polyhedron_id_map<Poly, typename boost::graph_traits<Poly>::vertex_descriptor>;
};
template <class Poly>
struct Polyhedron_index_map<Poly, halfedge_index_t, true> {
  using type = Polyhedron_id_map<Poly, typename boost::graph_traits<Poly>::halfedge_descriptor>;
};
template <class Poly>
struct Polyhedron_index_map<Poly, face_index_t, true> {
  using type = Polyhedron_id_map<Poly, typename boost::graph_traits<Poly>::face_descriptor>;
};
template <class Poly>
struct Polyhedron_index_map<Poly, edge_index_t, true> {
  using type = Polyhedron_edge_id_map<Poly, typename boost::graph_traits<Poly>::edge_descriptor>;
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
    return typename detail::Polyhedron_index_map<GENMESH_POLYHEDRON, TAG>::type{&p};   \
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

/// The stored bounds (one above the largest id, growing as elements are
/// added), not the sizes: ids are sparse after removals.
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(vertex_index_t, const GENMESH_POLYHEDRON& p) {
  return detail::ensure_polyhedron_ids(p).bound[0];
}
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(halfedge_index_t, const GENMESH_POLYHEDRON& p) {
  return detail::ensure_polyhedron_ids(p).bound[1];
}
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(edge_index_t, const GENMESH_POLYHEDRON& p) {
  return detail::ensure_polyhedron_ids(p).bound[1] / 2;
}
template <GENMESH_POLYHEDRON_TPARAMS>
  requires detail::polyhedron_has_ids<GENMESH_POLYHEDRON>
std::size_t index_bound(face_index_t, const GENMESH_POLYHEDRON& p) {
  return detail::ensure_polyhedron_ids(p).bound[2];
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
