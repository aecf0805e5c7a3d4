#include "postproc/navier_stokes/pressure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/fd_weights.hpp"
#include "solver/mode_solver.hpp"
#include "solver/navier_stokes/stages.hpp"

namespace magnus {

namespace {

/// Throws std::invalid_argument naming `name` when v has not n values or one is not finite.
void require_field(const std::vector<double>& v, size_t n, const char* name) {
  if (v.size() != n)
    throw std::invalid_argument(std::string("ns_pressure_field: ") + name + " has " +
                                std::to_string(v.size()) + " values, expected " + std::to_string(n));
  for (size_t q = 0; q < n; ++q)
    if (!std::isfinite(v[q]))
      throw std::invalid_argument(std::string("ns_pressure_field: ") + name + "[" + std::to_string(q) +
                                  "] is not finite");
}

/// ∂u/∂ξ on the wall ring of the field u, one-sided second order (any ξ spacing), units of u.
std::vector<double> wall_slope(const PolarGrid& g, const std::vector<double>& u) {
  const int n = g.n_theta;
  const std::array<double, 3> w = one_sided_weights(g.d_xi(0), g.d_xi(1));
  std::vector<double> out(n);
  for (int j = 0; j < n; ++j) out[j] = w[0] * u[j] + w[1] * u[size_t(n) + j] + w[2] * u[size_t(2 * n) + j];
  return out;
}

/// J·rhs = 2ρ [(ψ_ξξ − ψ_ξ)(ψ_ξ + ψ_θθ) − (ψ_ξθ − ψ_θ)²]/r², the source of p_ξξ + p_θθ, on rings 1…n_r−2
/// (central 3-point differences on any ξ spacing, ψ_ξθ the θ-difference of ψ_ξ), Pa; 0 on the wall and
/// outer rings (ModeSolver ignores them).
std::vector<double> pressure_source(const PolarGrid& g, double rho, const std::vector<double>& psi) {
  const int n = g.n_theta, N = g.n_r - 1;
  const double dth = g.d_theta;
  std::vector<double> f(size_t(g.n_r) * n, 0.0);
  auto at = [n](int i, int j) { return size_t(i) * n + size_t((j + n) % n); };
  for (int i = 1; i < N; ++i) {
    const double r2 = g.r[i] * g.r[i];
    const std::vector<double> x{g.xi[i - 1], g.xi[i], g.xi[i + 1]};
    const std::vector<double> d1 = fd_weights(g.xi[i], x, 1), d2 = fd_weights(g.xi[i], x, 2);
    auto xi_diff = [&](const std::vector<double>& w, int j) {
      return w[0] * psi[at(i - 1, j)] + w[1] * psi[at(i, j)] + w[2] * psi[at(i + 1, j)];
    };
    for (int j = 0; j < n; ++j) {
      const double c = psi[at(i, j)];
      const double ps_xi = xi_diff(d1, j), ps_xixi = xi_diff(d2, j);
      const double ps_th = (psi[at(i, j + 1)] - psi[at(i, j - 1)]) / (2.0 * dth);
      const double ps_thth = (psi[at(i, j + 1)] - 2.0 * c + psi[at(i, j - 1)]) / (dth * dth);
      const double ps_xith = (xi_diff(d1, j + 1) - xi_diff(d1, j - 1)) / (2.0 * dth);
      const double cross = ps_xith - ps_th;
      f[at(i, j)] = 2.0 * rho * ((ps_xixi - ps_xi) * (ps_xi + ps_thth) - cross * cross) / r2;
    }
  }
  return f;
}

/// ∂p/∂ξ on the wall ring from the steady r-momentum equation, a·∂p/∂r = −ρ(a u_r ∂u_r/∂r + u_θ ∂u_r/∂θ −
/// u_θ²) − μ ∂ζ/∂θ = −(ρ/a²)[ψ_θ(ψ_ξθ − ψ_θ) − ψ_ξ ψ_θθ − ψ_ξ²] − μ ζ_θ, Pa (one-sided 3-point ψ_ξ, central
/// θ derivatives). On a no-slip wall (ψ_θ = 0, u_r ≡ 0: exact for unsteady flow too) ρ u_θ(a)² − μ ζ_θ.
std::vector<double> wall_pressure_slope(const PolarGrid& g, double rho, double mu, const NsState& s) {
  const int n = g.n_theta;
  const double dth = g.d_theta, a2 = g.a * g.a;
  const std::vector<double> ps_xi = wall_slope(g, s.psi);
  std::vector<double> out(n);
  for (int j = 0; j < n; ++j) {
    const int e = (j + 1) % n, w = (j + n - 1) % n;
    const double ps_th = (s.psi[e] - s.psi[w]) / (2.0 * dth);
    const double ps_thth = (s.psi[e] - 2.0 * s.psi[j] + s.psi[w]) / (dth * dth);
    const double ps_xith = (ps_xi[e] - ps_xi[w]) / (2.0 * dth);
    const double z_th = (s.zeta[e] - s.zeta[w]) / (2.0 * dth);
    out[j] = -rho / a2 * (ps_th * (ps_xith - ps_th) - ps_xi[j] * ps_thth - ps_xi[j] * ps_xi[j]) - mu * z_th;
  }
  return out;
}

/// |u|² = (ψ_ξ² + ψ_θ²)/R² on the outer ring (ψ_ξ one-sided 3-point, ψ_θ central), m²/s².
std::vector<double> outer_speed_squared(const PolarGrid& g, const std::vector<double>& psi) {
  const int n = g.n_theta, N = g.n_r - 1;
  const double dth = g.d_theta, R = g.outer_radius();
  const std::array<double, 3> w = outer_slope_weights(g);
  auto at = [n](int i, int j) { return size_t(i) * n + size_t((j + n) % n); };
  std::vector<double> out(n);
  for (int j = 0; j < n; ++j) {
    const double ps_xi = w[0] * psi[at(N, j)] + w[1] * psi[at(N - 1, j)] + w[2] * psi[at(N - 2, j)];
    const double ps_th = (psi[at(N, j + 1)] - psi[at(N, j - 1)]) / (2.0 * dth);
    out[j] = (ps_xi * ps_xi + ps_th * ps_th) / (R * R);
  }
  return out;
}

/// H = p + ½ρ|u|² on the outer ring r = R, integrated along it from ∂H/∂θ = −ρψ_θ ζ + μ ζ_ξ (its ring mean
/// removed; periodic cumulative trapezoid) from H = p∞ + ½ρU² at θ = π; ζ_ξ one-sided 3-point, ψ_θ
/// central, Pa.
std::vector<double> outer_head(const PolarGrid& g, const NsParams& p, double rho, double p_inf,
                               const NsState& s) {
  const int n = g.n_theta, N = g.n_r - 1;
  const double dth = g.d_theta, mu = rho * p.nu;
  const std::array<double, 3> w = outer_slope_weights(g);
  auto at = [n](int i, int j) { return size_t(i) * n + size_t((j + n) % n); };
  std::vector<double> q(n);
  double q_mean = 0.0;
  for (int j = 0; j < n; ++j) {
    const double ps_th = (s.psi[at(N, j + 1)] - s.psi[at(N, j - 1)]) / (2.0 * dth);
    const double z_xi = w[0] * s.zeta[at(N, j)] + w[1] * s.zeta[at(N - 1, j)] + w[2] * s.zeta[at(N - 2, j)];
    q[j] = -rho * ps_th * s.zeta[at(N, j)] + mu * z_xi;
    q_mean += q[j] / n;
  }
  std::vector<double> H(n, 0.0);  // ∫_0^θ_j (q − q̄) dθ; periodic because the mean is removed
  for (int j = 0; j + 1 < n; ++j) H[j + 1] = H[j] + dth * (0.5 * (q[j] + q[j + 1]) - q_mean);
  const double H_up = H[n / 2];  // θ_{n/2} = π: the upstream point of a freestream towards +x
  const double H_inf = p_inf + 0.5 * rho * p.U * p.U;
  for (int j = 0; j < n; ++j) H[j] += H_inf - H_up;
  return H;
}

}  // namespace

std::vector<double> ns_pressure_field(const PolarGrid& g, const NsParams& p, double rho, double p_inf,
                                      const NsState& s) {
  const int n = g.n_theta, nr = g.n_r;
  if (g.spacing != Spacing::geometric || nr < 4 || n < 4 || g.r.size() != size_t(nr) || g.theta.size() != size_t(n))
    throw std::invalid_argument(
        "ns_pressure_field: need a geometric grid with n_r >= 4, n_theta >= 4");
  if (!(rho > 0.0) || !std::isfinite(rho) || !std::isfinite(p_inf) || !std::isfinite(p.nu) ||
      !std::isfinite(p.U))
    throw std::invalid_argument("ns_pressure_field: need rho > 0 and finite rho, p_inf, nu and U");
  require_field(s.psi, size_t(g.nodes()), "psi");
  require_field(s.zeta, size_t(g.nodes()), "zeta");
  const double mu = rho * p.nu;

  const std::vector<double> f = pressure_source(g, rho, s.psi);
  const std::vector<double> slope = wall_pressure_slope(g, rho, mu, s);
  std::vector<double> p_outer = outer_head(g, p, rho, p_inf, s);
  const std::vector<double> u2 = outer_speed_squared(g, s.psi);
  for (int j = 0; j < n; ++j) p_outer[j] -= 0.5 * rho * u2[j];  // p = H − ½ρ|u|²

  // p_ξξ + p_θθ = f with the Dirichlet-wall solver (σ = 0): first p_D with p = 0 on the wall, then the wall
  // values W whose influence vectors make the one-sided slope (wall_slope) equal the Neumann
  // data, mode by mode: Ŵ_k = (ĝ_k − slope(p_D)_k)/φ_k'(0). The solve with wall data W is p (linearity).
  const ModeSolver solver(g, std::vector<double>(size_t(nr), 0.0), OuterBoundary::dirichlet,
                          std::max(1, p.threads));
  const std::vector<double> p_d = solver.solve(f, std::vector<double>(size_t(n), 0.0), p_outer);
  std::vector<double> deficit = wall_slope(g, p_d);
  for (int j = 0; j < n; ++j) deficit[j] = slope[j] - deficit[j];
  // Real DFT of the deficit (direct: one ring), divided per mode by the influence slope, and back.
  std::vector<double> cos_tab(n), sin_tab(n);
  for (int q = 0; q < n; ++q)
    cos_tab[q] = std::cos(2.0 * M_PI * q / n), sin_tab[q] = std::sin(2.0 * M_PI * q / n);
  std::vector<double> W(n, 0.0);
  for (int k = 0; k <= n / 2; ++k) {
    double c = 0.0, sn = 0.0;
    for (int j = 0; j < n; ++j) {
      const int q = int((long(k) * j) % n);
      c += deficit[j] * cos_tab[q];
      sn += deficit[j] * sin_tab[q];
    }
    const bool real_mode = k == 0 || 2 * k == n;  // cos only: sin(kθ_j) = 0 on the nodes
    if (real_mode) sn = 0.0;
    const double weight = real_mode ? 1.0 : 2.0;
    const double scale = weight / (double(n) * solver.influence_wall_slope(k));
    c *= scale, sn *= scale;
    for (int j = 0; j < n; ++j) {
      const int q = int((long(k) * j) % n);
      W[j] += c * cos_tab[q] + sn * sin_tab[q];
    }
  }
  return solver.solve(f, W, p_outer);
}

}  // namespace magnus
