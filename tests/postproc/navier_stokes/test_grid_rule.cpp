// The navier-stokes grid that fits the scene: n_θ from √Re, the first ring inside the boundary layer
// D/√(Re(1 + α²)), the rings spreading smoothly; grid.refine scales it, grid.tolerance picks the refinement
// and is refused before solving when that grid does not fit.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "io/case_file.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/run.hpp"

using namespace magnus;
using Catch::Matchers::Contains;

namespace {

/// A navier-stokes case at Re, α (a = 0.5 m, U = 1 m/s) with extra TOML lines.
Case ns_case(double Re, double alpha, const std::string& extra = "") {
  return parse_case("[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = " +
                        std::to_string(alpha) + "\n[flow]\nspeed = 1.0\nreynolds = " + std::to_string(Re) +
                        "\n" + extra,
                    "rule.toml");
}

/// The wall slope dξ/ds of a grid, second order one-sided from rings 0, 1, 2 (uniform s).
double wall_slope(const PolarGrid& g) { return (-3.0 * g.xi[0] + 4.0 * g.xi[1] - g.xi[2]) / 2.0; }

}  // namespace

TEST_CASE("the scene's grid: n_theta from sqrt(Re), 10·min(max(1, alpha), 4) first-ring cells across the boundary layer",
          "[ns][grid_rule]") {
  // n_θ = 32·⌈6√(Re/100)⌉, and 32·⌈4√(Re/100)⌉ where the wake sheds (fourth order in θ); the far rings
  // keep Δξ = (2π/(32·⌈6√(Re/100)⌉))/(5/3) either way.
  CHECK(scene_grid(20, 0).n_theta == 96);
  CHECK(scene_grid(40, 0).n_theta == 128);
  CHECK(scene_grid(100, 2).n_theta == 192);
  CHECK(scene_grid(200, 6).n_theta == 288);
  CHECK(scene_grid(100, 1, 1.0, true).n_theta == 128);
  CHECK(scene_grid(150, 0, 1.0, true).n_theta == 160);
  CHECK(scene_grid(200, 0, 1.0, true).n_theta == 192);
  CHECK(scene_grid(100, 0, 2.0, true).n_theta == 256);
  CHECK(ns_params(ns_case(100, 1)).n_theta == 128);  // U > 0, Re ≥ 60, α ≤ 1: the wake sheds
  CHECK(ns_params(ns_case(100, 1.5)).n_theta == 192);
  CHECK(ns_params(ns_case(40, 0)).n_theta == 128);
  for (double Re : {20.0, 40.0, 100.0, 150.0, 200.0}) {
    const int n_ring = 32 * int(std::ceil(6.0 * std::sqrt(std::max(Re, 20.0) / 100.0) - 1e-9));
    for (double f : {1.0, 2.0}) {
      for (bool sheds : {false, true}) {
        const SceneGrid g = scene_grid(Re, 1.0, f, sheds);
        CHECK((2.0 * M_PI / g.n_theta) / g.radial_refinement == Approx(2.0 * M_PI / n_ring / (5.0 / 3.0) / f));
      }
    }
  }
  // Re 100, α 0: the far spacing nearly puts ten cells across δ: nearly uniform rings.
  CHECK(scene_grid(100, 0).wall_refinement == Approx(1.077).epsilon(0.01));
  CHECK(scene_grid(100, 0, 2.0).wall_layer == scene_grid(100, 0).wall_layer);
  for (double alpha : {1.0, 2.0, 4.0, 6.0}) {
    for (double Re : {40.0, 100.0, 200.0}) {
      const Case c = ns_case(Re, alpha);
      const NsParams p = ns_params(c);
      const PolarGrid g = ns_grid(p);
      const double delta_xi = std::log1p(2.0 / std::sqrt(Re * (1.0 + alpha * alpha)));
      INFO("Re " << Re << " alpha " << alpha << " q " << p.wall_refinement);
      REQUIRE(p.wall_refinement > 1.0);
      // The first ring: Δξ at the wall is δ_ξ/(10·min(max(1, α), 4)) (the map's slope there, to the scaling onto R).
      CHECK(wall_slope(g) == Approx(delta_xi / rule_wall_cells(alpha)).epsilon(0.03));
      // Smooth: no spacing grows by more than kRuleGrowth over its neighbour (plus the map's curvature).
      for (int i = 1; i + 1 < g.n_r; ++i) CHECK(g.d_xi(i) / g.d_xi(i - 1) <= 1.0 + 1.1 * kRuleGrowth);
      CHECK(g.outer_radius() == Approx(100.0 * 0.5));
    }
  }
}

