// genmesh/renumbering.h — putting a mesh's elements into a given order.
//
// renumber(g, vertex_order, edge_order, face_order) renumbers g's live
// elements so that vertices(g), edges(g) and faces(g) afterwards visit them in
// the given orders, and their indices (get(vertex_index, g), ...) increase
// along them. Algorithms that walk a mesh in index order (remeshing,
// simplification) read memory in that order: a spatial order (Morton, or a
// spatial tree's leaf order) makes neighbours near in memory, which a mesh
// that splits and collapses loses (new elements are appended).
// spatial_orders(g) computes such orders from a vertex order.
//
// How, on each backend (the same order everywhere, so the same algorithm
// gives the same result on every backend afterwards):
// - natively, through genmesh_native_renumber(g, vmap, emap, fmap) found by
//   argument-dependent lookup (Halfedge_mesh and Incidence_mesh: every
//   property follows its element and the garbage is dropped: the live
//   elements take the indices 0, 1, ... in the given order);
// - otherwise through the MutableFaceGraph operations (set_target,
//   set_next, set_face, set_halfedge) and the vertex point map: each live
//   element's connectivity and point move to the slot of the element that
//   is k-th in index order now, so the set of indices in use stays, removed
//   elements stay removed (CGAL::Surface_mesh, Polyhedron_3, OpenMesh).
//   Other per-element data of g (a Surface_mesh property, an OpenMesh
//   property) stays with the slot, not the element: follow the returned maps.
// Halfedges follow their edge with its orientation: halfedge(e) of an edge
// goes to halfedge(e') of its new edge e'.
//
// Returns the maps old index -> new index of each kind (the null index,
// 2^32 - 1, for removed elements), as long as the index bounds before.
// Refused (genmesh::invalid_input, g unchanged): an order that does not list
// every live element of its kind exactly once.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/exceptions.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

/// Old index -> new index for each element kind (see renumber()).
struct Renumbering_maps {
  static constexpr std::uint32_t null = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> vertices, edges, faces;
};

namespace detail::renumbering {

template <class G>
concept Has_native_renumber = requires(G& g, std::span<const std::uint32_t> m) { genmesh_native_renumber(g, m, m, m); };

template <class G>
concept Generic_renumberable = MutableFaceGraph<G> && FaceListGraph<G> && EdgeListGraph<G> && VertexListGraph<G> &&
                               HasVertexPoints<G> && HasIndexMap<G, vertex_index_t> && HasIndexMap<G, edge_index_t> &&
                               HasIndexMap<G, face_index_t>;

/// Old index -> rank in `order` (null for elements not listed); refuses an
/// order that does not list each of the `live` elements once.
template <class Order, class IndexMap>
std::vector<std::uint32_t> ranks(const Order& order, IndexMap index, std::size_t bound, std::size_t live,
                                 const char* what) {
  std::vector<std::uint32_t> rank(bound, Renumbering_maps::null);
  bool ok = order.size() == live;
  for (std::size_t k = 0; ok && k < order.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(get(index, order[k]));
    ok = i < bound && rank[i] == Renumbering_maps::null;
    if (ok) rank[i] = static_cast<std::uint32_t>(k);
  }
  if (!ok)
    throw invalid_input(std::string("renumber: the ") + what + " order does not list every live " + what +
                        " exactly once");
  return rank;
}

} // namespace detail::renumbering

/// A mesh renumber() accepts: one with genmesh_native_renumber, or a
/// MutableFaceGraph with vertex points and index maps.
template <class G>
concept Renumberable = detail::renumbering::Has_native_renumber<G> || detail::renumbering::Generic_renumberable<G>;

/// Renumbers g's live elements into the given orders (see the header
/// comment); returns the old -> new index maps. Each order must list every
/// live element of its kind once (else invalid_input, g unchanged).
template <class G>
  requires Renumberable<G> && VertexListGraph<G> && EdgeListGraph<G> && FaceListGraph<G> &&
           HasIndexMap<G, vertex_index_t> && HasIndexMap<G, edge_index_t> && HasIndexMap<G, face_index_t>
