// time.mode = "periodic": a short march from rest, then the shedding orbit by Newton–GMRES shooting
// (postproc/navier_stokes/orbit.hpp), reported as a march's result, with its error bar from the same orbit
// on the grid twice as coarse, found beside it on the second core.
#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <future>
#include <stdexcept>

#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/navier_stokes/steady_study.hpp"

namespace magnus {

namespace {

/// The orbit of pc (the companion grid, one thread) from `start`, its summary in the march's terms; it
/// gives up at its next step or period at or past *stop_at (CompanionRun::stop_at). A failure is the
/// companion's, not the run's: ok = false with the reason in message.
UnsteadyResult companion_orbit(NsParams pc, OrbitRunOptions o, NsState start,
                               const std::atomic<double>* stop_at) {
  pc.threads = 1;
  o.on_step = [stop_at](const NsState& s, const ViscousForces&) { return s.t < stop_at->load(); };
  o.orbit.on_period = [stop_at](const NsState& s) { return s.t < stop_at->load(); };
  UnsteadyResult coarse;
  try {
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

/// The periods the companion's second try may march from the run's orbit before it gives up.
constexpr double kCompanionRetryPeriods = 20.0;

}  // namespace

FlowResult periodic_by_shooting(const Case& c, const NsParams& p, const PolarGrid& g, double unit,
                                const ViscousHooks& hooks, const Checkpoint* resume) {
  if (resume)
    throw std::invalid_argument(
        "time.mode = \"periodic\" does not resume from a checkpoint: run without --resume (its "
        "march is short)");
  if (!(c.scene.speed > 0.0))
    throw std::invalid_argument(
        "time.mode = \"periodic\" needs a freestream (flow.speed > 0): a cylinder spinning in still "
        "fluid does not shed");
  OrbitRunOptions o;
  o.t_end = c.time.end * unit;
  o.rho = c.scene.density;

  // The error bar's companion: the same orbit on the grid twice as coarse, from rest, beside the run (a
  // run on one thread steps on one core). An orbit is periodic to Newton's tolerance, so its means have no
  // spread and no drift still to come: the bar is the grid's part alone.
  const std::string refusal = hooks.error_estimate ? companion_refusal(p, g, false) : "";
  const NsParams pc = companion_params(p, g);
  CompanionRun companion;
  if (hooks.error_estimate && refusal.empty()) {
    const PolarGrid gc = ns_grid(pc);
    NsState rest = impulsive_start(pc, gc);
    break_symmetry(pc, gc, rest);
    companion.result =
        std::async(std::launch::async, companion_orbit, pc, o, std::move(rest), &companion.stop_at);
  }

  NsState start = impulsive_start(p, g);
  break_symmetry(p, g, start);
  o.on_step = hooks.on_step;
  if (hooks.on_step)  // the progress line and Ctrl-C once a period during the Newton solve
    o.orbit.on_period = [&](const NsState& s) {
      return hooks.on_step(s, viscous_forces(g, p, c.scene.density, s));
    };
  OrbitRun run = periodic_orbit_run(p, o, std::move(start));
  FlowResult r = viscous_result(c, p, run.result, {});
  r.viscous->march_seconds = run.march.wall_seconds;
  if (!hooks.error_estimate) return r;

  ViscousPart& v = *r.viscous;
  v.means_converged = run.result.converged;
  if (!refusal.empty() || !run.result.converged) {
    v.error_note = !refusal.empty()
                       ? refusal
                       : "the orbit's Newton solve stalled: its means are one period of a state that "
                         "is not yet periodic, and no grid difference bounds that";
    return r;  // the companion, if any, is stopped by its destructor
  }
  UnsteadyResult coarse = finish_companion(companion, HUGE_VAL, hooks.keep_going);  // to its own end
  double seconds = coarse.wall_seconds;
  if (coarse.ok && !same_orbit(run.result, coarse)) {
    coarse.ok = false;
    coarse.message =
        fmt::format("from rest it found another orbit (St {:.4g} against {:.4g})", coarse.St, run.result.St);
  }
  if (!coarse.ok && !coarse.interrupted) {  // once more from the run's orbit: near it, a few periods at most
    OrbitRunOptions from_orbit = o;
    from_orbit.t_min = 0.0;  // no starting vortex to wait for
    from_orbit.t_end = std::min(o.t_end, kCompanionRetryPeriods * run.result.period);
    try {
      NsState near = interpolate_state(g, run.orbit.state, ns_grid(pc));
      near.t = 0.0;
      companion.result = std::async(std::launch::async, companion_orbit, pc, from_orbit, std::move(near),
                                    &companion.stop_at);
      coarse = finish_companion(companion, HUGE_VAL, hooks.keep_going);
    } catch (const std::exception& e) {
      coarse.ok = false;
      coarse.message = e.what();
    }
    seconds += coarse.wall_seconds;
    r.timing.total_s += coarse.wall_seconds;
  }
  record_companion(v, "orbit", pc, false, seconds);
  estimate_from_companion(v, run.result, coarse, {}, {});
  return r;
}

}  // namespace magnus
