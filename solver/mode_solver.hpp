#pragma once
// Fast per-mode solver of the shifted log-polar Poisson problem (FISHPACK HWSPLR with ELMBDA, per ring):
//     u_ξξ + u_θθ − σ_i·u = f_ij   on rings i = 0…n_r−1 (ξ = ln r/a), θ_j = 2πj/n_θ,
// i.e. ∇²u − λ(r)·u = F with σ_i = r_i²·λ(r_i) and f = r²·F. A real FFT in θ splits it into n_θ/2+1
// symmetric tridiagonal systems in ξ, one per Fourier mode k, factored once (Thomas) and reused.
// Discretisation: the 5-point flux form of solver/potential/stencil.cpp (any ξ spacing), per mode
//     [(û_{i+1}−û_i)/Δξ_{i+1/2} − (û_i−û_{i−1})/Δξ_{i−1/2}]/h_i − (λ_k + σ_i)·û_i = f̂_i,
//     h_i = (Δξ_{i−1/2} + Δξ_{i+1/2})/2,  λ_k = (2 − 2cos kΔθ)/Δθ².
// Wall ring 0: Dirichlet. Outer ring n_r−1: Dirichlet, or Neumann u_ξ = h through a mirror ghost ring
// (u_{N+1} = u_{N−1} + 2Δξ_{N−1/2}·h, second order).
// The same factorisation and sweeps also take any symmetric rows given per ring (ModeRows: the potential
// flow's 5- and 9-point stencils) with the two closures of its far fields on the last ring: an exterior
// term per mode, or a bordered mode-0 row for one extra unknown. Modes are split over a ThreadPool.
#include <complex>
#include <memory>
#include <mutex>
#include <vector>

#include "mesh/polar_grid.hpp"
#include "solver/pool.hpp"

namespace magnus {

/// Condition on the outer ring i = n_r−1: u = g_outer (Dirichlet) or ∂u/∂ξ = g_outer (Neumann).
enum class OuterBoundary { dirichlet, neumann };

/// A general symmetric per-mode operator on unknown rings i = 1…L, c_k = 2cos(kΔθ), dimensionless:
///   T_k(i,i) = diag_a[i] + c_k·diag_b[i],  T_k(i,i+1) = off_a[i] + c_k·off_b[i]  (entry i = 0 unused),
/// with at most one closure of ring L (the potential flow's far fields).
struct ModeRows {
  int n_theta = 0;
  double d_theta = 0.0;                              ///< Δθ = 2π/n_θ, rad
  std::vector<double> diag_a, diag_b, off_a, off_b;  ///< [i], i = 0…L
  /// Exterior closure: T_k(L,L) += exterior[k], k = 0…n_θ/2 (an eliminated outer region); empty: none.
  std::vector<double> exterior;
  /// Bordered mode-0 row: one more unknown X with T_0(L,X) = T_0(X,L) = −border, T(X,X) = border; 0: none.
  double border = 0.0;
};

/// The factored per-mode operator for one (grid, σ, outer boundary), or for one set of ModeRows. Immutable
/// after construction; solve() is const and may be called from several threads at once (they take turns in
/// the pool). A new σ (new Δt) = a new object.
class ModeSolver {
 public:
  /// Factor the n_θ/2+1 mode systems for shifts σ_i ≥ 0 (dimensionless, one per ring, n_r values;
  /// σ_0 unused, σ_{n_r−1} used only with the Neumann outer boundary). `threads` splits the modes.
  /// Throws std::invalid_argument on σ of the wrong size, negative or non-finite, or n_r < 3.
  ModeSolver(const PolarGrid& grid, const std::vector<double>& sigma, OuterBoundary outer, int threads = 1);
  /// Factor the n_θ/2+1 mode systems of general rows (L = diag_a.size() − 1 unknown rings). Only
  /// solve_spectrum() applies. Throws std::invalid_argument on rows of unequal sizes, L < 1 or a wrong
  /// exterior size; std::runtime_error when a mode's system (or the bordered row) is not positive definite.
  explicit ModeSolver(const ModeRows& rows, int threads = 1);
  ~ModeSolver();
  ModeSolver(const ModeSolver&) = delete;
  ModeSolver& operator=(const ModeSolver&) = delete;

  /// u (row-major (n_r, n_θ), units of g) of u_ξξ + u_θθ − σ_i·u = f_ij with u(ξ=0, θ_j) = g_wall[j]
  /// and u(ξ_N, θ_j) = g_outer[j] or ∂u/∂ξ(ξ_N, θ_j) = g_outer[j]. f is (n_r, n_θ) (units of u; the
  /// wall ring, and the outer ring when Dirichlet, are ignored). Throws std::invalid_argument on wrong
  /// sizes or non-finite input.
  std::vector<double> solve(const std::vector<double>& f, const std::vector<double>& g_wall,
                            const std::vector<double>& g_outer) const;

