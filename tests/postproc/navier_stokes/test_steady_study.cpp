// The steady grid study: Richardson extrapolation against functions with a known limit and order, the
// coarse-to-fine interpolation against fields it must reproduce exactly, and the sequenced Newton solves
// against a direct Newton solve on the finest grid.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "io/report_steady.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "postproc/navier_stokes/forces.hpp"

using namespace magnus;

TEST_CASE("[steady] Richardson: the limit and the order of f = f* + c·h^p", "[steady]") {
  const std::vector<double> h = {0.1, 0.07, 0.05};
  for (const double p : {1.5, 2.0, 2.7}) {
    std::vector<double> f;
    for (double x : h) f.push_back(1.5 + 0.3 * std::pow(x, p));
    const Richardson r = richardson(f, h);
    INFO("p = " << p);
    CHECK(r.observed);
    CHECK(r.order == Approx(p).margin(1e-6));
    CHECK(r.value == Approx(1.5).margin(1e-9));
    CHECK(r.finest == f.back());
    // The error bar: how far the value moves with the formal order 2 instead, at least a tenth of the
    // correction.
    const double formal = f[2] + (f[2] - f[1]) / (std::pow(h[1] / h[2], 2.0) - 1.0);
    CHECK(r.error == Approx(std::max(std::fabs(1.5 - formal), 0.1 * std::fabs(1.5 - f[2]))).margin(1e-9));
    CHECK(r.error >= 0.1 * std::fabs(r.value - r.finest));
  }
  // Two grids: order 2 assumed, the error bar the whole correction.
  const Richardson two = richardson({2.0 + 0.4 * 0.01, 2.0 + 0.4 * 0.0025}, {0.1, 0.05});
  CHECK_FALSE(two.observed);
  CHECK(two.value == Approx(2.0).margin(1e-12));
  CHECK(two.error == Approx(0.4 * 0.0025).margin(1e-12));
  // Not monotone: no order observed, 2 assumed.
  const Richardson wiggle = richardson({1.0, 1.2, 1.1}, h);
  CHECK_FALSE(wiggle.observed);
  CHECK(wiggle.order == 2.0);
  CHECK_THROWS_AS(richardson({1.0}, {0.1}), std::invalid_argument);
  CHECK_THROWS_AS(richardson({1.0, 2.0}, {0.05, 0.1}), std::invalid_argument);
}

TEST_CASE("[steady] significant digits an error bar keeps", "[steady]") {
  CHECK(significant_digits(1.4953, 0.0004) == 4);   // 1.495(3) ± 0.0004 < 0.0005
  CHECK(significant_digits(1.4953, 0.0006) == 3);
  CHECK(significant_digits(0.4406, 0.0157) == 1);
  CHECK(significant_digits(-5.513, 0.004) == 3);
  CHECK(significant_digits(2.0, 3.0) == 0);
  CHECK_FALSE(significant_digits(0.0, 0.1).has_value());
  CHECK_FALSE(significant_digits(1.0, 0.0).has_value());
}

