#pragma once
// A run in two steps, so that a caller can look at the grid before anything is solved (e.g. `magnus run`
// estimates the output file's size): plan_run resolves the grid (the tolerance search, if any), run_planned
// solves and post-processes. run_case (postproc/run_case.hpp) calls both for a potential-flow case.
#include "postproc/result.hpp"
#include "postproc/potential/tolerance.hpp"

namespace magnus {

/// The case with its grid and stencil resolved, and how they were chosen.
struct RunPlan {
  Case c;                 ///< grid.n_theta, n_r, spacing and solver.stencil as they will run
  GridChoice choice;      ///< the tolerance search's result (n_theta = 0: no search)
  double choice_s = 0.0;  ///< wall seconds of the search
};

/// Resolve the grid: with grid.tolerance > 0 the tolerance search (every grid tried passes the memory guard
/// against max_bytes; 0: the memory available); else the case as given.
RunPlan plan_run(const Case& c, int threads = 1, size_t max_bytes = 0);

/// Solve and post-process a planned run (no files); throws if any reported figure is not finite.
FlowResult run_planned(const RunPlan& plan, int threads = 1, size_t max_bytes = 0);

}  // namespace magnus
