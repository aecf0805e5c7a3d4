#pragma once
// The run summary `magnus run` prints.
#include <string>
#include "postproc/result.hpp"

namespace magnus {

/// The summary `magnus run` prints: grid, solver, timings, lift three ways, ΔP, S, stagnation, errors.
std::string summary_text(const FlowResult& r, const std::string& output_path);

/// Number formatting used in tables: "undefined" for an empty optional.
std::string fmt_opt(const std::optional<double>& v, const char* spec = "{:.6g}");

}  // namespace magnus
