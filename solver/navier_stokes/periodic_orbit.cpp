// Newton–GMRES shooting for the periodic orbits of the time stepper (periodic_orbit.hpp).
#include "solver/navier_stokes/periodic_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "solver/gmres.hpp"
#include "solver/navier_stokes/state_vector.hpp"

namespace magnus {

NsState period_map(const NsOperator& op, const NsState& s, int N,
                   const std::function<void(const NsState&)>& on_step) {
  NsState cur = s, nxt;
  for (int k = 0; k < N; ++k) {
    advance(op, cur, nxt);
    std::swap(cur, nxt);
    if (on_step) on_step(cur);
  }
  return cur;
}

namespace {

/// What the shooting keeps: the parameters, N, the node count n and the state's scaled unknowns (c); counts
/// the steps taken.
struct Shooting {
  const NsParams& p;
  int N;
  size_t n;
  StateVector c;
  const OrbitOptions& o;
  long steps = 0;

  std::vector<double> pack(const NsState& s) const { return c.pack(s); }
  NsState unpack(const std::vector<double>& x, double dt) const { return c.unpack(x, dt); }
  /// Φ_T(x) on op (Δt = T/N), scaled. A residual's period (residual = true) also keeps the unknowns after
  /// the first step in *first and reports its states to o.on_residual_step.
  std::vector<double> map(const NsOperator& op, const std::vector<double>& x, bool residual = false,
                          std::vector<double>* first = nullptr) {
    const NsState start = unpack(x, op.dt());
    const bool report = residual && o.on_residual_step;
    if (report) o.on_residual_step(0, N, start);
    int k = 0;
    const NsState end = period_map(op, start, N, [&](const NsState& s) {
      ++k;
      if (residual && k == 1 && first) *first = pack(s);
      if (report) o.on_residual_step(k, N, s);
    });
    steps += N;
    if (o.on_period && !o.on_period(end))
      throw std::runtime_error("interrupted during the Newton solve of the periodic orbit: no result");
    return pack(end);
  }
  /// ‖y_ζ − x_ζ‖/‖x_ζ‖: the vorticity block's relative change over a period.
  double residual(const std::vector<double>& y, const std::vector<double>& x) const {
    double d = 0.0, s = 0.0;
    for (size_t q = 0; q < n; ++q) d += (y[q] - x[q]) * (y[q] - x[q]), s += x[q] * x[q];
    return s > 0.0 ? std::sqrt(d / s) : std::sqrt(d);
  }
};

/// A Newton step (δx, δT in s) and its GMRES solve.
struct NewtonStep {
  std::vector<double> dx;
  double dT = 0.0;
  GmresResult gmres;
};

/// The bordered system of the Newton step at (x, T) with y = Φ_T(x) and first = S(x) on op, by GMRES to
/// the relative tolerance eta: products (Φ_T(x + εv) − y)/ε − v + ∂Φ/∂T·v_T and ⟨ẋ₀, v⟩/‖ẋ₀‖.
NewtonStep newton_step(Shooting& sh, const NsOperator& op, const std::vector<double>& x,
                       const std::vector<double>& y, const std::vector<double>& first, double T, double eta,
                       int max_krylov) {
  const size_t m = x.size();
  std::vector<double> xdot(m);
  for (size_t i = 0; i < m; ++i) xdot[i] = first[i] - x[i];
  const double xdot_norm = norm2(xdot);
  for (double& v : xdot) v /= xdot_norm > 0.0 ? xdot_norm : 1.0;
  const double dT_fd = 1e-6 * T;  // ∂Φ/∂T per scaled time, from one more period at Δt = (T + δT)/N
  const NsOperator op_T(sh.p, (T + dT_fd) / sh.N);
  std::vector<double> dPhi = sh.map(op_T, x);
  for (size_t i = 0; i < m; ++i) dPhi[i] = (dPhi[i] - y[i]) / (dT_fd * sh.c.time);
  const double x_norm = norm2(x);
  auto apply = [&](const std::vector<double>& v, std::vector<double>& out) {
    std::vector<double> vx(v.begin(), v.begin() + long(m));
    const double v_norm = norm2(vx), vT = v[m];
    std::fill(out.begin(), out.end(), 0.0);
    if (v_norm > 0.0) {
      const double eps = 1e-8 * (1.0 + x_norm) / v_norm;
      std::vector<double> xp(m);
      for (size_t i = 0; i < m; ++i) xp[i] = x[i] + eps * vx[i];
      const std::vector<double> yp = sh.map(op, xp);
      for (size_t i = 0; i < m; ++i) out[i] = (yp[i] - y[i]) / eps - vx[i];
    }
    for (size_t i = 0; i < m; ++i) out[i] += dPhi[i] * vT;
    out[m] = dot(xdot, vx);
  };
  std::vector<double> b(m + 1, 0.0), z;
  for (size_t i = 0; i < m; ++i) b[i] = x[i] - y[i];
  NewtonStep s;
  s.gmres = gmres(apply, b, z, eta, max_krylov);
  s.dx.assign(z.begin(), z.begin() + long(m));
  s.dT = z[m] / sh.c.time;
  return s;
}

/// x₀ + λ·dx.
std::vector<double> along(const std::vector<double>& x0, const std::vector<double>& dx, double lambda) {
  std::vector<double> x(x0.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = x0[i] + lambda * dx[i];
  return x;
}

}  // namespace

OrbitResult solve_periodic_orbit(const NsParams& p, const NsState& start, double T0, const OrbitOptions& o) {
  const PolarGrid g = ns_grid(p);
  const size_t n = size_t(g.n_r) * size_t(g.n_theta);
  if (o.steps <= 0) throw std::invalid_argument("solve_periodic_orbit: needs N > 0 time steps per period");
  if (!(T0 > 0.0) || !std::isfinite(T0))
    throw std::invalid_argument("solve_periodic_orbit: needs a period > 0");
  if (start.zeta.size() != n || start.psi.size() != n)
    throw std::invalid_argument("solve_periodic_orbit: the state does not match the grid");
  Shooting sh{p, o.steps, n, StateVector(p, n), o};
  OrbitResult res;
  res.steps = o.steps;
  std::vector<double> x = sh.pack(start), x_old, first;
  double T = T0, T_old = T0, rho_old = std::numeric_limits<double>::infinity(), lambda = 1.0;
  NewtonStep step;
  for (int k = 0;;) {
    auto op = std::make_unique<NsOperator>(p, T / o.steps);
    const std::vector<double> y = sh.map(*op, x, true, &first);
    const double rho = sh.residual(y, x);
    if (k > 0 && !(rho < rho_old) && lambda > 0.125) {  // backtrack: half the step
      lambda *= 0.5;
      x = along(x_old, step.dx, lambda);
      T = T_old + lambda * step.dT;
      continue;
    }
    res.history.push_back({k, rho, T, step.gmres.iterations, step.gmres.residual, lambda});
    if (o.on_iterate) o.on_iterate(res.history.back());
    res.residual = rho;
    if (!std::isfinite(rho)) break;
    if (rho <= o.tol) {
      res.converged = true;
      break;
    }
    if (k == o.max_newton) break;
    const double eta = std::clamp(10.0 * rho, 1e-7, o.forcing_max);
    step = newton_step(sh, *op, x, y, first, T, eta, o.max_krylov);
    res.krylov_total += step.gmres.iterations;
    x_old = x, T_old = T, rho_old = rho, lambda = 1.0;
    x = along(x_old, step.dx, 1.0);
    T = T_old + step.dT;
    ++k;
    if (!(T > 0.0)) throw std::runtime_error("solve_periodic_orbit: the period turned non-positive");
  }
  res.time_steps = sh.steps;
  res.T = T;
  res.state = sh.unpack(x, T / o.steps);
  res.message = res.converged ? "periodic orbit converged" : "Newton stopped before the tolerance";
  return res;
}

OrbitResult continue_orbit(const NsParams& p, const OrbitResult& near, OrbitOptions o) {
  if (o.steps <= 0) o.steps = near.steps;
  return solve_periodic_orbit(p, near.state, near.T, o);
}

}  // namespace magnus
