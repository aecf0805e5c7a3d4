#include "solver/potential/stencil.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace magnus {

double DiscreteOperator::symbol(int i, int d, int k) const {
  const RingStencil& s = ring[i];
  return s.a[d + 1] + 2.0 * std::cos(k * d_theta) * s.b[d + 1];
}

double DiscreteOperator::exterior(int k) const { return symbol(n_r - 1, +1, k) * mu[k]; }

namespace {

/// 5-point flux form on a (possibly non-uniform) ξ grid: w = Δθ/Δξ_{i±1/2}, V_i = (Δξ_− + Δξ_+)/2.
RingStencil five_point(double dxi_minus, double dxi_plus, double d_theta) {
  const double wm = d_theta / dxi_minus, wp = d_theta / dxi_plus;
  const double v = 0.5 * (dxi_minus + dxi_plus) / d_theta;
  RingStencil s;
  s.a = {-wm, wm + wp + 2.0 * v, -wp};
  s.b = {0.0, -v, 0.0};
  return s;
}

/// Compact 9-point (Mehrstellen) on uniform ξ: L = D_ξξ + D_θθ + (Δξ² + Δθ²)/12·D_ξξ·D_θθ,
/// times −Δξ·Δθ. With p = Δθ/Δξ, q = Δξ/Δθ, s = (p + q)/12.
RingStencil nine_point(double dxi, double d_theta) {
  const double p = d_theta / dxi, q = dxi / d_theta, s = (p + q) / 12.0;
  RingStencil st;
  st.a = {-p + 2.0 * s, 2.0 * p + 2.0 * q - 4.0 * s, -p + 2.0 * s};
  st.b = {-s, -q + 2.0 * s, -s};
  return st;
}

/// Decaying root of off·μ² + diag·μ + off = 0 (|μ| < 1), D = −diag/off, in the stable form
/// μ = 2/(D ± √(D²−4)): positive for D > 2; negative (alternating) for D < −2, which the 9-point stencil's
/// high modes reach on cells with Δξ/Δθ > √2. |D| ≤ 2 only for mode 0 (μ = 1).
double decaying_root(double diag, double off) {
  const double D = -diag / off;
  if (D > 2.0) return 2.0 / (D + std::sqrt((D - 2.0) * (D + 2.0)));
  if (D < -2.0) return 2.0 / (D - std::sqrt((D - 2.0) * (D + 2.0)));
  return 1.0;
}

}  // namespace

std::string stencil_refusal(const PolarGrid& grid, StencilKind stencil) {
  if (stencil == StencilKind::nine_point && !grid.uniform_in_xi())
    return "solver.stencil = \"9-point\" needs grid.spacing = \"geometric\" (uniform in ln r); "
           "use the 5-point stencil for uniform spacing";
  return "";
}

DiscreteOperator make_operator(const PolarGrid& grid, StencilKind stencil, FarField far_field) {
  const std::string why = stencil_refusal(grid, stencil);
  if (!why.empty()) throw std::invalid_argument(why);
  DiscreteOperator op;
  op.n_r = grid.n_r;
  op.n_theta = grid.n_theta;
  op.d_theta = grid.d_theta;
  op.stencil = stencil;
  op.far_field = far_field;
  op.r_outer = grid.outer_radius();
  const int i_outer = grid.n_r - 1;
  const double dxi_ext = grid.d_xi(i_outer - 1);  // the exterior continues with the last ξ spacing
  op.r_ghost = op.r_outer * std::exp(dxi_ext);
  op.ring.resize(grid.n_r);
  for (int i = 1; i <= i_outer; ++i) {
    const double dm = grid.d_xi(i - 1), dp = i < i_outer ? grid.d_xi(i) : dxi_ext;
    op.ring[i] =
        stencil == StencilKind::nine_point ? nine_point(dp, grid.d_theta) : five_point(dm, dp, grid.d_theta);
  }
  // Ring 0 (the body, not an unknown) only defines the flux weight w_{1/2}.
  op.ring[0] = stencil == StencilKind::nine_point ? nine_point(grid.d_xi(0), grid.d_theta)
                                                  : five_point(grid.d_xi(0), grid.d_xi(0), grid.d_theta);
  op.w.resize(grid.n_r);
  for (int i = 0; i <= i_outer; ++i) op.w[i] = -(op.ring[i].a[2] + 2.0 * op.ring[i].b[2]);
  if (far_field == FarField::exact) {
    // The exterior is an infinite uniform-ξ grid with the same stencil: mode k decays like μ_k^m.
    const RingStencil ext = op.ring[i_outer];
    op.mu.resize(grid.n_theta / 2 + 1);
    for (int k = 0; k <= grid.n_theta / 2; ++k) {
      const double c = 2.0 * std::cos(k * grid.d_theta);
      op.mu[k] = k == 0 ? 1.0 : decaying_root(ext.a[1] + c * ext.b[1], ext.a[2] + c * ext.b[2]);
    }
  }
  return op;
}

