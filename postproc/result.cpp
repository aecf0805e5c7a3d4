#include "postproc/result.hpp"

namespace magnus {

FlowResult postprocess(const PolarGrid& g, const Case& c, const std::vector<double>& psi,
                       const FieldSelection& sel) {
  const int order = derivative_order(c.stencil);
  FlowResult r;
  r.c = c;
  r.grid = g;
  r.fields = compute_fields(g, c, psi, sel, order);
  r.surface = compute_surface(g, c, psi, order);
  r.forces = compute_forces(c, r.surface);
  r.stagnation = find_stagnation_points(g, c, r.surface.u_theta,
                                       [&](double theta) { return u_theta_on_ray(g, psi, theta, order); });
  r.stagnation_exact = exact_flow(c).stagnation_points();
  r.errors = compute_errors(g, c, psi, r.surface, r.forces);
  return r;
}

}  // namespace magnus
