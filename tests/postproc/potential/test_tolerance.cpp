#include <catch2/catch.hpp>

#include "io/case_file.hpp"
#include "postproc/potential/tolerance.hpp"
#include "support.hpp"

using namespace magnus;

namespace {
/// The scene keys a case file requires.
const std::string scene = "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n";
}  // namespace

TEST_CASE("grid.tolerance: the chosen grid meets the requested lift error, and the estimate is honest",
          "[app][tolerance]") {
  const double tol = GENERATE(1e-4, 1e-6, 1e-8, 1e-10);
  const double alpha = GENERATE(0.5, 3.0);
  Case c = test::make_case(alpha, 256);
  c.grid.tolerance = tol;
  const FlowResult r = run_case(c);
  CAPTURE(tol, alpha, r.grid.n_theta, r.errors.cl_rel, r.info.estimated_cl_rel);
  REQUIRE(*r.errors.cl_rel <= tol);
  REQUIRE(r.info.estimated_cl_rel <= tol);
  // The a-posteriori estimate is within a factor 3 of the true error.
  REQUIRE(r.info.estimated_cl_rel <= 3 * *r.errors.cl_rel);
  REQUIRE(r.info.estimated_cl_rel >= *r.errors.cl_rel / 3);
  // The result records what ran: the chosen stencil and grid.
  REQUIRE(r.c.solver.stencil == StencilKind::nine_point);
  REQUIRE(r.c.grid.n_theta == r.grid.n_theta);
  REQUIRE(r.info.grid_choice.find("9-point") != std::string::npos);
  // Smallest: a grid with half the points would not meet the tolerance.
  Case half = c;
  half.grid.tolerance = 0;
  half.solver.stencil = StencilKind::nine_point;
  half.grid.n_theta = std::max(8, (r.grid.n_theta / 2) / 2 * 2);
  if (half.grid.n_theta < r.grid.n_theta) REQUIRE(*run_case(half).errors.cl_rel > tol);
}

TEST_CASE("grid.tolerance: impossible or conflicting requests fail with one line naming the key",
          "[app][tolerance]") {
  using Catch::Contains;
  Case c = test::make_case(1.0, 64);
  c.grid.tolerance = 1e-6;
  c.grid.far_field = FarField::freestream;
  REQUIRE_THROWS_WITH(choose_grid(c), Contains("grid.tolerance") && Contains("freestream"));
  c.grid.far_field = FarField::exact;
  c.grid.tolerance = 1e-14;
  REQUIRE_THROWS_WITH(choose_grid(c), Contains("grid.tolerance") && Contains("round-off"));
  c.grid.tolerance = 1e-6;
  c.scene.speed = 0.0;
  REQUIRE_THROWS_WITH(choose_grid(c), Contains("grid.tolerance") && Contains("U = 0"));
  REQUIRE_THROWS_WITH(parse_case(scene + "[grid]\ntolerance = 1e-8\nn_theta = 64\n", "t.toml"),
                      Contains("grid.tolerance") && Contains("grid.n_theta"));
  REQUIRE_THROWS_WITH(
      parse_case(scene + "[grid]\ntolerance = 1e-8\n[solver]\nstencil = \"5-point\"\n", "t.toml"),
      Contains("solver.stencil"));
  // The resolved case of a tolerance run can be run again: the chosen grid is not written into it.
  Case t = test::make_case(1.0, 64);
  t.grid.tolerance = 1e-8;
  const Case back = parse_case(to_toml(t), "resolved.toml");
  REQUIRE(back.grid.tolerance == 1e-8);
  // On the command line a tolerance supersedes the file's grid.
  const Case d = parse_case(scene + "[grid]\nn_theta = 64\n", "t.toml", {"grid.tolerance=1e-8"});
  REQUIRE(d.grid.tolerance == 1e-8);
}

TEST_CASE("grid.tolerance chooses the spacing too: geometric unless grid.spacing is stated",
          "[app][tolerance]") {
  Case c = test::make_case(1.0, 64, Spacing::uniform);
  c.grid.tolerance = 1e-6;
  const GridChoice g = choose_grid(c);  // uniform by default only, not stated: the search takes geometric
  CHECK(g.spacing == Spacing::geometric);
  CHECK(g.stencil == StencilKind::nine_point);
  CHECK(run_case(c).grid.spacing == Spacing::geometric);
  // Stated uniform is kept, and a grid beyond the limit is refused with its size and the alternative.
  c.grid.spacing_given = true;
  REQUIRE_THROWS_WITH(choose_grid(c),
                      "grid.tolerance = 1e-06 with grid.spacing = \"uniform\" needs about n_θ × n_r = "
                      "3136 × 9484 (2.97e+07 nodes, 226.9 MiB per field), more than the limit of "
                      "4194304 nodes; grid.spacing = \"geometric\" (9-point stencil, order 6) meets it "
                      "with 32 × 17");
  c.grid.tolerance = 1e-3;  // a tolerance a uniform grid meets within the limit: the stated spacing is kept
  CHECK(choose_grid(c).spacing == Spacing::uniform);
}

TEST_CASE("grid.tolerance: every grid the search tries passes the memory guard", "[app][tolerance]") {
  Case c = test::make_case(1.0, 64);
  c.grid.tolerance = 1e-8;
  REQUIRE_THROWS_WITH(choose_grid(c, 1, 4096),
                      Catch::Contains("needs about") && Catch::Contains("--max-memory 4 KiB"));
  RunHooks limit;
  limit.max_bytes = 4096;
  REQUIRE_THROWS_WITH(run_case(c, limit), Catch::Contains("--max-memory 4 KiB"));
  REQUIRE(choose_grid(c, 1, size_t(1) << 30).n_theta > 0);
}
