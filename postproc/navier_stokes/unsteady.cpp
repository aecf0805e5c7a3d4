#include "postproc/navier_stokes/unsteady.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "postproc/navier_stokes/means_drift.hpp"
#include "postproc/navier_stokes/periodic.hpp"
#include "solver/navier_stokes/rotation.hpp"

namespace magnus {

namespace {

bool analyse_periodic_from(const std::vector<ForceSample>& h, size_t first, double D, double U,
                           UnsteadyResult& out) {
  if (h.size() < first + 5 || !(U > 0.0)) return false;
  const std::vector<PeriodWindow> w = lift_periods(h, 8, first);
  if (w.empty()) return false;
  const PeriodWindow& p = w.back();
  out.period = p.length();
  out.period_note = period_disagreement(h, w);
  out.period_confirmed = out.period_note.empty();
  out.St = out.period > 0.0 && out.period_confirmed ? D / (U * out.period) : 0.0;
  out.C_L_mean = p.C_L, out.C_D_mean = p.C_D, out.C_M_mean = p.C_M, out.M_mean = p.M;
  out.C_L_amplitude = p.amp_L, out.C_D_amplitude = p.amp_D;
  return true;
}

}  // namespace

double step_rate(const NsParams& p, const PolarGrid& g, const NsState& s) {
  const double r = cfl_number(g, s.psi, 1.0, p.advection_order, p.advection_order_xi, reference_psi_xi(p));
  return p.stokes || rotation_implicit(p) ? r : std::max(r, std::fabs(p.omega) / g.d_theta);
}

namespace {

/// The Δt (s) for the next step from the state s, the current dt (returned unchanged unless it must move).
/// A user's time.dt (p.dt > 0) is replaced only when its CFL number passes 0.95·kNsCflLimit. Magnus's own
/// Δt: before `follow` (the impulsive start) rebuilt when the CFL number passes min(1.25·cfl, 0.95·limit);
/// after, whenever it leaves ±20% of the target cfl (back to the target). In both, never a step above
/// 0.99·kNsCflLimit: past it Δt drops to min(cfl, 0.95·limit) (CFL 0.8, the limit, runs at 0.76 then).
double next_time_step(const NsParams& p, const PolarGrid& g, const NsState& s, double dt, bool follow) {
  const double rate = step_rate(p, g, s), cfl = rate * dt;
  if (p.dt > 0.0) return cfl > 0.95 * kNsCflLimit ? cfl_time_step(p, g, s.psi, p.cfl) : dt;
  double dt_new = dt;
  if (follow) {
    if (cfl > 1.2 * p.cfl || cfl < 0.8 * p.cfl) dt_new = rate > 0.0 ? p.cfl / rate : dt;
  } else if (cfl > std::min(1.25 * p.cfl, 0.95 * kNsCflLimit)) {
    dt_new = cfl_time_step(p, g, s.psi, p.cfl);
  }
  if (rate * dt_new > 0.99 * kNsCflLimit) dt_new = std::min(p.cfl, 0.95 * kNsCflLimit) / rate;
  return dt_new;
}

/// The field f of grid `from` on grid `to` (same body), bilinear in (ξ, θ), periodic in θ; rings beyond
/// from's R take its outer ring.
std::vector<double> interpolate(const PolarGrid& from, const std::vector<double>& f, const PolarGrid& to) {
  const int nf = from.n_theta, nt = to.n_theta;
  std::vector<double> out(size_t(to.n_r) * nt);
  for (int i = 0; i < to.n_r; ++i) {
    const double x = std::min(to.xi[i], from.xi.back());
    int a = int(std::upper_bound(from.xi.begin(), from.xi.end(), x) - from.xi.begin()) - 1;
    a = std::max(0, std::min(a, from.n_r - 2));
    const double s = std::max(0.0, std::min(1.0, (x - from.xi[a]) / (from.xi[a + 1] - from.xi[a])));
    for (int j = 0; j < nt; ++j) {
      const double u = to.theta[j] / from.d_theta;
      const int b = int(std::floor(u)) % nf, c = (b + 1) % nf;
      const double v = u - std::floor(u);
      const double* r0 = &f[size_t(a) * nf];
      const double* r1 = &f[size_t(a + 1) * nf];
      out[size_t(i) * nt + j] =
          (1.0 - s) * ((1.0 - v) * r0[b] + v * r0[c]) + s * ((1.0 - v) * r1[b] + v * r1[c]);
    }
  }
  return out;
}

}  // namespace

ForceSample force_sample(double t, const ViscousForces& f) {
  ForceSample x;
  x.t = t;
  x.has_coefficients = f.C_L.has_value();
  x.C_L = f.C_L.value_or(0.0), x.C_D = f.C_D.value_or(0.0), x.C_M = f.C_M.value_or(0.0);
  x.F_x = f.F_x, x.F_y = f.F_y, x.M = f.M;
  return x;
}

bool analyse_periodic(const std::vector<ForceSample>& h, double D, double U, UnsteadyResult& out) {
  return analyse_periodic_from(h, 0, D, U, out);
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

bool means_agree(double f0, double f1, double tol) {
  return std::fabs(f1 - f0) < tol * std::max(1.0, std::fabs(f1));
}

namespace {

/// The reference speed U (or a|ω| when U = 0), m/s; throws std::invalid_argument when nothing moves or the
/// parameters are not a scene (run_unsteady's conditions).
double reference_speed(const NsParams& p) {
  if (!(p.U >= 0.0) || !std::isfinite(p.U) || !std::isfinite(p.omega) || !(p.a > 0.0))
    throw std::invalid_argument("run_unsteady: needs a > 0, U >= 0 and a finite spin");
  const double U_ref = p.U > 0.0 ? p.U : std::fabs(p.a * p.omega);
  if (!(U_ref > 0.0))
    throw std::invalid_argument(
        "run_unsteady: U = 0 and omega = 0: nothing moves (give a freestream U > 0 or a spin omega != 0)");
  return U_ref;
}

/// The warm start (UnsteadyOptions::coarse_start): run on the grid with half the points each way, then
/// interpolate its state onto g (the wall closed again) into start, its history into res; first_fine: the
/// first sample of g. Returns the note for the message.
std::string warm_start(const NsParams& p, const UnsteadyOptions& o, const PolarGrid& g, NsState& start,
                       UnsteadyResult& res, size_t& first_fine) {
  NsParams pc = p;
  pc.n_theta = (p.n_theta / 2 + 1) / 2 * 2;
  pc.n_r = (g.n_r + 1) / 2;
  pc.outer_over_a = g.outer_radius() / p.a;
  const PolarGrid gc = ns_grid(pc);
  NsState sc;
  sc.zeta = interpolate(g, start.zeta, gc);
  sc.psi = interpolate(g, start.psi, gc);
  sc.Gamma_R = start.Gamma_R;
  UnsteadyOptions oc = o;
  oc.coarse_start = false;
  oc.mean_tol = 10.0 * o.mean_tol;
  oc.steady_tol = 10.0 * o.steady_tol;
  oc.on_step = nullptr;
  UnsteadyResult rc = run_unsteady(pc, oc, std::move(sc));
  res.coarse_steps = rc.steps;
  res.steps += rc.steps;
  if (o.steps_taken) *o.steps_taken = res.steps;
  res.times += rc.times;
  if (!(rc.ok && rc.state.t < o.t_end)) return "warm start skipped (" + rc.message + ")";
  NsState s;
  s.t = rc.state.t;
  s.Gamma_R = rc.state.Gamma_R;
  s.zeta = interpolate(gc, rc.state.zeta, g);
  s.psi = interpolate(gc, rc.state.psi, g);
  const NsOperator op0(p, choose_time_step(p, g, s, nullptr));
  op0.close_wall(s.psi, s.zeta, s.Gamma_R);
  start = std::move(s);
  res.history = std::move(rc.history);
  first_fine = res.history.size();
  res.t_fine = start.t;
  return "warm start on " + std::to_string(gc.n_r) + " x " + std::to_string(gc.n_theta) +
         " to t = " + std::to_string(start.t) + " s (" + rc.message + ")";
}

/// Steady: the forces of the samples from first_fine on flat over the window from t_from on (on ½ρU_ref²D,
/// q_ref = ½ρU_ref²; torque on ½ρU_ref²D², which must be flat too when there is no freestream).
bool forces_flat(const std::vector<ForceSample>& h, size_t first_fine, double t_from, double q_ref, double D,
                 bool freestream, double tol) {
  if (!(t_from > 0.0 && (h.size() - first_fine) > 2 && h[first_fine].t <= t_from)) return false;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t q = h.size(); q-- > first_fine && h[q].t >= t_from;) {
    const ForceSample& x = h[q];
    const double v[3] = {x.F_x / (q_ref * D), x.F_y / (q_ref * D), x.M / (q_ref * D * D)};
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], v[c]), hi[c] = std::max(hi[c], v[c]);
  }
  return hi[0] - lo[0] < tol && hi[1] - lo[1] < tol && (freestream || hi[2] - lo[2] < tol);
}

