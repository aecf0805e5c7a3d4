#include "physics/exact.hpp"

#include <cmath>
#include <utility>

namespace magnus {

double ExactFlow::psi(double r, double theta) const {
  return U * (r - a * a / r) * std::sin(theta) - Gamma / (2.0 * M_PI) * std::log(r / a);
}

double ExactFlow::u_r(double r, double theta) const { return U * (1.0 - a * a / (r * r)) * std::cos(theta); }

double ExactFlow::u_theta(double r, double theta) const {
  return -U * (1.0 + a * a / (r * r)) * std::sin(theta) + Gamma / (2.0 * M_PI * r);
}

double ExactFlow::cp(double r, double theta) const {
  const double ur = u_r(r, theta), ut = u_theta(r, theta);
  return 1.0 - (ur * ur + ut * ut) / (U * U);
}

double ExactFlow::delta_p_top_bottom(double rho) const { return 4.0 * rho * U * Gamma / (2.0 * M_PI * a); }

std::vector<StagnationPoint> ExactFlow::stagnation_points() const {
  if (U <= 0.0) return {};
  const double s = Gamma / (4.0 * M_PI * a * U);  // sinθ_s; spin model: α/2
  // |s| = 1 within round-off (α = 2 gives s = 1 ± ε): the double root on the surface at θ = ±π/2.
  if (std::fabs(std::fabs(s) - 1.0) <= 1e-12) return {{a, s > 0 ? M_PI / 2 : 3 * M_PI / 2, true}};
  if (std::fabs(s) < 1.0) {
    double t1 = std::asin(s), t2 = M_PI - t1;
    if (t1 < 0.0) t1 += 2.0 * M_PI;
    if (t2 < t1) std::swap(t1, t2);  // sorted by θ in [0, 2π): backspin puts asin(s) + 2π last
    return {{a, t1, true}, {a, t2, true}};
  }
  // Free point on the y axis: r_s = a(|2s| + √(4s² − 4))/2, above for Γ > 0.
  const double al = 2.0 * std::fabs(s);
  const double rs = a * (al + std::sqrt(al * al - 4.0)) / 2.0;
  return {{rs, s > 0 ? M_PI / 2 : 3 * M_PI / 2, false}};
}

std::vector<double> ExactFlow::psi_field(const std::vector<double>& r,
                                         const std::vector<double>& theta) const {
  const size_t n_theta = theta.size();
  std::vector<double> out(r.size() * n_theta);
  std::vector<double> sn(n_theta);
  for (size_t j = 0; j < n_theta; ++j) sn[j] = std::sin(theta[j]);
  for (size_t i = 0; i < r.size(); ++i) {
    const double radial = U * (r[i] - a * a / r[i]), circ = -Gamma / (2.0 * M_PI) * std::log(r[i] / a);
    double* row = &out[i * n_theta];
    for (size_t j = 0; j < n_theta; ++j) row[j] = radial * sn[j] + circ;
  }
  return out;
}

ExactFlow exact_flow(const Scene& s) { return ExactFlow{s.radius, s.speed, s.Gamma()}; }

double seed_delta_p(const Scene& s) { return 2.0 * s.density * s.speed * s.radius * s.spin; }
double seed_cl(const Scene& s) { return -4.0 * s.spin_ratio(); }

}  // namespace magnus
