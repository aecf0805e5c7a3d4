#include "io/output_size.hpp"

#include <fmt/core.h>
#include <sys/statvfs.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "postproc/potential/fields.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "solver/memory.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

size_t estimated_output_bytes(long n_r, long n_theta, int fields) {
  return 8 * size_t(n_r) * size_t(n_theta) * size_t(fields + 2) + 8 * (size_t(n_r) + 6 * size_t(n_theta));
}

std::optional<size_t> free_bytes_for(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  struct statvfs s {};
  if (::statvfs(dir.c_str(), &s) != 0) return std::nullopt;
  return size_t(s.f_bavail) * size_t(s.f_frsize);
}

void check_disk_space(const std::string& path, size_t needed, size_t free_bytes, const char* what) {
  if (needed > free_bytes)
    throw std::runtime_error(fmt::format("{}: {} about {}, but only {} is free there", path, what,
                                         format_bytes(needed), format_bytes(free_bytes)));
}

namespace {

/// Bytes HDF5 allocates for a dataset of `rows` rows of `row_values` doubles, chunked as io/hdf5_io.cpp
/// does (whole rows, about 512 KiB a chunk; whole chunks are allocated).
size_t chunked_bytes(size_t rows, size_t row_values) {
  if (rows == 0 || row_values == 0) return 0;
  const size_t row = 8 * row_values;
  const size_t per_chunk = std::max<size_t>(1, std::min(rows, (size_t(512) << 10) / row));
  return (rows + per_chunk - 1) / per_chunk * per_chunk * row;
}

/// Samples of a navier-stokes run's force history: at most time.end/Δt₀ + 2, Δt₀ the start's time step
/// (its flow is the fastest of the run). None for a scene the run refuses (U = 0 and ω = 0, ν = 0).
size_t history_samples(const Case& c, const NsParams& p, const PolarGrid& g) {
  if (!(c.scene.reference_speed() > 0.0) || !(c.scene.viscosity > 0.0)) return 0;
  const double unit = c.scene.time_unit();
  const double dt0 = p.dt > 0.0 ? p.dt : cfl_time_step(p, g, impulsive_start(p, g).psi, p.cfl);
  return dt0 > 0.0 ? size_t(std::min(kNsMaxSteps + 2.0, c.time.end * unit / dt0 + 2.0)) : 0;  // a run takes no more
}

}  // namespace

size_t estimated_run_bytes(const Case& c) {
  const FieldSelection sel = select_fields(c.output.fields, c.model);
  int fields = 0;
  for (bool on : sel.on) fields += on;
  if (c.model != FlowModel::navier_stokes) {
    const GridShape g = grid_shape(c.grid);
    return estimated_output_bytes(g.n_r, g.n_theta, fields);
  }
  const NsParams p = ns_params(c);
  const PolarGrid g = ns_grid(p);
  const size_t n_r = size_t(g.n_r), n_theta = size_t(g.n_theta), nodes = n_r * n_theta;
  const size_t snapshots = size_t(std::max(0, c.output.snapshots)), samples = history_samples(c, p, g);
  const size_t metadata = (size_t(64) << 10) + 2048 * snapshots;  // headers; the mesh's views of snapshots
  // The result: the fields and x, y (n_r × n_θ each), ψ and ζ of the snapshots (each S × n_r × n_θ), the
  // history (8 columns), the axes and the surface.
  const size_t result = size_t(fields + 2) * chunked_bytes(n_r, n_theta) +
                        2 * chunked_bytes(snapshots, nodes) + 8 * chunked_bytes(samples, 1) +
                        8 * (n_r + 6 * n_theta) + metadata;
  // The checkpoint: ψ, ζ and the advection term, the snapshots' ψ and ζ (flat), the history (7 columns).
  const size_t checkpoint = 3 * chunked_bytes(nodes, 1) + 2 * chunked_bytes(snapshots * nodes, 1) +
                            7 * chunked_bytes(samples, 1) + metadata;
  return result + checkpoint;
}

void check_output_space(const Case& c, const std::string& path) {
  if (const std::optional<size_t> free_bytes = free_bytes_for(path))
    check_disk_space(
        path, estimated_run_bytes(c), *free_bytes,
        c.model == FlowModel::navier_stokes ? "the result and its checkpoint need" : "the result needs");
}

}  // namespace magnus
