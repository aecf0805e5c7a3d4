// The steady paths of a viscous run: time.mode "steady" (Newton's method on four grids), and what
// time.mode "auto" does before it would march (auto_plan, then Newton and the eigenvalue test).
#include <fmt/core.h>

#include <cmath>
#include <complex>
#include <future>
#include <stdexcept>
#include <string>

#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "postproc/navier_stokes/unsteady.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stability.hpp"

namespace magnus {

AutoPlan auto_plan(const NsParams& p) {
  const double Re = p.reynolds(), alpha = p.U > 0.0 ? std::fabs(p.a * p.omega / p.U) : 0.0;
  if (wake_sheds(p.U, Re, alpha))
    return {AutoStart::march, fmt::format("Re {:.4g} ≥ 60, α {:.3g} ≤ 1: the wake sheds", Re, alpha)};
  if (p.U > 0.0 && Re <= 35.0 && alpha <= 3.0)
    return {AutoStart::newton_only,
            fmt::format("Re {:.4g} ≤ 35, α {:.3g} ≤ 3: below the onset of shedding, Re ≈ 47 at α = 0; no "
                        "eigenvalue test",
                        Re, alpha)};
  return {};
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

/// Newton's solve of p from `guess` on one thread; a throw becomes a failed result (the companion's failure
/// leaves the estimate undefined, not the run).
NewtonResult companion_solve(NsParams p, const NsState& guess, const NewtonOptions& o) {
  p.threads = 1;
  try {
    return solve_steady(p, guess, o);
  } catch (const std::exception& e) {
    NewtonResult failed;
    failed.message = e.what();
    return failed;
  }
}

/// The companion of a steady solve: Newton from the potential flow on the grid twice as coarse (pc), on a
/// thread of its own, beside the case's solve.
std::future<NewtonResult> start_companion_newton(const NsParams& pc, const NewtonOptions& o) {
  return std::async(std::launch::async,
                    [pc, o] { return companion_solve(pc, potential_guess(pc, ns_grid(pc)), o); });
}

/// The companion's solve once more, when the one from the potential flow failed (at high spin the coarse
/// grid's Newton can stall far from its solution): from the run's own steady state `fine` (on g), sampled
/// onto the companion's grid pc (Fourier in θ, cubic in ξ). The seconds of the failed attempt are added.
NewtonResult companion_from_run(const NsParams& pc, const PolarGrid& g, const NsState& fine,
                                const NewtonOptions& o, double seconds_before) {
  NewtonResult r = companion_solve(pc, interpolate_state(g, fine, ns_grid(pc)), o);
  r.wall_seconds += seconds_before;
  return r;
}

/// The steady values of a converged solve as a run's result (C_L, C_D; ok = Newton converged).
UnsteadyResult steady_values(const NsParams& p, double rho, const NewtonResult& nr) {
  UnsteadyResult u;
  u.ok = nr.converged;
  u.message = nr.message;
  u.steady = u.converged = true;
  if (!nr.converged) return u;
  const ViscousForces f = viscous_forces(ns_grid(p), p, rho, nr.state);
  u.C_L_mean = f.C_L.value_or(0.0), u.C_D_mean = f.C_D.value_or(0.0);
  return u;
}

/// The error estimate of the steady result r of the solve `fine` from its companion's solve (pc its grid).
void steady_estimate(FlowResult& r, const NsParams& p, const NsParams& pc, const NewtonResult& fine,
                     const NewtonResult& coarse) {
  ViscousPart& v = *r.viscous;
  const double rho = r.c.scene.density;
  record_companion(v, "Newton solve", pc, pc.n_theta == p.n_theta, coarse.wall_seconds);
  estimate_from_companion(v, steady_values(p, rho, fine), steady_values(pc, rho, coarse), MeansSpread{});
}

/// The status tail of a converged Newton solve.
std::string newton_text(const NewtonResult& nr) {
  return fmt::format("steady, by Newton's method: {} steps, residual {:.1e}", nr.iterations,
                     nr.residuals.empty() ? 0.0 : nr.residuals.back());
}

/// time.mode = "steady": the study's Richardson bars as the estimates, (|f* − f_N| + its bar)/|f_N|.
void study_estimate(ViscousPart& v, const SteadyStudy& study) {
  v.error_method = "from the grid study: |f − f_Richardson| + its error bar";
  auto rel = [](const std::optional<Richardson>& x) -> std::optional<double> {
    if (!x || !(std::fabs(x->finest) >= kEstimateZero)) return std::nullopt;
    return (std::fabs(x->value - x->finest) + x->error) / std::fabs(x->finest);
  };
  v.cl_mean_rel_estimate = rel(study.C_L), v.cd_mean_rel_estimate = rel(study.C_D);
  if (!v.cl_mean_rel_estimate || !v.cd_mean_rel_estimate)
    v.error_note = study.levels.size() < 2 ? "one grid solved: no Richardson estimate"
                                           : "C_L or C_D ≈ 0 (or U = 0): no relative error";
}

/// The leading eigenvalue of a search for a status line, and whether its strip was covered.
std::string eigenvalue_text(const StabilityResult& st, const Scene& s) {
  const std::complex<double> l = st.eigenvalues.front();
  // St = f·D/U needs a stream: in still fluid (U = 0) the eigenvalues are in a|ω|/D and St is undefined.
  return fmt::format("leading eigenvalue {:.4g} {:+.4g}i {}, St {}{}", l.real(), l.imag(), rate_unit_name(s),
                     s.speed > 0.0 ? fmt::format("{:.4g}", st.strouhal()) : "undefined (U = 0)",
                     st.covered ? "" : "; not verified: the search left a gap right of it");
}

}  // namespace

std::string stepper_text(const StepperVerdict& v, const Scene& s) {
  if (!v.sigma) return "the time stepper's test failed: its march stopped";
  const std::optional<bool> stable = sign_verdict(v.sigma, kStepperMargin);
  const char* how = !stable ? "neither decays nor grows" : *stable ? "decays" : "grows";
  return fmt::format("by the time stepper, a weak vortex added to it {} at {:.3g} {} over {:g}–{:g} {}", how,
                     *v.sigma, rate_unit_name(s), 0.5 * kStepperSpan, kStepperSpan, time_unit_name(s));
}

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
  study_estimate(*r.viscous, study);
  r.viscous->steady_study = std::move(study);
  return r;
}

