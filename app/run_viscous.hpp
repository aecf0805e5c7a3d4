#pragma once
// `magnus run`: the run (run_case), its result written and its summary; a navier-stokes march with a
// progress line, Ctrl-C, SIGTERM and checkpoints.
#include <string>

#include "postproc/run_case.hpp"

namespace magnus {

/// Thrown once a run stopped by a signal has written its partial result and checkpoint: the program then
/// exits with 128 + signal (130 for SIGINT, 143 for SIGTERM), as the shell reports a signal.
struct Interrupted {
  int signal;
};

/// The command that goes on from the checkpoint: "magnus run CASE -o OUTPUT --resume" (shell-quoted).
std::string resume_command(const std::string& case_path, const std::string& output);

/// The progress line on a terminal before the march (Newton's method, the eigenvalue test), "" when none
/// runs: potential flow, time.mode "unsteady", or "auto" where it marches at once (auto_plan).
std::string before_march_text(const Case& c);

/// Run case c (read from case_path) by run_case with `hooks` (threads, max_bytes), write its result (and
/// remove the checkpoint it resumed from or wrote once the result is complete), print the summary unless
/// quiet, and return the result (what the summary and --json show). Potential flow: the free space for the
/// result is checked once the grid is chosen. Navier-stokes: resume continues from the case's checkpoint
/// file; stopped_by is set to the signal (SIGINT, SIGTERM) that cut the run short, else 0.
FlowResult run_and_report(const Case& c, const std::string& case_path, bool resume, bool quiet,
                          RunHooks hooks, int* stopped_by = nullptr);

}  // namespace magnus
