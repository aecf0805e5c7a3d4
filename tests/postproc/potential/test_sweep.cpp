// Sweeps by superposition: one run per point to 1e-12, two solves per sweep, the refusals.
#include <hdf5.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "postproc/potential/sweep.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {

/// |a − b| relative to max(|a|, |b|, floor): the floor keeps values near zero (α = 0) meaningful.
double rel_diff(double a, double b, double floor) {
  return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), floor});
}

}  // namespace

TEST_CASE("a sweep equals one run per point to 1e-12, with two linear solves in all", "[app][sweep]") {
  struct Setup {
    const char* what;
    Case c;
  };
  std::vector<Setup> setups = {
      {"fft, 5-point, exact far field", test::make_case(1.0, 64)},
      {"cholmod, 9-point, freestream far field",
       test::make_case(1.0, 64, Spacing::geometric, FarField::freestream, StencilKind::nine_point,
                       Method::cholmod)},
      {"uniform spacing", test::make_case(1.0, 48, Spacing::uniform, FarField::exact, StencilKind::five_point,
                                          Method::cholmod, 8.0)},
  };
  const std::vector<double> alphas = {0.0, 0.5, 1.0, 1.9, 2.0, 2.5, 4.0, -1.5};
  for (const auto& s : setups) {
    SECTION(s.what) {
      const SweepResult sw = sweep_spin_ratio(s.c, alphas);
      REQUIRE(sw.linear_solves == 2);
      REQUIRE(sw.points.size() == alphas.size());
      for (size_t k = 0; k < alphas.size(); ++k) {
        Case c = s.c;
        c.scene.spin = alphas[k] * c.scene.speed / c.scene.radius;
        const FlowResult r = run_case(c);
        const SweepPoint& p = sw.points[k];
        CAPTURE(alphas[k]);
        REQUIRE(p.scene.spin_ratio() == Approx(alphas[k]).epsilon(1e-15));
        const double q =
            0.5 * c.scene.density * c.scene.speed * c.scene.speed;  // dynamic pressure, the scale of ΔP
        CHECK(rel_diff(*p.forces.cl, *r.forces.cl, 1.0) <= 1e-12);
        CHECK(rel_diff(p.forces.lift, r.forces.lift, q * 2 * c.scene.radius) <= 1e-12);
        CHECK(rel_diff(p.forces.delta_p_top_bottom, r.forces.delta_p_top_bottom, q) <= 1e-12);
        CHECK(*p.forces.cl_kutta_joukowski == Approx(-2 * M_PI * alphas[k]).margin(1e-14));
        CHECK(*p.forces.cl_seed_estimate == Approx(-4 * alphas[k]).margin(1e-14));
        REQUIRE(p.stagnation.size() == r.stagnation.size());
        for (size_t j = 0; j < p.stagnation.size(); ++j) {
          CHECK(p.stagnation[j].on_surface == r.stagnation[j].on_surface);
          CHECK(p.stagnation[j].theta == Approx(r.stagnation[j].theta).margin(1e-10));
          CHECK(p.stagnation[j].r == Approx(r.stagnation[j].r).epsilon(1e-10));
        }
      }
    }
  }
  SECTION("circulation sweep (model \"given\")") {
    Case c = test::make_case(1.0, 64);
    c.scene.circulation_given = true;
    const std::vector<double> gammas = {-2.0, 0.0, 1.5, 20.0};
    const SweepResult sw = sweep_circulation(c, gammas);
    REQUIRE(sw.linear_solves == 2);
    for (size_t k = 0; k < gammas.size(); ++k) {
      Case ck = c;
      ck.scene.circulation_value = gammas[k];
      const FlowResult r = run_case(ck);
      CAPTURE(gammas[k]);
      CHECK(sw.points[k].scene.Gamma() == gammas[k]);
      CHECK(rel_diff(*sw.points[k].forces.cl, *r.forces.cl, 1.0) <= 1e-12);
      CHECK(rel_diff(sw.points[k].forces.delta_p_top_bottom, r.forces.delta_p_top_bottom, 61.25) <= 1e-12);
      // The α column of a circulation sweep is the equivalent spin ratio Γ/(2πaU).
      CHECK(sweep_row(sw, sw.points[k]).alpha ==
            Approx(gammas[k] / (2 * M_PI * c.scene.radius * c.scene.speed)));
    }
  }
}

TEST_CASE("two solves however many points, U = 0 and the wrong circulation model are refused",
          "[app][sweep]") {
  const Case c = test::make_case(1.0, 32);
  std::vector<double> many;
  for (int k = 0; k <= 2000; ++k) many.push_back(-5.0 + 0.005 * k);
  for (int threads : {1, 3}) {
    const SweepResult s = sweep_spin_ratio(c, many, threads);
    REQUIRE(s.linear_solves == 2);
    REQUIRE(s.points.size() == many.size());
    CHECK(s.points[1000].scene.spin_ratio() == Approx(0.0).margin(1e-12));
    CHECK(*s.points.back().forces.cl == Approx(-2 * M_PI * 5.0).epsilon(1e-2));
  }
  Case still = c;
  still.scene.speed = 0.0;
  REQUIRE_THROWS_AS(sweep_spin_ratio(still, {1.0}), std::invalid_argument);
  Case given = c;
  given.scene.circulation_given = true;
  REQUIRE_THROWS_AS(sweep_spin_ratio(given, {1.0}), std::invalid_argument);
  REQUIRE_THROWS_AS(sweep_circulation(c, {1.0}), std::invalid_argument);
  given.scene.speed = 0.0;
  REQUIRE_THROWS_AS(sweep_circulation(given, {1.0}), std::invalid_argument);
}
