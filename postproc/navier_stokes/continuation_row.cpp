#include "postproc/navier_stokes/continuation_row.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "physics/exact.hpp"
#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/map_orbits.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "postproc/run_case.hpp"
#include "solver/navier_stokes/newton.hpp"

namespace magnus {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
const double kNaN = std::nan("");

double max_norm(const std::vector<double>& r) {
  double m = 0.0;
  for (double v : r) m = std::max(m, std::isfinite(v) ? std::fabs(v) : HUGE_VAL);
  return m;
}

/// One Re row: the kept Jacobian, ∂F/∂α, and the Newton iteration at any α.
struct Row {
  NsParams p0;  ///< the row's parameters at α_0
  double alpha0 = 0.0;
  SteadyJacobian jac;
  std::vector<double> dF_dalpha;
  double tol;
  int max_iter;

  Row(const NsParams& p, double a0, double tol_, int max_)
      : p0(p), alpha0(a0), jac(p), tol(tol_), max_iter(max_) {
    // F is affine in ω: the difference of two residuals at any x is exact (up to round-off).
    NsParams p1 = p;
    p1.omega += p.U / p.a;  // α + 1
    const SteadyJacobian j1(p1);
    const std::vector<double> x = jac.pack(potential_guess(p, jac.grid()));
    const std::vector<double> f0 = jac.residual(x), f1 = j1.residual(x);
    dF_dalpha.resize(f0.size());
    for (size_t i = 0; i < f0.size(); ++i) dF_dalpha[i] = f1[i] - f0[i];
  }
  std::vector<double> F(const std::vector<double>& x, double alpha) const {
    std::vector<double> r = jac.residual(x);
    for (size_t i = 0; i < r.size(); ++i) r[i] += (alpha - alpha0) * dF_dalpha[i];
    return r;
  }
  /// Newton at α from x (in place); steps added to `steps`.
  bool newton(std::vector<double>& x, double alpha, int& steps) {
    for (int it = 0;; ++it) {
      const std::vector<double> r = F(x, alpha);
      const double res = max_norm(r);
      if (!std::isfinite(res)) return false;
      if (res <= tol) return true;
      if (it >= max_iter || res > 1e8) return false;
      try {
        jac.factor(x);
      } catch (const std::runtime_error&) {
        return false;
      }
      const std::vector<double> dx = jac.solve(r);
      for (size_t i = 0; i < x.size(); ++i) x[i] -= dx[i];
      ++steps;
    }
  }
  ArclengthProblem problem() {
    ArclengthProblem f;
    f.residual = [this](const std::vector<double>& x, double a) { return F(x, a); };
    f.d_lambda = [this](const std::vector<double>&, double) { return dF_dalpha; };
    f.factor = [this](const std::vector<double>& x, double) { jac.factor(x); };
    f.solve = [this](const std::vector<double>& b) { return jac.solve(b); };
    // Dimensionless unknowns (ψ/(Ua), ζa/U, Γ/(Ua)), mean square: the state weighs like α.
    const size_t n = dF_dalpha.size();
    const double sp = 1.0 / (p0.U * p0.a), sz = p0.a / p0.U;
    f.weight.resize(n);
    for (size_t i = 0; i + 1 < n; ++i) f.weight[i] = (i % 2 == 0 ? sp * sp : sz * sz) / double(n);
    f.weight[n - 1] = sp * sp / double(n);
    return f;
  }
};

/// The first steady state of a row at (Re, α): Newton from `guess` (the previous row's state, when the map
/// is continued in Re), else from the potential flow, else a ramp in Re from a low Reynolds number (each
/// its own Newton solve).
bool start_state(Row& row, const NsParams& p, double alpha, const NsState* guess, std::vector<double>& x,
                 int& steps) {
  if (guess) {
    x = row.jac.pack(*guess);
    if (row.newton(x, alpha, steps)) return true;
  }
  x = row.jac.pack(potential_guess(p, row.jac.grid()));
  if (row.newton(x, alpha, steps)) return true;
  const double re = p.reynolds();
  NsState s = potential_guess(p, row.jac.grid());
  const int n = 6;
  for (int k = 0; k <= n; ++k) {
    NsParams q = p;
    const double r = std::min(re, 10.0) * std::pow(re / std::min(re, 10.0), double(k) / n);
    q.nu = q.U * 2.0 * q.a / r;
    NewtonOptions o;
    o.tol = row.tol;
    const NewtonResult nr = solve_steady(q, s, o);
    steps += nr.iterations;
    if (!nr.converged) return false;
    s = nr.state;
  }
  x = row.jac.pack(s);
  return row.newton(x, alpha, steps);
}

void set_forces(NsMapPoint& m, const NsParams& p, const PolarGrid& g, double rho, const NsState& s) {
  const ViscousForces f = viscous_forces(g, p, rho, s);
  m.cl_steady = f.C_L.value_or(kNaN), m.cd_steady = f.C_D.value_or(kNaN), m.cm_steady = f.C_M.value_or(kNaN);
  m.cl_pressure = f.C_L_pressure.value_or(kNaN), m.cl_friction = f.C_L_friction.value_or(kNaN);
  m.cd_pressure = f.C_D_pressure.value_or(kNaN), m.cd_friction = f.C_D_friction.value_or(kNaN);
}

/// The steady point's error bars: the row's state interpolated onto the companion row's grid (twice as
/// coarse), Newton there at the same α, and the relative differences of C_L and C_D (relative_estimate).
/// Undefined (NaN) when that Newton fails.
void estimate_steady(Row& companion, const PolarGrid& fine, const NsState& s, double rho, NsMapPoint& m) {
  std::vector<double> xc = companion.jac.pack(interpolate_state(fine, s, companion.jac.grid()));
  int steps = 0;
  if (!companion.newton(xc, m.alpha, steps)) return;
  NsParams pc = companion.p0;
  pc.omega = m.alpha * pc.U / pc.a;
  const ViscousForces f = viscous_forces(companion.jac.grid(), pc, rho, companion.jac.unpack(xc));
  m.cl_rel_estimate = relative_estimate(m.cl_steady, f.C_L.value_or(kNaN), 0.0).value_or(kNaN);
  m.cd_rel_estimate = relative_estimate(m.cd_steady, f.C_D.value_or(kNaN), 0.0).value_or(kNaN);
}

NsMapPoint blank_point(const Case& base, int row, int col, double re, double alpha) {
  NsMapPoint m;
  m.row = row, m.column = col, m.reynolds = re, m.alpha = alpha;
  m.cl = m.cd = m.cm = m.cl_steady = m.cd_steady = m.cm_steady = kNaN;
  m.cl_pressure = m.cl_friction = m.cd_pressure = m.cd_friction = m.strouhal = kNaN;
  m.cl_rel_estimate = m.cd_rel_estimate = m.strouhal_rel_estimate = m.meets_tolerance = m.regime = kNaN;
  m.cl_ideal = exact_flow(map_point_case(base, re, alpha).scene).cl() + 0.0;  // + 0.0: no −0 at α = 0
  m.ratio = kNaN;
  return m;
}

/// The reported figures: steady when stable (or undecided); else what the flow does when it is marched in
/// time from rest: the time average of a shedding wake, or the steady state it settles on. The march starts
/// at once: a Newton solve from the potential flow (time.mode = "auto") may land on another steady state
/// than the continued one and would report that as the point's average without marching. With o.orbits a
/// shedding point is first sought as its periodic orbit (map_orbits.hpp: continued from the chain's, else
/// from `steady`, null when none, and the verdict's growing mode, else from rest), and a stable point after
/// a shedding one is tested for a coexisting orbit (bistable).
void finish_point(const Case& base, const NsMapOptions& o, const NsParams& p, const NsState* steady,
                  const StabilityVerdict& verdict, OrbitChain& chain, NsMapPoint& m) {
  if (m.converged && m.stable != std::optional<bool>(false)) {
    m.source = MapSource::steady;
    m.cl = m.cl_steady, m.cd = m.cd_steady, m.cm = m.cm_steady;
    // Does the row's shedding orbit persist here too? Then a stable steady state and an orbit coexist.
    const bool both = o.orbits && o.average_unstable && steady && m.stable &&
                      coexisting_orbit(map_point_case(base, m.reynolds, m.alpha), p, *steady, o, chain, m);
    if (!both) chain = {};  // the next shedding point starts its orbit afresh
    if (m.stable) m.regime = double(both ? MapRegime::bistable : MapRegime::steady);
  } else if (o.average_unstable && o.orbits &&
             orbit_point(map_point_case(base, m.reynolds, m.alpha), p, steady, verdict, o, chain, m)) {
    m.regime = double(MapRegime::shedding);  // m holds the orbit's means and bars
  } else if (o.average_unstable) {
    Case c = map_point_case(base, m.reynolds, m.alpha);
    c.time.mode = TimeMode::automatic;
    c.time.checkpoint_interval = 0.0;
    c.output.snapshots = 0;
    c.output.fields = std::vector<std::string>{};
    RunHooks marching;
    marching.viscous.march_at_once = true;
    marching.viscous.error_estimate = o.error_estimate;  // its companion march gives the point's bars
    const FlowResult r = run_case(c, marching);
    const ViscousPart& v = *r.viscous;
    m.source = v.steady      ? MapSource::marched_steady
               : m.converged ? MapSource::averaged_unstable
                             : MapSource::averaged_no_steady;
    m.regime = double(v.steady ? MapRegime::steady : MapRegime::shedding);
    m.cl = v.cl_mean.value_or(kNaN), m.cd = v.cd_mean.value_or(kNaN), m.cm = v.cm_mean.value_or(kNaN);
    m.strouhal = v.strouhal.value_or(kNaN);
    m.cl_rel_estimate = v.cl_mean_rel_estimate.value_or(kNaN);
    m.cd_rel_estimate = v.cd_mean_rel_estimate.value_or(kNaN);
    m.strouhal_rel_estimate = v.strouhal_rel_estimate.value_or(kNaN);
  } else {
    m.cl_rel_estimate = m.cd_rel_estimate = kNaN;  // no reported value: no bar either
  }
  if (std::isfinite(m.cl) && m.cl_ideal != 0.0) m.ratio = m.cl / m.cl_ideal;
  m.meets_tolerance = meets_tolerance(m);
}

/// Pseudo-arclength from the last converged point (x1, α_1 = a1) towards α = alpha > a1: once past α,
/// Newton at α from the chord (x set; m.converged), unless the branch turned back first (a fold: m.fold).
/// Its steps are counted into m.
void arclength_to(Row& R, const ArclengthProblem& prob, const NsMapOptions& o, const std::vector<double>& x1,
                  double a1, double alpha, NsMapPoint& m, std::vector<double>& x) {
  ArclengthPoint P = arclength_tangent(prob, x1, a1, +1.0);
  double ds = 0.5 * (alpha - a1) / std::max(P.tl, 1e-3);
  for (int s = 0; s < o.max_arclength_steps && !m.converged && !m.fold; ++s) {
    ArclengthPoint Q;
    int its = 0;
    const bool ok = arclength_step(prob, P, ds, o.newton_tol, o.corrector_max, Q, its);
    m.newton_steps += its;
    ++m.arclength_steps;
    if (!ok) {
      ds *= 0.5;
      if (std::fabs(ds) < 1e-6) break;
      continue;
    }
    Q = arclength_tangent(prob, Q.x, Q.lambda, +1.0, &P);
    if ((Q.tl > 0.0) != (P.tl > 0.0)) m.fold = true;  // the branch turns back: no state at α here
    if (Q.lambda >= alpha) {
      // Passed α: Newton at α from the chord between P and Q.
      const double w = (alpha - P.lambda) / (Q.lambda - P.lambda);
      x.resize(Q.x.size());
      for (size_t i = 0; i < x.size(); ++i) x[i] = P.x[i] + w * (Q.x[i] - P.x[i]);
      const int keep = R.max_iter;
      R.max_iter = std::max(keep, o.corrector_max);
      m.converged = !m.fold && R.newton(x, alpha, m.newton_steps);
      R.max_iter = keep;
    }
    P = std::move(Q);
    ds *= 1.5;
  }
}

/// A shedding orbit found at column k right after a stable steady point, with its steady state (the chain).
struct OrbitOnset {
  size_t k = 0;
  OrbitChain chain;
};

/// Below a subcritical Hopf point the orbit outlives the stable steady state it came from, in the columns
/// the row has already passed: for each onset, the orbit is carried back (coexisting_orbit, as forwards)
/// into the stable steady points before it, one after another, until it is lost. Each point it persists
/// at becomes bistable and is reported again through `done`.
void bistable_below(const Case& base, const NsMapOptions& o, const NsParams& p0,
                    const std::vector<std::optional<NsState>>& states, std::vector<OrbitOnset> onsets,
                    const std::function<void(const NsMapPoint&)>& done, std::vector<NsMapPoint>& out) {
  for (OrbitOnset& on : onsets)
    for (size_t j = on.k; j-- > 0;) {
      NsMapPoint& m = out[j];
      const bool stable_steady = m.source == MapSource::steady && m.stable == std::optional<bool>(true);
      if (!stable_steady || m.regime != double(MapRegime::steady) || !states[j]) break;
      const auto t0 = Clock::now();
      NsParams p = p0;
      p.omega = m.alpha * p.U / p.a;
      // A failure leaves m as it was (coexisting_orbit writes m only once the orbit is found).
      if (!coexisting_orbit(map_point_case(base, m.reynolds, m.alpha), p, *states[j], o, on.chain, m, true))
        break;
      m.regime = double(MapRegime::bistable);
      m.seconds += since(t0);
      done(m);
    }
}

}  // namespace

