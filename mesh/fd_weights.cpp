#include "mesh/fd_weights.hpp"

#include <algorithm>

namespace magnus {

std::vector<double> fd_weights(double x0, const std::vector<double>& x, int m) {
  const int n = int(x.size());
  std::vector<std::vector<double>> c(n, std::vector<double>(m + 1, 0.0));
  double c1 = 1.0, c4 = x[0] - x0;
  c[0][0] = 1.0;
  for (int i = 1; i < n; ++i) {
    const int mn = std::min(i, m);
    double c2 = 1.0;
    const double c5 = c4;
    c4 = x[i] - x0;
    for (int j = 0; j < i; ++j) {
      const double c3 = x[i] - x[j];
      c2 *= c3;
      if (j == i - 1) {
        for (int k = mn; k >= 1; --k) c[i][k] = c1 * (k * c[i - 1][k - 1] - c5 * c[i - 1][k]) / c2;
        c[i][0] = -c1 * c5 * c[i - 1][0] / c2;
      }
      for (int k = mn; k >= 1; --k) c[j][k] = (c4 * c[j][k] - k * c[j][k - 1]) / c3;
      c[j][0] = c4 * c[j][0] / c3;
    }
    c1 = c2;
  }
  std::vector<double> w(n);
  for (int i = 0; i < n; ++i) w[i] = c[i][m];
  return w;
}

std::array<double, 3> one_sided_weights(double h1, double h2) {
  return {-(2.0 * h1 + h2) / (h1 * (h1 + h2)), (h1 + h2) / (h1 * h2), -h1 / (h2 * (h1 + h2))};
}

RadialDerivative radial_derivative(const std::vector<double>& xi, int order, bool odd_at_wall) {
  const int n = int(xi.size());
  order = std::min(order, n - 1);  // a grid with fewer rings than the stencil is wide: lower the order
  const int width = order + 1, half = order / 2;
  RadialDerivative d;
  d.order = order;
  d.first.resize(n);
  d.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    if (odd_at_wall && i < half && n > i + half) {
      // Near the wall ψ is odd in ξ about ξ = 0 (ψ = 0 on the body, ψ harmonic): centred weights on
      // the reflected nodes −ξ_m, folded back onto the real node m with a minus sign.
      std::vector<double> x;
      for (int m = i + half; m >= 1; --m) x.push_back(-xi[m]);
      for (int m = 0; m <= i + half; ++m) x.push_back(xi[m]);
      const std::vector<double> w = fd_weights(xi[i], x, 1);
      const int ghosts = i + half;
      std::vector<double> folded(size_t(i + half + 1), 0.0);
      for (int m = 0; m <= i + half; ++m) folded[m] += w[ghosts + m];
      for (int m = 1; m <= ghosts; ++m) folded[m] -= w[ghosts - m];
      d.first[i] = 0;
      d.weights[i] = folded;
      continue;
    }
    const int f = std::clamp(i - half, 0, n - width);
    d.first[i] = f;
    d.weights[i] = fd_weights(xi[i], std::vector<double>(xi.begin() + f, xi.begin() + f + width), 1);
  }
  return d;
}

std::vector<double> periodic_derivative(double h, int order) {
  std::vector<double> x;
  for (int m = -order / 2; m <= order / 2; ++m) x.push_back(m * h);
  const std::vector<double> w = fd_weights(0.0, x, 1);
  return std::vector<double>(w.begin() + order / 2 + 1, w.end());
}

}  // namespace magnus
