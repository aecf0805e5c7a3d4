// The time step of the viscous model: AB2/CN stays second order when Δt changes from step to step (the
// variable-step Adams–Bashforth weights), and a Δt that magnus chose itself never passes the CFL limit.
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/unsteady.hpp"
#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/rotation.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::observed_order;

namespace {

/// Re 40 past a cylinder on a small grid (32 × 21, R = 10a).
NsParams small_flow() {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.omega = 0.5, p.nu = 0.025, p.outer_over_a = 10.0, p.n_theta = 32, p.threads = 1;
  return p;
}

/// From s over `pairs` pairs of steps h, 2h (Δt alternating by a factor 2): the final vorticity.
std::vector<double> alternate(const NsParams& p, NsState s, double h, int pairs) {
  const NsOperator a(p, h), b(p, 2.0 * h);
  NsState next;
  for (int k = 0; k < pairs; ++k) {
    advance(a, s, next);
    std::swap(s, next);
    advance(b, s, next);
    std::swap(s, next);
  }
  return s.zeta;
}

}  // namespace

TEST_CASE("[ns] time step: AB2/CN is second order in time with a step that changes every step", "[ns]") {
  const NsParams p = small_flow();
  const PolarGrid g = ns_grid(p);
  // A developed start (t = 0.5 from rest), then 0.6 s of steps h, 2h, h, 2h, … for h = 0.01, 0.005, 0.0025.
  NsState s = impulsive_start(p, g);
  {
    const NsOperator op(p, 0.005);
    NsState next;
    for (int k = 0; k < 100; ++k) advance(op, s, next), std::swap(s, next);
  }
  s.N_prev.clear(), s.dt_prev = 0.0;  // each run starts afresh (one Euler step)
  const auto z1 = alternate(p, s, 0.01, 20), z2 = alternate(p, s, 0.005, 40),
             z3 = alternate(p, s, 0.0025, 80);
  const double d12 = test::max_abs_diff(z1, z2), d23 = test::max_abs_diff(z2, z3);
  INFO("successive differences " << d12 << " " << d23);
  REQUIRE(d23 > 0.0);
  CHECK(observed_order(d12, d23) == Approx(2.0).margin(0.15));  // constant AB2 weights give order 1
}

TEST_CASE("[ns] time step: magnus's own step never passes the CFL limit, even at the limit itself", "[ns]") {
  // Re 100, α = 1. time.cfl = 0.8 = kNsCflLimit on 32 × R = 20a was refused at t = 2.12 ("CFL 0.8012 > 0.8")
  // when Δt was re-checked every 10 steps; now it is checked before every step and kept below the limit.
  struct Run {
    double cfl;
    int n_theta;
    double R, t_end;
  };
  for (const Run& c : {Run{0.8, 32, 20.0, 4.0}, Run{0.8, 16, 10.0, 40.0}, Run{0.7, 16, 10.0, 40.0}}) {
    NsParams p = small_flow();
    p.nu = 0.01, p.omega = 2.0, p.n_theta = c.n_theta, p.outer_over_a = c.R, p.cfl = c.cfl;
    const PolarGrid g = ns_grid(p);
    UnsteadyOptions o;
    o.t_end = c.t_end;
    o.t_min = 1e9;  // no early stop
    // The largest CFL number of a step: the rate of its start state (as advance() measures it, or above)
    // times the step.
    double worst = 0.0, last_rate = -1.0, last_t = 0.0;
    o.on_step = [&](const NsState& s, const ViscousForces&) {
      if (last_rate >= 0.0) worst = std::max(worst, last_rate * (s.t - last_t));
      // With the rotation implicit (the default) the explicit part's rate: ψ − ψ_ref, no wall ring term.
      const double r = cfl_number(g, s.psi, 1.0, 2, 2, reference_psi_xi(p));
      last_rate = rotation_implicit(p) ? r : std::max(r, std::fabs(p.omega) / g.d_theta), last_t = s.t;
      return true;
    };
    const UnsteadyResult r = run_unsteady(p, o, impulsive_start(p, g));
    INFO("cfl " << c.cfl << ", n_theta " << c.n_theta << ": " << r.message);
    CHECK(r.ok);
    CHECK(r.state.t == Approx(o.t_end));
    CHECK(worst <= kNsCflLimit);
    CHECK(worst > 0.9 * std::min(c.cfl, 0.95 * kNsCflLimit));  // it did run at its target
  }
}
