#pragma once
// Reading a magnus-flow result file back into a FlowResult.
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// As much of a FlowResult as the plots need, read from a magnus-flow file: the case (title, a, U, ω,
/// ρ, p∞, circulation model and Γ), the grid (r, θ), the fields that are present (psi, cp), the surface
/// (θ, u_θ, pressure, cp, cp_exact) and the stagnation points. Throws std::runtime_error with one line.
FlowResult read_result(const std::string& path);

}  // namespace magnus
