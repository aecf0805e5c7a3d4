// The physics layer alone: the scene's derived quantities (Γ, α, Re, the reference speed, rpm) and the
// turn of forces into the world frame, against their formulas.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/checked_cast.hpp"
#include "physics/scene.hpp"

using namespace magnus;

TEST_CASE("scene: Γ = 2πa²ω or as given, α = aω/U, Re = 2aU/ν, rpm = 60ω/2π", "[physics][scene]") {
  Scene s;  // a = 0.1 m, ω = 100 rad/s, U = 10 m/s
  CHECK(s.Gamma() == Approx(2.0 * M_PI * 0.01 * 100.0).epsilon(1e-15));
  CHECK(s.spin_ratio() == Approx(1.0).epsilon(1e-15));
  CHECK(s.rpm() == Approx(100.0 * 60.0 / (2.0 * M_PI)).epsilon(1e-15));
  s.viscosity = 1e-3;
  CHECK(s.reynolds() == Approx(10.0 * 0.2 / 1e-3).epsilon(1e-15));
  s.reynolds_given = true;
  s.reynolds_value = 200.0;  // echoed exactly as given
  CHECK(s.reynolds() == 200.0);
  s.circulation_given = true;
  s.circulation_value = -3.5;
  CHECK(s.Gamma() == -3.5);
  CHECK(s.reference_speed() == 10.0);
  s.speed = 0.0;  // still fluid: the wall speed a|ω| is the reference, α is undefined (0)
  s.spin = -40.0;
  CHECK(s.reference_speed() == Approx(4.0).epsilon(1e-15));
  CHECK(s.spin_ratio() == 0.0);
}

TEST_CASE("world_force turns (D, L) by the direction β, rotate_deg is exact at multiples of 90°", "[physics][scene]") {
  for (double beta : {0.0, 30.0, 135.0, -200.0}) {
    const double b = beta * M_PI / 180.0;
    const WorldForce w = world_force(2.0, -7.0, beta);
    CHECK(w.x == Approx(2.0 * std::cos(b) + 7.0 * std::sin(b)).epsilon(1e-14));
    CHECK(w.y == Approx(2.0 * std::sin(b) - 7.0 * std::cos(b)).epsilon(1e-14));
    CHECK(std::hypot(w.x, w.y) == Approx(std::hypot(2.0, 7.0)).epsilon(1e-14));
  }
  for (int k = -4; k <= 4; ++k) {
    const WorldForce r = rotate_deg(3.0, 1.0, 90.0 * k);
    const int q = ((k % 4) + 4) % 4;
    const double ex[4] = {3.0, -1.0, -3.0, 1.0}, ey[4] = {1.0, 3.0, -1.0, -3.0};
    CHECK(r.x == ex[q]);
    CHECK(r.y == ey[q]);
  }
}

TEST_CASE("checked_cast refuses NaN, inf and out-of-range values by name, saturate_cast clamps", "[physics][cast]") {
  CHECK(checked_cast<int>(12.9, "n") == 12);
  CHECK_THROWS_WITH(checked_cast<int>(NAN, "grid.n_theta"), Catch::Contains("grid.n_theta"));
  CHECK_THROWS_AS(checked_cast<int>(3e9, "n"), std::out_of_range);
  CHECK(saturate_cast<int>(1e300) == std::numeric_limits<int>::max());
  CHECK(saturate_cast<int>(-1e300) == std::numeric_limits<int>::min());
  CHECK(saturate_cast<long>(NAN) == 0);
}
