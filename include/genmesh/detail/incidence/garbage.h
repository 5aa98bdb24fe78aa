// genmesh/detail/incidence/garbage.h — Incidence_mesh::collect_garbage().
// Included by <genmesh/incidence_mesh.h>; not for direct use.
//
// The survivors are renumbered by detail::compaction_map(), the function
// Halfedge_mesh::collect_garbage() uses, so both meshes give the same maps;
// the rows are then rebuilt compact through assign_incidences() (the bulk
// path of load_soup and build_mesh), which also recomputes the derived
// helpers (turn records, border counts). O(V + E + F + non-zeros).
#pragma once

#include <genmesh/incidence_mesh.h>

namespace genmesh {

template <class P>
Garbage_collection_maps Incidence_mesh<P>::collect_garbage(Garbage_order order) {
  const std::vector<std::uint32_t> vmap = detail::compaction_map(vremoved_, order);
  const std::vector<std::uint32_t> emap = detail::compaction_map(eremoved_, order);
  const std::vector<std::uint32_t> fmap = detail::compaction_map(fremoved_, order);
  const std::vector<std::uint32_t> hmap = detail::halfedge_compaction_map(emap);

  if (garbage_) reassemble_(vmap, emap, hmap, fmap, false);

  Garbage_collection_maps maps;
  maps.vertices.reserve(vmap.size());
  for (const auto i : vmap) maps.vertices.emplace_back(i);
  maps.halfedges.reserve(hmap.size());
  for (const auto i : hmap) maps.halfedges.emplace_back(i);
  maps.edges.reserve(emap.size());
  for (const auto i : emap) maps.edges.emplace_back(i);
  maps.faces.reserve(fmap.size());
  for (const auto i : fmap) maps.faces.emplace_back(i);
  return maps;
}

template <class P>
void Incidence_mesh<P>::reassemble_(std::span<const std::uint32_t> vmap, std::span<const std::uint32_t> emap,
                                    std::span<const std::uint32_t> hmap, std::span<const std::uint32_t> fmap,
                                    bool any_order) {
  constexpr std::uint32_t null = Vertex_index::invalid_value;
  // New -> old, to gather the survivors in their new order.
  auto inverse = [](std::span<const std::uint32_t> map, std::size_t kept) {
    std::vector<std::uint32_t> old(kept);
    for (std::size_t i = 0; i < map.size(); ++i)
      if (map[i] != null) old[map[i]] = static_cast<std::uint32_t>(i);
    return old;
  };
  const std::vector<std::uint32_t> vold = inverse(vmap, n_vertices());
  const std::vector<std::uint32_t> eold = inverse(emap, n_edges());
  const std::vector<std::uint32_t> fold = inverse(fmap, n_faces());

  // assign_incidences() takes each edge as (source, target): refuse, before
  // changing anything, a live edge whose ends were never set.
  std::vector<std::uint32_t> ends(2 * eold.size());
  for (std::size_t j = 0; j < eold.size(); ++j) {
    const Vertex_index s = source(halfedge(Edge_index(eold[j]))), t = target(halfedge(Edge_index(eold[j])));
    if (!s.is_valid() || !t.is_valid())
      throw invalid_input("Incidence_mesh::collect_garbage: edge " + std::to_string(eold[j]) +
                          " has no two ends (set them with set_edge_vertices first)");
    ends[2 * j] = vmap[s.idx()];
    ends[2 * j + 1] = vmap[t.idx()];
  }
  std::vector<std::uint32_t> offsets(fold.size() + 1, 0);
  std::vector<std::uint32_t> corner_edge;
  std::vector<signed char> corner_sign;
  corner_edge.reserve(static_cast<std::size_t>(d1_.matrix().nonZeros()));
  corner_sign.reserve(corner_edge.capacity());
  for (std::size_t j = 0; j < fold.size(); ++j) {
    const std::uint32_t f = fold[j];
    for (int k = 0; k < d1_.size(f); ++k) {
      corner_edge.push_back(emap[static_cast<std::size_t>(d1_.cols(f)[k])]);
      corner_sign.push_back(d1_.vals(f)[k]);
    }
    offsets[j + 1] = static_cast<std::uint32_t>(corner_edge.size());
  }
  std::vector<P> pts;
  pts.reserve(vold.size());
  for (const std::uint32_t v : vold) pts.push_back(points_[v]);

  // The properties move with their elements (assign_incidences keeps them).
  if (any_order) {
    vprops_.permute(detail::full_permutation(vmap, vmap.size()), vold.size());
    hprops_.permute(detail::full_permutation(hmap, hmap.size()), 2 * eold.size());
    eprops_.permute(detail::full_permutation(emap, emap.size()), eold.size());
    fprops_.permute(detail::full_permutation(fmap, fmap.size()), fold.size());
  } else {
    vprops_.compact(vmap, vold.size());
    hprops_.compact(hmap, 2 * eold.size());
    eprops_.compact(emap, eold.size());
    fprops_.compact(fmap, fold.size());
  }

  const bool recycle = recycle_;
  assign_incidences(pts, ends, offsets, corner_edge, corner_sign);
  recycle_ = recycle;
  update_manifold_flags_();
}

template <class P>
void Incidence_mesh<P>::renumber(std::span<const std::uint32_t> vmap, std::span<const std::uint32_t> emap,
                                 std::span<const std::uint32_t> fmap) {
  if (vmap.size() != vertices_size() || emap.size() != edges_size() || fmap.size() != faces_size() ||
      detail::full_permutation(vmap, vmap.size(), &vremoved_).empty() != vmap.empty() ||
      detail::full_permutation(emap, emap.size(), &eremoved_).empty() != emap.empty() ||
      detail::full_permutation(fmap, fmap.size(), &fremoved_).empty() != fmap.empty())
    throw invalid_input("Incidence_mesh::renumber: a map is not one to one from the live elements onto [0, live count)");
  reassemble_(vmap, emap, detail::halfedge_compaction_map(std::vector<std::uint32_t>(emap.begin(), emap.end())), fmap,
              true);
}

} // namespace genmesh
