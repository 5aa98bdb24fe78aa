// benchmarks/bench_options.h — settings the benchmark process reads from its
// environment (benchmarks/side_by_side/run.py sets them).
#pragma once

#include <cstdlib>
#include <cstring>

namespace genmesh_bench {

/// Whether rows compute their quality counters (Hausdorff distance,
/// self-intersections, angles) after timing: yes unless GENMESH_BENCH_QUALITY=0.
/// Those counters take longer than the algorithm on large meshes, and a
/// repetition needs them only once.
inline bool quality_wanted() {
  const char* v = std::getenv("GENMESH_BENCH_QUALITY");
  return v == nullptr || std::strcmp(v, "0") != 0;
}

} // namespace genmesh_bench
