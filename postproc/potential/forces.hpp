#pragma once
// Forces from the surface pressure, the three lift figures, stagnation points and error norms.
#include <functional>
#include <optional>
#include <vector>
#include "physics/exact.hpp"
#include "postproc/potential/fields.hpp"

namespace magnus {

/// Forces per unit span and the comparisons of docs/design.md. Coefficients are empty when U = 0.
struct Forces {
  double lift = 0.0, drag = 0.0;             ///< F_y, F_x, N/m
  std::optional<double> cl, cd;              ///< F/(½ρU²·2a)
  std::optional<double> cl_kutta_joukowski;  ///< −Γ/(Ua)
  std::optional<double> cl_seed_estimate;    ///< −4α
  double lift_kutta_joukowski = 0.0;         ///< −ρUΓ, N/m
  double delta_p_top_bottom = 0.0;           ///< p(a, π/2) − p(a, 3π/2), Pa
  double delta_p_top_bottom_exact = 0.0;     ///< 4ρUΓ/(2πa), Pa
  double delta_p_seed_estimate = 0.0;        ///< 2ρUaω, Pa
  double circulation_measured = 0.0;         ///< ∮ u_θ a dθ at r = a, m²/s
  std::optional<double> magnus_S;            ///< S = −F_y/(Uω), kg/m (F = S ω × v_body)
  /// S exact, kg/m: 2πρa² (spin model); ρΓ/ω for a given Γ (F_y = −ρUΓ = −S·U·ω), empty when ω = 0
  /// (undefined)
  std::optional<double> magnus_S_exact;
};

/// F = −∮ p n̂ a dθ by the periodic trapezoid, in the form ½ρ∮(2ū u' + u'²) n̂ a dθ with the surface's
/// split u_θ = ū + u': the constant parts, p∞ and ½ρ(U² − ū²), integrate to zero exactly and are dropped.
Forces compute_forces(const Scene& scene, const Surface& s);

/// Stagnation points from the computed flow: sign changes of the surface u_θ, or else of u_θ along
/// the y axis on the side of Γ (a free point, |Γ| > 4πaU); ray(θ) gives u_θ(r_i, θ), m/s. θ in [0, 2π),
/// sorted by θ (sorted_stagnation_points).
std::vector<StagnationPoint> find_stagnation_points(const PolarGrid& g, const Scene& scene,
                                                    const std::vector<double>& surface_u_theta,
                                                    const std::function<std::vector<double>(double)>& ray);

/// Errors against the exact solution (/errors in the result file); psi_exact is ExactFlow::psi_field on the
/// same grid.
struct Errors {
  double psi_max_rel = 0.0;                  ///< max|ψ − ψ_ex| / max|ψ_ex|
  std::optional<double> cp_surface_max_abs;  ///< max|Cp − Cp_ex| on r = a (U > 0)
  /// |F_y − F_y,KJ| / |F_y,KJ| (absolute in units of ½ρU²·2a when F_y,KJ = 0); empty when U = 0 (undefined)
  std::optional<double> cl_rel;
  double circulation_rel = 0.0;  ///< |Γ_measured − Γ| / |Γ| (/(2πaU) when Γ = 0)
};
/// |F_y − F_y,KJ| / |F_y,KJ|; when F_y,KJ = 0, the absolute C_L error (U > 0) or the lift itself (N/m).
double lift_error(const Scene& scene, const Forces& f);

Errors compute_errors(const Scene& scene, const std::vector<double>& psi,
                      const std::vector<double>& psi_exact, const Surface& s, const Forces& f);

/// θ wrapped into [0, 2π), rad (a value within 1e-9 below 2π becomes 0).
double wrap_angle(double theta);
/// Stagnation points with θ in [0, 2π), sorted by θ: the one order every table and file uses.
std::vector<StagnationPoint> sorted_stagnation_points(const std::vector<StagnationPoint>& in);

}  // namespace magnus
