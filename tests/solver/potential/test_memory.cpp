#include <catch2/catch.hpp>

#include <limits>

#include "mesh/polar_grid.hpp"
#include "solver/potential/cholmod_solver.hpp"
#include "solver/potential/flow_solver.hpp"
#include "solver/potential/memory.hpp"
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
  // Beyond size_t: the largest size (no limit in practice), not an out-of-range conversion.
  REQUIRE(parse_bytes("1e300G") == std::numeric_limits<size_t>::max());
  REQUIRE(parse_bytes("1e30") == std::numeric_limits<size_t>::max());
  REQUIRE(format_bytes(3ull << 29) == "1.50 GiB");
  REQUIRE(available_bytes() > (64ull << 20));
}

TEST_CASE("memory guard: a grid above an explicit limit is refused before anything is built",
          "[solver][memory]") {
  Case c = test::make_case(1.0, 512, Spacing::geometric, FarField::exact, StencilKind::five_point,
                           Method::cholmod);
  const size_t MiB = 1 << 20;
  REQUIRE_THROWS_WITH(check_grid_memory(c.grid, c.solver.stencil, Method::cholmod, 0, MiB),
                      Catch::Contains("cholmod") && Catch::Contains("needs about") &&
                          Catch::Contains("--max-memory 1.0 MiB"));
  REQUIRE_THROWS_WITH(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 0, MiB),
                      Catch::Contains("fft") && Catch::Contains("needs about"));
  // The same grid passes a limit above its estimate: the refusal is the limit, not the grid.
  const size_t fft_estimate =
      solver_bytes(double(grid_shape(c.grid).n_r), 512, c.grid.far_field, c.solver.stencil, Method::fft);
  REQUIRE_NOTHROW(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 0, 2 * fft_estimate + (64 * MiB)));
  // CHOLMOD's own check after the symbolic analysis: the exact fill, refused before the numeric factor.
  const PolarGrid g = make_grid(c.grid, c.scene.radius);
  const DiscreteOperator op = make_operator(g, StencilKind::five_point, FarField::exact);
  REQUIRE_THROWS_WITH(make_cholmod_solver(g, op, MiB), Catch::Contains("cholmod factor"));
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

TEST_CASE("memory guard: the grid's shape alone, against an explicit limit", "[solver][memory]") {
  const size_t limit = 16ull << 30;  // 16 GiB, whatever the host has free
  Case c = test::make_case(1.0, 256);
  c.grid.spacing = Spacing::uniform;
  c.grid.outer_radius = 1e12;  // 4e13 rings: more than an int, refused from the shape
  const GridShape s = grid_shape(c.grid);
  REQUIRE(s.n_r > (1L << 40));
  REQUIRE_THROWS_WITH(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 0, limit),
                      Catch::Contains("needs about") && Catch::Contains("GiB"));
  c = test::make_case(1.0, 65536);  // 65536 × 31249: about 90 GiB for the FFT path
  REQUIRE_THROWS_WITH(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 0, limit),
                      Catch::Contains("fft solve on 65536"));
  c.grid.n_theta = 256;  // 256 × 123 with 9 fields: a few MiB
  REQUIRE_NOTHROW(check_grid_memory(c.grid, c.solver.stencil, Method::fft, 9, limit));
}
