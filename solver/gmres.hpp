#pragma once
// GMRES (Saad & Schultz) for A x = b with A given only as a product v ↦ A v: Arnoldi with modified
// Gram–Schmidt (reorthogonalised once), the small least-squares problem by Givens rotations, no restart.
// The periodic-orbit solver (solver/navier_stokes/periodic_orbit.hpp) uses it with products from the time
// stepper; it needs nothing of the flow.
#include <functional>
#include <vector>

namespace magnus {

/// What a GMRES solve reached.
struct GmresResult {
  int iterations = 0;       ///< products A v taken
  double residual = 0.0;    ///< ‖b − A x‖/‖b‖ of the returned x (the recurrence's value), dimensionless
  bool converged = false;   ///< residual ≤ the asked tolerance
};

/// x ≈ A⁻¹ b from x = 0, stopping when ‖b − A x‖ ≤ tol·‖b‖ or after max_iter products. apply(v, out) sets
/// out = A v (out has b's size). b = 0 gives x = 0 and residual 0.
GmresResult gmres(const std::function<void(const std::vector<double>&, std::vector<double>&)>& apply,
                  const std::vector<double>& b, std::vector<double>& x, double tol, int max_iter);

/// Euclidean inner product Σ a_i b_i and norm √(Σ a_i²) of vectors of one size.
double dot(const std::vector<double>& a, const std::vector<double>& b);
double norm2(const std::vector<double>& a);

}  // namespace magnus
