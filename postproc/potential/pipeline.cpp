#include "postproc/potential/pipeline.hpp"

#include <fmt/core.h>

#include "postproc/potential/plan.hpp"
#include "postproc/potential/tolerance.hpp"
#include "solver/potential/memory.hpp"

namespace magnus {

Discretization discretize(const Case& c, int threads, size_t max_bytes, int fields) {
  const Method method = resolve_method(c.solver.method);
  check_grid_memory(c.grid, c.solver.stencil, method, fields, max_bytes);
  const double t0 = now_s();
  Discretization d;
  d.grid = make_grid(c.grid, c.scene.radius);  // make grid
  const DiscreteOperator op =
      make_operator(d.grid, c.solver.stencil, c.grid.far_field);  // stencils, closures
  d.setup_s = now_s() - t0;
  d.solver = make_solver(d.grid, op, method, threads, max_bytes);  // assemble and factor
  return d;
}

std::optional<double> lift_coefficient(const Case& c, int threads) {
  const Discretization d = discretize(c, threads);
  const std::vector<double> psi = d.solver->solve(c.scene.speed, c.scene.Gamma());
  return compute_forces(c.scene, compute_surface(d.grid, c.scene, psi, derivative_order(c.solver.stencil)))
      .cl;
}

RunPlan plan_run(const Case& requested, int threads, size_t max_bytes) {
  const double t0 = now_s();
  RunPlan p;
  p.c = requested;
  if (p.c.grid.tolerance > 0.0) {  // only what the scene needs: the grid the tolerance asks for
    p.choice = choose_grid(p.c, threads, max_bytes);
    p.c.grid.n_theta = p.choice.n_theta;
    p.c.grid.n_r = 0;
    p.c.grid.spacing = p.choice.spacing;
    p.c.solver.stencil = p.choice.stencil;
  }
  p.choice_s = now_s() - t0;
  return p;
}

FlowResult run_planned(const RunPlan& plan, int threads, size_t max_bytes) {
  const double t0 = now_s();
  const Case& c = plan.c;
  const FieldSelection sel = select_fields(c.output.fields);
  int fields = 0;
  for (bool on : sel.on) fields += on;
  const Discretization d = discretize(c, threads, max_bytes, fields);  // the memory guard, then factor
  const PsiBasis basis = solve_basis(*d.solver);                       // solve ψ_U, ψ_Γ
  const double t1 = now_s();
  FlowResult r = postprocess(d.grid, c, basis.psi_U, basis.psi_Gamma, sel);
  r.timing.assemble_s = d.setup_s + d.solver->timing.assemble_s;
  r.timing.factor_s = d.solver->timing.factor_s;
  r.timing.solve_s = d.solver->timing.solve_s;
  r.timing.postproc_s = now_s() - t1;
  r.timing.total_s = now_s() - t0 + plan.choice_s;
  r.info.method = to_string(d.solver->method());
  r.info.threads = threads;
  if (c.grid.tolerance > 0.0) {
    r.info.estimated_cl_rel = plan.choice.estimated_cl_rel;
    r.info.grid_choice = fmt::format(
        "chosen for C_L tolerance {:.3g}: n_θ = {}, {} spacing, {} stencil (grids tried {}, {:.3g} ms)",
        c.grid.tolerance, c.grid.n_theta, to_string(c.grid.spacing), to_string(c.solver.stencil),
        plan.choice.trail, plan.choice_s * 1e3);
  }
  return r;
}

}  // namespace magnus
