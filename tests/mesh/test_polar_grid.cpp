#include <catch2/catch.hpp>
#include <cmath>

#include "mesh/polar_grid.hpp"

using namespace magnus;

TEST_CASE("geometric grid: r_i = a e^{iΔξ}, ends at a and R, no duplicated seam", "[mesh]") {
  const PolarGrid g = make_grid(0.1, 20.0, 50, 64, Spacing::geometric);
  REQUIRE(g.r.front() == 0.1);
  REQUIRE(g.r.back() == Approx(2.0).epsilon(1e-15));
  const double dxi = std::log(20.0) / 49;
  for (int i = 0; i + 1 < g.n_r; ++i) {
    REQUIRE(g.d_xi(i) == Approx(dxi).epsilon(1e-12));
    REQUIRE(g.r[i + 1] / g.r[i] == Approx(std::exp(dxi)).epsilon(1e-12));
  }
  REQUIRE(g.theta.size() == 64);
  REQUIRE(g.theta.front() == 0.0);
  REQUIRE(g.theta.back() == Approx(2 * M_PI * 63 / 64));
  REQUIRE(g.d_theta == Approx(2 * M_PI / 64));
}

TEST_CASE("uniform grid: r_i = a + iΔr, ξ = ln(r/a)", "[mesh]") {
  const PolarGrid g = make_grid(2.0, 5.0, 9, 16, Spacing::uniform);
  for (int i = 0; i < g.n_r; ++i) {
    REQUIRE(g.r[i] == Approx(2.0 + i * 1.0));
    REQUIRE(g.xi[i] == Approx(std::log(g.r[i] / 2.0)).margin(1e-15));
  }
  REQUIRE_FALSE(g.uniform_in_xi());
}

TEST_CASE("default n_r makes log-polar cells square", "[mesh]") {
  const int n_theta = GENERATE(64, 256, 1024);
  const double R = GENERATE(2.0, 20.0, 1000.0);
  const int n_r = default_n_r(Spacing::geometric, R, n_theta);
  const PolarGrid g = make_grid(1.0, R, n_r, n_theta, Spacing::geometric);
  const double aspect = g.d_xi(0) / g.d_theta;
  REQUIRE(aspect > 0.9);
  REQUIRE(aspect < 1.1);
  // Uniform spacing: square cells at the wall, Δr ≈ aΔθ.
  const int n_u = default_n_r(Spacing::uniform, R, n_theta);
  const PolarGrid gu = make_grid(1.0, R, n_u, n_theta, Spacing::uniform);
  REQUIRE((gu.r[1] - gu.r[0]) / gu.d_theta == Approx(1.0).epsilon(0.1));
}

TEST_CASE("grid from a case uses the case's parameters", "[mesh]") {
  Case c;
  c.scene.radius = 0.5;
  c.grid.outer_radius = 10.0;
  c.grid.n_theta = 32;
  c.grid.n_r = 7;
  c.grid.spacing = Spacing::uniform;
  const PolarGrid g = make_grid(c.grid, c.scene.radius);
  REQUIRE(g.n_r == 7);
  REQUIRE(g.n_theta == 32);
  REQUIRE(g.r.back() == Approx(5.0));
  REQUIRE_THROWS(make_grid(0.0, 10.0, 7, 32, Spacing::uniform));
  REQUIRE_THROWS(make_grid(1.0, 1.0, 7, 32, Spacing::uniform));
}

TEST_CASE("a geometric case grid has exactly square cells and covers the R asked for", "[mesh]") {
  Case c;
  c.grid.outer_radius = GENERATE(1.5, 20.0, 1e4);
  c.grid.n_theta = GENERATE(8, 100, 256);
  const PolarGrid g = make_grid(c.grid, c.scene.radius);
  REQUIRE(g.outer_radius() / g.a >= c.grid.outer_radius * (1 - 1e-12));
  // At most one cell more than asked, and never fewer than two cells.
  const double largest = std::max(c.grid.outer_radius * std::exp(g.d_theta), std::exp(2 * g.d_theta));
  REQUIRE(g.outer_radius() / g.a < largest * (1 + 1e-12));
  for (int i = 0; i + 1 < g.n_r; ++i) REQUIRE(g.d_xi(i) == Approx(g.d_theta).epsilon(1e-12));
}
