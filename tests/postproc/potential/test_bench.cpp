// magnus bench: the ladder's rows, its observed orders and its CSV (no timing is asserted: the figures
// in the README come from the command itself).
#include <catch2/catch.hpp>
#include <sstream>

#include "io/bench_table.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("bench: every rung of the ladder, errors against exact, observed orders 2 and 6", "[app][bench]") {
  BenchOptions opt;
  opt.ladder = {32, 64, 128};
  opt.repeats = 1;
  Case c = test::make_case(1.0, 64);
  const auto rows = run_bench(c, opt);
  REQUIRE(rows.size() == 2 * 2 * 3);
  for (const auto& r : rows) {
    CAPTURE(r.method, r.stencil, r.n_theta);
    REQUIRE(r.unknowns > 0);
    REQUIRE(r.total_s > 0);
    REQUIRE(r.total_s == Approx(r.setup_s + r.factor_s + r.solve_s + r.post_s));
    REQUIRE(r.cl_rel > 0);
    if (r.n_theta == 32) {
      REQUIRE(std::isnan(r.order_cl));
    } else {
      const double p = r.stencil == "9-point" ? 6.0 : 2.0;
      REQUIRE(r.order_cl == Approx(p).margin(0.15));
      REQUIRE(r.order_psi == Approx(p).margin(0.15));
    }
  }
  // Both solvers: the same errors on the same grid.
  REQUIRE(rows[0].cl_rel == Approx(rows[6].cl_rel).epsilon(1e-9));
  std::istringstream csv(bench_csv(rows));
  std::string line;
  int n = 0;
  while (std::getline(csv, line)) ++n;
  REQUIRE(n == 1 + int(rows.size()));
  REQUIRE(bench_table(rows).find("p C_L") != std::string::npos);
}

TEST_CASE("bench: uniform spacing skips the 9-point stencil, CHOLMOD rungs above the cap are skipped",
          "[app][bench]") {
  BenchOptions opt;
  opt.ladder = {16, 32};
  opt.repeats = 1;
  opt.cholmod_max_unknowns = 200;
  Case c = test::make_case(1.0, 16);
  c.grid.spacing = Spacing::uniform;
  const auto rows = run_bench(c, opt);
  for (const auto& r : rows) {
    REQUIRE(r.stencil == "5-point");
    if (r.method == "cholmod") REQUIRE(r.unknowns <= 200);
  }
}
