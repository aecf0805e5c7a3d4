// The time stepper's eigenvalues by Arnoldi on the linearised march (stepper_eigen.hpp) against the
// Jacobian's by shift-invert (stability.hpp): the same operator, so they differ by the scheme's time error
// alone, which falls at second order with Δt; and the generic map Arnoldi on a known matrix.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <vector>

#include "solver/navier_stokes/map_arnoldi.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stability.hpp"
#include "solver/navier_stokes/stepper_eigen.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("[ns][stepper_eigen] map Arnoldi: the outermost eigenvalues of a known matrix", "[ns][stepper_eigen]") {
  // Block diagonal: a rotation-scaling block with eigenvalues 1.1·e^{±0.7i}, then 0.9, 0.5, 0.4, … on the diagonal.
  const size_t n = 40;
  auto P = [&](const std::vector<double>& v) {
    std::vector<double> w(n);
    const double c = 1.1 * std::cos(0.7), s = 1.1 * std::sin(0.7);
    w[0] = c * v[0] - s * v[1], w[1] = s * v[0] + c * v[1];
    w[2] = 0.9 * v[2];
    for (size_t i = 3; i < n; ++i) w[i] = 0.5 * std::pow(0.97, double(i)) * v[i];
    return w;
  };
  MapArnoldiOptions o;
  o.krylov = 12;
  const MapArnoldiResult r = map_arnoldi(P, n, o);
  REQUIRE(r.ritz.size() >= 3);
  CHECK(r.products == 13);
  CHECK(std::abs(std::abs(r.ritz[0].mu) - 1.1) < 1e-10);
  CHECK(std::fabs(std::fabs(std::arg(r.ritz[0].mu)) - 0.7) < 1e-10);
  CHECK(std::abs(r.ritz[2].mu - 0.9) < 1e-10);
  CHECK(r.ritz[0].residual < 1e-8);
  // Stopping on a condition: the first time `done` is asked, with min_vectors vectors.
  o.min_vectors = 4;
  int asked = 0;
  const MapArnoldiResult s = map_arnoldi(P, n, o, [&](const std::vector<MapRitz>&) { return ++asked >= 1; });
  CHECK(s.products == 5);
  CHECK_THROWS_AS(map_arnoldi(P, 0, o), std::invalid_argument);
}

TEST_CASE("[ns][stepper_eigen] Re 80: the stepper's leading pair converges to the Jacobian's with Arnoldi",
          "[ns][stepper_eigen]") {
  const NsParams p = test::cylinder_flow(80.0, 0.0, 64, 40.0);  // D = 1 m, U = 1 m/s: 1/s = U/D
  const NewtonResult steady = solve_steady(p, potential_guess(p, ns_grid(p)));
  REQUIRE(steady.converged);
  StabilityOptions so;
  so.shifts = {{0.1, 0.7}};
  const StabilityResult jac = leading_eigenvalues(p, steady.state, 2, so);
  REQUIRE(jac.leading_pair());
  const std::complex<double> lambda = *jac.leading_pair();  // +0.07387 + 0.68189i
  // The seed's tolerance (1e-2) puts it within a few hundredths; a tight one within the time error (Δt² ≈ 1e-4
  // here, ~1e-5 relative) and Arnoldi's.
  int products_loose = 0;
  for (double tol : {1e-2, 1e-4}) {
    StepperEigenOptions o;
    o.tol = tol, o.krylov = 60;
    const StepperEigenResult r = stepper_eigenvalues(p, steady.state, o);
    REQUIRE(r.leading_pair());
    const double err = std::abs(*r.leading_pair() - lambda);
    INFO("tol " << tol << ": stepper " << *r.leading_pair() << " (estimate " << r.residuals.front() << ") against "
                << lambda << ", " << r.products << " products of " << r.steps / r.products << " steps");
    CHECK(r.leading_pair()->real() > 0.0);
    CHECK(err < 2.0 * tol);
    if (tol == 1e-2) products_loose = r.products;
    else CHECK(r.products > products_loose);  // it stopped once the tolerance was met
  }
  StepperEigenOptions bad;
  bad.span = 0.0;
  CHECK_THROWS_AS(stepper_eigenvalues(p, steady.state, bad), std::invalid_argument);
}
