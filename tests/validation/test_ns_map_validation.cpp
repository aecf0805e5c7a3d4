// The shipped S(Re, α) map (cases/s_map.toml): a 20 × 21 map over Re 10…200 and α 0…6 within 5 minutes on
// two cores, and the regimes the literature knows: the wake of a non-spinning cylinder starts to shed at
// Re ≈ 47 (Provansal et al. 1987), spin ratios around 2 stop the shedding at Re 100 (Stojković et al. 2002).
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "io/case_file.hpp"
#include "postproc/navier_stokes/continuation.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("the s_map case: 420 points within 5 minutes, the shedding onset near Re 47",
          "[validation][ns-map]") {
  const Case c = load_case(std::string(MAGNUS_SOURCE_DIR) + "/cases/s_map.toml");
  NsMapOptions o;
  for (int k = 0; k <= 20; ++k) o.alphas.push_back(0.3 * k);
  for (int k = 1; k <= 20; ++k) o.reynolds.push_back(10.0 * k);
  o.threads = 2;
  o.stability = make_stability_hook(StabilityMethod::march);  // the map-sized test (README: timing)
  const auto t0 = std::chrono::steady_clock::now();
  const NsMap m = ns_map(c, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("s_map: %zu points in %.1f s (wall, 2 threads)\n", m.points.size(), s);
  REQUIRE(m.points.size() == 420);
  CHECK(s < 300.0);
  auto at = [&](int row, int col) -> const NsMapPoint& { return m.points[size_t(row) * 21 + size_t(col)]; };
  for (int r = 0; r < 4; ++r) CHECK(at(r, 0).stable == std::optional<bool>(true));    // Re 10…40: steady
  for (int r = 4; r < 20; ++r) CHECK(at(r, 0).stable == std::optional<bool>(false));  // Re 50…200: sheds
  CHECK(at(9, 3).stable == std::optional<bool>(false));                               // Re 100, α 0.9: sheds
  CHECK(at(9, 8).stable == std::optional<bool>(true));  // Re 100, α 2.4: steady
  // Re 100 near α = 5: the one-sided shedding window is narrow (α 4.8 and 5.1 shed, slowly: the lift swings
  // with a faster ripple, St 0.040 and 0.023 from the mean crossings, each confirmed by its spectral peak;
  // successive maxima had read the ripple, St ≈ 0.12); beyond it the continued branch is unstable, but the
  // flow marched from rest settles on another steady state.
  CHECK(at(9, 16).source == MapSource::averaged_unstable);
  CHECK(at(9, 17).source == MapSource::averaged_unstable);
  CHECK(at(9, 16).strouhal > 0.02);
  CHECK(at(9, 17).strouhal > 0.01);
  for (int k = 18; k <= 20; ++k) {
    CHECK(at(9, k).source == MapSource::marched_steady);
    CHECK(at(9, k).stable == std::optional<bool>(false));
  }
  for (const auto& p : m.points)
    if (p.alpha > 0.0 && std::isfinite(p.ratio)) {
      CHECK(p.ratio > 0.0);
      CHECK(p.ratio < 1.2);  // at α = 6 finer grids reach 1.03 of the ideal lift (README); this one less
    }
}

TEST_CASE("the map marks the bistable range below the one-sided window's Hopf point (Re 200)",
          "[validation][ns-map]") {
  // On n_θ 128, R = 100a the one-sided window of Re 200 opens at a subcritical Hopf point (4.402): a march
  // from rest sheds at 4.38, where the steady state is still stable, and not at 4.34 (the README's
  // "Re 200, the second window"). The row runs upwards: the orbit found at 4.42 is carried back into the
  // stable points before it, persists at 4.38 (bistable) and is lost at 4.34 (steady).
  const Case c = parse_case(
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 4.4\n[flow]\nspeed = 1.0\n"
      "density = 1.0\nreynolds = 200.0\n[domain]\nouter_radius = 100.0\n[grid]\nn_theta = 128\n[time]\n"
      "end = 300.0\n",
      "bistable");
  const NsMap m = ns_map(c, test::orbit_row({4.34, 4.38, 4.42}, 200.0));
  REQUIRE(m.points.size() == 3);
  for (const NsMapPoint& p : m.points)
    std::printf("alpha %.2f: stable %d, regime %g, orbit from %s, St %.4f\n", p.alpha,
                int(p.stable.value_or(false)), p.regime, p.orbit_start.c_str(), p.strouhal);
  CHECK(m.points[0].stable == std::optional<bool>(true));
  CHECK(m.points[0].regime == double(MapRegime::steady));
  CHECK(m.points[1].stable == std::optional<bool>(true));
  CHECK(m.points[1].regime == double(MapRegime::bistable));
  CHECK(m.points[1].orbit_start == "continued");
  CHECK(m.points[2].source == MapSource::orbit);
  CHECK(m.points[2].regime == double(MapRegime::shedding));
  CHECK(m.points[2].strouhal == Approx(0.0361).epsilon(0.05));  // the march from rest's St at 4.42
}
