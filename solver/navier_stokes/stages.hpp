#pragma once
// The stages of the viscous operator (operator.hpp's equations), each the only place its term is
// discretised: advance() (time_step.cpp) calls them in order, Newton's steady residual (newton.cpp) calls
// the ones it shares (the advection, the 5-point Laplacian, the outer ring's flux and inflow/outflow
// choice). Free functions of the grid, the parameters and row-major arrays (n_r, n_θ), ring 0 the wall,
// ring N = n_r − 1 at R, any ξ spacing (the mode solver's flux form; ring widths h_i = ring_width(i)); Fourier-space stages work on the modes [kb, ke) of (n_r, m)
// arrays (m = n_θ/2 + 1, FFTW's unnormalised r2c), so several threads may run them on disjoint ranges.
#include <array>
#include <complex>
#include <vector>

#include "mesh/polar_grid.hpp"
#include "solver/mode_solver.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// The periodic θ-neighbours of column j of n: east j + 1 and west j − 1.
inline int east(int j, int n) { return j + 1 == n ? 0 : j + 1; }
inline int west(int j, int n) { return j == 0 ? n - 1 : j - 1; }

/// The ξ-part of ring i's Laplacian (1 ≤ i ≤ n_r − 2) in the mode solver's flux form (any ξ spacing),
/// times h_i²: c_p(u_{i+1} − u_i) − c_m(u_i − u_{i−1}), c_p = h_i/Δξ_{i+1/2}, c_m = h_i/Δξ_{i−1/2},
/// h_i = ring_width(i). On a uniform ξ: u_{i+1} − 2u_i + u_{i−1} (c_m = c_p = 1, summed as always).
struct XiFlux {
  double h, c_m, c_p;
  bool uniform;
  double operator()(double um, double u0, double up) const {
    return uniform ? up - 2.0 * u0 + um : c_p * (up - u0) - c_m * (u0 - um);
  }
};
inline XiFlux xi_flux(const PolarGrid& g, int i) {
  const double h = g.ring_width(i);
  if (g.uniform_in_xi()) return {h, 1.0, 1.0, true};
  return {h, h / g.d_xi(i - 1), h / g.d_xi(i), false};
}

/// The 5-point stencil's second differences of u at column j (neighbours e, w) of the rings um, u0, up:
/// ξ: x(u_m, u_0, u_p) (XiFlux), θ: u_e − 2u_0 + u_w (units of u; u_ξξ + u_θθ = xi/h_i² + theta/Δθ²).
struct SecondDifferences {
  double xi, theta;
};
inline SecondDifferences second_differences(const double* um, const double* u0, const double* up, int j,
                                            int e, int w, const XiFlux& x) {
  return {x(um[j], u0[j], up[j]), u0[e] - 2.0 * u0[j] + u0[w]};
}

/// Advection N = ψ_θ ζ_ξ − ψ_ξ ζ_θ on ring i (1 ≤ i ≤ n_r − 2) by Arakawa's Jacobian of p's orders
/// (arakawa.hpp) into N (n_θ values), m²/s²; 0 with p.stokes. Returns max_j κ_ξ|ψ_e − ψ_w| + κ_θ|ψ_p − ψ_m|
/// (κ = advection_factor of each direction's order; 0 with p.stokes), m²/s: ring_cfl_rate turns it into 1/s.
/// On a stretched ξ it is Arakawa's Jacobian in the ring index s (uniform) divided by the metric dξ/ds:
/// the same stencil over 12·Δθ·h_i (h_i = ring_width(i)), conserving with the mode solver's weights h_i.
double advection_ring(const PolarGrid& g, const NsParams& p, const double* psi, const double* zeta, int i,
                      double* N);

/// The CFL rate of ring i, 1/s, from advection_ring's value m: m/(2Δθ h_i J_i) (CFL number = rate·Δt).
inline double ring_cfl_rate(const PolarGrid& g, int i, double m) {
  return m * (1.0 / (2.0 * g.d_theta * g.ring_width(i))) * (1.0 / (g.r[i] * g.r[i]));
}

