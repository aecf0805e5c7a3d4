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
#include <thread>

#include "solver/fft_modes.hpp"
#include "solver/navier_stokes/operator_impl.hpp"
#include "solver/pool.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

/// Run body(i_begin, i_end) over rings [b, e), split in two threads when the grid is large enough to pay.
template <class F>
void parallel_over_rings(int b, int e, int threads, long nodes, const F& body) {
  if (threads <= 1 || nodes < 16384 || e - b < 8) return body(b, e);
  const int mid = b + (e - b) / 2;
  std::thread other([&body, mid, e] { body(mid, e); });
  body(b, mid);
  other.join();
}

}  // namespace

NsOperator::NsOperator(const NsParams& p, double dt) : p_(p), dt_(dt) {
  auto finite = [](double x) { return std::isfinite(x); };
  if (!(p.a > 0.0) || !(p.nu > 0.0) || !(p.U >= 0.0) || !finite(p.a) || !finite(p.nu) || !finite(p.U) ||
      !finite(p.omega) || !(p.outer_over_a > 1.0) || !finite(p.outer_over_a))
    throw std::invalid_argument("NsOperator: need a > 0, nu > 0, U >= 0, finite omega and R/a > 1");
  if (p.n_theta < 8 || p.n_theta % 2 != 0)
    throw std::invalid_argument("NsOperator: n_theta must be even and >= 8, got " +
                                std::to_string(p.n_theta));
  if (!(dt > 0.0) || !finite(dt)) throw std::invalid_argument("NsOperator: dt must be positive and finite");
  grid_ = ns_grid(p);
  h_ = grid_.d_xi(0);
  const int nr = grid_.n_r, n = grid_.n_theta, m = n / 2 + 1;
  impl_ = std::make_unique<Impl>();
  std::vector<double> sigma(nr), zero(nr, 0.0);
  for (int i = 0; i < nr; ++i) sigma[i] = 2.0 * grid_.r[i] * grid_.r[i] / (p.nu * dt);
  impl_->helmholtz = std::make_unique<ModeSolver>(grid_, sigma, OuterBoundary::dirichlet, p.threads);
  impl_->poisson = std::make_unique<ModeSolver>(grid_, zero, OuterBoundary::neumann, p.threads);
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_plan_with_nthreads(std::max(1, p.threads));
    std::vector<double> real(size_t(nr) * n);
    std::vector<cplx> spec(size_t(nr) * m);
    auto* s = reinterpret_cast<fftw_complex*>(spec.data());
    const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
    impl_->ring_r2c = fftw_plan_dft_r2c_1d(n, real.data(), s, flags);
    impl_->field_c2r = fftw_plan_many_dft_c2r(1, &n, nr, s, nullptr, 1, m, real.data(), nullptr, 1, n, flags);
    impl_->field_r2c = fftw_plan_many_dft_r2c(1, &n, nr, real.data(), nullptr, 1, n, s, nullptr, 1, m, flags);
    if (!impl_->ring_r2c || !impl_->field_c2r || !impl_->field_r2c)
      throw std::runtime_error("NsOperator: FFTW planning failed");
  }
  // φ_k: Helmholtz response to unit wall vorticity in mode k. χ_k: ψ of −J φ_k (ψ = 0 at the wall,
  // ψ_ξ = 0 at R): the Poisson mode solve of mode k with right-hand side −J φ_k, all modes at once.
  impl_->phi.resize(size_t(m) * nr);
  std::vector<cplx> spec(size_t(nr) * m, 0.0), zero_hat(size_t(m), 0.0);
  for (int k = 0; k < m; ++k) {
    const std::vector<double> phi = impl_->helmholtz->influence(k);
    std::copy(phi.begin(), phi.end(), impl_->phi.begin() + size_t(k) * nr);
    for (int i = 1; i < nr; ++i) spec[size_t(i) * m + k] = -grid_.r[i] * grid_.r[i] * phi[i];
  }
  impl_->poisson->solve_mode_range(spec.data(), zero_hat.data(), zero_hat.data(), 0, m);
  impl_->chi.resize(size_t(m) * nr);
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < nr; ++i) impl_->chi[size_t(k) * nr + i] = spec[size_t(i) * m + k].real();
  impl_->denom.resize(m);
  for (int k = 0; k < m; ++k) {
    impl_->denom[k] = impl_->chi[size_t(k) * nr + 1] + 0.5 * p.a * p.a * h_ * h_;
    if (!(std::fabs(impl_->denom[k]) > 0.0))
      throw std::runtime_error("NsOperator: the wall closure of mode " + std::to_string(k) + " is singular");
  }
  impl_->phi_t.resize(size_t(m) * nr);
  impl_->chi_t.resize(size_t(m) * nr);
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < nr; ++i) {
      impl_->phi_t[size_t(i) * m + k] = impl_->phi[size_t(k) * nr + i];
      impl_->chi_t[size_t(i) * m + k] = impl_->chi[size_t(k) * nr + i];
    }
  // The step's pool, its ring ranges and their FFT plans on the step's own (aligned) buffers. FFTW_ESTIMATE:
  // the same plan every run, so a run is reproducible to the last bit (FFTW_MEASURE picks by timing).
  impl_->pool = std::make_unique<ThreadPool>(std::max(1, std::min(p.threads, nr / 4)));
  impl_->buffers = std::make_unique<StepBuffers>(size_t(nr), size_t(n), size_t(m));
  StepBuffers& b = *impl_->buffers;
  const int parts = impl_->pool->size();
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_plan_with_nthreads(1);
    const unsigned flags = FFTW_ESTIMATE;
    for (int t = 0; t < parts; ++t) {
      int rb, re;
      impl_->pool->split(nr, t, rb, re);
      impl_->ring_begin.push_back(rb);
      impl_->ring_end.push_back(re);
      const int count = re - rb;
      auto* zh = reinterpret_cast<fftw_complex*>(b.zeta_hat.p + size_t(rb) * m);
      impl_->part_r2c.push_back(fftw_plan_many_dft_r2c(1, &n, count, b.f.p + size_t(rb) * n, nullptr, 1, n,
                                                       zh, nullptr, 1, m, flags));
      impl_->part_c2r.push_back(fftw_plan_many_dft_c2r(1, &n, count, zh, nullptr, 1, m,
                                                       b.zeta.p + size_t(rb) * n, nullptr, 1, n, flags));
      if (!impl_->part_r2c.back() || !impl_->part_c2r.back())
        throw std::runtime_error("NsOperator: FFTW planning failed");
    }
    impl_->step_ring_r2c =
        fftw_plan_dft_r2c_1d(n, b.ring.p, reinterpret_cast<fftw_complex*>(b.ring_hat.p), flags);
    if (!impl_->step_ring_r2c) throw std::runtime_error("NsOperator: FFTW planning failed");
  }
}

