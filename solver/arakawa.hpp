#pragma once
// Arakawa's (1966) energy- and enstrophy-conserving Jacobian J = (J++ + J+× + J×+)/3 of ∂(ψ,ζ)/∂(θ,ξ) =
// ψ_θ ζ_ξ − ψ_ξ ζ_θ at one node, x = θ (column j, periodic), y = ξ (ring i). One definition for the time
// stepper and the steady (Newton) equations, so both sum in the same order to the last bit.

namespace magnus {

/// 12·Δθ·Δξ·J at column j of ring i, from the rings i−1, i, i+1 of ψ (pm, p0, pp) and ζ (zm, z0, zp), each n
/// values (periodic in j); divide by 12·Δθ·Δξ for J (m²/s² with ψ in m²/s and ζ in 1/s, per unit ξ and θ).
inline double arakawa_12(const double* pm, const double* p0, const double* pp, const double* zm,
                         const double* z0, const double* zp, int j, int n) {
  const int e = j + 1 == n ? 0 : j + 1, w = j == 0 ? n - 1 : j - 1;
  const double j1 = (p0[e] - p0[w]) * (zp[j] - zm[j]) - (pp[j] - pm[j]) * (z0[e] - z0[w]);
  const double j2 =
      p0[e] * (zp[e] - zm[e]) - p0[w] * (zp[w] - zm[w]) - pp[j] * (zp[e] - zp[w]) + pm[j] * (zm[e] - zm[w]);
  const double j3 =
      zp[j] * (pp[e] - pp[w]) - zm[j] * (pm[e] - pm[w]) - z0[e] * (pp[e] - pm[e]) + z0[w] * (pp[w] - pm[w]);
  return j1 + j2 + j3;
}

}  // namespace magnus
