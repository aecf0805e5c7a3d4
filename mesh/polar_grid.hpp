#pragma once
// The polar grid r_i (i = 0…n_r−1, r_0 = a, r_{n_r−1} = R) × θ_j = 2πj/n_θ (no seam node).
#include <vector>
#include "physics/scene.hpp"

namespace magnus {

struct PolarGrid {
  double a = 1.0;  ///< body radius, m
  int n_r = 0, n_theta = 0;
  Spacing spacing = Spacing::geometric;
  bool stretched = false;     ///< rings clustered at the wall (make_stretched_grid): ξ not uniform
  std::vector<double> r;      ///< radii, m (n_r)
  std::vector<double> xi;     ///< ξ_i = ln(r_i/a) (n_r)
  std::vector<double> theta;  ///< angles, rad (n_θ)
  double d_theta = 0.0;       ///< Δθ = 2π/n_θ

  double outer_radius() const { return r.back(); }
  /// Δξ_{i+1/2} = ξ_{i+1} − ξ_i.
  double d_xi(int i) const { return xi[i + 1] - xi[i]; }
  /// True when ξ is uniform (log-polar spacing).
  bool uniform_in_xi() const { return spacing == Spacing::geometric && !stretched; }
  /// ξ-width of ring i's control volume h_i = (Δξ_{i−1/2} + Δξ_{i+1/2})/2 inside (the mode solver's), the
  /// adjacent spacing on rings 0 and n_r − 1; exactly Δξ = ξ_1 − ξ_0 when ξ is uniform.
  double ring_width(int i) const {
    if (uniform_in_xi() || i == 0) return d_xi(0);
    return i == n_r - 1 ? d_xi(i - 1) : 0.5 * (d_xi(i - 1) + d_xi(i));
  }
  /// Number of nodes n_r·n_θ.
  long nodes() const { return long(n_r) * n_theta; }
};

/// n_r that makes log-polar cells square (Δξ ≈ Δθ), or square cells at the wall for uniform spacing.
int default_n_r(Spacing spacing, double outer_over_a, int n_theta);

/// Geometric: r_i = a·e^{iΔξ}; uniform: r_i = a + iΔr. R = outer_over_a·a.
PolarGrid make_grid(double a, double outer_over_a, int n_r, int n_theta, Spacing spacing);

/// Rings clustered at the wall (geometric in r, stretched in ξ): the smooth map of the ring index s,
///     ξ(s) = Δ_f·s − (Δ_f − Δ_w)·L·(1 − e^{−s/L}),   Δ_w = Δ_f/wall_refinement,  L = wall_layer/Δ_f,
/// whose spacing relaxes from Δ_w at the wall to Δ_f over the ξ-length wall_layer. n_r > 0: Δ_f solved so
/// that ξ(n_r−1) = ln(R/a); n_r = 0: Δ_f = d_far and n_r the fewest rings reaching ln(R/a), then every ξ
/// scaled so that ξ(n_r−1) = ln(R/a) exactly. wall_refinement = 1: make_grid's uniform ξ (the same rings).
PolarGrid make_stretched_grid(double a, double outer_over_a, int n_r, int n_theta, double d_far,
                              double wall_refinement, double wall_layer);

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
