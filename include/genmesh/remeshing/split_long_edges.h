// genmesh/remeshing/split_long_edges.h — one step of isotropic remeshing, usable alone
// (<genmesh/remeshing.h>), with the same options and refusals.
#pragma once

#include <genmesh/remeshing/detail/remesher.h>

namespace genmesh {

/// Splits every edge longer than 4/3 L at its midpoint (longest first), joining the new vertex to
/// the opposite corners. Constrained edges only with Constraints::resample. Returns the number of
/// splits.
/// Throws genmesh::invalid_input (g unchanged) on the refusals of
/// isotropic_remeshing.
template <detail::remeshing::Remeshable G>
std::size_t split_long_edges(G& g, const Remeshing_options& options = {}) {
  detail::remeshing::Remesher<G> r(g, options, "split_long_edges");
  return r.split_long_edges();
}

} // namespace genmesh
