#pragma once
// Values of stored (n_r, n_θ) fields at points between the nodes: Lagrange interpolation in r through the
// nearest rings and periodic Lagrange interpolation in θ through the nearest columns, each with as many
// points as the fields' order asks for: 4 (cubic, interpolation error O(h⁴)) for the 2nd-order 5-point
// stencil and the navier-stokes model, 6 (quintic, O(h⁶)) for the 6th-order 9-point stencil. The
// interpolation is then never what limits the accuracy: a probed value is as accurate as the stored fields.
#include <array>
#include <vector>

#include "mesh/polar_grid.hpp"

namespace magnus {

/// Where one point falls on the grid and its interpolation weights.
struct ProbeStencil {
  double r = 0.0, theta = 0.0;  ///< the point: radius (m) and angle in [0, 2π) (rad)
  int points = 4;               ///< interpolation points per direction
  int i0 = 0;                   ///< first ring of the radial stencil
  std::array<double, 6> wr{};   ///< radial weights (points of them)
  std::array<int, 6> j{};       ///< columns of the angular stencil
  std::array<double, 6> wt{};   ///< angular weights
};

/// Interpolation points per direction for fields of the given order (2: 4 points; 6: 6 points).
int probe_points(int field_order);

/// The stencil for the point (x, y) in metres. Throws std::out_of_range with one line naming the point
/// when it lies outside the grid (r < a or r > R); std::invalid_argument when the grid is too small
/// (fewer rings or columns than points).
ProbeStencil probe_stencil(const PolarGrid& g, double x, double y, int points);

/// The interpolated value of a row-major (n_r, n_θ) field.
double probe_value(const ProbeStencil& s, const std::vector<double>& field, int n_theta);

}  // namespace magnus