Renumbering_maps renumber(G& g, std::span<const vertex_descriptor_t<G>> vertex_order,
                          std::span<const edge_descriptor_t<G>> edge_order,
                          std::span<const face_descriptor_t<G>> face_order) {
  using detail::renumbering::ranks;
  const auto vi = get(vertex_index, std::as_const(g));
  const auto ei = get(edge_index, std::as_const(g));
  const auto fi = get(face_index, std::as_const(g));
  const std::size_t vb = index_bound(vertex_index, g), eb = index_bound(edge_index, g),
                    fb = index_bound(face_index, g);
  // Live counts by iteration: num_vertices(g) of CGAL::Surface_mesh counts
  // removed elements too.
  auto count = [](auto&& range) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto x : range) ++n;
    return n;
  };
  Renumbering_maps maps;
  maps.vertices = ranks(vertex_order, vi, vb, count(vertices(g)), "vertex");
  maps.edges = ranks(edge_order, ei, eb, count(edges(g)), "edge");
  maps.faces = ranks(face_order, fi, fb, count(faces(g)), "face");
  if constexpr (detail::renumbering::Has_native_renumber<G>) {
    // New index = rank: the native renumbering compacts.
    genmesh_native_renumber(g, std::span<const std::uint32_t>(maps.vertices), std::span<const std::uint32_t>(maps.edges),
                            std::span<const std::uint32_t>(maps.faces));
    return maps;
  } else {
    using V = vertex_descriptor_t<G>;
    using H = halfedge_descriptor_t<G>;
    using E = edge_descriptor_t<G>;
    using F = face_descriptor_t<G>;
    constexpr std::uint32_t null = Renumbering_maps::null;
    // The slots (live elements in index order) and the rank -> slot tables.
    std::vector<V> vslot;
    std::vector<E> eslot;
    std::vector<F> fslot;
    for (const V v : vertices(g)) vslot.push_back(v);
    for (const E e : edges(g)) eslot.push_back(e);
    for (const F f : faces(g)) fslot.push_back(f);
    auto by_index = [](auto& slots, auto index) {
      std::sort(slots.begin(), slots.end(), [&](auto a, auto b) { return get(index, a) < get(index, b); });
    };
    by_index(vslot, vi), by_index(eslot, ei), by_index(fslot, fi);
    // Rank -> index: the maps returned.
    for (auto& r : maps.vertices)
      if (r != null) r = static_cast<std::uint32_t>(get(vi, vslot[r]));
    for (auto& r : maps.edges)
      if (r != null) r = static_cast<std::uint32_t>(get(ei, eslot[r]));
    for (auto& r : maps.faces)
      if (r != null) r = static_cast<std::uint32_t>(get(fi, fslot[r]));
    // Old descriptor -> new descriptor. An edge's halfedges by side: side 0
    // is halfedge(e) of the edge as edges(g) gives it (on Surface_mesh,
    // halfedge(edge(h)) is h itself, whichever side h is).
    std::vector<H> side0(eb, boost::graph_traits<G>::null_halfedge());
    for (const E e : eslot) side0[get(ei, e)] = halfedge(e, g);
    std::vector<V> vnew(vb, boost::graph_traits<G>::null_vertex());
    std::vector<F> fnew(fb, boost::graph_traits<G>::null_face());
    std::vector<H> hnew(2 * eb, boost::graph_traits<G>::null_halfedge()); // by 2 edge index + side
    for (std::size_t k = 0; k < vertex_order.size(); ++k) vnew[get(vi, vertex_order[k])] = vslot[k];
    for (std::size_t k = 0; k < face_order.size(); ++k) fnew[get(fi, face_order[k])] = fslot[k];
    auto hkey = [&](H h) {
      const std::size_t e = static_cast<std::size_t>(get(ei, edge(h, g)));
      return 2 * e + (h == side0[e] ? 0 : 1);
    };
    for (std::size_t k = 0; k < edge_order.size(); ++k) {
      const H from = side0[get(ei, edge_order[k])], to = side0[get(ei, eslot[k])];
      hnew[hkey(from)] = to;
      hnew[hkey(opposite(from, g))] = opposite(to, g);
    }
    auto map_h = [&](H h) { return h == boost::graph_traits<G>::null_halfedge() ? h : hnew[hkey(h)]; };
    auto map_f = [&](F f) { return f == boost::graph_traits<G>::null_face() ? f : fnew[get(fi, f)]; };
    // Read everything first, then write: the slots are overwritten in any order.
    struct Half {
      H to, next;
      V target;
      F face;
    };
    std::vector<Half> halves;
    halves.reserve(2 * edge_order.size());
    for (const E e : edge_order)
      for (const H h : {side0[get(ei, e)], opposite(side0[get(ei, e)], g)})
        halves.push_back({map_h(h), map_h(next(h, g)), vnew[get(vi, target(h, g))], map_f(face(h, g))});
    auto pm = get(vertex_point, g);
    std::vector<point_t<G>> points;
    std::vector<H> vhalf, fhalf;
    points.reserve(vertex_order.size());
    for (const V v : vertex_order) {
      points.push_back(get(pm, v));
      const H h = halfedge(v, g);
      vhalf.push_back(map_h(h));
    }
    for (const F f : face_order) fhalf.push_back(map_h(halfedge(f, g)));
    for (const Half& x : halves) {
      set_target(x.to, x.target, g);
      set_next(x.to, x.next, g);
      set_face(x.to, x.face, g);
    }
    for (std::size_t k = 0; k < vslot.size(); ++k) {
      set_halfedge(vslot[k], vhalf[k], g);
      put(pm, vslot[k], points[k]);
    }
    for (std::size_t k = 0; k < fslot.size(); ++k) set_halfedge(fslot[k], fhalf[k], g);
    return maps;
  }
}

