#include "postproc/probe.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mesh/fd_weights.hpp"

namespace magnus {

int probe_points(int field_order) { return field_order > 4 ? 6 : 4; }

ProbeStencil probe_stencil(const PolarGrid& g, double x, double y, int points) {
  if (points != 4 && points != 6) throw std::invalid_argument("probe: 4 or 6 interpolation points");
  if (g.n_r < points || g.n_theta < points || int(g.r.size()) != g.n_r)
    throw std::invalid_argument(fmt::format(
        "probe: the grid ({} × {}) is too small for {}-point interpolation", g.n_theta, g.n_r, points));
  if (!std::isfinite(x) || !std::isfinite(y))
    throw std::out_of_range(fmt::format("point ({:g}, {:g}) m is not finite", x, y));
  ProbeStencil s;
  s.points = points;
  s.r = std::hypot(x, y);
  const double a = g.r.front(), R = g.r.back();
  // A point on the body or the outer ring, up to round-off of its coordinates, is inside.
  if (s.r < a * (1.0 - 1e-12) || s.r > R * (1.0 + 1e-12))
    throw std::out_of_range(fmt::format(
        "point ({:g}, {:g}) m is outside the grid: r = {:g} m, the grid spans r = a = {:g} m to R = {:g} m",
        x, y, s.r, a, R));
  s.r = std::clamp(s.r, a, R);
  s.theta = std::atan2(y, x);
  if (s.theta < 0.0) s.theta += 2.0 * M_PI;
  const int half = points / 2;
  // Radial: the `points` rings nearest the point, shifted inwards at the outer edge and outwards at the wall.
  const int i = int(std::upper_bound(g.r.begin(), g.r.end(), s.r) - g.r.begin()) - 1;  // r_i ≤ r
  s.i0 = std::clamp(i - (half - 1), 0, g.n_r - points);
  std::vector<double> nodes(g.r.begin() + s.i0, g.r.begin() + s.i0 + points);
  const std::vector<double> wr = fd_weights(s.r, nodes, 0);
  // Angular: centred on the column interval holding θ, periodic (the angles unwrapped around it).
  const double h = 2.0 * M_PI / g.n_theta;
  const int jc = std::min(int(std::floor(s.theta / h)), g.n_theta - 1);
  std::vector<double> angles(static_cast<size_t>(points));
  for (int k = 0; k < points; ++k) {
    const int jj = jc - (half - 1) + k;
    angles[size_t(k)] = jj * h;
    s.j[size_t(k)] = ((jj % g.n_theta) + g.n_theta) % g.n_theta;
  }
  const std::vector<double> wt = fd_weights(s.theta, angles, 0);
  for (int k = 0; k < points; ++k) s.wr[size_t(k)] = wr[size_t(k)], s.wt[size_t(k)] = wt[size_t(k)];
  return s;
}

double probe_value(const ProbeStencil& s, const std::vector<double>& field, int n_theta) {
  double v = 0.0;
  for (int a = 0; a < s.points; ++a) {
    const size_t row = size_t(s.i0 + a) * size_t(n_theta);
    double ring = 0.0;
    for (int b = 0; b < s.points; ++b) ring += s.wt[size_t(b)] * field[row + size_t(s.j[size_t(b)])];
    v += s.wr[size_t(a)] * ring;
  }
  return v;
}

}  // namespace magnus
