// Round-off where it bites: at large α (or U → 0) the lift is a small antisymmetric part of a large
// pressure. The naive form −Σ p sinθ a Δθ, p = p∞ + ½ρ(U² − u_θ²), on a single solve loses ε·(p∞/(ρU²α) + α)
// relative; the forces magnus reports (the split ū + u' from the superposition basis) lose nothing
// α-dependent.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "postproc/potential/forces.hpp"
#include "solver/potential/flow_solver.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// Lift per span the naive way: one solve for (U, Γ), u_θ from it, p with p∞, F_y = −Σ p sinθ a Δθ.
double naive_lift(const Case& c) {
  const PolarGrid g = make_grid(c.grid, c.scene.radius);
  const DiscreteOperator op = make_operator(g, c.solver.stencil, c.grid.far_field);
  const auto psi = make_solver(g, op, c.solver.method)->solve(c.scene.speed, c.scene.Gamma());
  const std::vector<double> u = surface_u_theta(g, psi, derivative_order(c.solver.stencil));
  double fy = 0.0;
  for (int j = 0; j < g.n_theta; ++j) {
    const double p =
        c.scene.pressure_inf + 0.5 * c.scene.density * (c.scene.speed * c.scene.speed - u[j] * u[j]);
    fy -= p * std::sin(g.theta[j]) * c.scene.radius * g.d_theta;
  }
  return fy;
}

}  // namespace

TEST_CASE("round-off: the reported lift keeps its accuracy at large α and tiny U, the naive form does not",
          "[postproc][roundoff]") {
  struct Hard {
    const char* label;
    double alpha, speed, p_inf;
  };
  const Hard cases[] = {{"alpha = 1, p_inf = 1e5", 1.0, 10.0, 1e5},
                        {"alpha = 1e4", 1e4, 10.0, 1e5},
                        {"alpha = 1e8", 1e8, 10.0, 1e5},
                        {"U = 1e-6 (alpha = 1e7)", 0.0, 1e-6, 1e5},
                        {"U = 1e-12 (alpha = 1e13)", 0.0, 1e-12, 1e5}};
  const auto stencil = GENERATE(StencilKind::five_point, StencilKind::nine_point);
  // The discretization error alone, at α = 1 with no p∞: the floor both forms share.
  const FlowResult ref = run_case(test::make_case(1.0, 64, Spacing::geometric, FarField::exact, stencil));
  std::printf("\n%s: %-28s %14s %14s\n", to_string(stencil), "case", "naive C_L rel", "magnus C_L rel");
  for (const Hard& h : cases) {
    Case c = test::make_case(1.0, 64, Spacing::geometric, FarField::exact, stencil);
    c.scene.speed = h.speed;
    c.scene.spin = h.alpha > 0 ? h.alpha * h.speed / c.scene.radius : 100.0;
    c.scene.pressure_inf = h.p_inf;
    const FlowResult r = run_case(c);
    const double kj = r.forces.lift_kutta_joukowski;
    const double naive = std::fabs(naive_lift(c) / kj - 1), stable = *r.errors.cl_rel;
    std::printf("%s: %-28s %14.3e %14.3e\n", to_string(stencil), h.label, naive, stable);
    CAPTURE(h.label, naive, stable, ref.errors.cl_rel);
    // magnus: the α = 1 discretization error, to a few ε.
    REQUIRE(std::fabs(stable - *ref.errors.cl_rel) <= 1e-12 + 1e-6 * *ref.errors.cl_rel);
  }
  // The loss is real: at U = 1e-12 the naive lift has no correct digit.
  Case c = test::make_case(1.0, 64, Spacing::geometric, FarField::exact, stencil);
  c.scene.speed = 1e-12;
  c.scene.pressure_inf = 1e5;
  REQUIRE(std::fabs(naive_lift(c) / (-c.scene.density * c.scene.speed * c.scene.Gamma()) - 1) > 0.1);
}