BoundaryData boundary_data(const DiscreteOperator& op, const PolarGrid& grid, double U, double Gamma) {
  const int n = op.n_theta, L = op.last_ring();
  BoundaryData bd;
  bd.outer.assign(n, 0.0);
  if (op.far_field == FarField::freestream) {
    // Ring n_r−1 holds g_j + C: the g part moves to the right-hand side of ring L.
    const RingStencil& s = op.ring[L];
    bd.g.resize(n);
    double g_sum = 0.0;
    for (int j = 0; j < n; ++j) {
      bd.g[j] = U * op.r_outer * std::sin(grid.theta[j]);
      g_sum += bd.g[j];
    }
    for (int j = 0; j < n; ++j)
      bd.outer[j] = -(s.a[2] * bd.g[j] + s.b[2] * (bd.g[(j + 1) % n] + bd.g[(j + n - 1) % n]));
    // Circulation row: w·(Σ_j ψ_{L,j} − n·C − Σ_j g_j) = Γ, written as n·w·C − w·Σψ_L = −Γ − w·Σg.
    bd.c_rhs = -Gamma - op.w[L] * g_sum;
  } else {
    // Ghost ring N+1 (N = i_outer): mode 0 carries the circulation (ψ̄_{N+1} = ψ̄_N − Γ/(n·w)); mode 1 is the
    // growing freestream g = U r sinθ plus a decaying remainder: ψ_{N+1} − g_{N+1} = μ_1 (ψ_N − g_N).
    const double t1 = op.symbol(L, +1, 1);
    const double growth = op.r_ghost - op.mu[1] * op.r_outer;
    for (int j = 0; j < n; ++j) bd.outer[j] = -Gamma / n - t1 * U * std::sin(grid.theta[j]) * growth;
  }
  return bd;
}

std::vector<double> assemble_rhs(const DiscreteOperator& op, const BoundaryData& bd) {
  const int n = op.n_theta, L = op.last_ring();
  std::vector<double> rhs(size_t(op.unknowns()), 0.0);
  std::copy(bd.outer.begin(), bd.outer.end(), rhs.begin() + long(L - 1) * n);
  if (op.far_field == FarField::freestream) rhs[size_t(L) * n] = bd.c_rhs;
  return rhs;
}

std::vector<double> unpack_psi(const DiscreteOperator& op, const BoundaryData& bd,
                               const std::vector<double>& x) {
  const int n = op.n_theta, L = op.last_ring();
  std::vector<double> psi(size_t(op.n_r) * n, 0.0);
  std::copy(x.begin(), x.begin() + long(L) * n, psi.begin() + n);  // ring 0 stays 0
  if (op.far_field == FarField::freestream) {
    const double C = x[size_t(L) * n];
    for (int j = 0; j < n; ++j) psi[size_t(op.n_r - 1) * n + j] = bd.g[j] + C;
  }
  return psi;
}

}  // namespace magnus
