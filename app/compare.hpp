#pragma once
// `magnus compare FILE… [--csv FILE]`: lift, drag, the three lift coefficients and the errors of several
// results side by side, with the parameters that differ between them (only those).
#include <string>
#include <vector>

#include "io/compare.hpp"

namespace magnus {

/// Read every file (magnus-flow results, format version 1 or 2) and compare them, through the schema table:
/// only the rows of the files' models, and the parameters that differ (beyond 1e-12 relative).
/// Throws std::runtime_error with one line naming the first unreadable or foreign file.
Comparison compare_results(const std::vector<std::string>& paths);

/// `magnus compare`: print the table; write the CSV atomically when csv is not empty. csv "-" writes the
/// CSV to standard output instead, and then the table is not printed (stdout is the CSV alone). Throws.
void command_compare(const std::vector<std::string>& paths, const std::string& csv);

}  // namespace magnus
