// The analytic Jacobian of the steady viscous equations (see ns_newton.hpp): its triplet pattern, built once,
// and its values at a state, summed into compressed columns for UMFPACK.
#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/newton.hpp"

#include <umfpack.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace magnus {

namespace {

/// Arakawa's Jacobian (J++ + J+× + J×+)/3 as 24 bilinear terms c·ψ(i+pi, j+pj)·ζ(i+zi, j+zj), times
/// 1/(12ΔθΔξ): the same sums as NsOperator::advection (j1, j2, j3 there, in that order), written out so
/// that each term's two derivatives are its two factors.
struct ArakawaTerm {
  int c, pi, pj, zi, zj;
};
constexpr ArakawaTerm kArakawa[24] = {
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

}  // namespace

void SteadyJacobian::assemble(const std::vector<double>& x) {
  const int nr = grid_.n_r, n = grid_.n_theta, iN = nr - 1;
  const double h = h_, dth = grid_.d_theta, q2 = (h / dth) * (h / dth), R = grid_.outer_radius();
  const double a2 = p_.a * p_.a;
  const bool first = Ti_.empty();
  size_t k = 0;
  // Arakawa's 48 terms of a ζ row fall on 18 columns (order 4 in θ: 96 terms on 30 columns): the first
  // assembly merges the entries of each run of one row into distinct triplets (k-th call → Slot_[k]), so
  // the compressed columns are built from 2.5–3 times fewer triplets; the later ones only add into Tx_.
  const int order = p_.advection_order, order_xi = p_.advection_order_xi;
  const int strides = order == 4 || order_xi == 4 ? 2 : 1;
  long run_row = -1;
  size_t run_begin = 0;
  if (first) {
    const size_t calls = size_t(n) * (16 + size_t(nr - 2) * (p_.stokes ? 11 : 11 + 48 * strides));
    Slot_.reserve(calls), Ti_.reserve(calls / 2), Tj_.reserve(calls / 2), Tx_.reserve(calls / 2);
  } else {
    std::fill(Tx_.begin(), Tx_.end(), 0.0);
  }
  // Mirror: only the rows of the nodes 0 < θ_j < π enter the half system; the others are not assembled.
  auto dropped = [&](long row) {
    if (!mirror_) return false;
    const long j = (row / 2) % n;
    return row == size_ - 1 || j == 0 || 2 * j >= n;
  };
  auto add = [&](long row, long col, double v) {
    if (dropped(row)) return;
    if (first) {
      if (row != run_row) run_row = row, run_begin = Ti_.size();
      size_t slot = run_begin;
      while (slot < Ti_.size() && Tj_[slot] != col) ++slot;
      if (slot == Ti_.size()) Ti_.push_back(row), Tj_.push_back(col), Tx_.push_back(0.0);
      Slot_.push_back(int(slot));
      Tx_[slot] += v;
    } else {
      Tx_[size_t(Slot_[k])] += v;
    }
    ++k;
  };
  auto cp = [n](int i, int j) { return 2 * (long(i) * n + j); };
  auto cz = [n](int i, int j) { return 2 * (long(i) * n + j) + 1; };
  auto P = [&](int i, int j) { return x[size_t(cp(i, j))]; };
  auto Z = [&](int i, int j) { return x[size_t(cz(i, j))]; };
  auto wrap = [n](int j) { return j < 0 ? j + n : j >= n ? j - n : j; };
  const long gamma = size_ - 1;

  for (int j = 0; j < n; ++j) {  // wall: ψ = 0; Thom
    add(cp(0, j), cp(0, j), s_psi_);
    add(cz(0, j), cp(1, j), s_psi_);
    add(cz(0, j), cz(0, j), 0.5 * a2 * h * h * s_psi_);
  }
  const double cN = -h * h / p_.nu / (12.0 * dth * h) * s_zeta_;  // ∂/∂(term) of −(h²/ν)·N, scaled
  for (int i = 1; i < iN; ++i) {
    const double Jh2 = h * h * grid_.r[i] * grid_.r[i];
    for (int j = 0; j < n; ++j) {
      const int e = wrap(j + 1), w = wrap(j - 1);
      const long rp = cp(i, j), rz = cz(i, j);
      add(rp, cp(i + 1, j), s_psi_), add(rp, cp(i - 1, j), s_psi_);
      add(rp, cp(i, j), (-2.0 - 2.0 * q2) * s_psi_);
      add(rp, cp(i, e), q2 * s_psi_), add(rp, cp(i, w), q2 * s_psi_);
      add(rp, cz(i, j), Jh2 * s_psi_);
      add(rz, cz(i + 1, j), s_zeta_), add(rz, cz(i - 1, j), s_zeta_);
      add(rz, cz(i, j), (-2.0 - 2.0 * q2) * s_zeta_);
      add(rz, cz(i, e), q2 * s_zeta_), add(rz, cz(i, w), q2 * s_zeta_);
      if (p_.stokes) continue;
      AdvectionStride st[2];
      const int terms = advection_terms(order, order_xi, i, nr, st);
      for (int q = 0; q < terms; ++q) {  // strides (s, sx) in θ and ξ, weight c (solver/navier_stokes/arakawa.hpp)
        const int s = st[q].s_theta, sx = st[q].s_xi;
        const double cs = cN * st[q].weight;
        for (const ArakawaTerm& t : kArakawa) {
          const int pi = i + sx * t.pi, pj = wrap(j + s * t.pj), zi = i + sx * t.zi, zj = wrap(j + s * t.zj);
          add(rz, cp(pi, pj), cs * t.c * Z(zi, zj));
          add(rz, cz(zi, zj), cs * t.c * P(pi, pj));
        }
      }
    }
  }
  const bool convect = p_.outer_vorticity == NsOuterVorticity::inflow_outflow;
  const double ff = h / (2.0 * M_PI * p_.nu) * s_zeta_ * dth;  // the flux row's scale times Δθ
  for (int j = 0; j < n; ++j) {
    const int e = wrap(j + 1), w = wrap(j - 1);
    const long rp = cp(iN, j), rz = cz(iN, j);
    add(rp, cp(iN - 1, j), 2.0 * s_psi_);
    add(rp, cp(iN, j), (-2.0 - 2.0 * q2) * s_psi_);
    add(rp, cp(iN, e), q2 * s_psi_), add(rp, cp(iN, w), q2 * s_psi_);
    add(rp, cz(iN, j), h * h * R * R * s_psi_);
    add(rp, gamma, -h / M_PI * s_psi_);
    const double p_theta = (P(iN, e) - P(iN, w)) / (2.0 * dth);
    const bool out = convect && p_theta > 0.0;
    add(rz, cz(iN, j), s_zeta_);
    add(rz, cz(iN - 1, j), out ? -s_zeta_ : 0.0);
    add(gamma, cp(iN, e), -Z(iN, j) / (2.0 * dth) * ff);
    add(gamma, cp(iN, w), Z(iN, j) / (2.0 * dth) * ff);
    add(gamma, cz(iN, j), (-p_theta + 1.5 * p_.nu / h) * ff);
    add(gamma, cz(iN - 1, j), -2.0 * p_.nu / h * ff);
    add(gamma, cz(iN - 2, j), 0.5 * p_.nu / h * ff);
  }
  if (!first && k != Slot_.size()) throw std::logic_error("SteadyJacobian: the pattern changed");
  if (first) {
    triplet_pattern(size_, Ti_, Tj_, Ap_, Ai_, Map_);
    Ax_.resize(Ai_.size());
  }
  std::fill(Ax_.begin(), Ax_.end(), 0.0);
  for (size_t t = 0; t < Tx_.size(); ++t) Ax_[size_t(Map_[t])] += Tx_[t];
}

}  // namespace magnus
