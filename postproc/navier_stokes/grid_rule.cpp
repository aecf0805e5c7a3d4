#include "postproc/navier_stokes/grid_rule.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/resolution.hpp"
#include "solver/memory.hpp"

namespace magnus {

SceneGrid scene_grid(double Re, double alpha, double refine) {
  SceneGrid g;
  const double f = refine > 0.0 ? refine : 1.0;
  g.n_theta = std::max(16, 32 * int(std::ceil(6.0 * f * std::sqrt(std::max(Re, 20.0) / 100.0) - 1e-9)));
  const double d_xi_far = 2.0 * M_PI / g.n_theta / NsParams{}.radial_refinement;
  g.delta_xi = std::log1p(2.0 / std::sqrt(std::max(Re, 1e-12) * (1.0 + alpha * alpha)));
  const double d_xi_wall = std::min(d_xi_far, g.delta_xi / (kRuleWallCells * f));
  g.wall_refinement = d_xi_far / d_xi_wall;
  g.wall_layer = g.wall_refinement > 1.0 ? (g.wall_refinement - 1.0) * d_xi_far / kRuleGrowth : 0.1;
  return g;
}

double tolerance_refine(double tolerance) {
  return std::max(0.5, std::sqrt(2.0 * kRuleTolerance / tolerance));
}

namespace {

/// The refine factor of a case: grid.refine, times what grid.tolerance asks for.
double case_refine(const Case& c) {
  return c.grid.refine * (c.grid.tolerance > 0.0 ? tolerance_refine(c.grid.tolerance) : 1.0);
}

/// Re of the rule: U·D/ν, or a|ω|·D/ν in still fluid (the wall speed makes the boundary layer).
double rule_reynolds(const Scene& s) { return s.reference_speed() * 2.0 * s.radius / s.viscosity; }

}  // namespace

void apply_scene_grid(const Case& c, NsParams& p) {
  if (c.grid.n_theta_given || c.grid.n_r > 0) return;  // the grid as given (uniform rings unless stated)
  const SceneGrid g = scene_grid(rule_reynolds(c.scene), c.scene.spin_ratio(), case_refine(c));
  p.n_theta = g.n_theta;
  p.n_r = 0;
  if (!c.grid.wall_refinement_given) p.wall_refinement = g.wall_refinement;
  if (!c.grid.wall_layer_given) p.wall_layer = g.wall_layer;
}

void check_tolerance(const Case& c, const NsParams& p, size_t limit) {
  if (!(c.grid.tolerance > 0.0)) return;
  const PolarGrid g = ns_grid(p);
  // The run and its companion on the grid twice as coarse (a quarter of the nodes) march side by side.
  const double nodes = double(g.nodes()),
               bytes = nodes * (1.25 * kMarchBytesPerNode + 16.0 * std::max(0, c.output.snapshots));
  const bool given = limit > 0;
  if (!given) limit = bytes >= double(kUncheckedBytes) ? available_bytes() : 0;
  if (limit == 0 || bytes <= double(limit)) return;
  throw std::invalid_argument(fmt::format(
      "grid.tolerance: {:g} needs the scene's grid refined {:.3g}× (the default grid is built for {:g} and the "
      "error falls as the spacing squared): n_θ {} × {} rings ({:.3g} nodes), about {} with its companion "
      "run, more than {} {}; give a larger grid.tolerance",
      c.grid.tolerance, case_refine(c), kRuleTolerance, g.n_theta, g.n_r, nodes,
      format_bytes(size_t(std::min(1e18, bytes))), given ? "the limit" : "the memory available,",
      format_bytes(limit)));
}

std::string scene_grid_text(const Case& c, const NsParams& p) {
  if (c.grid.n_theta_given || c.grid.n_r > 0) return "as given (grid.n_theta, grid.n_r)";
  const double f = case_refine(c);
  return fmt::format("the scene's: δ = D/√(Re(1 + α²)) = {:.3g}a, {:.3g} first-ring cells across it, Δξ "
                     "{:.3g} times finer at the wall{}",
                     2.0 / std::sqrt(rule_reynolds(c.scene) * (1.0 + std::pow(c.scene.spin_ratio(), 2))),
                     kRuleWallCells * f, p.wall_refinement,
                     f != 1.0 ? fmt::format(", refined {:.3g}×{}", f,
                                            c.grid.tolerance > 0.0 ? " for grid.tolerance" : "")
                              : std::string());
}

}  // namespace magnus
