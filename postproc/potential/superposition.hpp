#pragma once
// Lift for any number of (U, Γ) pairs from two solutions: ψ = U·ψ_U + Γ·ψ_Γ is linear, so the surface
// velocity and u_θ along the y axis are too; pressure (quadratic) is formed after superposition.
#include <vector>
#include "postproc/potential/forces.hpp"

namespace magnus {

/// The linear parts of the flow per unit U (ψ_U) and per unit Γ (ψ_Γ).
struct FlowBasis {
  PolarGrid grid;
  std::vector<double> surface_U, surface_Gamma;  ///< u_θ(a, θ_j), (m/s)/(m/s) and (m/s)/(m²/s)
  std::vector<double> up_U, up_Gamma;            ///< u_θ(r_i, π/2)
  std::vector<double> down_U, down_Gamma;        ///< u_θ(r_i, 3π/2)
};

/// Basis from ψ_U (U = 1 m/s, Γ = 0) and ψ_Γ (U = 0, Γ = 1 m²/s) with derivatives of the given order.
FlowBasis flow_basis(const PolarGrid& g, const std::vector<double>& psi_U,
                     const std::vector<double>& psi_Gamma, int order);

/// One (U, Γ) point: forces, stagnation points and the lift error against Kutta–Joukowski.
struct SweepPoint {
  Scene scene;  ///< this point's scene: its speed, spin and circulation
  Forces forces;
  std::vector<StagnationPoint> stagnation, stagnation_exact;
  double cl_rel = 0.0;  ///< |F_y − F_y,KJ| / |F_y,KJ| (as Errors::cl_rel)
};

/// Evaluate a case (its U, ω, Γ) from the basis in O(n_θ + n_r).
SweepPoint evaluate(const FlowBasis& b, const Scene& scene);

}  // namespace magnus
