#pragma once
#include <array>
#include <vector>

namespace magnus {

/// Finite-difference weights (Fornberg 1988) for the m-th derivative at x0 from nodes x.
std::vector<double> fd_weights(double x0, const std::vector<double>& x, int m);

/// Second-order one-sided weights of f'(x_0) from x_0 and the next two nodes x_1 = x_0 + h1,
/// x_2 = x_1 + h2 (h1, h2 > 0): f'(x_0) ≈ w_0 f_0 + w_1 f_1 + w_2 f_2, 1/length; at the other end (nodes
/// below x_0 at distances h1, h1 + h2) the derivative is −(w_0 f_0 + w_1 f_1 + w_2 f_2).
std::array<double, 3> one_sided_weights(double h1, double h2);

/// Weights of ∂/∂ξ of order p at every ring of a ξ grid: centred inside, one-sided at the ends or,
/// with odd_at_wall, centred near the wall on the odd reflection ψ(−ξ) = −ψ(ξ) (ψ = 0 on the body
/// and ψ harmonic; the symmetric stencils keep that property discretely).
/// Row i uses rings first[i] … first[i] + weights[i].size() − 1.
struct RadialDerivative {
  int order = 2;
  std::vector<int> first;
  std::vector<std::vector<double>> weights;
};
RadialDerivative radial_derivative(const std::vector<double>& xi, int order, bool odd_at_wall);

/// Periodic centred weights of order p (p even) for ∂/∂θ on a uniform grid of spacing h: c_1…c_{p/2},
/// derivative = Σ_m c_m (f_{j+m} − f_{j−m}).
std::vector<double> periodic_derivative(double h, int order);

}  // namespace magnus
