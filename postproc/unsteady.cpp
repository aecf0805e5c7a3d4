#include "postproc/unsteady.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace magnus {

namespace {

/// Means and amplitudes of the samples [b, e] (trapezoid in time).
struct Window {
  double t0 = 0.0, t1 = 0.0, C_L = 0.0, C_D = 0.0, C_M = 0.0, amp_L = 0.0, amp_D = 0.0;
};

Window window(const std::vector<ForceSample>& h, size_t b, size_t e, double t0, double t1) {
  Window w;
  w.t0 = t0;
  w.t1 = t1;
  double T = 0.0, lo_L = h[b].C_L, hi_L = h[b].C_L, lo_D = h[b].C_D, hi_D = h[b].C_D;
  for (size_t q = b; q < e; ++q) {
    const double dt = h[q + 1].t - h[q].t;
    T += dt;
    w.C_L += 0.5 * dt * (h[q].C_L + h[q + 1].C_L);
    w.C_D += 0.5 * dt * (h[q].C_D + h[q + 1].C_D);
    w.C_M += 0.5 * dt * (h[q].C_M + h[q + 1].C_M);
    lo_L = std::min(lo_L, h[q + 1].C_L), hi_L = std::max(hi_L, h[q + 1].C_L);
    lo_D = std::min(lo_D, h[q + 1].C_D), hi_D = std::max(hi_D, h[q + 1].C_D);
  }
  if (T > 0.0) w.C_L /= T, w.C_D /= T, w.C_M /= T;
  w.amp_L = 0.5 * (hi_L - lo_L);
  w.amp_D = 0.5 * (hi_D - lo_D);
  return w;
}

/// Whole periods between successive maxima of C_L, oldest first (at most `last` of them).
std::vector<Window> periods(const std::vector<ForceSample>& h, size_t last) {
  std::vector<size_t> peaks;
  std::vector<double> t_peak;
  for (size_t m = h.size() - 2; m >= 1 && peaks.size() < last + 1; --m) {
    if (!(h[m].C_L > h[m - 1].C_L && h[m].C_L >= h[m + 1].C_L)) continue;
    // Parabola through the three samples (uniform Δt near a peak): its vertex times the maximum.
    const double ym = h[m - 1].C_L, y0 = h[m].C_L, yp = h[m + 1].C_L, d = ym - 2.0 * y0 + yp;
    const double s = d != 0.0 ? 0.5 * (ym - yp) / d : 0.0;
    peaks.push_back(m);
    t_peak.push_back(h[m].t + s * (h[m + 1].t - h[m].t));
  }
  std::vector<Window> out;
  for (size_t q = peaks.size(); q-- > 1;) {
    Window w = window(h, peaks[q], peaks[q - 1], t_peak[q], t_peak[q - 1]);
    if (w.amp_L > 1e-5) out.push_back(w);  // a steady flow's round-off wiggles are no period
  }
  return out;
}

}  // namespace

bool analyse_periodic(const std::vector<ForceSample>& h, double D, double U, UnsteadyResult& out) {
  if (h.size() < 5) return false;
  const std::vector<Window> w = periods(h, 1);
  if (w.empty()) return false;
  const Window& p = w.back();
  out.period = p.t1 - p.t0;
  out.St = out.period > 0.0 ? D / (U * out.period) : 0.0;
  out.C_L_mean = p.C_L, out.C_D_mean = p.C_D, out.C_M_mean = p.C_M;
  out.C_L_amplitude = p.amp_L, out.C_D_amplitude = p.amp_D;
  return true;
}

double choose_time_step(const NsParams& p, const PolarGrid& g, const NsState& s, std::string* note) {
  const double dt_cfl = cfl_time_step(p, g, s.psi, p.cfl);
  if (!(p.dt > 0.0)) return dt_cfl;
  const double dt_limit = cfl_time_step(p, g, s.psi, 0.9 * kNsCflLimit);
  if (p.dt <= dt_limit) return p.dt;
  if (note)
    *note = "time step " + std::to_string(p.dt) + " s is above the stability limit " +
            std::to_string(dt_limit) + " s (CFL " + std::to_string(0.9 * kNsCflLimit) + "): using " +
            std::to_string(dt_cfl) + " s (CFL " + std::to_string(p.cfl) + ")";
  return dt_cfl;
}

