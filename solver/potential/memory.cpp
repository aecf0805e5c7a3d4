#include "solver/potential/memory.hpp"

#include "mesh/polar_grid.hpp"

#include <algorithm>
#include <cmath>

namespace magnus {

size_t solver_bytes(const DiscreteOperator& op, Method method) {
  return solver_bytes(op.n_r, op.n_theta, op.far_field, op.stencil, method);
}

size_t solver_bytes(double n_r, double n, FarField far_field, StencilKind stencil, Method method) {
  const bool exact = far_field == FarField::exact;
  const double L = exact ? n_r - 1 : n_r - 2, n_unknowns = L * n + (exact ? 0 : 1), m = n / 2 + 1;
  if (method == Method::fft) return size_t(std::min(8.0 * 2 * L * m + 16.0 * L * m + 64.0 * n, 1e19));
  const double nnz_a =
      (stencil == StencilKind::nine_point ? 5.0 : 3.0) * n_unknowns + (exact ? n * n / 2 : 1.0);
  const double triplets = 24.0 * nnz_a, matrix = 16.0 * nnz_a;
  const double fill = 4.0 * n_unknowns * std::log2(std::max(n_unknowns, 2.0)) + (exact ? n * n / 2 : 0.0);
  return size_t(std::min(triplets + matrix + 10.0 * fill + 64.0 * n_unknowns, 1e19));
}

void check_grid_memory(const GridRequest& grid, StencilKind stencil, Method method, int fields,
                       size_t limit) {
  const GridShape s = grid_shape(grid);
  const double nr = double(s.n_r), n = double(s.n_theta);
  const double bytes =
      double(solver_bytes(nr, n, grid.far_field, stencil, method)) + 8.0 * nr * n * (4 + fields);
  check_memory(size_t(std::min(bytes, 1e19)), limit,
               "the " + std::string(to_string(method)) + " solve on " + std::to_string(s.n_theta) + " × " +
                   std::to_string(s.n_r) + " with " + std::to_string(fields) +
                   (fields == 1 ? " field" : " fields"));
}

}  // namespace magnus