  /// The per-mode part of solve() in Fourier space, for modes [kb, ke) (the caller transforms; several
  /// threads may work on disjoint ranges at once). u_hat is (n_r, modes()) row-major: on entry rings 1…L hold
  /// f̂ (FFTW's unnormalised r2c of f, L = n_r−2 Dirichlet, n_r−1 Neumann); on exit all rings hold û (the
  /// wall ring = g_wall_hat, a Dirichlet outer ring = g_outer_hat), in the same unnormalised scaling.
  /// g_wall_hat, g_outer_hat: r2c of the boundary data (modes() values each). No checks: O(n_r·(ke−kb)).
  void solve_mode_range(std::complex<double>* u_hat, const std::complex<double>* g_wall_hat,
                        const std::complex<double>* g_outer_hat, int kb, int ke) const;

  /// The per-mode solve in Fourier space, in place, all modes (split over the pool): y is rings 1…L ×
  /// modes() row-major, FFTW's unnormalised r2c of the right-hand side on entry, û on exit (same scaling).
  /// b_X: the bordered row's right-hand side (same scaling); returns X (0 without a border). With
  /// `last_ring_only` the right-hand side is zero but on ring L (rings 1…L−1 of y are not read). O(L·n_θ).
  double solve_spectrum(std::complex<double>* y, double b_X, bool last_ring_only) const;

  /// Influence vector of mode k = 0…n_θ/2: φ_k(ξ_i), i = 0…n_r−1, of the homogeneous problem
  /// (f = 0, g_outer = 0) with unit wall data in mode k: φ_k(0) = 1. Wall data cos(kθ) or sin(kθ)
  /// gives u_ij = φ_k(ξ_i)·cos(kθ_j) or ·sin(kθ_j) exactly (same discrete system). O(n_r).
  std::vector<double> influence(int k) const;

  /// ∂φ_k/∂ξ at the wall, one-sided second order from φ_k on rings 0, 1, 2 (any spacing); per unit wall
  /// value, dimensionless. O(n_r).
  double influence_wall_slope(int k) const;

  int n_r() const { return n_r_; }
  int n_theta() const { return n_theta_; }
  /// Number of Fourier modes n_θ/2+1.
  int modes() const { return m_; }
  OuterBoundary outer() const { return outer_; }

 private:
  struct Plans;
  size_t at(int i, int k) const { return size_t(i - 1) * m_ + k; }
  void factor(const std::vector<double>& sigma);
  /// The rows' symbols per mode, the exterior term on ring L, then the bordered row's pivot.
  void factor(const ModeRows& rows);
  /// Thomas LU of every mode with ring i's symbols row(i).diag(k) = T_k(i,i), row(i).off(k) = T_k(i,i+1).
  template <bool kDivide, class Row>
  void factor_modes(const Row& row);
  /// body(kb, ke) over the modes [0, m), split over the pool (if any).
  template <class F>
  void over_modes(const F& body) const;
  /// Forward elimination of modes [kb, ke): y_i −= upper_{i−1}·y_{i−1}, i = 2…L.
  void forward_sweep(std::complex<double>* y, int kb, int ke) const;
  /// Back substitution of modes [kb, ke): x_i = y_i/d'_i − upper_i·x_{i+1} (bordered X in mode 0 of ring L).
  void back_sweep(std::complex<double>* y, int kb, int ke, double X, bool with_rhs) const;
  /// Throws std::logic_error when the solver was built from rows (no grid): `what` needs one.
  void require_grid(const char* what) const;

  int n_r_, n_theta_, m_, L_;  ///< L_: last unknown ring (n_r−2 Dirichlet, n_r−1 Neumann)
  int threads_;
  OuterBoundary outer_;
  double d_theta_;
  std::vector<double> d_xi_;  ///< Δξ_{i+1/2} = ξ_{i+1} − ξ_i, i = 0…n_r−2 (empty: built from rows)
  std::vector<double> h_;     ///< control-volume width h_i in ξ (rings 1…L; half cell at a Neumann N)
  /// [i−1][k], rings 1…L × modes, uninitialised until factored (first touched by the thread of its modes):
  std::unique_ptr<double[]> inv_pivot_;  ///< 1/d'_i of the Thomas LU
  std::unique_ptr<double[]> upper_;      ///< T(i,i+1)/d'_i
  /// Bordered row (border w ≠ 0): off_X = T_0(L,X) = −w, lower_X = off_X·inv_pivot_(L, 0),
  /// inv_pivot_X = 1/(w − lower_X·off_X).
  bool bordered_ = false;
  double off_X_ = 0.0, lower_X_ = 0.0, inv_pivot_X_ = 0.0;
  std::unique_ptr<Plans> plans_;
  std::unique_ptr<ThreadPool> pool_;  ///< only with threads_ > 1 and m ≥ 256 modes (else one thread)
  mutable std::mutex pool_mutex_;     ///< one run() at a time: solve() may be called from several threads
};

}  // namespace magnus