/// Whether the last `periods` + 1 full-grid periods of C_L in h agree with the last one in amplitude and
/// length to tol (relative): the growth near the onset has ended (the means alone agree while it grows).
bool lift_settled(const std::vector<ForceSample>& h, size_t first_fine, int periods, double tol) {
  const std::vector<PeriodWindow> w = lift_periods(h, size_t(periods) + 1, first_fine);
  if (w.size() < size_t(periods) + 1) return false;
  for (const PeriodWindow& x : w)
    if (std::fabs(x.amp_L - w.back().amp_L) > tol * w.back().amp_L ||
        std::fabs(x.length() - w.back().length()) > tol * w.back().length())
      return false;
  return true;
}

/// Whether the drift still to come of the means of the periods w (means_drift) is below tol·max(1, |C|) for
/// C_L and C_D and below tol·T for the period T (the last period's values).
bool drift_small(const std::vector<PeriodWindow>& w, double tol) {
  const MeansDrift d = means_drift(w);
  const PeriodWindow& last = w.back();
  return d.cl < tol * std::max(1.0, std::fabs(last.C_L)) && d.cd < tol * std::max(1.0, std::fabs(last.C_D)) &&
         d.period < tol * last.length();
}

}  // namespace

bool periods_agree(const std::vector<ForceSample>& h, size_t first_fine, const UnsteadyOptions& o) {
  if (o.settle_amplitudes) return lift_settled(h, first_fine, o.converged_periods, o.mean_tol);
  // The last periods, enough for both tests (the means' agreement and the spectrum's).
  const size_t n_same = size_t(o.converged_periods) + 1;
  const std::vector<PeriodWindow> all = lift_periods(h, std::max<size_t>(8, n_same), first_fine);
  const std::vector<PeriodWindow> w(all.end() - std::min(all.size(), n_same), all.end());
  if (w.size() < n_same) return false;
  bool same = true;
  for (size_t q = 1; q < w.size(); ++q) {
    const double T0 = w[q - 1].t1 - w[q - 1].t0, T1 = w[q].t1 - w[q].t0;
    same = same && means_agree(w[q - 1].C_L, w[q].C_L, o.mean_tol) &&
           means_agree(w[q - 1].C_D, w[q].C_D, o.mean_tol) && std::fabs(T1 - T0) < o.mean_tol * T1;
  }
  return same && (!o.stop_on_drift || drift_small(all, o.mean_tol)) &&
         period_disagreement(h, all).empty();  // it reads the last 8 periods
}

