// genmesh/halfedge_mesh.h — genmesh's own halfedge mesh: Halfedge_mesh<Point>.
//
// What it is: an index-based halfedge data structure stored as a structure of
// arrays with 32-bit indices. The two halfedges of edge e are 2e and 2e+1, so
// opposite(h) = h^1 and edge(h).idx() = h/2 are arithmetic. Per halfedge it stores
// next, prev, target vertex and face (next and target in arrays of their own,
// which walks read; prev and face paired, which edits read and write
// together; the three in one allocation); per vertex one halfedge *targeting* it
// (null if isolated); per face one of its halfedges; one removed bit per vertex,
// edge and face. Positions and any user data are typed dynamic properties
// (positions are the vertex property "v:point").
//
// Guarantees:
// - Memory is CGAL::Surface_mesh's, byte for byte: the same 4-byte indices
//   (16 bytes per halfedge, 4 per vertex and face), the same removed bits,
//   the same doubling growth, so bytes per element never exceed
//   Surface_mesh's on the same mesh (about 66 bytes per triangle with
//   double points); memory_bytes() reports the total.
// - Index allocation is CGAL::Surface_mesh's exactly: remove_* only marks and
//   pushes onto a LIFO free list (threaded through the removed element's own
//   halfedge/next slot), add_* reuses the most recently freed index when
//   recycling is on (the default), else appends; a recycled element's
//   connectivity is null and its properties get their default values again.
//   Iteration is by increasing index, skipping removed elements. So a sequence
//   of low-level edits (and every CGAL algorithm made of them) gives the same
//   indices on both meshes.
// - collect_garbage() compacts *preserving the relative order* of surviving
//   elements (Surface_mesh instead swaps the last live element into each hole;
//   collect_garbage(Garbage_order::like_surface_mesh) does that too) and
//   returns the old -> new maps. Determinism across backends is stated up
//   to canonical soups, so this deviation is harmless there, and it keeps
//   iteration order meaningful after compaction.
// - Like Surface_mesh's, an Edge_index made by edge(h) remembers h, so
//   halfedge(edge(h)) == h and CGAL code relying on that behaves identically.
//
// Limits: the low-level edits (set_next, remove_edge, ...) keep nothing
// consistent by themselves, as in CGAL; algorithms use local operations.
// num_vertices(m) & co. are *live* counts (genmesh's convention), whereas
// CGAL's BGL concept only promises an upper bound and Surface_mesh returns
// its index bound; scratch arrays must be sized by index_bound / *_size().
//
// The whole CGAL BGL free-function surface (graph_traits, next, opposite,
// add_face, set_next, ...) is at the bottom of this header, found by ADL.
// No CGAL header is needed here; <genmesh/adaptors/cgal.h> adds CGAL's
// property-map tags.
#pragma once

#include <genmesh/concepts.h>
#include <genmesh/detail/elements/compaction.h>
#include <genmesh/detail/halfedge/cycle_iterator.h>
#include <genmesh/detail/halfedge/links.h>
#include <genmesh/elements.h>
#include <genmesh/exceptions.h>
#include <genmesh/mesh_properties.h>
#include <genmesh/point_traits.h>
#include <genmesh/property_maps.h>

#include <Eigen/Core>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cassert>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace genmesh {

class Halfedge_connectivity;
namespace detail {
struct Halfedge_mesh_bulk;
}

using Halfedge_around_face_iterator = detail::Cycle_iterator<detail::Step_face>;
using Vertex_around_face_iterator = detail::Cycle_iterator<detail::Step_face_vertex>;
using Halfedge_around_target_iterator = detail::Cycle_iterator<detail::Step_target>;
using Vertex_around_target_iterator = detail::Cycle_iterator<detail::Step_target_vertex>;
using Face_around_target_iterator = detail::Cycle_iterator<detail::Step_target_face>;
/// Edges e around a vertex v with target(e) == v (in) or source(e) == v (out).
using In_edge_iterator = detail::Cycle_iterator<detail::Step_target_in_edge>;
using Out_edge_iterator = detail::Cycle_iterator<detail::Step_target_out_edge>;

// ---------------------------------------------------------------------------
// Connectivity (everything but the point type)
// ---------------------------------------------------------------------------

/// The connectivity and properties of a Halfedge_mesh; the point type is added
/// by Halfedge_mesh<Point>. Not used on its own.
class Halfedge_connectivity : public Mesh_properties<Vertex_index, Halfedge_index, Edge_index, Face_index> {
public:
  using size_type = std::size_t;

  static constexpr Vertex_index null_vertex() { return {}; }
  static constexpr Halfedge_index null_halfedge() { return {}; }
  static constexpr Edge_index null_edge() { return {}; }
  static constexpr Face_index null_face() { return {}; }

  // ---- counts -------------------------------------------------------------

