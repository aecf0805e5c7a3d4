#include "solver/mode_solver.hpp"

#include "solver/fft_modes.hpp"

#include <fftw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace magnus {

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}


namespace {

using cplx = std::complex<double>;

void require_size(const std::vector<double>& v, size_t n, const char* name) {
  if (v.size() != n)
    throw std::invalid_argument(std::string("ModeSolver: ") + name + " has " + std::to_string(v.size()) +
                                " values, expected " + std::to_string(n));
}

void require_finite(const std::vector<double>& v, const char* name) {
  for (size_t q = 0; q < v.size(); ++q)
    if (!std::isfinite(v[q]))
      throw std::invalid_argument(std::string("ModeSolver: ") + name + "[" + std::to_string(q) +
                                  "] is not finite");
}

}  // namespace

/// r2c / c2r plans over the L unknown rings (out of place, FFTW_UNALIGNED: executed on per-call arrays).
struct ModeSolver::Plans {
  fftw_plan forward = nullptr, inverse = nullptr;
  ~Plans() {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (inverse) fftw_destroy_plan(inverse);
  }
};

ModeSolver::ModeSolver(const PolarGrid& grid, const std::vector<double>& sigma, OuterBoundary outer,
                       int threads)
    : n_r_(grid.n_r),
      n_theta_(grid.n_theta),
      m_(grid.n_theta / 2 + 1),
      L_(outer == OuterBoundary::neumann ? grid.n_r - 1 : grid.n_r - 2),
      threads_(std::max(1, threads)),
      outer_(outer),
      d_theta_(grid.d_theta) {
  if (n_r_ < 3 || n_theta_ < 2 || grid.xi.size() != size_t(n_r_))
    throw std::invalid_argument("ModeSolver: need a grid with n_r >= 3 and n_theta >= 2");
  require_size(sigma, size_t(n_r_), "sigma");
  require_finite(sigma, "sigma");
  for (int i = 0; i < n_r_; ++i)
    if (sigma[i] < 0.0)
      throw std::invalid_argument("ModeSolver: sigma[" + std::to_string(i) +
                                  "] = " + std::to_string(sigma[i]) + " is negative (need sigma >= 0)");
  d_xi_.resize(n_r_ - 1);
  for (int i = 0; i + 1 < n_r_; ++i) {
    d_xi_[i] = grid.d_xi(i);
    if (!(d_xi_[i] > 0.0) || !std::isfinite(d_xi_[i]))
      throw std::invalid_argument("ModeSolver: grid.xi must increase strictly");
  }
  const int i_outer = n_r_ - 1;
  h_.assign(size_t(L_) + 1, 0.0);
  for (int i = 1; i <= L_; ++i)
    h_[i] = i < i_outer ? 0.5 * (d_xi_[i - 1] + d_xi_[i]) : 0.5 * d_xi_[i_outer - 1];
  factor(sigma);

  plans_ = std::make_unique<Plans>();
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  static std::once_flag once;
  std::call_once(once, [] { fftw_init_threads(); });
  fftw_plan_with_nthreads(threads_);
  // ESTIMATE plans never touch the arrays; these only fix the layout (L rings, out of place).
  std::vector<double> real(size_t(L_) * n_theta_);
  std::vector<cplx> spec(size_t(L_) * m_);
  const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
  auto* s = reinterpret_cast<fftw_complex*>(spec.data());
  int n = n_theta_;
  plans_->forward = fftw_plan_many_dft_r2c(1, &n, L_, real.data(), nullptr, 1, n, s, nullptr, 1, m_, flags);
  plans_->inverse = fftw_plan_many_dft_c2r(1, &n, L_, s, nullptr, 1, m_, real.data(), nullptr, 1, n, flags);
  if (!plans_->forward || !plans_->inverse) throw std::runtime_error("ModeSolver: FFTW planning failed");
}

ModeSolver::~ModeSolver() = default;

