#pragma once
// The last line of defence: no NaN or inf is ever printed or written as a result.
#include <string>
#include "postproc/result.hpp"

namespace magnus {

/// The first reported figure or field of a result that is not finite, by name ("lift F_y", "field pressure
/// at (i, j) = (3, 7)"); "" if every one is. Undefined figures (empty optionals) are not reported, so not
/// checked.
std::string first_non_finite(const FlowResult& r);

/// Throws std::runtime_error with one line naming the quantity if first_non_finite(r) is not empty.
void check_finite(const FlowResult& r);

}  // namespace magnus