/// advection_ring on rings 1…n_r−2 into N (n_r·n_θ values; 0 on rings 0 and n_r−1), m²/s², one thread.
/// rate (optional): the largest ring_cfl_rate and the wall ring's |ω|/Δθ, 1/s.
void advection_field(const PolarGrid& g, const NsParams& p, const double* psi, const double* zeta, double* N,
                     double* rate = nullptr);

/// The Crank–Nicolson right-hand side on ring i (1 ≤ i ≤ n_r − 2), 1/s:
///     f_j = −(σ_i − s_i) ζ_j − (ζ_ξξ + ζ_θθ)_j + (2/ν)(w1 N_j + w0 N_prev_j),   σ_i = 2J_i/(νΔt)
/// (s_i = absorbing_shift: the layer's sink, Crank–Nicolson; the Helmholtz shift is σ_i + s_i)
/// (N_prev null: the Euler start, N alone). Adds Σ_j f_j to acc (a finiteness check).
void diffusion_rhs_ring(const PolarGrid& g, const NsParams& p, double dt, const double* zeta, int i,
                        const double* N, const double* N_prev, double w1, double w0, double* f, double& acc);

/// λ(r) of p's absorbing layer at radius r (m), 1/s: absorbing_rate·((r − r_s)/(R − r_s))² beyond
/// r_s = absorbing_start·a, 0 inside it or without a layer (operator.hpp).
inline double absorbing_rate_at(const NsParams& p, double r) {
  const double rs = p.absorbing_start * p.a, R = p.outer_over_a * p.a;
  if (!(p.absorbing_start > 0.0) || !(r > rs)) return 0.0;
  const double x = (r - rs) / (R - rs);
  return p.absorbing_rate * x * x;
}

/// The layer's term on ring i in the units of the Helmholtz shift: s_i = J_i λ(r_i)/ν (dimensionless), so
/// that the vorticity row (the equation times 1/ν) reads ζ_ξξ + ζ_θθ − s_i ζ − N/ν = 0.
inline double absorbing_shift(const PolarGrid& g, const NsParams& p, int i) {
  return g.r[i] * g.r[i] * absorbing_rate_at(p, g.r[i]) / p.nu;
}

/// Ring i's weight in the circulation the layer removes, λ_i J_i h_i (h_i = ring_width(i)), m²/s: per unit ζ
/// and Δθ.
inline double absorbing_weight(const PolarGrid& g, const NsParams& p, int i) {
  return absorbing_rate_at(p, g.r[i]) * g.r[i] * g.r[i] * g.ring_width(i);
}

/// The circulation the layer removes, ∫∫ λ ζ dA = Σ_{0<i<N} absorbing_weight_i Σ_j ζ_ij Δθ, m²/s²; 0 without
/// a layer.
double absorbed_circulation(const PolarGrid& g, const NsParams& p, const double* zeta);

/// ψ_θ at column j of the ring ps (central, periodic), m²/s.
inline double psi_theta(const double* ps, int j, int n, double d_theta) {
  return (ps[east(j, n)] - ps[west(j, n)]) / (2.0 * d_theta);
}

/// Whether the outer ring's column with ψ_θ = p_theta lets the wake out (u_r > 0, convective condition):
/// ψ_θ > 0 with NsOuterVorticity::inflow_outflow; otherwise ζ = 0 there.
inline bool outflow(const NsParams& p, double p_theta) {
  return p.outer_vorticity == NsOuterVorticity::inflow_outflow && p_theta > 0.0;
}

/// ∂ζ/∂ξ on the outer ring from the rings N, N−1, N−2 (one-sided, second order, any ξ spacing):
/// w_0 ζ_N + w_1 ζ_{N−1} + w_2 ζ_{N−2}, the weights w (1 per unit ξ).
std::array<double, 3> outer_slope_weights(const PolarGrid& g);

/// dΓ_R/dt = Σ_j (−ψ_θ ζ + ν ζ_ξ)|_R Δθ (ζ_ξ by outer_slope_weights) − absorbed_circulation of the fields
/// psi, zeta, m²/s².
double circulation_flux(const PolarGrid& g, const NsParams& p, const double* psi, const double* zeta);

