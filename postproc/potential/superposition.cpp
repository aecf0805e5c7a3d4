#include "postproc/potential/superposition.hpp"

#include <cmath>

#include "solver/potential/flow_solver.hpp"

namespace magnus {

FlowBasis flow_basis(const PolarGrid& g, const std::vector<double>& psi_U,
                     const std::vector<double>& psi_Gamma, int order) {
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

SweepPoint evaluate(const FlowBasis& b, const Scene& scene) {
  const double U = scene.speed, Gamma = scene.Gamma();
  SweepPoint p;
  p.scene = scene;
  const Surface s = surface_from_basis(b.grid, scene, b.surface_U, b.surface_Gamma);
  p.forces = compute_forces(scene, s);
  p.stagnation = find_stagnation_points(b.grid, scene, s.u_theta, [&](double theta) {
    return theta < M_PI ? superpose(U, b.up_U, Gamma, b.up_Gamma)
                        : superpose(U, b.down_U, Gamma, b.down_Gamma);
  });
  p.stagnation_exact = exact_flow(scene).stagnation_points();
  p.cl_rel = lift_error(scene, p.forces);
  return p;
}

}  // namespace magnus
