#pragma once
// One way to run a case: the model (model.flow) is chosen here, once. Potential flow: the grid (the
// tolerance search, if any), then the factored solve and the post-processing (potential/pipeline.hpp,
// potential/plan.hpp); navier-stokes: Newton's method, the march in time or both (navier_stokes/run.hpp).
// `magnus run`, the Python module, the map's marched points and the tests call it.
#include <cstddef>
#include <functional>

#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "postproc/potential/plan.hpp"

namespace magnus {

/// What a run is given besides its case (as data), and what it tells its caller while it runs (each hook
/// may be empty).
struct RunHooks {
  int threads = 1;                     ///< for the solver (≥ 1)
  size_t max_bytes = 0;                ///< the memory a run may need, bytes (0: what is free)
  const Checkpoint* resume = nullptr;  ///< navier-stokes: go on from this state instead of from rest
  /// With the case as it will run (its grid chosen, by the tolerance search if any), before the solve.
  std::function<void(const Case&)> on_plan;
  /// navier-stokes: after every time step (progress, a stop flag: false stops, the result is then
  /// partial), at every checkpoint, and whether time.mode "auto" marches at once.
  ViscousHooks viscous;
  /// navier-stokes: a computed 3D onset curve (read from `magnus stability` files) and those files, for
  /// the verdict whether the 2D flow is real (ViscousPart::onset3d_*); empty: none given.
  std::vector<Onset3d> onset3d;
  std::vector<std::string> onset3d_files;
};

/// Solve case c by its model and post-process it (no files): potential flow as plan_run then run_planned,
/// navier-stokes as run_viscous. Throws what they throw (one line).
FlowResult run_case(const Case& c, const RunHooks& hooks = {});

}  // namespace magnus
