#include <catch2/catch.hpp>
#include <cmath>

#include "physics/exact.hpp"
#include "postproc/derived.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::make_case;

namespace {

/// A result with the exact surface flow of a case: its forces without a solve.
FlowResult exact_result(const Case& c) {
  FlowResult r;
  r.c = c;
  r.grid = make_grid(c.scene.radius, 20.0, 10, c.grid.n_theta, Spacing::geometric);
  const ExactFlow ex = exact_flow(c.scene);
  std::vector<double> u;
  for (double th : r.grid.theta) u.push_back(ex.u_theta(c.scene.radius, th));
  r.forces = compute_forces(c.scene, surface_from_u_theta(r.grid, c.scene, u));
  return r;
}

}  // namespace

TEST_CASE("derived ratios follow their formulas: KJ/seed = π/2 and ΔP/seed = 2 with the spin model",
          "[postproc]") {
  const double alpha = GENERATE(-1.5, 0.5, 1.0, 3.0);
  const FlowResult r = exact_result(make_case(alpha, 32));
  const Scene& sc = r.c.scene;
  const Forces& f = r.forces;
  const DerivedRatios d = derived_ratios(r);
  CHECK_FALSE(d.alpha_Gamma);  // the spin model: α_Γ is α itself and not shown
  REQUIRE(d.kj_over_seed);
  CHECK(*d.kj_over_seed == *f.cl_kutta_joukowski / *f.cl_seed_estimate);
  CHECK(*d.kj_over_seed == Approx(M_PI / 2).epsilon(1e-14));
  REQUIRE(d.cl_over_kj_minus_1);
  CHECK(*d.cl_over_kj_minus_1 == *f.cl / *f.cl_kutta_joukowski - 1.0);
  CHECK(std::fabs(*d.cl_over_kj_minus_1) < 1e-12);  // the exact surface flow gives Kutta–Joukowski
  REQUIRE(d.delta_p_over_seed);
  CHECK(*d.delta_p_over_seed == f.delta_p_top_bottom / f.delta_p_seed_estimate);
  CHECK(*d.delta_p_over_seed == Approx(2.0).epsilon(1e-12));  // potential flow: 2U at the shoulders
  CHECK(d.magnus_S_seed == 4.0 * sc.density * sc.radius * sc.radius);
}

TEST_CASE("derived ratios: α_Γ = Γ/(2πaU) with a given Γ, undefined ratios without spin or circulation",
          "[postproc]") {
  Case c = make_case(0.0, 32);
  DerivedRatios d = derived_ratios(exact_result(c));
  CHECK_FALSE(d.cl_over_kj_minus_1);  // Γ = 0: C_L,KJ = 0
  CHECK_FALSE(d.kj_over_seed);        // ω = 0
  CHECK_FALSE(d.delta_p_over_seed);
  c.scene.circulation_given = true;
  c.scene.circulation_value = 3.0;
  d = derived_ratios(exact_result(c));
  REQUIRE(d.alpha_Gamma);
  CHECK(*d.alpha_Gamma == 3.0 / (2.0 * M_PI * c.scene.radius * c.scene.speed));
  CHECK_FALSE(d.kj_over_seed);  // a given Γ without spin: the seed says nothing
  REQUIRE(d.cl_over_kj_minus_1);
  c.scene.speed = 0.0;
  CHECK_FALSE(derived_ratios(exact_result(c)).alpha_Gamma);  // U = 0
}

TEST_CASE("the ideal lift −2πα, its share, and the potential vortex's torque −4πρνa²ω", "[postproc]") {
  CHECK(cl_ideal(0.5) == -M_PI);
  CHECK(*share_of_ideal_lift(-M_PI, 0.5) == 1.0);
  CHECK(*share_of_ideal_lift(-0.5 * M_PI, 0.5) == 0.5);
  CHECK_FALSE(share_of_ideal_lift(1.0, 0.0));
  Scene sc;
  sc.radius = 0.5;
  sc.density = 2.0;
  sc.spin = 3.0;
  CHECK(torque_potential_vortex(sc, 0.01) == Approx(-4.0 * M_PI * 2.0 * 0.01 * 0.25 * 3.0).epsilon(1e-15));
}

TEST_CASE("viscous ratios: t and Δt over D/U, the mode's St = |Im λ|/(2π), the vortex torque's ratio",
          "[postproc]") {
  FlowResult r;
  r.c = make_case(1.0, 32);
  r.viscous = ViscousPart{};
  ViscousPart& v = *r.viscous;
  v.time_unit = 0.02;
  v.t = 3.0;
  v.dt = 0.001;
  v.eigenvalue_imag = -0.5;
  v.steps = 300;
  v.steps_resumed = 100;
  r.timing.solve_s = 4.0;
  ViscousRatios d = viscous_ratios(r);
  CHECK(*d.t_convective == 3.0 / 0.02);
  CHECK(*d.dt_convective == 0.001 / 0.02);
  CHECK(*d.eigen_strouhal == 0.5 / (2.0 * M_PI));
  CHECK(*d.steps_per_second == 50.0);
  CHECK_FALSE(d.wall_cells);               // no Re
  CHECK_FALSE(d.torque_potential_vortex);  // U > 0
  r.c.scene.speed = 0.0;                   // still fluid: no St, the potential vortex's torque
  r.c.scene.spin = 2.0;
  v.viscosity = 1e-6;
  v.torque_mean = 1.5 * torque_potential_vortex(r.c.scene, 1e-6);
  d = viscous_ratios(r);
  CHECK_FALSE(d.eigen_strouhal);
  CHECK(*d.torque_potential_vortex == torque_potential_vortex(r.c.scene, 1e-6));
  CHECK(*d.torque_over_potential_vortex_minus_1 == Approx(0.5).epsilon(1e-14));
}
