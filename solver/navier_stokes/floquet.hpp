#pragma once
// Floquet stability of a time-periodic 2D state (a shedding wake) to spanwise-periodic disturbances ∝ e^{iβz}:
// the leading multipliers μ of the linearised period map, found by Arnoldi iteration on the linear time
// stepper over one period (Barkley & Henderson 1996). |μ| > 1: the disturbance grows from period to
// period; the Floquet exponent is ln|μ|/T.
//
// The linear operator is the spanwise problem of spanwise.hpp, M x_t = J(t) x, with the base flow (Ψ, Ω)(t)
// of the orbit. J is affine in the base, so with the base's Fourier series over the period,
//     b(t) = b_0 + Σ_{k=1..K} (b_k^c cos kωt + b_k^s sin kωt),   ω = 2π/T,
// J(t) = J_0 + Σ_k (cos kωt · B_k^c + sin kωt · B_k^s), where J_0 = J(b_0) and B = J(b_0 + b) − J(b_0)
// (exact: J is affine in the base, whose velocities are differences of Ψ). Which columns of R let the wake
// out is frozen at the mean flow's.
// The time step treats J_0 (the mean flow's advection, the viscous terms, the constraints) by
// Crank–Nicolson and the periodic rest by Adams–Bashforth 2; the pressure p (continuity's multiplier)
// is one unknown at the half step, implicit:
//     M (u^{n+1} − u^n)/Δt = ½ A_0 (u^{n+1} + u^n) + G p^{n+½} + ³⁄₂ B^n u^n − ½ B^{n−1} u^{n−1}   (rows with mass)
//     0 = C u^{n+1} + 2 B^n u^n − B^{n−1} u^{n−1}                                   (constraints)
// (J_0 = [A_0 G; C 0] split by columns). Carried from step to step as in plain Crank–Nicolson, the pressure
// would keep a mode of its own that flips sign each step (u = 0, p^{n+1} = −p^n): multiplier 1 exactly
// over an even number of steps. One sparse LU of [A_0 − (2/Δt)M, 2G; C, 0] serves every step of every
// period. On a steady base the period map is e^{JT}: its multipliers are e^{λT} of the same problem's
// eigenvalues (the first test). At β = 0 the orbit's own phase mode would have μ = 1 if the orbit solved
// these equations; it solves the (ψ, ζ) model's, a second discretisation, and the phase multiplier comes
// out below 1 (README).
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/shift_invert.hpp"

namespace magnus {

/// A time-periodic base state by its Fourier series over the period T (ω = 2π/T):
///     b(t) = mean + Σ_{k=1..K} (cos_part[k−1] cos kωt + sin_part[k−1] sin kωt),   fields ψ (m²/s), ζ (1/s).
struct PeriodicBase {
  NsState mean;
  std::vector<NsState> cos_part, sin_part;
  double T = 0.0;  ///< the period, s
  /// ‖ζ_K‖/‖ζ_1‖, the last harmonic kept relative to the first: how much the truncation leaves out.
  double truncation() const;
};

/// The same orbit from a phase every orbit shares: b(t + t_0), with t_0 where the first harmonic of the
/// total vorticity Σ ζ peaks (the base unchanged when that harmonic vanishes). Orbits of neighbouring
/// parameters then have neighbouring Floquet modes at phase 0.
PeriodicBase canonical_phase(PeriodicBase b);

/// The series of N states sampled uniformly over a period, t_n = nT/N, built one sample at a time (the
/// discrete Fourier sums, so the samples need not be kept); K ≤ N/2 − 1 harmonics.
class FourierAccumulator {
 public:
  FourierAccumulator(size_t nodes, int N, int K, double T);
  /// Sample n (0 ≤ n < N) of the period.
  void add(int n, const NsState& s);
  const PeriodicBase& base() const { return b_; }

 private:
  PeriodicBase b_;
  int N_;
};

/// How the multipliers are sought.
struct FloquetOptions {
  /// Time steps of the linear stepper per period. The stepper is second order and implicit in the stiff
  /// part: at Re 100 on n_θ 48 the multiplier moves 4e-4 from 250 steps to 2000 and 2e-5 from 1000.
  int steps = 400;
  int krylov = 20;      ///< Arnoldi vectors at most (one period of the stepper each)
  /// Stop sooner, once the leading multiplier's Ritz estimate ‖P x − μ x‖ (unit x) is ≤ tolerance or
  /// ≤ relative·|1 − |μ|| (a fraction of its distance from neutral: a growth rate far from 0 need not be
  /// known as closely); 0 and 0: never.
  double tolerance = 0.0, relative = 0.0;
  /// Whether a multiplier μ with Ritz estimate `residual` meets that: residual ≤ max(tolerance, relative·|1 − |μ||).
  bool met(std::complex<double> mu, double residual) const {
    return residual <= std::max(tolerance, relative * std::fabs(1.0 - std::abs(mu)));
  }
  /// Arnoldi's start (before its first period), e.g. the leading mode of a neighbouring problem on the same
  /// grid; empty or of another size: a random vector (seed).
  std::vector<double> start;
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
  double truncation = 0.0;        ///< the base's PeriodicBase::truncation
  double seconds = 0.0;           ///< wall time, s
  std::vector<double> mode;       ///< the leading multiplier's Ritz vector at phase 0 (its real part)
};

/// The periodic part of the Floquet operator, B(t) = Σ_h c_h(t) B_h (the harmonics' cos and sin parts), its
/// H matrices on the union of their patterns with each entry's H values side by side: B(t)x in one pass over
/// the entries, x and y touched once instead of H times (the stepper's every step; the matrices are
/// dimensionless like EigenProblem's).
struct HarmonicSum {
  long n = 0;
  size_t H = 0;
  std::vector<long> Ap, Ai;  ///< compressed columns of the union pattern
  std::vector<double> V;     ///< [entry][h]: B_h's value there (0 where B_h has none)
  /// The sum of B (all of size n; at least one).
  explicit HarmonicSum(const std::vector<EigenProblem>& B);
  /// y = Σ_h c[h]·B_h x (c: H coefficients; y resized by the caller to n).
  void apply(const double* c, const std::vector<double>& x, std::vector<double>& y) const;
};

/// One period of the linear stepper, P x: x (the spanwise problem's unknowns, dimensionless as
/// FloquetResult::mode) stepped `steps` times Δt = T/steps through the base's period at wavenumber β (1/m).
/// The map whose leading eigenvalues floquet_multipliers finds; its p entries are the last half step's.
/// Throws as floquet_multipliers, and for an x of the wrong size.
std::vector<double> floquet_period_map(const NsParams& p, const PeriodicBase& base, double beta, int steps,
                                       std::vector<double> x);

/// The leading Floquet multipliers at spanwise wavenumber β (1/m, ≥ 0) of the periodic base (states on
/// ns_grid(p), at least one harmonic). Throws std::invalid_argument for β < 0, T ≤ 0, no harmonic, a base
/// of the wrong size or steps < 4; std::runtime_error when a factorisation fails.
FloquetResult floquet_multipliers(const NsParams& p, const PeriodicBase& base, double beta,
                                  const FloquetOptions& o = {});

}  // namespace magnus
