// Shedding states as periodic orbits (Newton–GMRES shooting on the period map) against long marches on the
// same grid and Δt: the orbit's mean C_L, mean C_D, C_L amplitude and St agree with the march's to 1e-4,
// and the Newton residual falls to 1e-9. R = 30a runs in seconds (default); R = 100a, whose march converges
// slowly, under the ctest label "orbit".
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/periodic.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// Re, α past the cylinder of a = 0.5 m in U = 1 m/s (D/U = 1 s) on n_θ points, R = outer·a.
NsParams shedding_flow(double Re, double alpha, int n_theta, double outer) {
  return test::cylinder_flow(Re, alpha, n_theta, outer);
}

/// Impulsive start with the mirror symmetry broken by a weak vortex behind the body.
NsState broken_start(const NsParams& p) {
  const PolarGrid g = ns_grid(p);
  NsState s = impulsive_start(p, g);
  add_vortex_blob(g, s, 3.0 * p.a, 0.6 * p.a, 0.5 * p.a, 1e-3 * p.U * 2.0 * p.a);
  return s;
}

double rel(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

/// The orbit of p by shooting from a short march against a march on from the short march's state with the
/// orbit's Δt = T/N (the same discrete map; run_unsteady would clamp this Δt to its start's CFL floor) to
/// t_long, its forces every step: means, C_L amplitude (extremes refined alike) and St agree to 1e-4, and
/// the Newton residual falls to 1e-9, the last step by a factor 100 or more, the last two by 1e4.
void check_orbit_against_march(const NsParams& p, double t_long) {
  OrbitRunOptions o;
  o.t_end = 300.0;
  o.orbit.tol = 1e-9;
  const OrbitRun run = periodic_orbit_run(p, o, broken_start(p));
  const OrbitResult& orb = run.orbit;
  WARN(run.result.message);
  REQUIRE(orb.converged);  // residual ≤ o.orbit.tol = 1e-9
  // Faster at the end: the last Newton step gains a factor 100 or more and the last two together 1e4 (the
  // first steps gain 3 to 10 each), within 6 iterations.
  const size_t K = orb.history.size() - 1;
  REQUIRE(K >= 2);
  CHECK(K <= 6);
  CHECK(orb.history[K].residual < 1e-2 * orb.history[K - 1].residual);
  CHECK(orb.history[K].residual < 1e-4 * orb.history[K - 2].residual);

  const PolarGrid g = ns_grid(p);
  const NsOperator op(p, orb.T / orb.steps);
  std::vector<ForceSample> h;
  NsState s = run.march.state, next;
  while (s.t < t_long) {
    advance(op, s, next);
    std::swap(s, next);
    h.push_back(force_sample(s.t, viscous_forces(g, p, 1.0, s)));
  }
  const std::vector<PeriodWindow> w = lift_periods(h, 1);
  REQUIRE(w.size() == 1);
  std::vector<double> L;
  for (const ForceSample& x : h)
    if (x.t >= w[0].t0 && x.t <= w[0].t1) L.push_back(x.C_L);
  double lo, hi;
  periodic_extremes(L, lo, hi);
  const UnsteadyResult& r = run.result;
  WARN("orbit: C_L " << r.C_L_mean << " C_D " << r.C_D_mean << " amp " << r.C_L_amplitude << " St " << r.St
                     << "; march: C_L " << w[0].C_L << " C_D " << w[0].C_D << " amp " << 0.5 * (hi - lo)
                     << " St " << 1.0 / w[0].length());
  CHECK(std::fabs(r.C_L_mean - w[0].C_L) < 1e-4 * std::max(1.0, std::fabs(w[0].C_L)));
  CHECK(rel(r.C_D_mean, w[0].C_D) < 1e-4);
  CHECK(rel(r.C_L_amplitude, 0.5 * (hi - lo)) < 1e-4);
  CHECK(rel(r.St, 1.0 / w[0].length()) < 1e-4);
}

}  // namespace

TEST_CASE("orbit: extremes of a sampled sinusoid refined by parabolas give its amplitude", "[periodic_orbit]") {
  std::vector<double> y;
  const int N = 64;
  for (int k = 0; k < N; ++k) y.push_back(0.3 + 1.7 * std::sin(2.0 * M_PI * (k + 0.37) / N));
  double lo, hi;
  periodic_extremes(y, lo, hi);
  CHECK(std::fabs(0.5 * (hi - lo) - 1.7) < 1e-4 * 1.7);
  CHECK(std::fabs(0.5 * (hi + lo) - 0.3) < 1e-4);
}

