// The viscous model against published 2D results (label `validation`, minutes: ctest -L validation or
// magnus_tests "[validation]"). D = 1 m, U = 1 m/s, ρ = 1 kg/m³; every run starts impulsively from rest.
// Each case prints its figures (ours, published, difference, grid, wall time).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>

#include "postproc/navier_stokes/unsteady.hpp"

using namespace magnus;

namespace {

struct Run {
  UnsteadyResult res;
  PolarGrid grid;
  double L_r = 0.0;  ///< recirculation length, D (steady runs)
};

/// One run (cached: the convergence study reuses the finest grid of the Re 100 check).
/// n_r = 0: the NsParams default (Δξ = Δθ/radial_refinement).
/// order: the advection's order in θ (2 or 4).
const Run& run(double Re, double alpha, int n_theta, double R_over_a, double t_end, int n_r = 0,
               int order = 2) {
  static std::map<std::tuple<double, double, int, double, double, int, int>, Run> cache;
  const auto key = std::make_tuple(Re, alpha, n_theta, R_over_a, t_end, n_r, order);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 1.0 / Re, p.omega = alpha * p.U / p.a;
  p.n_theta = n_theta, p.outer_over_a = R_over_a, p.n_r = n_r, p.advection_order = order;
  UnsteadyOptions o;
  o.t_end = t_end;
  Run r;
  r.grid = ns_grid(p);
  NsState start = impulsive_start(p, r.grid);
  // A weak vortex (Γ = 0.1% of U·D) off the axis behind the body breaks the mirror symmetry at α = 0.
  add_vortex_blob(r.grid, start, 1.5, 0.3, 0.25, 1e-3);
  r.res = run_unsteady(p, o, std::move(start));
  if (r.res.steady) r.L_r = recirculation_length(r.grid, r.res.state);
  std::printf(
      "Re %g alpha %g, n_theta x n_r %d x %d, R/a %.1f, advection order %d: %s at t = %.1f; C_L %.4f (amp "
      "%.4f) C_D %.4f "
      "St %.5f; L_r %.3f D; %ld steps of %.4g s, wall %.1f s\n",
      Re, alpha, n_theta, r.grid.n_r, r.grid.outer_radius() / p.a, order, r.res.message.c_str(),
      r.res.state.t, r.res.C_L_mean, r.res.C_L_amplitude, r.res.C_D_mean, r.res.St, r.L_r, r.res.steps,
      r.res.dt, r.res.wall_seconds);
  std::fflush(stdout);
  return cache.emplace(key, std::move(r)).first->second;
}

void compare(const char* what, double ours, double published, const char* source) {
  std::printf("  %-14s ours %9.4f  published %9.4f (%s)  difference %+6.2f%%\n", what, ours, published,
              source, 100.0 * (ours - published) / published);
  std::fflush(stdout);
}

/// Observed order p from three values on grids h1 > h2 > h3 (any ratios): bisection on
/// (f1 − f2)/(f2 − f3) = (h1^p − h2^p)/(h2^p − h3^p).
double observed_order3(double f1, double f2, double f3, double h1, double h2, double h3) {
  const double q = (f1 - f2) / (f2 - f3);
  auto g = [&](double p) {
    return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p)) - q;
  };
  double lo = 0.1, hi = 8.0;
  if (g(lo) * g(hi) > 0.0) return std::nan("");
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(lo) * g(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

const NsParams kDefaults;
const double kR = kDefaults.outer_over_a;  // default R/a = 100 (50 D)
const int kN = kDefaults.n_theta;          // default n_θ = 192 (n_r = 236: Δξ = Δθ/(5/3) = 2π/320)

}  // namespace

