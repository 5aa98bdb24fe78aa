// genmesh/subdivision/types.h — the public vocabulary shared by the
// subdivision schemes: the border rule and the result of a call.
#pragma once

#include <cstddef>
#include <vector>

namespace genmesh {

/// How a scheme treats the mesh border.
enum class Boundary_rule {
  smooth, ///< the border curve is refined with the cubic B-spline rules (1/8, 3/4, 1/8; 1/2, 1/2)
  fixed,  ///< border vertices keep their positions; new border points are edge midpoints
};

/// What a subdivision did.
struct Subdivision_result {
  int levels_done = 0;        ///< levels applied
  std::size_t vertices = 0;   ///< live counts after the last level
  std::size_t faces = 0;
  /// With creases given: the sharpness of every edge of the result, in edge
  /// iteration order (feed it to the next call); empty otherwise.
  std::vector<double> edge_sharpness;
};

} // namespace genmesh
