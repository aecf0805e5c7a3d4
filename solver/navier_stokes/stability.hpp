#pragma once
// Linear stability of a steady viscous state: the leading eigenvalues of the time stepper's equations
// linearised about it. With F the steady residual of SteadyJacobian (rows scaled as there) the stepper is
//     M x_t = F(x),   M = diag(s_ζ·h²·J_i/ν) on the ζ rows of rings 1…n_r−2, 0 on the algebraic rows
// (ψ rows, the wall ζ row (Thom), inflow ζ rows on R: these hold at every instant), so a small
// perturbation x' e^{λt} obeys the generalised problem  J x' = λ M x',  J = ∂F/∂x at the state.
// The outflow ζ rows on R and the Γ_R row are dynamic in the stepper (ζ_t = −(ψ_θ/R²)ζ_ξ, dΓ_R/dt = flux)
// and carry those time derivatives in M: with them algebraic, Γ_R would follow the far field's tiny
// vorticity at once, and the leading pair at Re 80 came out at 0.24 + 0.91i instead of the stepper's
// 0.074 + 0.68i (U/D).
// M is singular: the problem has infinite eigenvalues. Shift-invert removes them: the operator
// (J − σM)⁻¹M maps an eigenpair (λ, x) to μ = 1/(λ − σ) and the infinite ones to μ = 0. Each shift σ
// (complex, UMFPACK's complex LU) gets a complex Arnoldi factorisation (classical Gram–Schmidt twice,
// Krylov–Schur restarts until the Ritz values nearest σ converge; ns_shift_invert.hpp) whose Ritz values μ
// give λ = σ + 1/μ; a value is kept when its residual ‖J x − λ M x‖ is small relative to
// ‖J x‖ + |λ|·‖M x‖.
//
// Finding the rightmost pair: shift-invert converges first to the eigenvalues nearest σ. The default
// shifts sit just right of the imaginary axis, σ·D/U = 0.1 + i·{0, 0.3, 0.6, 0.95, 1.4}: a steady (Im λ = 0)
// mode, the wake's Hopf pair (Im λ·D/U = 2π·St ≈ 0.75–1.1 for St 0.12–0.17) and the slow one-sided shedding
// at high spin (Im λ·D/U ≈ 0.25–0.3, St ≈ 0.04, near α = 5) lie near them. Without the shift at 0.3i that
// last pair was missed at Re 150, α 4.8 and 5.1 on the map's grid (growth +0.023 and +0.10 U/D). The
// eigenvalues of all shifts are merged (conjugates added: the problem is real) and sorted by real part. An
// eigenvalue with a larger real part that none of the shifts found would have to lie outside every shift's
// disk (the distance within which all its Ritz values were accepted): the strip from the leading eigenvalue
// to the imaginary axis is checked to lie inside the disks (`covered`), and a gap gets a shift of its own. The wake's modes of higher frequency than the highest shift are damped.
#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/shift_invert.hpp"

