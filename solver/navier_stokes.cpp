#include "solver/navier_stokes.hpp"

#include "solver/arakawa.hpp"

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
#include "solver/ns_pool.hpp"

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

std::string fmt_time(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g s", t);
  return buf;
}

}  // namespace

/// Work buffers of advance(), FFTW-aligned (the plans are made for them).
struct StepBuffers {
  FftwBuffer<double> f, zeta, psi;     ///< (n_r, n_θ): right-hand side; ζ and ψ before scaling
  FftwBuffer<cplx> zeta_hat, psi_hat;  ///< (n_r, m)
  FftwBuffer<double> ring;             ///< n_θ
  FftwBuffer<cplx> ring_hat;           ///< m
  std::vector<cplx> zero_hat, delta;   ///< m
  std::vector<double> g_outer;         ///< n_θ
  StepBuffers(size_t nr, size_t n, size_t m)
      : f(nr * n),
        zeta(nr * n),
        psi(nr * n),
        zeta_hat(nr * m),
        psi_hat(nr * m),
        ring(n),
        ring_hat(m),
        zero_hat(m, 0.0),
        delta(m),
        g_outer(n) {}
};

/// The factorisations, the influence data of the wall closure and the FFT plans of one operator.
struct NsOperator::Impl {
  std::unique_ptr<ModeSolver> helmholtz;  ///< ζ: u_ξξ + u_θθ − σ_i u = f, σ_i = 2J_i/(νΔt), Dirichlet at R
  std::unique_ptr<ModeSolver> poisson;  ///< ψ: u_ξξ + u_θθ = f, Neumann at R
  std::vector<double> phi, chi;         ///< [k][i]: φ_k(ξ_i), χ_k(ξ_i)
  std::vector<double> phi_t, chi_t;     ///< [i][k]: the same, ring-major (the step's layout)
  std::vector<double> denom;            ///< [k]: χ_k(ξ_1) + a²Δξ²/2
  fftw_plan ring_r2c = nullptr, field_c2r = nullptr, field_r2c = nullptr;
  // advance(): the pool, ring ranges per thread and their FFT plans (on `buffers`), the buffers.
  std::unique_ptr<NsPool> pool;
  std::vector<int> ring_begin, ring_end;
  std::vector<fftw_plan> part_r2c, part_c2r;
  fftw_plan step_ring_r2c = nullptr;
  std::unique_ptr<StepBuffers> buffers;
  std::mutex step_mutex;
  ~Impl() {
    pool.reset();
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    for (fftw_plan q : {ring_r2c, field_c2r, field_r2c, step_ring_r2c})
      if (q) fftw_destroy_plan(q);
    for (fftw_plan q : part_r2c)
      if (q) fftw_destroy_plan(q);
    for (fftw_plan q : part_c2r)
      if (q) fftw_destroy_plan(q);
  }
};

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
  impl_->pool = std::make_unique<NsPool>(std::max(1, std::min(p.threads, nr / 4)));
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
    for (int i = ib; i < ie; ++i) {
      double rmax = 0.0;
      const double *pm = &psi[size_t(i - 1) * n], *p0 = &psi[size_t(i) * n], *pp = &psi[size_t(i + 1) * n];
      const double *zm = &zeta[size_t(i - 1) * n], *z0 = &zeta[size_t(i) * n], *zp = &zeta[size_t(i + 1) * n];
      for (int j = 0; j < n; ++j) {
        const int e = j + 1 == n ? 0 : j + 1, w = j == 0 ? n - 1 : j - 1;
        N[size_t(i) * n + j] = arakawa_12(pm, p0, pp, zm, z0, zp, j, n) * scale;
        rmax = std::max(rmax, std::fabs(p0[e] - p0[w]) * cx + std::fabs(pp[j] - pm[j]) * cy);
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
  NsPool& pool = *im.pool;
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
          // Arakawa (1966) J = (J++ + J+× + J×+)/3 for ∂(ψ,ζ)/∂(θ,ξ); x = θ (j), y = ξ (i).
          Nij = arakawa_12(pm, p0, pp, zm, z0, zp, j, n) * scale;
          ring_rate = std::max(ring_rate, std::fabs(p0[e] - p0[w]) + std::fabs(pp[j] - pm[j]));
        }
        N[j] = Nij;
        const double lap = (zp[j] - 2.0 * z0[j] + zm[j]) * inv_h2 + (z0[e] - 2.0 * z0[j] + z0[w]) * inv_t2;
        const double adv = first ? Nij : w1 * Nij + w0 * Nold[j];
        f[j] = -sigma * z0[j] - lap + two_nu * adv;
        acc += f[j];
      }
      // |ψ_θ|/(JΔξ) + |ψ_ξ|/(JΔθ) with central differences: both share the factor 1/(2ΔθΔξ J).
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
  const double cfl = p.stokes ? cfl_number(g, old.psi, dt) : rate * dt;
  if (!(cfl <= kNsCflLimit))
    throw std::runtime_error("advance: at t = " + fmt_time(old.t) + " the CFL number is " +
                             std::to_string(cfl) + " > " + std::to_string(kNsCflLimit) + ": the time step " +
                             fmt_time(dt) + " is above the stability limit (reduce dt or the CFL number)");
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