TEST_CASE("[steady] interpolation to a finer grid keeps trigonometric-times-cubic fields exactly",
          "[steady]") {
  NsParams p;
  p.n_theta = 16, p.n_r = 21, p.outer_over_a = 20.0;
  const PolarGrid c = ns_grid(p);
  p.n_theta = 24, p.n_r = 31;
  const PolarGrid f = ns_grid(p);
  // Modes up to 7 (< 16/2) in θ, cubic in ξ; ψ vanishes on the wall as the interpolation imposes.
  auto psi = [](double xi, double th) { return xi * (1.0 - 0.3 * xi + 0.05 * xi * xi) * (std::sin(th) + 0.2 * std::cos(7 * th)); };
  auto zeta = [](double xi, double th) { return (2.0 - xi + 0.1 * xi * xi * xi) * (1.0 + std::cos(3 * th) - 0.5 * std::sin(5 * th)); };
  auto fill = [&](const PolarGrid& g) {
    NsState s;
    for (int i = 0; i < g.n_r; ++i)
      for (int j = 0; j < g.n_theta; ++j) {
        const double xi = std::log(g.r[i] / g.a);
        s.psi.push_back(psi(xi, g.theta[j])), s.zeta.push_back(zeta(xi, g.theta[j]));
      }
    s.Gamma_R = 0.7;
    return s;
  };
  const NsState exact = fill(f), got = interpolate_state(c, fill(c), f);
  REQUIRE(got.psi.size() == exact.psi.size());
  double err = 0.0;
  for (size_t q = 0; q < exact.psi.size(); ++q)
    err = std::max({err, std::fabs(got.psi[q] - exact.psi[q]), std::fabs(got.zeta[q] - exact.zeta[q])});
  CHECK(err < 1e-11);
  CHECK(got.Gamma_R == 0.7);
}

TEST_CASE("[steady] the grid study: sequenced Newton gives the direct solve's state, in fewer factorisations",
          "[steady]") {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 1.0 / 20.0, p.omega = 2.0 * 0.3;  // Re 20, α 0.3
  p.n_theta = 64, p.outer_over_a = 20.0;
  SteadyStudyOptions o;
  int calls = 0;
  o.on_iteration = [&calls](int, int, double) { ++calls; };
  const SteadyStudy st = steady_study(p, o);
  INFO(st.message);
  REQUIRE(st.converged);
  REQUIRE(st.levels.size() == 4);
  CHECK(st.levels[0].n_theta == 16);
  CHECK(st.levels[1].n_theta == 32);
  CHECK(st.levels[2].n_theta == 42);
  CHECK(st.levels[3].n_theta == 64);
  // A case grid whose quarter is below kMinStudyTheta: that level is left out.
  NsParams small = p;
  small.n_theta = 32;
  SteadyStudyOptions two;
  two.scales = {0.25, 1.0};
  const SteadyStudy s2 = steady_study(small, two);
  REQUIRE(s2.converged);
  CHECK(s2.levels.size() == 1);
  int residuals = 0;
  for (const SteadyLevel& lv : st.levels) residuals += int(lv.newton.residuals.size());
  CHECK(calls == residuals);
  // The first level by plain Newton (quadratic: r_{k+1} ≤ 10 r_k² once r_k < 1e-2), the others with one
  // or two factorisations from the interpolated coarser state.
  const std::vector<double>& r0 = st.levels[0].newton.residuals;
  CHECK(st.levels[0].newton.chord_steps == 0);
  int quadratic = 0;
  for (size_t k = 0; k + 1 < r0.size(); ++k)
    if (r0[k] < 1e-2 && r0[k + 1] > 1e-13) {
      CHECK(r0[k + 1] <= 10.0 * r0[k] * r0[k]);
      ++quadratic;
    }
  CHECK(quadratic >= 1);
  for (size_t k = 1; k < st.levels.size(); ++k) CHECK(st.levels[k].newton.factorisations <= 2);

  // The direct solve on the finest grid from the potential flow: the same state.
  const PolarGrid g = ns_grid(p);
  const NewtonResult direct = solve_steady(p, potential_guess(p, g));
  REQUIRE(direct.converged);
  double d = 0.0, m = 0.0;
  for (size_t q = 0; q < direct.state.zeta.size(); ++q)
    d = std::max(d, std::fabs(st.state.zeta[q] - direct.state.zeta[q])), m = std::max(m, std::fabs(direct.state.zeta[q]));
  CHECK(d < 1e-9 * m);
  const ViscousForces f = viscous_forces(g, p, 1.0, direct.state);
  CHECK(st.levels.back().C_D == Approx(*f.C_D).epsilon(1e-10));
  CHECK(st.levels.back().C_L == Approx(*f.C_L).epsilon(1e-10));
  // C_D on the last three grids, extrapolated: the correction is the right way (drag rises with resolution).
  REQUIRE(st.C_D);
  CHECK(st.C_D->finest == st.levels.back().C_D);
  CHECK(st.C_D->value > st.C_D->finest);
  CHECK(std::isfinite(st.C_D->error));
  CHECK_FALSE(st.mirror);  // spin: the whole grid

  SteadyStudyOptions bad;
  bad.scales = {0.5, 0.8};
  CHECK_THROWS_AS(steady_study(p, bad), std::invalid_argument);
  bad.scales = {0.6, 0.5, 1.0};
  CHECK_THROWS_AS(steady_study(p, bad), std::invalid_argument);
}

