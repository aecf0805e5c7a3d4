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

namespace {

/// ξ(s) of make_stretched_grid for the far spacing d_far (Δ_w = d_far/q, L = layer/d_far).
double stretched_xi(double s, double d_far, double q, double layer) {
  return d_far * s - (1.0 - 1.0 / q) * layer * -std::expm1(-s * d_far / layer);
}

}  // namespace

PolarGrid make_stretched_grid(double a, double outer_over_a, int n_r, int n_theta, double d_far,
                              double wall_refinement, double wall_layer) {
  const double span = std::log(outer_over_a), q = wall_refinement, layer = wall_layer;
  if (!(q >= 1.0) || !(layer > 0.0) || !std::isfinite(q) || !std::isfinite(layer) || !(outer_over_a > 1.0))
    throw std::invalid_argument("make_stretched_grid: need wall_refinement >= 1, wall_layer > 0, R/a > 1");
  if (n_r <= 0) {
    if (!(d_far > 0.0)) throw std::invalid_argument("make_stretched_grid: need d_far > 0 when n_r = 0");
    const double rings = std::ceil(span / d_far - 1e-9) + 1.0;
    if (!(rings <= double(1 << 24)))
      throw std::invalid_argument("make_stretched_grid: more rings than magnus builds (2^24)");
    if (q == 1.0) return make_grid(a, outer_over_a, int(rings), n_theta, Spacing::geometric);
    n_r = 1;
    while (stretched_xi(n_r - 1, d_far, q, layer) < span * (1.0 - 1e-12) && n_r < (1 << 24)) ++n_r;
    n_r = std::max(n_r, 3);
  } else if (q == 1.0) {
    return make_grid(a, outer_over_a, n_r, n_theta, Spacing::geometric);
  } else {
    // ξ(n_r−1) = span: the fixed point of Δ_f = (span + (1 − 1/q)·layer·(1 − e^{−(n_r−1)Δ_f/layer}))/(n_r−1),
    // a contraction (its slope (1 − 1/q)e^{−…} < 1).
    const double last = n_r - 1;
    d_far = span / last;
    for (int it = 0; it < 200; ++it) {
      const double next = (span + (1.0 - 1.0 / q) * layer * -std::expm1(-last * d_far / layer)) / last;
      const bool done = std::fabs(next - d_far) <= 1e-15 * next;
      d_far = next;
      if (done) break;
    }
  }
  PolarGrid g = make_grid(a, outer_over_a, n_r, n_theta, Spacing::geometric);
  g.stretched = true;
  const double scale = span / stretched_xi(n_r - 1, d_far, q, layer);
  for (int i = 0; i < n_r; ++i) {
    g.xi[i] = i + 1 < n_r ? scale * stretched_xi(i, d_far, q, layer) : span;
    g.r[i] = a * std::exp(g.xi[i]);
  }
  g.r.front() = a;
  g.r.back() = a * outer_over_a;
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
