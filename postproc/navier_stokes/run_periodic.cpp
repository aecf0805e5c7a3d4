// time.mode = "periodic": a short march from rest, then the shedding orbit by Newton–GMRES shooting
// (postproc/navier_stokes/orbit.hpp), reported as a march's result.
#include <stdexcept>

#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"

namespace magnus {

FlowResult periodic_by_shooting(const Case& c, const NsParams& p, const PolarGrid& g, double unit,
                                const ViscousHooks& hooks, const Checkpoint* resume) {
  if (resume)
    throw std::invalid_argument(
        "time.mode = \"periodic\" does not resume from a checkpoint: run without --resume (its march is short)");
  if (!(c.scene.speed > 0.0))
    throw std::invalid_argument(
        "time.mode = \"periodic\" needs a freestream (flow.speed > 0): a cylinder spinning in still fluid does "
        "not shed");
  NsState start = impulsive_start(p, g);
  break_symmetry(p, g, start);
  OrbitRunOptions o;
  o.t_end = c.time.end * unit;
  o.rho = c.scene.density;
  o.on_step = hooks.on_step;
  if (hooks.on_step)  // the progress line and Ctrl-C once a period during the Newton solve
    o.orbit.on_period = [&](const NsState& s) {
      return hooks.on_step(s, viscous_forces(g, p, c.scene.density, s));
    };
  OrbitRun run = periodic_orbit_run(p, o, std::move(start));
  FlowResult r = viscous_result(c, p, run.result, {});
  r.viscous->march_seconds = run.march.wall_seconds;
  return r;
}

}  // namespace magnus
