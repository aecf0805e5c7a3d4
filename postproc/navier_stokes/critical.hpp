#pragma once
// The critical spin ratio of the viscous model: where the steady state's leading eigenvalue crosses the
// imaginary axis (Re λ = 0), by bisection on Re λ(α) of the leading complex pair over a bracket [A, B]; each α's steady state by
// Newton's method from the nearest state already solved (continuation), then leading_eigenvalues.
#include <functional>
#include <vector>

#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stability.hpp"

namespace magnus {

/// One spin ratio of the search: its steady state and that state's leading eigenvalues.
struct SpinStability {
  double alpha = 0.0;       ///< spin ratio aω/U
  bool converged = false;   ///< Newton reached a steady state (else stability is empty)
  NsState state;            ///< the steady state (the last iterate when not converged)
  StabilityResult stability;
  double newton_seconds = 0.0;  ///< wall time of the Newton solve, s
  /// Re λ of the leading complex pair (the wake's Hopf mode; the leading eigenvalue when no pair was
  /// found), U/D: the slow real far-field modes near −0.002 would otherwise bias the crossing.
  double growth() const {
    const auto l = stability.leading_pair();
    return l ? l->real() : stability.growth_rate();
  }
};

/// The crossing and its bracket.
struct CriticalSpin {
  double alpha_c = 0.0;       ///< Re λ = 0 by linear interpolation inside the final bracket
  double lo = 0.0, hi = 0.0;  ///< final bracket: Re λ changes sign between them
  SpinStability at_a, at_b;   ///< the two ends asked for
  std::vector<SpinStability> evaluations;  ///< every α solved, in order (states dropped)
  double seconds = 0.0;       ///< wall time, s
};

/// Newton from `guess` (potential_guess when null or when it fails from guess) and the leading eigenvalues
/// at spin ratio α (p.omega = α U/a). Throws std::invalid_argument when U = 0.
SpinStability spin_stability(const NsParams& p, double alpha, const NsState* guess, int count = 6);

/// Bisection for Re λ(α) = 0 on [A, B] until hi − lo ≤ tol. Throws std::invalid_argument (one line, with
/// both growth rates) when Re λ has the same sign at A and B, and std::runtime_error when Newton fails at
/// some α. progress (optional) is called after each α.
CriticalSpin critical_spin(const NsParams& p, double A, double B, double tol,
                           const std::function<void(const SpinStability&)>& progress = {});

}  // namespace magnus
