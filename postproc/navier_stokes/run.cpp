#include "postproc/navier_stokes/run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>

#include "physics/exact.hpp"
#include "postproc/navier_stokes/pressure.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stability.hpp"

namespace magnus {

namespace {

/// A weak vortex (Γ = 0.1% of U·D) off the axis behind the body: it breaks the mirror symmetry of the
/// start so that a flow that sheds starts shedding (round-off alone takes hundreds of D/U at α = 0).
void break_symmetry(const NsParams& p, const PolarGrid& g, NsState& s) {
  if (p.U > 0.0) add_vortex_blob(g, s, 3.0 * p.a, 0.6 * p.a, 0.5 * p.a, 1e-3 * p.U * 2.0 * p.a);
}

}  // namespace

const char* time_unit_name(const Scene& s) { return s.speed > 0.0 ? "D/U" : "D/(a|ω|)"; }
const char* rate_unit_name(const Scene& s) { return s.speed > 0.0 ? "U/D" : "a|ω|/D"; }

AutoPlan auto_plan(const NsParams& p) {
  const double Re = p.reynolds(), alpha = p.U > 0.0 ? std::fabs(p.a * p.omega / p.U) : 0.0;
  if (Re >= 60.0 && alpha <= 1.0)
    return {AutoStart::march, fmt::format("Re {:.4g} ≥ 60, α {:.3g} ≤ 1: the wake sheds", Re, alpha)};
  if (p.U > 0.0 && Re <= 35.0 && alpha <= 3.0)
    return {AutoStart::newton_only,
            fmt::format("Re {:.4g} ≤ 35, α {:.3g} ≤ 3: below the onset of shedding, Re ≈ 47 at α = 0; no "
                        "eigenvalue test",
                        Re, alpha)};
  return {};
}

NsParams ns_params(const Case& c) {
  NsParams p;
  const Scene& s = c.scene;
  p.a = s.radius;
  p.U = s.speed;
  p.omega = s.spin;
  p.nu = s.viscosity;
  p.outer_over_a = c.grid.outer_radius;
  p.n_theta = c.grid.n_theta;
  p.n_r = c.grid.n_r;
  p.cfl = c.time.cfl;
  p.advection_order = c.solver.advection_order;
  p.advection_order_xi = c.solver.advection_order_xi;
  p.dt = c.time.dt > 0.0 && s.reference_speed() > 0.0 ? c.time.dt * s.time_unit() : 0.0;
  return p;
}

FlowResult viscous_result(const Case& c, const NsParams& p, const UnsteadyResult& run,
                          std::vector<Snapshot> snapshots) {
  const auto clock0 = std::chrono::steady_clock::now();
  const Scene& sc = c.scene;
  const double a = sc.radius, U = sc.speed, w = sc.spin, rho = sc.density, D = 2.0 * a;
  FlowResult r;
  r.c = c;
  r.grid = ns_grid(p);
  const PolarGrid& g = r.grid;
  const NsState& st = run.state;
  const size_t nt = size_t(g.n_theta), n = size_t(g.n_r) * nt;

  // Fields: ψ and ζ as stepped; u from ψ; p from the pressure Poisson equation; Cp on ½ρU².
  const FieldSelection sel = select_fields(c.output.fields, c.model);
  Fields all;
  all.psi = st.psi;
  all.vorticity = st.zeta;
  ns_velocity(g, st.psi, all.u_r, all.u_theta);
  all.u_x.resize(n), all.u_y.resize(n);
  for (size_t i = 0; i < size_t(g.n_r); ++i)
    for (size_t j = 0; j < nt; ++j) {
      const double cs = std::cos(g.theta[j]), sn = std::sin(g.theta[j]), ur = all.u_r[i * nt + j],
                   ut = all.u_theta[i * nt + j];
      all.u_x[i * nt + j] = ur * cs - ut * sn;
      all.u_y[i * nt + j] = ur * sn + ut * cs;
    }
  all.pressure = ns_pressure_field(g, p, rho, sc.pressure_inf, st);
  const std::vector<double> wall_p(all.pressure.begin(), all.pressure.begin() + long(nt));
  const double q = 0.5 * rho * U * U;
  if (U > 0.0)
    for (double pv : all.pressure) all.cp.push_back((pv - sc.pressure_inf) / q);
  for (const auto& name : field_names())
    if (!sel.has(name)) all.get(name).clear();
  r.fields = std::move(all);

  // Surface: the wall moves with the body; its pressure is the field's wall ring (the θ-integral of
  // μ ζ_ξ fixed by the r-momentum balance), its shear μ(ζ_w − 2ω).
  const ViscousSurface vs = viscous_surface(g, p, rho, st);
  Surface& s = r.surface;
  s.theta = g.theta;
  s.u_theta.assign(nt, a * w);
  s.u_mean = a * w;
  s.u_fluct.assign(nt, 0.0);
  // The wall formula's pressure (it converges faster than the field's wall ring, and the forces use it),
  // placed at the field's mean wall pressure (the level the far field fixes).
  double level = 0.0;
  for (double pv : wall_p) level += pv / double(nt);
  s.pressure = vs.pressure;
  for (double& pv : s.pressure) pv += level;
  if (U > 0.0)
    for (double pv : s.pressure) s.cp.push_back((pv - sc.pressure_inf) / q);
  s.shear_stress = vs.tau_w;

  // Forces: the last step's, and the potential flow's figures for the same scene beside them.
  const ViscousForces vf = viscous_forces(g, p, rho, st);
  Forces& f = r.forces;
  f.lift = vf.F_y;
  f.drag = vf.F_x;
  f.cl = vf.C_L;
  f.cd = vf.C_D;
  const ExactFlow ideal = exact_flow(sc);
  f.lift_kutta_joukowski = ideal.lift(rho);
  f.circulation_measured = 2.0 * M_PI * a * a * w;  // ∮ u_θ a dθ with u_θ = aω: no slip
  f.delta_p_top_bottom =
      periodic_interpolate(s.pressure, M_PI / 2) - periodic_interpolate(s.pressure, 1.5 * M_PI);
  f.delta_p_top_bottom_exact = ideal.delta_p_top_bottom(rho);
  f.delta_p_seed_estimate = seed_delta_p(sc);
  f.magnus_S_exact = 2.0 * M_PI * rho * a * a;

  ViscousPart& v = r.viscous.emplace();
  v.viscosity = sc.viscosity;
  if (U > 0.0) v.reynolds = sc.reynolds();
  v.time_unit = sc.time_unit();
  v.status = run.message;
  v.steady = run.steady, v.periodic = run.periodic, v.converged = run.converged;
  v.partial = run.interrupted || !run.ok;
  v.t = st.t, v.dt = run.dt, v.steps = run.steps;
  v.Gamma_R = st.Gamma_R;
  v.last = vf;
  if (U > 0.0) {
    v.cl_mean = run.C_L_mean, v.cd_mean = run.C_D_mean, v.cm_mean = run.C_M_mean;
    if (run.periodic) {
      v.cl_amplitude = run.C_L_amplitude, v.cd_amplitude = run.C_D_amplitude;
      if (run.period_confirmed) v.strouhal = run.St, v.period = run.period;  // else undefined (status why)
    }
    v.lift_mean = run.C_L_mean * q * D, v.drag_mean = run.C_D_mean * q * D;
    v.torque_mean = run.C_M_mean * q * D * D;
    f.cl_kutta_joukowski = ideal.cl();
    f.cl_seed_estimate = seed_cl(sc);
    v.cl_ideal = ideal.cl();
    if (w != 0.0) {
      f.magnus_S = -v.lift_mean / (U * w);
      v.magnus_ratio = run.C_L_mean / ideal.cl();
    }
  } else {
    v.torque_mean = run.M_mean;  // U = 0: the torque (no coefficients)
  }
  v.spin_power_mean = -v.torque_mean * w;
  for (double th : separation_angles(vs)) v.separation.push_back(th);
  if (run.steady && U > 0.0) v.recirculation_length = recirculation_length(g, st);
  v.history = run.history;
  v.snapshots = std::move(snapshots);

  r.timing.solve_s = run.wall_seconds;
  r.timing.postproc_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  r.timing.total_s = r.timing.solve_s + r.timing.postproc_s;
  r.info.method = "fft";
  return r;
}

namespace {

/// The steady result of a converged Newton solve, with its status line (one history sample), Newton's wall
/// time (s) and, when computed, the leading eigenvalue of its linear stability and its time; the run's
/// time is their sum.
FlowResult steady_result(const Case& c, const NsParams& p, const PolarGrid& g, NsState state,
                         const std::string& status, double newton_seconds, const StabilityResult* stab) {
  UnsteadyResult u;
  u.state = std::move(state);
  u.steady = u.converged = true;
  u.message = status;
  const ViscousForces f = viscous_forces(g, p, c.scene.density, u.state);
  u.history = {force_sample(0.0, f)};
  u.has_coefficients = f.C_L.has_value();
  u.C_L_mean = f.C_L.value_or(0.0), u.C_D_mean = f.C_D.value_or(0.0), u.C_M_mean = f.C_M.value_or(0.0);
  u.M_mean = f.M;
  u.reference_speed = c.scene.reference_speed();
  u.wall_seconds = newton_seconds + (stab ? stab->seconds : 0.0);
  FlowResult r = viscous_result(c, p, u, {});
  r.viscous->newton = true;
  r.viscous->newton_seconds = newton_seconds;
  if (stab) r.viscous->stability_seconds = stab->seconds;
  if (stab && !stab->eigenvalues.empty()) {
    r.viscous->eigenvalue_real = stab->eigenvalues.front().real();
    r.viscous->eigenvalue_imag = stab->eigenvalues.front().imag();
    if (!stab->residuals.empty()) r.viscous->eigenvalue_residual = stab->residuals.front();
  }
  return r;
}

/// time.mode = "steady": Newton's method on the time stepper's discrete steady equations on four grids
/// (a quarter, half, two thirds and all of the case's spacing), each from the previous one's state (the
/// first from the potential flow with circulation), and C_D, C_L, L/D extrapolated from the last three
/// (Richardson); a checkpoint's state is solved on the case's grid alone. The result has one history sample.
FlowResult steady_by_newton(const Case& c, const NsParams& p, const PolarGrid& g, const Checkpoint* resume) {
  SteadyStudyOptions o;
  if (resume) o.scales = {1.0};
  SteadyStudy study = steady_study(p, o, resume ? &resume->state : nullptr);
  if (!study.converged) {
    const NewtonResult& nr = study.levels.back().newton;
    throw std::runtime_error(fmt::format(
        "time.mode = \"steady\": Newton's method did not converge ({}; residual {:.2e} after {} steps): the "
        "flow may have no steady state here; time.mode = \"auto\" marches in time instead",
        study.message, nr.residuals.empty() ? 0.0 : nr.residuals.back(), nr.iterations));
  }
  const NewtonResult& nr = study.levels.back().newton;
  const std::string status = fmt::format("steady, by Newton's method: {}, residual {:.1e}", study.message,
                                         nr.residuals.empty() ? 0.0 : nr.residuals.back());
  NsState state = std::move(study.state);
  study.state = NsState{};
  FlowResult r = steady_result(c, p, g, std::move(state), status, study.wall_seconds, nullptr);
  r.viscous->steady_study = std::move(study);
  return r;
}

/// What time.mode = "auto" decided before marching (empty `steady` when it marches), and what it cost.
struct AutoChoice {
  std::optional<FlowResult> steady;
  std::string why;  ///< for the status line of a marched run
  std::optional<std::complex<double>> eigenvalue;
  std::optional<double> eigenvalue_residual;  ///< its ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖)
  std::optional<double> newton_seconds, stability_seconds;  ///< s, when run
};

/// The status tail of a converged Newton solve.
std::string newton_text(const NewtonResult& nr) {
  return fmt::format("steady, by Newton's method: {} steps, residual {:.1e}", nr.iterations,
                     nr.residuals.empty() ? 0.0 : nr.residuals.back());
}

/// time.mode = "auto" (see auto_plan): Newton from the potential flow; a converged state that is linearly
/// stable (leading eigenvalue Re λ < 0), or one where steady flow is certain, is the result; otherwise the
/// flow is marched in time.
AutoChoice auto_steady(const Case& c, const NsParams& p, const PolarGrid& g) {
  AutoChoice a;
  const AutoPlan plan = auto_plan(p);
  if (plan.start == AutoStart::march) {
    a.why = "auto: marched in time (" + plan.why + "); ";
    return a;
  }
  NewtonOptions o;
  o.max_iterations = 15;
  const NewtonResult nr = solve_steady(p, potential_guess(p, g), o);
  a.newton_seconds = nr.wall_seconds;
  if (!nr.converged) {
    a.why = fmt::format("auto: marched in time (no steady state by Newton: {}); ", nr.message);
    return a;
  }
  if (plan.start == AutoStart::newton_only) {
    a.steady = steady_result(c, p, g, nr.state, "auto: steady (" + plan.why + "); " + newton_text(nr),
                             nr.wall_seconds, nullptr);
    return a;
  }
  StabilityResult st;
  try {
    // Cheaper than `magnus stability`: fewer restarts and no shifts added for gaps (the status says when
    // the strip right of the leading eigenvalue was not covered).
    StabilityOptions so;
    so.restarts = 4, so.extra_shifts = 0;
    st = leading_eigenvalues(p, nr.state, 4, so);
  } catch (const std::exception& e) {
    a.why = fmt::format("auto: marched in time (stability not computed: {}); ", e.what());
    return a;
  }
  a.stability_seconds = st.seconds;
  if (st.eigenvalues.empty()) {
    a.why = fmt::format("auto: marched in time (steady state found, {}); ", st.message);
    return a;
  }
  const std::complex<double> l = st.eigenvalues.front();
  a.eigenvalue = l;
  if (!st.residuals.empty()) a.eigenvalue_residual = st.residuals.front();
  // St = f·D/U needs a stream: in still fluid (U = 0) the eigenvalues are in a|ω|/D and St is undefined.
  const std::string lam =
      fmt::format("leading eigenvalue {:.4g} {:+.4g}i {}, St {}", l.real(), l.imag(), rate_unit_name(c.scene),
                  p.U > 0.0 ? fmt::format("{:.4g}", st.strouhal()) : "undefined (U = 0)");
  if (st.stable) {
    a.steady = steady_result(c, p, g, nr.state,
                             fmt::format("auto: stable ({}{}); {}", lam,
                                         st.covered ? "" : "; not verified: the search left a gap right of it",
                                         newton_text(nr)),
                             nr.wall_seconds, &st);
  } else
    a.why = fmt::format("auto: marched in time (the steady state is unstable: {}); ", lam);
  return a;
}

}  // namespace

FlowResult run_viscous(const Case& c, const ViscousHooks& hooks, const Checkpoint* resume, int threads) {
  const Scene& sc = c.scene;
  if (c.model != FlowModel::navier_stokes)
    throw std::invalid_argument("model.flow: run_viscous needs \"navier-stokes\"");
  if (!(sc.viscosity > 0.0)) throw std::invalid_argument("flow.viscosity: navier-stokes needs ν > 0");
  if (!(sc.reference_speed() > 0.0))
    throw std::invalid_argument("flow.speed and cylinder.spin are both 0: nothing moves, there is no flow");
  check_resolvable(c);  // before anything is solved or allocated
  NsParams p = ns_params(c);
  p.threads = std::max(1, threads);
  const PolarGrid g = ns_grid(p);
  const double unit = sc.time_unit();

  if (c.time.mode == TimeMode::steady) return steady_by_newton(c, p, g, resume);
  AutoChoice choice;
  if (c.time.mode == TimeMode::automatic && hooks.march_at_once)
    choice.why = "auto: marched in time (asked to march at once); ";
  else if (c.time.mode == TimeMode::automatic && !resume) {
    choice = auto_steady(c, p, g);
    if (choice.steady) return std::move(*choice.steady);
  }

  // A checkpoint already past time.end has nothing left to march: refused, so that it is kept.
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
          resume
              ? "of the state it resumes from"
              : "at the start (from rest, where the flow is fastest; the Δt that time.cfl picks grows as the "
                "flow settles)",
          0.9 * kNsCflLimit));
  }

  // The march's length in steps, with time.dt or with the step time.cfl gives at the start (the impulsive start
  // is the fastest flow of the run: its step is about the smallest): refused above kNsMaxSteps.
  if (!start.psi.empty()) {
    const double dt = p.dt > 0.0 ? p.dt : cfl_time_step(p, g, start.psi, p.cfl);
    const double steps = (c.time.end * unit - start.t) / dt;
    if (!(steps <= kNsMaxSteps))
      throw std::invalid_argument(fmt::format(
          "time.end = {:g} {} takes about {:.3g} time steps of {:.3g} {} on this grid, more than the {:g} a run "
          "may take: lower time.end or coarsen the grid",
          c.time.end, time_unit_name(sc), steps, dt / unit, time_unit_name(sc), kNsMaxSteps));
  }
  UnsteadyOptions o;
  o.t_end = c.time.end * unit;
  o.rho = sc.density;
  o.mean_tol = c.time.mean_tolerance;
  if (c.time.mode == TimeMode::unsteady) o.steady_tol = 0.0;  // march on: a steady flow runs to time.end

  std::vector<ForceSample> history = resume ? resume->history : std::vector<ForceSample>{};
  std::deque<Snapshot> snaps;
  if (resume) {  // the newest output.snapshots of them: the case may keep fewer than the checkpoint holds
    const size_t keep = std::min(resume->snapshots.size(), size_t(std::max(0, c.output.snapshots)));
    snaps.assign(resume->snapshots.end() - long(keep), resume->snapshots.end());
  }
  const double snap_every = c.output.snapshot_interval * unit;
  double next_snap = snaps.empty() ? start.t : snaps.back().t + snap_every;
  const double ckpt_every = c.time.checkpoint_interval * unit;
  double next_ckpt = start.t + ckpt_every;
  // The hooks' copy of the history (a checkpoint needs it; run_unsteady keeps its own for the analysis).
  std::vector<ForceSample> seen = history;
  const long steps_before = resume ? resume->steps : 0;
  long steps = 0;
  o.steps_taken = &steps;
  o.on_step = [&](const NsState& s, const ViscousForces& f) {
    if (seen.empty() || s.t > seen.back().t) seen.push_back(force_sample(s.t, f));
    if (c.output.snapshots > 0 && s.t >= next_snap - 1e-9 * snap_every) {
      snaps.push_back({s.t, s.psi, s.zeta});
      if (snaps.size() > size_t(c.output.snapshots)) snaps.pop_front();
      next_snap = s.t + snap_every;
    }
    if (hooks.on_checkpoint && ckpt_every > 0.0 && s.t >= next_ckpt) {
      hooks.on_checkpoint({s, seen, {snaps.begin(), snaps.end()}, steps_before + steps});
      next_ckpt = s.t + ckpt_every;
    }
    return !hooks.on_step || hooks.on_step(s, f);
  };
  UnsteadyResult run = run_unsteady(p, o, std::move(start), std::move(history));
  // An error is the error alone: why the run marched belongs to the status of a result, not to a failure.
  if (!run.ok) throw std::runtime_error(run.error);  // the last checkpoint stays as it was
  run.message = choice.why + run.message;
  if (run.interrupted && hooks.on_checkpoint)
    hooks.on_checkpoint({run.state, run.history, {snaps.begin(), snaps.end()}, steps_before + run.steps});
  FlowResult r = viscous_result(c, p, run, {snaps.begin(), snaps.end()});
  r.viscous->steps += steps_before;  // the total from rest; the summary's rate counts this run's alone
  r.viscous->steps_resumed = steps_before;
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

}  // namespace magnus
