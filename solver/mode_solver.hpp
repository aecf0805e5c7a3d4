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
#include <complex>
#include <memory>
#include <vector>

#include "mesh/polar_grid.hpp"

namespace magnus {

/// Condition on the outer ring i = n_r−1: u = g_outer (Dirichlet) or ∂u/∂ξ = g_outer (Neumann).
enum class OuterBoundary { dirichlet, neumann };

/// The factored per-mode operator for one (grid, σ, outer boundary). Immutable after construction;
/// solve() is const and may be called from several threads at once. A new σ (new Δt) = a new object.
class ModeSolver {
 public:
  /// Factor the n_θ/2+1 mode systems for shifts σ_i ≥ 0 (dimensionless, one per ring, n_r values;
  /// σ_0 unused, σ_{n_r−1} used only with the Neumann outer boundary). `threads` splits the modes.
  /// Throws std::invalid_argument on σ of the wrong size, negative or non-finite, or n_r < 3.
  ModeSolver(const PolarGrid& grid, const std::vector<double>& sigma, OuterBoundary outer, int threads = 1);
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

  int n_r_, n_theta_, m_, L_;  ///< L_: last unknown ring (n_r−2 Dirichlet, n_r−1 Neumann)
  int threads_;
  OuterBoundary outer_;
  double d_theta_;
  std::vector<double> d_xi_;       ///< Δξ_{i+1/2} = ξ_{i+1} − ξ_i, i = 0…n_r−2
  std::vector<double> h_;          ///< control-volume width h_i in ξ (rings 1…L; half cell at a Neumann N)
  std::vector<double> inv_pivot_;  ///< [i−1][k]: 1/d'_i of the Thomas LU, rings 1…L × modes
  std::vector<double> upper_;      ///< [i−1][k]: T(i,i+1)/d'_i
  std::unique_ptr<Plans> plans_;
};

}  // namespace magnus
