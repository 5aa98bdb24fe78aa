// genmesh/remeshing/equalize_valences.h — one step of isotropic remeshing, usable alone
// (<genmesh/remeshing.h>), with the same options and refusals.
#pragma once

#include <genmesh/remeshing/detail/remesher.h>

namespace genmesh {

/// Flips free inner edges where that lowers the sum of squared valence deviations from 6 (4 on the
/// border) of the four vertices involved and keeps both triangles' orientation; at most 10 passes;
/// never raises the deviation. Returns the number of flips.
/// Throws genmesh::invalid_input (g unchanged) on the refusals of
/// isotropic_remeshing.
template <detail::remeshing::Remeshable G>
std::size_t equalize_valences(G& g, const Remeshing_options& options = {}) {
  detail::remeshing::Remesher<G> r(g, options, "equalize_valences");
  return r.equalize_valences();
}

} // namespace genmesh
