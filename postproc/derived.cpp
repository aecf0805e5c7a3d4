#include "postproc/derived.hpp"

#include <cmath>

namespace magnus {

std::optional<double> cl_over_kj_minus_1(std::optional<double> cl, std::optional<double> kj) {
  return cl && kj && *kj != 0.0 ? std::optional<double>(*cl / *kj - 1.0) : std::nullopt;
}

std::optional<double> kj_over_seed(std::optional<double> kj, std::optional<double> seed) {
  return kj && seed && *seed != 0.0 ? std::optional<double>(*kj / *seed) : std::nullopt;
}

DerivedRatios derived_ratios(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  const Forces& f = r.forces;
  DerivedRatios d;
  if (sc.circulation_given && sc.speed > 0.0)
    d.alpha_Gamma = sc.Gamma() / (2.0 * M_PI * sc.radius * sc.speed);
  d.cl_over_kj_minus_1 = cl_over_kj_minus_1(f.cl, f.cl_kutta_joukowski);
  d.kj_over_seed = kj_over_seed(f.cl_kutta_joukowski, sc.spin != 0.0 ? f.cl_seed_estimate : std::nullopt);
  if (f.delta_p_seed_estimate != 0.0) d.delta_p_over_seed = f.delta_p_top_bottom / f.delta_p_seed_estimate;
  d.magnus_S_seed = 4.0 * sc.density * sc.radius * sc.radius;
  return d;
}

double wall_cells(const PolarGrid& g, double reynolds, double alpha) {
  return g.a * boundary_layer_over_a(reynolds, alpha) / (g.r[1] - g.r[0]);
}

ViscousRatios viscous_ratios(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  const ViscousPart& v = *r.viscous;
  ViscousRatios d;
  if (v.reynolds && *v.reynolds > 0.0 && r.grid.r.size() > 1)
    d.wall_cells = wall_cells(r.grid, *v.reynolds, sc.spin_ratio());
  if (v.time_unit > 0.0) {
    d.t_convective = v.t / v.time_unit;
    d.dt_convective = v.dt / v.time_unit;
  }
  if (v.eigenvalue_imag && sc.speed > 0.0) d.eigen_strouhal = std::fabs(*v.eigenvalue_imag) / (2.0 * M_PI);
  if (r.timing.solve_s > 0.0) d.steps_per_second = double(v.steps - v.steps_resumed) / r.timing.solve_s;
  if (sc.speed <= 0.0) {  // still fluid: the potential vortex u_θ = a²ω/r is an exact viscous solution
    const double exact = torque_potential_vortex(sc, v.viscosity > 0.0 ? v.viscosity : sc.viscosity);
    d.torque_potential_vortex = exact;
    if (exact != 0.0) d.torque_over_potential_vortex_minus_1 = v.torque_mean / exact - 1.0;
  }
  return d;
}

double cl_ideal(double alpha) { return -2.0 * M_PI * alpha; }

std::optional<double> share_of_ideal_lift(double cl, double alpha) {
  return alpha != 0.0 ? std::optional<double>(cl / cl_ideal(alpha)) : std::nullopt;
}

double torque_potential_vortex(const Scene& sc, double nu) {
  return -4.0 * M_PI * sc.density * nu * sc.radius * sc.radius * sc.spin;
}

}  // namespace magnus