  /// Live (not removed) elements.
  [[nodiscard]] size_type n_vertices() const { return vertices_size() - removed_vertices_; }
  [[nodiscard]] size_type n_halfedges() const { return halfedges_size() - 2 * removed_edges_; }
  [[nodiscard]] size_type n_edges() const { return edges_size() - removed_edges_; }
  [[nodiscard]] size_type n_faces() const { return faces_size() - removed_faces_; }
  [[nodiscard]] bool is_empty() const { return n_vertices() == 0; }
  /// Surface_mesh's spellings of the live counts.
  [[nodiscard]] size_type number_of_vertices() const { return n_vertices(); }
  [[nodiscard]] size_type number_of_halfedges() const { return n_halfedges(); }
  [[nodiscard]] size_type number_of_edges() const { return n_edges(); }
  [[nodiscard]] size_type number_of_faces() const { return n_faces(); }

  /// Index bounds: live plus removed, not yet collected, elements.
  [[nodiscard]] size_type vertices_size() const { return vhalfedge_.size(); }
  [[nodiscard]] size_type halfedges_size() const { return hlinks_.size(); }
  [[nodiscard]] size_type edges_size() const { return hlinks_.size() / 2; }
  [[nodiscard]] size_type faces_size() const { return fhalfedge_.size(); }

  [[nodiscard]] size_type number_of_removed_vertices() const { return removed_vertices_; }
  [[nodiscard]] size_type number_of_removed_halfedges() const { return 2 * removed_edges_; }
  [[nodiscard]] size_type number_of_removed_edges() const { return removed_edges_; }
  [[nodiscard]] size_type number_of_removed_faces() const { return removed_faces_; }

  // ---- validity -----------------------------------------------------------

  [[nodiscard]] bool is_removed(Vertex_index v) const { return vremoved_[v.idx()]; }
  [[nodiscard]] bool is_removed(Halfedge_index h) const { return eremoved_[h.idx() >> 1]; }
  [[nodiscard]] bool is_removed(Edge_index e) const { return eremoved_[e.idx()]; }
  [[nodiscard]] bool is_removed(Face_index f) const { return fremoved_[f.idx()]; }

  /// Index within the current bounds (removed or not), as CGAL's has_valid_index.
  [[nodiscard]] bool has_valid_index(Vertex_index v) const { return v.idx() < vertices_size(); }
  [[nodiscard]] bool has_valid_index(Halfedge_index h) const { return h.idx() < halfedges_size(); }
  [[nodiscard]] bool has_valid_index(Edge_index e) const { return e.idx() < edges_size(); }
  [[nodiscard]] bool has_valid_index(Face_index f) const { return f.idx() < faces_size(); }

  /// Within bounds and not removed.
  [[nodiscard]] bool is_valid(Vertex_index v) const { return has_valid_index(v) && !is_removed(v); }
  [[nodiscard]] bool is_valid(Halfedge_index h) const { return has_valid_index(h) && !is_removed(h); }
  [[nodiscard]] bool is_valid(Edge_index e) const { return has_valid_index(e) && !is_removed(e); }
  [[nodiscard]] bool is_valid(Face_index f) const { return has_valid_index(f) && !is_removed(f); }

  // ---- connectivity -------------------------------------------------------

  [[nodiscard]] Halfedge_index next(Halfedge_index h) const { return hlinks_.next(h.idx()); }
  [[nodiscard]] Halfedge_index prev(Halfedge_index h) const { return hlinks_.prev(h.idx()); }
  [[nodiscard]] Vertex_index target(Halfedge_index h) const { return hlinks_.target(h.idx()); }
  [[nodiscard]] Vertex_index source(Halfedge_index h) const { return hlinks_.target(h.idx() ^ 1u); }
  [[nodiscard]] Face_index face(Halfedge_index h) const { return hlinks_.face(h.idx()); }
  [[nodiscard]] static constexpr Halfedge_index opposite(Halfedge_index h) {
    return Halfedge_index(h.idx() ^ 1u);
  }
  /// The edge of h, remembering h (see Edge_index).
  [[nodiscard]] static constexpr Edge_index edge(Halfedge_index h) { return Edge_index(h); }
  /// The halfedge e was made from: h for edge(h), 2e for Edge_index(e) and
  /// for the edges of edges() (as Surface_mesh).
  [[nodiscard]] static constexpr Halfedge_index halfedge(Edge_index e) { return e.halfedge(); }
  /// Halfedge i (0 or 1) of e: 2e + i.
  [[nodiscard]] static constexpr Halfedge_index halfedge(Edge_index e, unsigned i) {
    return Halfedge_index((e.idx() << 1) + i);
  }
  /// Vertex i (0 or 1) of e: target(halfedge(e, i)).
  [[nodiscard]] Vertex_index vertex(Edge_index e, unsigned i) const { return target(halfedge(e, i)); }
  /// A halfedge with target v; null if v is isolated.
  [[nodiscard]] Halfedge_index halfedge(Vertex_index v) const { return vhalfedge_[v.idx()]; }
  [[nodiscard]] Halfedge_index halfedge(Face_index f) const { return fhalfedge_[f.idx()]; }
  /// The halfedge from u to v, or null (searches around v).
  [[nodiscard]] Halfedge_index halfedge(Vertex_index u, Vertex_index v) const {
    const Halfedge_index start = halfedge(v);
    if (!start.is_valid()) return {};
    Halfedge_index h = start;
    do {
      if (source(h) == u) return h;
      h = next_around_target(h);
    } while (h != start);
    return {};
  }

