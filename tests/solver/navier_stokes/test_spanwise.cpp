// Spanwise (e^{iβz}) stability of steady states (spanwise.hpp): at β = 0 the 2D problem comes back, the
// eigenvalues are even and smooth in β (λ(β) − λ(0) ∝ β² near 0), and the wake's pair converges with the grid.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <vector>

#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/spanwise.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

NsState newton(const NsParams& p) {
  const NewtonResult r = solve_steady(p, potential_guess(p, ns_grid(p)));
  REQUIRE(r.converged);
  return r.state;
}

/// One shift next to the Re 60 wake's pair (λ·D/U ≈ 0.03 + 0.67i on these grids), no extra shifts.
StabilityOptions near_the_pair() {
  StabilityOptions o;
  o.shifts = {{0.05, 0.67}};
  o.extra_shifts = 0;
  return o;
}

std::complex<double> pair(const StabilityResult& r) {
  const auto l = r.leading_pair();
  REQUIRE(l);
  return *l;
}

}  // namespace

TEST_CASE("[ns][spanwise] at beta 0 the 2D eigenvalues come back", "[ns][spanwise]") {
  const NsParams p = test::cylinder_flow(60.0, 0.0, 32, 40.0);
  const NsState s = newton(p);
  const StabilityResult two = leading_eigenvalues(p, s, 4, near_the_pair());
  const StabilityResult three = spanwise_eigenvalues(p, s, 0.0, 4, near_the_pair());
  INFO(two.message << " | " << three.message);
  const std::complex<double> l2 = pair(two), l3 = pair(three);
  CHECK(l2.real() > 0.0);  // the unstable wake of Re 60
  CHECK(std::abs(l3 - l2) < 1e-7 * std::abs(l2));
  // The mode's in-plane part is the 2D mode (both normalised to max |ζ| = 1).
  REQUIRE(three.mode_zeta.size() == two.mode_zeta.size());
  double d = 0.0;
  for (size_t q = 0; q < two.mode_zeta.size(); ++q) d = std::max(d, std::abs(three.mode_zeta[q] - two.mode_zeta[q]));
  CHECK(d < 1e-5);
}

TEST_CASE("[ns][spanwise] the wake's pair is even in beta: lambda - lambda_0 grows as beta^2",
          "[ns][spanwise]") {
  const NsParams p = test::cylinder_flow(60.0, 0.0, 32, 40.0);
  const NsState s = newton(p);
  const double D = 2.0 * p.a;
  const std::complex<double> l0 = pair(spanwise_eigenvalues(p, s, 0.0, 4, near_the_pair()));
  const std::complex<double> l1 = pair(spanwise_eigenvalues(p, s, 0.1 / D, 4, near_the_pair()));
  const std::complex<double> l2 = pair(spanwise_eigenvalues(p, s, 0.2 / D, 4, near_the_pair()));
  INFO("λ(0) " << l0 << ", λ(0.1/D) " << l1 << ", λ(0.2/D) " << l2);
  // Three-dimensional disturbances of long wavelength damp the pair: Re λ falls with β.
  CHECK(l1.real() < l0.real());
  CHECK(l2.real() < l1.real());
  // Even and smooth in β: doubling β quadruples the change (a term linear in β would halve the ratio).
  const double ratio = std::abs(l2 - l0) / std::abs(l1 - l0);
  CHECK(ratio == Approx(4.0).margin(0.1));
}
