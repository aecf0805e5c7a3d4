// Three-dimensional stability against what is known of the cylinder wake: the steady wake at Re 40 is
// stable to every spanwise disturbance (the first instability of the cylinder wake is the 2D onset of
// shedding near Re 47); the Re 100 shedding orbit is stable at mode A's wavelength, and mode A sets in at
// Re 188.5 with λ_z = 3.96 D (Barkley & Henderson 1996), its multiplier converging in the time slices of the
// period and the base's harmonics; the BiGlobal shift agrees with an independent solver.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "postproc/navier_stokes/spanwise_scan.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "solver/navier_stokes/floquet.hpp"
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
  // |μ| = 0.44 (0.385 − 0.215i) on this grid. Far below onset the leading multipliers crowd together (the
  // slow far-field modes) and Arnoldi is stopped once the Ritz estimate is a tenth of |1 − |μ||: the
  // verdict needs only the sign, so |μ| is rough here (0.42 with 30 vectors); near onset mode A stands
  // alone and converges to 1e-3.
  CHECK(std::abs(pt.multiplier) < 0.8);
  CHECK(s.T == Approx(1.0 / 0.1644).epsilon(0.05));  // St within 5% of the consensus 0.1644 on this grid
}

TEST_CASE("[validation][spanwise] BiGlobal: the spanwise shift agrees with an independent solver",
          "[validation][spanwise]") {
  // The Re 60 steady wake (unstable in 2D, so no published 3D value to meet) at R = 40a: how far the spanwise
  // wavenumber β·D = 0.5 moves the wake's pair, λ(0.5) − λ(0), on n_θ 96, 128 and 192 (n_r follows). An
  // independent primitive-variable solver on its own grids (scripts/independent_biglobal: SciPy, velocities
  // interpolated from magnus's base) gives −0.0464 and −0.0463 U/D on the n_θ 96 and 128 bases (its
  // limits in its own grid). Measured here: shifts −0.04655, −0.04638, −0.04627 (−0.04725 on n_θ 64); the
  // growth at β·D 0.5 −0.00406, −0.00265, −0.00177, observed order 2.38 (2.65 over 64, 96, 128: not yet
  // asymptotic), limit −0.0012 (the independent solver: about −0.002).
  std::vector<double> shift, growth;
  const std::vector<int> n = {96, 128, 192};
  for (int n_theta : n) {
    const NsParams p = test::cylinder_flow(60.0, 0.0, n_theta, 40.0);
    const NewtonResult steady = solve_steady(p, potential_guess(p, ns_grid(p)));
    REQUIRE(steady.converged);
    double at[2];
    for (int k = 0; k < 2; ++k) {
      const StabilityResult r = spanwise_eigenvalues(p, steady.state, k * 0.5 / (2.0 * p.a), 6, StabilityOptions{});
      double best = -1e300;
      for (const auto& l : r.eigenvalues)
        if (std::fabs(l.imag()) > 0.3) best = std::max(best, l.real());  // the wake pair (St ≈ 0.11)
      REQUIRE(best > -1e300);
      at[k] = best;
    }
    INFO("n_θ " << n_theta << ": growth " << at[0] << " at β = 0, " << at[1] << " at β·D = 0.5");
    shift.push_back(at[1] - at[0]), growth.push_back(at[1]);
  }
  const Richardson r = richardson(growth, {1.0 / n[0], 1.0 / n[1], 1.0 / n[2]});
  INFO("shifts " << shift[0] << ", " << shift[1] << ", " << shift[2] << "; growth at β·D 0.5 " << growth[0] << ", "
                 << growth[1] << ", " << growth[2] << ": observed order " << r.order << ", limit " << r.value);
  CHECK(shift[0] == Approx(-0.0464).epsilon(0.01));
  CHECK(shift[1] == Approx(-0.0463).epsilon(0.01));
  CHECK(shift[2] == Approx(-0.0463).epsilon(0.01));
  REQUIRE(r.observed);
  CHECK(std::fabs(r.order - 2.0) < 0.5);
}

