// time.mode = "periodic": a short march from rest, then the shedding orbit by Newton–GMRES shooting
// (postproc/navier_stokes/orbit.hpp), reported as a march's result, with its error bar from the same orbit
// on the grid twice as coarse.
#include <exception>
#include <stdexcept>

#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/navier_stokes/steady_study.hpp"

namespace magnus {

namespace {

/// The companion orbit on grid pc, started from the run's orbit state (on grid g) interpolated there: a
/// short march with no earliest stop (it starts near its orbit), then Newton to the run's tolerance. A
/// failure is the companion's, not the run's: ok = false with the reason in message.
UnsteadyResult companion_orbit(const NsParams& pc, const PolarGrid& g, const OrbitRunOptions& run_options,
                               const NsState& orbit_state) {
  OrbitRunOptions o = run_options;
  o.t_min = 0.0;
  o.on_step = {};
  o.orbit.on_period = {};
  UnsteadyResult coarse;
  try {
    NsState start = interpolate_state(g, orbit_state, ns_grid(pc));
    start.t = 0.0;  // its short march has the run's time.end to find the period
    OrbitRun c = periodic_orbit_run(pc, o, std::move(start));
    coarse = std::move(c.result);
    if (!c.orbit.converged) {
      coarse.ok = false;
      coarse.message = "its Newton solve stalled";
    }
  } catch (const std::exception& e) {
    coarse.ok = false;
    coarse.message = e.what();
  }
  return coarse;
}

}  // namespace

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
  if (!hooks.error_estimate) return r;

  // The error bar: the orbit is periodic to Newton's tolerance, so its means have no spread and no drift
  // still to come; what is left is the grid's error, from the same orbit on the grid twice as coarse.
  ViscousPart& v = *r.viscous;
  v.means_converged = run.result.converged;
  if (const std::string refusal = companion_refusal(p, g, false); !refusal.empty()) {
    v.error_note = refusal;
    return r;
  }
  const NsParams pc = companion_params(p, g);
  const UnsteadyResult coarse = companion_orbit(pc, g, o, run.orbit.state);
  record_companion(v, "orbit", pc, false, coarse.wall_seconds);
  estimate_from_companion(v, run.result, coarse, {}, {});
  r.timing.total_s += coarse.wall_seconds;  // after the run, not beside it
  return r;
}

}  // namespace magnus
