#include "postproc/navier_stokes/run.hpp"

#include <algorithm>
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
  p.dt = c.time.dt > 0.0 && s.reference_speed() > 0.0 ? c.time.dt * s.time_unit() : 0.0;
  apply_scene_grid(c, p);
  return p;
}

FlowResult run_viscous(const Case& c, const ViscousHooks& hooks, const Checkpoint* resume, int threads) {
  const Scene& sc = c.scene;
  if (c.model != FlowModel::navier_stokes)
    throw std::invalid_argument("model.flow: run_viscous needs \"navier-stokes\"");
  if (!(sc.viscosity > 0.0)) throw std::invalid_argument("flow.viscosity: navier-stokes needs ν > 0");
  if (!(sc.reference_speed() > 0.0))
    throw std::invalid_argument("flow.speed and cylinder.spin are both 0: nothing moves, there is no flow");
  check_resolvable(c);  // before anything is solved or allocated
  NsParams p = ns_params(c);
  check_tolerance(c, p);  // the grid a tolerance asks for must fit, before anything is solved
  p.threads = std::max(1, threads);
  const PolarGrid g = ns_grid(p);
  const double unit = sc.time_unit();

  if (c.time.mode == TimeMode::steady) return steady_by_newton(c, p, g, resume);
  AutoChoice choice;
  if (c.time.mode == TimeMode::automatic && hooks.march_at_once)
    choice.why = "auto: marched in time (asked to march at once); ";
  else if (c.time.mode == TimeMode::automatic && !resume) {
    choice = auto_steady(c, p, g, hooks.error_estimate);
    if (choice.steady) return std::move(*choice.steady);
  }
  return march(c, p, g, unit, hooks, resume, choice);
}

}  // namespace magnus
