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

TEST_CASE("stretched grid: wall refinement 1 is the uniform grid to the last bit", "[mesh]") {
  const double d_far = 2.0 * M_PI / 192 / (5.0 / 3.0);
  // n_r = 0: the fewest rings with Δξ ≤ d_far (R kept), as the navier-stokes grid has always had.
  const PolarGrid s = make_stretched_grid(0.5, 100.0, 0, 192, d_far, 1.0, 0.1);
  const PolarGrid u = make_grid(0.5, 100.0, int(std::ceil(std::log(100.0) / d_far - 1e-9)) + 1, 192,
                                Spacing::geometric);
  REQUIRE(s.n_r == 236);
  REQUIRE(s.uniform_in_xi());
  REQUIRE(s.xi == u.xi);
  REQUIRE(s.r == u.r);
  const PolarGrid s2 = make_stretched_grid(0.5, 20.0, 40, 64, 0.0, 1.0, 0.3);
  REQUIRE(s2.xi == make_grid(0.5, 20.0, 40, 64, Spacing::geometric).xi);
}

TEST_CASE("stretched grid: the wall spacing is Δ_f/q, it ends at R and grows smoothly", "[mesh]") {
  const double span = std::log(20.0), d_theta = 2.0 * M_PI / 64, q = 4.0;
  // The map ξ(s) = Δ_f s − (Δ_f − Δ_f/q)L(1 − e^{−s/L}), L = layer/Δ_f (rings).
  auto map = [q](double s, double d_far, double layer) {
    const double L = layer / d_far;
    return d_far * s - (d_far - d_far / q) * L * (1.0 - std::exp(-s / L));
  };
  for (const int n_r : {0, 40}) {
    const PolarGrid g = make_stretched_grid(0.5, 20.0, n_r, 64, d_theta, q, 0.3);
    INFO("n_r asked " << n_r << ", built " << g.n_r);
    REQUIRE(!g.uniform_in_xi());
    REQUIRE(g.xi.front() == 0.0);
    REQUIRE(g.xi.back() == span);
    REQUIRE(g.r.back() == 0.5 * 20.0);
    if (n_r > 0) REQUIRE(g.n_r == n_r);
    if (n_r == 0) {  // Δ_f = Δθ: the fewest rings reaching ln(R/a), then the map scaled onto it
      REQUIRE(map(g.n_r - 1, d_theta, 0.3) >= span);
      REQUIRE(map(g.n_r - 2, d_theta, 0.3) < span);
      const double scale = span / map(g.n_r - 1, d_theta, 0.3);
      for (int i = 0; i < g.n_r; ++i) REQUIRE(g.xi[i] == Approx(scale * map(i, d_theta, 0.3)).margin(1e-14));
    }
    double worst = 0.0;
    for (int i = 0; i + 2 < g.n_r; ++i) {
      REQUIRE(g.d_xi(i + 1) > g.d_xi(i));  // monotone
      worst = std::max(worst, g.d_xi(i + 1) / g.d_xi(i));
    }
    // Smooth: ξ''/ξ' ≤ (q − 1)/L per ring, so successive spacings differ by at most e^{(q−1)/L}; here L ≈ 3
    // rings (1.50 measured, the first pair): a longer layer makes it smaller.
    INFO("largest ratio of successive spacings " << worst);
    CHECK(worst <= std::exp((q - 1.0) * g.d_xi(g.n_r - 2) / 0.3));
    // The control widths the solvers weigh rings by: (Δξ_{i−1/2} + Δξ_{i+1/2})/2.
    CHECK(g.ring_width(3) == 0.5 * (g.d_xi(2) + g.d_xi(3)));
  }
  // The wall's spacing is Δ_f/q: the one-sided slope (−3ξ_0 + 4ξ_1 − ξ_2)/2 per ring is ξ'(0) = Δ_f/q up to
  // ξ'''(0)/3 = (1 − 1/q)Δ_f/(3L²): 1e-4 relative for a layer of L = 80 rings.
  const double d_far = d_theta / 4.0;
  const PolarGrid g = make_stretched_grid(0.5, 20.0, 0, 256, d_far, q, 2.0);
  const double scale = span / map(g.n_r - 1, d_far, 2.0);
  const double slope = (-3.0 * g.xi[0] + 4.0 * g.xi[1] - g.xi[2]) / 2.0;
  INFO("n_r " << g.n_r << ", scale " << scale);
  CHECK(slope == Approx(scale * d_far / q).epsilon(1e-3));
}

TEST_CASE("stretched grid: bad wall refinement or layer is refused", "[mesh]") {
  CHECK_THROWS_AS(make_stretched_grid(0.5, 20.0, 40, 64, 0.1, 0.5, 0.3), std::invalid_argument);
  CHECK_THROWS_AS(make_stretched_grid(0.5, 20.0, 40, 64, 0.1, 4.0, 0.0), std::invalid_argument);
}