/// Per mode, the symmetric tridiagonal rows (equation times −h_i):
///   T(i,i−1) = −1/Δξ_{i−1/2},  T(i,i) = 1/Δξ_{i−1/2} + 1/Δξ_{i+1/2} + h_i(λ_k + σ_i),  T(i,i+1) =
///   −1/Δξ_{i+1/2}
/// (Neumann ring N: T(N,N) = 1/Δξ_{N−1/2} + h_N(λ_k + σ_N), h_N = Δξ_{N−1/2}/2). Thomas LU:
/// d'_i = T(i,i) − T(i−1,i)·upper_{i−1}, upper_i = T(i,i+1)/d'_i; the lower factor is upper_{i−1}.
void ModeSolver::factor(const std::vector<double>& sigma) {
  inv_pivot_.resize(size_t(L_) * m_);
  upper_.resize(size_t(L_) * m_);
  std::vector<double> lambda(m_);
  for (int k = 0; k < m_; ++k) lambda[k] = (2.0 - 2.0 * std::cos(k * d_theta_)) / (d_theta_ * d_theta_);
  const int i_outer = n_r_ - 1;
  std::atomic<bool> ok{true};
  parallel_over_modes(m_, threads_, [&](int kb, int ke) {
    bool good = true;
    for (int i = 1; i <= L_; ++i) {
      const double wm = 1.0 / d_xi_[i - 1], wp = i < i_outer ? 1.0 / d_xi_[i] : 0.0;
      const double off_up = i < L_ ? -wp : 0.0;  // T(i,i+1)
      for (int k = kb; k < ke; ++k) {
        double d = wm + wp + h_[i] * (lambda[k] + sigma[i]);
        if (i > 1) d -= -wm * upper_[at(i - 1, k)];  // T(i−1,i) = −1/Δξ_{i−1/2}
        inv_pivot_[at(i, k)] = 1.0 / d;
        upper_[at(i, k)] = off_up / d;
        good = good && d > 0.0 && std::isfinite(1.0 / d);
      }
    }
    if (!good) ok = false;
  });
  if (!ok) throw std::runtime_error("ModeSolver: a mode's tridiagonal system is not positive definite");
}

std::vector<double> ModeSolver::solve(const std::vector<double>& f, const std::vector<double>& g_wall,
                                      const std::vector<double>& g_outer) const {
  const size_t n = size_t(n_theta_);
  require_size(f, size_t(n_r_) * n, "f");
  require_size(g_wall, n, "g_wall");
  require_size(g_outer, n, "g_outer");
  require_finite(f, "f");
  require_finite(g_wall, "g_wall");
  require_finite(g_outer, "g_outer");
  const int i_outer = n_r_ - 1;
  // Right-hand side of rings 1…L in physical space (equation times −h_i), boundary values moved over.
  std::vector<double> u(size_t(n_r_) * n);
  double* rhs = u.data() + n;  // rings 1…L of u hold the right-hand side, then the solution
  for (int i = 1; i <= L_; ++i)
    for (size_t j = 0; j < n; ++j) rhs[(i - 1) * n + j] = -h_[i] * f[i * n + j];
  for (size_t j = 0; j < n; ++j) rhs[j] += g_wall[j] / d_xi_[0];
  if (outer_ == OuterBoundary::dirichlet)
    for (size_t j = 0; j < n; ++j) rhs[(L_ - 1) * n + j] += g_outer[j] / d_xi_[i_outer - 1];
  else
    for (size_t j = 0; j < n; ++j) rhs[(L_ - 1) * n + j] += g_outer[j];

  std::vector<cplx> spec(size_t(L_) * m_);
  cplx* y = spec.data();
  fftw_execute_dft_r2c(plans_->forward, rhs, reinterpret_cast<fftw_complex*>(y));
  parallel_over_modes(m_, threads_, [&](int kb, int ke) {
    for (int i = 2; i <= L_; ++i)  // forward: y_i −= T(i,i−1)/d'_{i−1}·y_{i−1} = upper_{i−1}·y_{i−1}
      for (int k = kb; k < ke; ++k) y[at(i, k)] -= upper_[at(i - 1, k)] * y[at(i - 1, k)];
    for (int k = kb; k < ke; ++k) y[at(L_, k)] *= inv_pivot_[at(L_, k)];
    for (int i = L_ - 1; i >= 1; --i)  // back: x_i = y_i/d'_i − upper_i·x_{i+1}
      for (int k = kb; k < ke; ++k)
        y[at(i, k)] = y[at(i, k)] * inv_pivot_[at(i, k)] - upper_[at(i, k)] * y[at(i + 1, k)];
  });
  fftw_execute_dft_c2r(plans_->inverse, reinterpret_cast<fftw_complex*>(y), rhs);
  const double scale = 1.0 / double(n);
  for (size_t q = 0; q < size_t(L_) * n; ++q) rhs[q] *= scale;
  std::copy(g_wall.begin(), g_wall.end(), u.begin());
  if (outer_ == OuterBoundary::dirichlet) std::copy(g_outer.begin(), g_outer.end(), u.begin() + i_outer * n);
  return u;
}