void mark_second_window(std::vector<NsMapPoint>& row) {
  double first_st = kNaN;
  bool steady_since = false;
  for (NsMapPoint& m : row) {
    if (m.regime == double(MapRegime::steady) || m.regime == double(MapRegime::bistable)) {
      steady_since = std::isfinite(first_st);
    } else if (m.regime == double(MapRegime::shedding)) {
      if (steady_since && m.strouhal < 0.5 * first_st) {
        m.regime = double(MapRegime::second_window);
      } else if (std::isfinite(m.strouhal)) {  // the first window (again, past a stable island)
        first_st = m.strouhal;
        steady_since = false;
      }
    }
  }
}

double meets_tolerance(const NsMapPoint& m) {
  const auto within = [](double value, double bar, double tol, bool needed) -> std::optional<bool> {
    if (!needed || !std::isfinite(value)) return true;
    if (!std::isfinite(bar)) return std::nullopt;
    return bar <= tol;
  };
  const std::optional<bool> checks[] = {
      within(m.cd, m.cd_rel_estimate, 2.0 * kRuleTolerance, true),
      within(m.cl, m.cl_rel_estimate, kRuleTolerance, std::fabs(m.cl) >= kEstimateZero),
      within(m.strouhal, m.strouhal_rel_estimate, kRuleTolerance, true)};
  for (const auto& c : checks)
    if (c == std::optional<bool>(false)) return 0.0;
  for (const auto& c : checks)
    if (!c) return kNaN;
  return 1.0;
}