TEST_CASE("the scene's grid: refine scales every spacing, a given grid is kept, tolerance refines",
          "[ns][grid_rule]") {
  const NsParams p1 = ns_params(ns_case(100, 4)), p2 = ns_params(ns_case(100, 4, "[grid]\nrefine = 2\n"));
  CHECK(p2.n_theta == 2 * p1.n_theta);
  CHECK(wall_slope(ns_grid(p2)) == Approx(0.5 * wall_slope(ns_grid(p1))).epsilon(0.01));
  CHECK(ns_grid(p2).n_r == Approx(2 * (ns_grid(p1).n_r - 1) + 1).margin(2));  // the same map, halved
  // A stated n_θ: that grid, uniform rings unless the clustering is stated too.
  const NsParams given = ns_params(ns_case(100, 4, "[grid]\nn_theta = 64\n"));
  CHECK(given.n_theta == 64);
  CHECK(given.wall_refinement == 1.0);
  CHECK(ns_params(ns_case(100, 4, "[grid]\nn_theta = 64\nwall_refinement = 3\n")).wall_refinement == 3.0);
  // grid.tolerance τ asks for refine √(2·1e-2/τ): 1e-2 → √2.
  CHECK(tolerance_refine(1e-2) == Approx(std::sqrt(2.0)));
  CHECK(tolerance_refine(0.1) == 0.5);
  CHECK(ns_params(ns_case(100, 1, "[grid]\ntolerance = 5e-3\n")).n_theta == 256);
  CHECK_THAT(scene_grid_text(ns_case(100, 1, "[grid]\ntolerance = 5e-3\n")),
             Contains("refined 2× for grid.tolerance = 0.005"));
  CHECK_THAT(scene_grid_text(ns_case(100, 1, "[grid]\nn_theta = 64\n")), Contains("the grid as given"));
}

TEST_CASE("grid.tolerance: a grid that does not fit in memory is refused before solving, in one line",
          "[ns][grid_rule]") {
  const Case c = ns_case(100, 1, "[grid]\ntolerance = 1e-4\n");
  const NsParams p = ns_params(c);
  const std::string limit_msg = [&] {
    try {
      check_grid_memory(c, p, size_t(64) << 20);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  CHECK_THAT(limit_msg, Contains("grid.tolerance: 0.0001 needs the scene's grid refined 14.1×"));
  CHECK_THAT(limit_msg, Contains("more than the limit 64.0 MiB; give a larger grid.tolerance"));
  CHECK(limit_msg.find('\n') == std::string::npos);
  CHECK_NOTHROW(check_grid_memory(ns_case(100, 1, "[grid]\ntolerance = 1e-2\n"),
                                ns_params(ns_case(100, 1, "[grid]\ntolerance = 1e-2\n")), size_t(64) << 20));
  // Without a tolerance the scene's grid (or the given one) is checked the same way.
  CHECK_THAT(
      [&] {
        try {
          check_grid_memory(ns_case(100, 1), ns_params(ns_case(100, 1)), 1 << 20);
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      Contains("grid.refine: the grid needs n_θ 128 × 238 rings") && Contains("give grid.refine < 1"));
}

TEST_CASE("grid.tolerance: a cheap run's own estimate sizes the grid, and judges it", "[ns][grid_rule]") {
  // Re 20, α 0.5, steady (Newton), R = 20a.
  const Case c = ns_case(20, 0.5, "[domain]\nouter_radius = 20.0\n[grid]\ntolerance = 5e-3\n");
  const FlowResult r = run_viscous(c);
  REQUIRE(r.viscous);
  REQUIRE(r.viscous->tolerance_met);
  double worst = 0.0;
  for (const auto& e : {r.viscous->cl_mean_rel_estimate, r.viscous->cd_mean_rel_estimate}) {
    REQUIRE(e);
    worst = std::max(worst, *e);
  }
  CHECK(*r.viscous->tolerance_met == (worst <= 5e-3));
  // The search starts on the scene's grid (n_θ 96), whose estimate (about 1%) asks for a finer one; that one
  // meets τ and is coarser than the grid the design error would have taken (refine 2: n_θ 192).
  CHECK(*r.viscous->tolerance_met);
  CHECK_THAT(r.viscous->tolerance_note, Contains("the first grid, 96 × "));
  CHECK(r.grid.n_theta > 96);
  CHECK(r.grid.n_theta < 192);
}

TEST_CASE("the scene's grid comes with its scheme: Jensen's wall closure, fourth order in theta where it sheds",
          "[ns][grid_rule]") {
  const Case rule = ns_case(100, 1);
  CHECK(rule.solver.advection_order == 4);
  CHECK(ns_case(100, 2).solver.advection_order == 2);  // steady by the rule: second order, Newton's cheaper LU
  CHECK(ns_case(40, 1).solver.advection_order == 2);
  CHECK(ns_case(40, 1).solver.wall_closure == "jensen");
  CHECK(rule.solver.wall_closure == "jensen");
  CHECK(ns_params(rule).advection_order == 4);
  CHECK(ns_params(rule).wall_closure == NsWallClosure::jensen);
  // The resolved case states them, so it runs the same scheme again.
  const Case again = parse_case(rule.source_text, "resolved.toml");
  CHECK(again.solver.advection_order == 4);
  CHECK(again.solver.wall_closure == "jensen");
  // A stated grid keeps the model's defaults; stated solver keys win over the scene's.
  const Case given = ns_case(100, 1, "[grid]\nn_theta = 64\n");
  CHECK(given.solver.advection_order == 2);
  CHECK(given.solver.wall_closure == "thom");
  const Case stated = ns_case(100, 1, "[solver]\nadvection_order = 2\nwall_closure = \"thom\"\n");
  CHECK(stated.solver.advection_order == 2);
  CHECK(stated.solver.wall_closure == "thom");
}
