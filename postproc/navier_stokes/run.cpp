#include "postproc/navier_stokes/run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "postproc/navier_stokes/run_paths.hpp"

namespace magnus {

const char* time_unit_name(const Scene& s) { return s.speed > 0.0 ? "D/U" : "D/(a|ω|)"; }
const char* rate_unit_name(const Scene& s) { return s.speed > 0.0 ? "U/D" : "a|ω|/D"; }

NsParams ns_params(const Case& c) {
  NsParams p;
  const Scene& s = c.scene;
  p.a = s.radius;
  p.U = s.speed;
  p.omega = s.spin;
  p.nu = s.viscosity;
  p.outer_over_a = c.grid.outer_radius;
  p.n_theta = c.grid.n_theta;
  p.n_r = c.grid.n_r;
  p.wall_refinement = c.grid.wall_refinement;
  p.wall_layer = c.grid.wall_layer;
  p.cfl = c.time.cfl;
  p.advection_order = c.solver.advection_order;
  p.advection_order_xi = c.solver.advection_order_xi;
  p.wall_closure = c.solver.wall_closure == "jensen" ? NsWallClosure::jensen : NsWallClosure::thom;
  p.implicit_rotation = c.solver.implicit_rotation;
  p.absorbing_start = c.grid.absorbing_layer;
  p.absorbing_rate = c.grid.absorbing_strength / s.time_unit();  // λ_R: U_ref/D in 1/s
  p.dt = c.time.dt > 0.0 && s.reference_speed() > 0.0 ? c.time.dt * s.time_unit() : 0.0;
  apply_scene_grid(c, p);
  return p;
}

namespace {

/// One run on the grid the case asks for (the scene's, refined for a tolerance): the path time.mode and
/// "auto" choose.
FlowResult run_on_grid(const Case& c, const ViscousHooks& hooks, const Checkpoint* resume, int threads) {
  NsParams p = ns_params(c);
  check_grid_memory(c, p, hooks.max_bytes);  // the grid (and its companion) must fit: before any solve
  p.threads = std::max(1, threads);
  const PolarGrid g = ns_grid(p);
  const double unit = c.scene.time_unit();

  if (c.time.mode == TimeMode::steady) return steady_by_newton(c, p, g, resume);
  if (c.time.mode == TimeMode::periodic) return periodic_by_shooting(c, p, g, unit, hooks, resume);
  AutoChoice choice;
  if (c.time.mode == TimeMode::automatic && hooks.march_at_once)
    choice.why = "auto: marched in time (asked to march at once); ";
  else if (c.time.mode == TimeMode::automatic && !resume) {
    choice = auto_steady(c, p, g, hooks.error_estimate);
    if (choice.steady) return std::move(*choice.steady);
  }
  return march(c, p, g, unit, hooks, resume, choice);
}

/// The largest defined estimate of mean C_L, mean C_D and St (relative), if any.
std::optional<double> worst_estimate(const ViscousPart& v) {
  std::optional<double> w;
  for (const auto& e : {v.cl_mean_rel_estimate, v.cd_mean_rel_estimate, v.strouhal_rel_estimate})
    if (e) w = std::max(w.value_or(0.0), *e);
  return w;
}

}  // namespace

FlowResult run_viscous(const Case& c, const ViscousHooks& hooks, const Checkpoint* resume, int threads) {
  const Scene& sc = c.scene;
  if (c.model != FlowModel::navier_stokes)
    throw std::invalid_argument("model.flow: run_viscous needs \"navier-stokes\"");
  if (!(sc.viscosity > 0.0)) throw std::invalid_argument("flow.viscosity: navier-stokes needs ν > 0");
  if (!(sc.reference_speed() > 0.0))
    throw std::invalid_argument("flow.speed and cylinder.spin are both 0: nothing moves, there is no flow");
  check_resolvable(c, hooks.max_bytes);  // before anything is solved or allocated
  const double tol = c.grid.tolerance;
  if (!(tol > 0.0)) return run_on_grid(c, hooks, resume, threads);
  // grid.tolerance: the grid the rule's design error asks for must fit (refused before solving). The
  // search starts on the scene's grid, or coarser when τ is above the design error: that cheap run's own
  // estimate sizes the grid (error ∝ spacing², 10% to spare) and judges the second run on it, if it fits.
  check_grid_memory(c, ns_params(c), hooks.max_bytes);
  Case first = c;
  first.grid.refine_solved = c.grid.refine * std::min(1.0, tolerance_refine(tol));
  FlowResult r = run_on_grid(first, hooks, resume, threads);
  if (!r.viscous || r.viscous->partial) return r;
  std::optional<double> worst = worst_estimate(*r.viscous);
  if (worst && *worst > tol && !resume) {
    const double more = 1.1 * std::sqrt(*worst / tol);  // error ∝ spacing², 10% to spare
    Case finer = first;
    finer.grid.refine_solved *= more;
    try {
      check_grid_memory(finer, ns_params(finer), hooks.max_bytes);
      const std::string first_grid = fmt::format("{} × {}", r.grid.n_theta, r.grid.n_r);
      r = run_on_grid(finer, hooks, nullptr, threads);
      r.viscous->tolerance_note = fmt::format("the first grid, {}, estimated {:.2g}; refined {:.3g}× more",
                                              first_grid, *worst, more);
    } catch (const std::invalid_argument& e) {
      r.viscous->tolerance_note = fmt::format("the grid it would need does not fit: {}", e.what());
    }
    worst = worst_estimate(*r.viscous);
  }
  r.viscous->tolerance_met = worst && *worst <= tol;
  return r;
}

}  // namespace magnus
