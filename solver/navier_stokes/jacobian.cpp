// The analytic Jacobian of the steady viscous equations (see newton.hpp): its triplet pattern, built once,
// and its values at a state, summed into compressed columns for UMFPACK.
#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stages.hpp"

#include <umfpack.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace magnus {

namespace {

/// Where assemble() puts its entries: the first assembly merges the entries of each run of one row into
/// distinct triplets (the k-th add → slot[k]), so the compressed columns are built from 2.5–3 times fewer
/// triplets; the later ones only add into the values. Mirror: only the rows of the nodes 0 < θ_j < π enter
/// the half system; the others are not assembled.
struct TripletSink {
  std::vector<long>&Ti, &Tj;
  std::vector<int>& slot;
  std::vector<double>& Tx;
  bool first, mirror;
  long size;
  int n;
  size_t k = 0;
  long run_row = -1;
  size_t run_begin = 0;

  bool dropped(long row) const {
    if (!mirror) return false;
    const long j = (row / 2) % n;
    return row == size - 1 || j == 0 || 2 * j >= n;
  }
  void add(long row, long col, double v) {
    if (dropped(row)) return;
    if (first) {
      if (row != run_row) run_row = row, run_begin = Ti.size();
      size_t s = run_begin;
      while (s < Ti.size() && Tj[s] != col) ++s;
      if (s == Ti.size()) Ti.push_back(row), Tj.push_back(col), Tx.push_back(0.0);
      slot.push_back(int(s));
      Tx[s] += v;
    } else {
      Tx[size_t(slot[k])] += v;
    }
    ++k;
  }
  /// add() without the merge, for a long run of distinct columns (a duplicate triplet is summed by the
  /// pattern anyway; the merge's search would be quadratic in the run's length).
  void add_unmerged(long row, long col, double v) {
    if (dropped(row)) return;
    if (first) {
      run_row = -1;
      slot.push_back(int(Ti.size()));
      Ti.push_back(row), Tj.push_back(col), Tx.push_back(v);
    } else {
      Tx[size_t(slot[k])] += v;
    }
    ++k;
  }
};

/// The unknowns' numbering (ψ_q, ζ_q interleaved per node q = i·n_θ + j) and the state x read through it.
struct Unknowns {
  const std::vector<double>& x;
  int n;
  long cp(int i, int j) const { return 2 * (long(i) * n + j); }
  long cz(int i, int j) const { return 2 * (long(i) * n + j) + 1; }
  double P(int i, int j) const { return x[size_t(cp(i, j))]; }
  double Z(int i, int j) const { return x[size_t(cz(i, j))]; }
  int wrap(int j) const { return j < 0 ? j + n : j >= n ? j - n : j; }
};

/// ∂/∂x of −(h²/ν)·N in the ζ row of node (i, j), times cN = −(h²/ν)/(12ΔθΔξ)·s_ζ: each Arakawa term
/// c·ψ·ζ of each stride (advection_terms) gives c·ζ to its ψ and c·ψ to its ζ.
void advection_entries(TripletSink& sink, const Unknowns& u, const NsParams& p, int nr, int i, int j,
                       double cN) {
  AdvectionStride st[2];
  const int terms = advection_terms(p.advection_order, p.advection_order_xi, i, nr, st);
  const long rz = u.cz(i, j);
  // Strides (s, sx) in θ and ξ, weight c (arakawa.hpp).
  for (int q = 0; q < terms; ++q) {
    const int s = st[q].s_theta, sx = st[q].s_xi;
    const double cs = cN * st[q].weight;
    for (const ArakawaTerm& t : kArakawa) {
      const int pi = i + sx * t.pi, pj = u.wrap(j + s * t.pj), zi = i + sx * t.zi, zj = u.wrap(j + s * t.zj);
      sink.add(rz, u.cp(pi, pj), cs * t.c * u.Z(zi, zj));
      sink.add(rz, u.cz(zi, zj), cs * t.c * u.P(pi, pj));
    }
  }
}

/// The ψ and ζ rows of the rings 1…n_r−2: the 5-point Laplacians, J ζ, and the advection's entries.
void interior_rows(TripletSink& sink, const Unknowns& u, const PolarGrid& g, const NsParams& p, double s_psi,
                   double s_zeta) {
  const int n = g.n_theta, iN = g.n_r - 1;
  for (int i = 1; i < iN; ++i) {
    const XiFlux xf = xi_flux(g, i);  // the rows of ring i are scaled by h_i²
    const double h = xf.h, q2 = (h / g.d_theta) * (h / g.d_theta), Jh2 = h * h * g.r[i] * g.r[i];
    const double cN = -h * h / p.nu / (12.0 * g.d_theta * h) * s_zeta;  // ∂/∂(term) of −(h_i²/ν)·N, scaled
    const double c0 = -xf.c_m - xf.c_p - 2.0 * q2, c_s = -h * h * absorbing_shift(g, p, i);
    for (int j = 0; j < n; ++j) {
      const int e = u.wrap(j + 1), w = u.wrap(j - 1);
      const long rp = u.cp(i, j), rz = u.cz(i, j);
      sink.add(rp, u.cp(i + 1, j), xf.c_p * s_psi), sink.add(rp, u.cp(i - 1, j), xf.c_m * s_psi);
      sink.add(rp, u.cp(i, j), c0 * s_psi);
      sink.add(rp, u.cp(i, e), q2 * s_psi), sink.add(rp, u.cp(i, w), q2 * s_psi);
      sink.add(rp, u.cz(i, j), Jh2 * s_psi);
      sink.add(rz, u.cz(i + 1, j), xf.c_p * s_zeta), sink.add(rz, u.cz(i - 1, j), xf.c_m * s_zeta);
      sink.add(rz, u.cz(i, j), (c0 + c_s) * s_zeta);
      sink.add(rz, u.cz(i, e), q2 * s_zeta), sink.add(rz, u.cz(i, w), q2 * s_zeta);
      if (!p.stokes) advection_entries(sink, u, p, g.n_r, i, j, cN);
    }
  }
}

/// The rows of the outer ring (ψ with the far field's ghost ring, ζ inflow/outflow) and of Γ_R (the flux).
void outer_rows(TripletSink& sink, const Unknowns& u, const PolarGrid& g, const NsParams& p, double s_psi,
                double s_zeta, long gamma) {
  const int n = g.n_theta, iN = g.n_r - 1;
  const double h = g.d_xi(iN - 1);  // the outer ring's rows are scaled by Δξ_{N−1/2}²
  const std::array<double, 3> wz = outer_slope_weights(g);
  const double dth = g.d_theta, q2 = (h / dth) * (h / dth), R = g.outer_radius();
  const double ff = h / (2.0 * M_PI * p.nu) * s_zeta * dth;  // the flux row's scale times Δθ
  for (int j = 0; j < n; ++j) {
    const int e = u.wrap(j + 1), w = u.wrap(j - 1);
    const long rp = u.cp(iN, j), rz = u.cz(iN, j);
    sink.add(rp, u.cp(iN - 1, j), 2.0 * s_psi);
    sink.add(rp, u.cp(iN, j), (-2.0 - 2.0 * q2) * s_psi);
    sink.add(rp, u.cp(iN, e), q2 * s_psi), sink.add(rp, u.cp(iN, w), q2 * s_psi);
    sink.add(rp, u.cz(iN, j), h * h * R * R * s_psi);
    sink.add(rp, gamma, -h / M_PI * s_psi);
    const double p_theta = (u.P(iN, e) - u.P(iN, w)) / (2.0 * dth);
    const bool out = outflow(p, p_theta);
    sink.add(rz, u.cz(iN, j), s_zeta);
    sink.add(rz, u.cz(iN - 1, j), out ? -s_zeta : 0.0);
    sink.add(gamma, u.cp(iN, e), -u.Z(iN, j) / (2.0 * dth) * ff);
    sink.add(gamma, u.cp(iN, w), u.Z(iN, j) / (2.0 * dth) * ff);
    sink.add(gamma, u.cz(iN, j), (-p_theta + p.nu * wz[0]) * ff);
    sink.add(gamma, u.cz(iN - 1, j), p.nu * wz[1] * ff);
    sink.add(gamma, u.cz(iN - 2, j), p.nu * wz[2] * ff);
  }
}

/// The Γ_R row's entries of the absorbing layer's −∫∫ λ ζ dA (absorbed_circulation), on the rings it reaches.
void absorbing_rows(TripletSink& sink, const Unknowns& u, const PolarGrid& g, const NsParams& p, double s_zeta,
                    long gamma) {
  const int n = g.n_theta, iN = g.n_r - 1;
  const double ff = g.d_xi(iN - 1) / (2.0 * M_PI * p.nu) * s_zeta * g.d_theta;  // outer_rows' flux scale
  for (int i = 1; i < iN; ++i) {
    const double w = absorbing_weight(g, p, i);
    if (w == 0.0) continue;
    const double c = -w * ff;
    for (int j = 0; j < n; ++j) sink.add_unmerged(gamma, u.cz(i, j), c);
  }
}

}  // namespace

