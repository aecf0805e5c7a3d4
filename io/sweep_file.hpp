#pragma once
// `magnus sweep`'s inputs and outputs: the A:B:STEP range, the table, the CSV and the HDF5 file
// (format "magnus-sweep").
#include <string>
#include <vector>

#include "physics/reference_data.hpp"
#include "postproc/potential/sweep.hpp"

namespace magnus {

/// An inclusive range A:B:STEP as given on the command line, expanded.
struct SweepRange {
  double first = 0.0, last = 0.0, step = 0.0;
  std::vector<double> values;  ///< first, first + step, … ≤ last (+ a rounding allowance)
};

/// Largest number of points a sweep accepts.
constexpr long kMaxSweepPoints = 100000;

/// Parse "A:B:STEP" (A ≤ B, STEP > 0, all finite, at most kMaxSweepPoints values). `option` names the
/// option in messages. Throws std::invalid_argument with one line.
SweepRange parse_sweep_range(const std::string& text, const std::string& option);

/// The table printed on stdout: a heading with the case, grid, solver and timing, then one aligned
/// line per point with units in the header.
std::string sweep_table(const SweepResult& s);

/// CSV, one header line (names with units) and one line per point; undefined values are empty.
std::string sweep_csv(const SweepResult& s);

/// HDF5 (format "magnus-sweep", version 2): root attributes, /parameters and /timing (each numeric attribute
/// NAME with its unit in NAME_units), and one dataset per column in /sweep with `units` and `description`;
/// angles in rad. Never NaN: a column undefined at every point is not stored and is listed in
/// /sweep@undefined; a column undefined at some points holds 9.969209968386869e36 there, named by its
/// `_FillValue` attribute (the netCDF convention: xarray masks it). Written beside the target under a
/// temporary name, then renamed. Throws std::runtime_error with one line naming the file.
void write_sweep_hdf5(const SweepResult& s, const std::string& path);

/// Viscous reference points within the swept α range beside potential flow's −2πα ("" if none).
std::string sweep_reference_text(const SweepResult& s, const ViscousReference& ref);

}  // namespace magnus
