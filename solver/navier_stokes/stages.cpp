// The operator's stages (stages.hpp): each term of the viscous equations discretised once.
#include "solver/navier_stokes/stages.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/fd_weights.hpp"
#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/rotation.hpp"

namespace magnus {

using cplx = std::complex<double>;

namespace {

/// A ring of n values with `pad` periodic ghosts either side: out[pad + j] = ring[j], j = −pad … n − 1 + pad.
void pad_ring(const double* ring, int n, int pad, double* out) {
  std::copy(ring + n - pad, ring + n, out);
  std::copy(ring, ring + n, out + pad);
  std::copy(ring, ring + pad, out + pad + n);
}

/// out_j += weight·arakawa_12_ew at columns j = 0…n−1 of padded rings (neighbours j ± s, no wrap).
[[gnu::noinline]] void add_arakawa(const double* pm, const double* p0, const double* pp, const double* zm, const double* z0,
                 const double* zp, int n, int s, double weight, double* __restrict out) {
  for (std::ptrdiff_t j = 0; j < n; ++j) out[j] += weight * arakawa_12_ew(pm, p0, pp, zm, z0, zp, j, j + s, j - s);
}

}  // namespace

double advection_ring(const PolarGrid& g, const NsParams& p, const double* psi, const double* zeta, int i,
                      double* N) {
  const int nr = g.n_r, n = g.n_theta;
  if (p.stokes) {
    std::fill(N, N + n, 0.0);
    return 0.0;
  }
  const double scale = 1.0 / (12.0 * g.d_theta * g.ring_width(i));
  const int order = p.advection_order, order_xi = p.advection_order_xi;
  const double kappa = advection_factor(order), kappa_xi = advection_factor(order_xi);
  // Arakawa (1966) J = (J++ + J+× + J×+)/3 for ∂(ψ,ζ)/∂(θ,ξ); x = θ (j), y = ξ (i); order 4 in θ or ξ: the
  // combination of strides 1 and 2 (arakawa.hpp), each on padded copies of its rings so that the loop over
  // j has no wrap (and vectorises); the same sums as advection_12, to the last bit.
  constexpr int pad = 2;
  const int w = n + 2 * pad;
  thread_local std::vector<double> buf;
  buf.resize(size_t(6) * w);
  AdvectionStride t[2];
  const int terms = advection_terms(order, order_xi, i, nr, t);
  std::fill(N, N + n, 0.0);
  double ring_rate = 0.0;
  for (int q = 0; q < terms; ++q) {
    const int s = t[q].s_theta, d = t[q].s_xi;
    for (int k = 0; k < 3; ++k) {
      pad_ring(psi + size_t(i + (k - 1) * d) * n, n, pad, &buf[size_t(k) * w]);
      pad_ring(zeta + size_t(i + (k - 1) * d) * n, n, pad, &buf[size_t(3 + k) * w]);
    }
    const double *pm = &buf[pad], *p0 = pm + w, *pp = p0 + w, *zm = pp + w, *z0 = zm + w, *zp = z0 + w;
    add_arakawa(pm, p0, pp, zm, z0, zp, n, s, t[q].weight, N);
    if (q == 0)  // stride (1, 1): the rings i ± 1 and the columns j ± 1 of the CFL rate
      for (int j = 0; j < n; ++j)
        ring_rate =
            std::max(ring_rate, kappa_xi * std::fabs(p0[j + 1] - p0[j - 1]) + kappa * std::fabs(pp[j] - pm[j]));
  }
  for (int j = 0; j < n; ++j) N[j] *= scale;
  return ring_rate;
}

void advection_field(const PolarGrid& g, const NsParams& p, const double* psi, const double* zeta, double* N,
                     double* rate) {
  const int nr = g.n_r, n = g.n_theta;
  double r = std::fabs(p.omega) / g.d_theta;  // the wall ring: ψ_θ = 0, ψ_ξ = −a²ω
  std::fill(N, N + n, 0.0);
  std::fill(N + size_t(nr - 1) * n, N + size_t(nr) * n, 0.0);
  for (int i = 1; i < nr - 1; ++i)
    r = std::max(r, ring_cfl_rate(g, i, advection_ring(g, p, psi, zeta, i, N + size_t(i) * n)));
  if (rate) *rate = r;
}

void diffusion_rhs_ring(const PolarGrid& g, const NsParams& p, double dt, const double* zeta, int i,
                        const double* N, const double* N_prev, double w1, double w0, double* f, double& acc) {
  const int n = g.n_theta;
  const double *zm = zeta + size_t(i - 1) * n, *z0 = zeta + size_t(i) * n, *zp = zeta + size_t(i + 1) * n;
  const double sigma = 2.0 * g.r[i] * g.r[i] / (p.nu * dt) - absorbing_shift(g, p, i);
  const XiFlux x = xi_flux(g, i);
  const double inv_h2 = 1.0 / (x.h * x.h), inv_t2 = 1.0 / (g.d_theta * g.d_theta), two_nu = 2.0 / p.nu;
  double* __restrict out = f;
  auto node = [&](int j, int e, int w) {
    const SecondDifferences d = second_differences(zm, z0, zp, j, e, w, x);
    const double lap = d.xi * inv_h2 + d.theta * inv_t2;
    const double adv = N_prev ? w1 * N[j] + w0 * N_prev[j] : N[j];
    out[j] = -sigma * z0[j] - lap + two_nu * adv;
  };
  node(0, east(0, n), west(0, n));  // the wrapped columns apart: the rest vectorises
  for (int j = 1; j < n - 1; ++j) node(j, j + 1, j - 1);
  node(n - 1, east(n - 1, n), west(n - 1, n));
  double sum[2] = {0.0, 0.0};  // a finiteness check only: two partial sums, half the latency chain
  for (int j = 0; j + 1 < n; j += 2) sum[0] += out[j], sum[1] += out[j + 1];
  if (n % 2) sum[0] += out[n - 1];
  acc += sum[0] + sum[1];
}

std::array<double, 3> outer_slope_weights(const PolarGrid& g) {
  const std::array<double, 3> w = one_sided_weights(g.d_xi(g.n_r - 2), g.d_xi(g.n_r - 3));
  return {-w[0], -w[1], -w[2]};
}

double circulation_flux(const PolarGrid& g, const NsParams& p, const double* psi, const double* zeta) {
  const int n = g.n_theta;
  const std::array<double, 3> w = outer_slope_weights(g);
  const double* z = zeta + size_t(g.n_r - 1) * n;
  const double* ps = psi + size_t(g.n_r - 1) * n;
  double flux = 0.0;
  for (int j = 0; j < n; ++j) {
    const double p_theta = psi_theta(ps, j, n, g.d_theta);
    const double z_xi = w[0] * z[j] + w[1] * z[j - n] + w[2] * z[j - 2 * n];
    flux += (-p_theta * z[j] + p.nu * z_xi) * g.d_theta;
  }
  return flux - absorbed_circulation(g, p, zeta);
}

double absorbed_circulation(const PolarGrid& g, const NsParams& p, const double* zeta) {
  const int n = g.n_theta;
  double sum = 0.0;
  for (int i = 1; i + 1 < g.n_r; ++i) {
    const double w = absorbing_weight(g, p, i);
    if (w == 0.0) continue;
    double ring = 0.0;
    for (int j = 0; j < n; ++j) ring += zeta[size_t(i) * n + j];
    sum += w * ring * g.d_theta;
  }
  return sum;
}

void outer_vorticity(const PolarGrid& g, const NsParams& p, double dt, const double* psi, const double* zeta,
                     double* out) {
  const int n = g.n_theta;
  const double h = g.d_xi(g.n_r - 2);
  const double R = g.outer_radius();
  const double* z = zeta + size_t(g.n_r - 1) * n;
  const double* ps = psi + size_t(g.n_r - 1) * n;
  for (int j = 0; j < n; ++j) {
    const double p_theta = psi_theta(ps, j, n, g.d_theta);
    out[j] = outflow(p, p_theta) ? z[j] - dt * p_theta / (R * R) * (z[j] - z[j - n]) / h : 0.0;
  }
}

void far_field_hat(const PolarGrid& g, const NsParams& p, double Gamma_R, cplx* g_hat) {
  const int n = g.n_theta, m = n / 2 + 1;
  std::fill(g_hat, g_hat + m, cplx(0.0));
  g_hat[0] = double(n) * (-Gamma_R / (2.0 * M_PI));
  g_hat[1] = cplx(0.0, -0.5 * double(n) * p.U * g.outer_radius());  // r2c of U R sin θ_j
}

void helmholtz_modes(const ModeSolver& helmholtz, cplx* zeta_hat, const cplx* zero_hat, const cplx* outer_hat,
                     int kb, int ke) {
  helmholtz.solve_mode_range(zeta_hat, zero_hat, outer_hat, kb, ke);
}

void poisson_modes(const ModeSolver& poisson, const PolarGrid& g, const cplx* zeta_hat, cplx* psi_hat,
                   const cplx* zero_hat, const cplx* g_hat, int kb, int ke) {
  const int m = g.n_theta / 2 + 1;
  for (int i = 1; i < g.n_r; ++i) {
    const double J = -g.r[i] * g.r[i];
    const cplx* z = zeta_hat + size_t(i) * m;
    cplx* q = psi_hat + size_t(i) * m;
    for (int k = kb; k < ke; ++k) q[k] = J * z[k];
  }
  poisson.solve_mode_range(psi_hat, zero_hat, g_hat, kb, ke);
}

WallClosureRow wall_closure_row(const PolarGrid& g, const NsParams& p) {
  const double a2 = p.a * p.a, h0 = g.d_xi(0);
  if (p.wall_closure == NsWallClosure::thom) return {1.0, 0.0, 0.5 * a2 * h0 * h0, 1.0};
  const double rho = (h0 + g.d_xi(1)) / h0;
  return {rho * rho * rho, 1.0, 0.5 * a2 * h0 * h0 * rho * rho * (rho - 1.0), rho * (rho * rho - 1.0)};
}

namespace {

/// wall_closure_modes on real (T = double) or complex influence data.
template <class T>
void closure_modes(const WallClosureRow& c, const T* phi_t, const T* chi_t, const T* denom, const int* modes,
                   int n_r, int m, double target0, cplx* zeta_hat, cplx* psi_hat, cplx* delta, int kb, int ke) {
  for (int k = kb; k < ke; ++k) {
    const cplx psi_star = c.c1 * psi_hat[size_t(m) + k] - c.c2 * psi_hat[size_t(2 * m) + k];
    delta[k] = ((k == 0 ? target0 : 0.0) - psi_star) / denom[k];
  }
  for (int i = 0; i < n_r; ++i) {
    cplx* z = zeta_hat + size_t(i) * m;
    cplx* q = psi_hat + size_t(i) * m;
    const T* ph = &phi_t[size_t(i) * m];
    const T* ch = &chi_t[size_t(i) * m];
    const int end = modes ? std::min(ke, modes[i]) : ke;
    for (int k = kb; k < end; ++k) z[k] += cmul(delta[k], ph[k]), q[k] += cmul(delta[k], ch[k]);
  }
}

}  // namespace

void wall_closure_modes(const WallInfluence& w, int n_r, int m, double target0, cplx* zeta_hat, cplx* psi_hat,
                        cplx* delta, int kb, int ke) {
  if (w.denom_c.empty())
    closure_modes(w.row, w.phi_t.data(), w.chi_t.data(), w.denom.data(), nullptr, n_r, m, target0, zeta_hat,
                  psi_hat, delta, kb, ke);
  else
    closure_modes(w.row, w.phi_c.data(), w.chi_c.data(), w.denom_c.data(), w.modes_c.data(), n_r, m, target0,
                  zeta_hat, psi_hat, delta, kb, ke);
}

}  // namespace magnus