void SteadyJacobian::assemble(const std::vector<double>& x) {
  const int nr = grid_.n_r, n = grid_.n_theta;
  const bool first = Ti_.empty();
  // Arakawa's 48 terms of a ζ row fall on 18 columns (order 4 in θ: 96 terms on 30 columns): TripletSink
  // merges them on the first assembly.
  const int strides = p_.advection_order == 4 || p_.advection_order_xi == 4 ? 2 : 1;
  if (first) {
    const size_t calls = size_t(n) * (16 + size_t(nr - 2) * (p_.stokes ? 11 : 11 + 48 * strides));
    Slot_.reserve(calls), Ti_.reserve(calls / 2), Tj_.reserve(calls / 2), Tx_.reserve(calls / 2);
  } else {
    std::fill(Tx_.begin(), Tx_.end(), 0.0);
  }
  TripletSink sink{Ti_, Tj_, Slot_, Tx_, first, mirror_, size_, n};
  const Unknowns u{x, n};
  const WallClosureRow c = wall_closure_row(grid_, p_);
  for (int j = 0; j < n; ++j) {  // wall: ψ = 0; the closure's row c_1ψ_1 − c_2ψ_2 + c_w ζ_w
    sink.add(u.cp(0, j), u.cp(0, j), s_psi_);
    sink.add(u.cz(0, j), u.cp(1, j), c.c1 * s_psi_);
    if (c.c2 != 0.0) sink.add(u.cz(0, j), u.cp(2, j), -c.c2 * s_psi_);
    sink.add(u.cz(0, j), u.cz(0, j), c.cw * s_psi_);
  }
  interior_rows(sink, u, grid_, p_, s_psi_, s_zeta_);
  outer_rows(sink, u, grid_, p_, s_psi_, s_zeta_, size_ - 1);
  absorbing_rows(sink, u, grid_, p_, s_zeta_, size_ - 1);
  if (!first && sink.k != Slot_.size()) throw std::logic_error("SteadyJacobian: the pattern changed");
  if (first) {
    triplet_pattern(size_, Ti_, Tj_, Ap_, Ai_, Map_);
    Ax_.resize(Ai_.size());
  }
  std::fill(Ax_.begin(), Ax_.end(), 0.0);
  for (size_t t = 0; t < Tx_.size(); ++t) Ax_[size_t(Map_[t])] += Tx_[t];
}

}  // namespace magnus
