#pragma once
// What the navier-stokes model can resolve at all: the boundary layer's thickness D/√(Re(1 + α²)) against
// the first ring of the log-polar grid, and the memory of the coarsest grid that puts enough cells across it.
#include <cstddef>

#include "physics/scene.hpp"

namespace magnus {

/// Wall cells across D/√(Re(1 + α²)) below which no grid is offered: with fewer the forces are off by tens
/// of per cent (C_D +12% at 4.5 cells, Re 100, α 2; the wrong sign of C_L below one cell).
constexpr double kWallCellsNeeded = 2.0;

/// Bytes per node of a march without snapshots (ψ, ζ, the FFT modes' LU factors, the advection and the
/// force history): /usr/bin/time -v gave 26 MB at n_θ 96 (11 328 nodes), 161 MB at n_θ 768 (722 000),
/// i.e. 190 B per node above the program's own 24 MB.
constexpr double kMarchBytesPerNode = 200.0;

/// The companion run of the error estimate (the grid twice as coarse, a quarter of the nodes) beside it:
/// its bytes as a share of the run's march.
constexpr double kCompanionBytesShare = 0.25;

/// Bytes of a march on `nodes` nodes with its companion, keeping `snapshots` snapshots (16 B per node each).
double march_bytes(double nodes, int snapshots);

/// The limit an estimate of `bytes` passes, or 0 when it fits: `limit` when given (> 0), else the memory
/// available (read only for estimates of kUncheckedBytes or more).
size_t passed_limit(double bytes, size_t limit);

/// The coarsest navier-stokes grid of the case's cell shape (Δξ = Δθ/(5/3), R/a as given) that puts
/// `cells` cells of its first ring across D/√(Re(1 + α²)): Δξ = ln(1 + 2/(cells·√(Re(1 + α²)))).
struct ResolvingGrid {
  double n_theta = 0.0, n_r = 0.0;  ///< points in θ (even), rings
  double nodes = 0.0;               ///< n_θ·n_r
  double bytes = 0.0;  ///< a march on it with the case's output.snapshots and its companion, bytes
};
/// Needs U > 0 (Re defined), cells > 0.
ResolvingGrid resolving_grid(const Case& c, double cells);

/// Throws std::invalid_argument (one line, naming flow.reynolds or flow.viscosity) when even the coarsest
/// grid with kWallCellsNeeded wall cells needs more than `limit` bytes (0: the memory available): the 2D
/// laminar model cannot resolve the scene here. Still fluid (U = 0) is not checked.
void check_resolvable(const Case& c, size_t limit = 0);

}  // namespace magnus