NsOperator::~NsOperator() = default;

std::vector<double> NsOperator::advection(const std::vector<double>& psi, const std::vector<double>& zeta,
                                          double* rate) const {
  const int nr = grid_.n_r, n = grid_.n_theta;
  std::vector<double> N(size_t(nr) * n, 0.0);
  if (rate) *rate = std::fabs(p_.omega) / grid_.d_theta;  // the wall ring: ψ_θ = 0, ψ_ξ = −a²ω
  if (p_.stokes) return N;
  const double scale = 1.0 / (12.0 * grid_.d_theta * h_);
  double rate_half[2] = {0.0, 0.0};
  const int i_mid = 1 + (nr - 2) / 2;
  // Arakawa (1966) J = (J++ + J+× + J×+)/3 for ∂(ψ,ζ)/∂(θ,ξ) = ψ_θ ζ_ξ − ψ_ξ ζ_θ; x = θ (j), y = ξ (i).
  parallel_over_rings(1, nr - 1, p_.threads, grid_.nodes(), [&](int ib, int ie) {
    const double cx = 1.0 / (2.0 * grid_.d_theta * h_), cy = 1.0 / (2.0 * h_ * grid_.d_theta);
    const double kappa = advection_factor(p_.advection_order),
                 kappa_xi = advection_factor(p_.advection_order_xi);
    for (int i = ib; i < ie; ++i) {
      double rmax = 0.0;
      const double *pm = &psi[size_t(i - 1) * n], *p0 = &psi[size_t(i) * n], *pp = &psi[size_t(i + 1) * n];
      for (int j = 0; j < n; ++j) {
        const int e = j + 1 == n ? 0 : j + 1, w = j == 0 ? n - 1 : j - 1;
        N[size_t(i) * n + j] =
            advection_12(p_.advection_order, p_.advection_order_xi, psi.data(), zeta.data(), i, j, n, nr) *
            scale;
        rmax =
            std::max(rmax, kappa_xi * std::fabs(p0[e] - p0[w]) * cx + kappa * std::fabs(pp[j] - pm[j]) * cy);
      }
      rate_half[ib >= i_mid ? 1 : 0] =
          std::max(rate_half[ib >= i_mid ? 1 : 0], rmax / (grid_.r[i] * grid_.r[i]));
    }
  });
  if (rate) *rate = std::max({*rate, rate_half[0], rate_half[1]});
  return N;
}

