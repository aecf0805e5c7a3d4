#pragma once
#include <vector>

namespace magnus {

/// Finite-difference weights (Fornberg 1988) for the m-th derivative at x0 from nodes x.
std::vector<double> fd_weights(double x0, const std::vector<double>& x, int m);

/// Weights of ∂/∂ξ of order p at every ring of a ξ grid: centred inside, one-sided near the ends.
/// first[i] is the first ring of row i's window; weights[i] has p+1 entries.
struct RadialDerivative {
  int order = 2;
  std::vector<int> first;
  std::vector<std::vector<double>> weights;
};
RadialDerivative radial_derivative(const std::vector<double>& xi, int order);

/// Periodic centred weights of order p (p even) for ∂/∂θ on a uniform grid of spacing h: c_1…c_{p/2},
/// derivative = Σ_m c_m (f_{j+m} − f_{j−m}).
std::vector<double> periodic_derivative(double h, int order);

}  // namespace magnus
