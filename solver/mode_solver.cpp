#include "solver/mode_solver.hpp"

#include "mesh/fd_weights.hpp"
#include "solver/fft_modes.hpp"

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <complex>
#include <mutex>
#include <stdexcept>
#include <string>

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

/// Modes below which one thread does all the per-mode work (a split costs more than it saves).
constexpr int kPoolModes = 256;

/// Ring i's symbols in the flux form: T_k(i,i) = w_sum + h·(λ_k + σ), T_k(i,i+1) = off.
struct FluxRow {
  double w_sum, h, sigma, off_;
  const double* lambda;
  double diag(int k) const { return w_sum + h * (lambda[k] + sigma); }
  double off(int) const { return off_; }
};

/// Ring i's symbols of ModeRows: T_k(i,i) = a_d + c_k·b_d (+ e_k on ring L), T_k(i,i+1) = a_o + c_k·b_o.
struct StencilRow {
  double a_d, b_d, a_o, b_o;
  const double* c2;
  const double* ext;  ///< ring L with an exterior closure, else null
  double diag(int k) const {
    const double d = a_d + c2[k] * b_d;
    return ext ? d + ext[k] : d;
  }
  double off(int k) const { return a_o + c2[k] * b_o; }
};

}  // namespace

/// Thomas LU of every mode, ring by ring, with ring i's symbols from row(i) (diag(k) = T_k(i,i),
/// off(k) = T_k(i,i+1)): d'_i = T_k(i,i) − T_k(i−1,i)·upper_{i−1}, inv_pivot_ = 1/d'_i, upper_ =
/// T_k(i,i+1)/d'_i (kDivide) or T_k(i,i+1)·inv_pivot_ (each form as its callers always computed it, to the
/// bit). The lower factor of a symmetric matrix is upper_ of the ring before.
template <bool kDivide, class Row>
void ModeSolver::factor_modes(const Row& row) {
  // Uninitialised: the first touch (and its page faults) happens in the threads that fill them.
  inv_pivot_.reset(new double[size_t(L_) * m_]);
  upper_.reset(new double[size_t(L_) * m_]);
  std::atomic<bool> ok{true};
  over_modes([&](int kb, int ke) {
    bool good = true;
    for (int i = 1; i <= L_; ++i) {
      const auto r = row(i), rp = row(i > 1 ? i - 1 : i);
      double* p = &inv_pivot_[at(i, 0)];
      double* u = &upper_[at(i, 0)];
      const double* up = i > 1 ? &upper_[at(i - 1, 0)] : nullptr;
      for (int k = kb; k < ke; ++k) {
        double d = r.diag(k);
        if (up) d -= rp.off(k) * up[k];
        p[k] = 1.0 / d;
        u[k] = kDivide ? r.off(k) / d : r.off(k) * p[k];
        good = good && d > 0.0 && std::isfinite(p[k]);
      }
    }
    if (!good) ok = false;
  });
  if (!ok) throw std::runtime_error("ModeSolver: a mode's tridiagonal system is not positive definite");
}

/// body(kb, ke) over the modes [0, m): split over the pool, or all on the calling thread without one.
template <class F>
void ModeSolver::over_modes(const F& body) const {
  if (!pool_) return body(0, m_);
  std::lock_guard<std::mutex> lock(pool_mutex_);
  pool_->run([&](int t) {
    int kb, ke;
    pool_->split(m_, t, kb, ke);
    body(kb, ke);
  });
}

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

ModeSolver::ModeSolver(const ModeRows& rows, int threads)
    : n_r_(int(rows.diag_a.size())),
      n_theta_(rows.n_theta),
      m_(rows.n_theta / 2 + 1),
      L_(int(rows.diag_a.size()) - 1),
      threads_(std::max(1, threads)),
      outer_(OuterBoundary::dirichlet),
      d_theta_(rows.d_theta) {
  const size_t n = rows.diag_a.size();
  if (n < 2 || n_theta_ < 2 || rows.diag_b.size() != n || rows.off_a.size() != n || rows.off_b.size() != n)
    throw std::invalid_argument("ModeSolver: need rows 0…L of equal sizes, L >= 1, and n_theta >= 2");
  if (!rows.exterior.empty()) require_size(rows.exterior, size_t(m_), "exterior");
  if (threads_ > 1 && m_ >= kPoolModes) pool_ = std::make_unique<ThreadPool>(threads_);
  factor(rows);
}

ModeSolver::~ModeSolver() = default;

/// Per mode, the symmetric tridiagonal rows (equation times −h_i):
///   T(i,i−1) = −1/Δξ_{i−1/2},  T(i,i) = 1/Δξ_{i−1/2} + 1/Δξ_{i+1/2} + h_i(λ_k + σ_i),  T(i,i+1) =
///   −1/Δξ_{i+1/2}
/// (Neumann ring N: T(N,N) = 1/Δξ_{N−1/2} + h_N(λ_k + σ_N), h_N = Δξ_{N−1/2}/2).
void ModeSolver::factor(const std::vector<double>& sigma) {
  std::vector<double> lambda(m_), w_sum(size_t(L_) + 1), off(size_t(L_) + 1);
  for (int k = 0; k < m_; ++k) lambda[k] = (2.0 - 2.0 * std::cos(k * d_theta_)) / (d_theta_ * d_theta_);
  const int i_outer = n_r_ - 1;
  for (int i = 1; i <= L_; ++i) {
    const double wm = 1.0 / d_xi_[i - 1], wp = i < i_outer ? 1.0 / d_xi_[i] : 0.0;
    w_sum[i] = wm + wp;
    off[i] = i < L_ ? -wp : 0.0;
  }
  factor_modes<true>([&](int i) { return FluxRow{w_sum[i], h_[i], sigma[i], off[i], lambda.data()}; });
}