TEST_CASE("[validation] Re 100, alpha 1: mean lift, drag, Strouhal (Stojkovic, Breuer & Durst 2002)",
          "[validation]") {
  // The defaults. Measured: |C_L| −0.44%, C_D −1.69%, St −0.97% against SBD; against Kang +0.19%, −1.34%,
  // −0.79% (St is grid- and Δt-converged at 0.1644, −0.85%, on finer θ grids; C_D converges to ~1.088,
  // 1.7% below SBD's 1.108 and 1.4% below Kang's 1.104: the README's validation table. Before the forces'
  // wall derivative was fourth order, this grid's +1.5% error in C_D hid that gap).
  const Run& r = run(100, 1.0, kN, kR, 250);
  REQUIRE(r.res.ok);
  REQUIRE(r.res.periodic);
  compare("|C_L| mean", std::fabs(r.res.C_L_mean), 2.504, "SBD 2002");
  compare("C_D mean", r.res.C_D_mean, 1.108, "SBD 2002");
  compare("St", r.res.St, 0.1658, "SBD 2002");
  compare("C_L amplitude", r.res.C_L_amplitude, 0.3616, "SBD 2002");
  CHECK(r.res.C_L_mean < 0.0);  // CCW spin: lift towards −y
  CHECK(std::fabs(r.res.C_L_mean) == Approx(2.504).epsilon(0.006));
  CHECK(r.res.C_D_mean == Approx(1.108).epsilon(0.02));
  CHECK(r.res.St == Approx(0.1658).epsilon(0.01));
  CHECK(r.res.C_L_amplitude == Approx(0.3616).epsilon(0.03));
  compare("|C_L| mean", std::fabs(r.res.C_L_mean), 2.4881, "Kang 1999");
  compare("C_D mean", r.res.C_D_mean, 1.1040, "Kang 1999");
  compare("St", r.res.St, 0.1655, "Kang 1999");
  CHECK(std::fabs(r.res.C_L_mean) == Approx(2.4881).epsilon(0.01));
  CHECK(r.res.C_D_mean == Approx(1.1040).epsilon(0.016));
  CHECK(r.res.St == Approx(0.1655).epsilon(0.01));
}

TEST_CASE("[validation] Re 100, alpha 1, advection order 4: St converged in theta on the default grid",
          "[validation]") {
  // Order 2's St rises ~1e-4 per refinement in θ (0.16419 at n_θ 192 … 0.16450 at 512); order 4 removes
  // that error. Measured: order 4, 236 x 192: St 0.16445, C_L −2.4913, C_D 1.1028; 236 x 256: 0.16444.
  const Run& r2 = run(100, 1.0, kN, kR, 250);
  const Run& r4 = run(100, 1.0, kN, kR, 250, 0, 4);
  const Run& r4t = run(100, 1.0, 256, kR, 250, r4.grid.n_r, 4);  // θ refined, the same rings
  REQUIRE((r2.res.periodic && r4.res.periodic && r4t.res.periodic));
  compare("St order 2", r2.res.St, 0.1658, "SBD 2002");
  compare("St order 4", r4.res.St, 0.1658, "SBD 2002");
  compare("St o4 n_t 256", r4t.res.St, 0.1658, "SBD 2002");
  compare("|C_L| order 4", std::fabs(r4.res.C_L_mean), 2.504, "SBD 2002");
  compare("C_D order 4", r4.res.C_D_mean, 1.108, "SBD 2002");
  CHECK(r4.res.St - r2.res.St > 1.5e-4);              // the θ-advection error of order 2 (2.6e-4)
  CHECK(std::fabs(r4t.res.St - r4.res.St) < 5e-5);    // converged in θ (measured 1e-5)
  CHECK(r4.res.St == Approx(0.1658).epsilon(0.009));  // −0.82%
  CHECK(std::fabs(r4.res.C_L_mean) == Approx(2.504).epsilon(0.006));
  CHECK(r4.res.C_D_mean == Approx(1.108).epsilon(0.02));  // the converged 1.088 is 1.8% below SBD
  CHECK(std::fabs(r4.res.C_L_mean - r2.res.C_L_mean) < 5e-4 * std::fabs(r2.res.C_L_mean));  // forces: < 0.05%
  CHECK(std::fabs(r4.res.C_D_mean - r2.res.C_D_mean) < 5e-4 * r2.res.C_D_mean);
}

