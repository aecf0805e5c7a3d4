#pragma once
// Pieces the --json outputs share (io/json_output.cpp, io/json_output_files.cpp). Internal to io/.
#include <optional>
#include <string>

#include "io/json_output.hpp"
#include "postproc/derived.hpp"
#include "postproc/navier_stokes/steady_study.hpp"

namespace magnus::json_parts {

/// "/forces" → "forces"; "/" → "" (the top level).
std::string key_of(const std::string& group);

/// cl_over_kj_minus_1 = C_L/C_L,KJ − 1 and kj_over_seed = C_L,KJ/C_L,seed (null when undefined; computed
/// by postproc/derived.hpp): the ratios the run summary and the compare table show.
Json kj_ratios(std::optional<double> cl_over_kj_minus_1, std::optional<double> kj_over_seed);

/// A stagnation point: r in m and over a, θ in rad and degrees, on the surface or free.
Json point_json(const StagnationPoint& p, double a);

/// A steady grid study (time.mode = "steady"): each level's grid, C_D, C_L, L/D, Newton's residuals,
/// factorisations and seconds, and the Richardson values of C_D, C_L and L/D with their error bars and the
/// order used (the summary's "grid study" and "Richardson" lines).
Json steady_study_json(const SteadyStudy& st);

}  // namespace magnus::json_parts