TEST_CASE("[validation][spanwise] mode A: the 3D onset without spin at Re 188.5, wavelength 3.96 D (n_theta 64)",
          "[validation][spanwise]") {
  // The Floquet onset search of `magnus stability --spanwise --critical-reynolds` on n_θ 64, R = 30a, three
  // wavenumbers around mode A's. Barkley & Henderson (1996): Re_A = 188.5 ± 1.0, λ_z = 3.96 ± 0.02 D; the
  // tolerance asked for, ±1.5 in Re and ±0.1 D. Measured: 187.53 ± 0.42, 3.97 D in 3 scans (about 6 min on
  // two cores). This grid is not converged for mode A: at Re 190 its multiplier is 1.027 here, 0.9585 on
  // n_θ 96 and 0.9582 on n_θ 128, so the converged onset on R = 30a is near Re 195 (README: "Where it falls
  // short"); the agreement here is the coarse grid's.
  const NsParams p = test::cylinder_flow(180.0, 0.0, 64, 30.0);
  const SpanwiseCritical c = spanwise_critical(p, {1.4, 1.6, 1.8}, 175.0, 200.0, 1.0, "arnoldi");
  INFO("Re_c " << c.Re_c << " ± " << c.change << " [" << c.lo << ", " << c.hi << "], β·D " << c.beta_D
               << ", λ_z " << c.wavelength_D() << " D, " << c.evaluations.size() << " scans, " << c.seconds << " s; "
               << c.message);
  REQUIRE(c.found);
  CHECK(c.Re_c == Approx(188.5).margin(1.5));
  CHECK(c.wavelength_D() == Approx(3.96).margin(0.1));
}

TEST_CASE("[validation][spanwise] fast spin: the first instability is a stationary 3D mode, below the "
          "non-rotating onset (n_theta 64)",
          "[validation][spanwise]") {
  // Pralits, Giannetti & Brandt (2013): at high rotation rates the first bifurcation of the rotating cylinder's
  // steady flow is a stationary three-dimensional mode, and its critical Reynolds number is lower than that
  // of the stationary cylinder (the 2D onset of shedding). Rao et al. (2013): a steady-base 3D mode that
  // becomes harder to excite as the rotation rate grows. Their thresholds could not be read here, so this
  // checks what they state, on one grid (n_θ 64, R = 30a) for every comparison:
  // - at α = 5.25 the 3D onset search finds a crossing, of steady, 2D-stable bases, by a real eigenvalue;
  // - it lies below the onset of 2D shedding without spin on the same grid (Re 43.13; 46.7 converged);
  // - at α = 6 the flow is stable to the same wavenumbers at Re 40 and 60.
  // Measured: Re_c 40.13 ± 0.14, λ_z 4.48 D (β·D 1.40), against 43.13; α = 6: largest growth rates −0.067
  // (a Floquet scan: on this grid the 2D steady state at Re 40 sheds) and −0.078 U/D. About 6 min.
  const NsParams p = test::cylinder_flow(40.0, 5.25, 64, 30.0);
  const SpanwiseCritical c = spanwise_critical(p, {1.0, 1.5, 2.0}, 30.0, 50.0, 0.5, "arnoldi");
  INFO("Re_c " << c.Re_c << " ± " << c.change << " [" << c.lo << ", " << c.hi << "], β·D " << c.beta_D
               << ", λ_z " << c.wavelength_D() << " D, " << c.evaluations.size() << " scans; " << c.message);
  REQUIRE(c.found);
  for (const SpanwiseEvaluation& e : c.evaluations) {
    INFO("Re " << e.Re << ": " << e.scan.verdict);
    CHECK(!e.scan.periodic);  // the 2D steady state is stable: the flow turns 3D before it sheds
    if (e.Re == c.lo || e.Re == c.hi) CHECK(e.scan.stationary);
  }
  const HopfPoint shedding = hopf_point(with_parameter(p, HopfParameter::spin_ratio, 0.0), HopfParameter::reynolds,
                                        40.0, 55.0);
  INFO("2D onset of shedding without spin on this grid: Re " << shedding.x_c);
  CHECK(c.Re_c < shedding.x_c - 1.0);
  CHECK(c.wavelength_D() > 3.0);
  CHECK(c.wavelength_D() < 6.0);

  for (double Re : {40.0, 60.0}) {
    const NsParams q = test::cylinder_flow(Re, 6.0, 64, 30.0);
    const SpanwiseScan s = spanwise_stability(q, steady_stability(q, "arnoldi"), {1.0, 1.5, 2.0}, "arnoldi");
    INFO("α 6, Re " << Re << ": " << s.verdict);
    CHECK(s.stable);  // whichever base the 2D answer gives (at Re 40 on this grid its steady state sheds)
  }
}

