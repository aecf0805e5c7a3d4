#include "mesh/polar_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace magnus {

int default_n_r(Spacing spacing, double outer_over_a, int n_theta) {
  const double d_theta = 2.0 * M_PI / n_theta;
  const double span = spacing == Spacing::geometric ? std::log(outer_over_a) : outer_over_a - 1.0;
  return int(std::min<long>(std::max(3L, std::lround(span / d_theta) + 1), 1L << 30));
}

PolarGrid make_grid(double a, double outer_over_a, int n_r, int n_theta, Spacing spacing) {
  if (!(a > 0.0) || !(outer_over_a > 1.0) || n_r < 3 || n_theta < 4)
    throw std::invalid_argument("make_grid: need a > 0, R/a > 1, n_r >= 3, n_theta >= 4");
  PolarGrid g;
  g.a = a;
  g.n_r = n_r;
  g.n_theta = n_theta;
  g.spacing = spacing;
  g.d_theta = 2.0 * M_PI / n_theta;
  g.r.resize(n_r);
  g.xi.resize(n_r);
  const double log_span = std::log(outer_over_a);
  for (int i = 0; i < n_r; ++i) {
    const double s = double(i) / (n_r - 1);
    if (spacing == Spacing::geometric) {
      g.xi[i] = s * log_span;
      g.r[i] = a * std::exp(g.xi[i]);
    } else {
      g.r[i] = a * (1.0 + s * (outer_over_a - 1.0));
      g.xi[i] = std::log1p(s * (outer_over_a - 1.0));
    }
  }
  g.r.front() = a;
  g.r.back() = a * outer_over_a;
  g.theta.resize(n_theta);
  for (int j = 0; j < n_theta; ++j) g.theta[j] = g.d_theta * j;
  return g;
}

GridShape grid_shape(const GridRequest& c) {
  const double d_theta = 2.0 * M_PI / c.n_theta;
  GridShape s;
  s.n_theta = c.n_theta;
  s.outer_over_a = c.outer_radius;
  if (c.n_r > 0) {
    s.n_r = c.n_r;
  } else if (c.spacing == Spacing::geometric) {
    // Square cells exactly: whole cells of Δξ = Δθ, R rounded up to the next one.
    const long cells = std::max(2L, long(std::ceil(std::log(c.outer_radius) / d_theta - 1e-9)));
    s.n_r = cells + 1;
    s.outer_over_a = std::exp(double(cells) * d_theta);
  } else {
    s.n_r = std::max(3L, std::lround((c.outer_radius - 1.0) / d_theta) + 1);
  }
  return s;
}

PolarGrid make_grid(const GridRequest& c, double a) {
  const GridShape s = grid_shape(c);
  if (s.n_r > (1L << 24))
    throw std::invalid_argument("make_grid: " + std::to_string(s.n_r) +
                                " rings is more than magnus builds (2^24)");
  return make_grid(a, s.outer_over_a, int(s.n_r), c.n_theta, c.spacing);
}

}  // namespace magnus