  /// Hints that h's links (next, prev, target, face; its opposite's share
  /// their cache lines) will be read soon: a cache prefetch, nothing else.
  void prefetch(Halfedge_index h) const { hlinks_.prefetch(h.idx()); }
  /// Hints that halfedge(v) will be read soon.
  void prefetch(Vertex_index v) const { detail::prefetch(vhalfedge_.data() + v.idx()); }

  /// opposite(next(h)): the next halfedge clockwise around target(h).
  [[nodiscard]] Halfedge_index next_around_target(Halfedge_index h) const { return opposite(next(h)); }
  /// prev(opposite(h)).
  [[nodiscard]] Halfedge_index prev_around_target(Halfedge_index h) const { return prev(opposite(h)); }
  /// next(opposite(h)).
  [[nodiscard]] Halfedge_index next_around_source(Halfedge_index h) const { return next(opposite(h)); }
  /// opposite(prev(h)).
  [[nodiscard]] Halfedge_index prev_around_source(Halfedge_index h) const { return opposite(prev(h)); }

  /// next(h) = nh and, if nh is not null, prev(nh) = h (as Surface_mesh).
  void set_next(Halfedge_index h, Halfedge_index nh) {
    hlinks_.next(h.idx()) = nh;
    if (nh.is_valid()) hlinks_.prev(nh.idx()) = h;
  }
  void set_next_only(Halfedge_index h, Halfedge_index nh) { hlinks_.next(h.idx()) = nh; }
  void set_prev_only(Halfedge_index h, Halfedge_index ph) {
    if (h.is_valid()) hlinks_.prev(h.idx()) = ph;
  }
  void set_target(Halfedge_index h, Vertex_index v) { hlinks_.target(h.idx()) = v; }
  void set_face(Halfedge_index h, Face_index f) { hlinks_.face(h.idx()) = f; }
  void set_halfedge(Vertex_index v, Halfedge_index h) { vhalfedge_[v.idx()] = h; }
  void set_halfedge(Face_index f, Halfedge_index h) { fhalfedge_[f.idx()] = h; }

  // ---- borders and degrees ------------------------------------------------

  /// face(h) is null.
  [[nodiscard]] bool is_border(Halfedge_index h) const { return !face(h).is_valid(); }
  /// Either halfedge of e is a border halfedge.
  [[nodiscard]] bool is_border(Edge_index e) const {
    return is_border(halfedge(e, 0)) || is_border(halfedge(e, 1));
  }
  /// v is isolated or incident to a border halfedge. With check_all = false,
  /// only halfedge(v) is looked at (O(1) if border vertices keep a border
  /// halfedge, as Surface_mesh's flag does).
  [[nodiscard]] bool is_border(Vertex_index v, bool check_all = true) const {
    const Halfedge_index start = halfedge(v);
    if (!start.is_valid()) return true;
    if (!check_all) return is_border(start);
    Halfedge_index h = start;
    do {
      if (is_border(h)) return true;
      h = next_around_target(h);
    } while (h != start);
    return false;
  }
  [[nodiscard]] bool is_isolated(Vertex_index v) const { return !halfedge(v).is_valid(); }

  /// Number of halfedges targeting v (0 if isolated).
  [[nodiscard]] size_type degree(Vertex_index v) const {
    const Halfedge_index start = halfedge(v);
    if (!start.is_valid()) return 0;
    size_type n = 0;
    Halfedge_index h = start;
    do {
      ++n;
      h = next_around_target(h);
    } while (h != start);
    return n;
  }
  /// Number of halfedges around f (0 if f has no halfedge).
  [[nodiscard]] size_type degree(Face_index f) const {
    const Halfedge_index start = halfedge(f);
    if (!start.is_valid()) return 0;
    size_type n = 0;
    Halfedge_index h = start;
    do {
      ++n;
      h = next(h);
    } while (h != start);
    return n;
  }

  // ---- adding and removing ------------------------------------------------

  /// A new isolated vertex (recycled if possible); its properties have their defaults.
  Vertex_index add_vertex() {
    if (recycle_ && vertices_freelist_ != invalid) [[unlikely]]
      return recycle_vertex();
    check_room(vhalfedge_.size());
    vhalfedge_.push_back(Halfedge_index());
    vremoved_.push_back(false);
    vprops_.push_back();
    return Vertex_index(static_cast<std::uint32_t>(vhalfedge_.size() - 1));
  }

  /// A new edge (recycled if possible) with null connectivity; returns its
  /// halfedge 0 (2e).
  Halfedge_index add_edge() {
    if (recycle_ && edges_freelist_ != invalid) [[unlikely]]
      return recycle_edge();
    check_room(hlinks_.size() + 1);
    const auto h = static_cast<std::uint32_t>(hlinks_.push_back_pair());
    hprops_.push_back();
    hprops_.push_back();
    eremoved_.push_back(false);
    eprops_.push_back();
    return Halfedge_index(h);
  }

