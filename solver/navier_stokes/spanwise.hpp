#pragma once
// Linear stability of a 2D state to spanwise-periodic (three-dimensional) disturbances ∝ e^{iβz} (BiGlobal),
// in primitive variables on a staggered (MAC) copy of the polar grid. The base (U_r, U_θ)(r, θ) has no
// spanwise velocity, so one real β-mode holds: u_r, u_θ, p go with cos βz and w = w̃ sin βz. With
// ∂_r = (1/r)∂_ξ and ∇₂²f = (f_ξξ + f_θθ)/r², the linearised equations are
//     u_r,t = −[U_r u_r,r + (U_θ/r) u_r,θ − 2U_θ u_θ/r + u_r U_r,r + (u_θ/r) U_r,θ] − p_r
//             + ν[∇₂²u_r − u_r/r² − (2/r²) u_θ,θ − β² u_r]
//     u_θ,t = −[U_r u_θ,r + (U_θ/r) u_θ,θ + U_θ u_r/r + u_r U_θ,r + (u_θ/r) U_θ,θ + u_θ U_r/r] − p_θ/r
//             + ν[∇₂²u_θ − u_θ/r² + (2/r²) u_r,θ − β² u_θ]
//     w̃_t   = −[U_r w̃_r + (U_θ/r) w̃_θ] + β p + ν[∇₂²w̃ − β² w̃]
//     0     = (1/r)(r u_r)_r + (1/r) u_θ,θ + β w̃
// (p the kinematic pressure, m²/s²). Continuity is a constraint: the pressure is its multiplier.
// With an absorbing layer (NsParams::absorbing_start) each momentum equation gains −λ(r)·u, the velocity
// form of the 2D vorticity's sink −λζ (they differ by ∇λ × u, small where λ varies slowly).
// The staggered grid: u_r on the rings ξ_i at θ_{j+½}, u_θ at the ring midpoints ξ_{i+½} and θ_j, w̃ and p
// at the cell centres (ξ_{i+½}, θ_{j+½}); the base's Ψ on the nodes (ξ_i, θ_j) gives U_r = Ψ_θ/r on the
// u_r points and U_θ = −Ψ_ξ/r on the u_θ points by one difference each, so the problem is affine in the
// base (the Floquet stepper relies on it). Second-order central differences on any ξ spacing; the other
// component at a point is the mean of its four neighbours.
// Boundaries, through ghost values beyond the wall and R (their rows are the conditions, with no mass):
// the wall has no slip (u = 0; the ghosts of u_θ and w̃ put the quadratic through 0 on the wall); on R
// the base's inflow columns have u = 0, its outflow columns p = 0 and ∂u/∂r = 0.
// This is an independent discretisation of the 2D problem too: at β = 0 it gives the 2D eigenvalues of
// stability.hpp to the discretisation error of both (not entry for entry).
// Unknowns: four per slot (i, j), i = 0 … n_r (n_r + 1 slots, the last beyond R): u_r on ring i, and u_θ,
// w̃, p of the cell i − ½ (slot 0 holds the wall's ghosts, its p an unused unknown fixed at 0). Each is
// made dimensionless by the speed U (stability_speed): u/U, p/U². M is a/U on the momentum rows of the
// interior (and the outflow u_r on R), 0 on the constraints.
#include <vector>

#include "solver/navier_stokes/stability.hpp"

namespace magnus {

/// Unknowns per slot of the spanwise problem: u_r, u_θ, w̃, p (in that order).
constexpr int kSpanwiseFields = 4;
/// The field index of p: unknown kSpanwiseFields·slot + kSpanwisePressure.
constexpr int kSpanwisePressure = 3;

/// Unknowns of the spanwise problem on n_r rings × n_θ columns: kSpanwiseFields per slot, n_r + 1 slots a
/// column (the last beyond R).
long spanwise_unknowns(int n_r, int n_theta);

/// A vector of the spanwise problem on grid `from` sampled onto grid `to` (Arnoldi's start on a finer grid
/// from a coarser grid's mode): each field linear in ξ and in θ between its own staggered points of `from`
/// (the ghosts beyond the wall and R included; p, which has no ghost at the wall, constant below its first
/// centre), 0 beyond its last point (beyond a smaller R's ghost). Throws std::invalid_argument when x does
/// not fit `from`.
std::vector<double> spanwise_prolong(const PolarGrid& from, const PolarGrid& to,
                                     const std::vector<double>& x);

/// Which columns of R let the base out (U_r > 0 there, and the case's outer vorticity lets the wake out):
/// u at θ_{j+½} (the u_r points, also the cell centres), v at θ_j (the u_θ points).
struct SpanwiseOutflow {
  std::vector<char> u, v;
};

/// The outflow columns of the base state (n_θ each).
SpanwiseOutflow spanwise_outflow(const NsParams& p, const NsState& base);

/// The spanwise problem at wavenumber β (1/m, ≥ 0) about the 2D state `base` of p (on ns_grid(p)), its
/// outflow columns from the base itself or given (the Floquet stepper fixes them at the mean flow's).
/// Throws std::invalid_argument for β < 0 or not finite, or a state of the wrong size.
EigenProblem spanwise_problem(const NsParams& p, const NsState& base, double beta);
EigenProblem spanwise_problem(const NsParams& p, const NsState& base, double beta, const SpanwiseOutflow& out);

/// The leading eigenvalues (U/D) of the spanwise problem at β (1/m) about a steady state, the search of
/// leading_eigenvalues on it with every shift moved left by νβ² (the damping spanwise diffusion adds to
/// each velocity component; covered is false once a shift lies left of the axis). The result's mode
/// fields are empty (the mode is not a (ψ, ζ) pair).
StabilityResult spanwise_eigenvalues(const NsParams& p, const NsState& steady, double beta, int count,
                                     const StabilityOptions& o);

}  // namespace magnus
