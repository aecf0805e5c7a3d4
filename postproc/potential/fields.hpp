#pragma once
// Velocity, pressure and Cp from ψ: central differences inside; at r = R one-sided, and at r = a one-sided
// (5-point) or centred on the odd reflection ψ(−ξ) = −ψ(ξ) (9-point, see mesh/fd_weights).
#include <optional>
#include <string>
#include <vector>
#include "mesh/polar_grid.hpp"

namespace magnus {

/// Which (n_r, n_θ) fields to compute and write; everything by default.
struct FieldSelection {
  std::vector<bool> on = std::vector<bool>(field_names().size(), true);  ///< per field_names()
  bool has(const std::string& name) const;
  bool any_velocity() const;
};
/// Selection from names (absent: all; empty: none). Throws std::invalid_argument naming an unknown field.
/// Absent names: every field of the model (field_of_model).
FieldSelection select_fields(const std::optional<std::vector<std::string>>& names,
                             FlowModel model = FlowModel::potential);

/// Fields (n_r, n_θ), row-major; a field not selected stays empty.
struct Fields {
  std::vector<double> psi, u_r, u_theta, u_x, u_y, pressure, cp, psi_exact, psi_error;
  std::vector<double> vorticity;  ///< ζ = −∇²ψ, 1/s (navier-stokes)
  /// The field of a given name (one of field_names()).
  const std::vector<double>& get(const std::string& name) const;
  std::vector<double>& get(const std::string& name);
};

/// Values on the body r = a (n_θ).
struct Surface {
  std::vector<double> theta;         ///< rad
  std::vector<double> u_theta;       ///< m/s, = u_mean + u_fluct
  double u_mean = 0.0;               ///< ū, the mean of u_θ (the circulation's part, Γ/(2πa)), m/s
  std::vector<double> u_fluct;       ///< u' = u_θ − ū, m/s
  std::vector<double> pressure;      ///< Pa
  std::vector<double> cp, cp_exact;  ///< empty when U = 0 (undefined)
  std::vector<double> shear_stress;  ///< wall shear τ_w = μ(ζ_w − 2ω), Pa (navier-stokes)
};

/// Order of the derivative formulas matching a stencil: 2 (5-point) or 6 (9-point).
int derivative_order(StencilKind stencil);

/// All fields a selection asks for, from ψ and the exact ψ on the same grid (m²/s) and the case's ρ, U, p∞.
Fields compute_fields(const PolarGrid& g, const Scene& scene, const std::vector<double>& psi,
                      const std::vector<double>& psi_exact, const FieldSelection& sel, int order);

/// Surface velocity u_θ(a, θ_j) = −(1/a)·∂ψ/∂ξ at the wall, m/s.
std::vector<double> surface_u_theta(const PolarGrid& g, const std::vector<double>& psi, int order);

/// Surface pressure p = p∞ + ½ρ(U² − u_θ²) and Cp (u_r = 0 on the body) from u_θ.
Surface surface_from_u_theta(const PolarGrid& g, const Scene& scene, std::vector<double> u_theta);

/// Surface from the wall velocities of the superposition basis: ū = U·mean(s_U) + Γ·mean(s_Γ),
/// u' = U·(s_U − mean(s_U)). The Γ part of the discrete flow is axisymmetric (the operator commutes with
/// rotations by Δθ and its boundary data is constant), so its θ-varying remainder is round-off and is
/// dropped: u' carries no error of order ε·|ū| however large α is.
Surface surface_from_basis(const PolarGrid& g, const Scene& scene, const std::vector<double>& s_U,
                           const std::vector<double>& s_Gamma);

/// surface_from_u_theta(surface_u_theta(ψ)).
Surface compute_surface(const PolarGrid& g, const Scene& scene, const std::vector<double>& psi, int order);

/// u_θ(r_i, θ) along the ray θ (periodic cubic interpolation between columns), m/s.
std::vector<double> u_theta_on_ray(const PolarGrid& g, const std::vector<double>& psi, double theta,
                                   int order);

/// Periodic cubic (4-point Lagrange) interpolation of f_j = f(jh), h = 2π/n, at θ.
double periodic_interpolate(const std::vector<double>& f, double theta);

}  // namespace magnus
