#include "postproc/tolerance.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "postproc/pipeline.hpp"

namespace magnus {

namespace {

/// C_L on an n_θ grid with square cells.
double lift_on(Case c, int n_theta, int threads) {
  c.grid.n_theta = n_theta;
  c.grid.n_r = 0;
  return *lift_coefficient(c, threads);
}

double relative(double diff, double cl) { return std::fabs(cl) > 1e-12 ? std::fabs(diff / cl) : std::fabs(diff); }

/// Round-off in C_L on an n_θ grid, which Richardson cannot see: about 0.25·ε·n_θ² (measured by the
/// stability suite: the discrete Laplacian's conditioning times the wall derivative's 1/h).
double roundoff(int n) { return 0.25 * 2.220446049250313e-16 * double(n) * n; }

}  // namespace

GridChoice choose_grid(const Case& base, int threads) {
  const double tol = base.grid.tolerance;
  if (!(base.scene.speed > 0.0))
    throw std::runtime_error("grid.tolerance needs flow.speed > 0: the lift coefficient is undefined at U = 0");
  if (base.grid.far_field == FarField::freestream) {
    const double floor = 1.0 / (base.grid.outer_radius * base.grid.outer_radius);
    if (tol < 2.0 * floor)
      throw std::runtime_error(fmt::format(
          "grid.tolerance = {:.3g} cannot be met with domain.far_field = \"freestream\" at R/a = {:.6g}: its error "
          "floor is (a/R)² = {:.3g}; use far_field = \"exact\" (no floor)", tol, base.grid.outer_radius, floor));
  }
  Case c = base;
  c.solver.stencil = base.grid.spacing == Spacing::geometric ? StencilKind::nine_point : StencilKind::five_point;
  const double p = c.solver.stencil == StencilKind::nine_point ? 6.0 : 2.0;
  const int n_max = 1 << 14;
  GridChoice choice;
  choice.stencil = c.solver.stencil;
  int n = c.solver.stencil == StencilKind::nine_point ? 16 : 32;
  double cl = lift_on(c, n, threads), est_prev = INFINITY, est_best = INFINITY;
  int n_best = n;
  choice.trail = std::to_string(n);
  for (;;) {
    const int n2 = 2 * n;
    if (n2 > n_max)
      throw std::runtime_error(fmt::format("grid.tolerance = {:.3g} needs n_theta > {} (estimate {:.3g} at {})", tol,
                                           n_max, est_prev, n));
    const double cl2 = lift_on(c, n2, threads);
    const double est = relative(cl2 - cl, cl2) / (std::pow(2.0, p) - 1.0) + roundoff(n2);
    choice.trail += " → " + std::to_string(n2);
    if (est <= tol) {
      choice.n_theta = n2;
      choice.estimated_cl_rel = est;
      // Smaller n the order predicts; accept it if it agrees with n2 to within the tolerance.
      int n_star = int(std::ceil(n2 * std::pow(est / tol, 1.0 / p) / 4.0)) * 4;
      n_star = std::max(8, n_star);
      if (n_star < n2) {
        const double cl_star = lift_on(c, n_star, threads);
        const double est_star = relative(cl_star - cl2, cl2) + est + roundoff(n_star);
        choice.trail += " → " + std::to_string(n_star);
        if (est_star <= tol) {
          choice.n_theta = n_star;
          choice.estimated_cl_rel = est_star;
        }
      }
      return choice;
    }
    if (est < est_best) est_best = est, n_best = n2;
    if (est > 0.5 * est_prev && est_prev < 1e-8)
      throw std::runtime_error(fmt::format(
          "grid.tolerance = {:.3g} is below the round-off floor: the best estimated C_L error is {:.3g} "
          "(n_theta = {}); ask for {:.1g} or more", tol, est_best, n_best, est_best * 1.5));
    est_prev = est;
    n = n2;
    cl = cl2;
  }
}

}  // namespace magnus
