#pragma once
// Arnoldi iteration on a real linear map given only as a product v ↦ P v: the Ritz values μ of largest
// modulus, each with its estimate ‖P x − μ x‖ (unit x). It serves the maps whose leading eigenvalues are
// wanted without a factorisation: the Floquet period map (floquet.hpp) and the linearised march about a
// steady state (stepper_eigen.hpp), where |μ| = e^{Re λ·T} puts the rightmost λ outermost.
#include <complex>
#include <functional>
#include <vector>

namespace magnus {

/// One Ritz value of the map and its residual estimate.
struct MapRitz {
  std::complex<double> mu;  ///< Ritz value (the map's eigenvalue estimate), 1
  double residual = 0.0;    ///< |h_{k+1,k} y_k|/‖y‖: the estimate of ‖P x − μ x‖ for the unit Ritz vector x
};

/// How map_arnoldi runs.
struct MapArnoldiOptions {
  int krylov = 20;       ///< Arnoldi vectors at most (one product each)
  int min_vectors = 2;   ///< vectors before `done` is first asked
  /// The start (mapped once first, so that it satisfies the map's constraints); empty or of another size: a
  /// random vector from seed.
  std::vector<double> start;
  unsigned seed = 12345;
};

/// What it found.
struct MapArnoldiResult {
  std::vector<MapRitz> ritz;    ///< all Ritz values of the last factorisation, largest |μ| first
  int products = 0;             ///< products with P (the start's included)
  std::vector<double> leading;  ///< the real part of the largest-|μ| Ritz vector (unit Ritz vector)
};

/// Arnoldi (classical Gram–Schmidt twice) on P in ℝⁿ: stops at o.krylov vectors, on an invariant subspace,
/// or once done(ritz) (asked after each vector from o.min_vectors on, the Ritz values largest |μ| first)
/// returns true. Throws std::invalid_argument for n = 0 or krylov < 1.
MapArnoldiResult map_arnoldi(const std::function<std::vector<double>(const std::vector<double>&)>& P, size_t n,
                             const MapArnoldiOptions& o,
                             const std::function<bool(const std::vector<MapRitz>&)>& done = {});

}  // namespace magnus
