#pragma once
// The pressure field of a navier-stokes state, fixed to p∞ far upstream. The pressure Poisson equation
//     ∇²p = 2ρ (∂u_x/∂x ∂u_y/∂y − ∂u_x/∂y ∂u_y/∂x)          (incompressible: ∇²p = −ρ ∇·(u·∇u))
// is solved per Fourier mode in ξ = ln(r/a), with J = r² and the Hessian of ψ in polar components:
//     p_ξξ + p_θθ = J·rhs = 2ρ [(ψ_ξξ − ψ_ξ)(ψ_ξ + ψ_θθ) − (ψ_ξθ − ψ_θ)²] / r²          (Pa).
// Wall r = a: the steady r-momentum equation,
//     ∂p/∂ξ|_0 = a ∂p/∂r = −ρ(a u_r ∂u_r/∂r + u_θ ∂u_r/∂θ − u_θ²) − μ ∂ζ/∂θ
//              = −(ρ/a²)[ψ_θ(ψ_ξθ − ψ_θ) − ψ_ξ ψ_θθ − ψ_ξ²] − μ ζ_θ,
// which on the spinning no-slip wall (u_r ≡ 0, u_θ = aω: exact for unsteady flow too) is
// ∂p/∂r|_a = ρaω² − (μ/a) ∂ζ/∂θ (with u_θ(a) = −ψ_ξ/a from the state), and with ζ = 0, u_r(a) = 0 the wall
// condition of Bernoulli's potential-flow pressure.
// Outer ring r = R: p = H − ½ρ|u|², with the total head H = p + ½ρ|u|² integrated along the ring from
// the θ-momentum equation (steady),  ∂H/∂θ = R(−ρ u_r ζ + μ ∂ζ/∂r) = −ρ ψ_θ ζ + μ ζ_ξ,  starting from
// H = p∞ + ½ρU² at the upstream point θ = π. Where irrotational flow enters, H stays p∞ + ½ρU²
// (Bernoulli: p = p∞ + ½ρ(U² − |u|²)); where the wake leaves, H drops by the head the wake has lost (so p
// is not simply p∞ there: the far wake recovers p∞ only as its deficit decays). Exact for steady flow;
// for unsteady flow it omits −ρR ∂u_θ/∂t on r = R: the ring mean of ∂H/∂θ (= ρ dΓ_R/dt, 0 when steady) is
// removed so that H closes round the ring.
// Discretisation, second order: ψ derivatives central on rings 1…n_r−2 (ψ_ξθ by the 4-point cross
// difference), one-sided 3-point in ξ on the wall and outer rings, central in θ; the 5-point flux form of
// ModeSolver (σ = 0, Dirichlet outer) on rings 1…n_r−2; on the wall ring the Neumann condition as the
// one-sided 3-point ∂p/∂ξ, imposed per Fourier mode through ModeSolver's influence vectors; the ring
// integral of ∂H/∂θ by the periodic cumulative trapezoid rule. The wall values then satisfy the
// θ-momentum condition ∂p/∂θ|_a = μ ∂ζ/∂ξ|_0 of postproc/viscous_forces to the scheme's order.
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// Pressure p(r_i, θ_j), Pa, (n_r, n_θ) row-major, of a state; ρ in kg/m³, p∞ in Pa. Needs geometric
/// (uniform-ξ) spacing, n_r ≥ 4 and n_θ ≥ 4; throws std::invalid_argument on a state of the wrong size,
/// non-finite input or ρ ≤ 0.
std::vector<double> ns_pressure_field(const PolarGrid& g, const NsParams& p, double rho, double p_inf,
                                      const NsState& s);

}  // namespace magnus
