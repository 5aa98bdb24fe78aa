// genmesh/remeshing/tangential_relaxation.h — one step of isotropic remeshing, usable alone
// (<genmesh/remeshing.h>), with the same options and refusals.
#pragma once

#include <genmesh/remeshing/detail/remesher.h>

namespace genmesh {

/// Moves every free vertex (not on a constrained edge, not fixed) options.smoothing_steps times
/// towards the area-weighted centroid of its triangles (Smoothing::uniform: the mean of its
/// neighbours), within its tangent plane, by options.smoothing_step_size of the way; all vertices
/// move at once (Jacobi). Then projects them onto the input when options.projection. Returns the
/// number of vertices moved.
/// Throws genmesh::invalid_input (g unchanged) on the refusals of
/// isotropic_remeshing.
template <detail::remeshing::Remeshable G>
std::size_t tangential_relaxation(G& g, const Remeshing_options& options = {}) {
  detail::remeshing::Remesher<G> r(g, options, "tangential_relaxation");
  if (options.projection) r.build_reference();
  return r.tangential_relaxation_and_project();
}

} // namespace genmesh
