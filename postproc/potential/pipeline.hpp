#pragma once
// The chain, written once: case → grid → operator → factored solver → ψ → fields → forces.
// run, sweep, bench and the tolerance search all call it; the method is chosen by resolve_method alone.
#include <memory>
#include <string>
#include <vector>

#include "postproc/result.hpp"
#include "solver/potential/flow_solver.hpp"

namespace magnus {

/// A case's discrete system, factored: the grid and the solver (which holds the operator). Any number of
/// right-hand sides may be solved with it.
struct Discretization {
  PolarGrid grid;
  std::unique_ptr<PsiSolver> solver;
  double setup_s = 0.0;  ///< wall seconds for the grid and the stencil rows (the solver times the rest)
};

/// Grid → operator → factored solver for the case's grid request and solver choice, after the memory guard
/// (the solver plus `fields` ψ-sized arrays against max_bytes; 0: the memory available). threads ≥ 1.
Discretization discretize(const Case& c, int threads = 1, size_t max_bytes = 0, int fields = 0);

/// C_L of the case on its own grid (no fields, no files): what the tolerance search needs per grid.
/// Empty when U = 0 (undefined).
std::optional<double> lift_coefficient(const Case& c, int threads = 1);

}  // namespace magnus
