// Three-dimensional stability against what is known of the cylinder wake, on n_θ 96: the steady wake at
// Re 40 is stable to every
// spanwise disturbance (the first instability of the cylinder wake is the 2D onset of shedding near Re 47),
// and the Re 100 shedding orbit is stable at mode A's wavelength (mode A sets in at Re 188.5, λ_z = 3.96 D;
// Barkley & Henderson 1996).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "postproc/navier_stokes/spanwise_scan.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "solver/navier_stokes/spanwise.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("[validation][spanwise] Re 40: the steady wake is stable to 3D disturbances (n_theta 96)",
          "[validation][spanwise]") {
  const NsParams p = test::cylinder_flow(40.0, 0.0, 96, 40.0);
  const NewtonResult steady = solve_steady(p, potential_guess(p, ns_grid(p)));
  REQUIRE(steady.converged);
  const SpanwiseScan s = spanwise_scan(p, steady.state, {0.5, 1.0, 2.0, 4.0}, quick_stability_options());
  INFO(s.verdict);
  for (const SpanwisePoint& pt : s.points) {
    INFO("β·D " << pt.beta_D << ": λ " << pt.lambda);
    REQUIRE(pt.found);
    CHECK(pt.growth() < 0.0);
  }
  CHECK(s.stable);
}

TEST_CASE("[validation][spanwise] Re 100: the shedding orbit is stable at mode A's wavelength (n_theta 96)",
          "[validation][spanwise]") {
  const NsParams p = test::cylinder_flow(100.0, 0.0, 96, 30.0);
  const SpanwiseScan s = floquet_scan(p, {2.0 * M_PI / 3.96}, 300.0);
  REQUIRE(s.points.size() == 1);
  const SpanwisePoint& pt = s.points.front();
  INFO(s.verdict << "; μ " << pt.multiplier);
  REQUIRE(pt.found);
  CHECK(pt.covered);  // the Ritz estimate of the leading multiplier below 1e-3
  CHECK(std::abs(pt.multiplier) < 1.0);
  CHECK(s.T == Approx(1.0 / 0.1644).epsilon(0.05));  // St within 5% of the consensus 0.1644 on this grid
}

TEST_CASE("[validation][spanwise] the BiGlobal growth rate converges at second order in the grid",
          "[validation][spanwise]") {
  // The Re 60 steady wake (unstable in 2D, so no published 3D value to meet) at β·D = 0.5, R = 40a: the wake
  // pair, moved by the spanwise wavenumber, on n_θ 64, 96 and 128 (n_r follows). Measured: −0.00512,
  // +0.00352, +0.00664 U/D; the observed order 1.91 (48, 64, 96: 1.32, not yet asymptotic); the limit
  // +0.0109 U/D. The order is not correctness: an independent primitive-variable solver
  // (scripts/independent_biglobal) gives about −0.002 on the n_θ 128 base, so this checks convergence only.
  std::vector<double> growth;
  const std::vector<int> n = {64, 96, 128};
  for (int n_theta : n) {
    const NsParams p = test::cylinder_flow(60.0, 0.0, n_theta, 40.0);
    const NewtonResult steady = solve_steady(p, potential_guess(p, ns_grid(p)));
    REQUIRE(steady.converged);
    const StabilityResult r = spanwise_eigenvalues(p, steady.state, 0.5 / (2.0 * p.a), 6, StabilityOptions{});
    double best = -1e300;
    for (const auto& l : r.eigenvalues)
      if (std::fabs(l.imag()) > 0.3) best = std::max(best, l.real());  // the wake pair (St ≈ 0.11)
    REQUIRE(best > -1e300);
    INFO("n_θ " << n_theta << ": " << best);
    growth.push_back(best);
  }
  // σ_n = σ_∞ − C h^p through the three, h = 1/n_θ: the steady grid study's Richardson reading.
  const Richardson r = richardson(growth, {1.0 / n[0], 1.0 / n[1], 1.0 / n[2]});
  INFO("growth rates " << growth[0] << ", " << growth[1] << ", " << growth[2] << ": observed order " << r.order
                       << ", limit " << r.value);
  REQUIRE(r.observed);
  const double order = r.order;
  CHECK(growth[0] < growth[1]);
  CHECK(growth[1] < growth[2]);
  CHECK(std::fabs(order - 2.0) < 0.1);
}