namespace magnus {

/// How leading_eigenvalues searches.
struct StabilityOptions {
  /// Shifts σ in units of U/D (U → a|ω| when U = 0); the conjugates of their eigenvalues come free.
  std::vector<std::complex<double>> shifts{{0.1, 0.0}, {0.1, 0.3}, {0.1, 0.6}, {0.1, 0.95}, {0.1, 1.4}};
  /// Arnoldi vectors (≥ count + 10). 32 were enough on the map's grid but left the default grid at Re 100,
  /// α 2.2 with no converged eigenvalue (with tol = 1e-6 then).
  int krylov = 40;
  /// Krylov–Schur restarts per shift (each keeps the nearest Ritz vectors and adds krylov − kept solves)
  /// while the `want` Ritz values nearest the shift have not all converged. With one explicit restart
  /// and no more, at Re 100, α 3 on the default grid four of the five shifts accepted nothing and a damped
  /// pair at −0.167 + 1.399i was reported as leading, above the slow real modes near −0.001.
  int restarts = 8;
  int want = 3;  ///< Ritz values nearest each shift that must converge (they make the shift's disk)
  /// Shifts searched at once, each with its own complex LU (memory ×threads): the given shifts after the
  /// first (which makes the symbolic analysis they share). 1 where the caller already runs in parallel.
  int threads = 1;
  /// Shifts added where the disks leave a gap in the strip from the leading eigenvalue to the imaginary
  /// axis, up to the highest shift's frequency.
  int extra_shifts = 3;
  /// Relative residual ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖) of an accepted eigenpair. On the default grid the
  /// leading pairs stall at 1e-6…4e-6 with 40 vectors (UMFPACK's iterative refinement does not lower it: a
  /// cluster of non-normal modes), already the same to five digits pass after pass; with 1e-6 the wake's
  /// pair at Re 100, α 2.2 (−0.0444 + 0.925i) and the slow real modes were never accepted, and a damped
  /// pair farther left was reported as leading.
  double tol = 1e-5;
  unsigned seed = 12345;  ///< of the random start vector (results do not depend on it beyond tol)
  /// Each shift's search: "arnoldi" (the hand-written Krylov–Schur Arnoldi, shift_invert_arnoldi) or
  /// "arpack" (ARPACK-ng, shift_invert_arpack); both accept an eigenpair by the same residual test (tol).
  std::string eigensolver = "arnoldi";
  /// ARPACK's own stopping test: Ritz estimate ≤ arpack_tol·|μ| for the eigenvalues μ of (J − σM)⁻¹M (all
  /// 2·want + 4 it is asked for). At Re 50, α 0, n_θ 64 with nev 10 it took 2070 solves at 1e-5 and 2160,
  /// 2324, 2390 at 1e-7, 1e-6, 1e-8 for the same leading eigenvalues; at 1e-4 its Ritz pairs failed the
  /// residual test on J and the strip was left uncovered; asking for 6, 4 or 3 instead of 10 left it
  /// uncovered too.
  double arpack_tol = 1e-5;
  /// A mode to follow (the problem's unknowns; e.g. the eigenvector found at a neighbouring state on the same
  /// grid): each shift's Arnoldi starts from it (arnoldi only), and the result's `followed` is the accepted
  /// eigenpair most nearly parallel to it. Empty: neither.
  std::vector<std::complex<double>> follow;
  /// Without `follow`: the result's `followed` is the accepted pair (Im λ > 0) nearest this eigenvalue, U/D.
  std::optional<std::complex<double>> follow_near;
};

/// The names StabilityOptions::eigensolver takes, "arnoldi, arpack".
std::string eigensolver_names();
/// Whether name is one of them.
bool known_eigensolver(const std::string& name);

/// One shift's search (U/D): what it accepted and how far from it every eigenvalue was found.
struct ShiftReport {
  std::complex<double> sigma;  ///< the shift, U/D
  int found = 0;               ///< eigenpairs accepted
  double radius = 0.0;         ///< every Ritz value nearer σ than this was accepted, U/D
  bool converged = false;      ///< the `want` nearest all accepted
  int restarts = 0;            ///< Krylov–Schur restarts taken
};

/// The leading eigenvalues and the state they belong to.
struct StabilityResult {
  std::vector<std::complex<double>> eigenvalues;  ///< rightmost first (Im ≥ 0 first in a pair), U/D
  /// Of each eigenvalue: ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖) of its eigenvector (the smallest over the shifts).
  std::vector<double> residuals;
  std::vector<ShiftReport> shifts;  ///< the shifts searched, in order (extra ones last)
  /// The shifts' disks cover the strip from the leading eigenvalue to the imaginary axis for 0 ≤ Im λ ≤ the
  /// highest shift's: no eigenvalue right of the leading one and left of Re λ = 0 was left unseen there.
  bool covered = false;
  bool stable = false;   ///< every eigenvalue found has Re λ < 0 (false when none was found)
  double seconds = 0.0;  ///< wall time, s
  int solves = 0;        ///< solves with the shifted LUs (J − σM)⁻¹, all shifts together
  std::string message;   ///< what was found (or why nothing was)
  double reach = 0.0;    ///< per shift the distance to its farthest accepted eigenvalue, the minimum, U/D
  /// The leading eigenvector (ψ, ζ fields row-major as NsState, complex; Γ_R), normalised to max |ζ| = 1.
  std::vector<std::complex<double>> mode_psi, mode_zeta;
  std::complex<double> mode_Gamma_R;
  /// With StabilityOptions::follow: the accepted eigenvalue (Im λ ≥ 0 member, U/D) whose eigenvector x is most
  /// nearly parallel to the followed one f, the overlap |f^H x|/(‖f‖‖x‖) (0 when nothing was accepted), and x;
  /// with follow_near instead, the accepted pair nearest it and its x (overlap 1). x is empty when neither.
  std::complex<double> followed;
  double followed_overlap = 0.0;
  std::vector<std::complex<double>> followed_vector;
  /// Growth rate Re λ and Strouhal number |Im λ|/(2π) of the leading eigenvalue (U/D units, so St = f·D/U).
  double growth_rate() const { return eigenvalues.empty() ? 0.0 : eigenvalues.front().real(); }
  double strouhal() const;
  /// The rightmost complex pair's member with Im λ > 0 (the wake's Hopf mode), if one was found. The
  /// spectrum also holds slow real modes of the far field (Re λ·D/U ≈ −0.001 … −0.003 at R = 40a: the
  /// circulation on R relaxing through the outflow), which lead whenever the wake is stable.
  std::optional<std::complex<double>> leading_pair() const;
};

/// The first member with Im λ > 0 of eigenvalues sorted rightmost first (the rightmost complex pair's upper
/// member), if there is one.
std::optional<std::complex<double>> rightmost_pair(const std::vector<std::complex<double>>& eigenvalues);

/// The Strouhal number of an eigenvalue λ in U/D: St = f·D/U = |Im λ|/(2π).
inline double eigen_strouhal(std::complex<double> lambda) { return std::fabs(lambda.imag()) / (2.0 * M_PI); }

/// The cheaper search of `time.mode = "auto"` and of the onset search's ends: the default shifts with at most
/// four restarts each and no shifts added for gaps (the result's `covered` says when the strip was left open).
StabilityOptions quick_stability_options();

/// o with threads for a search that runs alone (auto's, the onset search's, `magnus stability`'s): 2 on a
/// machine with two cores or more, else 1.
StabilityOptions lone_search(StabilityOptions o);

/// The leading eigenvalues at a steady state of p (a converged solve_steady state on ns_grid(p)). Throws
/// std::invalid_argument for a state of the wrong size, std::runtime_error when a factorisation fails.
StabilityResult leading_eigenvalues(const NsParams& p, const NsState& steady, int count = 6);
StabilityResult leading_eigenvalues(const NsParams& p, const NsState& steady, int count,
                                    const StabilityOptions& o);

/// The 2D problem J x = λ M x at a steady state of p: SteadyJacobian's J, the stepper's dynamic rows in M
/// (see above), the grid's nested-dissection order.
EigenProblem stability_problem(const NsParams& p, const NsState& steady);

/// Throws std::invalid_argument for count < 1, no shifts or an unknown eigensolver.
void check_stability_options(int count, const StabilityOptions& o);

/// The search of leading_eigenvalues on any problem: the options' shifts (in units of `unit`, 1/s), the
/// strip check and its extra shifts, the eigenvalues rightmost first in units of `unit`, and the leading
/// eigenvector's ψ and ζ (unknowns stride·q and stride·q + 1 of node q < nodes; Γ_R the last unknown).
StabilityResult search_eigenvalues(const EigenProblem& ep, double unit, int count, const StabilityOptions& o,
                                   size_t nodes, size_t stride);

/// The speed the eigenvalues are made dimensionless with: U, or a|ω| when U = 0, or ν/a (m/s).
double stability_speed(const NsParams& p);

}  // namespace magnus
