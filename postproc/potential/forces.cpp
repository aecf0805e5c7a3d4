#include "postproc/potential/forces.hpp"

#include <algorithm>
#include <cmath>

namespace magnus {

Forces compute_forces(const Scene& scene, const Surface& s) {
  const int n = int(s.theta.size());
  const double a = scene.radius, rho = scene.density, U = scene.speed, omega = scene.spin;
  const double h = 2.0 * M_PI / n;
  Forces f;
  const double mean = s.u_mean;
  double fx = 0.0, fy = 0.0;
  for (int j = 0; j < n; ++j) {
    const double up = s.u_fluct[j];
    const double q = up * (2.0 * mean + up);  // |u|² − ū²
    fx += q * std::cos(s.theta[j]);
    fy += q * std::sin(s.theta[j]);
  }
  f.drag = 0.5 * rho * a * h * fx;
  f.lift = 0.5 * rho * a * h * fy;
  f.circulation_measured = mean * 2.0 * M_PI * a;
  const ExactFlow ex = exact_flow(scene);
  f.lift_kutta_joukowski = ex.lift(rho);
  const auto top = periodic_interpolate(s.u_theta, M_PI / 2);
  const auto bottom = periodic_interpolate(s.u_theta, 3 * M_PI / 2);
  f.delta_p_top_bottom = 0.5 * rho * (bottom - top) * (bottom + top);
  f.delta_p_top_bottom_exact = ex.delta_p_top_bottom(rho);
  f.delta_p_seed_estimate = seed_delta_p(scene);
  if (!scene.circulation_given)
    f.magnus_S_exact = 2.0 * M_PI * rho * a * a;
  else if (omega != 0.0)
    f.magnus_S_exact = rho * scene.Gamma() / omega;
  if (U > 0.0) {
    const double q_ref = 0.5 * rho * U * U * 2.0 * a;
    f.cl = f.lift / q_ref;
    f.cd = f.drag / q_ref;
    f.cl_kutta_joukowski = ex.cl();
    f.cl_seed_estimate = seed_cl(scene);
    if (omega != 0.0) f.magnus_S = -f.lift / (U * omega);
  }
  return f;
}

std::vector<StagnationPoint> find_stagnation_points(
    const PolarGrid& g, const Scene& scene, const std::vector<double>& u,
    const std::function<std::vector<double>(double)>& ray_u_theta) {
  std::vector<StagnationPoint> pts;
  if (scene.speed <= 0.0) return pts;
  const int n = g.n_theta;
  for (int j = 0; j < n; ++j) {
    const double u0 = u[j], u1 = u[(j + 1) % n];
    if (u0 == 0.0 || (u0 < 0.0) != (u1 < 0.0)) {
      const double t = u0 == 0.0 ? 0.0 : u0 / (u0 - u1);
      pts.push_back({g.a, g.theta[j] + t * g.d_theta, true});
    }
  }
  if (!pts.empty()) return sorted_stagnation_points(pts);
  // No zero on the body: a free stagnation point on the y axis, on the side of Γ.
  const double theta = scene.Gamma() > 0.0 ? M_PI / 2 : 3 * M_PI / 2;
  const std::vector<double> ray = ray_u_theta(theta);
  for (int i = 0; i + 1 < g.n_r; ++i)
    if ((ray[i] < 0.0) != (ray[i + 1] < 0.0)) {
      const double t = ray[i] / (ray[i] - ray[i + 1]);
      pts.push_back({g.r[i] + t * (g.r[i + 1] - g.r[i]), theta, false});
      break;
    }
  return pts;
}

double lift_error(const Scene& scene, const Forces& f) {
  const double err = std::fabs(f.lift - f.lift_kutta_joukowski);
  if (f.lift_kutta_joukowski != 0.0) return err / std::fabs(f.lift_kutta_joukowski);
  return scene.speed > 0.0 ? err / (scene.density * scene.speed * scene.speed * scene.radius) : err;
}

Errors compute_errors(const Scene& scene, const std::vector<double>& psi, const std::vector<double>& pe,
                      const Surface& s, const Forces& f) {
  Errors e;
  double dmax = 0.0, emax = 0.0;
  for (size_t q = 0; q < pe.size(); ++q) {
    dmax = std::max(dmax, std::fabs(psi[q] - pe[q]));
    emax = std::max(emax, std::fabs(pe[q]));
  }
  e.psi_max_rel = emax > 0.0 ? dmax / emax : dmax;
  if (!s.cp.empty()) {
    double m = 0.0;
    for (size_t j = 0; j < s.cp.size(); ++j) m = std::max(m, std::fabs(s.cp[j] - s.cp_exact[j]));
    e.cp_surface_max_abs = m;
  }
  if (scene.speed > 0.0) e.cl_rel = lift_error(scene, f);  // U = 0: C_L, and so its error, is undefined
  const double G = scene.Gamma();
  const double scale = G != 0.0            ? std::fabs(G)
                       : scene.speed > 0.0 ? 2.0 * M_PI * scene.radius * scene.speed
                                           : 1.0;
  e.circulation_rel = std::fabs(f.circulation_measured - G) / scale;
  return e;
}

/// θ in [0, 2π): a zero found in the last interval before the seam can land on 2π itself.
double wrap_angle(double theta) {
  double t = std::fmod(theta, 2.0 * M_PI);
  if (t < 0.0) t += 2.0 * M_PI;
  return 2.0 * M_PI - t < 1e-9 ? 0.0 : t;
}
/// Stagnation points with θ in [0, 2π), sorted by θ.
std::vector<StagnationPoint> sorted_stagnation_points(const std::vector<StagnationPoint>& in) {
  std::vector<StagnationPoint> pts = in;
  for (auto& q : pts) q.theta = wrap_angle(q.theta);
  std::sort(pts.begin(), pts.end(), [](const auto& x, const auto& y) { return x.theta < y.theta; });
  return pts;
}

}  // namespace magnus
