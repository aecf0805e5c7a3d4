#pragma once
// Before solving: will the result file fit on the disk?
#include <cstddef>
#include <optional>
#include <string>
#include "physics/scene.hpp"

namespace magnus {

/// Bytes of the HDF5 result of a run on an n_r × n_θ grid writing `fields` fields: 8·n_r·n_θ·(fields + 2)
/// (the fields and the grid's x, y) + 8·(n_r + 6·n_θ) (r, θ and the surface arrays), bytes.
size_t estimated_output_bytes(long n_r, long n_theta, int fields);

/// Free bytes for an unprivileged user (statvfs f_bavail·f_frsize) in the directory of `path`; empty if
/// unknown.
std::optional<size_t> free_bytes_for(const std::string& path);

/// Throws std::runtime_error (one line: the estimate and the free space) if `needed` exceeds `free_bytes`;
/// `what` names what needs it ("the result needs", "the result and its checkpoint need").
void check_disk_space(const std::string& path, size_t needed, size_t free_bytes,
                      const char* what = "the result needs");

/// Bytes of a run's files at their largest. Potential flow: the result, estimated_output_bytes on the
/// case's grid. Navier-stokes, on the grid as built (n_r of square cells when grid.n_r is 0), each dataset
/// in whole HDF5 chunks: the result (its fields, output.snapshots × (ψ, ζ), the force history of at most
/// time.end/Δt₀ samples, Δt₀ the start's time step, the smallest of the run) plus the checkpoint beside
/// it (ψ, ζ and the advection term, the snapshots, the history), both of which exist when the result is
/// written.
size_t estimated_run_bytes(const Case& c);

/// The free-space check for a run's output: estimated_run_bytes against free_bytes_for(path).
void check_output_space(const Case& c, const std::string& path);

}  // namespace magnus