TEST_CASE("orbit: Re 100, alpha 1, n_theta 64, R 30a: the orbit by shooting is the long march's periodic state",
          "[periodic_orbit]") {
  check_orbit_against_march(shedding_flow(100.0, 1.0, 64, 30.0), 400.0);
}

TEST_CASE("orbit: Re 100, alpha 1, n_theta 64, R 100a: the orbit by shooting is the long march's periodic state",
          "[orbit]") {
  check_orbit_against_march(shedding_flow(100.0, 1.0, 64, 100.0), 3000.0);
}

TEST_CASE("orbit: Re 60, alpha 0, n_theta 64, R 100a: the orbit by shooting is the long march's periodic state",
          "[orbit]") {
  check_orbit_against_march(shedding_flow(60.0, 0.0, 64, 100.0), 3000.0);
}

TEST_CASE("orbit: the summary from the solve's last period is one more period of steps, bit for bit",
          "[periodic_orbit]") {
  // The run keeps the forces of the last period the Newton solve stepped (that of the state it returns);
  // stepping the returned state once more gives the same samples, so the same summary to the last bit, and
  // the run's step count leaves that period out.
  const NsParams p = shedding_flow(100.0, 1.0, 64, 30.0);
  OrbitRunOptions o;
  o.t_end = 300.0;
  o.orbit.tol = 1e-9;
  const OrbitRun run = periodic_orbit_run(p, o, broken_start(p));
  REQUIRE(run.orbit.converged);
  const UnsteadyResult stepped = orbit_summary(p, run.orbit, o.rho);
  const UnsteadyResult& kept = run.result;
  REQUIRE(kept.history.size() == size_t(run.orbit.steps) + 1);
  REQUIRE(stepped.history.size() == kept.history.size());
  for (size_t k = 0; k < kept.history.size(); ++k) {
    CHECK(kept.history[k].t == stepped.history[k].t);
    CHECK(kept.history[k].C_L == stepped.history[k].C_L);
    CHECK(kept.history[k].C_D == stepped.history[k].C_D);
  }
  CHECK(kept.C_L_mean == stepped.C_L_mean);
  CHECK(kept.C_D_mean == stepped.C_D_mean);
  CHECK(kept.C_L_amplitude == stepped.C_L_amplitude);
  CHECK(kept.state.t == stepped.state.t);
  CHECK(kept.state.zeta == stepped.state.zeta);
  CHECK(kept.state.psi == stepped.state.psi);
  CHECK(kept.steps == run.march.steps + run.orbit.time_steps);
  CHECK(stepped.steps == run.orbit.steps);  // the summary that stepped counts its period
}

TEST_CASE("orbit: a flow that does not shed (Re 40) is refused in one line", "[periodic_orbit]") {
  OrbitRunOptions o;
  o.t_end = 200.0;
  const NsParams p = shedding_flow(40.0, 0.0, 48, 20.0);
  try {
    periodic_orbit_run(p, o, broken_start(p));
    FAIL("a steady flow gave an orbit");
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    CHECK((m.find("does not shed") != std::string::npos || m.find("steady") != std::string::npos));
    CHECK(m.find('\n') == std::string::npos);
  }
}

TEST_CASE("orbit: continued from alpha 1 to 1.2, the orbit is the one found from a march at 1.2",
          "[periodic_orbit]") {
  OrbitRunOptions o;
  o.orbit.tol = 1e-9;
  const NsParams p1 = shedding_flow(100.0, 1.0, 64, 30.0), p2 = shedding_flow(100.0, 1.2, 64, 30.0);
  const OrbitRun at1 = periodic_orbit_run(p1, o, broken_start(p1));
  REQUIRE(at1.orbit.converged);
  const OrbitResult next = continue_orbit(p2, at1.orbit, o.orbit);
  REQUIRE(next.converged);
  CHECK(next.history.size() <= 7);  // 6 Newton iterations at most
  o.orbit.steps = at1.orbit.steps;  // the same N: the same discrete map
  const OrbitRun at2 = periodic_orbit_run(p2, o, broken_start(p2));
  REQUIRE(at2.orbit.converged);
  const UnsteadyResult a = orbit_summary(p2, next, 1.0), &b = at2.result;
  WARN(orbit_history_text(next, 1.0) << "; C_L " << a.C_L_mean << " against " << b.C_L_mean);
  CHECK(rel(a.C_L_mean, b.C_L_mean) < 1e-6);
  CHECK(rel(a.C_D_mean, b.C_D_mean) < 1e-6);
  CHECK(rel(next.T, at2.orbit.T) < 1e-6);
}
