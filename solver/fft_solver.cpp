// Fast path: a real FFT in θ decouples the system into n_θ/2+1 symmetric tridiagonal systems in r,
// one per Fourier mode k, with the same closures as the matrix (circulation row for mode 0 with the
// freestream far field; the exterior factor e_k on the outer ring with the exact far field).
#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "solver/flow_solver.hpp"

namespace magnus {

namespace {

void init_fftw_threads() {
  static std::once_flag once;
  std::call_once(once, [] { fftw_init_threads(); });
}

/// Run body(k_begin, k_end) over [0, m) split across `threads` threads.
template <class F>
void parallel_over_modes(int m, int threads, F&& body) {
  if (threads <= 1 || m < 64) return body(0, m);
  std::vector<std::thread> pool;
  const int chunk = (m + threads - 1) / threads;
  for (int t = 1; t < threads; ++t) {
    const int b = std::min(m, t * chunk), e = std::min(m, (t + 1) * chunk);
    if (b < e) pool.emplace_back([&body, b, e] { body(b, e); });
  }
  body(0, std::min(m, chunk));
  for (auto& th : pool) th.join();
}

class FftSolver final : public PsiSolver {
 public:
  FftSolver(const PolarGrid& grid, const DiscreteOperator& op, int threads)
      : PsiSolver(grid, op), threads_(std::max(1, threads)) {
    const double t0 = now_s();
    n_ = op.n_theta;
    m_ = n_ / 2 + 1;
    L_ = op.last_ring();
    // Symbols T_k(i, i) and T_k(i, i+1) for rings 1…L, stored [i][k] so sweeps run along k.
    diag_.assign(size_t(L_) * m_, 0.0);
    off_.assign(size_t(L_) * m_, 0.0);
    std::vector<double> c2(m_);
    for (int k = 0; k < m_; ++k) c2[k] = 2.0 * std::cos(k * op.d_theta);
    for (int i = 1; i <= L_; ++i) {
      const RingStencil& s = op.ring[i];
      for (int k = 0; k < m_; ++k) {
        diag_[at(i, k)] = s.a[1] + c2[k] * s.b[1];
        off_[at(i, k)] = s.a[2] + c2[k] * s.b[2];
      }
    }
    if (op.far_field == FarField::exact)
      for (int k = 0; k < m_; ++k) diag_[at(L_, k)] += op.exterior(k);
    const double t1 = now_s();
    timing.assemble_s = t1 - t0;
    factor();
    init_fftw_threads();
    fftw_plan_with_nthreads(threads_);
    real_ = fftw_alloc_real(size_t(L_) * n_);
    spec_ = fftw_alloc_complex(size_t(L_) * m_);
    forward_ = fftw_plan_many_dft_r2c(1, &n_, L_, real_, nullptr, 1, n_, spec_, nullptr, 1, m_,
                                      FFTW_ESTIMATE);
    inverse_ = fftw_plan_many_dft_c2r(1, &n_, L_, spec_, nullptr, 1, m_, real_, nullptr, 1, n_,
                                      FFTW_ESTIMATE);
    if (!real_ || !spec_ || !forward_ || !inverse_) throw std::runtime_error("FFTW planning failed");
    timing.factor_s = now_s() - t1;
  }

  ~FftSolver() override {
    fftw_destroy_plan(forward_);
    fftw_destroy_plan(inverse_);
    fftw_free(real_);
    fftw_free(spec_);
  }

  std::vector<double> solve_unknowns(const std::vector<double>& rhs) override {
    std::copy(rhs.begin(), rhs.begin() + long(L_) * n_, real_);
    fftw_execute(forward_);
    auto* y = reinterpret_cast<std::complex<double>*>(spec_);
    parallel_over_modes(m_, threads_, [&](int kb, int ke) { forward_sweep(y, kb, ke); });
    double x_c = 0.0;
    if (op_.far_field == FarField::freestream) {
      // Mode 0 carries one more unknown X = n·C, coupled to ring L by −w_L.
      x_c = (rhs[size_t(L_) * n_] - lower_c_ * y[at(L_, 0)].real()) * inv_pivot_c_;
    }
    parallel_over_modes(m_, threads_, [&](int kb, int ke) { back_sweep(y, kb, ke, x_c); });
    fftw_execute(inverse_);
    std::vector<double> x(size_t(op_.unknowns()));
    const double scale = 1.0 / n_;
    for (size_t q = 0; q < size_t(L_) * n_; ++q) x[q] = real_[q] * scale;
    if (op_.far_field == FarField::freestream) x[size_t(L_) * n_] = x_c / n_;
    return x;
  }

