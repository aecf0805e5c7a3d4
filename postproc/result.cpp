#include "postproc/result.hpp"

namespace magnus {

FlowResult postprocess(const PolarGrid& g, const Case& c, const std::vector<double>& psi_U,
                       const std::vector<double>& psi_Gamma, const FieldSelection& sel) {
  const int order = derivative_order(c.stencil);
  const double U = c.speed, G = c.circulation();
  std::vector<double> psi(psi_U.size());
  for (size_t q = 0; q < psi.size(); ++q) psi[q] = U * psi_U[q] + G * psi_Gamma[q];
  FlowResult r;
  r.c = c;
  r.grid = g;
  const std::vector<double> psi_exact = exact_flow(c).psi_field(g);  // once: fields and error norms
  r.fields = compute_fields(g, c, psi, psi_exact, sel, order);
  r.surface = surface_from_basis(g, c, surface_u_theta(g, psi_U, order), surface_u_theta(g, psi_Gamma, order));
  r.forces = compute_forces(c, r.surface);
  r.stagnation = find_stagnation_points(g, c, r.surface.u_theta,
                                       [&](double theta) { return u_theta_on_ray(g, psi, theta, order); });
  r.stagnation_exact = exact_flow(c).stagnation_points();
  r.errors = compute_errors(c, psi, psi_exact, r.surface, r.forces);
  return r;
}

}  // namespace magnus
