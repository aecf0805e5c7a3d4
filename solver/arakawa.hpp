#pragma once
// Arakawa's (1966) energy- and enstrophy-conserving Jacobian J = (J++ + J+× + J×+)/3 of ∂(ψ,ζ)/∂(θ,ξ) =
// ψ_θ ζ_ξ − ψ_ξ ζ_θ at one node, x = θ (column j, periodic), y = ξ (ring i), second order; and its
// fourth-order-in-θ form. One definition for the time stepper and the steady (Newton) equations, so both
// sum in the same order to the last bit.

namespace magnus {

/// 12·Δθ·Δξ·J at column j of ring i, from the rings i−1, i, i+1 of ψ (pm, p0, pp) and ζ (zm, z0, zp), each n
/// values (periodic in j), with θ-neighbours j ± s (s = 1: the scheme; s = 2: the same on the sub-lattice of
/// every other column, whose θ-differences span 4Δθ); divide by 12·Δθ·Δξ for J (m²/s² with ψ in m²/s and ζ
/// in 1/s, per unit ξ and θ).
inline double arakawa_12(const double* pm, const double* p0, const double* pp, const double* zm,
                         const double* z0, const double* zp, int j, int n, int s = 1) {
  const int e = j + s >= n ? j + s - n : j + s, w = j < s ? j - s + n : j - s;
  const double j1 = (p0[e] - p0[w]) * (zp[j] - zm[j]) - (pp[j] - pm[j]) * (z0[e] - z0[w]);
  const double j2 =
      p0[e] * (zp[e] - zm[e]) - p0[w] * (zp[w] - zm[w]) - pp[j] * (zp[e] - zp[w]) + pm[j] * (zm[e] - zm[w]);
  const double j3 =
      zp[j] * (pp[e] - pp[w]) - zm[j] * (pm[e] - pm[w]) - z0[e] * (pp[e] - pm[e]) + z0[w] * (pp[w] - pm[w]);
  return j1 + j2 + j3;
}

/// Weights of the θ-strides s = 1, 2 in 12·Δθ·Δξ·J of advection order 2 or 4 (in θ; ξ stays second
/// order): order 4 is (4/3)·A_1 − (1/6)·A_2, A_s = arakawa_12(…, s). Every term of Arakawa's three forms
/// holds one θ-difference, so this replaces each by the fourth-order (4/3)D_1 − (1/3)D_2 (A_2's differences
/// span twice the distance: −(1/3)/2); a sum of conserving Jacobians, it conserves what each conserves.
inline double advection_weight(int order, int s) {
  if (order != 4) return s == 1 ? 1.0 : 0.0;
  return s == 1 ? 4.0 / 3.0 : -1.0 / 6.0;
}

/// θ-strides the advection of this order uses (1 or 2).
inline int advection_strides(int order) { return order == 4 ? 2 : 1; }

/// 12·Δθ·Δξ·J of advection order 2 (Arakawa) or 4 (fourth order in θ): Σ_s advection_weight(order, s)·A_s
/// over the strides s = 1 … advection_strides(order); same arguments as arakawa_12.
inline double advection_12(int order, const double* pm, const double* p0, const double* pp, const double* zm,
                           const double* z0, const double* zp, int j, int n) {
  double J = advection_weight(order, 1) * arakawa_12(pm, p0, pp, zm, z0, zp, j, n);
  for (int s = 2; s <= advection_strides(order); ++s)
    J += advection_weight(order, s) * arakawa_12(pm, p0, pp, zm, z0, zp, j, n, s);
  return J;
}

/// The largest modified wavenumber of the θ-difference of advection order 2 or 4, times Δθ: 1, and
/// max_x[(4/3)sin x − (1/6)sin 2x] = 1.3722 (x = 1.797). The CFL number's θ part is scaled by it, so that one
/// limit holds for both orders.
inline double advection_theta_factor(int order) { return order == 4 ? 1.3722 : 1.0; }

}  // namespace magnus
