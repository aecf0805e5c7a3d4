#pragma once
// Reading a "magnus-sweep" file's lift columns. A stop-gap: io/hdf5_io's ResultFile refuses every
// format but "magnus-flow"; once it accepts "magnus-sweep", this reader should become a few calls to it.
#include <map>
#include <string>
#include <vector>

namespace magnus {

/// What a sweep file holds for a lift plot.
struct SweepFileData {
  std::string format, title, variable;          ///< root attributes ("" when absent)
  std::map<std::string, double> parameters;     ///< numeric /parameters attributes
  std::map<std::string, std::vector<double>> columns;  ///< /sweep/<name> datasets asked for
};

/// The root attributes and parameters of an HDF5 file, and the /sweep columns named (missing ones are
/// left out). Throws std::runtime_error with one line when the file cannot be read.
SweepFileData read_sweep_columns(const std::string& path, const std::vector<std::string>& columns);

}  // namespace magnus
