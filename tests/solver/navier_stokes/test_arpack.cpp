// The two eigensolvers of the linear stability: the hand-written Krylov–Schur Arnoldi and ARPACK-ng find
// the same leading eigenvalues (each accepted by the same residual test on J itself), and an unknown name
// is refused, by the library and by `magnus stability --eigensolver`, before anything is solved.
#include <catch2/catch.hpp>
#include <complex>
#include <stdexcept>
#include <string>

#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stability.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// D = 1 m, U = 1 m/s (1/s = U/D), ν = 1/Re, no spin; a coarse grid.
NsParams coarse_wake(double Re, int n_theta) { return test::cylinder_flow(Re, 0.0, n_theta, 40.0); }

}  // namespace

TEST_CASE("[ns][stability][arpack] Re 50, α 0: ARPACK and the hand-written Arnoldi agree on the leading "
          "eigenvalues",
          "[ns][stability][arpack]") {
  // Just past the Hopf onset (Re ≈ 47): the wake's pair has crossed into Re λ > 0, and the far field's slow
  // real modes lie just left of the axis. Two shifts, one at each.
  const NsParams p = coarse_wake(50.0, 48);
  const NewtonResult nr = solve_steady(p, potential_guess(p, ns_grid(p)));
  REQUIRE(nr.converged);
  StabilityOptions o;
  o.shifts = {{0.1, 0.0}, {0.1, 0.7}};
  o.extra_shifts = 0;
  const StabilityResult hand = leading_eigenvalues(p, nr.state, 4, o);
  o.eigensolver = "arpack";
  const StabilityResult arpack = leading_eigenvalues(p, nr.state, 4, o);
  INFO(hand.message << "\n" << arpack.message);
  REQUIRE(hand.eigenvalues.size() == 4);
  REQUIRE(arpack.eigenvalues.size() == 4);
  // The leading pair grows (unstable) at St ≈ 0.11 on this grid in both.
  const auto pair_h = hand.leading_pair(), pair_a = arpack.leading_pair();
  REQUIRE(pair_h);
  REQUIRE(pair_a);
  CHECK(pair_h->real() > 0.0);
  CHECK(!hand.stable);
  CHECK(!arpack.stable);
  // Each eigenpair was accepted with ‖Jx − λMx‖ ≤ tol·(‖Jx‖ + |λ|‖Mx‖): the eigenvalues agree to well
  // within that (an eigenvalue moves by about the residual times its condition number).
  for (size_t k = 0; k < 4; ++k) {
    INFO("eigenvalue " << k << ": " << hand.eigenvalues[k] << " and " << arpack.eigenvalues[k]);
    CHECK(std::abs(hand.eigenvalues[k] - arpack.eigenvalues[k]) <= 1e-4 * (1.0 + std::abs(hand.eigenvalues[k])));
  }
}

TEST_CASE("[ns][stability][arpack] an unknown eigensolver is refused before any solve", "[ns][stability][arpack]") {
  const NsParams p = coarse_wake(50.0, 16);
  StabilityOptions o;
  o.eigensolver = "lapack";
  // The state (empty, the wrong size) is never looked at: the name is checked first.
  NsState s;
  try {
    leading_eigenvalues(p, s, 4, o);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    CHECK(what.find("\"lapack\"") != std::string::npos);
    CHECK(what.find("arnoldi, arpack") != std::string::npos);
  }
}

TEST_CASE("magnus stability --eigensolver: an unknown name is one line naming the option", "[app][arpack]") {
  using namespace magnus::test;
  const std::string dir = temp_dir("stability-eigensolver");
  const std::string c = std::string(MAGNUS_SOURCE_DIR) + "/cases/s_map.toml";
  const Outcome o = magnus_cmd({"stability", c, "--eigensolver", "slepc"}, dir);
  INFO(o.err);
  CHECK(o.status != 0);
  CHECK(one_line(o.err));
  CHECK(o.err.find("--eigensolver slepc: unknown eigensolver (expected arnoldi, arpack)") != std::string::npos);
}
