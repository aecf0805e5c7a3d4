#pragma once
// Only what a scene needs: the smallest grid and stencil that meet a requested relative lift error.
#include <string>
#include "physics/scene.hpp"

namespace magnus {

/// The grid a tolerance chose, with the a-posteriori estimate that chose it.
struct GridChoice {
  int n_theta = 0;
  StencilKind stencil = StencilKind::nine_point;
  double estimated_cl_rel = 0.0;  ///< Richardson estimate of the relative C_L error on the chosen grid
  std::string trail;              ///< the grids tried, e.g. "16 → 32 → 64 → 60"
};

/// Choose n_θ and the stencil for c.grid.tolerance > 0 (geometric: 9-point, order 6; uniform: 5-point,
/// order 2) by doubling until the estimate |C_L(2n) − C_L(n)|/(2^p − 1) + 0.25·ε·n² (Richardson plus
/// round-off) meets the tolerance,
/// then shrinking to the n the order predicts if a check against the finer grid confirms it.
/// Throws std::runtime_error naming grid.tolerance when it cannot be met (freestream floor, round-off).
GridChoice choose_grid(const Case& c, int threads = 1);

}  // namespace magnus
