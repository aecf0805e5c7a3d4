#pragma once
// The rightmost eigenvalues of a steady state from the march itself, without a factorisation (the
// "time-stepper" approach of Tuckerman & Barkley): the march over a span T_s linearised about the steady
// state x₀ is a map P v = (Φ(x₀ + εv) − Φ(x₀))/ε, Φ = n steps of the AB2/CN scheme (Δt = T_s/n, state
// vectors as state_vector.hpp packs them). A mode e^{λt} of the stepper is an eigenvector of P with
// μ = e^{λT_s}, so the rightmost λ are the outermost μ, which Arnoldi (map_arnoldi.hpp) finds first; the
// scheme's parasitic AB2 modes sit near μ = 0. λ = ln μ / T_s is the time stepper's eigenvalue, which
// differs from the Jacobian's J x = λ M x (stability.hpp) by the time error of Δt (second order): it is a
// cheap, safe place for one shift-invert search at the eigenvalue itself, not a replacement for it.
// Frequencies |Im λ|·T_s ≥ π alias; the wake's (Im λ·D/U ≤ 1.4) do not at T_s ≤ 2 D/U.
#include <complex>
#include <optional>
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// How stepper_eigenvalues runs.
struct StepperEigenOptions {
  /// T_s in D/U (U_ref as in stability_speed): the march's span per product. At 1 D/U the Re 100, α 1.6
  /// wake's pair (+0.06 U/D) did not settle in 40 products; at 2 it did in 25–30.
  double span = 2.0;
  double cfl = 0.7;   ///< the march's CFL number at the steady state (Δt from it, then T_s/n exactly)
  int krylov = 40;    ///< Arnoldi vectors at most (one product each)
  int min_vectors = 10;  ///< vectors before the stopping test
  /// A Ritz value counts as converged when its estimate ‖P x − μ x‖ ≤ tol·|μ| (an error of about tol/T_s in
  /// λ, U/D); Arnoldi stops once the leading complex one has.
  double tol = 1e-3;
  unsigned seed = 12345;  ///< of the random start
};

/// The stepper's leading eigenvalues and what they cost.
struct StepperEigenResult {
  std::vector<std::complex<double>> eigenvalues;  ///< λ = ln μ / T_s of the converged Ritz values, U/D, rightmost first
  std::vector<double> residuals;                  ///< each one's ‖P x − μ x‖/|μ|, 1
  int products = 0;                               ///< products with P (each a march over T_s)
  long steps = 0;                                 ///< time steps in all
  double dt = 0.0;                                ///< the march's step, s
  double seconds = 0.0;                           ///< wall time, s
  /// The rightmost converged λ with Im λ > 0 (a pair's upper member), if any.
  std::optional<std::complex<double>> leading_pair() const;
};

/// The stepper's rightmost eigenvalues about a steady state of p (a converged solve_steady state on
/// ns_grid(p)). Throws std::invalid_argument for a state of the wrong size or span ≤ 0; a failing time step
/// (non-finite fields) propagates as std::runtime_error.
StepperEigenResult stepper_eigenvalues(const NsParams& p, const NsState& steady, const StepperEigenOptions& o = {});

}  // namespace magnus