/// Spatially coherent orders for renumber(): the vertices in `vertex_order`
/// (e.g. a Morton order), each edge and face after the vertices ordered before
/// it: by the lowest rank of their vertices, ties in index order (a stable
/// counting sort). Deterministic: only ranks and indices decide.
template <class G>
struct Spatial_orders {
  std::vector<vertex_descriptor_t<G>> vertices;
  std::vector<edge_descriptor_t<G>> edges;
  std::vector<face_descriptor_t<G>> faces;
};

template <class G>
  requires VertexListGraph<G> && EdgeListGraph<G> && FaceListGraph<G> && HasIndexMap<G, vertex_index_t>
Spatial_orders<G> spatial_orders(const G& g, std::vector<vertex_descriptor_t<G>> vertex_order) {
  const auto vi = get(vertex_index, g);
  std::vector<std::uint32_t> rank(index_bound(vertex_index, g), 0);
  const auto nv = static_cast<std::uint32_t>(vertex_order.size());
  for (std::uint32_t k = 0; k < nv; ++k) rank[get(vi, vertex_order[k])] = k;
  // A stable counting sort by key; the keys computed once.
  std::vector<std::uint32_t> keys, bucket;
  auto sorted = [&](auto&& range, auto&& key, auto& out) {
    using X = typename std::remove_cvref_t<decltype(out)>::value_type;
    std::vector<X> items;
    items.reserve(range.size());
    keys.clear();
    keys.reserve(range.size());
    bucket.assign(std::size_t(nv) + 1, 0);
    for (const X x : range) {
      const std::uint32_t k = key(x);
      items.push_back(x);
      keys.push_back(k);
      ++bucket[k + 1];
    }
    for (std::size_t t = 1; t < bucket.size(); ++t) bucket[t] += bucket[t - 1];
    out.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) out[bucket[keys[i]]++] = items[i];
  };
  Spatial_orders<G> o;
  sorted(edges(g), [&](edge_descriptor_t<G> e) {
    const auto h = halfedge(e, g);
    return std::min(rank[get(vi, source(h, g))], rank[get(vi, target(h, g))]);
  }, o.edges);
  sorted(faces(g), [&](face_descriptor_t<G> f) {
    const auto h0 = halfedge(f, g);
    std::uint32_t r = rank[get(vi, target(h0, g))];
    for (auto h = next(h0, g); h != h0; h = next(h, g)) r = std::min(r, rank[get(vi, target(h, g))]);
    return r;
  }, o.faces);
  o.vertices = std::move(vertex_order);
  return o;
}

} // namespace genmesh
