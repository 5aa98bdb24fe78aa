// genmesh/remeshing/make_delaunay.h — one step of isotropic remeshing, usable alone
// (<genmesh/remeshing.h>), with the same options and refusals.
#pragma once

#include <genmesh/remeshing/detail/remesher.h>

namespace genmesh {

/// Flips free inner edges whose opposite angles sum to more than π (where the flip keeps the
/// orientation) until none is left or 50 passes are done. Returns the number of flips.
/// Throws genmesh::invalid_input (g unchanged) on the refusals of
/// isotropic_remeshing.
template <detail::remeshing::Remeshable G>
std::size_t make_delaunay(G& g, const Remeshing_options& options = {}) {
  detail::remeshing::Remesher<G> r(g, options, "make_delaunay");
  return r.make_delaunay();
}

} // namespace genmesh