TEST_CASE("[validation] Re 100, alpha 1: grid convergence on three grids, observed order, Richardson",
          "[validation]") {
  // The mean forces' error is in Δξ (n_θ 128 → 256 moved them < 0.1%): refine the rings at n_θ = 128.
  // Measured n_r 143 / 190 / 285: |C_L| 2.48798 2.49107 2.49384 (order 1.35), C_D 1.08858 1.08909 1.08893,
  // St 0.1643 flat. With the three-ring wall derivative C_D went 1.1284 1.1109 1.0980: that Δξ error was
  // the derivative's, and with five rings C_D is flat to 0.05%, the size of the means' own tolerance.
  const Run& r1 = run(100, 1.0, kN, kR, 250, 143);
  const Run& r2 = run(100, 1.0, kN, kR, 250, 190);
  const Run& r3 = run(100, 1.0, kN, kR, 250, 285);
  REQUIRE((r1.res.periodic && r2.res.periodic && r3.res.periodic));
  const double h1 = 1.0 / 142, h2 = 1.0 / 189, h3 = 1.0 / 284;
  struct Q {
    const char* name;
    double f1, f2, f3, ref;
  };
  for (const Q& q : {Q{"|C_L| mean", -r1.res.C_L_mean, -r2.res.C_L_mean, -r3.res.C_L_mean, 2.504},
                     Q{"C_D mean", r1.res.C_D_mean, r2.res.C_D_mean, r3.res.C_D_mean, 1.108},
                     Q{"St", r1.res.St, r2.res.St, r3.res.St, 0.1658}}) {
    const double p = observed_order3(q.f1, q.f2, q.f3, h1, h2, h3);
    const double richardson = q.f3 + (q.f3 - q.f2) / (std::pow(h2 / h3, 2.0) - 1.0);  // design order 2
    std::printf(
        "  %-10s n_r 143 / 190 / 285: %.5f %.5f %.5f  observed order %.2f  Richardson (p = 2) %.5f"
        "  (published %.4f, %+.2f%%)\n",
        q.name, q.f1, q.f2, q.f3, p, richardson, q.ref, 100.0 * (richardson - q.ref) / q.ref);
    std::fflush(stdout);
    if (std::string(q.name) == "|C_L| mean") CHECK((p > 1.0 && p < 3.5));  // St, C_D barely move: noise
    if (std::string(q.name) == "C_D mean") {
      const double lo = std::min({q.f1, q.f2, q.f3}), hi = std::max({q.f1, q.f2, q.f3});
      CHECK(hi - lo < 1e-3 * q.f3);  // converged in the rings to the means' tolerance
    }
  }
}

TEST_CASE("[validation] Re 100, alpha 1: doubling R changes C_L, C_D, St by < 0.5%", "[validation]") {
  // Same Δξ on both (the default's): only R changes. Measured at n_θ 128, n_r 190 / 219: C_L +0.03%,
  // C_D −0.02%, St +0.03%; R/a 50 → 100 moved C_D −0.64% and St −0.59% (too small a domain).
  const int n_r = kDefaults.n_r > 0 ? kDefaults.n_r : ns_grid(kDefaults).n_r;
  const int n_r2 = int(std::lround((n_r - 1) * std::log(2 * kR) / std::log(kR))) + 1;
  const Run& a = run(100, 1.0, kN, kR, 400);
  const Run& b = run(100, 1.0, kN, 2 * kR, 400, n_r2);
  REQUIRE((a.res.periodic && b.res.periodic));
  auto rel = [](double x, double y) { return std::fabs(y - x) / std::fabs(x); };
  std::printf("  R/a %g -> %g: C_L %+.3f%%, C_D %+.3f%%, St %+.3f%%\n", kR, 2 * kR,
              100 * rel(a.res.C_L_mean, b.res.C_L_mean), 100 * rel(a.res.C_D_mean, b.res.C_D_mean),
              100 * rel(a.res.St, b.res.St));
  CHECK(rel(a.res.C_L_mean, b.res.C_L_mean) < 0.005);
  CHECK(rel(a.res.C_D_mean, b.res.C_D_mean) < 0.005);
  CHECK(rel(a.res.St, b.res.St) < 0.005);
}

TEST_CASE("[validation] steady alpha 0: drag and recirculation length at Re 20 and 40", "[validation]") {
  const Run& r20 = run(20, 0.0, kN, kR, 300);
  const Run& r40 = run(40, 0.0, kN, kR, 300);
  REQUIRE((r20.res.steady && r40.res.steady));
  compare("C_D Re 20", r20.res.C_D_mean, 2.045, "Dennis & Chang 1970");
  compare("C_D Re 20", r20.res.C_D_mean, 2.000, "Fornberg 1980");
  compare("L_r/D Re 20", r20.L_r, 0.93, "Dennis & Chang 1970");
  compare("C_D Re 40", r40.res.C_D_mean, 1.522, "Dennis & Chang 1970");
  compare("C_D Re 40", r40.res.C_D_mean, 1.498, "Fornberg 1980");
  compare("L_r/D Re 40", r40.L_r, 2.25, "2.2-2.35, Dennis & Chang; Fornberg");
  // Separation: τ_w changes sign at the separation angle, measured from the rear stagnation point (θ = 0,
  // +x); D&C: 43.7° (Re 20), 53.8° (Re 40).
  auto separation_deg = [](const Run& r) {
    NsParams q;  // α = 0: τ_w = μ ζ_w, its sign is ζ_w's whatever μ
    q.omega = 0.0;
    const std::vector<double> th = separation_angles(viscous_surface(r.grid, q, 1.0, r.res.state));
    for (double t : th)  // skip the rear stagnation point θ = 0 (τ_w = 0 there by symmetry)
      if (t > 0.05 && t < M_PI) return 180.0 / M_PI * t;
    return 0.0;
  };
  compare("theta_s Re 20", separation_deg(r20), 43.7, "Dennis & Chang 1970");
  compare("theta_s Re 40", separation_deg(r40), 53.8, "Dennis & Chang 1970");
  CHECK(separation_deg(r20) == Approx(43.7).epsilon(0.03));
  CHECK(separation_deg(r40) == Approx(53.8).epsilon(0.03));
  // Between the two references (they differ by 2%); the recirculation lengths within their spread.
  CHECK(r20.res.C_D_mean == Approx(2.0225).epsilon(0.02));
  CHECK(r40.res.C_D_mean == Approx(1.510).epsilon(0.02));
  CHECK(r20.L_r == Approx(0.93).epsilon(0.03));
  CHECK((r40.L_r > 2.2 && r40.L_r < 2.35));
}

