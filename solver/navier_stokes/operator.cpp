#include "solver/navier_stokes/operator.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/fft_modes.hpp"
#include "solver/navier_stokes/operator_impl.hpp"
#include "solver/pool.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

/// Throws std::invalid_argument unless the parameters and Δt make an operator (NsOperator's conditions).
void check_params(const NsParams& p, double dt) {
  auto finite = [](double x) { return std::isfinite(x); };
  if (!(p.a > 0.0) || !(p.nu > 0.0) || !(p.U >= 0.0) || !finite(p.a) || !finite(p.nu) || !finite(p.U) ||
      !finite(p.omega) || !(p.outer_over_a > 1.0) || !finite(p.outer_over_a))
    throw std::invalid_argument("NsOperator: need a > 0, nu > 0, U >= 0, finite omega and R/a > 1");
  if (p.n_theta < 8 || p.n_theta % 2 != 0)
    throw std::invalid_argument("NsOperator: n_theta must be even and >= 8, got " +
                                std::to_string(p.n_theta));
  if (!(p.wall_refinement >= 1.0 && p.wall_refinement <= 100.0) || !(p.wall_layer > 0.0) ||
      !finite(p.wall_layer))
    throw std::invalid_argument("NsOperator: need 1 <= wall_refinement <= 100 and wall_layer > 0");
  if (p.absorbing_start != 0.0 &&
      !(p.absorbing_start > 1.0 && p.absorbing_start < p.outer_over_a && p.absorbing_rate >= 0.0 &&
        finite(p.absorbing_rate)))
    throw std::invalid_argument("NsOperator: need 1 < absorbing_start < R/a and a finite absorbing_rate >= 0");
  if (!(dt > 0.0) || !finite(dt)) throw std::invalid_argument("NsOperator: dt must be positive and finite");
}

/// close_wall's whole-field plans (unaligned, on FFTW's threads).
void plan_fields(NsOperator::Impl& im, int nr, int n, int threads) {
  const int m = n / 2 + 1;
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_plan_with_nthreads(std::max(1, threads));
  std::vector<double> real(size_t(nr) * n);
  std::vector<cplx> spec(size_t(nr) * m);
  auto* s = reinterpret_cast<fftw_complex*>(spec.data());
  const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
  im.ring_r2c = fftw_plan_dft_r2c_1d(n, real.data(), s, flags);
  im.field_c2r = fftw_plan_many_dft_c2r(1, &n, nr, s, nullptr, 1, m, real.data(), nullptr, 1, n, flags);
  im.field_r2c = fftw_plan_many_dft_r2c(1, &n, nr, real.data(), nullptr, 1, n, s, nullptr, 1, m, flags);
  if (!im.ring_r2c || !im.field_c2r || !im.field_r2c)
    throw std::runtime_error("NsOperator: FFTW planning failed");
}

/// The wall closure's influence data. φ_k: Helmholtz response to unit wall vorticity in mode k. χ_k: ψ of
/// −J φ_k (ψ = 0 at the wall, ψ_ξ = 0 at R): the Poisson mode solve of mode k with right-hand side −J φ_k,
/// all modes at once.
void wall_influence(NsOperator::Impl& im, const PolarGrid& g, const NsParams& p) {
  const int nr = g.n_r, m = g.n_theta / 2 + 1;
  im.phi.resize(size_t(m) * nr);
  std::vector<cplx> spec(size_t(nr) * m, 0.0), zero_hat(size_t(m), 0.0);
  for (int k = 0; k < m; ++k) {
    const std::vector<double> phi = im.helmholtz->influence(k);
    std::copy(phi.begin(), phi.end(), im.phi.begin() + size_t(k) * nr);
    for (int i = 1; i < nr; ++i) spec[size_t(i) * m + k] = -g.r[i] * g.r[i] * phi[i];
  }
  im.poisson->solve_mode_range(spec.data(), zero_hat.data(), zero_hat.data(), 0, m);
  im.chi.resize(size_t(m) * nr);
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < nr; ++i) im.chi[size_t(k) * nr + i] = spec[size_t(i) * m + k].real();
  WallInfluence& w = im.wall;
  w.row = wall_closure_row(g, p);
  w.denom.resize(m);
  for (int k = 0; k < m; ++k) {
    const double* chi = &im.chi[size_t(k) * nr];
    w.denom[k] = w.row.c1 * chi[1] - w.row.c2 * chi[2] + w.row.cw;
    if (!(std::fabs(w.denom[k]) > 0.0))
      throw std::runtime_error("NsOperator: the wall closure of mode " + std::to_string(k) + " is singular");
  }
  w.phi_t.resize(size_t(m) * nr);
  w.chi_t.resize(size_t(m) * nr);
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < nr; ++i) {
      w.phi_t[size_t(i) * m + k] = im.phi[size_t(k) * nr + i];
      w.chi_t[size_t(i) * m + k] = im.chi[size_t(k) * nr + i];
    }
}

