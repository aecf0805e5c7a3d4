#pragma once
// Memory guard: what a solve will need, and what the machine has, before anything large is allocated.
#include <cstddef>
#include <string>
#include "solver/potential/stencil.hpp"

namespace magnus {

/// Bytes the solver needs for the operator: FFT: the LU factors (2 doubles per mode and ring) and the
/// spectrum (1 complex); CHOLMOD: the matrix, its assembly triplets and the factor's fill-in,
/// estimated as 4·N·log₂N (nested dissection on a 2D grid; measured 3.1) plus the dense outer ring n²/2.
size_t solver_bytes(const DiscreteOperator& op, Method method);
/// The same from the shape: rings, n_θ, the far field and the stencil.
size_t solver_bytes(double n_r, double n_theta, FarField far_field, StencilKind stencil, Method method);

/// Memory this process may use: MemAvailable from /proc/meminfo, capped by the cgroup limit.
size_t available_bytes();

/// "2G", "512M", "1.5GiB", "800000000" → bytes. Throws std::invalid_argument on anything else.
size_t parse_bytes(const std::string& text);

/// "1.23 GiB".
std::string format_bytes(size_t bytes);

/// Estimates below this are not checked against available_bytes() (an explicit limit still applies), bytes.
constexpr size_t kUncheckedBytes = size_t(16) << 20;

/// Throws std::runtime_error with the estimate if `needed` exceeds `limit` (0: available_bytes(), read
/// only when needed ≥ kUncheckedBytes).
void check_memory(size_t needed, size_t limit, const std::string& what);

/// The memory guard for a grid request, before anything is built, from the grid's shape alone: the solver's
/// bytes plus the ψ-sized arrays a run holds (ψ_U, ψ_Γ, ψ, the exact ψ and `fields` selected fields, n_r·n_θ
/// doubles each). Throws naming the estimate, the grid and the method.
void check_grid_memory(const GridRequest& grid, StencilKind stencil, Method method, int fields, size_t limit);

}  // namespace magnus
