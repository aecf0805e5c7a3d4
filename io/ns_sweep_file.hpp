#pragma once
// The viscous S(Re, α) map's table, CSV and HDF5 file (format "magnus-sweep", version 2, model
// "navier-stokes"), reading such files back, and merging shards into one map.
#include <string>
#include <vector>

#include "postproc/navier_stokes/continuation.hpp"

namespace magnus {

/// The table printed on stdout: a heading (case, grid, axes, shard, time) and one line per point.
std::string ns_map_table(const NsMap& m);

/// CSV: one header line (names with units), one line per point; undefined values empty.
std::string ns_map_csv(const NsMap& m);

/// `magnus sweep --json` on a navier-stokes case: one JSON object with the table's figures: model, title,
/// grid, shard, axes, timing, then "columns" (each column's units and description) and "points" (one object
/// per point, each figure {"value", "units"}, null where undefined), and the files written.
std::string ns_map_json(const NsMap& m, const std::vector<std::string>& written);

/// HDF5, format "magnus-sweep" version 2, root model = "navier-stokes": root attributes (case text, shard,
/// shards), /parameters (radius, speed, density, n_theta, n_r, outer_radius), /axes/alpha and
/// /axes/reynolds (the whole map's axes), /timing, and one dataset per column in /sweep (row-major points
/// of the computed rows) with units and a description; undefined values hold the netCDF fill value named
/// by `_FillValue` (never NaN). Atomic. Throws std::runtime_error with one line naming the file.
void write_ns_map_hdf5(const NsMap& m, const std::string& path);

/// Read a file written by write_ns_map_hdf5 (the case is parsed back from its text). Throws
/// std::runtime_error with one line naming the file.
NsMap read_ns_map_hdf5(const std::string& path);

/// One map from shards (paths name them in messages): the same case, grid and axes, the same N, each K
/// once, all K present, each shard's rows those of its K. Throws std::runtime_error with one line.
NsMap merge_ns_maps(const std::vector<NsMap>& shards, const std::vector<std::string>& paths);

}  // namespace magnus
