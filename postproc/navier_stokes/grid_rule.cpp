#include "postproc/navier_stokes/grid_rule.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/resolution.hpp"
#include "solver/memory.hpp"

namespace magnus {

SceneGrid scene_grid(double Re, double alpha, double refine, bool sheds) {
  const double f = refine > 0.0 ? refine : 1.0;
  auto n_theta_of = [Re](double factor) {
    return std::max(16, 32 * int(std::ceil(factor * std::sqrt(std::max(Re, 20.0) / 100.0) - 1e-9)));
  };
  const double shape = 5.0 / 3.0;  // Δθ/Δξ of the validation studies' cells, at n_θ of kRuleThetaFactor
  SceneGrid g;
  g.n_theta = n_theta_of((sheds ? kRuleThetaFactorShedding : kRuleThetaFactor) * f);
  g.delta_xi = std::log1p(boundary_layer_over_a(std::max(Re, 1e-12), alpha));
  // q and the layer's ξ-length are those of the unrefined grid: refining keeps the map, halving each spacing.
  const double d_xi_far = 2.0 * M_PI / n_theta_of(kRuleThetaFactor) / shape;
  g.radial_refinement = (2.0 * M_PI / g.n_theta) / (d_xi_far / f);
  g.wall_refinement = std::max(1.0, d_xi_far / (g.delta_xi / rule_wall_cells(alpha)));
  g.wall_layer = g.wall_refinement > 1.0 ? (g.wall_refinement - 1.0) * d_xi_far / kRuleGrowth : 0.1;
  return g;
}

double tolerance_refine(double tolerance) {
  return std::max(0.5, std::sqrt(2.0 * kRuleTolerance / tolerance));
}

namespace {

/// The refine factor of a case: grid.refine, times what grid.tolerance asks for.
double case_refine(const Case& c) {
  if (c.grid.refine_solved > 0.0) return c.grid.refine_solved;
  return c.grid.refine * (c.grid.tolerance > 0.0 ? tolerance_refine(c.grid.tolerance) : 1.0);
}

/// Re of the rule: U·D/ν, or a|ω|·D/ν in still fluid (the wall speed makes the boundary layer).
double rule_reynolds(const Scene& s) { return s.reference_speed() * 2.0 * s.radius / s.viscosity; }

}  // namespace

bool rule_grid(const Case& c) { return !c.grid.n_theta_given && c.grid.n_r == 0; }

bool scene_sheds(const Case& c) {
  return wake_sheds(c.scene.speed, c.scene.reynolds(), c.scene.spin_ratio());
}

void apply_scene_grid(const Case& c, NsParams& p) {
  if (!rule_grid(c)) return;  // the grid as given (uniform rings unless stated)
  const SceneGrid g = scene_grid(rule_reynolds(c.scene), c.scene.spin_ratio(), case_refine(c), scene_sheds(c));
  p.n_theta = g.n_theta;
  p.radial_refinement = g.radial_refinement;
  p.n_r = 0;
  if (!c.grid.wall_refinement_given) p.wall_refinement = g.wall_refinement;
  if (!c.grid.wall_layer_given) p.wall_layer = g.wall_layer;
}

void check_grid_memory(const Case& c, const NsParams& p, size_t limit) {
  const PolarGrid g = ns_grid(p);
  // The run and its companion on the grid twice as coarse (a quarter of the nodes) march side by side.
  const double nodes = double(g.nodes()), bytes = march_bytes(nodes, c.output.snapshots);
  const bool given = limit > 0;
  limit = passed_limit(bytes, limit);
  if (limit == 0) return;
  const std::string need = fmt::format(
      "n_θ {} × {} rings ({:.3g} nodes), about {} with its companion run, more than {} {}", g.n_theta, g.n_r,
      nodes, format_bytes(size_t(std::min(1e18, bytes))), given ? "the limit" : "the memory available,",
      format_bytes(limit));
  if (c.grid.tolerance > 0.0)
    throw std::invalid_argument(fmt::format(
        "grid.tolerance: {:g} needs the scene's grid refined {:.3g}× (the default grid is built for {:g} and "
        "the error falls as the spacing squared): {}; give a larger grid.tolerance",
        c.grid.tolerance, case_refine(c), kRuleTolerance, need));
  const bool rule = rule_grid(c);
  throw std::invalid_argument(fmt::format(
      "{}: the grid needs {}; {}", rule ? "grid.refine" : "grid.n_theta", need,
      rule ? fmt::format("the scene's grid at Re = {:.4g}, α = {:.4g} is that fine: give grid.refine < {:g} for "
                         "a coarser one (less accurate)",
                         c.scene.reynolds(), c.scene.spin_ratio(), c.grid.refine)
           : std::string("give a coarser grid")));
}

std::string scene_grid_text(const Case& c) {
  if (!rule_grid(c))
    return "the grid as given (grid.n_theta, grid.n_r); without them magnus fits the grid to the scene";
  const double f = case_refine(c), alpha = c.scene.spin_ratio();
  const std::string why =
      c.grid.tolerance > 0.0 ? fmt::format(", refined {:.3g}× for grid.tolerance = {:g}", f, c.grid.tolerance)
      : f != 1.0             ? fmt::format(", refined {:.3g}× (grid.refine)", f)
                             : std::string();
  const std::string theta = scene_sheds(c) ? "n_θ from √Re for fourth order in θ (the wake sheds)" : "n_θ from √Re";
  return fmt::format("the scene's grid: {}, {:.3g} first-ring cells across δ = D/√(Re(1 + α²)) = {:.3g}a{}", theta,
                     rule_wall_cells(alpha) * f, boundary_layer_over_a(rule_reynolds(c.scene), alpha), why);
}

}  // namespace magnus
