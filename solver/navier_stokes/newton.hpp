#pragma once
// Steady states of the viscous model by Newton's method on the time stepper's own discrete equations.
//
// A state is a fixed point of advance() (with the AB2 history equal to the current advection) exactly when
// it solves, on the log-polar grid of ns_grid(p) (ring 0 = wall, ring N = n_r−1 at R; shown for uniform
// Δξ = h: on a stretched ξ, h is Δξ_0 at the wall, inside the flux form of xi_flux with rows scaled by h_i²,
// on ring N Δξ_{N−1/2}):
//   wall ψ row        ψ_0j = 0
//   wall ζ row        ψ_1j + (a²h²/2)·ζ_0j + h·a²ω = 0                      (Thom, the stepper's closure;
//                     Jensen's 8ψ_1j − ψ_2j + 2a²h²ζ_0j + 6h·a²ω = 0 with NsWallClosure::jensen)
//   rings 1…N−1, ζ    ν(ζ_ξξ + ζ_θθ) − N(ψ, ζ) = 0                          (5-point, Arakawa's N)
//   rings 1…N−1, ψ    ψ_ξξ + ψ_θθ + J ζ = 0,  J = r²
//   ring N, ψ         2(ψ_{N−1} − ψ_N)/h² + 2g/h + ψ_θθ + J ζ_N = 0,  g = U R sinθ − Γ_R/2π  (ghost ring)
//   ring N, ζ         ζ_N − ζ_{N−1} = 0 where ψ_θ > 0 (outflow: the convective condition's fixed point),
//                     ζ_N = 0 elsewhere (inflow; everywhere with NsOuterVorticity::zero)
//   Γ_R               Σ_j (−ψ_θ ζ + ν ζ_ξ)|_R Δθ = 0                        (dΓ_R/dt = 0, one-sided ζ_ξ)
// Unknowns x = (ψ_q, ζ_q) interleaved per node q = i·n_θ + j, then Γ_R: 2·n_r·n_θ + 1. The Jacobian is
// assembled analytically (the equations are linear but for the bilinear N and the flux row) and factored
// by UMFPACK (LU with partial pivoting); the outflow/inflow choice is frozen at the state it is taken at.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// Newton's stopping rule and progress hook.
struct NewtonOptions {
  double tol = 1e-10;       ///< stop when the scaled residual (max norm, see steady_residual) is ≤ this
  int max_iterations = 20;  ///< Newton steps (each one LU factorisation)
  /// Chord steps: > 0 reuses the last factors while each such step cuts the residual by at least this
  /// factor (a rejected try costs one solve and one residual, then Newton refactors at the same iterate).
  /// 0: plain Newton, one factorisation per step (quadratic convergence).
  double chord_ratio = 0.0;
  /// After each evaluation of the residual: (iteration, scaled max-norm residual); iteration 0 = the guess.
  std::function<void(int, double)> on_iteration;
};

/// What Newton's method reached.
struct NewtonResult {
  NsState state;                  ///< the last iterate (t = 0, no history: a fixed point of advance())
  bool converged = false;         ///< residual ≤ tol
  int iterations = 0;             ///< steps taken (Newton steps and accepted chord steps)
  int factorisations = 0;         ///< LU factorisations (Newton steps)
  int chord_steps = 0;            ///< accepted steps with earlier factors
  std::vector<double> residuals;  ///< scaled max-norm residual per iterate, [0] = the guess
  std::string message;            ///< why it stopped
  double wall_seconds = 0.0;      ///< whole solve, s
  double factor_seconds = 0.0;    ///< of which UMFPACK's symbolic and numeric factorisations, s
};

/// The sparse Jacobian of the steady equations at a state, in compressed columns, and its LU factors.
/// Keep one to solve more systems with it (e.g. a later linear-stability shift-invert).
class SteadyJacobian {
 public:
  /// The equations of the parameters' grid (ns_grid(p)); throws std::invalid_argument like NsOperator.
  /// mirror: factor only the mirror-symmetric half (a cylinder without spin, ω = 0 and U > 0, has steady
  /// states with ψ and ζ odd in θ, Γ_R = 0; the Jacobian there maps odd corrections to odd residuals, so
  /// its restriction to the nodes 0 < θ_j < π is the whole Newton system at half the size and about a third
  /// of the factorisation's cost). solve() then expects an odd right-hand side and returns an odd vector
  /// with Γ_R's component 0. Throws std::invalid_argument for mirror with ω ≠ 0 or U = 0.
  explicit SteadyJacobian(const NsParams& p, bool mirror = false);
  ~SteadyJacobian();
  SteadyJacobian(const SteadyJacobian&) = delete;
  SteadyJacobian& operator=(const SteadyJacobian&) = delete;

  const PolarGrid& grid() const { return grid_; }
  const NsParams& params() const { return p_; }
  /// Unknowns 2·n_r·n_θ + 1.
  long size() const { return size_; }
  /// The ζ rows' scale (a/U, s; residual() multiplies them by h²/ν first): linear stability's mass matrix
  /// on interior ζ rows is zeta_row_scale()·h²·J/ν (s·s/m²·m² = s), so M x_t = F(x) is the time stepper.
  double zeta_row_scale() const { return s_zeta_; }
  /// Δξ of the grid.
  double d_xi() const { return h_; }

