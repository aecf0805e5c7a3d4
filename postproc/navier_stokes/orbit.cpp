// A shedding state as a periodic orbit: the short march, the shooting, the orbit's summary (orbit.hpp).
#include "postproc/navier_stokes/orbit.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/periodic.hpp"

namespace magnus {

namespace {

/// The short march: from `start` until, after t_min, the lift's periods have settled (run_unsteady's
/// settle_amplitudes), or it is steady, or t_end.
UnsteadyResult short_march(const NsParams& p, const OrbitRunOptions& o, NsState start) {
  UnsteadyOptions m;
  m.t_end = o.t_end;
  m.rho = o.rho;
  m.t_min = o.t_min;
  m.settle_amplitudes = true;
  m.mean_tol = o.march_tol;
  m.converged_periods = o.march_periods;
  m.on_step = o.on_step;
  return run_unsteady(p, m, std::move(start));
}

/// Refuses a short march that leaves nothing to shoot from (one line, why).
void check_short_march(const UnsteadyResult& m, double t_conv) {
  if (!m.ok) throw std::runtime_error("the short march before the orbit failed: " + m.error);
  if (m.interrupted) throw std::runtime_error("interrupted during the short march before the orbit");
  if (m.steady)
    throw std::runtime_error(fmt::format(
        "the flow is steady by t = {:.4g} D/U: there is no periodic orbit to find (time.mode = \"periodic\" "
        "needs a shedding flow; \"auto\" finds steady ones)",
        m.state.t / t_conv));
  if (!m.periodic || !(m.period > 0.0))
    throw std::runtime_error(fmt::format(
        "no shedding period in the lift by t = {:.4g} D/U (time.end): no start for the periodic orbit; "
        "a later time.end, or time.mode = \"auto\"",
        m.state.t / t_conv));
}

/// Refuses an orbit that is the steady state (a fixed point of every period map): its C_L amplitude below
/// kOrbitMinAmplitude·max(1, |mean C_L|), when the short march caught a decaying wobble as a period.
void check_sheds(const UnsteadyResult& r) {
  if (orbit_sheds(r)) return;
  throw std::runtime_error(fmt::format(
      "the flow does not shed: the orbit shrank onto the steady state (C_L amplitude {:.2g}); time.mode = "
      "\"periodic\" needs a shedding flow (\"auto\" or \"steady\" find steady ones)",
      r.C_L_amplitude));
}

/// The trapezoidal mean of samples y over their span (uniform in time).
double trapezoid_mean(const std::vector<double>& y) {
  if (y.size() < 2) return y.empty() ? 0.0 : y[0];
  double s = 0.5 * (y.front() + y.back());
  for (size_t k = 1; k + 1 < y.size(); ++k) s += y[k];
  return s / double(y.size() - 1);
}

}  // namespace

bool orbit_sheds(const UnsteadyResult& r) {
  return r.C_L_amplitude >= kOrbitMinAmplitude * std::max(1.0, std::fabs(r.C_L_mean));
}

void periodic_extremes(const std::vector<double>& y, double& lo, double& hi) {
  const size_t n = y.size();
  lo = hi = n ? y[0] : 0.0;
  if (n < 3) {
    for (double v : y) lo = std::min(lo, v), hi = std::max(hi, v);
    return;
  }
  const size_t kmax = size_t(std::max_element(y.begin(), y.end()) - y.begin());
  const size_t kmin = size_t(std::min_element(y.begin(), y.end()) - y.begin());
  auto vertex = [&](size_t k) {
    const double a = y[(k + n - 1) % n], b = y[k], c = y[(k + 1) % n];
    const double curv = a - 2.0 * b + c;
    return curv != 0.0 ? b - (c - a) * (c - a) / (8.0 * curv) : b;
  };
  hi = std::max(y[kmax], vertex(kmax));
  lo = std::min(y[kmin], vertex(kmin));
}

void keep_last_period(const NsParams& p, double rho, OrbitOptions& o, OrbitPeriod& period) {
  o.on_residual_step = [g = ns_grid(p), &p, rho, &period](int k, int N, const NsState& s) {
    if (k == 0) period.history.clear();
    period.history.push_back(force_sample(s.t, viscous_forces(g, p, rho, s)));
    if (k == N) period.end = s;
  };
}

UnsteadyResult orbit_summary(const NsParams& p, const OrbitResult& orbit, double rho,
                             const OrbitPeriod* period) {
  UnsteadyResult r;
  if (period && period->history.size() == size_t(orbit.steps) + 1) {
    r.history = period->history;
    r.state = period->end;
    r.steps = 0;
  } else {
    const PolarGrid g = ns_grid(p);
    const NsOperator op(p, orbit.T / orbit.steps);
    auto sample = [&](const NsState& s) {
      r.history.push_back(force_sample(s.t, viscous_forces(g, p, rho, s)));
    };
    NsState at0 = orbit.state;
    at0.t = 0.0;
    sample(at0);
    r.state = period_map(op, at0, orbit.steps, sample);
    r.steps = orbit.steps;
  }
  std::vector<double> L, Dc, M, Cm;
  for (const ForceSample& s : r.history)
    L.push_back(s.C_L), Dc.push_back(s.C_D), M.push_back(s.M), Cm.push_back(s.C_M);
  r.C_L_mean = trapezoid_mean(L), r.C_D_mean = trapezoid_mean(Dc), r.C_M_mean = trapezoid_mean(Cm);
  r.M_mean = trapezoid_mean(M);
  L.pop_back(), Dc.pop_back();  // one period: the last sample is the first again
  double lo, hi;
  periodic_extremes(L, lo, hi);
  r.C_L_amplitude = 0.5 * (hi - lo);
  periodic_extremes(Dc, lo, hi);
  r.C_D_amplitude = 0.5 * (hi - lo);
  r.has_coefficients = p.U > 0.0;
  r.reference_speed = p.U > 0.0 ? p.U : std::fabs(p.a * p.omega);
  r.period = orbit.T;
  r.St = p.U > 0.0 ? 2.0 * p.a / (p.U * orbit.T) : 0.0;
  r.periodic = true;
  r.converged = orbit.converged;
  r.dt = orbit.T / orbit.steps;
  return r;
}

std::string orbit_history_text(const OrbitResult& orbit, double time_unit) {
  std::string s = "Newton residual";
  for (const OrbitIterate& it : orbit.history) {
    s += fmt::format("{} {:.2e}", it.newton ? " →" : "", it.residual);
    if (it.newton == 0) continue;
    s += fmt::format(" (GMRES {}{})", it.krylov, it.damping < 1.0 ? fmt::format(", step {:g}", it.damping) : "");
  }
  return s + fmt::format("; T = {:.6g} D/U, N = {} steps a period, {} Newton iterations, {} GMRES products",
                         orbit.T / time_unit, orbit.steps, orbit.history.empty() ? 0 : orbit.history.back().newton,
                         orbit.krylov_total);
}

NsState hopf_start(const NsState& steady, const std::vector<std::complex<double>>& mode_psi,
                   const std::vector<std::complex<double>>& mode_zeta, std::complex<double> mode_Gamma_R,
                   double size) {
  if (mode_psi.size() != steady.psi.size() || mode_zeta.size() != steady.zeta.size())
    throw std::invalid_argument("hopf_start: the mode is not of the steady state's grid");
  double zeta_max = 0.0, mode_max = 0.0;
  for (double z : steady.zeta) zeta_max = std::max(zeta_max, std::fabs(z));
  for (const auto& z : mode_zeta) mode_max = std::max(mode_max, std::abs(z));
  NsState s;
  s.psi = steady.psi, s.zeta = steady.zeta, s.Gamma_R = steady.Gamma_R;
  if (!(mode_max > 0.0)) return s;
  const double eps = size * zeta_max / mode_max;
  for (size_t i = 0; i < s.psi.size(); ++i) s.psi[i] += eps * mode_psi[i].real();
  for (size_t i = 0; i < s.zeta.size(); ++i) s.zeta[i] += eps * mode_zeta[i].real();
  s.Gamma_R += eps * mode_Gamma_R.real();
  return s;
}

OrbitRun periodic_orbit_run(const NsParams& p, const OrbitRunOptions& o, NsState start) {
  const auto clock0 = std::chrono::steady_clock::now();
  OrbitRun run;
  run.march = short_march(p, o, std::move(start));
  const UnsteadyResult& m = run.march;
  const double t_conv = 2.0 * p.a / m.reference_speed;  // D/U, s (run_unsteady's reference speed)
  check_short_march(m, t_conv);
  OrbitOptions oo = o.orbit;
  if (oo.steps <= 0) oo.steps = int(std::ceil(m.period / m.dt));
  OrbitPeriod last;
  keep_last_period(p, o.rho, oo, last);
  run.orbit = solve_periodic_orbit(p, m.state, m.period, oo);
  run.result = orbit_summary(p, run.orbit, o.rho, &last);
  check_sheds(run.result);
  run.result.steps += m.steps + run.orbit.time_steps;  // to the summary's own (none if it kept the period)
  run.result.times = m.times;
  run.result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  run.result.steps_per_second =
      run.result.wall_seconds > 0.0 ? double(run.result.steps) / run.result.wall_seconds : 0.0;
  run.result.message = fmt::format("periodic orbit {}after a march to t = {:.4g} D/U ({} steps): {}",
                                   run.orbit.converged ? "" : "NOT converged ", m.state.t / t_conv, m.steps,
                                   orbit_history_text(run.orbit, t_conv));
  return run;
}

PeriodicBase orbit_series(const NsParams& p, const OrbitResult& orbit, int K) {
  const NsOperator op(p, orbit.T / orbit.steps);
  FourierAccumulator acc(orbit.state.psi.size(), orbit.steps, K, orbit.T);
  acc.add(0, orbit.state);
  int n = 0;
  period_map(op, orbit.state, orbit.steps - 1, [&](const NsState& s) { acc.add(++n, s); });
  return acc.base();
}

}  // namespace magnus