TEST_CASE("[steady] on two cores the last two levels overlap and find the same figures", "[steady]") {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 1.0 / 20.0, p.omega = 2.0 * 0.3;  // Re 20, α 0.3
  p.n_theta = 64, p.outer_over_a = 20.0;
  SteadyStudyOptions o;
  std::vector<int> levels_reported;
  o.on_iteration = [&levels_reported](int level, int, double) { levels_reported.push_back(level); };
  const SteadyStudy both = steady_study(p, o);
  o.overlap = false;
  const SteadyStudy one = steady_study(p, o);
  INFO(both.message << " | " << one.message);
  REQUIRE((both.converged && one.converged));
  REQUIRE(both.levels.size() == 4);
  REQUIRE(one.levels.size() == 4);
  for (size_t k = 0; k < 4; ++k) {
    CHECK(both.levels[k].n_theta == one.levels[k].n_theta);
    CHECK(both.levels[k].C_D == Approx(one.levels[k].C_D).epsilon(1e-9));
    CHECK(both.levels[k].C_L == Approx(one.levels[k].C_L).epsilon(1e-9));
  }
  // With two cores the finest level started from the second, not the third: its first residual is larger.
  if (std::thread::hardware_concurrency() >= 2)
    CHECK(both.levels[3].newton.residuals.front() > one.levels[3].newton.residuals.front());
  else
    CHECK(both.levels[3].newton.residuals == one.levels[3].newton.residuals);
  CHECK(both.levels[2].newton.residuals == one.levels[2].newton.residuals);
  REQUIRE((both.C_D && one.C_D));
  CHECK(both.C_D->value == Approx(one.C_D->value).epsilon(1e-9));
  // Every level reported its residuals, the overlapping ones from two threads.
  for (int level = 0; level < 4; ++level)
    CHECK(std::count(levels_reported.begin(), levels_reported.end(), level) >=
          int(both.levels[size_t(level)].newton.residuals.size()));
}

TEST_CASE("[steady] without spin the study solves the mirror half, and finds the whole grid's figures",
          "[steady]") {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 1.0 / 20.0, p.omega = 0.0;  // Re 20, α 0
  p.n_theta = 64, p.outer_over_a = 20.0;
  SteadyStudyOptions o;
  const SteadyStudy half = steady_study(p, o);
  o.mirror = false;
  const SteadyStudy whole = steady_study(p, o);
  INFO(half.message << " | " << whole.message);
  REQUIRE((half.converged && whole.converged));
  CHECK(half.mirror);
  CHECK_FALSE(whole.mirror);
  CHECK(half.message.find("mirror-symmetric half") != std::string::npos);
  REQUIRE(half.levels.size() == whole.levels.size());
  for (size_t k = 0; k < half.levels.size(); ++k) {
    CHECK(half.levels[k].C_D == Approx(whole.levels[k].C_D).epsilon(1e-10));
    CHECK(half.levels[k].recirculation == Approx(whole.levels[k].recirculation).epsilon(1e-8));
    CHECK(std::fabs(half.levels[k].C_L) < 1e-12);
  }
  REQUIRE((half.C_D && whole.C_D));
  CHECK(half.C_D->value == Approx(whole.C_D->value).epsilon(1e-9));
}
