#pragma once
// A scalar field on a polar grid, and its drawing interpolant: a coarse grid is refined (periodic
// trigonometric interpolation in θ, cubic Lagrange interpolation in ln r) before contouring, so that
// contours are smooth curves of the scheme's order rather than polygons between the grid's nodes.
#include <vector>

namespace magnus {

/// A field on a polar grid: values[i·n_θ + j] at (r[i], theta[j]); r ascending, θ_j = 2πj/n_θ.
struct PolarField {
  std::vector<double> r;       ///< ring radii (any length unit, the same as the plot's)
  std::vector<double> theta;   ///< angles, rad, uniform over [0, 2π), no repeated seam
  std::vector<double> values;  ///< row-major (n_r, n_θ)
};

/// The field on the rings up to the first ring at or beyond r_max, refined for drawing: at least
/// min_theta angles (trigonometric interpolation, exact for the grid's Fourier modes) and rings spaced
/// about as finely in ln r as the angles (cubic Lagrange interpolation in ln r). A fine grid is returned
/// with its nodes unchanged. Throws std::invalid_argument when the sizes do not match (n_r ≥ 2, n_θ ≥ 4).
PolarField refine_polar_field(const PolarField& f, double r_max, int min_theta = 256);

/// The field's value at (r, θ) by the same interpolation (cubic in ln r, trigonometric in θ); r is
/// clamped to the grid.
double polar_value(const PolarField& f, double r, double theta);

}  // namespace magnus
