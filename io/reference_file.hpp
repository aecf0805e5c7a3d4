#pragma once
// Reading the published viscous lift data (data/viscous_lift_reference.toml) and finding the data directory.
#include <string>

#include "physics/reference_data.hpp"

namespace magnus {

/// Parse the reference file's TOML text; `origin` names it in messages. Every dataset must carry a
/// citation, a label, a Reynolds number and matching alpha/cl(/cd) arrays. Throws std::runtime_error
/// with one line.
ViscousReference parse_viscous_reference(const std::string& toml_text, const std::string& origin);

/// Read and parse a reference file. Throws std::runtime_error with one line.
ViscousReference load_viscous_reference(const std::string& path);

/// The data directory: $MAGNUS_DATA_DIR if set and non-empty; else the source tree's data/ for the binary
/// in the build tree; else <prefix>/share/magnus/data beside the binary (found from /proc/self/exe).
std::string data_dir();

/// data_dir() + "/viscous_lift_reference.toml".
std::string viscous_reference_path();

}  // namespace magnus
