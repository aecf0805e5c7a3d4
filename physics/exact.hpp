#pragma once
// The exact potential flow past a spinning cylinder: the reference for every test and report.
// Never used by the solver.
#include <vector>
#include "physics/scene.hpp"

namespace magnus {

struct StagnationPoint {
  double r = 0.0;      ///< m
  double theta = 0.0;  ///< rad in [0, 2π)
  bool on_surface = true;
};

/// ψ = U (r − a²/r) sinθ − (Γ/2π) ln(r/a), with its gradient, pressure and forces.
struct ExactFlow {
  double a = 1.0;      ///< radius, m
  double U = 1.0;      ///< freestream speed, m/s
  double Gamma = 0.0;  ///< circulation, m²/s

  /// ψ(r, θ), m²/s.
  double psi(double r, double theta) const;
  /// u_r = U (1 − a²/r²) cosθ, m/s.
  double u_r(double r, double theta) const;
  /// u_θ = −U (1 + a²/r²) sinθ + Γ/(2πr), m/s.
  double u_theta(double r, double theta) const;
  /// Cp = 1 − |u|²/U² (U > 0).
  double cp(double r, double theta) const;
  /// Lift per span F_y = −ρUΓ (Kutta–Joukowski), N/m.
  double lift(double rho) const { return -rho * U * Gamma; }
  /// C_L = F_y/(½ρU²·2a) = −Γ/(Ua) (U > 0).
  double cl() const { return -Gamma / (U * a); }
  /// p(a, π/2) − p(a, 3π/2) = 4ρU·Γ/(2πa), Pa.
  double delta_p_top_bottom(double rho) const;
  /// Stagnation points, sorted by θ in [0, 2π): two on the surface (sinθ_s = Γ/(4πaU)), one on the surface at
  /// θ = ±π/2 when |sinθ_s| = 1 (to within 1e-12), or one free on the y axis.
  std::vector<StagnationPoint> stagnation_points() const;
  /// ψ on every node (r_i, θ_j) of a polar grid, row-major (n_r, n_θ), m²/s.
  std::vector<double> psi_field(const std::vector<double>& r, const std::vector<double>& theta) const;
};

/// The exact flow of a scene: a, U and Γ from its parameters.
ExactFlow exact_flow(const Scene& s);

/// The seed's estimate ΔP = 2ρ U a ω, Pa.
double seed_delta_p(const Scene& s);
/// The seed's lift coefficient C_L = −4α (F = ΔP·2a on ½ρU²·2a).
double seed_cl(const Scene& s);

}  // namespace magnus
