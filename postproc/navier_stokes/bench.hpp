#pragma once
// The cost of a navier-stokes time step (magnus bench on a navier-stokes case): a ladder of grids, each
// stepped from the impulsive start, with the wall time per step split into its parts.
#include <vector>

#include "physics/scene.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// One rung: the grid, Δt and the wall time of the timed steps, per part.
struct NsBenchRow {
  int n_theta = 0, n_r = 0;
  long nodes = 0;
  double dt = 0.0;        ///< time step, s (CFL time.cfl at the start)
  double time_unit = 0.0; ///< D/U_ref, s
  NsStepTimes times;      ///< summed over the timed steps (forces: one evaluation per step)
  double wall_s = 0.0;    ///< the timed steps' wall time, s
  double steps_per_second() const { return wall_s > 0.0 ? double(times.steps) / wall_s : 0.0; }
  /// Wall nanoseconds per node per step, 1e9·wall_s/(steps·nodes) (0 before a step is timed).
  double ns_per_node() const {
    return times.steps > 0 && nodes > 0 ? 1e9 * wall_s / (double(times.steps) * double(nodes)) : 0.0;
  }
};

/// Bytes one time step moves per node, counted from the step's code (solver/navier_stokes/time_step.cpp,
/// stages.cpp, solver/mode_solver.cpp) as STREAM counts them: 8 per real value read or written (a write's
/// read-for-ownership not counted); a spectral array (n_θ/2+1 complex per ring) is 8 bytes per node, a
/// per-mode factor (n_θ/2+1 doubles per ring) 4. A stencil's neighbour rings and an FFT's row stay in cache.
///   right-hand side   56: ψ, ζ read; N^n written; N^{n−1} read; f written; its r2c reads f, writes f̂
///   Helmholtz         60: scale by −h_i (f̂ read, written 16), forward sweep (f̂ read, written, upper 20),
///                         back sweep (f̂ read, written, 1/pivot, upper 24)
///   Poisson           76: −J·ζ̂ into ψ̂ (16), then the same three sweeps (60)
///   wall closure      40: ζ̂ and ψ̂ read and written (32), φ_k and χ_k read (8)
///   back to the grid  64: two c2r (spectrum read, buffer written: 32), both buffers read, ζ and ψ written (32)
///   total            296 bytes/node; the outer ring's boundary and the forces' wall rings are O(n_θ).
/// With each write's read-for-ownership (8 fresh arrays written) the traffic is 360, 1.22× the count; the
/// triad's is 32/24 = 1.33× its count: the quotient of the two counts is near like-for-like (~10% low).
constexpr double kNsStepBytesPerNode = 56 + 60 + 76 + 40 + 64;
/// Bytes per node of the arrays a step touches (its working set): nine real arrays (old and new ψ, ζ, N; f
/// and the two c2r buffers: 72), two spectra (ζ̂, ψ̂: 16), six per-mode factors (1/pivot and upper of the two
/// mode solvers, φ_k, χ_k: 24). Below the last-level cache the step reads from cache, not memory.
constexpr double kNsStepArrayBytesPerNode = 72 + 16 + 24;


/// For each n_θ of the ladder (the case's radial refinement and R kept): `warmup` untimed steps, then `steps`
/// timed ones, forces evaluated after each as in a run, on `threads` threads (advection and mode solves).
std::vector<NsBenchRow> run_ns_bench(const Case& c, const std::vector<int>& ladder, int steps, int warmup = 20,
                                     int threads = 1);

}  // namespace magnus