  /// A new edge from v0 to v1: returns the halfedge targeting v1 (its opposite
  /// targets v0). halfedge(v0)/halfedge(v1) are not changed.
  Halfedge_index add_edge(Vertex_index v0, Vertex_index v1) {
    const Halfedge_index h = add_edge();
    set_target(h, v1);
    set_target(opposite(h), v0);
    return h;
  }

  /// A new face (recycled if possible) with no halfedge.
  Face_index add_face() {
    if (recycle_ && faces_freelist_ != invalid) [[unlikely]]
      return recycle_face();
    check_room(fhalfedge_.size());
    fhalfedge_.push_back(Halfedge_index());
    fremoved_.push_back(false);
    fprops_.push_back();
    return Face_index(static_cast<std::uint32_t>(fhalfedge_.size() - 1));
  }

  /// Marks v removed and frees its index; adjusts nothing else. Removing an
  /// element twice is a precondition violation (asserted in debug builds).
  void remove_vertex(Vertex_index v) {
    assert(!vremoved_[v.idx()] && "removed twice");
    vremoved_[v.idx()] = true;
    ++removed_vertices_;
    garbage_ = true;
    vhalfedge_[v.idx()] = Halfedge_index(vertices_freelist_);
    vertices_freelist_ = v.idx();
  }
  /// Marks e (both halfedges) removed and frees its index; adjusts nothing else.
  void remove_edge(Edge_index e) {
    assert(!eremoved_[e.idx()] && "removed twice");
    eremoved_[e.idx()] = true;
    ++removed_edges_;
    garbage_ = true;
    hlinks_.next(e.idx() << 1) = Halfedge_index(edges_freelist_);
    edges_freelist_ = e.idx() << 1;
  }
  /// Marks f removed and frees its index; adjusts nothing else.
  void remove_face(Face_index f) {
    assert(!fremoved_[f.idx()] && "removed twice");
    fremoved_[f.idx()] = true;
    ++removed_faces_;
    garbage_ = true;
    fhalfedge_[f.idx()] = Halfedge_index(faces_freelist_);
    faces_freelist_ = f.idx();
  }

  /// Some element was removed since the last collect_garbage() (stays true
  /// when removed indices were recycled, as in Surface_mesh).
  [[nodiscard]] bool has_garbage() const { return garbage_; }
  /// Whether add_* reuses removed indices (default true).
  void set_recycle_garbage(bool b) { recycle_ = b; }
  [[nodiscard]] bool does_recycle_garbage() const { return recycle_; }

  /// Drops removed elements, updates connectivity and compacts every
  /// property; returns the old -> new maps (identity if there was no
  /// garbage). Links to removed elements become null. Shrinks storage to fit,
  /// as Surface_mesh does. With Garbage_order::stable (the default) survivors
  /// keep their relative order; with Garbage_order::like_surface_mesh they are
  /// renumbered exactly as CGAL::Surface_mesh::collect_garbage() does (the
  /// last live element fills the first hole, repeatedly).
  Garbage_collection_maps collect_garbage(Garbage_order order = Garbage_order::stable) {
    const std::uint32_t nv = static_cast<std::uint32_t>(vertices_size());
    const std::uint32_t ne = static_cast<std::uint32_t>(edges_size());
    const std::uint32_t nf = static_cast<std::uint32_t>(faces_size());
    const std::vector<std::uint32_t> vmap = detail::compaction_map(vremoved_, order);
    const std::vector<std::uint32_t> emap = detail::compaction_map(eremoved_, order);
    const std::vector<std::uint32_t> fmap = detail::compaction_map(fremoved_, order);
    const std::vector<std::uint32_t> hmap = detail::halfedge_compaction_map(emap);
    auto kept = [](const std::vector<std::uint32_t>& map) {
      return static_cast<std::uint32_t>(std::ranges::count_if(map, [](std::uint32_t i) { return i != invalid; }));
    };
    const std::uint32_t kv = kept(vmap), ke = kept(emap), kf = kept(fmap);

    if (garbage_) {
      auto map_h = [&](Halfedge_index h) {
        return h.is_valid() && h.idx() < hmap.size() ? Halfedge_index(hmap[h.idx()]) : Halfedge_index();
      };
      auto map_v = [&](Vertex_index v) {
        return v.is_valid() && v.idx() < nv ? Vertex_index(vmap[v.idx()]) : Vertex_index();
      };
      auto map_f = [&](Face_index f) {
        return f.is_valid() && f.idx() < nf ? Face_index(fmap[f.idx()]) : Face_index();
      };
      // Every destination is the source itself or a removed slot (whose old
      // content is never read), so moving in place in any order is safe.
      for (std::uint32_t i = 0; i < nv; ++i)
        if (vmap[i] != invalid) vhalfedge_[vmap[i]] = map_h(vhalfedge_[i]);
      for (std::uint32_t i = 0; i < 2 * ne; ++i) {
        if (hmap[i] == invalid) continue;
        const std::uint32_t j = hmap[i];
        hlinks_.next(j) = map_h(hlinks_.next(i));
        hlinks_.prev(j) = map_h(hlinks_.prev(i));
        hlinks_.target(j) = map_v(hlinks_.target(i));
        hlinks_.face(j) = map_f(hlinks_.face(i));
      }
      for (std::uint32_t i = 0; i < nf; ++i)
        if (fmap[i] != invalid) fhalfedge_[fmap[i]] = map_h(fhalfedge_[i]);

      vhalfedge_.resize(kv);
      hlinks_.resize(2 * std::size_t(ke));
      fhalfedge_.resize(kf);
      vremoved_.assign(kv, false);
      eremoved_.assign(ke, false);
      fremoved_.assign(kf, false);
      vprops_.compact(vmap, kv);
      hprops_.compact(hmap, 2 * std::size_t(ke));
      eprops_.compact(emap, ke);
      fprops_.compact(fmap, kf);
      shrink_to_fit();

      removed_vertices_ = removed_edges_ = removed_faces_ = 0;
      vertices_freelist_ = edges_freelist_ = faces_freelist_ = invalid;
      garbage_ = false;
    }

    Garbage_collection_maps maps;
    maps.vertices.reserve(nv);
    for (auto i : vmap) maps.vertices.emplace_back(i);
    maps.halfedges.reserve(hmap.size());
    for (auto i : hmap) maps.halfedges.emplace_back(i);
    maps.edges.reserve(ne);
    for (auto i : emap) maps.edges.emplace_back(i);
    maps.faces.reserve(nf);
    for (auto i : fmap) maps.faces.emplace_back(i);
    return maps;
  }

