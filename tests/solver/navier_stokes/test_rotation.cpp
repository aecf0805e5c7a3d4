// The wall's spin taken implicitly (solver/navier_stokes/rotation.hpp): the per-mode operator is
// advection_ring's J(ψ_ref, ·) to round-off, the split step stays second order in time, its CFL step grows at
// high spin, and ω = 0 steps exactly as the explicit scheme.
#include <catch2/catch.hpp>
#include <array>
#include <cmath>
#include <complex>
#include <random>

#include "postproc/navier_stokes/unsteady.hpp"
#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/rotation.hpp"
#include "solver/navier_stokes/stages.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::observed_order;
using cplx = std::complex<double>;

namespace {

/// Re 40 past a cylinder at spin ratio alpha on a small grid (R = 10a).
NsParams spin_flow(double alpha, int n_theta = 32) {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 0.025, p.omega = alpha * p.U / p.a, p.outer_over_a = 10.0;
  p.n_theta = n_theta, p.threads = 1;
  return p;
}

/// The DFT of n values in FFTW's r2c sign: x̂_k = Σ_j x_j e^{−2πijk/n}.
cplx dft(const double* x, int n, int k) {
  cplx s = 0.0;
  for (int j = 0; j < n; ++j) s += x[j] * std::polar(1.0, -2.0 * M_PI * double(k) * j / n);
  return s;
}

/// max over rings and modes of |N̂_i(k) − Σ_d â_{i,d}(k) ζ̂_{i+d}(k)| and of the physical stencil's
/// |N − Aζ|, relative to max |N| (N = advection_ring(ψ_ref, ζ) of a random ζ); and the rows' asymmetry
/// max |h_i â_{i,−1} − h_{i−1} â_{i−1,+1}| relative to max |h_i â| (RotationFactors takes it as 0).
std::array<double, 3> symbol_error(const NsParams& p) {
  const PolarGrid g = ns_grid(p);
  const int nr = g.n_r, n = g.n_theta;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> zeta(size_t(nr) * n), N(static_cast<size_t>(n)), A(static_cast<size_t>(n));
  for (double& z : zeta) z = u(rng);
  const std::vector<double> psi = reference_psi(g, p);
  const RotationStencil s = rotation_stencil(g, p);
  double e_mode = 0.0, e_grid = 0.0, N_max = 0.0, asym = 0.0, a_max = 0.0;
  for (int i = 1; i < nr - 1; ++i) {
    advection_ring(g, p, psi.data(), zeta.data(), i, N.data());
    std::fill(A.begin(), A.end(), 0.0);
    add_rotation_ring(s, zeta.data(), i, 1.0, A.data());
    for (int j = 0; j < n; ++j)
      N_max = std::max(N_max, std::fabs(N[j])), e_grid = std::max(e_grid, std::fabs(N[j] - A[j]));
    for (int k = 0; k <= n / 2; ++k) {
      const cplx lower = g.ring_width(i) * rotation_symbol(s, i, -1, k);
      a_max = std::max(a_max, std::abs(lower));
      if (i >= 2) asym = std::max(asym, std::abs(lower - g.ring_width(i - 1) * rotation_symbol(s, i - 1, 1, k)));
      cplx sum = 0.0;
      for (int d = -1; d <= 1; ++d) sum += rotation_symbol(s, i, d, k) * dft(&zeta[size_t(i + d) * n], n, k);
      e_mode = std::max(e_mode, std::abs(dft(N.data(), n, k) - sum) / n);
    }
  }
  return {e_mode / N_max, e_grid / N_max, asym / a_max};
}

/// From s over `pairs` pairs of steps h, 2h: the final vorticity.
std::vector<double> alternate(const NsParams& p, NsState s, double h, int pairs) {
  const NsOperator a(p, h), b(p, 2.0 * h);
  NsState next;
  for (int k = 0; k < pairs; ++k) {
    advance(a, s, next), std::swap(s, next);
    advance(b, s, next), std::swap(s, next);
  }
  return s.zeta;
}

}  // namespace

