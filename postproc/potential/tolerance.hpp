#pragma once
// Only what a scene needs: the smallest grid and stencil that meet a requested relative lift error.
#include <string>
#include "physics/scene.hpp"

namespace magnus {

/// The grid a tolerance chose, with the a-posteriori estimate that chose it.
struct GridChoice {
  int n_theta = 0;
  Spacing spacing = Spacing::geometric;
  StencilKind stencil = StencilKind::nine_point;
  double estimated_cl_rel = 0.0;  ///< Richardson estimate of the relative C_L error on the chosen grid
  std::string trail;              ///< the grids tried, e.g. "16 → 32 → 64 → 60"
};

/// The largest grid (n_r·n_θ nodes) a tolerance search may ask for: 2^22 nodes, 32 MiB per field.
constexpr long tolerance_max_nodes = 1L << 22;

/// Choose the spacing, n_θ and the stencil for c.grid.tolerance > 0. The spacing is geometric (9-point
/// stencil, order 6 for Laplace) unless grid.spacing was stated: stated uniform keeps uniform (5-point, order
/// 2). n_θ doubles until the estimate |C_L(2n) − C_L(n)|/(2^p − 1) + 0.25·ε·n² (Richardson plus round-off)
/// meets the tolerance, then shrinks to the n the order predicts if a check against the finer grid confirms
/// it. Every grid tried passes the memory guard (check_grid_memory against max_bytes; 0: the memory
/// available). Throws std::runtime_error naming grid.tolerance when it cannot be met (freestream floor,
/// round-off), or when the order predicts a grid of more than max_nodes nodes (the message gives that grid
/// and the alternative).
GridChoice choose_grid(const Case& c, int threads = 1, size_t max_bytes = 0,
                       long max_nodes = tolerance_max_nodes);

}  // namespace magnus