  /// Renumbers the live elements in any order: vertex i becomes vmap[i],
  /// edge i emap[i], face i fmap[i] (removed elements: the null index).
  /// Each map must send the live elements one to one onto [0, live count)
  /// (checked: throws invalid_input, the mesh unchanged). Halfedges follow
  /// their edge with their orientation (2i -> 2 emap[i], 2i + 1 -> 2 emap[i] + 1);
  /// connectivity and every property follow; the garbage is gone afterwards.
  /// genmesh::renumber (<genmesh/renumbering.h>) calls it.
  void renumber(std::span<const std::uint32_t> vmap, std::span<const std::uint32_t> emap,
                std::span<const std::uint32_t> fmap) {
    const std::uint32_t kv = static_cast<std::uint32_t>(n_vertices()), ke = static_cast<std::uint32_t>(n_edges()),
                        kf = static_cast<std::uint32_t>(n_faces());
    // In place, along the permutations' cycles (no second copy of the
    // mesh): the removed elements' slots move behind the live ones and are
    // cut off; capacities stay, so a mesh that grows again (remeshing's
    // splits) does not reallocate at once.
    const std::size_t nv = vmap.size(), ne = emap.size(), nf = fmap.size();
    const std::vector<std::uint32_t> vp = detail::full_permutation(vmap, vertices_size(), &vremoved_),
                                     ep = detail::full_permutation(emap, edges_size(), &eremoved_),
                                     fp = detail::full_permutation(fmap, faces_size(), &fremoved_);
    if (nv != vertices_size() || ne != edges_size() || nf != faces_size() || vp.size() != nv || ep.size() != ne ||
        fp.size() != nf)
      throw invalid_input("Halfedge_mesh::renumber: a map is not one to one from the live elements onto [0, live count)");
    auto map_h = [&](Halfedge_index h) {
      return h.is_valid() && h.idx() < 2 * ne ? Halfedge_index(2 * ep[h.idx() >> 1] | (h.idx() & 1u)) : Halfedge_index();
    };
    auto map_v = [&](Vertex_index v) { return v.is_valid() && v.idx() < nv ? Vertex_index(vp[v.idx()]) : Vertex_index(); };
    auto map_f = [&](Face_index f) { return f.is_valid() && f.idx() < nf ? Face_index(fp[f.idx()]) : Face_index(); };
    for (auto& h : vhalfedge_) h = map_h(h);
    for (auto& h : fhalfedge_) h = map_h(h);
    for (std::size_t i = 0; i < 2 * ne; ++i) {
      hlinks_.next(i) = map_h(hlinks_.next(i));
      hlinks_.prev(i) = map_h(hlinks_.prev(i));
      hlinks_.target(i) = map_v(hlinks_.target(i));
      hlinks_.face(i) = map_f(hlinks_.face(i));
    }
    detail::permute_in_place(vp, [&](std::size_t i, std::size_t j) { std::swap(vhalfedge_[i], vhalfedge_[j]); });
    detail::permute_in_place(fp, [&](std::size_t i, std::size_t j) { std::swap(fhalfedge_[i], fhalfedge_[j]); });
    detail::permute_in_place(ep, [&](std::size_t i, std::size_t j) {
      for (std::size_t s = 0; s < 2; ++s) {
        const std::size_t a = 2 * i + s, b = 2 * j + s;
        std::swap(hlinks_.next(a), hlinks_.next(b));
        std::swap(hlinks_.prev(a), hlinks_.prev(b));
        std::swap(hlinks_.target(a), hlinks_.target(b));
        std::swap(hlinks_.face(a), hlinks_.face(b));
      }
    });
    std::vector<std::uint32_t> hp;
    if (hprops_.n_properties() != 0) {
      hp.resize(2 * ne);
      for (std::size_t e = 0; e < ne; ++e) hp[2 * e] = 2 * ep[e], hp[2 * e + 1] = 2 * ep[e] + 1;
    }
    vhalfedge_.resize(kv);
    fhalfedge_.resize(kf);
    hlinks_.resize(2 * std::size_t(ke));
    vremoved_.assign(kv, false);
    eremoved_.assign(ke, false);
    fremoved_.assign(kf, false);
    vprops_.permute(vp, kv);
    if (hp.empty()) hprops_.resize(2 * std::size_t(ke));
    else hprops_.permute(hp, 2 * std::size_t(ke));
    eprops_.permute(ep, ke);
    fprops_.permute(fp, kf);
    removed_vertices_ = removed_edges_ = removed_faces_ = 0;
    vertices_freelist_ = edges_freelist_ = faces_freelist_ = invalid;
    garbage_ = false;
  }

