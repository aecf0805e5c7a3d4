// The rightmost eigenvalues of a steady state by Arnoldi on the linearised march (stepper_eigen.hpp).
#include "solver/navier_stokes/stepper_eigen.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "solver/gmres.hpp"
#include "solver/navier_stokes/map_arnoldi.hpp"
#include "solver/navier_stokes/periodic_orbit.hpp"
#include "solver/navier_stokes/stability.hpp"
#include "solver/navier_stokes/state_vector.hpp"

namespace magnus {

namespace {

/// Whether μ is one of a complex pair (not real to rounding).
bool complex_value(std::complex<double> mu) { return std::fabs(mu.imag()) > 1e-10 * std::abs(mu); }

}  // namespace

std::optional<std::complex<double>> StepperEigenResult::leading_pair() const { return rightmost_pair(eigenvalues); }

StepperEigenResult stepper_eigenvalues(const NsParams& p, const NsState& steady, const StepperEigenOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(o.span > 0.0) || !std::isfinite(o.span))
    throw std::invalid_argument("stepper_eigenvalues: the span must be > 0 (D/U)");
  const PolarGrid g = ns_grid(p);
  const size_t nodes = size_t(g.nodes());
  if (steady.psi.size() != nodes || steady.zeta.size() != nodes)
    throw std::invalid_argument("stepper_eigenvalues: the state does not match the grid");
  StepperEigenResult res;
  const double unit = stability_speed(p) / (2.0 * p.a);  // U/D in 1/s
  const double span = o.span / unit;                     // T_s, s
  const int n = std::max(1, int(std::ceil(span / cfl_time_step(p, g, steady.psi, o.cfl))));
  res.dt = span / n;
  const NsOperator op(p, res.dt);
  const StateVector sv(p, nodes);
  // x₀: one step from the steady state (Euler, its AB2 history then its own), so that the history is consistent.
  NsState first;
  advance(op, steady, first);
  const std::vector<double> x0 = sv.pack(first);
  auto march = [&](const std::vector<double>& x) {
    res.steps += n;
    return sv.pack(period_map(op, sv.unpack(x, res.dt), n));
  };
  const std::vector<double> y0 = march(x0);
  const double x0_norm = norm2(x0);
  auto P = [&](const std::vector<double>& v) {
    const double v_norm = norm2(v);
    std::vector<double> out(v.size(), 0.0);
    if (!(v_norm > 0.0)) return out;
    const double eps = 1e-8 * (1.0 + x0_norm) / v_norm;
    std::vector<double> xp(v.size());
    for (size_t i = 0; i < v.size(); ++i) xp[i] = x0[i] + eps * v[i];
    const std::vector<double> yp = march(xp);
    for (size_t i = 0; i < v.size(); ++i) out[i] = (yp[i] - y0[i]) / eps;
    return out;
  };
  auto converged = [&](const MapRitz& r) { return r.residual <= o.tol * std::abs(r.mu); };
  MapArnoldiOptions mo;
  mo.krylov = o.krylov, mo.min_vectors = o.min_vectors, mo.seed = o.seed;
  const MapArnoldiResult a = map_arnoldi(P, sv.size(), mo, [&](const std::vector<MapRitz>& ritz) {
    for (const MapRitz& r : ritz)
      if (complex_value(r.mu)) return converged(r);
    return false;
  });
  res.products = a.products;
  std::vector<std::pair<std::complex<double>, double>> found;
  for (const MapRitz& r : a.ritz)
    if (converged(r) && std::abs(r.mu) > 0.0) {
      std::complex<double> l = std::log(r.mu) / o.span;
      if (!complex_value(r.mu)) l = {l.real(), 0.0};
      found.emplace_back(l, r.residual / std::abs(r.mu));
    }
  std::stable_sort(found.begin(), found.end(), [](const auto& u, const auto& v) { return u.first.real() > v.first.real(); });
  for (const auto& [l, r] : found) res.eigenvalues.push_back(l), res.residuals.push_back(r);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace magnus
