// Floquet stability of shedding orbits to spanwise disturbances (solver/navier_stokes/floquet.hpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "solver/navier_stokes/floquet.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// The orbit of p (from rest, the symmetry broken as a run breaks it) and its Fourier series.
PeriodicBase shedding_orbit(const NsParams& p) {
  OrbitRunOptions o;
  o.t_end = 400.0;
  o.orbit.tol = 1e-8;
  const PolarGrid g = ns_grid(p);
  NsState start = impulsive_start(p, g);
  break_symmetry(p, g, start);
  const OrbitRun run = periodic_orbit_run(p, o, std::move(start));
  REQUIRE(run.orbit.converged);
  return orbit_series(p, run.orbit);
}

}  // namespace

TEST_CASE("[ns][floquet] Re 100: the orbit's phase mode has multiplier 1 and mode A decays", "[ns][floquet]") {
  // Re 100 without spin on n_θ 48, R = 30a: the shedding orbit and its multipliers at β = 0 and at mode A's
  // wavelength λ_z = 3.96 D (β·D = 1.59), which sets in only near Re 189 (Barkley & Henderson 1996).
  const NsParams p = test::cylinder_flow(100.0, 0.0, 48, 30.0);
  const PeriodicBase base = shedding_orbit(p);
  // The phase mode's multiplier over 96, 192 and 384 steps a period: the stepper's second order.
  FloquetOptions o;
  o.krylov = 30;  // 12 leave the phase mode's Ritz estimate at 1.5e-2
  std::vector<FloquetResult> two;
  for (int steps : {96, 192, 384}) {
    o.steps = steps;
    two.push_back(floquet_multipliers(p, base, 0.0, o));
    const FloquetResult& r = two.back();
    INFO(steps << " steps, β = 0: μ " << r.multipliers[0] << " residual " << r.residuals[0] << ", " << r.seconds << " s");
    // The time derivative of the orbit is neutral: μ = 1 (here 1.011: the linear operator freezes which
    // outer columns let the wake out at the mean flow's, the orbit switches them).
    CHECK(r.multipliers[0].imag() == 0.0);
    CHECK(std::abs(r.multipliers[0] - 1.0) < 0.02);
    CHECK(r.residuals[0] < 1e-3);
    for (size_t k = 1; k < r.multipliers.size(); ++k) CHECK(std::abs(r.multipliers[k]) < 0.99);
  }
  const double order = test::observed_order(std::abs(two[0].multipliers[0] - two[1].multipliers[0]),
                                            std::abs(two[1].multipliers[0] - two[2].multipliers[0]));
  INFO("observed order in the time step " << order);
  CHECK(std::fabs(order - 2.0) < 0.1);
  o.steps = FloquetOptions{}.steps;
  const FloquetResult a = floquet_multipliers(p, base, 2.0 * M_PI / 3.96 / (2.0 * p.a), o);
  INFO("mode A's wavelength: μ " << a.multipliers[0] << " residual " << a.residuals[0] << ", " << a.seconds << " s");
  CHECK(std::abs(a.multipliers[0]) < 1.0);  // 0.947
  CHECK(a.residuals[0] < 2e-3);              // 7.8e-4: 30 Arnoldi vectors, no restart
  CHECK(a.harmonics == 8);
  CHECK(a.truncation < 1e-2);  // the 8th harmonic of the base is below 1% of the first
}
