// The march in time of a viscous run: its start (from rest, or from a checkpoint), the checks of Δt and
// of the number of steps, the snapshots and checkpoints kept on the way, and the result.
#include <fmt/core.h>

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/means_drift.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

void break_symmetry(const NsParams& p, const PolarGrid& g, NsState& s) {
  if (p.U > 0.0) add_vortex_blob(g, s, 3.0 * p.a, 0.6 * p.a, 0.5 * p.a, 1e-3 * p.U * 2.0 * p.a);
}

namespace {

/// The state the march starts from: the checkpoint's, or the impulsive start from rest with the symmetry
/// broken. A checkpoint already past time.end has nothing left to march: refused, so that it is kept.
NsState march_start(const Case& c, const NsParams& p, const PolarGrid& g, double unit,
                    const Checkpoint* resume) {
  const Scene& sc = c.scene;
  if (resume && c.time.end * unit < resume->state.t * (1.0 - 1e-12))
    throw std::invalid_argument(
        fmt::format("time.end = {:.6g} {} is before the checkpoint's time t = {:.6g} {}: give a later "
                    "time.end to go on from the checkpoint, or run without --resume",
                    c.time.end, time_unit_name(sc), resume->state.t / unit, time_unit_name(sc)));
  NsState start;
  if (resume) {
    start = resume->state;
    if (start.psi.size() != size_t(g.nodes()) || start.zeta.size() != size_t(g.nodes()))
      throw std::invalid_argument("the checkpoint's grid is not the case's grid");
  } else {
    start = impulsive_start(p, g);
    break_symmetry(p, g, start);
  }
  return start;
}

/// Refuses an asked Δt above the stability limit of the start, and a march longer than kNsMaxSteps steps.
void check_march(const Case& c, const NsParams& p, const PolarGrid& g, double unit, const NsState& start,
                 bool resumed) {
  const Scene& sc = c.scene;
  // An asked Δt above the stability limit of the start is refused (the driver would have to clamp it). The
  // limit is the start's: the impulsive start from rest has the fastest flow of the run, so its limit is
  // lower than the Δt that time.cfl picks once the flow has settled (0.016 against 0.028 D/U at n_θ 48).
  if (p.dt > 0.0) {
    const double limit = cfl_time_step(p, g, start.psi, 0.9 * kNsCflLimit);
    if (p.dt > limit)
      throw std::invalid_argument(fmt::format(
          "time.dt = {:g} ({}) is above {:.4g} {}, the stability limit {} on this grid (CFL {:g}): leave it "
          "out or lower it",
          c.time.dt, time_unit_name(sc), limit / unit, time_unit_name(sc),
          resumed
              ? "of the state it resumes from"
              : "at the start (from rest, where the flow is fastest; the Δt that time.cfl picks grows as the "
                "flow settles)",
          0.9 * kNsCflLimit));
  }

  // The march's length in steps, with time.dt or with the step time.cfl gives at the start (the impulsive
  // start is the fastest flow of the run: its step is about the smallest): refused above kNsMaxSteps.
  if (!start.psi.empty()) {
    const double dt = p.dt > 0.0 ? p.dt : cfl_time_step(p, g, start.psi, p.cfl);
    const double steps = (c.time.end * unit - start.t) / dt;
    if (!(steps <= kNsMaxSteps))
      throw std::invalid_argument(
          fmt::format("time.end = {:g} {} takes about {:.3g} time steps of {:.3g} {} on this grid, more than "
                      "the {:g} a run "
                      "may take: lower time.end or coarsen the grid",
                      c.time.end, time_unit_name(sc), steps, dt / unit, time_unit_name(sc), kNsMaxSteps));
  }
}

/// What the march keeps on the way: the newest output.snapshots snapshots, one every
/// output.snapshot_interval, and a checkpoint every time.checkpoint_interval (through the hooks).
struct MarchRecord {
  const Case& c;
  const ViscousHooks& hooks;
  std::deque<Snapshot> snaps;
  double snap_every, next_snap, ckpt_every, next_ckpt;
  /// The hooks' copy of the history (a checkpoint needs it; run_unsteady keeps its own for the analysis).
  std::vector<ForceSample> seen;
  long steps_before = 0;  ///< steps from rest to the checkpoint resumed from
  long steps = 0;         ///< steps of this run