/// The step's wall-closure data with the rotation implicit: complex φ_k (rotation_influence), χ_k (the Poisson
/// mode solve of −J φ_k, all modes at once, already ring-major) and c_1χ_k(ξ_1) − c_2χ_k(ξ_2) + c_w.
void rotation_wall_influence(NsOperator::Impl& im, const PolarGrid& g) {
  const int nr = g.n_r, m = g.n_theta / 2 + 1;
  WallInfluence& w = im.wall;
  w.phi_c.assign(size_t(nr) * m, 0.0);
  w.chi_c.assign(size_t(nr) * m, 0.0);
  const std::vector<cplx> zero_hat(size_t(m), 0.0);
  for (int k = 0; k < m; ++k) {
    const std::vector<cplx> phi = rotation_influence(*im.rotation, k);
    for (int i = 0; i < nr; ++i) w.phi_c[size_t(i) * m + k] = phi[i];
    for (int i = 1; i < nr; ++i) w.chi_c[size_t(i) * m + k] = -g.r[i] * g.r[i] * phi[i];
  }
  im.poisson->solve_mode_range(w.chi_c.data(), zero_hat.data(), zero_hat.data(), 0, m);
  // Rings with φ_k or χ_k above round-off, made non-increasing in k: mode k reaches ring i iff k < modes_c[i].
  std::vector<int> reach(size_t(m), 1);
  for (int k = m - 1; k >= 0; --k) {
    double big = 0.0;
    for (int i = 0; i < nr; ++i)
      big = std::max({big, std::abs(w.phi_c[size_t(i) * m + k]), std::abs(w.chi_c[size_t(i) * m + k])});
    for (int i = nr - 1; i >= reach[k]; --i)
      if (std::abs(w.phi_c[size_t(i) * m + k]) > 1e-17 * big || std::abs(w.chi_c[size_t(i) * m + k]) > 1e-17 * big)
        reach[k] = i + 1;
    if (k + 1 < m) reach[k] = std::max(reach[k], reach[k + 1]);
  }
  w.modes_c.assign(size_t(nr), 0);
  for (int i = 0; i < nr; ++i)
    while (w.modes_c[i] < m && reach[w.modes_c[i]] > i) ++w.modes_c[i];
  w.denom_c.resize(m);
  for (int k = 0; k < m; ++k) {
    w.denom_c[k] = w.row.c1 * w.chi_c[size_t(m) + k] - w.row.c2 * w.chi_c[size_t(2 * m) + k] + w.row.cw;
    if (!(std::abs(w.denom_c[k]) > 0.0))
      throw std::runtime_error("NsOperator: the wall closure of mode " + std::to_string(k) + " is singular");
  }
}

/// The step's pool, its ring ranges and their FFT plans on the step's own (aligned) buffers. FFTW_ESTIMATE:
/// the same plan every run, so a run is reproducible to the last bit (FFTW_MEASURE picks by timing).
void plan_step(NsOperator::Impl& im, int nr, int n, int threads) {
  const int m = n / 2 + 1;
  im.pool = std::make_unique<ThreadPool>(std::max(1, std::min(threads, nr / 4)));
  im.buffers = std::make_unique<StepBuffers>(size_t(nr), size_t(n), size_t(m));
  StepBuffers& b = *im.buffers;
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_plan_with_nthreads(1);
  const unsigned flags = FFTW_ESTIMATE;
  for (int t = 0; t < im.pool->size(); ++t) {
    int rb, re;
    im.pool->split(nr, t, rb, re);
    im.ring_begin.push_back(rb);
    im.ring_end.push_back(re);
    const int count = re - rb;
    auto* zh = reinterpret_cast<fftw_complex*>(b.zeta_hat.p + size_t(rb) * m);
    im.part_r2c.push_back(fftw_plan_many_dft_r2c(1, &n, count, b.f.p + size_t(rb) * n, nullptr, 1, n, zh,
                                                 nullptr, 1, m, flags));
    im.part_c2r.push_back(fftw_plan_many_dft_c2r(1, &n, count, zh, nullptr, 1, m, b.zeta.p + size_t(rb) * n,
                                                 nullptr, 1, n, flags));
    if (!im.part_r2c.back() || !im.part_c2r.back())
      throw std::runtime_error("NsOperator: FFTW planning failed");
  }
  im.step_ring_r2c = fftw_plan_dft_r2c_1d(n, b.ring.p, reinterpret_cast<fftw_complex*>(b.ring_hat.p), flags);
  if (!im.step_ring_r2c) throw std::runtime_error("NsOperator: FFTW planning failed");
}

