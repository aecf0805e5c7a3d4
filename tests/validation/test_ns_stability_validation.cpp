// The onset of shedding (label `validation`, minutes each): linear stability of the Newton steady state,
// the Hopf point by the secant search. At Re 100 the critical spin ratio against 1.84 ± 0.03 (Kang, Choi &
// Lee 1999, by extrapolating their amplitudes; the linear-stability studies), then the time stepper itself
// on either side.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "postproc/navier_stokes/critical.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

using namespace magnus;

namespace {

NsParams re100() {
  NsParams p;  // the default grid: n_θ = 192, R = 100a
  p.a = 0.5, p.U = 1.0, p.nu = 1.0 / 100.0;
  return p;
}

/// The time stepper from the steady state at α plus a weak vortex; the C_L amplitude at t_end.
UnsteadyResult march(double alpha, double t_end, const NsState& steady) {
  NsParams p = re100();
  p.omega = alpha * p.U / p.a;
  const PolarGrid g = ns_grid(p);
  NsState s = steady;
  add_vortex_blob(g, s, 1.5, 0.3, 0.25, 1e-2);
  UnsteadyOptions o;
  o.t_end = t_end;
  o.steady_tol = 0.0;  // march to t_end
  return run_unsteady(p, o, std::move(s));
}

}  // namespace

TEST_CASE("[validation][stability] Re 100: the critical spin ratio is 1.84 ± 0.03 and the stepper agrees",
          "[validation][stability]") {
  HopfOptions o;
  o.tol = 0.002;
  const HopfPoint c = hopf_point(re100(), HopfParameter::spin_ratio, 1.6, 2.2, o, [](const HopfEvaluation& s) {
    std::printf("  alpha %.5f growth %+.5f St %.4f%s\n", s.x, s.growth(), eigen_strouhal(s.mode),
                s.tracked ? " (tracked)" : "");
    std::fflush(stdout);
  });
  std::printf("Re 100: alpha_c %.4f +- %.1g in [%.4f, %.4f], %zu steady states, %.1f s\n", c.x_c, c.change, c.lo,
              c.hi, c.evaluations.size(), c.seconds);
  // Kang, Choi & Lee 1999 (extrapolating their amplitudes) and the linear-stability studies: 1.84 ± 0.03.
  CHECK(c.x_c == Approx(1.84).margin(0.03));
  CHECK(c.change <= 0.001);
  CHECK(c.at_a.growth() > 0.0);
  CHECK(c.at_b.growth() < 0.0);
  // At α = 2.2 the wake's pair leads the oscillating modes: −0.0444 + 0.925i (U/D), found from both the
  // case in SI units and this one. With the acceptance tolerance at 1e-6 it stalled just above it in this
  // scaling, and a damped pair at −0.136 + 1.34i was reported as the leading one.
  // The wake's pair at the crossing: St 0.15–0.16 (the march below sheds at St 0.159 at α_c − 0.1).
  CHECK(c.strouhal() > 0.15);
  CHECK(c.strouhal() < 0.16);

  // The time stepper on either side, from the steady state plus a disturbance: at α_c − 0.1 the lift
  // oscillates with a clear amplitude; at α_c + 0.1 the disturbance dies away.
  const double below = c.x_c - 0.1, above = c.x_c + 0.1;
  const HopfEvaluation sb = hopf_evaluation(re100(), HopfParameter::spin_ratio, below, nullptr, std::nullopt);
  const HopfEvaluation sa = hopf_evaluation(re100(), HopfParameter::spin_ratio, above, nullptr, std::nullopt);
  REQUIRE(sb.converged);
  REQUIRE(sa.converged);
  const UnsteadyResult rb = march(below, 400.0, sb.state), ra = march(above, 400.0, sa.state);
  const auto amplitude = [](const UnsteadyResult& r) {
    double lo = 1e300, hi = -1e300;  // over the last 20 D/U
    for (const auto& f : r.history)
      if (f.t > r.state.t - 20.0) lo = std::min(lo, f.C_L), hi = std::max(hi, f.C_L);
    return 0.5 * (hi - lo);
  };
  std::printf("stepper: alpha %.3f C_L amplitude %.4g; alpha %.3f C_L amplitude %.4g\n", below, amplitude(rb),
              above, amplitude(ra));
  // From the steady state the disturbance grows at only ~0.025 U/D at α_c − 0.1, so at t = 400 it has not
  // saturated (measured: 0.031, against 0.19 for a run from rest that reached the limit cycle): what the
  // stepper must show is growth below and decay above, three orders of magnitude apart (measured 1450×).
  CHECK(amplitude(rb) > 0.01);
  CHECK(amplitude(rb) > 100.0 * amplitude(ra));
  CHECK(amplitude(ra) < 1e-3);
}
