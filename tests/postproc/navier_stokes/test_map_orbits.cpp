// The S(Re, α) map's shedding points as periodic orbits (NsMapOptions::orbits): the first started on the
// growing pair's mode, the next continued along α, each the same orbit as shooting from rest finds on its
// own, with its error bars; the start on the Hopf mode against its definition.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "postproc/navier_stokes/continuation.hpp"
#include "postproc/navier_stokes/continuation_row.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// The map's coarse case (cases/s_map.toml's grid): D = 1 m, U = 1 m/s, n_θ = 48, R = 20a, Re 100.
Case map_case() {
  return parse_case(
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 0.0\n[flow]\nspeed = 1.0\n"
      "density = 1.0\nreynolds = 100.0\n[domain]\nouter_radius = 20.0\n[grid]\nn_theta = 48\n[time]\nend = "
      "300.0\n",
      "test");
}

double rel(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

}  // namespace

TEST_CASE("[ns][map] shedding points as orbits: started on the Hopf mode, continued in alpha, as from rest",
          "[ns][map][periodic_orbit]") {
  const Case c = map_case();
  NsMapOptions o;
  o.alphas = {0.0, 0.25, 0.5};
  o.stability = make_stability_hook(StabilityMethod::eigenvalues);
  o.stability_method = "eigenvalues";
  o.orbits = true;
  const NsMap map = ns_map(c, o);
  REQUIRE(map.orbits);
  REQUIRE(map.points.size() == 3);
  std::optional<OrbitResult> previous;  // the own orbit of the previous α
  for (const NsMapPoint& m : map.points) {
    INFO("alpha " << m.alpha << ", started from " << m.orbit_start);
    // Re 100 sheds at these spin ratios: the steady state is unstable, the point is its orbit.
    REQUIRE(m.converged);
    CHECK(m.stable == std::optional<bool>(false));
    REQUIRE(m.source == MapSource::orbit);
    CHECK(m.orbit_start == (m.alpha == 0.0 ? "hopf mode" : "continued"));
    // Its bars, from the same orbit on the grid twice as coarse.
    CHECK(std::isfinite(m.cd_rel_estimate));
    CHECK(std::isfinite(m.strouhal_rel_estimate));
    CHECK((m.alpha == 0.0 || std::isfinite(m.cl_rel_estimate)));
    // The orbit by shooting from rest on its own: a short march, then Newton to 1e-9, N = T/Δt of the march.
    const NsParams p = ns_params(map_point_case(c, m.reynolds, m.alpha));
    const PolarGrid g = ns_grid(p);
    NsState start = impulsive_start(p, g);
    break_symmetry(p, g, start);
    OrbitRunOptions ro;
    ro.t_end = 300.0;
    ro.orbit.tol = 1e-9;
    const OrbitRun own = periodic_orbit_run(p, ro, std::move(start));
    REQUIRE(own.orbit.converged);
    // The map's orbit is that one at its own Δt (the target CFL number; the march's Δt is free within ±20%
    // of it): the time step's error of the scheme, 0.1-0.2% here, is all that parts them.
    CHECK(rel(m.cd, own.result.C_D_mean) < 3e-3);
    CHECK(rel(m.strouhal, own.result.St) < 3e-3);
    if (m.alpha > 0.0)
      CHECK(rel(m.cl, own.result.C_L_mean) < 3e-3);
    else
      CHECK(std::fabs(m.cl) < 1e-6);
    if (previous) {
      // The orbit is unique: continued from the previous α's own orbit at the own N, Newton lands on it to
      // 1e-6 in the means (Newton to 1e-9), with no march.
      OrbitOptions oo = ro.orbit;
      oo.steps = own.orbit.steps;
      const OrbitResult next = continue_orbit(p, *previous, oo);
      REQUIRE(next.converged);
      const UnsteadyResult s = orbit_summary(p, next, 1.0);
      CHECK(rel(s.C_D_mean, own.result.C_D_mean) < 1e-6);
      CHECK(rel(s.C_L_mean, own.result.C_L_mean) < 1e-6);
      CHECK(rel(s.St, own.result.St) < 1e-5);  // T follows from ρ on ζ a little less closely
    }
    previous = own.orbit;
  }
  // Without --orbits the same points are marched from rest; the marches stop when their means agree to
  // 1e-3, so they lie within about that of the orbits.
  o.orbits = false;
  const NsMap marched = ns_map(c, o);
  for (size_t k = 0; k < 3; ++k) {
    INFO("alpha " << marched.points[k].alpha);
    CHECK(marched.points[k].source == MapSource::averaged_unstable);
    CHECK(rel(marched.points[k].cd, map.points[k].cd) < 5e-3);
  }
}

