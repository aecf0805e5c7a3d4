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

}  // namespace magnus
