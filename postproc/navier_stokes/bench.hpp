#pragma once
// The cost of a navier-stokes time step (magnus bench on a navier-stokes case): a ladder of grids, each
// stepped from the impulsive start, with the wall time per step split into its parts.
#include <vector>

#include "physics/scene.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// One rung: the grid, Δt and the wall time of the timed steps, per part.
struct NsBenchRow {
  int n_theta = 0, n_r = 0;
  long nodes = 0;
  double dt = 0.0;        ///< time step, s (CFL time.cfl at the start)
  double time_unit = 0.0; ///< D/U_ref, s
  NsStepTimes times;      ///< summed over the timed steps (forces: one evaluation per step)
  double wall_s = 0.0;    ///< the timed steps' wall time, s
  double steps_per_second() const { return wall_s > 0.0 ? double(times.steps) / wall_s : 0.0; }
};

/// For each n_θ of the ladder (the case's radial refinement and R kept): `warmup` untimed steps, then `steps`
/// timed ones, forces evaluated after each as in a run, on `threads` threads (advection and mode solves).
std::vector<NsBenchRow> run_ns_bench(const Case& c, const std::vector<int>& ladder, int steps, int warmup = 20,
                                     int threads = 1);

}  // namespace magnus
