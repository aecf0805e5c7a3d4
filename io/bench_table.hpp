#pragma once
// `magnus bench`'s table (stdout) and CSV.
#include <string>
#include <vector>

#include "postproc/potential/bench.hpp"
#include "postproc/navier_stokes/bench.hpp"

namespace magnus {

/// The table as text, and as CSV.
std::string bench_table(const std::vector<BenchRow>& rows);
std::string bench_csv(const std::vector<BenchRow>& rows);
/// The navier-stokes step cost table: grid, Δt, steps/s, ms per step and its split (ms and %), and as CSV.
std::string ns_bench_table(const std::vector<NsBenchRow>& rows);
std::string ns_bench_csv(const std::vector<NsBenchRow>& rows);
/// What bounds a step from below: its bytes moved and arrays per node, the measured bandwidth (bytes/s, on
/// `threads` threads) and the last-level cache (bytes, 0: unknown).
struct NsBound {
  double bytes_per_node = 0.0, array_bytes_per_node = 0.0, bandwidth = 0.0, cache = 0.0;
  int threads = 1;
};
/// The memory-bandwidth bound of a step, one line: B bytes per node at the bandwidth take at least
/// 1e9·B/bandwidth ns per node; the largest rung's ns/node against it, and whether its arrays fit in cache.
std::string ns_bench_bound(const std::vector<NsBenchRow>& rows, const NsBound& b);

}  // namespace magnus
