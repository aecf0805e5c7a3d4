// Fast path: a real FFT in θ decouples the system into n_θ/2+1 symmetric tridiagonal systems in r,
// one per Fourier mode k, with the same closures as the matrix (circulation row for mode 0 with the
// freestream far field; the exterior factor e_k on the outer ring with the exact far field).
#include <fftw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "solver/fft_modes.hpp"
#include "solver/potential/flow_solver.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

class FftSolver final : public PsiSolver {
 public:
  FftSolver(const PolarGrid& grid, const DiscreteOperator& op, int threads)
      : PsiSolver(grid, op),
        threads_(std::max(1, threads)),
        n_(op.n_theta),
        m_(n_ / 2 + 1),
        L_(op.last_ring()),
        spec_(size_t(L_) * m_),
        ring_real_(size_t(n_)),
        ring_spec_(size_t(m_)) {
    const double t0 = now_s();
    factor();
    plan();
    timing.factor_s = now_s() - t0;
  }

  ~FftSolver() override {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    for (fftw_plan p : {forward_, inverse_, ring_forward_})
      if (p) fftw_destroy_plan(p);
  }

  std::vector<double> solve_unknowns(const std::vector<double>& rhs) override {
    std::vector<double> x(size_t(op_.unknowns()), 0.0);
    // Forward transform of every ring (into the spectrum), then the sweeps, then back.
    std::copy(rhs.begin(), rhs.begin() + long(L_) * n_, x.begin());
    fftw_execute_dft_r2c(forward_, x.data(), reinterpret_cast<fftw_complex*>(spec_.p));
    cplx* y = spec_.p;
    parallel_over_modes(m_, threads_, [&](int kb, int ke) { forward_sweep(y, kb, ke); });
    const double x_c = op_.far_field == FarField::freestream
                           ? (rhs[size_t(L_) * n_] - lower_c_ * y[at(L_, 0)].real()) * inv_pivot_c_
                           : 0.0;
    parallel_over_modes(m_, threads_, [&](int kb, int ke) { back_sweep(y, kb, ke, x_c, true); });
    fftw_execute_dft_c2r(inverse_, reinterpret_cast<fftw_complex*>(spec_.p), x.data());
    const double scale = 1.0 / n_;
    for (size_t q = 0; q < size_t(L_) * n_; ++q) x[q] *= scale;
    if (op_.far_field == FarField::freestream) x[size_t(L_) * n_] = x_c / n_;
    return x;
  }

  std::vector<double> solve_boundary(const BoundaryData& bd) override {
    // Only ring L has a right-hand side: one short FFT; forward elimination leaves y_L = r̂_L.
    const double scale = 1.0 / n_;
    for (int j = 0; j < n_; ++j) ring_real_.p[j] = bd.outer[j] * scale;
    fftw_execute(ring_forward_);
    cplx* y = spec_.p;
    std::copy(ring_spec_.p, ring_spec_.p + m_, y + at(L_, 0));
    const double x_c = op_.far_field == FarField::freestream
                           ? (bd.c_rhs * scale - lower_c_ * y[at(L_, 0)].real()) * inv_pivot_c_
                           : 0.0;
    parallel_over_modes(m_, threads_, [&](int kb, int ke) { back_sweep(y, kb, ke, x_c, false); });
    std::vector<double> psi(size_t(op_.n_r) * n_);
    std::fill(psi.begin(), psi.begin() + n_, 0.0);  // ψ = 0 on the body
    fftw_execute_dft_c2r(inverse_, reinterpret_cast<fftw_complex*>(spec_.p), psi.data() + n_);
    if (op_.far_field == FarField::freestream) {
      const double C = x_c;  // X = n·C, scaled by 1/n above
      for (int j = 0; j < n_; ++j) psi[size_t(op_.n_r - 1) * n_ + j] = bd.g[j] + C;
    }
    return psi;
  }

  Method method() const override { return Method::fft; }

 private:
  size_t at(int i, int k) const { return size_t(i - 1) * m_ + k; }

