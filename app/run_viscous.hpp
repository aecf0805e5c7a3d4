#pragma once
// `magnus run` for a navier-stokes case: the time marching with a progress line, Ctrl-C and checkpoints.
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// Run case c (navier-stokes), write its result (and remove its checkpoint once the result is complete),
/// print the summary unless quiet, and return the result (what the summary and --json show). resume:
/// continue from the case's checkpoint file; threads ≥ 1.
FlowResult run_viscous_case(const Case& c, bool resume, bool quiet, int threads = 1);

}  // namespace magnus