std::vector<NsMapPoint> solve_row(const Case& base, const NsMapOptions& o, int row, double re,
                                  const std::function<void(const NsMapPoint&)>& done, const NsState* guess,
                                  std::optional<NsState>* first, OrbitChain* orbits) {
  const std::vector<double>& al = o.alphas;
  const Case c0 = map_point_case(base, re, al.front());
  const NsParams p0 = ns_params(c0);
  const double rho = base.scene.density;
  Row R(p0, al.front(), o.newton_tol, o.newton_max);
  const PolarGrid& g = R.jac.grid();
  // The same branch on the grid twice as coarse, for each steady point's error bars.
  std::optional<Row> companion;
  if (o.error_estimate && companion_refusal(p0, g, false).empty())
    companion.emplace(companion_params(p0, g), al.front(), o.newton_tol, o.newton_max);
  const ArclengthProblem prob = R.problem();
  std::vector<NsMapPoint> out;
  // The last two converged points of the branch (for the secant predictor and the arclength start).
  std::vector<double> x1, x2;
  double a1 = 0.0, a2 = 0.0;
  bool have1 = false, have2 = false;
  OrbitChain own;  // the row's last shedding orbit (o.orbits)
  OrbitChain& chain = orbits ? *orbits : own;
  // With o.orbits: each point's steady state and the orbits that start right after a stable point, for
  // the columns below a subcritical Hopf point (bistable_below).
  const bool back = o.orbits && o.average_unstable;
  std::vector<std::optional<NsState>> states(back ? al.size() : 0);
  std::vector<OrbitOnset> onsets;
  for (size_t k = 0; k < al.size(); ++k) {
    const auto t0 = Clock::now();
    NsMapPoint m = blank_point(base, row, int(k), re, al[k]);
    NsParams p = p0;
    p.omega = al[k] * p.U / p.a;
    std::vector<double> x;
    if (!have1) {
      // The first point, or a restart after the branch was lost (the row's Jacobian shifts to any α).
      m.converged = start_state(R, p, al[k], k == 0 ? guess : nullptr, x, m.newton_steps);
    } else {
      x = x1;
      if (have2 && a1 != a2)
        for (size_t i = 0; i < x.size(); ++i) x[i] += (al[k] - a1) / (a1 - a2) * (x1[i] - x2[i]);
      m.converged = R.newton(x, al[k], m.newton_steps);
      if (!m.converged) {
        arclength_to(R, prob, o, x1, a1, al[k], m, x);
      }
    }
    std::optional<NsState> s;
    StabilityVerdict verdict;
    if (m.converged) {
      s = R.jac.unpack(x);
      set_forces(m, p, g, rho, *s);
      if (companion) estimate_steady(*companion, g, *s, rho, m);
      if (k == 0 && first) *first = *s;
      if (o.stability) verdict = o.stability(p, *s);
      m.stable = verdict.stable;
      x2 = std::move(x1), a2 = a1, have2 = have1;
      x1 = R.jac.pack(*s), a1 = al[k], have1 = true;
    } else {
      have1 = have2 = false;  // the branch is lost: the next α starts afresh
    }
    finish_point(base, o, p, s ? &*s : nullptr, verdict, chain, m);
    m.seconds = since(t0);
    done(m);
    if (back) {
      states[k] = std::move(s);
      // An orbit right after a stable steady point (not one a march from rest settled on instead).
      if (m.source == MapSource::orbit && k > 0 && out.back().source == MapSource::steady &&
          out.back().stable == std::optional<bool>(true))
        onsets.push_back({k, chain});
    }
    out.push_back(m);
  }
  if (back) bistable_below(base, o, p0, states, std::move(onsets), done, out);
  mark_second_window(out);
  return out;
}

}  // namespace magnus
