// Floquet stability of shedding orbits to spanwise disturbances (solver/navier_stokes/floquet.hpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "solver/navier_stokes/floquet.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// The orbit of p (from rest, the symmetry broken as a run breaks it) and its states over one period.
std::vector<NsState> shedding_orbit_samples(const NsParams& p, double& T) {
  OrbitRunOptions o;
  o.t_end = 400.0;
  o.orbit.tol = 1e-8;
  const PolarGrid g = ns_grid(p);
  NsState start = impulsive_start(p, g);
  break_symmetry(p, g, start);
  const OrbitRun run = periodic_orbit_run(p, o, std::move(start));
  REQUIRE(run.orbit.converged);
  T = run.orbit.T;
  return orbit_samples(p, run.orbit);
}

}  // namespace

TEST_CASE("[ns][floquet] Re 100: the orbit's phase mode has multiplier 1 and mode A decays", "[ns][floquet]") {
  // Re 100 without spin on n_θ 48, R = 30a: the shedding orbit and its multipliers at β = 0 and at mode A's
  // wavelength λ_z = 3.96 D (β·D = 1.59), which sets in only near Re 189 (Barkley & Henderson 1996).
  const NsParams p = test::cylinder_flow(100.0, 0.0, 48, 30.0);
  double T = 0.0;
  const std::vector<NsState> samples = shedding_orbit_samples(p, T);
  FloquetOptions o;
  o.krylov = 30;
  const FloquetResult two = floquet_multipliers(p, samples, T, 0.0, o);
  INFO("β = 0: μ " << two.multipliers[0] << " residual " << two.residuals[0] << ", " << two.seconds << " s");
  // The time derivative of the orbit is neutral: μ = 1 (here 1.011: the linear operator freezes which outer
  // columns let the wake out at the mean flow's, the orbit switches them).
  CHECK(two.multipliers[0].imag() == 0.0);
  CHECK(std::abs(two.multipliers[0] - 1.0) < 0.02);
  CHECK(two.residuals[0] < 1e-3);
  for (size_t k = 1; k < two.multipliers.size(); ++k) CHECK(std::abs(two.multipliers[k]) < 0.99);
  const FloquetResult a = floquet_multipliers(p, samples, T, 2.0 * M_PI / 3.96 / (2.0 * p.a), o);
  INFO("mode A's wavelength: μ " << a.multipliers[0] << " residual " << a.residuals[0] << ", " << a.seconds << " s");
  CHECK(std::abs(a.multipliers[0]) < 1.0);  // 0.947
  CHECK(a.residuals[0] < 2e-3);              // 7.8e-4: 30 Arnoldi vectors, no restart
  CHECK(a.harmonics == 8);
  CHECK(a.truncation < 1e-2);  // the 8th harmonic of the base is below 1% of the first
}