  /// Symmetric tridiagonal LU of every mode, ring by ring with the symbols
  /// T_k(i,i) = a[1] + 2cos(kΔθ)·b[1] and T_k(i,i+1) = a[2] + 2cos(kΔθ)·b[2] formed on the fly:
  /// pivot d'_i = T_k(i,i) − T_k(i−1,i)·upper_{i−1}, inv_pivot_ = 1/d'_i, upper_ = T_k(i,i+1)/d'_i.
  /// (The lower factor of a symmetric matrix is upper_ of the ring before.)
  void factor() {
    // Uninitialised: the first touch (and its page faults) happens in the threads that fill them.
    inv_pivot_.reset(new double[size_t(L_) * m_]);
    upper_.reset(new double[size_t(L_) * m_]);
    std::vector<double> c2(m_), ext(m_, 0.0);
    for (int k = 0; k < m_; ++k) c2[k] = 2.0 * std::cos(k * op_.d_theta);
    if (op_.far_field == FarField::exact)
      for (int k = 0; k < m_; ++k) ext[k] = op_.exterior(k);
    std::atomic<bool> ok{true};
    parallel_over_modes(m_, threads_, [&](int kb, int ke) {
      bool good = true;
      for (int i = 1; i <= L_; ++i) {
        const RingStencil& s = op_.ring[i];
        const RingStencil& sp = op_.ring[i - 1];
        double* p = &inv_pivot_[at(i, 0)];
        double* u = &upper_[at(i, 0)];
        const double* up = i > 1 ? &upper_[at(i - 1, 0)] : nullptr;
        for (int k = kb; k < ke; ++k) {
          double d = s.a[1] + c2[k] * s.b[1] + (i == L_ ? ext[k] : 0.0);
          if (up) d -= (sp.a[2] + c2[k] * sp.b[2]) * up[k];
          p[k] = 1.0 / d;
          u[k] = (s.a[2] + c2[k] * s.b[2]) * p[k];
          good = good && d > 0.0 && std::isfinite(p[k]);
        }
      }
      if (!good) ok = false;
    });
    if (!ok) throw std::runtime_error("FFT path: a mode's tridiagonal system is not positive definite");
    if (op_.far_field == FarField::freestream) {
      const double w = op_.w[L_];
      off_c_ = -w;  // coupling of ring L (mode 0) with X = n·C
      lower_c_ = off_c_ * inv_pivot_[at(L_, 0)];
      inv_pivot_c_ = 1.0 / (w - lower_c_ * off_c_);
      if (!(inv_pivot_c_ > 0.0) || !std::isfinite(inv_pivot_c_))
        throw std::runtime_error("FFT path: the circulation row is singular");
    }
  }

  void plan() {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    static std::once_flag once;
    std::call_once(once, [] { fftw_init_threads(); });
    fftw_plan_with_nthreads(threads_);
    // Plans for many rings; executed on other arrays of the same layout (FFTW_UNALIGNED).
    // ESTIMATE plans never touch the arrays: the spectrum (L·(n/2+1) complex ≥ L·n doubles) stands in
    // for the real side too.
    const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
    auto* spec = reinterpret_cast<fftw_complex*>(spec_.p);
    auto* real = reinterpret_cast<double*>(spec_.p);
    forward_ = fftw_plan_many_dft_r2c(1, &n_, L_, real, nullptr, 1, n_, spec, nullptr, 1, m_, flags);
    inverse_ = fftw_plan_many_dft_c2r(1, &n_, L_, spec, nullptr, 1, m_, real, nullptr, 1, n_, flags);
    ring_forward_ =
        fftw_plan_dft_r2c_1d(n_, ring_real_.p, reinterpret_cast<fftw_complex*>(ring_spec_.p), FFTW_ESTIMATE);
    if (!forward_ || !inverse_ || !ring_forward_) throw std::runtime_error("FFTW planning failed");
  }

  void forward_sweep(cplx* y, int kb, int ke) const {
    for (int i = 2; i <= L_; ++i) {
      const double* l = &upper_[at(i - 1, 0)];  // T(i−1,i)/d'_{i−1}
      cplx* yi = &y[at(i, 0)];
      const cplx* yp = &y[at(i - 1, 0)];
      for (int k = kb; k < ke; ++k) yi[k] -= l[k] * yp[k];
    }
  }

  /// x_L = y_L/d'_L, x_i = y_i/d'_i − u_i·x_{i+1}; without `with_rhs` the y_i (i < L) are zero.
  void back_sweep(cplx* y, int kb, int ke, double x_c, bool with_rhs) const {
    cplx* yL = &y[at(L_, 0)];
    const double* pL = &inv_pivot_[at(L_, 0)];
    for (int k = kb; k < ke; ++k) yL[k] *= pL[k];
    if (kb == 0 && op_.far_field == FarField::freestream) yL[0] -= off_c_ * x_c * pL[0];
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

  int threads_;
  int n_, m_, L_;
  std::unique_ptr<double[]> inv_pivot_, upper_;  ///< [i][k], rings 1…L × modes 0…n/2
  double off_c_ = 0.0, lower_c_ = 0.0, inv_pivot_c_ = 0.0;
  FftwBuffer<cplx> spec_;
  FftwBuffer<double> ring_real_;
  FftwBuffer<cplx> ring_spec_;
  fftw_plan forward_ = nullptr, inverse_ = nullptr, ring_forward_ = nullptr;
};

}  // namespace

std::unique_ptr<PsiSolver> make_fft_solver(const PolarGrid& grid, const DiscreteOperator& op, int threads) {
  return std::make_unique<FftSolver>(grid, op, threads);
}

}  // namespace magnus
