// genmesh/remeshing/collapse_short_edges.h — one step of isotropic remeshing, usable alone
// (<genmesh/remeshing.h>), with the same options and refusals.
#pragma once

#include <genmesh/remeshing/detail/remesher.h>

namespace genmesh {

/// Collapses edges shorter than 4/5 L (shortest first) where the link condition holds, no edge
/// longer than 4/3 L appears and no triangle turns over; the lower-valence end disappears. A vertex
/// on a constrained edge only moves along it (Constraints::resample); corners stay. Returns the
/// number of collapses.
/// Throws genmesh::invalid_input (g unchanged) on the refusals of
/// isotropic_remeshing.
template <detail::remeshing::Remeshable G>
std::size_t collapse_short_edges(G& g, const Remeshing_options& options = {}) {
  detail::remeshing::Remesher<G> r(g, options, "collapse_short_edges");
  return r.collapse_short_edges();
}

} // namespace genmesh
