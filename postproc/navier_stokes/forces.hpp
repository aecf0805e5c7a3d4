#pragma once
// Forces, torque and separation points of the viscous flow, per unit span, from the wall:
//   wall shear      τ_w = μ (ζ_w − 2ω)                       (u_r = 0 and u_θ = aω on r = a), Pa
//   pressure        ∂p/∂θ|_a = μ ∂ζ/∂ξ|_0                    (θ-momentum on a wall moving tangentially,
//   steadily) force           F = ∮ (−p n̂ + τ_w θ̂) a dθ,  n̂ = (cosθ, sinθ), θ̂ = (−sinθ, cosθ), N/m
//                   pressure part by parts: F_p = μ a ∮ ζ_ξ (sinθ, −cosθ) dθ (no constant needed)
//   torque          M = ∮ τ_w a² dθ (N·m/m),  spin power P = −M ω (W/m)
//   coefficients    C_L = F_y/(½ρU²D), C_D = F_x/(½ρU²D), C_M = M/(½ρU²D²), D = 2a (empty when U = 0).
// ζ_ξ at the wall is one-sided of fourth order (five rings); the θ integrals are the periodic trapezoid.
// Why fourth: the field ζ is second order, but the three-ring difference adds an error ζ_ξξξ·Δξ²/3 that
// is large where the wall layer's vorticity bends, and its higher terms kept C_D's convergence in the
// rings at order 1.7 (Re 40, 158–1257 rings); with five rings it is 2.0, and Richardson's bar shrinks 4x.
#include <optional>
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// Rings the wall derivative ζ_ξ|_0 is taken from (its order is one less).
constexpr int kWallRings = 5;

/// Forces per unit span on the body and their coefficients.
struct ViscousForces {
  double F_x = 0.0, F_y = 0.0;                    ///< drag, lift, N/m
  double F_x_pressure = 0.0, F_y_pressure = 0.0;  ///< pressure parts, N/m
  double F_x_friction = 0.0, F_y_friction = 0.0;  ///< friction (shear) parts, N/m
  double M = 0.0;                                 ///< torque about the axis, N·m/m (CCW positive)
  double P_spin = 0.0;                            ///< power to keep the spin, P = −Mω, W/m
  std::optional<double> C_L, C_D, C_M;            ///< on ½ρU²·D (C_M on ½ρU²·D²)
  std::optional<double> C_L_pressure, C_L_friction, C_D_pressure, C_D_friction;
};

/// Values on the body r = a.
struct ViscousSurface {
  std::vector<double> theta;     ///< θ_j, rad
  std::vector<double> tau_w;     ///< wall shear stress τ_w = μ(ζ_w − 2ω), Pa
  std::vector<double> pressure;  ///< p − p̄ (its θ-mean removed; forces do not depend on it), Pa
  std::vector<double> zeta_xi;   ///< ∂ζ/∂ξ at the wall, 1/s
};

/// The surface values of a state; ρ in kg/m³ (μ = ρν). The pressure is the spectral θ-integral of μ ζ_ξ.
ViscousSurface viscous_surface(const PolarGrid& g, const NsParams& p, double rho, const NsState& s);

/// Forces, torque and coefficients of a state (the formulas above).
ViscousForces viscous_forces(const PolarGrid& g, const NsParams& p, double rho, const NsState& s);

/// The zeros of τ_w (θ in [0, 2π), rad, linear between nodes), by the wall flow's direction (τ_w > 0: the
/// fluid next to the wall moves towards +θ relative to it).
struct WallShearZeros {
  /// τ_w goes from + to − with θ: the wall flow on both sides runs into the point and leaves the wall
  /// (separation, with reverse flow downstream of it).
  std::vector<double> separation;
  /// τ_w goes from − to +: the flow comes onto the wall and spreads both ways (front stagnation point,
  /// reattachment); also a rear stagnation point where τ_w is zero by mirror symmetry (no spin, no bubble).
  std::vector<double> attachment;
};
/// The zeros of the surface's τ_w, sorted into separation and attachment points.
WallShearZeros wall_shear_zeros(const ViscousSurface& surf);

/// Separation points only (wall_shear_zeros(surf).separation), rad.
std::vector<double> separation_angles(const ViscousSurface& surf);

/// Recirculation length behind the body along θ = 0 (the +x axis, downstream): the distance from the rear
/// of the body to the first point where u_r turns from negative to positive, in diameters D; 0 if none.
double recirculation_length(const PolarGrid& g, const NsState& s);

}  // namespace magnus
