// genmesh/subdivision/types.h — the public vocabulary shared by the
// subdivision schemes: the border rule, the "map not given" marker of the
// options, and the result of a call.
#pragma once

#include <cstddef>

namespace genmesh {

/// How a scheme treats the mesh border.
enum class Boundary_rule {
  smooth, ///< the border curve is refined with the cubic B-spline rules (1/8, 3/4, 1/8; 1/2, 1/2)
  fixed,  ///< border vertices keep their positions; new border points are edge midpoints
};

/// The type of an option's property map left out: the scheme uses its
/// default (no creases, no corners).
struct Default_map {};

/// What a subdivision did.
struct Subdivision_result {
  int levels_done = 0;        ///< levels applied
  std::size_t vertices = 0;   ///< live counts after the last level
  std::size_t faces = 0;
};

} // namespace genmesh
