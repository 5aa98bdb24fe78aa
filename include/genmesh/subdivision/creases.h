// genmesh/subdivision/creases.h — crease and corner maps for Loop and
// Catmull-Clark subdivision (.crease_map, .corner_map), from vertex pairs.
//
// The schemes read sharpness per edge through a property map and write the
// refined mesh's back into it; files and users name creases by their end
// vertices. make_crease_map(g) / make_corner_map(g) give scratch properties
// of g (<genmesh/properties.h>): in g's own property system where it has one
// (genmesh's meshes, Surface_mesh; a vector over g's index map otherwise),
// growing with the elements a subdivision adds, removed with their last
// copy. crease_map(g, creases) fills one from vertex pairs, vertices
// numbered in vertex iteration order (the numbering of to_soup() and of the
// file the mesh was read from).
#pragma once

#include <genmesh/properties.h>
#include <genmesh/subdivision/detail/refinement.h>

#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace genmesh {

/// A crease edge named by its end vertices (vertex iteration order numbers).
struct Crease {
  std::uint32_t a = 0, b = 0;
  double sharpness = 0; ///< 0 smooth, infinity sharp, fractional semi-sharp
};

/// The sharpness of every edge in edge iteration order. Throws
/// genmesh::invalid_input naming the crease when its vertices are out of
/// range or not joined by an edge, or its sharpness is negative or NaN.
template <class G>
  requires detail::subdivision::Subdividable<G>
std::vector<double> crease_sharpness(const G& g, std::span<const Crease> creases) {
  auto vi = get(vertex_index, g);
  std::vector<std::uint32_t> number(index_bound(vertex_index, g), detail::subdivision::k_none);
  std::uint32_t n = 0;
  for (auto v : vertices(g)) number[static_cast<std::size_t>(get(vi, v))] = n++;
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
  };
  std::unordered_map<std::uint64_t, std::size_t> edge_of;
  edge_of.reserve(creases.size());
  for (const Crease& c : creases) edge_of.emplace(key(c.a, c.b), SIZE_MAX);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(num_edges(g)));
  for (auto e : edges(g)) {
    auto h = halfedge(e, g);
    auto it = edge_of.find(key(number[static_cast<std::size_t>(get(vi, source(h, g)))],
                               number[static_cast<std::size_t>(get(vi, target(h, g)))]));
    if (it != edge_of.end()) it->second = out.size();
    out.push_back(0.0);
  }
  for (std::size_t i = 0; i < creases.size(); ++i) {
    const Crease& c = creases[i];
    const std::size_t e = edge_of.at(key(c.a, c.b));
    if (!(c.sharpness >= 0))
      throw invalid_input("crease_sharpness: crease " + std::to_string(i) + " has a negative or NaN sharpness");
    if (e == SIZE_MAX)
      throw invalid_input("crease_sharpness: crease " + std::to_string(i) + " (" + std::to_string(c.a) + ", " +
                          std::to_string(c.b) + ") is not an edge of the mesh");
    out[e] = c.sharpness;
  }
  return out;
}

/// An edge → sharpness map of g for .crease_map, every edge 0 (smooth): a
/// scratch property of g, so it grows with the edges added later (on a
/// const g, the generic storage of <genmesh/properties.h>).
template <class G>
  requires detail::subdivision::Subdividable<std::remove_const_t<G>>
auto make_crease_map(G& g) {
  return scratch_property(edge_index, g, 0.0);
}

/// A vertex → bool map of g for .corner_map, no vertex tagged (a byte per
/// vertex, converted to bool); a scratch property of g, as make_crease_map.
template <class G>
  requires detail::subdivision::Subdividable<std::remove_const_t<G>>
auto make_corner_map(G& g) {
  return scratch_property(vertex_index, g, static_cast<unsigned char>(0));
}

/// make_crease_map(g) holding the creases named by their end vertices.
/// Throws as crease_sharpness().
template <class G>
  requires detail::subdivision::Subdividable<std::remove_const_t<G>>
auto crease_map(G& g, std::span<const Crease> creases) {
  const std::vector<double> sharp = crease_sharpness(g, creases);
  auto m = make_crease_map(g);
  std::size_t k = 0;
  for (auto e : edges(g)) put(m, e, sharp[k++]);
  return m;
}

} // namespace genmesh
