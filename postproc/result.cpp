#include "postproc/result.hpp"

#include "solver/potential/flow_solver.hpp"

namespace magnus {

FlowResult postprocess(const PolarGrid& g, const Case& c, const std::vector<double>& psi_U,
                       const std::vector<double>& psi_Gamma, const FieldSelection& sel) {
  const int order = derivative_order(c.solver.stencil);
  const Scene& scene = c.scene;
  const std::vector<double> psi = superpose(scene.speed, psi_U, scene.Gamma(), psi_Gamma);
  FlowResult r;
  r.c = c;
  r.grid = g;
  const std::vector<double> psi_exact =
      exact_flow(scene).psi_field(g.r, g.theta);  // once: fields and error norms
  r.fields = compute_fields(g, scene, psi, psi_exact, sel, order);
  r.surface =
      surface_from_basis(g, scene, surface_u_theta(g, psi_U, order), surface_u_theta(g, psi_Gamma, order));
  r.forces = compute_forces(scene, r.surface);
  r.stagnation = find_stagnation_points(g, scene, r.surface.u_theta,
                                        [&](double theta) { return u_theta_on_ray(g, psi, theta, order); });
  r.stagnation_exact = sorted_stagnation_points(exact_flow(scene).stagnation_points());
  r.errors = compute_errors(scene, psi, psi_exact, r.surface, r.forces);
  return r;
}

std::optional<StagnationPoint> stagnation_outside_grid(const FlowResult& r) {
  if (r.stagnation.empty())
    for (const auto& p : r.stagnation_exact)
      if (!p.on_surface && p.r > r.grid.outer_radius()) return p;
  return std::nullopt;
}

}  // namespace magnus
