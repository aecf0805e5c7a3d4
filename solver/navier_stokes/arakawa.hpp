#pragma once
// Arakawa's (1966) energy- and enstrophy-conserving Jacobian J = (J++ + J+× + J×+)/3 of ∂(ψ,ζ)/∂(θ,ξ) =
// ψ_θ ζ_ξ − ψ_ξ ζ_θ at one node, x = θ (column j, periodic), y = ξ (ring i), second order; and its
// fourth-order forms in θ, in ξ, or in both. One definition for the time stepper and the steady (Newton)
// equations, so both sum in the same order to the last bit.

#include <cstddef>

namespace magnus {

/// 12·Δθ·Δξ·J at column j of ring i from the rings i−1, i, i+1 of ψ (pm, p0, pp) and ζ (zm, z0, zp), with
/// θ-neighbours e and w (columns j ± s: s = 1 the scheme; s = 2 the same on the sub-lattice of every other
/// column, whose θ-differences span 4Δθ); divide by 12·Δθ·Δξ for J (m²/s² with ψ in m²/s and ζ in 1/s, per
/// unit ξ and θ). e and w index the same arrays: wrapped (arakawa_12) or into padded copies (no wrap).
inline double arakawa_12_ew(const double* pm, const double* p0, const double* pp, const double* zm,
                            const double* z0, const double* zp, std::ptrdiff_t j, std::ptrdiff_t e,
                            std::ptrdiff_t w) {
  const double j1 = (p0[e] - p0[w]) * (zp[j] - zm[j]) - (pp[j] - pm[j]) * (z0[e] - z0[w]);
  const double j2 =
      p0[e] * (zp[e] - zm[e]) - p0[w] * (zp[w] - zm[w]) - pp[j] * (zp[e] - zp[w]) + pm[j] * (zm[e] - zm[w]);
  const double j3 =
      zp[j] * (pp[e] - pp[w]) - zm[j] * (pm[e] - pm[w]) - z0[e] * (pp[e] - pm[e]) + z0[w] * (pp[w] - pm[w]);
  return j1 + j2 + j3;
}

/// 12·Δθ·Δξ·J at column j of ring i (arakawa_12_ew with its periodic θ-neighbours j ± s of n columns).
inline double arakawa_12(const double* pm, const double* p0, const double* pp, const double* zm,
                         const double* z0, const double* zp, int j, int n, int s = 1) {
  const int e = j + s >= n ? j + s - n : j + s, w = j < s ? j - s + n : j - s;
  return arakawa_12_ew(pm, p0, pp, zm, z0, zp, j, e, w);
}

/// One Arakawa Jacobian of an advection scheme: θ-stride s_theta, ξ-stride s_xi (1 or 2; stride 2 is the
/// scheme on the sub-lattice of every other column or ring, its differences spanning twice the distance)
/// and its weight in 12·Δθ·Δξ·J.
struct AdvectionStride {
  int s_theta = 1, s_xi = 1;
  double weight = 1.0;
};

/// The Jacobians of advection order p_theta in θ and p_xi in ξ (2 or 4 each) at ring i of n_r; returns how
/// many (1 or 2) it wrote to `out`. A_{s,t} ≈ s·t·(12ΔθΔξ J) + s·t·(s²E_θ + t²E_ξ) with E the second-order
/// errors, so a fourth-order direction cancels its E by a stride-2 term: θ only (4/3)A_11 − (1/6)A_21, ξ only
/// (4/3)A_11 − (1/6)A_12, both (4/3)A_11 − (1/12)A_22. Every term of Arakawa's three forms holds one
/// θ- and one ξ-difference, so each is replaced by the fourth-order (4/3)D_1 − (1/3)D_2; a sum of conserving
/// Jacobians, it conserves what each conserves. ξ-order 4 needs the rings i ± 2: on rings 1 and n_r − 2
/// (next to the wall and the outer ring) ξ falls back to second order.
inline int advection_terms(int p_theta, int p_xi, int i, int n_r, AdvectionStride out[2]) {
  const bool t4 = p_theta == 4, x4 = p_xi == 4 && i >= 2 && i <= n_r - 3;
  out[0] = {1, 1, t4 || x4 ? 4.0 / 3.0 : 1.0};
  if (!t4 && !x4) return 1;
  out[1] = {t4 ? 2 : 1, x4 ? 2 : 1, t4 && x4 ? -1.0 / 12.0 : -1.0 / 6.0};
  return 2;
}

/// Columns (θ) the advection of order p reaches either side of a node: 1 or 2; rings (ξ) likewise.
inline int advection_reach(int p) { return p == 4 ? 2 : 1; }

/// 12·Δθ·Δξ·J at node (i, j) of the fields psi, zeta (row-major (n_r, n), ring 0 the wall, 1 ≤ i ≤ n_r − 2)
/// with advection order p_theta in θ and p_xi in ξ: Σ weight·A_{s_theta, s_xi} over advection_terms.
inline double advection_12(int p_theta, int p_xi, const double* psi, const double* zeta, int i, int j, int n,
                           int n_r) {
  AdvectionStride t[2];
  const int terms = advection_terms(p_theta, p_xi, i, n_r, t);
  double J = 0.0;
  for (int q = 0; q < terms; ++q) {
    const size_t m = size_t(i - t[q].s_xi) * n, c = size_t(i) * n, p = size_t(i + t[q].s_xi) * n;
    J +=
        t[q].weight * arakawa_12(psi + m, psi + c, psi + p, zeta + m, zeta + c, zeta + p, j, n, t[q].s_theta);
  }
  return J;
}

/// Arakawa's Jacobian (J++ + J+× + J×+)/3 as 24 bilinear terms c·ψ(i+pi, j+pj)·ζ(i+zi, j+zj), times
/// 1/(12ΔθΔξ) (offsets times a stride's s_xi, s_theta): the same sums as arakawa_12 (j1, j2, j3 there, in
/// that order), written out so that each term's two derivatives are its two factors. The linearised
/// operators (the steady Jacobian, the spanwise problem) take their entries from it.
struct ArakawaTerm {
  int c, pi, pj, zi, zj;
};
inline constexpr ArakawaTerm kArakawa[24] = {
    // j1 = (ψ_0e − ψ_0w)(ζ_pj − ζ_mj) − (ψ_pj − ψ_mj)(ζ_0e − ζ_0w)
    {+1, 0, +1, +1, 0},
    {-1, 0, +1, -1, 0},
    {-1, 0, -1, +1, 0},
    {+1, 0, -1, -1, 0},
    {-1, +1, 0, 0, +1},
    {+1, +1, 0, 0, -1},
    {+1, -1, 0, 0, +1},
    {-1, -1, 0, 0, -1},
    // j2 = ψ_0e(ζ_pe − ζ_me) − ψ_0w(ζ_pw − ζ_mw) − ψ_pj(ζ_pe − ζ_pw) + ψ_mj(ζ_me − ζ_mw)
    {+1, 0, +1, +1, +1},
    {-1, 0, +1, -1, +1},
    {-1, 0, -1, +1, -1},
    {+1, 0, -1, -1, -1},
    {-1, +1, 0, +1, +1},
    {+1, +1, 0, +1, -1},
    {+1, -1, 0, -1, +1},
    {-1, -1, 0, -1, -1},
    // j3 = ζ_pj(ψ_pe − ψ_pw) − ζ_mj(ψ_me − ψ_mw) − ζ_0e(ψ_pe − ψ_me) + ζ_0w(ψ_pw − ψ_mw)
    {+1, +1, +1, +1, 0},
    {-1, +1, -1, +1, 0},
    {-1, -1, +1, -1, 0},
    {+1, -1, -1, -1, 0},
    {-1, +1, +1, 0, +1},
    {+1, -1, +1, 0, +1},
    {+1, +1, -1, 0, -1},
    {-1, -1, -1, 0, -1}};

/// The largest modified wavenumber of the difference of advection order 2 or 4, times the spacing: 1, and
/// max_x[(4/3)sin x − (1/6)sin 2x] = 1.3722 (x = 1.797). The CFL number's θ and ξ parts are scaled by the
/// factor of their direction's order, so that one limit holds for every order.
inline double advection_factor(int order) { return order == 4 ? 1.3722 : 1.0; }

}  // namespace magnus
