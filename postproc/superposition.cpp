#include "postproc/superposition.hpp"

#include <cmath>

namespace magnus {

FlowBasis flow_basis(const PolarGrid& g, const std::vector<double>& psi_U, const std::vector<double>& psi_Gamma,
                     int order) {
  FlowBasis b;
  b.grid = g;
  b.surface_U = surface_u_theta(g, psi_U, order);
  b.surface_Gamma = surface_u_theta(g, psi_Gamma, order);
  b.up_U = u_theta_on_ray(g, psi_U, M_PI / 2, order);
  b.up_Gamma = u_theta_on_ray(g, psi_Gamma, M_PI / 2, order);
  b.down_U = u_theta_on_ray(g, psi_U, 3 * M_PI / 2, order);
  b.down_Gamma = u_theta_on_ray(g, psi_Gamma, 3 * M_PI / 2, order);
  return b;
}

namespace {
std::vector<double> combine(double U, const std::vector<double>& a, double G, const std::vector<double>& b) {
  std::vector<double> out(a.size());
  for (size_t k = 0; k < a.size(); ++k) out[k] = U * a[k] + G * b[k];
  return out;
}
}  // namespace

SweepPoint evaluate(const FlowBasis& b, const Case& c) {
  const double U = c.speed, G = c.circulation();
  SweepPoint p;
  p.c = c;
  const Surface s = surface_from_basis(b.grid, c, b.surface_U, b.surface_Gamma);
  p.forces = compute_forces(c, s);
  p.stagnation = find_stagnation_points(b.grid, c, s.u_theta, [&](double theta) {
    return theta < M_PI ? combine(U, b.up_U, G, b.up_Gamma) : combine(U, b.down_U, G, b.down_Gamma);
  });
  p.stagnation_exact = exact_flow(c).stagnation_points();
  p.cl_rel = lift_error(c, p.forces);
  return p;
}

}  // namespace magnus