/// ψ from ζ with the far-field data (Neumann ψ_ξ = U R sinθ − Γ_R/2π) and ψ = 0 on the wall, m²/s.
std::vector<double> stream_function(const NsOperator& op, const ModeSolver& poisson,
                                    const std::vector<double>& zeta, double Gamma_R) {
  const PolarGrid& g = op.grid();
  const int nr = g.n_r, n = g.n_theta;
  std::vector<double> f(size_t(nr) * n);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < n; ++j) f[size_t(i) * n + j] = -g.r[i] * g.r[i] * zeta[size_t(i) * n + j];
  const double R = g.outer_radius();
  std::vector<double> g_outer(n);
  for (int j = 0; j < n; ++j) g_outer[j] = op.params().U * R * std::sin(g.theta[j]) - Gamma_R / (2.0 * M_PI);
  return poisson.solve(f, std::vector<double>(n, 0.0), g_outer);
}

}  // namespace

NsOperator::NsOperator(const NsParams& p, double dt) : p_(p), dt_(dt) {
  check_params(p, dt);
  grid_ = ns_grid(p);
  h_ = grid_.d_xi(0);
  const int nr = grid_.n_r, n = grid_.n_theta;
  impl_ = std::make_unique<Impl>();
  std::vector<double> sigma(nr), zero(nr, 0.0);
  for (int i = 0; i < nr; ++i) {  // the implicit diffusion's shift, and the absorbing layer's (stages.hpp)
    sigma[i] = 2.0 * grid_.r[i] * grid_.r[i] / (p.nu * dt);
    if (i > 0 && i + 1 < nr) sigma[i] += absorbing_shift(grid_, p, i);
  }
  impl_->helmholtz = std::make_unique<ModeSolver>(grid_, sigma, OuterBoundary::dirichlet, p.threads);
  impl_->poisson = std::make_unique<ModeSolver>(grid_, zero, OuterBoundary::neumann, p.threads);
  plan_fields(*impl_, nr, n, p.threads);
  wall_influence(*impl_, grid_, p);
  plan_step(*impl_, nr, n, p.threads);
  if (rotation_implicit(p)) {
    impl_->psi_ref = reference_psi(grid_, p);
    impl_->rotation_stencil = rotation_stencil(grid_, p);
    impl_->rotation =
        std::make_unique<RotationFactors>(factor_rotation(grid_, sigma, impl_->rotation_stencil, p.nu));
    rotation_wall_influence(*impl_, grid_);
    impl_->buffers->psi_prime.resize(size_t(nr) * n);
  }
}

NsOperator::~NsOperator() = default;

void NsOperator::close_wall(std::vector<double>& psi, std::vector<double>& zeta, double Gamma_R) const {
  const int nr = grid_.n_r, n = grid_.n_theta, m = n / 2 + 1;
  psi = stream_function(*this, *impl_->poisson, zeta, Gamma_R);
  // Residual of the wall row per mode, then the correction δ_k along (φ_k, χ_k) that removes it.
  std::vector<cplx> Psi1(m), Psi2(m), W0(m), delta(m);
  const std::pair<int, cplx*> rings[] = {{1, Psi1.data()}, {2, Psi2.data()}};
  std::vector<double> ring(static_cast<size_t>(n));
  for (const auto& r : rings) {
    ring.assign(psi.begin() + size_t(r.first) * n, psi.begin() + size_t(r.first + 1) * n);
    fftw_execute_dft_r2c(impl_->ring_r2c, ring.data(), reinterpret_cast<fftw_complex*>(r.second));
  }
  ring.assign(zeta.begin(), zeta.begin() + n);
  fftw_execute_dft_r2c(impl_->ring_r2c, ring.data(), reinterpret_cast<fftw_complex*>(W0.data()));
  const WallClosureRow& c = impl_->wall.row;
  for (int k = 0; k < m; ++k) {
    const double target = k == 0 ? -double(n) * h_ * p_.a * p_.a * p_.omega * c.kappa : 0.0;
    delta[k] = (target - (c.c1 * Psi1[k] - c.c2 * Psi2[k]) - c.cw * W0[k]) / impl_->wall.denom[k];
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
