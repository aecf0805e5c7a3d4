#pragma once
// Reading a magnus-flow result file back into a FlowResult.
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// A FlowResult read from a magnus-flow file (format version 1 or 2), through the schema table
/// (io/schema.hpp): every attribute the file holds (case, parameters, forces, errors, timing), the grid
/// (r, θ), the fields and surface values present, and the stagnation points. Throws std::runtime_error
/// with one line.
FlowResult read_result(const std::string& path);

}  // namespace magnus
