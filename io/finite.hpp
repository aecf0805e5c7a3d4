#pragma once
// The last line of defence: nothing that is not finite is ever printed or written as a result. Every
// number the result schema (io/schema) stores is checked, so a new figure is covered when it is added.
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// The first stored number of r that is not finite, described for a user ("" if all are finite): an
/// attribute by its description and place, a dataset by its path and the index of the value.
std::string first_non_finite(const FlowResult& r);

/// Throws std::runtime_error with one line naming the quantity if first_non_finite(r) is not empty.
void check_finite(const FlowResult& r);

}  // namespace magnus
