#include "postproc/potential/tolerance.hpp"
#include "physics/checked_cast.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "postproc/potential/pipeline.hpp"
#include "solver/memory.hpp"

namespace magnus {

namespace {

/// C_L on an n_θ grid with square cells, after the memory guard (discretize) against max_bytes.
double lift_on(Case c, int n_theta, int threads, size_t max_bytes) {
  c.grid.n_theta = n_theta;
  c.grid.n_r = 0;
  const Discretization d = discretize(c, threads, max_bytes);
  const std::vector<double> psi = d.solver->solve(c.scene.speed, c.scene.Gamma());
  return *compute_forces(c.scene, compute_surface(d.grid, c.scene, psi, derivative_order(c.solver.stencil)))
              .cl;
}

/// n_r·n_θ of the grid with n_θ = n and square cells.
long nodes_of(Case c, int n) {
  c.grid.n_theta = n;
  c.grid.n_r = 0;
  const GridShape g = grid_shape(c.grid);
  return g.n_r * g.n_theta;
}

double relative(double diff, double cl) {
  return std::fabs(cl) > 1e-12 ? std::fabs(diff / cl) : std::fabs(diff);
}

/// Round-off in C_L on an n_θ grid, which Richardson cannot see: about 0.25·ε·n_θ² (measured by the
/// stability suite: the discrete Laplacian's conditioning times the wall derivative's 1/h).
double roundoff(int n) { return 0.25 * 2.220446049250313e-16 * double(n) * n; }

/// Refuses a tolerance no grid can meet: U = 0 (C_L undefined), or below the freestream far field's error
/// floor (a/R)².
void check_reachable(const Case& base) {
  const double tol = base.grid.tolerance;
  if (!(base.scene.speed > 0.0))
    throw std::runtime_error(
        "grid.tolerance needs flow.speed > 0: the lift coefficient is undefined at U = 0");
  if (base.grid.far_field == FarField::freestream) {
    const double floor = 1.0 / (base.grid.outer_radius * base.grid.outer_radius);
    if (tol < 2.0 * floor)
      throw std::runtime_error(
          fmt::format("grid.tolerance = {:.3g} cannot be met with domain.far_field = \"freestream\" at R/a = "
                      "{:.6g}: its error "
                      "floor is (a/R)² = {:.3g}; use far_field = \"exact\" (no floor)",
                      tol, base.grid.outer_radius, floor));
  }
}

/// Refuses the search once the grid the order predicts (n_θ = n_pred) has more than max_nodes nodes,
/// naming the geometric spacing's grid for the tolerance when c's spacing is uniform.
[[noreturn]] void refuse_too_large(const Case& base, const Case& c, int n_pred, int threads, size_t max_bytes,
                                   long max_nodes) {
  const double tol = base.grid.tolerance;
  Case shape = c;
  shape.grid.n_theta = n_pred;
  shape.grid.n_r = 0;
  const GridShape g = grid_shape(shape.grid);
  std::string alternative;
  if (c.grid.spacing == Spacing::uniform) {
    Case geo = base;
    geo.grid.spacing = Spacing::geometric;
    geo.grid.spacing_given = true;
    try {
      const GridChoice gc = choose_grid(geo, threads, max_bytes, max_nodes);
      geo.grid.n_theta = gc.n_theta;
      geo.grid.n_r = 0;
      const GridShape gg = grid_shape(geo.grid);
      alternative =
          fmt::format("; grid.spacing = \"geometric\" (9-point stencil, order 6) meets it with {} × {}",
                      gg.n_theta, gg.n_r);
    } catch (const std::runtime_error&) {
      alternative = "; try grid.spacing = \"geometric\" (9-point stencil, order 6)";
    }
  } else {
    alternative = "; ask for a larger tolerance";
  }
  throw std::runtime_error(
      fmt::format("grid.tolerance = {:g} with grid.spacing = \"{}\" needs about n_θ × n_r = {} × {} "
                  "({:.3g} nodes, {} per "
                  "field), more than the limit of {} nodes{}",
                  tol, to_string(c.grid.spacing), g.n_theta, g.n_r, double(g.n_r) * g.n_theta,
                  format_bytes(size_t(8 * g.n_r * g.n_theta)), max_nodes, alternative));
}

}  // namespace

GridChoice choose_grid(const Case& base, int threads, size_t max_bytes, long max_nodes) {
  const double tol = base.grid.tolerance;
  check_reachable(base);
  Case c = base;
  if (!base.grid.spacing_given) c.grid.spacing = Spacing::geometric;  // 6th order: the smallest grid
  c.solver.stencil = c.grid.spacing == Spacing::geometric ? StencilKind::nine_point : StencilKind::five_point;
  const double p = c.solver.stencil == StencilKind::nine_point ? 6.0 : 2.0;
  const int n_max = 1 << 14;
  GridChoice choice;
  choice.stencil = c.solver.stencil;
  choice.spacing = c.grid.spacing;
  int n = c.solver.stencil == StencilKind::nine_point ? 16 : 32;
  double cl = lift_on(c, n, threads, max_bytes), est_prev = INFINITY, est_best = INFINITY;
  int n_best = n;
  choice.trail = std::to_string(n);
  for (;;) {
    const int n2 = 2 * n;
    if (n2 > n_max)
      throw std::runtime_error(fmt::format(
          "grid.tolerance = {:.3g} needs n_theta > {} (estimate {:.3g} at {})", tol, n_max, est_prev, n));
    const double cl2 = lift_on(c, n2, threads, max_bytes);
    const double est = relative(cl2 - cl, cl2) / (std::pow(2.0, p) - 1.0) + roundoff(n2);
    choice.trail += " → " + std::to_string(n2);
    if (est <= tol) {
      choice.n_theta = n2;
      choice.estimated_cl_rel = est;
      // Smaller n the order predicts; accept it if it agrees with n2 to within the tolerance.
      int n_star = saturate_cast<int>(std::ceil(n2 * std::pow(est / tol, 1.0 / p) / 4.0)) * 4;
      n_star = std::max(8, n_star);
      if (n_star < n2) {
        const double cl_star = lift_on(c, n_star, threads, max_bytes);
        const double est_star = relative(cl_star - cl2, cl2) + est + roundoff(n_star);
        choice.trail += " → " + std::to_string(n_star);
        if (est_star <= tol) {
          choice.n_theta = n_star;
          choice.estimated_cl_rel = est_star;
        }
      }
      return choice;
    }
    // The n the order predicts for the tolerance: refuse at once if that grid is too large.
    const int n_pred = saturate_cast<int>(std::min(double(n_max), std::ceil(n2 * std::pow(est / tol, 1.0 / p) / 4.0) * 4));
    if (nodes_of(c, n_pred) > max_nodes) refuse_too_large(base, c, n_pred, threads, max_bytes, max_nodes);
    if (est < est_best) est_best = est, n_best = n2;
    if (est > 0.5 * est_prev && est_prev < 1e-8)
      throw std::runtime_error(fmt::format(
          "grid.tolerance = {:.3g} is below the round-off floor: the best estimated C_L error is {:.3g} "
          "(n_theta = {}); ask for {:.1g} or more",
          tol, est_best, n_best, est_best * 1.5));
    est_prev = est;
    n = n2;
    cl = cl2;
  }
}

}  // namespace magnus
