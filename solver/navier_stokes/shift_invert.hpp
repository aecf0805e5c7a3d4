#pragma once
// Shift-invert Arnoldi for J x = λ M x at one complex shift σ (the operator (J − σM)⁻¹M, UMFPACK's complex
// LU), restarted in Krylov–Schur form until the Ritz values nearest σ have converged: leading_eigenvalues
// (ns_stability.hpp) runs it at each of its shifts. shift_invert_arpack does the same search with ARPACK-ng.
#include <complex>
#include <random>
#include <vector>

namespace magnus {

/// The generalised eigenproblem J x = λ M x of a linear stability: J real in compressed columns (row
/// indices sorted in each column), M diagonal (its zero entries are the algebraic rows), and the
/// fill-reducing order of the unknowns that the shifted LU gives UMFPACK. The 2D stability (stability.cpp)
/// and the spanwise one (spanwise.hpp) each build one; the searches below serve both.
struct EigenProblem {
  long n = 0;                 ///< unknowns
  std::vector<long> Ap, Ai;   ///< J's compressed columns
  std::vector<double> Ax;     ///< J's values (rows scaled to be dimensionless)
  std::vector<double> m;      ///< M's diagonal, s (n values)
  std::vector<long> order;    ///< a fill-reducing order of the unknowns (empty: UMFPACK's own)
  /// y = J x.
  std::vector<double> multiply(const std::vector<double>& x) const;
  /// y += c·J x (columns whose c·x is 0 skipped).
  void multiply_add(const std::vector<double>& x, double c, std::vector<double>& y) const;
};

/// One accepted eigenpair of J x = λ M x.
struct Eigenpair {
  std::complex<double> lambda;           ///< 1/s
  std::vector<std::complex<double>> x;   ///< the eigenvector (the problem's unknowns)
  double residual = 0.0;                 ///< ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖)
};

/// What one shift found.
struct ShiftSearch {
  std::complex<double> sigma;  ///< the shift, 1/s
  std::vector<Eigenpair> found;
  /// Every Ritz value within this distance of σ was accepted (1/s; 0 when the nearest was not): with
  /// shift-invert the eigenvalues nearest σ come first, so none is missing inside the disk |λ − σ| < radius.
  double radius = 0.0;
  bool converged = false;  ///< the `want` Ritz values nearest σ were all accepted
  int restarts = 0;        ///< Krylov–Schur restarts taken
  int solves = 0;          ///< solves with J − σM
};

/// Shift-invert Arnoldi at σ (1/s) with `krylov` vectors, restarted (keeping the nearest Ritz vectors) up to
/// max_restarts times until the `want` Ritz values nearest σ have a relative residual ≤ tol. symbolic: the
/// UMFPACK symbolic analysis, made at the first call and reused. start (optional, n values): the first
/// vector before its first solve, e.g. a neighbouring problem's eigenvector (else a random one from rng).
ShiftSearch shift_invert_arnoldi(const EigenProblem& ep, std::complex<double> sigma, int want, int krylov,
                                 int max_restarts, double tol, void** symbolic, std::mt19937& rng,
                                 const std::vector<std::complex<double>>* start = nullptr);

/// The same search by ARPACK-ng (znaupd/zneupd, mode 1 on OP = (J − σM)⁻¹M, which = "LM", implicit restarts
/// with exact shifts): nev = 2·want + 4 Ritz values from ncv = max(krylov, 2·want + 10) vectors, at most
/// max_restarts + 1 Arnoldi iterations, stopping when ARPACK's Ritz estimates are ≤ arpack_tol·|μ|. Its
/// converged Ritz pairs then pass the same test on J (relative residual ≤ tol) as shift_invert_arnoldi's;
/// the ones it did not converge end the disk. ARPACK is not reentrant: searches in other threads wait.
ShiftSearch shift_invert_arpack(const EigenProblem& ep, std::complex<double> sigma, int want, int krylov,
                                int max_restarts, double tol, double arpack_tol, void** symbolic,
                                std::mt19937& rng);

}  // namespace magnus