  /// Capacity for nv vertices, ne edges (2 ne halfedges) and nf faces, in
  /// connectivity and every property.
  void reserve(size_type nv, size_type ne, size_type nf) {
    vhalfedge_.reserve(nv);
    vremoved_.reserve(nv);
    vprops_.reserve(nv);
    hlinks_.reserve(2 * ne);
    hprops_.reserve(2 * ne);
    eremoved_.reserve(ne);
    eprops_.reserve(ne);
    fhalfedge_.reserve(nf);
    fremoved_.reserve(nf);
    fprops_.reserve(nf);
  }

  /// Releases unused capacity of every array.
  void shrink_to_fit() {
    vhalfedge_.shrink_to_fit();
    hlinks_.shrink_to_fit();
    fhalfedge_.shrink_to_fit();
    vremoved_.shrink_to_fit();
    eremoved_.shrink_to_fit();
    fremoved_.shrink_to_fit();
    vprops_.shrink_to_fit();
    hprops_.shrink_to_fit();
    eprops_.shrink_to_fit();
    fprops_.shrink_to_fit();
  }

  /// Bytes held by all arrays (capacities: connectivity, removed bits, every
  /// property including the points); excludes the fixed-size object itself.
  [[nodiscard]] size_type memory_bytes() const {
    auto bits = [](const std::vector<bool>& b) { return (b.capacity() + 7) / 8; };
    return sizeof(Halfedge_index) * (vhalfedge_.capacity() + 2 * hlinks_.capacity() + fhalfedge_.capacity()) +
           (sizeof(Vertex_index) + sizeof(Face_index)) * hlinks_.capacity() +
           bits(vremoved_) + bits(eremoved_) + bits(fremoved_) + vprops_.memory_bytes() +
           hprops_.memory_bytes() + eprops_.memory_bytes() + fprops_.memory_bytes();
  }

  // ---- ranges -------------------------------------------------------------

  /// Live vertices by increasing index (also halfedges(), edges(), faces()).
  [[nodiscard]] Range<Vertex_iterator> vertices() const {
    return detail::live_range<Vertex_iterator>(vertices_size(), n_vertices(), vremoved_, garbage_);
  }
  [[nodiscard]] Range<Halfedge_iterator> halfedges() const {
    return detail::live_range<Halfedge_iterator>(halfedges_size(), n_halfedges(), eremoved_, garbage_);
  }
  [[nodiscard]] Range<Edge_iterator> edges() const {
    return detail::live_range<Edge_iterator>(edges_size(), n_edges(), eremoved_, garbage_);
  }
  [[nodiscard]] Range<Face_iterator> faces() const {
    return detail::live_range<Face_iterator>(faces_size(), n_faces(), fremoved_, garbage_);
  }

