#pragma once
// Solver choice, separate from the operator: both solve the same DiscreteOperator.
#include <memory>
#include <vector>
#include "solver/potential/stencil.hpp"

namespace magnus {

/// Wall-clock seconds spent in each phase.
struct SolveTiming {
  double assemble_s = 0.0;  ///< stencil rows / matrix
  double factor_s = 0.0;    ///< CHOLMOD analyse + factor, or FFT plans + tridiagonal LU
  double solve_s = 0.0;     ///< all right-hand sides solved so far
};

/// A factored discrete system: solve() for any (U, Γ) reuses the factorization.
class PsiSolver {
 public:
  PsiSolver(const PolarGrid& grid, const DiscreteOperator& op) : grid_(grid), op_(op) {}
  virtual ~PsiSolver() = default;
  /// ψ on all rings, row-major (n_r, n_θ), m²/s, for speed U (m/s) and circulation Γ (m²/s).
  std::vector<double> solve(double U, double Gamma);
  /// x = A⁻¹·rhs for any right-hand side in the unknowns' layout (rings 1…L row-major, then C).
  virtual std::vector<double> solve_unknowns(const std::vector<double>& rhs) = 0;
  /// ψ on all rings for boundary data alone (right-hand side zero but on the outer ring and C).
  virtual std::vector<double> solve_boundary(const BoundaryData& bd);
  virtual Method method() const = 0;
  const DiscreteOperator& op() const { return op_; }
  SolveTiming timing;

 protected:
  PolarGrid grid_;
  DiscreteOperator op_;
};

/// The method `auto` resolves to (the fastest that applies: θ is uniform and periodic on every grid magnus
/// makes, so the FFT path always does). The one place a method is chosen.
Method resolve_method(Method requested);

/// Factor the operator with the chosen method. threads ≥ 1; max_bytes > 0 refuses a CHOLMOD factor
/// larger than that (checked after the symbolic analysis, before the numeric factorization).
std::unique_ptr<PsiSolver> make_solver(const PolarGrid& grid, const DiscreteOperator& op, Method method,
                                       int threads = 1, size_t max_bytes = 0);

std::unique_ptr<PsiSolver> make_cholmod_solver(const PolarGrid& grid, const DiscreteOperator& op,
                                               size_t max_bytes = 0);
std::unique_ptr<PsiSolver> make_fft_solver(const PolarGrid& grid, const DiscreteOperator& op,
                                           int threads = 1);

/// U·f_U + Γ·f_Γ elementwise: any field that is linear in ψ, from its parts per unit U and per unit Γ.
std::vector<double> superpose(double U, const std::vector<double>& f_U, double Gamma,
                              const std::vector<double>& f_Gamma);

/// Superposition basis: ψ = U·ψ_U + Γ·ψ_Γ (two solves serve any number of (U, Γ) pairs).
struct PsiBasis {
  std::vector<double> psi_U;      ///< ψ for U = 1 m/s, Γ = 0, (m²/s)/(m/s)
  std::vector<double> psi_Gamma;  ///< ψ for U = 0, Γ = 1 m²/s, dimensionless
  /// U·ψ_U + Γ·ψ_Γ, m²/s.
  std::vector<double> combine(double U, double Gamma) const;
};
PsiBasis solve_basis(PsiSolver& solver);

/// Seconds since an arbitrary epoch (steady clock).
double now_s();

}  // namespace magnus