TEST_CASE("[validation][spanwise] mode A's multiplier converges at order 2 in the time slices of the period "
          "and spectrally in the base's harmonics (Re 190, n_theta 64)",
          "[validation][spanwise]") {
  // The Floquet problem near mode A's onset, where its multiplier stands alone: the Re 190 orbit on n_θ 64,
  // R = 30a, at β·D = 1.6. The linear stepper takes N steps a period (second order: the periodic part of the
  // operator by Adams–Bashforth 2) over the base's Fourier series of K harmonics (exact for the orbit as
  // K grows, the harmonics falling geometrically). Each run starts Arnoldi from the last one's mode.
  const NsParams p = test::cylinder_flow(190.0, 0.0, 64, 30.0);
  const OrbitRun run = test::shedding_orbit_run(p, 400.0, 1e-9);
  REQUIRE(run.orbit.converged);
  const double beta = 1.6;  // 1/m: D = 1 m
  std::vector<double> mode;
  auto run_floquet = [&](int N, int K) {
    FloquetOptions o;
    o.steps = N, o.krylov = 30, o.tolerance = 1e-7, o.start = mode;
    const FloquetResult r = floquet_multipliers(p, orbit_series(p, run.orbit, K), beta, o);
    REQUIRE(!r.multipliers.empty());
    mode = r.mode;
    std::printf("  N %4d, K %d: mu %.7f%+.7fi (|mu| %.7f, residual %.1e, %d periods, %.0f s)\n", N, K,
                r.multipliers[0].real(), r.multipliers[0].imag(), std::abs(r.multipliers[0]), r.residuals[0],
                r.periods, r.seconds);
    std::fflush(stdout);
    return r;
  };
  // From a random start Arnoldi stops at its 31 vectors with the Ritz estimate near 3e-4 (μ 1.03534 on 200
  // steps, 1.02772 on 400, 1.6e-4 and 1.8e-4 from their converged values: 400 run first, the order came out
  // 2.22). So a first run finds the mode, and the three that give the order start from it. Measured:
  // 1.0355008, 1.0279023, 1.0260507 (estimates 8e-8 to 3e-7), order 2.04.
  run_floquet(200, 8);
  const FloquetResult r1 = run_floquet(200, 8), r2 = run_floquet(400, 8), r4 = run_floquet(800, 8);
  const std::complex<double> n1 = r1.multipliers[0], n2 = r2.multipliers[0], n4 = r4.multipliers[0];
  const double order_N = test::observed_order(std::abs(n1 - n2), std::abs(n2 - n4));
  std::printf("  time slices: |mu_200 - mu_400| %.2e, |mu_400 - mu_800| %.2e, observed order %.2f\n",
              std::abs(n1 - n2), std::abs(n2 - n4), order_N);
  // The three converged: the order is the stepper's, not Arnoldi's.
  CHECK(std::max({r1.residuals[0], r2.residuals[0], r4.residuals[0]}) < 1e-5);
  CHECK(std::fabs(order_N - 2.0) < 0.1);
  const std::complex<double> k2 = run_floquet(400, 2).multipliers[0], k4 = run_floquet(400, 4).multipliers[0],
                             k6 = run_floquet(400, 6).multipliers[0];
  std::printf("  harmonics: |mu_K - mu_8| at K 2, 4, 6: %.2e, %.2e, %.2e\n", std::abs(k2 - n2), std::abs(k4 - n2),
              std::abs(k6 - n2));
  // Geometric: each two harmonics more take at least a factor 4 off the difference to K = 8.
  CHECK(std::abs(k4 - n2) < 0.25 * std::abs(k2 - n2));
  CHECK(std::abs(k6 - n2) < 0.25 * std::abs(k4 - n2));
}