  Method method() const override { return Method::fft; }

 private:
  size_t at(int i, int k) const { return size_t(i - 1) * m_ + k; }

  /// Symmetric tridiagonal LU of every mode: lower_[i][k] = T(i−1,i)/d'_{i−1}, inv_pivot_ = 1/d'.
  void factor() {
    lower_.assign(size_t(L_) * m_, 0.0);
    inv_pivot_.assign(size_t(L_) * m_, 0.0);
    for (int k = 0; k < m_; ++k) inv_pivot_[at(1, k)] = 1.0 / diag_[at(1, k)];
    for (int i = 2; i <= L_; ++i)
      for (int k = 0; k < m_; ++k) {
        const double l = off_[at(i - 1, k)] * inv_pivot_[at(i - 1, k)];
        lower_[at(i, k)] = l;
        inv_pivot_[at(i, k)] = 1.0 / (diag_[at(i, k)] - l * off_[at(i - 1, k)]);
      }
    for (size_t q = 0; q < inv_pivot_.size(); ++q)
      if (!(inv_pivot_[q] > 0.0) || !std::isfinite(inv_pivot_[q]))
        throw std::runtime_error("FFT path: a mode's tridiagonal system is not positive definite");
    if (op_.far_field == FarField::freestream) {
      const double w = op_.w[L_];
      off_c_ = -w;
      lower_c_ = off_c_ * inv_pivot_[at(L_, 0)];
      inv_pivot_c_ = 1.0 / (w - lower_c_ * off_c_);
      if (!(inv_pivot_c_ > 0.0)) throw std::runtime_error("FFT path: circulation row is singular");
    }
  }

  void forward_sweep(std::complex<double>* y, int kb, int ke) const {
    for (int i = 2; i <= L_; ++i) {
      const double* l = &lower_[at(i, 0)];
      std::complex<double>* yi = &y[at(i, 0)];
      const std::complex<double>* yp = &y[at(i - 1, 0)];
      for (int k = kb; k < ke; ++k) yi[k] -= l[k] * yp[k];
    }
  }

  void back_sweep(std::complex<double>* y, int kb, int ke, double x_c) const {
    {
      std::complex<double>* yL = &y[at(L_, 0)];
      const double* p = &inv_pivot_[at(L_, 0)];
      for (int k = kb; k < ke; ++k) yL[k] *= p[k];
      if (kb == 0 && op_.far_field == FarField::freestream)
        yL[0] -= off_c_ * x_c * p[0];
    }
    for (int i = L_ - 1; i >= 1; --i) {
      const double* o = &off_[at(i, 0)];
      const double* p = &inv_pivot_[at(i, 0)];
      std::complex<double>* yi = &y[at(i, 0)];
      const std::complex<double>* yn = &y[at(i + 1, 0)];
      for (int k = kb; k < ke; ++k) yi[k] = (yi[k] - o[k] * yn[k]) * p[k];
    }
  }

  int threads_;
  int n_ = 0, m_ = 0, L_ = 0;
  std::vector<double> diag_, off_, lower_, inv_pivot_;
  double off_c_ = 0.0, lower_c_ = 0.0, inv_pivot_c_ = 0.0;
  double* real_ = nullptr;
  fftw_complex* spec_ = nullptr;
  fftw_plan forward_ = nullptr, inverse_ = nullptr;
};

}  // namespace

std::unique_ptr<PsiSolver> make_fft_solver(const PolarGrid& grid, const DiscreteOperator& op,
                                           int threads) {
  return std::make_unique<FftSolver>(grid, op, threads);
}

}  // namespace magnus
