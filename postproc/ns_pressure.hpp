#pragma once
// The pressure field of a navier-stokes state, fixed to p∞ far upstream. The pressure Poisson equation
//     ∇²p = 2ρ (∂u_x/∂x ∂u_y/∂y − ∂u_x/∂y ∂u_y/∂x)          (incompressible: ∇²p = −ρ ∇·(u·∇u))
// is solved per Fourier mode in ξ = ln(r/a) (J = r²: p_ξξ + p_θθ = J·rhs) with the exact wall condition of
// the r-momentum equation on a wall that only turns, ∂p/∂r|_a = ρ a ω² − (μ/a) ∂ζ/∂θ, and the far field
// p = p∞ + ½ρ(U² − |u|²) where the flow enters (u_r < 0) and p = p∞ where the wake leaves.
#include <vector>

#include "solver/navier_stokes.hpp"

namespace magnus {

/// Pressure p(r_i, θ_j), Pa, (n_r, n_θ) row-major, of a state; ρ in kg/m³, p∞ in Pa.
std::vector<double> ns_pressure_field(const PolarGrid& g, const NsParams& p, double rho, double p_inf,
                                      const NsState& s);

}  // namespace magnus