UnsteadyResult run_unsteady(const NsParams& p, const UnsteadyOptions& o, NsState start,
                            std::vector<ForceSample> history) {
  const auto clock0 = std::chrono::steady_clock::now();
  UnsteadyResult res;
  res.history = std::move(history);
  if (!(p.U > 0.0)) throw std::invalid_argument("run_unsteady: needs U > 0 (coefficients and St use U)");
  const PolarGrid g = ns_grid(p);
  const double D = 2.0 * p.a, t_conv = D / p.U;
  std::string note;
  double dt = choose_time_step(p, g, start, &note);
  auto op = std::make_unique<NsOperator>(p, dt);
  NsState cur = std::move(start), nxt;
  // Record a state's forces (a resumed history already holds its first sample); false: asked to stop.
  auto sample = [&](const NsState& s) {
    const ViscousForces f = viscous_forces(g, p, o.rho, s);
    if (res.history.empty() || s.t > res.history.back().t)
      res.history.push_back({s.t, *f.C_L, *f.C_D, *f.C_M, f.F_x, f.F_y, f.M});
    return !o.on_step || o.on_step(s, f);
  };
  bool go_on = sample(cur);
  const double t_min = o.t_min >= 0.0 ? o.t_min : (g.outer_radius() - p.a) / p.U + 10.0 * t_conv;
  res.message = "reached t_end";
  try {
    while (go_on && cur.t < o.t_end - 1e-12 * o.t_end) {
      // Keep the CFL number near its target: the velocities grow as the wake forms.
      if (res.steps % 10 == 0) {
        const double cfl = cfl_number(g, cur.psi, dt);
        if (cfl > 0.95 * kNsCflLimit || (p.dt <= 0.0 && cfl > std::min(1.25 * p.cfl, 0.95 * kNsCflLimit))) {
          dt = cfl_time_step(p, g, cur.psi, p.cfl);
          op = std::make_unique<NsOperator>(p, dt);
        }
      }
      const double step = std::min(dt, o.t_end - cur.t);
      if (step < 0.999 * dt) op = std::make_unique<NsOperator>(p, step);  // land on t_end
      advance(*op, cur, nxt);
      std::swap(cur, nxt);
      ++res.steps;
      go_on = sample(cur);
      if (cur.t < t_min || res.steps % 50 != 0) continue;
      // Steady: forces flat over the window.
      const double t_from = cur.t - o.steady_window * t_conv;
      if (t_from > 0.0) {
        double lo_L = 1e300, hi_L = -1e300, lo_D = 1e300, hi_D = -1e300;
        for (size_t q = res.history.size(); q-- > 0 && res.history[q].t >= t_from;) {
          lo_L = std::min(lo_L, res.history[q].C_L), hi_L = std::max(hi_L, res.history[q].C_L);
          lo_D = std::min(lo_D, res.history[q].C_D), hi_D = std::max(hi_D, res.history[q].C_D);
        }
        if (hi_L - lo_L < o.steady_tol && hi_D - lo_D < o.steady_tol) {
          res.steady = res.converged = true;
          res.message = "steady";
          break;
        }
      }
      // Periodic: the last periods agree.
      const std::vector<Window> w = periods(res.history, size_t(o.converged_periods) + 1);
      if (w.size() >= size_t(o.converged_periods) + 1) {
        bool same = true;
        for (size_t q = 1; q < w.size(); ++q) {
          const double T0 = w[q - 1].t1 - w[q - 1].t0, T1 = w[q].t1 - w[q].t0;
          same = same && std::fabs(w[q].C_L - w[q - 1].C_L) < o.mean_tol &&
                 std::fabs(w[q].C_D - w[q - 1].C_D) < o.mean_tol && std::fabs(T1 - T0) < o.mean_tol * T1;
        }
        if (same) {
          res.converged = true;
          res.message = "periodic means converged";
          break;
        }
      }
    }
  } catch (const std::exception& e) {
    res.ok = false;
    res.message = e.what();
  }
  if (!go_on) {
    res.interrupted = true;
    res.message = "interrupted";
  }
  if (!note.empty()) res.message += "; " + note;
  res.periodic = !res.steady && analyse_periodic(res.history, D, p.U, res);
  if (!res.periodic) {
    const ForceSample& last = res.history.back();
    res.C_L_mean = last.C_L, res.C_D_mean = last.C_D, res.C_M_mean = last.C_M;
  }
  res.dt = dt;
  res.state = std::move(cur);
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  return res;
}

}  // namespace magnus
