#pragma once
// The polar grid r_i (i = 0…n_r−1, r_0 = a, r_{n_r−1} = R) × θ_j = 2πj/n_θ (no seam node).
#include <vector>
#include "physics/scene.hpp"

namespace magnus {

struct PolarGrid {
  double a = 1.0;  ///< body radius, m
  int n_r = 0, n_theta = 0;
  Spacing spacing = Spacing::geometric;
  std::vector<double> r;      ///< radii, m (n_r)
  std::vector<double> xi;     ///< ξ_i = ln(r_i/a) (n_r)
  std::vector<double> theta;  ///< angles, rad (n_θ)
  double d_theta = 0.0;       ///< Δθ = 2π/n_θ

  double outer_radius() const { return r.back(); }
  /// Δξ_{i+1/2} = ξ_{i+1} − ξ_i.
  double d_xi(int i) const { return xi[i + 1] - xi[i]; }
  /// True when ξ is uniform (log-polar spacing).
  bool uniform_in_xi() const { return spacing == Spacing::geometric; }
  /// Number of nodes n_r·n_θ.
  long nodes() const { return long(n_r) * n_theta; }
};

/// n_r that makes log-polar cells square (Δξ ≈ Δθ), or square cells at the wall for uniform spacing.
int default_n_r(Spacing spacing, double outer_over_a, int n_theta);

/// Geometric: r_i = a·e^{iΔξ}; uniform: r_i = a + iΔr. R = outer_over_a·a.
PolarGrid make_grid(double a, double outer_over_a, int n_r, int n_theta, Spacing spacing);

/// The (n_r, n_θ) of the grid a request asks for, without building it (64-bit: a uniform grid far out can
/// ask for more rings than an int holds; the memory guard refuses it before anything is allocated).
struct GridShape {
  long n_r = 0, n_theta = 0;
  double outer_over_a = 0.0;  ///< R/a as built (geometric square cells round it up)
};
GridShape grid_shape(const GridRequest& c);

/// The grid a request asks for, for a body of radius a (m). n_r = 0: geometric spacing gets exactly square
/// cells (Δξ = Δθ, R rounded up to a whole cell, so R ≥ the R asked for); uniform spacing gets default_n_r.
PolarGrid make_grid(const GridRequest& c, double a);

}  // namespace magnus