std::vector<double> NsOperator::stream_function(const std::vector<double>& zeta, double Gamma_R) const {
  const int nr = grid_.n_r, n = grid_.n_theta;
  std::vector<double> f(size_t(nr) * n);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < n; ++j) f[size_t(i) * n + j] = -grid_.r[i] * grid_.r[i] * zeta[size_t(i) * n + j];
  const double R = grid_.outer_radius();
  std::vector<double> g_outer(n);
  for (int j = 0; j < n; ++j) g_outer[j] = p_.U * R * std::sin(grid_.theta[j]) - Gamma_R / (2.0 * M_PI);
  return impl_->poisson->solve(f, std::vector<double>(n, 0.0), g_outer);
}

void NsOperator::close_wall(std::vector<double>& psi, std::vector<double>& zeta, double Gamma_R) const {
  const int nr = grid_.n_r, n = grid_.n_theta, m = n / 2 + 1;
  psi = stream_function(zeta, Gamma_R);
  // Residual of Thom's wall row per mode, then the correction δ_k along (φ_k, χ_k) that removes it.
  std::vector<cplx> Psi1(m), W0(m), delta(m);
  std::vector<double> ring(psi.begin() + n, psi.begin() + 2 * n);
  fftw_execute_dft_r2c(impl_->ring_r2c, ring.data(), reinterpret_cast<fftw_complex*>(Psi1.data()));
  ring.assign(zeta.begin(), zeta.begin() + n);
  fftw_execute_dft_r2c(impl_->ring_r2c, ring.data(), reinterpret_cast<fftw_complex*>(W0.data()));
  const double c = 0.5 * p_.a * p_.a * h_ * h_;
  for (int k = 0; k < m; ++k) {
    const double target = k == 0 ? -double(n) * h_ * p_.a * p_.a * p_.omega : 0.0;
    delta[k] = (target - Psi1[k] - c * W0[k]) / impl_->denom[k];
  }
  std::vector<cplx> spec(size_t(nr) * m);
  std::vector<double> corr(size_t(nr) * n);
  const double inv_n = 1.0 / n;
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<double>& basis = pass == 0 ? impl_->phi : impl_->chi;
    std::vector<double>& field = pass == 0 ? zeta : psi;
    for (int i = 0; i < nr; ++i)
      for (int k = 0; k < m; ++k) spec[size_t(i) * m + k] = delta[k] * basis[size_t(k) * nr + i];
    fftw_execute_dft_c2r(impl_->field_c2r, reinterpret_cast<fftw_complex*>(spec.data()), corr.data());
    for (size_t q = 0; q < corr.size(); ++q) field[q] += corr[q] * inv_n;
  }
  std::fill(psi.begin(), psi.begin() + n, 0.0);  // ψ = 0 on the wall exactly (χ_k(0) = 0: round-off only)
}

}  // namespace magnus
