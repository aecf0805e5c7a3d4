// Fast path: a real FFT in θ decouples the system into n_θ/2+1 symmetric tridiagonal systems in r,
// one per Fourier mode k, with the same closures as the matrix (circulation row for mode 0 with the
// freestream far field; the exterior factor e_k on the outer ring with the exact far field). The per-mode
// factorisation and sweeps are ModeSolver's (solver/mode_solver.hpp); this driver holds the transforms.
#include <fftw3.h>

#include <algorithm>
#include <complex>
#include <mutex>
#include <stdexcept>

#include "solver/fft_modes.hpp"
#include "solver/mode_solver.hpp"
#include "solver/potential/flow_solver.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

/// The operator's rows per mode, T_k(i,i) = a[1] + 2cos(kΔθ)·b[1] and T_k(i,i+1) = a[2] + 2cos(kΔθ)·b[2]
/// on rings 1…L, with its far field's closure: e_k on ring L (exact) or the circulation row (freestream:
/// X = n·C couples to ring L's mode 0 by −w_L).
ModeRows mode_rows(const DiscreteOperator& op) {
  ModeRows rows;
  rows.n_theta = op.n_theta;
  rows.d_theta = op.d_theta;
  const int L = op.last_ring();
  for (int i = 0; i <= L; ++i) {
    rows.diag_a.push_back(op.ring[i].a[1]);
    rows.diag_b.push_back(op.ring[i].b[1]);
    rows.off_a.push_back(op.ring[i].a[2]);
    rows.off_b.push_back(op.ring[i].b[2]);
  }
  if (op.far_field == FarField::exact)
    for (int k = 0; k <= op.n_theta / 2; ++k) rows.exterior.push_back(op.exterior(k));
  else
    rows.border = op.w[L];
  return rows;
}

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
    modes_ = std::make_unique<ModeSolver>(mode_rows(op), threads_);
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
    const bool bordered = op_.far_field == FarField::freestream;
    const double x_c = modes_->solve_spectrum(spec_.p, bordered ? rhs[size_t(L_) * n_] : 0.0, false);
    fftw_execute_dft_c2r(inverse_, reinterpret_cast<fftw_complex*>(spec_.p), x.data());
    const double scale = 1.0 / n_;
    for (size_t q = 0; q < size_t(L_) * n_; ++q) x[q] *= scale;
    if (bordered) x[size_t(L_) * n_] = x_c / n_;
    return x;
  }

  std::vector<double> solve_boundary(const BoundaryData& bd) override {
    // Only ring L has a right-hand side: one short FFT; forward elimination leaves y_L = r̂_L.
    const double scale = 1.0 / n_;
    for (int j = 0; j < n_; ++j) ring_real_.p[j] = bd.outer[j] * scale;
    fftw_execute(ring_forward_);
    std::copy(ring_spec_.p, ring_spec_.p + m_, spec_.p + size_t(L_ - 1) * m_);
    const bool bordered = op_.far_field == FarField::freestream;
    const double x_c = modes_->solve_spectrum(spec_.p, bordered ? bd.c_rhs * scale : 0.0, true);
    std::vector<double> psi(size_t(op_.n_r) * n_);
    std::fill(psi.begin(), psi.begin() + n_, 0.0);  // ψ = 0 on the body
    fftw_execute_dft_c2r(inverse_, reinterpret_cast<fftw_complex*>(spec_.p), psi.data() + n_);
    if (bordered) {
      const double C = x_c;  // X = n·C, scaled by 1/n above
      for (int j = 0; j < n_; ++j) psi[size_t(op_.n_r - 1) * n_ + j] = bd.g[j] + C;
    }
    return psi;
  }

  Method method() const override { return Method::fft; }

 private:
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

  int threads_;
  int n_, m_, L_;
  std::unique_ptr<ModeSolver> modes_;  ///< the per-mode LU and sweeps, with the far field's closure
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
