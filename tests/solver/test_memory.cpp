#include <catch2/catch.hpp>

#include "solver/flow_solver.hpp"
#include "solver/memory.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("sizes parse and print", "[solver][memory]") {
  REQUIRE(parse_bytes("2G") == 2ull << 30);
  REQUIRE(parse_bytes("512M") == 512ull << 20);
  REQUIRE(parse_bytes("1.5GiB") == 3ull << 29);
  REQUIRE(parse_bytes("1000") == 1000);
  REQUIRE_THROWS(parse_bytes("lots"));
  REQUIRE_THROWS(parse_bytes("2X"));
  REQUIRE_THROWS(parse_bytes("-1G"));
  REQUIRE(format_bytes(3ull << 29) == "1.50 GiB");
  REQUIRE(available_bytes() > (64ull << 20));
}

TEST_CASE("memory guard: a run above the limit is refused before it allocates, naming the estimate", "[solver][memory]") {
  Case c = test::make_case(1.0, 512, Spacing::geometric, FarField::exact, StencilKind::five_point, Method::cholmod);
  REQUIRE_THROWS_WITH(run_case(c, 1, 1 << 20), Catch::Contains("cholmod") && Catch::Contains("needs about") &&
                                                   Catch::Contains("--max-memory 1.0 MiB"));
  c.solver.method = Method::fft;
  REQUIRE_THROWS_WITH(run_case(c, 1, 1 << 20), Catch::Contains("fft") && Catch::Contains("needs about"));
  // CHOLMOD's own check after the symbolic analysis: the exact fill, refused before the numeric factor.
  const PolarGrid g = make_grid(c.grid, c.scene.radius);
  const DiscreteOperator op = make_operator(g, StencilKind::five_point, FarField::exact);
  REQUIRE_THROWS_WITH(make_cholmod_solver(g, op, 1 << 20), Catch::Contains("cholmod factor"));
  REQUIRE_NOTHROW(make_cholmod_solver(g, op, 1ull << 32));
}

TEST_CASE("memory estimates bound the CHOLMOD factor the analysis finds", "[solver][memory]") {
  // The estimate must not be below what the factor needs: refuse too little rather than too much.
  for (int n : {64, 256}) {
    const PolarGrid g = make_grid(0.1, 20.0, default_n_r(Spacing::geometric, 20.0, n), n, Spacing::geometric);
    const DiscreteOperator op = make_operator(g, StencilKind::five_point, FarField::exact);
    const size_t estimate = solver_bytes(op, Method::cholmod);
    REQUIRE_NOTHROW(make_cholmod_solver(g, op, estimate));
    REQUIRE(solver_bytes(op, Method::fft) < estimate);
  }
}

TEST_CASE("memory guard: the grid's shape alone, before anything is built, on every path that solves", "[solver][memory]") {
  Case c = test::make_case(1.0, 256);
  c.grid.spacing = Spacing::uniform;
  c.grid.outer_radius = 1e12;  // 4e13 rings: more than an int, refused from the shape
  const GridShape s = grid_shape(c.grid);
  REQUIRE(s.n_r > (1L << 40));
  REQUIRE_THROWS_WITH(run_case(c), Catch::Contains("needs about") && Catch::Contains("GiB"));
  c = test::make_case(1.0, 65536);  // 65536 × 31249: about 90 GiB for the FFT path
  REQUIRE_THROWS_WITH(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 0, 0), Catch::Contains("fft solve on 65536"));
  c.grid.tolerance = 1e-8;
  c.grid.n_theta = 256;
  REQUIRE_NOTHROW(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 9, 0));
}
