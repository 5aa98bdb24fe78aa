// benchmarks/heap_counter.h — the heap bytes the benchmark process holds, as
// counted by the replaced global operator new in bench_memory.cpp.
#pragma once

namespace genmesh_bench {

/// Bytes currently allocated through operator new.
long long live_bytes();
/// The highest live_bytes() since the last reset_peak().
long long peak_bytes();
/// Starts a new peak at the current live_bytes().
void reset_peak();

} // namespace genmesh_bench