namespace {

/// Why a run may stop at time t (checked every 50 steps after earliest_stop): "steady" (forces_flat over
/// the last steady_window), "periodic means converged" or "the lift's periods settled" (periods_agree; with
/// coefficients only), or "".
std::string stop_reason(const UnsteadyResult& res, size_t first_fine, double t, const UnsteadyOptions& o,
                        double q_ref, double D, double t_conv, bool freestream) {
  if (forces_flat(res.history, first_fine, t - o.steady_window * t_conv, q_ref, D, freestream, o.steady_tol))
    return "steady";
  if (res.has_coefficients && periods_agree(res.history, first_fine, o))
    return o.settle_amplitudes ? "the lift's periods settled" : "periodic means converged";
  return "";
}

/// The radius (m) by which the starting vortex, carried at U, has faded by e⁻⁶ in the absorbing layer:
/// ∫λ dt = λ_R (R − r_s) x³/(3U) = 6 at x = (r − r_s)/(R − r_s), i.e. x = (18U/(λ_R (R − r_s)))^{1/3}
/// (at most 1); R without a layer.
double vortex_fade_radius(const NsParams& p, const PolarGrid& g) {
  const double R = g.outer_radius(), rs = p.absorbing_start * p.a;
  if (!(p.absorbing_start > 0.0) || !(p.absorbing_rate > 0.0) || !(p.U > 0.0)) return R;
  const double x = std::cbrt(18.0 * p.U / (p.absorbing_rate * (R - rs)));
  return x >= 1.0 ? R : rs + x * (R - rs);
}

/// The time before which a run never stops, s: o.t_min if set, else the warm start's end, else when the
/// starting vortex has left (U > 0) and the impulsive transient is over: (r_f − a)/U + 10·D/U, r_f = R or,
/// with an absorbing layer, the radius where it has faded (vortex_fade_radius); 10·D/U_ref without a
/// freestream.
double earliest_stop(const NsParams& p, const UnsteadyOptions& o, const PolarGrid& g, double t_fine,
                     double U_ref) {
  const double t_conv = 2.0 * p.a / U_ref;
  return o.t_min >= 0.0 ? o.t_min
         : t_fine > 0.0 ? t_fine
         : p.U > 0.0    ? (vortex_fade_radius(p, g) - p.a) / U_ref + 10.0 * t_conv
                        : 10.0 * t_conv;
}

/// The end of a run: the notes joined to the message, the period, means and amplitudes (or the last
/// sample's) found.
void summarise(UnsteadyResult& res, bool go_on, const std::string& warm_note, const std::string& dt_note,
               size_t first_fine, double D, double U) {
  if (!go_on) {
    res.interrupted = true;
    res.message = "interrupted";
  }
  if (!warm_note.empty()) res.message += "; " + warm_note;
  if (!dt_note.empty()) res.message += "; " + dt_note;
  res.periodic = !res.steady && analyse_periodic_from(res.history, first_fine, D, U, res);
  if (res.periodic && !res.period_confirmed) {
    res.converged = false;
    res.message += "; " + res.period_note;
  }
  if (!res.periodic) {
    const ForceSample& last = res.history.back();
    res.C_L_mean = last.C_L, res.C_D_mean = last.C_D, res.C_M_mean = last.C_M, res.M_mean = last.M;
  }
}

/// One step from cur into nxt, of dt or less to land on t_end (op rebuilt for a shorter step). When the
/// flow sped up more within the steps between two rate checks than the margin allows (a vortex leaving
/// the wall at high spin), advance() refuses the step (CflExceeded; cur untouched): magnus's own Δt is then
/// rebuilt from cur's exact rate and the step taken again. A user's time.dt is the user's: refused.
void take_step(const NsParams& p, const PolarGrid& g, bool own_dt, double t_end, double& dt,
               std::unique_ptr<NsOperator>& op, const NsState& cur, NsState& nxt, NsStepTimes* times) {
  const double step = std::min(dt, t_end - cur.t);
  if (step < 0.999 * dt) op = std::make_unique<NsOperator>(p, step);  // land on t_end
  try {
    advance(*op, cur, nxt, times);
  } catch (const CflExceeded&) {
    if (!own_dt) throw;
    dt = std::min(p.cfl, 0.95 * kNsCflLimit) / step_rate(p, g, cur);
    op = std::make_unique<NsOperator>(p, std::min(dt, t_end - cur.t));
    advance(*op, cur, nxt, times);
  }
}

}  // namespace