TEST_CASE("[ns][orbit] the start on the Hopf mode: the steady state plus the mode's real part, sized",
          "[ns][periodic_orbit]") {
  NsState steady;
  steady.psi = {1.0, 2.0, 3.0};
  steady.zeta = {-4.0, 0.5, 2.0};
  steady.Gamma_R = 0.25;
  steady.N_prev = {9.0, 9.0, 9.0};
  const std::vector<std::complex<double>> psi = {{0.5, 1.0}, {-1.0, 0.0}, {0.0, 2.0}};
  const std::vector<std::complex<double>> zeta = {{0.0, 1.0}, {0.6, 0.8}, {-0.5, 0.0}};  // max |ζ| = 1
  const NsState s = hopf_start(steady, psi, zeta, {0.5, 0.5}, 0.1);
  const double eps = 0.1 * 4.0;  // size × max |ζ_steady|
  for (size_t i = 0; i < 3; ++i) {
    CHECK(s.psi[i] == Approx(steady.psi[i] + eps * psi[i].real()).epsilon(1e-14));
    CHECK(s.zeta[i] == Approx(steady.zeta[i] + eps * zeta[i].real()).epsilon(1e-14));
  }
  CHECK(s.Gamma_R == Approx(0.25 + eps * 0.5).epsilon(1e-14));
  CHECK(s.N_prev.empty());  // the march's first step is Euler's: no history of another state
  CHECK(s.t == 0.0);
  CHECK_THROWS_AS(hopf_start(steady, {psi[0]}, zeta, {0.0, 0.0}), std::invalid_argument);
}

TEST_CASE("[ns][map] the second shedding window: shedding again after a steady stretch, slower",
          "[ns][map]") {
  const double steady = double(MapRegime::steady), shed = double(MapRegime::shedding);
  auto row = [](std::vector<std::pair<double, double>> regime_st) {
    std::vector<NsMapPoint> r;
    for (const auto& [regime, st] : regime_st) {
      NsMapPoint m;
      m.regime = regime, m.strouhal = st;
      r.push_back(m);
    }
    mark_second_window(r);
    std::vector<double> out;
    for (const auto& m : r) out.push_back(m.regime);
    return out;
  };
  const double nan = std::nan(""), second = double(MapRegime::second_window);
  // Re 100 on the map's grid: sheds to α 1.8 (St 0.154), steady to 4.8, sheds at 5.1 with St 0.023.
  CHECK(row({{shed, 0.155}, {shed, 0.154}, {steady, nan}, {steady, nan}, {shed, 0.023}, {shed, 0.03}}) ==
        std::vector<double>{shed, shed, steady, steady, second, second});
  // A stable island between two unstable stretches: the wake sheds again at its own frequency.
  CHECK(row({{shed, 0.19}, {steady, nan}, {shed, 0.18}, {steady, nan}, {shed, 0.02}}) ==
        std::vector<double>{shed, steady, shed, steady, second});
  // Steady below the onset, then shedding: the first window, whatever its frequency.
  CHECK(row({{steady, nan}, {shed, 0.10}, {shed, 0.04}}) == std::vector<double>{steady, shed, shed});
  // A bistable point counts as steady; an undecided St leaves the point as it is.
  const double both = double(MapRegime::bistable);
  CHECK(row({{shed, 0.2}, {both, nan}, {shed, nan}, {shed, 0.05}}) ==
        std::vector<double>{shed, both, shed, second});
}

TEST_CASE("[ns][map] past alpha_L at Re 200 the continued orbit shrinks onto the steady state: not bistable",
          "[ns][map][periodic_orbit]") {
  // The map's grid at Re 200: the wake sheds at α 2.15 and the steady state is stable at 2.2. The orbit of
  // 2.15, continued into 2.2, collapses onto the steady state (a supercritical Hopf point between them), so
  // the point is steady, not bistable, and the row's orbit chain ends there.
  const Case c = map_case();
  const NsMap map = ns_map(c, test::orbit_row({2.15, 2.2}, 200.0));
  REQUIRE(map.points.size() == 2);
  const NsMapPoint &a = map.points[0], &b = map.points[1];
  CHECK(a.source == MapSource::orbit);
  CHECK(a.regime == double(MapRegime::shedding));
  CHECK(a.strouhal == Approx(0.174).epsilon(0.02));
  CHECK(b.stable == std::optional<bool>(true));
  CHECK(b.source == MapSource::steady);
  CHECK(b.regime == double(MapRegime::steady));
  CHECK(b.orbit_start.empty());  // the continuation was tried and found no orbit
}
