// The wall's spin taken implicitly (rotation.hpp): ψ_ref, the stencil of J(ψ_ref, ·) read off
// advection_ring, its symbols per mode and the complex per-mode Helmholtz factors and solves.
#include "solver/navier_stokes/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/stages.hpp"

namespace magnus {

using cplx = std::complex<double>;

bool rotation_implicit(const NsParams& p) {
  return p.implicit_rotation && p.omega != 0.0 && !p.stokes && p.advection_order_xi == 2;
}

double reference_psi_xi(const NsParams& p) { return rotation_implicit(p) ? -p.a * p.a * p.omega : 0.0; }

std::vector<double> reference_psi(const PolarGrid& g, const NsParams& p) {
  const int n = g.n_theta;
  std::vector<double> psi(size_t(g.n_r) * n);
  for (int i = 0; i < g.n_r; ++i)
    std::fill(psi.begin() + size_t(i) * n, psi.begin() + size_t(i + 1) * n, -p.a * p.a * p.omega * g.xi[i]);
  return psi;
}

RotationStencil rotation_stencil(const PolarGrid& g, const NsParams& p) {
  const int nr = g.n_r, n = g.n_theta;
  RotationStencil s;
  s.n_r = nr, s.n_theta = n, s.reach = advection_reach(p.advection_order);
  const int width = 2 * s.reach + 1;
  s.w.assign(size_t(nr) * 3 * width, 0.0);
  const std::vector<double> psi = reference_psi(g, p);
  std::vector<double> zeta(size_t(nr) * n, 0.0), N(static_cast<size_t>(n), 0.0);
  for (int i = 1; i < nr - 1; ++i)
    for (int d = -1; d <= 1; ++d) {
      // A unit ζ at column 0 of ring i + d: ring i's response at column t is w_{i,d,t}.
      zeta[size_t(i + d) * n] = 1.0;
      advection_ring(g, p, psi.data(), zeta.data(), i, N.data());
      zeta[size_t(i + d) * n] = 0.0;
      for (int t = -s.reach; t <= s.reach; ++t)
        s.w[(size_t(i) * 3 + size_t(d + 1)) * width + size_t(t + s.reach)] = N[size_t((t + n) % n)];
    }
  return s;
}

namespace {

/// add_rotation_ring for θ-reach R (1 or 2): the 3·(2R + 1) weights c (scale included) in one pass over j.
template <int R>
void rotation_ring_reach(const double* c, const double* zm, const double* z0, const double* zp, int n,
                         double* out) {
  const double* z[3] = {zm, z0, zp};
  auto node = [&](int j, auto column) {
    double s = 0.0;
    for (int d = 0; d < 3; ++d)
      for (int t = -R; t <= R; ++t) s += c[d * (2 * R + 1) + t + R] * z[d][column(j - t)];
    out[j] += s;
  };
  auto wrap = [n](int q) { return q < 0 ? q + n : q >= n ? q - n : q; };
  auto inside = [](int q) { return q; };
  for (int j = 0; j < R; ++j) node(j, wrap);
  for (int j = R; j < n - R; ++j) node(j, inside);
  for (int j = n - R; j < n; ++j) node(j, wrap);
}

}  // namespace

void add_rotation_ring(const RotationStencil& s, const double* zeta, int i, double scale, double* out) {
  const int n = s.n_theta, width = 2 * s.reach + 1;
  double c[15];
  for (int d = -1; d <= 1; ++d)
    for (int t = -s.reach; t <= s.reach; ++t) c[(d + 1) * width + t + s.reach] = scale * s.at(i, d, t);
  const double *zm = zeta + size_t(i - 1) * n, *z0 = zm + n, *zp = z0 + n;
  if (s.reach == 1)
    rotation_ring_reach<1>(c, zm, z0, zp, n, out);
  else
    rotation_ring_reach<2>(c, zm, z0, zp, n, out);
}

cplx rotation_symbol(const RotationStencil& s, int i, int d, int k) {
  cplx a = 0.0;
  for (int t = -s.reach; t <= s.reach; ++t) {
    const double angle = -2.0 * M_PI * double(k) * double(t) / double(s.n_theta);
    a += s.at(i, d, t) * cplx(std::cos(angle), std::sin(angle));
  }
  return a;
}

RotationFactors factor_rotation(const PolarGrid& g, const std::vector<double>& sigma, const RotationStencil& s,
                                double nu) {
  RotationFactors f;
  const int nr = g.n_r, n = g.n_theta, m = n / 2 + 1, L = nr - 2;
  f.n_r = nr, f.m = m, f.L = L;
  f.h.assign(size_t(L) + 1, 0.0);
  for (int i = 1; i <= L; ++i) f.h[i] = 0.5 * (g.d_xi(i - 1) + g.d_xi(i));
  f.inv_pivot.assign(size_t(L) * m, 0.0);
  f.upper.assign(size_t(L) * m, 0.0);
  f.wall.resize(m);
  f.outer.resize(m);
  const double dt2 = g.d_theta * g.d_theta;
  for (int k = 0; k < m; ++k) {
    const double lambda = (2.0 - 2.0 * std::cos(k * g.d_theta)) / dt2;
    cplx upper_prev = 0.0, pivot_prev = 1.0;
    for (int i = 1; i <= L; ++i) {
      // The rows times −h_i: the mode solver's flux form plus (h_i/ν)·â_{i,d}.
      const double wm = 1.0 / g.d_xi(i - 1), wp = 1.0 / g.d_xi(i), hv = f.h[i] / nu;
      const cplx T_m = -wm + hv * rotation_symbol(s, i, -1, k);
      const cplx T_0 = wm + wp + f.h[i] * (lambda + sigma[i]) + hv * rotation_symbol(s, i, 0, k);
      const cplx T_p = -wp + hv * rotation_symbol(s, i, 1, k);
      const size_t q = size_t(i - 1) * m + k;
      if (i == 1) f.wall[k] = -T_m;
      if (i == L) f.outer[k] = -T_p;
      // Symmetric rows (T(i,i−1) = T(i−1,i), rotation.hpp): the lower factor is the upper of the ring before.
      const cplx d = i > 1 ? T_0 - upper_prev * (upper_prev / pivot_prev) : T_0;
      if (!(std::abs(d) > 0.0) || !std::isfinite(std::abs(d)))
        throw std::runtime_error("factor_rotation: mode " + std::to_string(k) + " is singular");
      f.inv_pivot[q] = 1.0 / d;
      f.upper[q] = i < L ? T_p / d : 0.0;
      upper_prev = i < L ? T_p : 0.0, pivot_prev = d;
    }
  }
  return f;
}

void solve_rotation_modes(const RotationFactors& f, cplx* u_hat, const cplx* wall_hat, const cplx* outer_hat,
                          int kb, int ke) {
  const size_t m = size_t(f.m);
  const int L = f.L;
  cplx* y = u_hat + m;  // ring i at y[(i − 1)m + k]
  for (int i = 1; i <= L; ++i) {
    const double s = -f.h[i];
    for (int k = kb; k < ke; ++k) y[size_t(i - 1) * m + k] *= s;
  }
  for (int k = kb; k < ke; ++k) y[k] += cmul(f.wall[k], wall_hat[k]);
  for (int k = kb; k < ke; ++k) y[size_t(L - 1) * m + k] += cmul(f.outer[k], outer_hat[k]);
  for (int i = 2; i <= L; ++i) {
    const cplx* l = &f.upper[size_t(i - 2) * m];  // T(i,i−1)/d'_{i−1} = T(i−1,i)/d'_{i−1}
    cplx* yi = y + size_t(i - 1) * m;
    const cplx* yp = yi - m;
    for (int k = kb; k < ke; ++k) yi[k] -= cmul(l[k], yp[k]);
  }
  for (int i = L; i >= 1; --i) {
    const cplx* p = &f.inv_pivot[size_t(i - 1) * m];
    const cplx* u = &f.upper[size_t(i - 1) * m];
    cplx* yi = y + size_t(i - 1) * m;
    if (i == L)
      for (int k = kb; k < ke; ++k) yi[k] = cmul(yi[k], p[k]);
    else
      for (int k = kb; k < ke; ++k) yi[k] = cmul(yi[k], p[k]) - cmul(u[k], yi[k + m]);
  }
  for (int k = kb; k < ke; ++k) u_hat[k] = wall_hat[k];
  for (int k = kb; k < ke; ++k) u_hat[size_t(f.n_r - 1) * m + k] = outer_hat[k];
}

std::vector<cplx> rotation_influence(const RotationFactors& f, int k) {
  if (k < 0 || k >= f.m) throw std::invalid_argument("rotation_influence: mode out of range");
  const size_t m = size_t(f.m);
  std::vector<cplx> phi(size_t(f.n_r), 0.0), rhs(size_t(f.n_r) * m, 0.0), zero(m, 0.0), unit(m, 0.0);
  unit[size_t(k)] = 1.0;
  solve_rotation_modes(f, rhs.data(), unit.data(), zero.data(), k, k + 1);
  for (int i = 0; i < f.n_r; ++i) phi[i] = rhs[size_t(i) * m + k];
  return phi;
}

}  // namespace magnus
