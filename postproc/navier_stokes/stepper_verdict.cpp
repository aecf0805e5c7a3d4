#include "postproc/navier_stokes/stepper_verdict.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

void add_weak_vortex(const NsParams& p, NsState& s) {
  add_vortex_blob(ns_grid(p), s, 3.0 * p.a, 0.6 * p.a, 0.5 * p.a, 1e-4 * stability_speed(p) * 2.0 * p.a);
}

std::optional<bool> sign_verdict(std::optional<double> sigma, double margin) {
  if (!sigma || std::fabs(*sigma) <= margin) return std::nullopt;
  return *sigma < 0.0;
}

std::optional<double> marched_growth_rate(const NsParams& p, const NsState& steady, double span) {
  const PolarGrid g = ns_grid(p);
  NsState s = steady;
  s.t = 0.0, s.N_prev.clear(), s.dt_prev = 0.0, s.Gamma_flux_prev = 0.0;
  const double unit = 2.0 * p.a / stability_speed(p);  // D/U_ref
  add_weak_vortex(p, s);
  const size_t n = s.zeta.size();
  // Least-squares slope of ln‖ζ − ζ_s‖ (the wall ring left out) over the second half of the march.
  double st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
  long m = 0;
  bool finite = true;
  UnsteadyOptions o;
  o.t_end = span * unit;
  o.steady_tol = 0.0, o.mean_tol = 0.0;  // to t_end, whatever the flow does
  o.on_step = [&](const NsState& x, const ViscousForces&) {
    if (2.0 * x.t < o.t_end) return true;
    double e = 0.0;
    for (size_t q = size_t(g.n_theta); q < n; ++q)
      e += (x.zeta[q] - steady.zeta[q]) * (x.zeta[q] - steady.zeta[q]);
    if (!(e > 0.0) || !std::isfinite(e)) return finite = false;
    const double t = x.t / unit, y = 0.5 * std::log(e);
    st += t, sy += y, stt += t * t, sty += t * y, ++m;
    return true;
  };
  // 100 steps over the span where the run's own Δt would be longer (a slow spin in still fluid, whose Δt
  // grows as the flow settles): then a fixed Δt, which a CFL overshoot stops instead of shortening it.
  NsParams q = p;
  if (100.0 * choose_time_step(p, g, s, nullptr) > o.t_end) q.dt = o.t_end / 100.0;
  try {
    const UnsteadyResult r = run_unsteady(q, o, std::move(s));
    if (!r.ok || !finite || m < 3) return std::nullopt;
  } catch (const std::exception&) {  // e.g. an operator that cannot be built
    return std::nullopt;
  }
  return (double(m) * sty - st * sy) / (double(m) * stt - st * st);  // per D/U
}

StepperVerdict stepper_verdict(const NsParams& p, const NsState& steady) {
  const auto t0 = std::chrono::steady_clock::now();
  StepperVerdict v;
  v.sigma = marched_growth_rate(p, steady, kStepperSpan);
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return v;
}

std::optional<bool> checked_verdict(const NsParams& p, const NsState& steady, const StabilityResult& st,
                                    std::optional<StepperVerdict>* asked) {
  const bool found = !st.eigenvalues.empty();
  if (found && (!st.stable || st.covered)) return st.stable;
  const StepperVerdict v = stepper_verdict(p, steady);
  if (asked) *asked = v;
  const std::optional<bool> said = sign_verdict(v.sigma, kStepperMargin);
  if (found) return said != std::optional<bool>(false);  // a gapped "stable" falls only if the vortex grows
  return said;
}

}  // namespace magnus