  MarchRecord(const Case& c_, const ViscousHooks& h, double unit, double t0, const Checkpoint* resume)
      : c(c_), hooks(h) {
    if (resume) {  // the newest output.snapshots of them: the case may keep fewer than the checkpoint holds
      const size_t keep = std::min(resume->snapshots.size(), size_t(std::max(0, c.output.snapshots)));
      snaps.assign(resume->snapshots.end() - long(keep), resume->snapshots.end());
      seen = resume->history;
      steps_before = resume->steps;
    }
    snap_every = c.output.snapshot_interval * unit;
    next_snap = snaps.empty() ? t0 : snaps.back().t + snap_every;
    ckpt_every = c.time.checkpoint_interval * unit;
    next_ckpt = t0 + ckpt_every;
  }
  std::vector<Snapshot> snapshots() const { return {snaps.begin(), snaps.end()}; }
  /// After every step: the history, a snapshot and a checkpoint when due, then the caller's hook.
  bool step(const NsState& s, const ViscousForces& f) {
    if (seen.empty() || s.t > seen.back().t) seen.push_back(force_sample(s.t, f));
    if (c.output.snapshots > 0 && s.t >= next_snap - 1e-9 * snap_every) {
      snaps.push_back({s.t, s.psi, s.zeta});
      if (snaps.size() > size_t(c.output.snapshots)) snaps.pop_front();
      next_snap = s.t + snap_every;
    }
    if (hooks.on_checkpoint && ckpt_every > 0.0 && s.t >= next_ckpt) {
      hooks.on_checkpoint({s, seen, snapshots(), steps_before + steps});
      next_ckpt = s.t + ckpt_every;
    }
    return !hooks.on_step || hooks.on_step(s, f);
  }
};

/// The result of a finished (or interrupted) march, with the steps from rest and what "auto" found before.
FlowResult marched_result(const Case& c, const NsParams& p, UnsteadyResult& run, const MarchRecord& rec,
                          const AutoChoice& choice) {
  // An error is the error alone: why the run marched belongs to the status of a result, not to a failure.
  if (!run.ok) throw std::runtime_error(run.error);  // the last checkpoint stays as it was
  run.message = choice.why + run.message;
  if (run.interrupted && rec.hooks.on_checkpoint)
    rec.hooks.on_checkpoint({run.state, run.history, rec.snapshots(), rec.steps_before + run.steps});
  FlowResult r = viscous_result(c, p, run, rec.snapshots());
  r.viscous->steps += rec.steps_before;  // the total from rest; the summary's rate counts this run's alone
  r.viscous->steps_resumed = rec.steps_before;
  if (choice.eigenvalue) {
    r.viscous->eigenvalue_real = choice.eigenvalue->real();
    r.viscous->eigenvalue_imag = choice.eigenvalue->imag();
    r.viscous->eigenvalue_residual = choice.eigenvalue_residual;
  }
  // The solves before the march count in the run's time, each named.
  r.viscous->newton_seconds = choice.newton_seconds, r.viscous->stability_seconds = choice.stability_seconds;
  r.viscous->march_seconds = run.wall_seconds;
  r.timing.total_s += choice.newton_seconds.value_or(0.0) + choice.stability_seconds.value_or(0.0);
  return r;
}

}  // namespace

FlowResult march(const Case& c, const NsParams& p, const PolarGrid& g, double unit, const ViscousHooks& hooks,
                 const Checkpoint* resume, const AutoChoice& choice) {
  NsState start = march_start(c, p, g, unit, resume);
  check_march(c, p, g, unit, start, resume != nullptr);
  UnsteadyOptions o;
  o.t_end = c.time.end * unit;
  o.rho = c.scene.density;
  o.mean_tol = stop_mean_tolerance(c.time.mean_tolerance, c.grid.tolerance);
  o.stop_on_drift = c.time.stop_on_drift;
  if (c.time.mode == TimeMode::unsteady) o.steady_tol = 0.0;  // march on: a steady flow runs to time.end

  // The companion for the error estimate: from rest on the grid twice as coarse, beside the run.
  const std::string refusal = hooks.error_estimate ? companion_refusal(p, g, resume != nullptr) : "";
  const NsParams pc = companion_params(p, g);
  std::unique_ptr<CompanionRun> companion;
  if (hooks.error_estimate && refusal.empty())
    companion = start_companion(pc, o, march_start(c, pc, ns_grid(pc), unit, nullptr));

  MarchRecord rec(c, hooks, unit, start.t, resume);
  o.steps_taken = &rec.steps;
  o.on_step = [&rec](const NsState& s, const ViscousForces& f) { return rec.step(s, f); };
  UnsteadyResult run =
      run_unsteady(p, o, std::move(start), resume ? resume->history : std::vector<ForceSample>{});
  if (run.converged && !run.steady && o.mean_tol < c.time.mean_tolerance)
    run.message += fmt::format(" (to {:g}: a fifth of grid.tolerance)", o.mean_tol);
  FlowResult r = marched_result(c, p, run, rec, choice);
  if (!hooks.error_estimate) return r;
  ViscousPart& v = *r.viscous;
  v.means_converged = run.converged;
  if (!companion) {
    v.error_note = refusal;
    return r;
  }
  const UnsteadyResult coarse =
      finish_companion(*companion, run.interrupted ? -HUGE_VAL : run.state.t, hooks.keep_going);
  record_companion(v, "run", pc, false, coarse.wall_seconds);
  estimate_from_companion(v, run, coarse,
                          means_spread(run, o.converged_periods + 1, o.steady_window * 2.0 * p.a / p.U),
                          means_drift_rel(run));
  return r;
}

}  // namespace magnus
