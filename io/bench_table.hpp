#pragma once
// `magnus bench`'s table (stdout) and CSV.
#include <string>
#include <vector>

#include "postproc/bench.hpp"

namespace magnus {

/// The table as text, and as CSV.
std::string bench_table(const std::vector<BenchRow>& rows);
std::string bench_csv(const std::vector<BenchRow>& rows);

}  // namespace magnus