/// ζ on the outer ring a step dt later into out (n_θ values), 1/s: 0 on inflow; on outflow
/// ζ_t + (ψ_θ/J) ζ_ξ = 0, explicit upwind (over the last spacing Δξ_{N−1/2}).
void outer_vorticity(const PolarGrid& g, const NsParams& p, double dt, const double* psi, const double* zeta,
                     double* out);

/// r2c of the far-field data ψ_ξ = U R sinθ − Γ_R/2π into g_hat (m values: modes 0 and 1, the rest 0).
void far_field_hat(const PolarGrid& g, const NsParams& p, double Gamma_R, std::complex<double>* g_hat);

/// Helmholtz (the implicit diffusion) on modes [kb, ke): ζ̂* from f̂ in zeta_hat, ζ = 0 at the wall,
/// ζ = outer_hat at R (zero_hat: m zeros).
void helmholtz_modes(const ModeSolver& helmholtz, std::complex<double>* zeta_hat,
                     const std::complex<double>* zero_hat, const std::complex<double>* outer_hat, int kb,
                     int ke);

/// Poisson on modes [kb, ke): ψ̂* of ψ_ξξ + ψ_θθ = −J ζ̂* into psi_hat, ψ = 0 at the wall, ψ_ξ = g_hat at R.
void poisson_modes(const ModeSolver& poisson, const PolarGrid& g, const std::complex<double>* zeta_hat,
                   std::complex<double>* psi_hat, const std::complex<double>* zero_hat,
                   const std::complex<double>* g_hat, int kb, int ke);

/// The wall's ζ_w row c_1ψ_1 − c_2ψ_2 + c_w ζ_w = −κ h_0 a²ω (m²/s) of p.wall_closure on g's first
/// spacings h_0 = ξ_1 − ξ_0, h_1 = ξ_2 − ξ_1, ρ = (h_0 + h_1)/h_0. Thom: c_1 = 1, c_2 = 0, c_w = a²h_0²/2,
/// κ = 1. Jensen (ψ_ξξξ eliminated between the two rings' Taylor series): c_1 = ρ³, c_2 = 1,
/// c_w = a²h_0²ρ²(ρ − 1)/2, κ = ρ(ρ² − 1) (uniform ξ: 8ψ_1 − ψ_2 + 2a²h²ζ_w = −6h a²ω).
struct WallClosureRow {
  double c1, c2, cw, kappa;
};
WallClosureRow wall_closure_row(const PolarGrid& g, const NsParams& p);

/// The wall closure's influence data, ring-major [i][k]: φ_k(ξ_i), χ_k(ξ_i) (operator.hpp), per mode
/// c_1χ_k(ξ_1) − c_2χ_k(ξ_2) + c_w, and the row. With the rotation implicit (rotation.hpp) the step's φ_k,
/// χ_k and denominators are complex (phi_c, chi_c, denom_c; else empty): wall_closure_modes takes those,
/// on ring i only the modes [0, modes_c[i]) whose φ_k or χ_k there is above 1e-17 of its largest (high
/// modes decay within a few rings: r^−k and faster).
struct WallInfluence {
  std::vector<double> phi_t, chi_t, denom;
  std::vector<std::complex<double>> phi_c, chi_c, denom_c;
  std::vector<int> modes_c;
  WallClosureRow row;
};

/// The wall closure on modes [kb, ke): δ_k = (t_k − c_1ψ̂*_{1,k} + c_2ψ̂*_{2,k})/denom_k (ζ̂*_w = 0) with
/// t_0 = target0 = −n_θ κ h_0 a²ω (the closure's ψ_ξ = −a²ω), t_k = 0 else; ζ̂ += δ_k φ_k, ψ̂ += δ_k χ_k on
/// every ring. delta: m values.
void wall_closure_modes(const WallInfluence& w, int n_r, int m, double target0,
                        std::complex<double>* zeta_hat, std::complex<double>* psi_hat,
                        std::complex<double>* delta, int kb, int ke);

}  // namespace magnus
