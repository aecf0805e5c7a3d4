// The state side of the viscous model: its grid, the impulsive start, a symmetry-breaking vortex, the
// velocity of a state and its CFL number (solver/navier_stokes/operator.hpp declares them; the step is in
// navier_stokes.cpp).
#include <algorithm>
#include <cmath>

#include "mesh/fd_weights.hpp"
#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/rotation.hpp"
#include "solver/navier_stokes/state_vector.hpp"

namespace magnus {

namespace {

/// ∂ψ/∂θ at node (i, j), centred across the periodic seam; psi row-major (n_r, n).
double psi_theta_at(const std::vector<double>& psi, int i, int j, int n, double d_theta) {
  const int e = j + 1 == n ? 0 : j + 1, w = j == 0 ? n - 1 : j - 1;
  return (psi[size_t(i) * n + e] - psi[size_t(i) * n + w]) / (2.0 * d_theta);
}

/// ∂ψ/∂ξ at node (i, j) by the weights d (radial_derivative of order 2: one-sided at the wall and at R,
/// centred inside, any ξ spacing).
double psi_xi_at(const std::vector<double>& psi, int i, int j, int n, const RadialDerivative& d) {
  double s = 0.0;
  const std::vector<double>& w = d.weights[size_t(i)];
  for (size_t m = 0; m < w.size(); ++m) s += w[m] * psi[size_t(d.first[size_t(i)] + int(m)) * n + j];
  return s;
}

}  // namespace

PolarGrid ns_grid(const NsParams& p) {
  const bool grid_ok = p.n_theta > 0 && p.outer_over_a > 1.0;
  if (grid_ok && (p.wall_refinement != 1.0 || (p.n_r <= 0 && p.radial_refinement > 1.0))) {
    const double d_theta = 2.0 * M_PI / p.n_theta;
    const double d_far = p.radial_refinement > 0.0 ? d_theta / p.radial_refinement : d_theta;
    return make_stretched_grid(p.a, p.outer_over_a, p.n_r, p.n_theta, d_far, p.wall_refinement,
                               p.wall_layer);
  }
  GridRequest req;  // square cells (R rounded up to whole cells), or n_r rings as given
  req.outer_radius = p.outer_over_a;
  req.n_theta = p.n_theta;
  req.n_r = p.n_r;
  req.spacing = Spacing::geometric;
  return make_grid(req, p.a);
}

double cfl_number(const PolarGrid& g, const std::vector<double>& psi, double dt, int order_theta,
                  int order_xi, double psi_xi_ref) {
  const int nr = g.n_r, n = g.n_theta;
  const double kappa = advection_factor(order_theta), kappa_xi = advection_factor(order_xi);
  const RadialDerivative d = radial_derivative(g.xi, 2, false);
  double rate = 0.0;
  for (int i = 0; i < nr; ++i) {
    const double J = g.r[i] * g.r[i], h = g.ring_width(i);
    for (int j = 0; j < n; ++j) {
      const double p_theta = psi_theta_at(psi, i, j, n, g.d_theta);
      const double p_xi = psi_xi_at(psi, i, j, n, d) - psi_xi_ref;
      rate =
          std::max(rate, kappa_xi * std::fabs(p_theta) / (J * h) + kappa * std::fabs(p_xi) / (J * g.d_theta));
    }
  }
  return rate * dt;
}

double cfl_time_step(const NsParams& p, const PolarGrid& g, const std::vector<double>& psi, double cfl) {
  const double wall_speed = rotation_implicit(p) ? 0.0 : std::fabs(p.a * p.omega);
  const double floor_rate = advection_factor(p.advection_order) * (2.0 * p.U + wall_speed) / (p.a * g.d_theta);
  const double r = cfl_number(g, psi, 1.0, p.advection_order, p.advection_order_xi, reference_psi_xi(p));
  // ψ' of a state that is ψ_ref to round-off (the potential vortex alone): nothing moves explicitly.
  const double round_off = 1e-10 * std::fabs(p.omega) / g.d_theta;
  const double rate = std::max(r > round_off ? r : 0.0, floor_rate);
  if (!(rate > 0.0)) return 0.1 * p.a * p.a / p.nu;  // nothing moves: the diffusion time of a cell
  return cfl / rate;
}

NsState impulsive_start(const NsParams& p, const PolarGrid& g) {
  NsState s;
  const int nr = g.n_r, n = g.n_theta;
  s.psi.resize(size_t(nr) * n);
  s.zeta.assign(size_t(nr) * n, 0.0);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < n; ++j)
      s.psi[size_t(i) * n + j] = p.U * (g.r[i] - p.a * p.a / g.r[i]) * std::sin(g.theta[j]);
  return s;
}

void add_vortex_blob(const PolarGrid& g, NsState& s, double x_b, double y_b, double radius, double Gamma_b) {
  const int n = g.n_theta;
  for (int i = 1; i < g.n_r - 1; ++i)
    for (int j = 0; j < n; ++j) {
      const double dx = g.r[i] * std::cos(g.theta[j]) - x_b, dy = g.r[i] * std::sin(g.theta[j]) - y_b;
      s.zeta[size_t(i) * n + j] +=
          Gamma_b / (M_PI * radius * radius) * std::exp(-(dx * dx + dy * dy) / (radius * radius));
    }
}

void ns_velocity(const PolarGrid& g, const std::vector<double>& psi, std::vector<double>& u_r,
                 std::vector<double>& u_theta) {
  const int nr = g.n_r, n = g.n_theta;
  const RadialDerivative d = radial_derivative(g.xi, 2, false);
  u_r.assign(size_t(nr) * n, 0.0);
  u_theta.assign(size_t(nr) * n, 0.0);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < n; ++j) {
      const size_t q = size_t(i) * n + j;
      u_r[q] = psi_theta_at(psi, i, j, n, g.d_theta) / g.r[i];
      u_theta[q] = -psi_xi_at(psi, i, j, n, d) / g.r[i];
    }
}

}  // namespace magnus

namespace magnus {

StateVector::StateVector(const NsParams& p, size_t n) : nodes(n) {
  const double U = p.U > 0.0 ? p.U : std::fabs(p.a * p.omega), D = 2.0 * p.a;
  zeta = D / U, psi = 1.0 / (U * D), N = 1.0 / (U * U), Gamma = 1.0 / (U * D), flux = 1.0 / (U * U), time = U / D;
}

std::vector<double> StateVector::pack(const NsState& s) const {
  const size_t n = nodes;
  std::vector<double> x(size(), 0.0);
  for (size_t q = 0; q < n; ++q) x[q] = s.zeta[q] * zeta, x[n + q] = s.psi[q] * psi;
  if (s.N_prev.size() == n)
    for (size_t q = 0; q < n; ++q) x[2 * n + q] = s.N_prev[q] * N;
  x[3 * n] = s.Gamma_R * Gamma;
  x[3 * n + 1] = s.Gamma_flux_prev * flux;
  return x;
}

NsState StateVector::unpack(const std::vector<double>& x, double dt) const {
  const size_t n = nodes;
  NsState s;
  s.zeta.resize(n), s.psi.resize(n), s.N_prev.resize(n);
  for (size_t q = 0; q < n; ++q) s.zeta[q] = x[q] / zeta, s.psi[q] = x[n + q] / psi, s.N_prev[q] = x[2 * n + q] / N;
  s.Gamma_R = x[3 * n] / Gamma;
  s.Gamma_flux_prev = x[3 * n + 1] / flux;
  s.dt_prev = dt;
  return s;
}

}  // namespace magnus
