#pragma once
// The discrete Laplacian ψ_ξξ + ψ_θθ = 0 (ξ = ln r/a) on a PolarGrid, ring by ring, scaled by Δξ·Δθ
// and negated so that the assembled matrix is symmetric positive definite.
#include <array>
#include <vector>
#include "mesh/polar_grid.hpp"

namespace magnus {

/// Row (i, j): Σ_d a[d+1]·ψ_{i+d,j} + b[d+1]·(ψ_{i+d,j+1} + ψ_{i+d,j−1}), d ∈ {−1, 0, 1}.
struct RingStencil {
  std::array<double, 3> a{};
  std::array<double, 3> b{};
};

/// The discrete system: ring stencils, boundary closures and the exterior decay factors.
/// Unknowns are rings 1…last_ring (ψ = 0 on ring 0, the body); with the freestream far field one
/// extra unknown C sets ψ(R, θ) = U R sinθ + C, and its row is the circulation equation.
struct DiscreteOperator {
  int n_r = 0, n_theta = 0;
  double d_theta = 0.0;
  StencilKind stencil = StencilKind::five_point;
  FarField far_field = FarField::exact;
  std::vector<RingStencil> ring;  ///< ring[i], i = 0…n_r−1 (ring[0] unused)
  std::vector<double> w;          ///< flux weight w_{i+1/2} = −(a[2] + 2b[2]) of ring i, i = 0…n_r−1
  std::vector<double> mu;         ///< exact far field: decaying root μ_k of mode k = 0…n_θ/2 (μ_0 = 1)
  double r_outer = 0.0;           ///< R, m
  double r_ghost = 0.0;           ///< exact far field: radius of the exterior ring R·e^{Δξ}, m

  /// Index of the outermost unknown ring: n_r−2 (freestream) or n_r−1 (exact).
  int last_ring() const { return far_field == FarField::exact ? n_r - 1 : n_r - 2; }
  /// Unknowns: rings 1…last_ring × n_θ, plus C for the freestream far field.
  long unknowns() const { return long(last_ring()) * n_theta + (far_field == FarField::freestream ? 1 : 0); }
  /// Mode-k symbol T_k(i, i+d) = a[d+1] + 2cos(kΔθ)·b[d+1].
  double symbol(int i, int d, int k) const;
  /// Exterior coupling of the outer ring in mode k after the ghost ring is eliminated:
  /// e_k = T_k(N, N+1)·μ_k (exact far field only).
  double exterior(int k) const;
};

/// Stencil rows for a grid: 5-point flux form (any spacing) or compact 9-point (uniform ξ only).
DiscreteOperator make_operator(const PolarGrid& grid, StencilKind stencil, FarField far_field);

/// Boundary data for speed U (m/s) and circulation Γ (m²/s): right-hand side of the last unknown
/// ring (per j), the circulation row (freestream), and the Dirichlet part g_j = U R sinθ_j.
struct BoundaryData {
  std::vector<double> outer;  ///< added to the right-hand side of ring last_ring()
  double c_rhs = 0.0;         ///< right-hand side of the circulation row (freestream)
  std::vector<double> g;      ///< freestream: ψ(R, θ_j) − C = U R sinθ_j
};
BoundaryData boundary_data(const DiscreteOperator& op, const PolarGrid& grid, double U, double Gamma);

/// Right-hand side in the unknowns' layout: zero but for ring last_ring() and the C row.
std::vector<double> assemble_rhs(const DiscreteOperator& op, const BoundaryData& bd);

/// ψ on all rings from the unknowns x (freestream: ring n_r−1 = g + C). Row-major (n_r, n_θ).
std::vector<double> unpack_psi(const DiscreteOperator& op, const BoundaryData& bd,
                               const std::vector<double>& x);

/// Why a stencil cannot be used on a grid ("" when it can).
std::string stencil_refusal(const PolarGrid& grid, StencilKind stencil);

}  // namespace magnus
