#pragma once
// Linear stability of a steady 2D state to spanwise-periodic (three-dimensional) disturbances ∝ e^{iβz}
// (BiGlobal). The base flow (Ψ, Ω) has no spanwise velocity, so one "half-complex" β-mode is real: the
// in-plane fields and the pressure go with cos βz, the spanwise velocity w = w̃ sin βz. The in-plane
// perturbation velocity is a solenoidal part plus a potential part, u₂ = ∇⊥ψ + ∇φ, so that
//     u_r = (ψ_θ + φ_ξ)/r,   u_θ = (φ_θ − ψ_ξ)/r,   ζ = ω_z = −∇²ψ,   ∇²φ = −βw̃   (continuity, exactly).
// On the log-polar grid (ξ = ln r/a, J = r², {f, g} = f_θ g_ξ − f_ξ g_θ, Arakawa's Jacobian as in 2D):
//     J ζ_t = −{Ψ, ζ} − {ψ, Ω} − (φ_ξ Ω_ξ + φ_θ Ω_θ) + β J Ω w̃ + ν(ζ_ξξ + ζ_θθ − β² J ζ)
//           = −{Ψ, ζ} − {ψ, Ω} − [(Ω φ_ξ)_ξ + (Ω φ_θ)_θ] + ν(ζ_ξξ + ζ_θθ − β² J ζ)   (discretised so)
//     ψ_ξξ + ψ_θθ = −J ζ,            φ_ξξ + φ_θθ = −β J w̃
//     J w̃_t = −{Ψ, w̃} + β J p + ν(w̃_ξξ + w̃_θθ − β² J w̃)
//     p_ξξ + p_θθ − β² J p = −2 S,   S = J tr(∇U·∇u) = U_r,ξ u_r,ξ + (U_r,θ − U_θ) u_θ,ξ
//                                                   + U_θ,ξ (u_r,θ − u_θ) + (U_θ,θ + U_r)(u_θ,θ + u_r)
// (p the kinematic pressure, m²/s²: the divergence of the momentum equations). The ζ equation is the curl
// of the in-plane momentum: the stretching βΩw̃ is ∂_z w tilting nothing (U_z = 0).
// Wall (no slip): ψ = 0, φ_ξ = 0 (u_r = 0), the ζ_w closure with the slip ψ_ξ = φ_θ in place of −a²ω
// (u_θ = 0), w̃ = 0, and p_ξ = −ν(ζ_θ + β w̃_ξ) (the normal momentum on the wall).
// Far field: ψ_ξ = −Γ_R/2π, ζ and w̃ zero on inflow and convected out on outflow, φ = 0, p = 0; the
// circulation's balance gains −νβ²Γ_R (from ∂_z² u_θ) and the potential part's −φ_ξ Ω in the flux.
// At β = 0 the (ψ, ζ, Γ_R) block is the 2D problem of stability.hpp, entry for entry: φ = 0, p is slaved
// and w̃ a passive scalar whose modes decay; the 2D eigenvalues come back unchanged.
// The eigenproblem J x = λ M x has five unknowns per node, (ψ, ζ, φ, w̃, p) interleaved, then Γ_R; M holds
// the 2D dynamic rows and the w̃ rows (interior, and the outflow ones on R). The eigenvalues are even in β.
#include <vector>

#include "solver/navier_stokes/stability.hpp"

namespace magnus {

/// Unknowns per node of the spanwise problem: ψ, ζ, φ, w̃, p (in that order).
constexpr int kSpanwiseFields = 5;

/// The spanwise problem at wavenumber β (1/m, ≥ 0) about the steady state `steady` of p (a converged
/// solve_steady state on ns_grid(p)). Throws std::invalid_argument for β < 0 or not finite, or a state of the
/// wrong size.
EigenProblem spanwise_problem(const NsParams& p, const NsState& steady, double beta);

/// The leading eigenvalues (U/D) of the spanwise problem at β (1/m), the search of leading_eigenvalues on
/// it; mode_psi, mode_zeta hold the leading mode's in-plane part.
StabilityResult spanwise_eigenvalues(const NsParams& p, const NsState& steady, double beta, int count,
                                     const StabilityOptions& o);

}  // namespace magnus
