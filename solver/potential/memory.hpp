#pragma once
// Memory guard, the potential solve's part: what its solvers will need, from the operator or the grid's shape
// alone (the check itself and the machine's memory: solver/memory.hpp).
#include <cstddef>
#include <string>
#include "solver/memory.hpp"
#include "solver/potential/stencil.hpp"

namespace magnus {

/// Bytes the solver needs for the operator: FFT: the LU factors (2 doubles per mode and ring) and the
/// spectrum (1 complex); CHOLMOD: the matrix, its assembly triplets and the factor's fill-in,
/// estimated as 4·N·log₂N (nested dissection on a 2D grid; measured 3.1) plus the dense outer ring n²/2.
size_t solver_bytes(const DiscreteOperator& op, Method method);
/// The same from the shape: rings, n_θ, the far field and the stencil.
size_t solver_bytes(double n_r, double n_theta, FarField far_field, StencilKind stencil, Method method);

/// The memory guard for a grid request, before anything is built, from the grid's shape alone: the solver's
/// bytes plus the ψ-sized arrays a run holds (ψ_U, ψ_Γ, ψ, the exact ψ and `fields` selected fields, n_r·n_θ
/// doubles each). Throws naming the estimate, the grid and the method.
void check_grid_memory(const GridRequest& grid, StencilKind stencil, Method method, int fields, size_t limit);

}  // namespace magnus
