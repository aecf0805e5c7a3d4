#pragma once
// Internal to the solver layer: the state an NsOperator keeps (factorisations, wall-closure influence data,
// FFT plans, the step's pool and buffers), shared by operator.cpp (the operator) and time_step.cpp (the
// time step).
#include <fftw3.h>

#include <complex>
#include <memory>
#include <mutex>
#include <vector>

#include "solver/fft_modes.hpp"
#include "solver/mode_solver.hpp"
#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/rotation.hpp"
#include "solver/navier_stokes/stages.hpp"
#include "solver/pool.hpp"

namespace magnus {

/// Work buffers of advance(), FFTW-aligned (the plans are made for them).
struct StepBuffers {
  FftwBuffer<double> f, zeta, psi;  ///< (n_r, n_θ): right-hand side; ζ and ψ before scaling
  FftwBuffer<std::complex<double>> zeta_hat, psi_hat;  ///< (n_r, m)
  FftwBuffer<double> ring;                             ///< n_θ
  FftwBuffer<std::complex<double>> ring_hat;           ///< m
  std::vector<std::complex<double>> zero_hat, delta;   ///< m
  std::vector<double> g_outer;                         ///< n_θ
  std::vector<double> psi_prime;                       ///< ψ' = ψ − ψ_ref (n_r, n_θ): the implicit rotation only
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
  WallInfluence wall;                   ///< the same ring-major (the step's layout), and the denominators
  /// The implicit rotation (rotation_implicit(p); else empty): ψ_ref, A's stencil, the complex Helmholtz.
  std::vector<double> psi_ref;
  RotationStencil rotation_stencil;
  std::unique_ptr<RotationFactors> rotation;
  fftw_plan ring_r2c = nullptr, field_c2r = nullptr, field_r2c = nullptr;
  // advance(): the pool, ring ranges per thread and their FFT plans (on `buffers`), the buffers.
  std::unique_ptr<ThreadPool> pool;
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

}  // namespace magnus
