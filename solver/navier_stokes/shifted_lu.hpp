#pragma once
// What both shift-invert backends (the hand-written Krylov–Schur Arnoldi and ARPACK) share: J − σM factored
// in complex arithmetic (UMFPACK), the relative residual of an eigenpair on J itself, and the test that
// turns Ritz values μ of (J − σM)⁻¹M, nearest σ first, into accepted eigenpairs λ = σ + 1/μ and a disk.
#include <complex>
#include <functional>
#include <vector>

#include "solver/navier_stokes/shift_invert.hpp"

namespace magnus {

/// J − σM in UMFPACK's split complex form, factored; solves (J − σM) y = b. J's pattern gets a diagonal
/// entry in every column that M touches (the Γ_R column has none in J).
class ShiftedLu {
 public:
  /// Factors J − σM (σ in 1/s); symbolic: the UMFPACK symbolic analysis, made at the first call and reused
  /// (calls on several threads with the same symbolic wait for the first to make it).
  ShiftedLu(const EigenProblem& ep, std::complex<double> sigma, void** symbolic);
  ~ShiftedLu();
  ShiftedLu(const ShiftedLu&) = delete;
  ShiftedLu& operator=(const ShiftedLu&) = delete;

  /// y = (J − σM)⁻¹ b.
  std::vector<std::complex<double>> solve(const std::vector<std::complex<double>>& b) const;

 private:
  std::vector<long> Ap_, Ai_;
  std::vector<double> Ax_, Az_;
  void* numeric_ = nullptr;
};

/// J − σM of ep in UMFPACK's split complex form (Az: the imaginary parts; all zero for a real σ): J's pattern
/// with a diagonal entry in every column that M touches.
void shifted_matrix(const EigenProblem& ep, std::complex<double> sigma, std::vector<long>& Ap, std::vector<long>& Ai,
                    std::vector<double>& Ax, std::vector<double>& Az);

/// ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖): the relative residual of an eigenpair of J x = λ M x (λ in 1/s).
double relative_residual(const EigenProblem& ep, std::complex<double> lambda,
                         const std::vector<std::complex<double>>& x);

/// One Ritz value μ of (J − σM)⁻¹M; `vector` gives its Ritz vector, or is empty for a Ritz value the
/// eigensolver did not converge (it can only end the disk).
struct RitzValue {
  std::complex<double> mu;
  std::function<std::vector<std::complex<double>>()> vector;
};

/// Ritz values a shift's search tests on J (nev): 2·want + 4, the `want` nearest σ and a margin beyond.
inline int ritz_tested(int want) { return 2 * want + 4; }
/// Arnoldi vectors a shift's search keeps (ncv): at least 2·want + 10, room for ritz_tested and restarts.
inline int krylov_vectors(int krylov, int want) { return krylov > 2 * want + 10 ? krylov : 2 * want + 10; }

/// Tests the Ritz values (sorted by |μ| from the largest: nearest σ first) on J itself, λ = σ + 1/μ:
/// each with relative residual ≤ tol goes into out.found; every one nearer σ than the first that fails is
/// accepted, and out.radius = 1/|μ| of the farthest of those (1/s); out.converged when that holds for at
/// least `want`.
void accept_ritz_values(const EigenProblem& ep, const std::vector<RitzValue>& ritz, int want, double tol,
                        ShiftSearch& out);

}  // namespace magnus
