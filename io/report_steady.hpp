#pragma once
// The summary lines of a steady (Newton) run's grid study: each grid's figures and Newton residuals, and
// the Richardson values with their error bars.
#include <optional>
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// "" without a study; else one line per grid (n_θ × n_r, C_D, C_L, L/D, residuals per Newton step) and
/// "C_D = f* ± e (Richardson, grids n_θ,1/…/n_θ,N, order p)" for C_D, |C_L| (when not 0) and L/D.
std::string steady_study_text(const ViscousPart& v);

/// Significant digits of v that an error bar e keeps: the largest d with e < ½ unit in the d-th digit (0 if
/// none; v = 0 or e = 0: undefined).
std::optional<int> significant_digits(double v, double e);

}  // namespace magnus
