#pragma once
// The wall's spin taken implicitly in the time step (NsParams::implicit_rotation). The streamfunction splits
// into the potential vortex of the wall's spin and the rest, ψ = ψ_ref + ψ',
//     ψ_ref(ξ) = −a²ω ξ   (ψ_ξ = −a²ω on every ring: u_θ = a²ω/r, the wall's speed aω at r = a),
// and Arakawa's Jacobian is linear in ψ, so N = J(ψ_ref, ζ) + J(ψ', ζ) exactly on the grid. Aζ = J(ψ_ref, ζ)
// is linear in ζ, steady and the same on every column: per θ-Fourier mode k a tridiagonal operator in the
// ring index with complex symbols â_{i,d}(k) (d = −1, 0, 1; its stencil read off advection_ring itself).
// Crank–Nicolson takes A with the diffusion, Adams–Bashforth 2 takes N' = J(ψ', ζ):
//     ζ^{n+1}_ξξ + ζ^{n+1}_θθ − σ_i ζ^{n+1} − Aζ^{n+1}/ν = −σ_i ζ^n − Lζ^n + Aζ^n/ν + (2/ν)·N'^{n+1/2},
// one complex tridiagonal solve per mode (RotationFactors), and the explicit CFL rate is ψ''s: the wall
// ring's |ω|/Δθ and the spin's share near the wall leave it. At a steady state the two halves sum to the
// full N again (the same steady equations as Newton's). A is skew-adjoint in the weights h_i (Arakawa's
// enstrophy conservation), so its Crank–Nicolson step conserves Σ h_i r_i² ζ² of its own part exactly.
// Used when rotation_implicit(p): ω ≠ 0, advection on, advection order 2 in ξ (order 4 in ξ reaches the
// rings i ± 2: a pentadiagonal operator; that case keeps the explicit scheme).
#include <complex>
#include <vector>

#include "mesh/polar_grid.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// a·b written out: std::complex's operator* checks for NaN and infinity after each product (C99 Annex G),
/// which keeps the per-mode loops from vectorising; finite data gives the same value.
inline std::complex<double> cmul(std::complex<double> a, std::complex<double> b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}
/// a·b for a real b: std::complex's own (the explicit scheme's products, bit for bit).
inline std::complex<double> cmul(std::complex<double> a, double b) { return a * b; }

/// Whether the step takes J(ψ_ref, ζ) implicitly: p.implicit_rotation, ω ≠ 0, not p.stokes, advection
/// order 2 in ξ.
bool rotation_implicit(const NsParams& p);

/// ψ_ξ of the implicit part, m²/s: −a²ω when rotation_implicit(p), else 0 (the CFL rate's ψ' = ψ − ψ_ref).
double reference_psi_xi(const NsParams& p);

/// ψ_ref on every node, −a²ω ξ_i (n_r·n_θ values, row-major), m²/s.
std::vector<double> reference_psi(const PolarGrid& g, const NsParams& p);

/// J(ψ_ref, ·) of advection_ring as a stencil: (Aζ)_{i,j} = Σ_d Σ_t w_{i,d,t} ζ_{i+d, j−t}, d = −1…1,
/// t = −reach…reach (reach: the θ-order's columns either side), w in m²/s per unit ξ and θ (N's units per ζ).
struct RotationStencil {
  int n_r = 0, n_theta = 0, reach = 1;
  std::vector<double> w;  ///< [i][d + 1][t + reach], rings 1…n_r−2 (rings 0 and n_r−1: 0)
  double at(int i, int d, int t) const {
    return w[(size_t(i) * 3 + size_t(d + 1)) * size_t(2 * reach + 1) + size_t(t + reach)];
  }
};

/// The stencil of A read off advection_ring (ψ_ref, a unit ζ on one node of ring i + d at a time): the same
/// orders in θ, the same ring widths and metric, so A is advection_ring's to round-off by construction.
RotationStencil rotation_stencil(const PolarGrid& g, const NsParams& p);

/// Adds scale·(Aζ) on ring i (1 ≤ i ≤ n_r − 2) to out (n_θ values), one pass over the columns.
void add_rotation_ring(const RotationStencil& s, const double* zeta, int i, double scale, double* out);

/// â_{i,d}(k) = Σ_t w_{i,d,t} e^{−iktΔθ}: A per Fourier mode k (FFTW's r2c sign), (Âζ̂)_i = Σ_d â_{i,d} ζ̂_{i+d}.
std::complex<double> rotation_symbol(const RotationStencil& s, int i, int d, int k);

/// The Helmholtz operator with A, per mode k, factored (complex Thomas, no pivoting: the rows times −h_i are
/// the real symmetric positive-definite diffusion rows plus (h_i/ν)Â, whose Hermitian part is zero), rings
/// 1…L = n_r−2 unknown, ζ given on the wall and on R. A is skew-adjoint in the weights h_i and its symbols
/// are imaginary, so h_i â_{i,−1} = h_{i−1} â_{i−1,+1} (to round-off; the test asserts it): the rows are
/// complex symmetric, taken as T(i,i−1) = T(i−1,i), and the lower factor is the upper one of the ring
/// before (as in ModeSolver).
///     [(ζ̂_{i+1} − ζ̂_i)/Δξ_{i+1/2} − (ζ̂_i − ζ̂_{i−1})/Δξ_{i−1/2}]/h_i − (λ_k + σ_i)ζ̂_i − (Âζ̂)_i/ν = f̂_i.
struct RotationFactors {
  int n_r = 0, m = 0, L = 0;
  std::vector<double> h;                            ///< h_i (the mode solver's), rings 0…L
  std::vector<std::complex<double>> inv_pivot;      ///< [i−1][k]: 1/d'_i
  std::vector<std::complex<double>> upper;          ///< [i−1][k]: T(i,i+1)/d'_i
  std::vector<std::complex<double>> wall, outer;    ///< [k]: −T(1,0), −T(L,L+1) (boundary values' weights)
};

/// Factor the modes for shifts σ_i = 2J_i/(νΔt) (n_r values) and A's stencil.
RotationFactors factor_rotation(const PolarGrid& g, const std::vector<double>& sigma, const RotationStencil& s,
                                double nu);

/// The solve on modes [kb, ke) in place, like ModeSolver::solve_mode_range: u_hat (n_r, m) holds f̂ on rings
/// 1…L on entry, ζ̂ on every ring on exit (the wall ring = wall_hat, the outer ring = outer_hat).
void solve_rotation_modes(const RotationFactors& f, std::complex<double>* u_hat,
                          const std::complex<double>* wall_hat, const std::complex<double>* outer_hat, int kb,
                          int ke);

/// φ_k(ξ_i), i = 0…n_r−1: the response to unit wall vorticity in mode k (f = 0, ζ = 0 on R), complex.
std::vector<std::complex<double>> rotation_influence(const RotationFactors& f, int k);

}  // namespace magnus