TEST_CASE("[validation] Re 100, alpha 0 to 2: lift, drag, Strouhal (Stojkovic, Breuer & Durst 2002)",
          "[validation]") {
  // Two grids per α, the default and its rings doubled (Δξ halved, n_θ kept), and their Richardson value
  // (p = 2 in Δξ): the mean drag depends on the radial spacing and hardly on n_θ, and its grid error grows
  // with α (the boundary layer thins on the side moving against the stream). Halving n_θ as well puts the
  // coarse grid outside the asymptotic range (96 × 118 gave C_D 1.3097 at α = 0, against 1.3127 from the
  // rings). α = 1 has its own tests above.
  struct Ref {
    double alpha, C_L, C_D, St, amp;
    double cd_tol;  ///< the drag's tolerance: 2%, 3% where the ring-converged drag is 2.2% low
  };
  for (const Ref& ref :
       {Ref{0.0, 0.0, 1.3371, 0.1650, 0.3259, 0.02}, Ref{0.5, 1.220, 1.2770, 0.1657, 0.3420, 0.02},
        Ref{1.5, 3.900, 0.8180, 0.1626, 0.3180, 0.03}, Ref{2.0, 5.48, 0.46, 0.0, 0.0, 0.03}}) {
    const Run& f = run(100, ref.alpha, kN, kR, 300);
    const Run& r = run(100, ref.alpha, kN, kR, 300, 2 * (f.grid.n_r - 1) + 1);  // Δξ halved
    REQUIRE((f.res.ok && r.res.ok));
    auto richardson = [](double coarse, double fine) {
      return fine + (fine - coarse) / 3.0;
    };  // p = 2, ratio 2
    const double C_L = std::fabs(richardson(f.res.C_L_mean, r.res.C_L_mean));
    const double C_D = richardson(f.res.C_D_mean, r.res.C_D_mean);
    std::printf("  alpha %.1f (n_theta %d; Richardson from %d and %d rings):\n", ref.alpha, kN, f.grid.n_r,
                r.grid.n_r);
    if (ref.alpha > 0) {
      compare("|C_L|", std::fabs(f.res.C_L_mean), ref.C_L, "SBD 2002");
      compare("|C_L| Rich.", C_L, ref.C_L, "SBD 2002");
    }
    compare("C_D", f.res.C_D_mean, ref.C_D, "SBD 2002");
    compare("C_D Rich.", C_D, ref.C_D, "SBD 2002");
    if (ref.St > 0) {
      compare("St", f.res.St, ref.St, "SBD 2002");
      compare("C_L amplitude", f.res.C_L_amplitude, ref.amp, "SBD 2002");
    }
    // The default grid against the table: |C_L|, St and the amplitude within 2%. The drag on the
    // Richardson value. Measured (R = 100a): 1.3127, 1.2581, 0.7979, 0.4508, i.e. −1.8%, −1.5%, −2.5%,
    // −2.0% at α = 0, 0.5, 1.5, 2; with a third grid (942 rings, observed order 2.2) α = 1.5 converges to
    // −2.3%, and the steady study at α = 2 to −2.2%: the model's drag there is just outside 2%, hence 3%.
    if (ref.alpha > 0) CHECK(std::fabs(f.res.C_L_mean) == Approx(ref.C_L).epsilon(0.02));
    CHECK(C_D == Approx(ref.C_D).epsilon(ref.cd_tol));
    if (ref.St > 0) CHECK(f.res.St == Approx(ref.St).epsilon(0.02));
    if (ref.St > 0) CHECK(f.res.C_L_amplitude == Approx(ref.amp).epsilon(0.02));
    // Steady at α = 2: by t = 300 D/U what is left is a decaying wiggle of C_L amplitude ~5e-4 (against
    // 0.318 at α = 1.5), below the published tables' resolution.
    if (ref.alpha == 2.0) CHECK((f.res.steady || f.res.C_L_amplitude < 1e-3));
  }
}
