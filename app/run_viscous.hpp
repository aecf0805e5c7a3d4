#pragma once
// `magnus run` for a navier-stokes case: the time marching with a progress line, Ctrl-C, SIGTERM and
// checkpoints.
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// Thrown once a run stopped by a signal has written its partial result and checkpoint: the program then
/// exits with 128 + signal (130 for SIGINT, 143 for SIGTERM), as the shell reports a signal.
struct Interrupted {
  int signal;
};

/// The command that goes on from the checkpoint: "magnus run CASE -o OUTPUT --resume" (shell-quoted).
std::string resume_command(const std::string& case_path, const std::string& output);

/// The progress line on a terminal before the march (Newton's method, the eigenvalue test), "" when none
/// runs: time.mode "unsteady", or "auto" where it marches at once (auto_plan).
std::string before_march_text(const Case& c);

/// Run case c (read from case_path, navier-stokes), write its result (and remove the checkpoint it resumed
/// from or wrote once the result is complete), print the summary unless quiet, and return the result (what
/// the summary and --json show). resume: continue from the case's checkpoint file; threads ≥ 1.
/// stopped_by: set to the signal (SIGINT, SIGTERM) that cut the run short, else 0.
FlowResult run_viscous_case(const Case& c, const std::string& case_path, bool resume, bool quiet,
                            int threads = 1, int* stopped_by = nullptr);

}  // namespace magnus
