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

/// Throws std::runtime_error (one line: the estimate and the free space) if `needed` exceeds `free_bytes`.
void check_disk_space(const std::string& path, size_t needed, size_t free_bytes);

/// The free-space check for a run's output: the estimate for the case's resolved grid against
/// free_bytes_for(path). The environment variable MAGNUS_TEST_FREE_BYTES, when set, replaces the measured
/// free space (the tests use it to check the refusal deterministically; it can only make the check stricter
/// or looser, never skip it).
void check_output_space(const Case& c, const std::string& path);

}  // namespace magnus
