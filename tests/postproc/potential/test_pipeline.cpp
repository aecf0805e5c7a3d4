// The chain written once: run, sweep, bench and the tolerance search all go through discretize(), so on
// the same grid they report the same lift to round-off, and the memory guard stops each of them.
#include <catch2/catch.hpp>

#include "postproc/potential/bench.hpp"
#include "postproc/potential/pipeline.hpp"
#include "postproc/potential/sweep.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("pipeline: run, sweep, bench and the tolerance's lift agree on one grid", "[postproc][pipeline]") {
  for (StencilKind stencil : {StencilKind::five_point, StencilKind::nine_point})
    for (Method method : {Method::fft, Method::cholmod}) {
      CAPTURE(to_string(stencil), to_string(method));
      const Case c = test::make_case(1.5, 64, Spacing::geometric, FarField::exact, stencil, method);
      const double cl_run = *run_case(c).forces.cl;
      const double cl_lift = *lift_coefficient(c);
      const double cl_sweep = *sweep_spin_ratio(c, {1.5}).points[0].forces.cl;
      BenchOptions opt;
      opt.ladder = {64};
      opt.methods = {method};
      opt.stencils = {stencil};
      opt.repeats = 1;
      const BenchRow row = run_bench(c, opt).at(0);
      const double cl_exact = -2 * M_PI * 1.5;
      REQUIRE(cl_lift == Approx(cl_run).epsilon(1e-12));
      REQUIRE(cl_sweep == Approx(cl_run).epsilon(1e-12));
      REQUIRE(row.cl_rel == Approx(std::fabs(cl_run / cl_exact - 1)).margin(1e-12));
      // …and the lift is right: within the scheme's error on this grid, not merely consistent.
      REQUIRE(std::fabs(cl_run / cl_exact - 1) < (stencil == StencilKind::nine_point ? 1e-8 : 5e-3));
    }
}

TEST_CASE("pipeline: discretize builds the requested grid and method, resolving auto to FFT",
          "[postproc][pipeline]") {
  Case c = test::make_case(1.0, 32);
  c.solver.method = Method::automatic;
  const Discretization d = discretize(c);
  REQUIRE(d.grid.n_theta == 32);
  REQUIRE(d.grid.n_r == grid_shape(c.grid).n_r);
  REQUIRE(d.grid.r.front() == c.scene.radius);
  REQUIRE(d.solver->method() == Method::fft);
  c.solver.method = Method::cholmod;
  REQUIRE(discretize(c).solver->method() == Method::cholmod);
}

TEST_CASE("pipeline: a run above an explicit memory limit is refused before it allocates",
          "[postproc][pipeline][memory]") {
  Case c = test::make_case(1.0, 512, Spacing::geometric, FarField::exact, StencilKind::five_point,
                           Method::cholmod);
  RunHooks limit;
  limit.max_bytes = 1 << 20;
  REQUIRE_THROWS_WITH(run_case(c, limit), Catch::Contains("cholmod") && Catch::Contains("needs about") &&
                                              Catch::Contains("--max-memory 1.0 MiB"));
  c.solver.method = Method::fft;
  REQUIRE_THROWS_WITH(run_case(c, limit), Catch::Contains("fft") && Catch::Contains("needs about"));
  REQUIRE_THROWS_WITH(discretize(c, 1, 1 << 20), Catch::Contains("needs about"));
  REQUIRE_NOTHROW(discretize(c, 1, 1ull << 32));
}