TEST_CASE("[ns] implicit rotation: the per-mode operator is advection_ring's J(psi_ref, .) to round-off",
          "[ns][rotation]") {
  struct Case {
    int order;
    double wall_refinement;
  };
  for (const Case c : {Case{2, 1.0}, Case{4, 1.0}, Case{2, 4.0}, Case{4, 4.0}}) {
    NsParams p = spin_flow(3.0);
    p.advection_order = c.order, p.wall_refinement = c.wall_refinement, p.wall_layer = 0.5;
    const auto e = symbol_error(p);
    INFO("advection order " << c.order << " in theta, wall refinement " << c.wall_refinement << ": per mode "
                            << e[0] << ", on the grid " << e[1] << ", rows' asymmetry " << e[2]);
    CHECK(e[0] < 1e-13);
    CHECK(e[1] < 1e-13);
    CHECK(e[2] < 1e-13);
  }
}

TEST_CASE("[ns] implicit rotation: which cases take it", "[ns][rotation]") {
  NsParams p = spin_flow(2.0);
  CHECK(rotation_implicit(p));
  CHECK(reference_psi_xi(p) == Approx(-p.a * p.a * p.omega));
  for (int q = 0; q < 4; ++q) {
    NsParams r = p;
    if (q == 0) r.implicit_rotation = false;
    if (q == 1) r.omega = 0.0;
    if (q == 2) r.stokes = true;
    if (q == 3) r.advection_order_xi = 4;  // pentadiagonal: stays explicit
    CHECK_FALSE(rotation_implicit(r));
    CHECK(reference_psi_xi(r) == 0.0);
  }
}

TEST_CASE("[ns] implicit rotation: AB2/CN with the split is second order in time at alpha 2", "[ns][rotation]") {
  const NsParams p = spin_flow(2.0);
  REQUIRE(rotation_implicit(p));
  const PolarGrid g = ns_grid(p);
  NsState s = impulsive_start(p, g);
  {
    const NsOperator op(p, 0.005);
    NsState next;
    for (int k = 0; k < 100; ++k) advance(op, s, next), std::swap(s, next);
  }
  s.N_prev.clear(), s.dt_prev = 0.0;
  const auto z1 = alternate(p, s, 0.01, 20), z2 = alternate(p, s, 0.005, 40), z3 = alternate(p, s, 0.0025, 80);
  const double d12 = test::max_abs_diff(z1, z2), d23 = test::max_abs_diff(z2, z3);
  INFO("successive differences " << d12 << " " << d23);
  REQUIRE(d23 > 0.0);
  CHECK(observed_order(d12, d23) == Approx(2.0).margin(0.1));
}

TEST_CASE("[ns] implicit rotation: at alpha 5 the CFL step is over twice the explicit scheme's",
          "[ns][rotation]") {
  // Re 100, α = 5 on 32 × R = 10a, time.cfl 0.7, 20 D/U from rest: both runs stable, the implicit one in
  // fewer than half the steps (its Δt follows ψ − ψ_ref: the wall's |ω|/Δθ is gone).
  long steps[2] = {0, 0};
  double lift[2] = {0.0, 0.0};
  for (int q = 0; q < 2; ++q) {
    NsParams p = spin_flow(5.0);
    p.nu = 0.01, p.implicit_rotation = q == 1;
    UnsteadyOptions o;
    o.t_end = 20.0;
    o.t_min = 1e9;
    const UnsteadyResult r = run_unsteady(p, o, impulsive_start(p, ns_grid(p)));
    INFO("implicit rotation " << q << ": " << r.message);
    REQUIRE(r.ok);
    CHECK(r.state.t == Approx(o.t_end));
    steps[q] = r.steps, lift[q] = r.history.back().C_L;
  }
  INFO("steps explicit " << steps[0] << ", implicit " << steps[1] << "; C_L " << lift[0] << " " << lift[1]);
  CHECK(2 * steps[1] <= steps[0]);
  CHECK(lift[1] == Approx(lift[0]).epsilon(0.02));  // the same flow: Δt's error only
}

TEST_CASE("[ns] implicit rotation: without spin both settings step bit for bit alike", "[ns][rotation]") {
  NsParams p = spin_flow(0.0);
  const PolarGrid g = ns_grid(p);
  NsState start = impulsive_start(p, g), out[2];
  for (int q = 0; q < 2; ++q) {
    p.implicit_rotation = q == 1;
    const NsOperator op(p, 0.01);
    NsState s = start, next;
    for (int k = 0; k < 20; ++k) advance(op, s, next), std::swap(s, next);
    out[q] = s;
  }
  CHECK(out[0].zeta == out[1].zeta);
  CHECK(out[0].psi == out[1].psi);
  CHECK(out[0].N_prev == out[1].N_prev);
}