UnsteadyResult run_unsteady(const NsParams& p, const UnsteadyOptions& o, NsState start,
                            std::vector<ForceSample> history) {
  using clock = std::chrono::steady_clock;
  const auto clock0 = clock::now();
  const double U_ref = reference_speed(p);
  UnsteadyResult res;
  res.history = std::move(history);
  res.has_coefficients = p.U > 0.0;
  res.reference_speed = U_ref;
  const PolarGrid g = ns_grid(p);
  const double D = 2.0 * p.a, t_conv = D / U_ref;
  std::string warm_note;
  size_t first_fine = 0;  // convergence tests use samples from here on (the full grid's)
  const double t_start = start.t;
  if (o.coarse_start && res.history.empty() && start.t == 0.0 && p.n_theta >= 96 && g.n_r >= 32)
    warm_note = warm_start(p, o, g, start, res, first_fine);

  std::string dt_note;
  double dt = choose_time_step(p, g, start, &dt_note);
  auto op = std::make_unique<NsOperator>(p, dt);
  NsState cur = std::move(start), nxt;
  const double q_ref = 0.5 * o.rho * U_ref * U_ref;  // ½ρU_ref², Pa
  // Record a state's forces (a resumed history already holds its first sample); false: asked to stop.
  auto forces = [&](const NsState& s) {
    ScopedTimer timer(&res.times.forces);
    const ViscousForces f = viscous_forces(g, p, o.rho, s);
    if (res.history.empty() || s.t > res.history.back().t) res.history.push_back(force_sample(s.t, f));
    return f;
  };
  auto sample = [&](const NsState& s) {
    const ViscousForces f = forces(s);
    return !o.on_step || o.on_step(s, f);
  };
  bool go_on = sample(cur);
  const double t_min = earliest_stop(p, o, g, res.t_fine, U_ref);
  // Δt: the CFL floor of cfl_time_step covers the impulsive start; after 2 D/U_ref (or at once after a warm
  // start) Δt follows the measured CFL number (next_time_step); when magnus chose Δt, each step also
  // checks the previous step's rate (a time.dt of the user's is checked every 10 steps and refused by
  // advance() beyond the limit).
  const bool own_dt = !(p.dt > 0.0);
  const double t_floor_off = res.t_fine > 0.0 ? cur.t : t_start + 2.0 * t_conv;
  res.message = "reached t_end";
  try {
    while (go_on && cur.t < o.t_end - 1e-12 * o.t_end) {
      // Every 10 steps, and whenever the last step's rate (known from the step itself) puts the next one
      // above 0.95 × the limit: then the exact rate of this state decides (one pass over the grid).
      if (res.steps % 10 == 0 || (own_dt && cur.rate_prev * dt > 0.95 * kNsCflLimit)) {
        const double dt_new = next_time_step(p, g, cur, dt, cur.t >= t_floor_off);
        if (dt_new != dt) {
          dt = dt_new;
          op = std::make_unique<NsOperator>(p, dt);
        }
      }
      take_step(p, g, own_dt, o.t_end, dt, op, cur, nxt, &res.times);
      std::swap(cur, nxt);
      ++res.steps;
      if (o.steps_taken) *o.steps_taken = res.steps;
      go_on = sample(cur);
      if (cur.t < t_min || res.steps % 50 != 0) continue;
      const std::string stop = stop_reason(res, first_fine, cur.t, o, q_ref, D, t_conv, p.U > 0.0);
      if (!stop.empty()) {
        res.steady = stop == "steady";
        res.converged = true;
        res.message = stop;
        break;
      }
    }
  } catch (const std::exception& e) {
    res.ok = false;
    res.message = res.error = e.what();
  }
  summarise(res, go_on, warm_note, dt_note, first_fine, D, p.U);
  res.dt = dt;
  res.state = std::move(cur);
  res.wall_seconds = std::chrono::duration<double>(clock::now() - clock0).count();
  res.steps_per_second = res.wall_seconds > 0.0 ? double(res.steps) / res.wall_seconds : 0.0;
  return res;
}

}  // namespace magnus