AutoChoice auto_steady(const Case& c, const NsParams& p, const PolarGrid& g, bool error_estimate) {
  AutoChoice a;
  const AutoPlan plan = auto_plan(p);
  if (plan.start == AutoStart::march) {
    a.why = "auto: marched in time (" + plan.why + "); ";
    return a;
  }
  NewtonOptions o;
  o.max_iterations = 15;
  const std::string refusal = error_estimate ? companion_refusal(p, g, false) : "";
  const NsParams pc = companion_params(p, g);
  std::future<NewtonResult> companion;
  if (error_estimate && refusal.empty()) companion = start_companion_newton(pc, o);
  // The estimate of a steady result: from the companion's solve (it waits for it), or why there is none.
  auto estimate = [&](FlowResult& r, const NewtonResult& fine) {
    if (companion.valid()) {
      NewtonResult coarse = companion.get();
      NsParams used = pc;
      // Stalled from the potential flow: again from the run's own state. Stalled again (the coarse θ spacing
      // cannot carry the wall's rotation at high spin): coarser in the rings alone, ratio 2 still, where the
      // drag's error lies at high spin.
      if (!coarse.converged) coarse = companion_from_run(used, g, fine.state, o, coarse.wall_seconds);
      if (!coarse.converged) {
        used.n_theta = p.n_theta;
        coarse = companion_from_run(used, g, fine.state, o, coarse.wall_seconds);
      }
      steady_estimate(r, p, used, fine, coarse);
    } else if (error_estimate) {
      r.viscous->error_note = refusal;
    }
  };
  const NewtonResult nr = solve_steady(p, potential_guess(p, g), o);
  a.newton_seconds = nr.wall_seconds;
  if (!nr.converged) {
    a.why = fmt::format("auto: marched in time (no steady state by Newton: {}); ", nr.message);
    return a;
  }
  if (plan.start == AutoStart::newton_only) {
    a.steady = steady_result(c, p, g, nr.state, "auto: steady (" + plan.why + "); " + newton_text(nr),
                             nr.wall_seconds, nullptr);
    estimate(*a.steady, nr);
    return a;
  }
  StabilityResult st;
  try {
    // Cheaper than `magnus stability` (the status says when the strip right of the leading eigenvalue was
    // not covered).
    st = leading_eigenvalues(p, nr.state, 4, lone_search(quick_stability_options()));
  } catch (const std::exception& e) {
    a.why = fmt::format("auto: marched in time (stability not computed: {}); ", e.what());
    return a;
  }
  // Where the search converged nothing (slow far-field modes can crowd 0 on R = 100a), or called the state
  // stable but left a gap right of its leading eigenvalue (Re 200, α 1.6 and α 6), the time stepper decides
  // (checked_verdict); undecided or failed, it marches from rest.
  const bool found = !st.eigenvalues.empty();
  std::string said = found ? eigenvalue_text(st, c.scene) : "steady state found, " + st.message;
  std::optional<StepperVerdict> asked;
  const bool stable = checked_verdict(p, nr.state, st, &asked).value_or(false);
  if (asked) st.seconds += asked->seconds, said += "; " + stepper_text(*asked, c.scene);
  a.stability_seconds = st.seconds;
  if (found && stable == st.stable) {  // the eigenvalue shown agrees with the verdict
    a.eigenvalue = st.eigenvalues.front();
    if (!st.residuals.empty()) a.eigenvalue_residual = st.residuals.front();
  }
  if (stable) {
    a.steady = steady_result(c, p, g, nr.state, fmt::format("auto: stable ({}); {}", said, newton_text(nr)),
                             nr.wall_seconds, &st);
    estimate(*a.steady, nr);
  } else
    a.why = fmt::format("auto: marched in time ({}{}); ",
                        found && !st.stable ? "the steady state is unstable: " : "", said);
  return a;
}

}  // namespace magnus
