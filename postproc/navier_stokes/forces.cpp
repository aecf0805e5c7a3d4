#include "postproc/navier_stokes/forces.hpp"

#include "mesh/fd_weights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

namespace magnus {

namespace {

/// ∂ζ/∂ξ on the wall ring, one-sided from the first kWallRings rings (order kWallRings − 1, any ξ
/// spacing; fewer on a grid with fewer rings), 1/s.
std::vector<double> wall_zeta_xi(const PolarGrid& g, const NsState& s) {
  const int n = g.n_theta, m = std::min(kWallRings, g.n_r);
  const std::vector<double> w = fd_weights(g.xi[0], std::vector<double>(g.xi.begin(), g.xi.begin() + m), 1);
  std::vector<double> z_xi(n, 0.0);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < n; ++j) z_xi[j] += w[size_t(k)] * s.zeta[size_t(k) * n + j];
  return z_xi;
}

}  // namespace

ViscousSurface viscous_surface(const PolarGrid& g, const NsParams& p, double rho, const NsState& s) {
  const int n = g.n_theta;
  const double mu = rho * p.nu;
  ViscousSurface out;
  out.theta = g.theta;
  out.zeta_xi = wall_zeta_xi(g, s);
  out.tau_w.resize(n);
  for (int j = 0; j < n; ++j) out.tau_w[j] = mu * (s.zeta[j] - 2.0 * p.omega);
  // p(θ) − p̄ = Σ_{0<|k|<n/2} q̂_k/(ik) e^{ikθ}, q = μ ζ_ξ (a direct DFT: n_θ is small, called rarely).
  std::vector<std::complex<double>> q_hat(n / 2);
  for (int k = 1; k < n / 2; ++k) {
    std::complex<double> sum = 0.0;
    for (int j = 0; j < n; ++j) sum += mu * out.zeta_xi[j] * std::polar(1.0, -double(k) * g.theta[j]);
    q_hat[k] = sum / double(n);
  }
  out.pressure.assign(n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int k = 1; k < n / 2; ++k)
      out.pressure[j] +=
          2.0 * (q_hat[k] / std::complex<double>(0.0, k) * std::polar(1.0, k * g.theta[j])).real();
  return out;
}

ViscousForces viscous_forces(const PolarGrid& g, const NsParams& p, double rho, const NsState& s) {
  const int n = g.n_theta;
  const double mu = rho * p.nu, a = p.a, dth = g.d_theta;
  const std::vector<double> zeta_xi = wall_zeta_xi(g, s);
  ViscousForces f;
  for (int j = 0; j < n; ++j) {
    const double c = std::cos(g.theta[j]), sn = std::sin(g.theta[j]);
    const double z_xi = zeta_xi[j];
    const double tau = mu * (s.zeta[j] - 2.0 * p.omega);
    f.F_x_pressure += mu * a * z_xi * sn * dth;
    f.F_y_pressure += -mu * a * z_xi * c * dth;
    f.F_x_friction += -tau * sn * a * dth;
    f.F_y_friction += tau * c * a * dth;
    f.M += tau * a * a * dth;
  }
  f.F_x = f.F_x_pressure + f.F_x_friction;
  f.F_y = f.F_y_pressure + f.F_y_friction;
  f.P_spin = -f.M * p.omega;
  if (p.U > 0.0) {
    const double q = 0.5 * rho * p.U * p.U, D = 2.0 * a;
    f.C_L = f.F_y / (q * D);
    f.C_D = f.F_x / (q * D);
    f.C_M = f.M / (q * D * D);
    f.C_L_pressure = f.F_y_pressure / (q * D);
    f.C_L_friction = f.F_y_friction / (q * D);
    f.C_D_pressure = f.F_x_pressure / (q * D);
    f.C_D_friction = f.F_x_friction / (q * D);
  }
  return f;
}

namespace {

/// τ_w is antisymmetric about node j (a zero by mirror symmetry, as at the rear point of a flow without
/// spin): |τ(j + k) + τ(j − k)| ≤ 1e-9·max|τ| for every k.
bool antisymmetric_about(const std::vector<double>& tau, size_t j) {
  const size_t n = tau.size();
  double big = 0.0, worst = 0.0;
  for (double t : tau) big = std::max(big, std::fabs(t));
  for (size_t k = 1; k < n; ++k) worst = std::max(worst, std::fabs(tau[(j + k) % n] + tau[(j + n - k) % n]));
  return worst <= 1e-9 * big;
}

}  // namespace

WallShearZeros wall_shear_zeros(const ViscousSurface& surf) {
  WallShearZeros out;
  const size_t n = surf.tau_w.size();
  if (n < 3) return out;
  const std::vector<double>& tau = surf.tau_w;
  const double d_theta = 2.0 * M_PI / double(n);
  for (size_t j = 0; j < n; ++j) {
    const double tm = tau[(j + n - 1) % n], t0 = tau[j], t1 = tau[(j + 1) % n];
    double th = 0.0;
    bool leaves = false;  // τ_w from + to − with θ: the wall flow on both sides runs into the point
    if (t0 == 0.0 && tm * t1 < 0.0) {
      th = surf.theta[j], leaves = tm > 0.0;
      if (leaves && antisymmetric_about(tau, j)) {  // a rear stagnation point by symmetry
        out.attachment.push_back(th);
        continue;
      }
    } else if (t0 * t1 < 0.0) {
      th = surf.theta[j] + d_theta * t0 / (t0 - t1), leaves = t0 > 0.0;
      if (th >= 2.0 * M_PI) th -= 2.0 * M_PI;
    } else {
      continue;
    }
    (leaves ? out.separation : out.attachment).push_back(th);
  }
  return out;
}

std::vector<double> separation_angles(const ViscousSurface& surf) {
  return wall_shear_zeros(surf).separation;
}

double recirculation_length(const PolarGrid& g, const NsState& s) {
  const int n = g.n_theta;
  // u_r(r_i, θ = 0) = ψ_θ/r, central in θ across the node j = 0.
  double prev = 0.0;
  for (int i = 1; i < g.n_r; ++i) {
    const double u = (s.psi[size_t(i) * n + 1] - s.psi[size_t(i) * n + n - 1]) / (2.0 * g.d_theta) / g.r[i];
    if (i > 1 && prev < 0.0 && u >= 0.0) {
      const double r0 = g.r[i - 1], r1 = g.r[i];
      const double rs = r0 + (r1 - r0) * prev / (prev - u);
      return (rs - g.a) / (2.0 * g.a);
    }
    if (i == 1 && u >= 0.0) return 0.0;  // attached: the flow leaves the rear point outwards
    prev = u;
  }
  return 0.0;
}

}  // namespace magnus
