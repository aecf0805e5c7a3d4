#include "solver/navier_stokes/operator.hpp"

#include "solver/navier_stokes/arakawa.hpp"

#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>

#include "solver/fft_modes.hpp"
#include "solver/navier_stokes/operator_impl.hpp"
#include "solver/pool.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

std::string fmt_time(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g s", t);
  return buf;
}

/// A CFL number for a message: 4 digits, or "not finite" (never "inf" or a 300-digit number).
std::string fmt_cfl(double c) {
  if (!std::isfinite(c)) return "not finite";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", c);
  return buf;
}

}  // namespace

void advance(const NsOperator& op, const NsState& old, NsState& next, NsStepTimes* times) {
  using clock = std::chrono::steady_clock;
  const auto t_start = clock::now();
  const PolarGrid& g = op.grid();
  const NsParams& p = op.params();
  NsOperator::Impl& im = *op.impl_;
  const int nr = g.n_r, n = g.n_theta, m = n / 2 + 1, iN = nr - 1;
  const double dt = op.dt(), h = op.d_xi(), R = g.outer_radius();
  const size_t size = size_t(nr) * n;
  if (old.psi.size() != size || old.zeta.size() != size)
    throw std::invalid_argument("advance: the state does not match the operator's grid");
  if (&old == &next) throw std::invalid_argument("advance: next may not alias old");
  std::lock_guard<std::mutex> step_lock(im.step_mutex);
  StepBuffers& b = *im.buffers;
  ThreadPool& pool = *im.pool;
  const int parts = pool.size();

  // AB2 weights for a step dt after a step dt_prev (Euler on the first step).
  const bool first = old.N_prev.size() != size || !(old.dt_prev > 0.0);
  const double r = first ? 0.0 : dt / old.dt_prev, w1 = 1.0 + 0.5 * r, w0 = -0.5 * r;

  // Circulation on r = R: dΓ_R/dt = Σ_j (−ψ_θ ζ + ν ζ_ξ)|_R Δθ. Outer ring of ζ: 0 on inflow; on outflow
  // ζ_t + (ψ_θ/J) ζ_ξ = 0, explicit upwind.
  double flux = 0.0;
  {
    const double* z = &old.zeta[size_t(iN) * n];
    const double* ps = &old.psi[size_t(iN) * n];
    const bool convect = p.outer_vorticity == NsOuterVorticity::inflow_outflow;
    for (int j = 0; j < n; ++j) {
      const int e = j + 1 == n ? 0 : j + 1, w = j == 0 ? n - 1 : j - 1;
      const double p_theta = (ps[e] - ps[w]) / (2.0 * g.d_theta);
      const double z_xi = (3.0 * z[j] - 4.0 * z[j - n] + z[j - 2 * n]) / (2.0 * h);
      flux += (-p_theta * z[j] + p.nu * z_xi) * g.d_theta;
      b.ring.p[j] = convect && p_theta > 0.0 ? z[j] - dt * p_theta / (R * R) * (z[j] - z[j - n]) / h : 0.0;
    }
    fftw_execute_dft_r2c(im.step_ring_r2c, b.ring.p, reinterpret_cast<fftw_complex*>(b.ring_hat.p));
  }
  next.Gamma_R = old.Gamma_R + dt * (w1 * flux + w0 * old.Gamma_flux_prev);
  const auto t_bc = clock::now();

  // Advection N^n (Arakawa) into next.N_prev and the Crank–Nicolson right-hand side f on rings 1…n_r−2:
  //   f = −σ_i ζ^n − Lζ^n + (2/ν)(w1 N^n + w0 N^{n−1}),  then f̂ (r2c) per thread's rings.
  next.N_prev.resize(size);
  std::vector<double> rate_part(size_t(parts), 0.0), sum_part(size_t(parts), 0.0);
  double t_adv0 = 0.0;
  pool.run([&](int t) {
    const auto c0 = clock::now();
    const int rb = im.ring_begin[t], re = im.ring_end[t];
    double rmax = 0.0, acc = 0.0;
    const double scale = 1.0 / (12.0 * g.d_theta * h), cx = 1.0 / (2.0 * g.d_theta * h);
    const double inv_h2 = 1.0 / (h * h), inv_t2 = 1.0 / (g.d_theta * g.d_theta), two_nu = 2.0 / p.nu;
    const int order = p.advection_order, order_xi = p.advection_order_xi;
    const double kappa = advection_factor(order), kappa_xi = advection_factor(order_xi);
    for (int i = rb; i < re; ++i) {
      double* N = &next.N_prev[size_t(i) * n];
      double* f = b.f.p + size_t(i) * n;
      if (i == 0 || i == iN) {
        std::fill(N, N + n, 0.0);
        std::fill(f, f + n, 0.0);
        continue;
      }
      const double *pm = &old.psi[size_t(i - 1) * n], *p0 = &old.psi[size_t(i) * n],
                   *pp = &old.psi[size_t(i + 1) * n];
      const double *zm = &old.zeta[size_t(i - 1) * n], *z0 = &old.zeta[size_t(i) * n],
                   *zp = &old.zeta[size_t(i + 1) * n];
      const double* Nold = first ? nullptr : &old.N_prev[size_t(i) * n];
      const double sigma = 2.0 * g.r[i] * g.r[i] / (p.nu * dt), inv_J = 1.0 / (g.r[i] * g.r[i]);
      double ring_rate = 0.0;
      for (int j = 0; j < n; ++j) {
        const int e = j + 1 == n ? 0 : j + 1, w = j == 0 ? n - 1 : j - 1;
        double Nij = 0.0;
        if (!p.stokes) {
          // Arakawa (1966) J = (J++ + J+× + J×+)/3 for ∂(ψ,ζ)/∂(θ,ξ); x = θ (j), y = ξ (i); order 4 in θ
          // or ξ: the combination of strides 1 and 2 (solver/navier_stokes/arakawa.hpp).
          Nij = advection_12(order, order_xi, old.psi.data(), old.zeta.data(), i, j, n, nr) * scale;
          ring_rate =
              std::max(ring_rate, kappa_xi * std::fabs(p0[e] - p0[w]) + kappa * std::fabs(pp[j] - pm[j]));
        }
        N[j] = Nij;
        const double lap = (zp[j] - 2.0 * z0[j] + zm[j]) * inv_h2 + (z0[e] - 2.0 * z0[j] + z0[w]) * inv_t2;
        const double adv = first ? Nij : w1 * Nij + w0 * Nold[j];
        f[j] = -sigma * z0[j] - lap + two_nu * adv;
        acc += f[j];
      }
      // |ψ_θ|/(JΔξ) + κ|ψ_ξ|/(JΔθ) with central differences: both share the factor 1/(2ΔθΔξ J).
      rmax = std::max(rmax, ring_rate * cx * inv_J);
    }
    rate_part[t] = rmax;
    sum_part[t] = acc;
    if (t == 0) t_adv0 = std::chrono::duration<double>(clock::now() - c0).count();
    fftw_execute_dft_r2c(im.part_r2c[t], b.f.p + size_t(rb) * n,
                         reinterpret_cast<fftw_complex*>(b.zeta_hat.p + size_t(rb) * m));
  });
  const auto t_adv = clock::now();
  double rate = std::fabs(p.omega) / g.d_theta;  // the wall ring: ψ_θ = 0, ψ_ξ = −a²ω
  double acc = 0.0;
  for (int t = 0; t < parts; ++t) rate = std::max(rate, rate_part[t]), acc += sum_part[t];
  const double cfl =
      p.stokes ? cfl_number(g, old.psi, dt, p.advection_order, p.advection_order_xi) : rate * dt;
  if (!(cfl <= kNsCflLimit))
    throw std::runtime_error("advance: at t = " + fmt_time(old.t) + " the CFL number is " + fmt_cfl(cfl) +
                             " > " + fmt_cfl(kNsCflLimit) + ": the time step " + fmt_time(dt) +
                             " is above the stability limit (reduce dt or the CFL number)");
  auto non_finite = [&](const std::string& where) {
    return std::runtime_error("advance: the flow turned non-finite at t = " + fmt_time(old.t + dt) + " (" +
                              where + "); likely cause: the time step " + fmt_time(dt) +
                              " is above the stability limit, or the grid is too coarse for Re");
  };
  if (!std::isfinite(acc)) throw non_finite("vorticity right-hand side");
  if (!std::isfinite(next.Gamma_R)) throw non_finite("circulation at R");

  // Per mode k: Helmholtz ζ̂*, Poisson ψ̂* of −J ζ̂*, and the wall closure δ_k along (φ_k, χ_k).
  std::vector<cplx> g_psi_outer(size_t(m), 0.0);
  g_psi_outer[0] = double(n) * (-next.Gamma_R / (2.0 * M_PI));
  g_psi_outer[1] = cplx(0.0, -0.5 * double(n) * p.U * R);  // r2c of U R sin θ_j
  const double target0 = -double(n) * h * p.a * p.a * p.omega;
  double t_h0 = 0.0, t_p0 = 0.0, t_w0 = 0.0;
  pool.run([&](int t) {
    int kb, ke;
    pool.split(m, t, kb, ke);
    const auto c0 = clock::now();
    im.helmholtz->solve_mode_range(b.zeta_hat.p, b.zero_hat.data(), b.ring_hat.p, kb, ke);
    const auto c1 = clock::now();
    for (int i = 1; i < nr; ++i) {
      const double J = -g.r[i] * g.r[i];
      const cplx* z = b.zeta_hat.p + size_t(i) * m;
      cplx* q = b.psi_hat.p + size_t(i) * m;
      for (int k = kb; k < ke; ++k) q[k] = J * z[k];
    }
    im.poisson->solve_mode_range(b.psi_hat.p, b.zero_hat.data(), g_psi_outer.data(), kb, ke);
    const auto c2 = clock::now();
    cplx* delta = b.delta.data();
    for (int k = kb; k < ke; ++k)
      delta[k] = ((k == 0 ? target0 : 0.0) - b.psi_hat.p[size_t(m) + k]) / im.denom[k];
    for (int i = 0; i < nr; ++i) {
      cplx* z = b.zeta_hat.p + size_t(i) * m;
      cplx* q = b.psi_hat.p + size_t(i) * m;
      const double* ph = &im.phi_t[size_t(i) * m];
      const double* ch = &im.chi_t[size_t(i) * m];
      for (int k = kb; k < ke; ++k) z[k] += delta[k] * ph[k], q[k] += delta[k] * ch[k];
    }
    if (t == 0) {
      const auto c3 = clock::now();
      t_h0 = std::chrono::duration<double>(c1 - c0).count();
      t_p0 = std::chrono::duration<double>(c2 - c1).count();
      t_w0 = std::chrono::duration<double>(c3 - c2).count();
    }
  });
  const auto t_modes = clock::now();

  // Back to the grid, ring ranges per thread: ζ and ψ scaled by 1/n_θ, ψ = 0 on the wall exactly.
  next.zeta.resize(size);
  next.psi.resize(size);
  double t_cz0 = 0.0, t_cp0 = 0.0;
  pool.run([&](int t) {
    const int rb = im.ring_begin[t], re = im.ring_end[t];
    const auto c0 = clock::now();
    fftw_execute_dft_c2r(im.part_c2r[t], reinterpret_cast<fftw_complex*>(b.zeta_hat.p + size_t(rb) * m),
                         b.zeta.p + size_t(rb) * n);
    const auto c1 = clock::now();
    fftw_execute_dft_c2r(im.part_c2r[t], reinterpret_cast<fftw_complex*>(b.psi_hat.p + size_t(rb) * m),
                         b.psi.p + size_t(rb) * n);
    const auto c2 = clock::now();
    const double inv_n = 1.0 / n;
    double s = 0.0;
    for (size_t q = size_t(rb) * n; q < size_t(re) * n; ++q) {
      next.zeta[q] = b.zeta.p[q] * inv_n;
      next.psi[q] = b.psi.p[q] * inv_n;
      s += next.zeta[q] + next.psi[q];
    }
    if (rb == 0) std::fill(next.psi.begin(), next.psi.begin() + n, 0.0);
    sum_part[t] = s;
    if (t == 0) {
      t_cz0 = std::chrono::duration<double>(c1 - c0).count();
      t_cp0 = std::chrono::duration<double>(c2 - c1).count();
    }
  });
  acc = 0.0;
  for (int t = 0; t < parts; ++t) acc += sum_part[t];
  if (!std::isfinite(acc)) {
    for (size_t q = 0; q < size; ++q)
      if (!std::isfinite(next.zeta[q]) || !std::isfinite(next.psi[q]))
        throw non_finite("ring " + std::to_string(q / n));
    throw non_finite("the fields");
  }
  next.t = old.t + dt;
  next.Gamma_flux_prev = flux;
  next.dt_prev = dt;
  next.rate_prev = dt > 0.0 ? cfl / dt : 0.0;
  if (times) {
    const auto t_end = clock::now();
    auto sec = [](clock::time_point a, clock::time_point c) {
      return std::chrono::duration<double>(c - a).count();
    };
    // Parallel regions are timed on thread 0 and scaled to the region's wall time.
    const double adv_region = sec(t_bc, t_adv), mode_region = sec(t_adv, t_modes), back = sec(t_modes, t_end);
    const double a_share = adv_region > 0.0 ? std::min(1.0, t_adv0 / adv_region) : 1.0;
    times->advection += a_share * adv_region;
    times->helmholtz += (1.0 - a_share) * adv_region;  // the r2c of the right-hand side
    const double mode_sum = t_h0 + t_p0 + t_w0;
    if (mode_sum > 0.0) {
      times->helmholtz += mode_region * t_h0 / mode_sum;
      times->poisson += mode_region * t_p0 / mode_sum;
      times->wall += mode_region * t_w0 / mode_sum;
    } else {
      times->helmholtz += mode_region;
    }
    const double fft_sum = t_cz0 + t_cp0;
    const double fft_region = std::min(back, fft_sum);
    times->helmholtz += fft_sum > 0.0 ? fft_region * t_cz0 / fft_sum : 0.0;
    times->poisson += fft_sum > 0.0 ? fft_region * t_cp0 / fft_sum : 0.0;
    times->other += sec(t_start, t_bc) + (back - fft_region);
    ++times->steps;
  }
}

}  // namespace magnus