  /// x = (ψ_q, ζ_q interleaved, Γ_R) of a state, and back (t = 0 and no AB2 history: advance()'s first,
  /// Euler-advection step has the same fixed points as its AB2 steps).
  std::vector<double> pack(const NsState& s) const;
  NsState unpack(const std::vector<double>& x) const;

  /// The residual F(x) of the steady equations, each row scaled to be dimensionless: ψ rows by 1/(U a),
  /// ζ rows by a/U (ζ rows times h²/ν first, the flux row times h/(2πν)); U → a|ω| or ν/a when U = 0.
  std::vector<double> residual(const std::vector<double>& x) const;

  /// Assemble ∂F/∂x at x and factor it (the symbolic analysis once, on the first call). Throws
  /// std::runtime_error when UMFPACK fails or finds the matrix singular.
  void factor(const std::vector<double>& x);
  /// Assemble ∂F/∂x at x without factoring it (the linear stability problems take the matrix alone).
  void assemble(const std::vector<double>& x);
  /// Whether the factors are of the mirror-symmetric half (see the constructor).
  bool mirror() const { return mirror_; }
  /// Solve J·y = b (transpose: Jᵀ·y = b) with the last factors; throws std::logic_error before factor().
  std::vector<double> solve(const std::vector<double>& b, bool transpose = false) const;
  /// y = J·x with the last assembled matrix; throws std::logic_error with mirror (its rows are not all
  /// there).
  std::vector<double> multiply(const std::vector<double>& x) const;

  /// The last assembled matrix, compressed sparse columns (row indices sorted in each column); with mirror
  /// only the rows of the nodes 0 < θ_j < π are filled (the half system's).
  const std::vector<long>& col_ptr() const { return Ap_; }
  const std::vector<long>& row_index() const { return Ai_; }
  const std::vector<double>& values() const { return Ax_; }
  /// Seconds of the last symbolic analysis and numeric factorisation; nonzeros in L + U.
  double symbolic_seconds() const { return symbolic_s_; }
  double numeric_seconds() const { return numeric_s_; }
  long lu_nonzeros() const { return lu_nnz_; }

 private:
  void build_half();  ///< the half system's pattern from the whole one's (mirror, first factor)
  /// The system UMFPACK factors: the whole (Ap_, Ai_, Ax_) or, with mirror, the half (Hp_, Hi_, Hx_).
  const long* fp() const { return mirror_ ? Hp_.data() : Ap_.data(); }
  const long* fi() const { return mirror_ ? Hi_.data() : Ai_.data(); }
  const double* fx() const { return mirror_ ? Hx_.data() : Ax_.data(); }
  long factored_size() const { return mirror_ ? half_size_ : size_; }
  NsParams p_;
  bool mirror_ = false;
  PolarGrid grid_;
  long size_ = 0;
  double h_ = 0.0, s_psi_ = 1.0, s_zeta_ = 1.0;
  std::vector<long> Ti_, Tj_, Map_;  ///< distinct triplets (fixed pattern) and their slots in Ax_
  std::vector<int> Slot_;            ///< the triplet each entry of assemble() adds into
  std::vector<double> Tx_;
  std::vector<long> Ap_, Ai_;
  std::vector<double> Ax_;
  /// Mirror: the half system's unknown of each whole unknown (−1: none; odd: its value is ∓ that one's),
  /// its size, and its compressed columns summed from the whole matrix's values (entry Ax_[from] times
  /// sign into Hx_[to]).
  std::vector<long> half_of_;
  std::vector<signed char> half_sign_;
  long half_size_ = 0;
  std::vector<long> Hp_, Hi_, half_from_, half_to_;
  std::vector<signed char> half_entry_sign_;
  std::vector<double> Hx_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  double symbolic_s_ = 0.0, numeric_s_ = 0.0;
  long lu_nnz_ = 0;
};

/// The potential flow with the spin model's circulation Γ = 2πa²ω as a starting guess (m²/s, 1/s):
/// ψ = U (r − a²/r) sinθ − a²ω ln(r/a), ζ = 0, Γ_R = Γ. Its wall slope ψ_ξ = 2Ua sinθ − a²ω meets the
/// no-slip ψ_ξ = −a²ω only in mode 0 (the potential flow slips); Newton's first step adds the wall layer.
NsState potential_guess(const NsParams& p, const PolarGrid& g);

/// Newton's method from `guess` (a state on ns_grid(p): potential_guess, or a neighbouring steady state for
/// continuation). Full steps; the residual per iterate is in residuals and passed to on_iteration. Never
/// throws on a failing iteration (converged = false, message); throws std::invalid_argument on bad
/// parameters or a guess of the wrong size.
NewtonResult solve_steady(const NsParams& p, const NsState& guess, const NewtonOptions& o = {});
/// The same with a kept SteadyJacobian (its symbolic analysis, ~half the first factorisation, is reused:
/// continuation along a branch); on return it holds the factors of the last Newton step.
NewtonResult solve_steady(SteadyJacobian& jac, const NsState& guess, const NewtonOptions& o = {});

}  // namespace magnus