  /// h, next(h), next(next(h)), ... once around the cycle (empty for null h).
  [[nodiscard]] Range<Halfedge_around_face_iterator> halfedges_around_face(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Halfedge_around_face_iterator> halfedges_around_face(Face_index f) const {
    return halfedges_around_face(halfedge(f));
  }
  /// target of each halfedge of halfedges_around_face(h).
  [[nodiscard]] Range<Vertex_around_face_iterator> vertices_around_face(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Vertex_around_face_iterator> vertices_around_face(Face_index f) const {
    return vertices_around_face(halfedge(f));
  }
  /// h, opposite(next(h)), ...: every halfedge targeting target(h), clockwise.
  [[nodiscard]] Range<Halfedge_around_target_iterator> halfedges_around_target(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Halfedge_around_target_iterator> halfedges_around_target(Vertex_index v) const {
    return halfedges_around_target(halfedge(v));
  }
  /// source of each halfedge of halfedges_around_target(h): the neighbours.
  [[nodiscard]] Range<Vertex_around_target_iterator> vertices_around_target(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Vertex_around_target_iterator> vertices_around_target(Vertex_index v) const {
    return vertices_around_target(halfedge(v));
  }
  /// face of each halfedge of halfedges_around_target(h). As in CGAL, border
  /// halfedges give null_face() (not skipped), and a face may repeat on a
  /// non-manifold configuration.
  [[nodiscard]] Range<Face_around_target_iterator> faces_around_target(Halfedge_index h) const {
    return {{this, h, 0}, {this, h, 1}};
  }
  [[nodiscard]] Range<Face_around_target_iterator> faces_around_target(Vertex_index v) const {
    return faces_around_target(halfedge(v));
  }
  /// The sources of the halfedges around v (Boost adjacent_vertices).
  [[nodiscard]] Range<Vertex_around_target_iterator> adjacent_vertices(Vertex_index v) const {
    return vertices_around_target(v);
  }
  /// The edges targeting v, each oriented towards v (Boost in_edges).
  [[nodiscard]] Range<In_edge_iterator> in_edges(Vertex_index v) const {
    return {{this, halfedge(v), 0}, {this, halfedge(v), 1}};
  }
  /// The edges leaving v, each oriented away from v (Boost out_edges).
  [[nodiscard]] Range<Out_edge_iterator> out_edges(Vertex_index v) const {
    return {{this, halfedge(v), 0}, {this, halfedge(v), 1}};
  }

protected:
  static constexpr std::uint32_t invalid = Vertex_index::invalid_value;

  Halfedge_connectivity() = default;

  /// Back to empty, every property removed (the derived mesh re-adds points).
  void clear_connectivity() {
    *this = Halfedge_connectivity();
  }

  friend struct detail::Halfedge_mesh_bulk; // bulk growth (detail/halfedge/bulk.h)

  static void check_room(std::size_t size) {
    // Two indices per edge must stay below the null value.
    if (size + 2 >= std::size_t(invalid)) [[unlikely]]
      too_many();
  }
  [[noreturn]] static void too_many() { throw invalid_input("Halfedge_mesh: more than 2^32-2 elements"); }

  // The recycling halves of add_vertex/add_edge/add_face, kept out of the
  // appending path so that it stays small enough to inline.
  Vertex_index recycle_vertex() {
    const std::uint32_t i = vertices_freelist_;
    vertices_freelist_ = vhalfedge_[i].idx();
    --removed_vertices_;
    vremoved_[i] = false;
    vhalfedge_[i] = Halfedge_index();
    vprops_.reset(i);
    return Vertex_index(i);
  }
  Halfedge_index recycle_edge() {
    const std::uint32_t h = edges_freelist_;
    edges_freelist_ = hlinks_.next(h).idx();
    --removed_edges_;
    eremoved_[h >> 1] = false;
    for (std::uint32_t k : {h, h ^ 1u}) {
      hlinks_.next(k) = hlinks_.prev(k) = Halfedge_index();
      hlinks_.target(k) = Vertex_index();
      hlinks_.face(k) = Face_index();
      hprops_.reset(k);
    }
    eprops_.reset(h >> 1);
    return Halfedge_index(h);
  }
  Face_index recycle_face() {
    const std::uint32_t i = faces_freelist_;
    faces_freelist_ = fhalfedge_[i].idx();
    --removed_faces_;
    fremoved_[i] = false;
    fhalfedge_[i] = Halfedge_index();
    fprops_.reset(i);
    return Face_index(i);
  }

  detail::Halfedge_links hlinks_;
  detail::huge_page_vector<Halfedge_index> vhalfedge_; // big ones on huge pages (memory/huge_pages.h)
  detail::huge_page_vector<Halfedge_index> fhalfedge_;
  std::vector<bool> vremoved_, eremoved_, fremoved_;
  std::size_t removed_vertices_ = 0, removed_edges_ = 0, removed_faces_ = 0;
  std::uint32_t vertices_freelist_ = invalid, edges_freelist_ = invalid, faces_freelist_ = invalid;
  bool garbage_ = false;
  bool recycle_ = true;
};


// ---------------------------------------------------------------------------
// Halfedge_mesh<Point>
// ---------------------------------------------------------------------------

/// genmesh's own halfedge mesh; see the top of this header for the layout and
/// the guarantees. Point is any copyable type (Eigen::Vector3d by default);
/// genmesh algorithms need Point_traits<Point> (point_traits.h), CGAL's need
/// a CGAL point (Halfedge_mesh<K::Point_3>, see <genmesh/adaptors/cgal.h>).
///
/// Copies are deep (properties included). A property handle belongs to the
/// mesh it came from: after a copy, look the property up by name in the copy.
/// Handles give mutable access even when obtained from a const mesh, as in
/// CGAL and pmp.
template <class P = Eigen::Vector3d>
class Halfedge_mesh : public Halfedge_connectivity {
public:
  using Point = P;

  Halfedge_mesh() { points_ = vprops_.add<P>("v:point", detail::default_point<P>()); }
  Halfedge_mesh(const Halfedge_mesh& o) : Halfedge_connectivity(o) { rebind_points(); }
  Halfedge_mesh(Halfedge_mesh&& o) noexcept : Halfedge_connectivity(std::move(o)), points_(o.points_) {
    o.reset_after_move();
  }
  Halfedge_mesh& operator=(const Halfedge_mesh& o) {
    if (this != &o) {
      Halfedge_connectivity::operator=(o);
      rebind_points();
    }
    return *this;
  }
  Halfedge_mesh& operator=(Halfedge_mesh&& o) noexcept {
    if (this != &o) {
      Halfedge_connectivity::operator=(std::move(o));
      points_ = o.points_;
      o.reset_after_move();
    }
    return *this;
  }
  ~Halfedge_mesh() = default;

  using Halfedge_connectivity::add_vertex;
  /// A new isolated vertex at p.
  Vertex_index add_vertex(const Point& p) {
    const Vertex_index v = add_vertex();
    points_[v] = p;
    return v;
  }

  Point& point(Vertex_index v) { return points_[v]; }
  const Point& point(Vertex_index v) const { return points_[v]; }
  /// The positions, as a vertex property (a boost lvalue property map).
  [[nodiscard]] Vertex_property<Point> points() const { return points_; }
  /// The positions as one array by vertex index (removed vertices' slots
  /// included), valid until a vertex is added or the garbage is collected.
  [[nodiscard]] std::span<const Point> point_array() const {
    const auto& a = points_.array().storage();
    return {a.data(), a.size()};
  }

  /// Back to a new, empty mesh: every element and every property but the
  /// positions is gone; recycling is on again.
  void clear() {
    clear_connectivity();
    points_ = vprops_.add<P>("v:point", detail::default_point<P>());
  }

private:
  void rebind_points() { points_ = *vprops_.template get<P>("v:point"); }
  void reset_after_move() {
    clear_connectivity();
    points_ = vprops_.add<P>("v:point", detail::default_point<P>());
  }

  Vertex_property<Point> points_;
};

// get(vertex_point_t / *_index_t, m) and index_bound(tag, m): see
// <genmesh/detail/elements/mesh_functions.h>; Index_map: <genmesh/elements.h>;
// Scoped_vertex_property & co.: <genmesh/mesh_properties.h>.

} // namespace genmesh

#include <genmesh/detail/elements/mesh_functions.h>

// ---------------------------------------------------------------------------
// boost::graph_traits (choices copied from CGAL's Surface_mesh traits; the
// part every genmesh mesh shares: detail::Mesh_graph_traits)
// ---------------------------------------------------------------------------

namespace boost {

template <class P>
struct graph_traits<genmesh::Halfedge_mesh<P>> : genmesh::detail::Mesh_graph_traits<P> {
  using in_edge_iterator = genmesh::In_edge_iterator;
  using out_edge_iterator = genmesh::Out_edge_iterator;
  using adjacency_iterator = genmesh::Vertex_around_target_iterator;
};

template <class P>
struct graph_traits<const genmesh::Halfedge_mesh<P>> : graph_traits<genmesh::Halfedge_mesh<P>> {};

} // namespace boost

// ---------------------------------------------------------------------------
// CGAL BGL free functions (found by ADL through Halfedge_mesh)
// ---------------------------------------------------------------------------

namespace genmesh {

namespace detail {
template <>
inline constexpr bool is_genmesh_mesh<Halfedge_mesh> = true;
} // namespace detail

// What only Halfedge_mesh has; the rest: <genmesh/detail/elements/mesh_functions.h>.

// MutableHalfedgeGraph
template <class P>
void set_target(Halfedge_index h, Vertex_index v, Halfedge_mesh<P>& m) {
  m.set_target(h, v);
}
template <class P>
void set_next(Halfedge_index h, Halfedge_index nh, Halfedge_mesh<P>& m) {
  m.set_next(h, nh);
}
template <class P>
void set_halfedge(Vertex_index v, Halfedge_index h, Halfedge_mesh<P>& m) {
  m.set_halfedge(v, h);
}
/// A new edge; returns it as an edge (its halfedges are halfedge(e, 0/1)).
template <class P>
Edge_index add_edge(Halfedge_mesh<P>& m) {
  return m.edge(m.add_edge());
}

// MutableFaceGraph
template <class P>
void set_face(Halfedge_index h, Face_index f, Halfedge_mesh<P>& m) {
  m.set_face(h, f);
}
template <class P>
void set_halfedge(Face_index f, Halfedge_index h, Halfedge_mesh<P>& m) {
  m.set_halfedge(f, h);
}

// Cache hints (genmesh::detail::prefetch_links, <genmesh/property_maps.h>).
template <class P>
void genmesh_native_prefetch_links(Halfedge_index h, const Halfedge_mesh<P>& m) {
  m.prefetch(h);
}
template <class P>
void genmesh_native_prefetch_links(Vertex_index v, const Halfedge_mesh<P>& m) {
  m.prefetch(v);
}

// The claims of this header, checked where it is compiled.
static_assert(HalfedgeListGraph<Halfedge_mesh<>> && VertexListGraph<Halfedge_mesh<>> &&
              EdgeListGraph<Halfedge_mesh<>> && FaceListGraph<Halfedge_mesh<>> &&
              MutableFaceGraph<Halfedge_mesh<>>);
static_assert(HasVertexPoints<Halfedge_mesh<>> && HasIndexMap<Halfedge_mesh<>, vertex_index_t> &&
              HasIndexMap<Halfedge_mesh<>, halfedge_index_t> && HasIndexMap<Halfedge_mesh<>, edge_index_t> &&
              HasIndexMap<Halfedge_mesh<>, face_index_t>);

} // namespace genmesh

#include <genmesh/detail/halfedge/bulk.h>
