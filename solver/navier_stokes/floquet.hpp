#pragma once
// Floquet stability of a time-periodic 2D state (a shedding wake) to spanwise-periodic disturbances ∝ e^{iβz}:
// the leading multipliers μ of the linearised period map, found by Arnoldi iteration on the linear time
// stepper over one period (Barkley & Henderson 1996). |μ| > 1: the disturbance grows from period to
// period; the Floquet exponent is ln|μ|/T.
//
// The linear operator is the spanwise problem of spanwise.hpp, M x_t = J(t) x, with the base flow (Ψ, Ω)(t)
// of the orbit. J is affine in the base, so with the base's Fourier series over the period,
//     b(t) = b_0 + Σ_{k=1..K} (b_k^c cos kωt + b_k^s sin kωt),   ω = 2π/T,
// J(t) = J_0 + Σ_k (cos kωt · B_k^c + sin kωt · B_k^s), where J_0 = J(b_0) and B = J(b_0 + εb) − J(b_0),
// divided by ε. (The outflow ζ and w̃ rows on R are rescaled to a constant mass first: ζ_t = −(Ψ_θ/R²)ζ_ξ
// is linear in Ψ only in that form. Which columns let the wake out is frozen at the mean flow's.)
// The time step treats J_0 (the mean flow's advection, the viscous terms, the constraints) by
// Crank–Nicolson and the periodic rest by Adams–Bashforth 2:
//     M (x^{n+1} − x^n)/Δt = ½ J_0 (x^{n+1} + x^n) + ³⁄₂ B^n x^n − ½ B^{n−1} x^{n−1}   (rows with mass)
//     0 = J_0 x^{n+1} + 2 B^n x^n − B^{n−1} x^{n−1}                                   (constraints)
// so one sparse LU of J_0 − (2/Δt) M serves every step of every period. At β = 0 the orbit's own phase
// mode (the base's time derivative) has μ = 1: the first test.
#include <complex>
#include <string>
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// How the multipliers are sought.
struct FloquetOptions {
  int steps = 0;        ///< time steps of the linear stepper per period (0: as many as the base has samples)
  int harmonics = 8;    ///< K, Fourier harmonics of the base kept (at most samples/2 − 1)
  int krylov = 20;      ///< Arnoldi vectors (one period of the stepper each)
  int count = 6;        ///< multipliers reported, largest |μ| first
  unsigned seed = 12345;
};

/// The multipliers and what they cost.
struct FloquetResult {
  std::vector<std::complex<double>> multipliers;  ///< largest |μ| first
  std::vector<double> residuals;  ///< Ritz estimates ‖P x − μ x‖ of each (unit x)
  double T = 0.0;                 ///< the base's period, s
  int steps = 0;                  ///< time steps per period
  int periods = 0;                ///< periods of the stepper run (products with the period map)
  int harmonics = 0;              ///< harmonics of the base kept
  /// Largest relative amplitude ‖b_K‖/‖b_1‖ of the last harmonic kept (of ζ): how much the truncation
  /// leaves out.
  double truncation = 0.0;
  double seconds = 0.0;           ///< wall time, s
};

/// The leading Floquet multipliers at spanwise wavenumber β (1/m, ≥ 0) of the periodic base sampled at
/// t_n = nT/N, n = 0…N−1 (samples: states on ns_grid(p), ψ and ζ; N ≥ 4). Throws std::invalid_argument for
/// β < 0, T ≤ 0, too few samples or samples of the wrong size; std::runtime_error when a factorisation fails.
FloquetResult floquet_multipliers(const NsParams& p, const std::vector<NsState>& samples, double T, double beta,
                                  const FloquetOptions& o = {});

}  // namespace magnus
