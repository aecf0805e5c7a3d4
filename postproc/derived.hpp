#pragma once
// The ratios a run's summary and its --json show beside the stored figures: computed once here, formatted
// by io/.
#include <optional>

#include "postproc/result.hpp"

namespace magnus {

/// What potential flow's summary ("C_L", "ΔP top−bottom", "Magnus S") derives from the forces and the scene.
struct DerivedRatios {
  std::optional<double> alpha_Gamma;         ///< α_Γ = Γ/(2πaU), 1 (a given Γ with U > 0 only)
  std::optional<double> cl_over_kj_minus_1;  ///< C_L/C_L,KJ − 1, 1 (undefined when C_L,KJ = 0)
  std::optional<double> kj_over_seed;        ///< C_L,KJ/C_L,seed, 1 (undefined when ω = 0)
  std::optional<double> delta_p_over_seed;  ///< ΔP/ΔP_seed = ΔP/(2ρUaω), 1 (undefined when ΔP_seed = 0)
  double magnus_S_seed = 0.0;               ///< S_seed = 4ρa², kg/m
};

/// What the navier-stokes summary derives from the stored figures of a run.
struct ViscousRatios {
  /// Cells of the first ring across the boundary layer D/√(Re(1 + α²)), 1 (Re > 0 and two rings only).
  std::optional<double> wall_cells;
  std::optional<double> t_convective;      ///< t/(D/U_ref), 1 (undefined when D/U_ref = 0)
  std::optional<double> dt_convective;     ///< Δt/(D/U_ref), 1 (undefined when D/U_ref = 0)
  std::optional<double> steps_per_second;  ///< this run's steps/solve time, 1/s (undefined without one)
  /// Strouhal number of the leading stability mode, |Im λ|/(2π) with λ in U/D, 1 (U > 0 only).
  std::optional<double> eigen_strouhal;
  /// The steady potential vortex's torque −4πρνa²ω, N·m/m (still fluid, U = 0, only).
  std::optional<double> torque_potential_vortex;
  /// M̄/(−4πρνa²ω) − 1, 1 (U = 0 and ω ≠ 0 only).
  std::optional<double> torque_over_potential_vortex_minus_1;
};

/// The ratios of a navier-stokes result (r.viscous present).
ViscousRatios viscous_ratios(const FlowResult& r);

/// Cells of the first ring across the boundary layer's thickness D/√(Re(1 + α²)) (spin thins it where the
/// wall moves against the stream): (2a/√(Re(1 + α²)))/(r_1 − r_0), 1. Needs Re > 0 and two rings.
double wall_cells(const PolarGrid& g, double reynolds, double alpha);

/// The ratios of a potential-flow result (the seed's ratio is undefined without spin).
DerivedRatios derived_ratios(const FlowResult& r);

/// C_L/C_L,KJ − 1, 1: undefined when either is undefined or C_L,KJ = 0.
std::optional<double> cl_over_kj_minus_1(std::optional<double> cl, std::optional<double> kj);

/// C_L,KJ/C_L,seed, 1: undefined when either is undefined or C_L,seed = 0.
std::optional<double> kj_over_seed(std::optional<double> kj, std::optional<double> seed);

/// Potential flow's (ideal) lift coefficient at spin ratio α with the spin model: C_L,ideal = −2πα, 1.
double cl_ideal(double alpha);

/// The share of the ideal lift a lift coefficient is: C_L/(−2πα) = S/(2πρa²), 1 (undefined at α = 0).
std::optional<double> share_of_ideal_lift(double cl, double alpha);

/// Torque of the steady potential vortex u_θ = a²ω/r (an exact viscous flow in still fluid):
/// M = −4πρνa²ω, N·m/m, with ν in m²/s.
double torque_potential_vortex(const Scene& sc, double nu);

}  // namespace magnus