void ModeSolver::solve_mode_range(cplx* u_hat, const cplx* g_wall_hat, const cplx* g_outer_hat, int kb,
                                  int ke) const {
  const int i_outer = n_r_ - 1;
  const size_t m = size_t(m_);
  cplx* y = u_hat + m;  // ring i at y[at(i, k)]
  // Right-hand side (equation times −h_i) and the boundary values moved over, then Thomas, per mode.
  for (int i = 1; i <= L_; ++i) {
    const double s = -h_[i];
    for (int k = kb; k < ke; ++k) y[at(i, k)] *= s;
  }
  const double w_wall = 1.0 / d_xi_[0];
  for (int k = kb; k < ke; ++k) y[at(1, k)] += g_wall_hat[k] * w_wall;
  const double w_outer = outer_ == OuterBoundary::dirichlet ? 1.0 / d_xi_[i_outer - 1] : 1.0;
  for (int k = kb; k < ke; ++k) y[at(L_, k)] += g_outer_hat[k] * w_outer;
  for (int i = 2; i <= L_; ++i)
    for (int k = kb; k < ke; ++k) y[at(i, k)] -= upper_[at(i - 1, k)] * y[at(i - 1, k)];
  for (int k = kb; k < ke; ++k) y[at(L_, k)] *= inv_pivot_[at(L_, k)];
  for (int i = L_ - 1; i >= 1; --i)
    for (int k = kb; k < ke; ++k)
      y[at(i, k)] = y[at(i, k)] * inv_pivot_[at(i, k)] - upper_[at(i, k)] * y[at(i + 1, k)];
  for (int k = kb; k < ke; ++k) u_hat[k] = g_wall_hat[k];
  if (outer_ == OuterBoundary::dirichlet)
    for (int k = kb; k < ke; ++k) u_hat[size_t(i_outer) * m + k] = g_outer_hat[k];
}

std::vector<double> ModeSolver::influence(int k) const {
  if (k < 0 || k >= m_)
    throw std::invalid_argument("ModeSolver: mode " + std::to_string(k) + " is outside 0…" +
                                std::to_string(m_ - 1));
  std::vector<double> phi(size_t(n_r_), 0.0);
  phi[0] = 1.0;
  // Right-hand side 1/Δξ_{1/2} on ring 1 only: forward elimination gives y_i = −upper_{i−1}·y_{i−1}.
  std::vector<double> y(size_t(L_) + 1);
  y[1] = 1.0 / d_xi_[0];
  for (int i = 2; i <= L_; ++i) y[i] = -upper_[at(i - 1, k)] * y[i - 1];
  phi[L_] = y[L_] * inv_pivot_[at(L_, k)];
  for (int i = L_ - 1; i >= 1; --i) phi[i] = y[i] * inv_pivot_[at(i, k)] - upper_[at(i, k)] * phi[i + 1];
  return phi;  // Dirichlet: φ_k(ξ_N) = 0 stays
}

double ModeSolver::influence_wall_slope(int k) const {
  const std::vector<double> phi = influence(k);
  const double h1 = d_xi_[0], h2 = d_xi_[1];
  return -(2.0 * h1 + h2) / (h1 * (h1 + h2)) * phi[0] + (h1 + h2) / (h1 * h2) * phi[1] -
         h1 / (h2 * (h1 + h2)) * phi[2];
}

}  // namespace magnus