/// The rows' symbols formed per mode, c_k = 2cos(kΔθ); the exterior term on ring L; then the bordered row's
/// elimination: lower_X = off_X/d'_L (mode 0), pivot w − lower_X·off_X.
void ModeSolver::factor(const ModeRows& rows) {
  std::vector<double> c2(m_);
  for (int k = 0; k < m_; ++k) c2[k] = 2.0 * std::cos(k * d_theta_);
  factor_modes<false>([&](int i) {
    return StencilRow{rows.diag_a[i], rows.diag_b[i], rows.off_a[i], rows.off_b[i], c2.data(),
                      i == L_ && !rows.exterior.empty() ? rows.exterior.data() : nullptr};
  });
  if (rows.border == 0.0) return;
  bordered_ = true;
  off_X_ = -rows.border;
  lower_X_ = off_X_ * inv_pivot_[at(L_, 0)];
  inv_pivot_X_ = 1.0 / (rows.border - lower_X_ * off_X_);
  if (!(inv_pivot_X_ > 0.0) || !std::isfinite(inv_pivot_X_))
    throw std::runtime_error("ModeSolver: the bordered mode-0 row is singular");
}

/// Forward elimination of modes [kb, ke): y_i −= T(i,i−1)/d'_{i−1}·y_{i−1} = upper_{i−1}·y_{i−1}.
void ModeSolver::forward_sweep(cplx* y, int kb, int ke) const {
  for (int i = 2; i <= L_; ++i) {
    const double* l = &upper_[at(i - 1, 0)];
    cplx* yi = &y[at(i, 0)];
    const cplx* yp = &y[at(i - 1, 0)];
    for (int k = kb; k < ke; ++k) yi[k] -= l[k] * yp[k];
  }
}

/// Back substitution of modes [kb, ke): x_L = y_L/d'_L (less the bordered unknown X in mode 0),
/// x_i = y_i/d'_i − upper_i·x_{i+1}; without `with_rhs` the y_i (i < L) are taken as zero (not read).
void ModeSolver::back_sweep(cplx* y, int kb, int ke, double X, bool with_rhs) const {
  cplx* yL = &y[at(L_, 0)];
  const double* pL = &inv_pivot_[at(L_, 0)];
  for (int k = kb; k < ke; ++k) yL[k] *= pL[k];
  if (kb == 0 && bordered_) yL[0] -= off_X_ * X * pL[0];
  for (int i = L_ - 1; i >= 1; --i) {
    const double* u = &upper_[at(i, 0)];
    const double* p = &inv_pivot_[at(i, 0)];
    cplx* yi = &y[at(i, 0)];
    const cplx* yn = &y[at(i + 1, 0)];
    if (with_rhs)
      for (int k = kb; k < ke; ++k) yi[k] = yi[k] * p[k] - u[k] * yn[k];
    else
      for (int k = kb; k < ke; ++k) yi[k] = -u[k] * yn[k];
  }
}

double ModeSolver::solve_spectrum(cplx* y, double b_X, bool last_ring_only) const {
  if (!last_ring_only) over_modes([&](int kb, int ke) { forward_sweep(y, kb, ke); });
  // After forward elimination mode 0 of ring L holds y_L; X's row: (b_X − lower_X·y_L)/(its pivot).
  const double X = bordered_ ? (b_X - lower_X_ * y[at(L_, 0)].real()) * inv_pivot_X_ : 0.0;
  over_modes([&](int kb, int ke) { back_sweep(y, kb, ke, X, !last_ring_only); });
  return X;
}

void ModeSolver::require_grid(const char* what) const {
  if (d_xi_.empty())
    throw std::logic_error(std::string("ModeSolver: ") + what + " needs a solver built on a grid");
}

std::vector<double> ModeSolver::solve(const std::vector<double>& f, const std::vector<double>& g_wall,
                                      const std::vector<double>& g_outer) const {
  require_grid("solve()");
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
  over_modes([&](int kb, int ke) {
    forward_sweep(y, kb, ke);
    back_sweep(y, kb, ke, 0.0, true);
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
  forward_sweep(y, kb, ke);
  back_sweep(y, kb, ke, 0.0, true);
  for (int k = kb; k < ke; ++k) u_hat[k] = g_wall_hat[k];
  if (outer_ == OuterBoundary::dirichlet)
    for (int k = kb; k < ke; ++k) u_hat[size_t(i_outer) * m + k] = g_outer_hat[k];
}

std::vector<double> ModeSolver::influence(int k) const {
  require_grid("influence()");
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
  const std::array<double, 3> w = one_sided_weights(d_xi_[0], d_xi_[1]);
  return w[0] * phi[0] + w[1] * phi[1] + w[2] * phi[2];
}

}  // namespace magnus
