#pragma once
// Published rotor-sail (Flettner rotor) lift and drag against spin ratio (data/rotor_data.toml): reading
// and checking the file. The data, and what is computed from them, are postproc/rotor_data's.
#include <string>

#include "postproc/rotor_data.hpp"

namespace magnus {

/// Parse the rotor data file's TOML text; `origin` names it in messages. Every dataset needs id, label,
/// citation, source, method, accuracy, reynolds (+ note), geometry, aspect_ratio, end_plates,
/// alpha_range, cl_sign = "magnitude", and either alpha/cl(/cd) arrays inside alpha_range or
/// cl_poly(/cd_poly). Throws std::runtime_error with one line naming the file and the dataset.
RotorData parse_rotor_data(const std::string& toml_text, const std::string& origin);

/// Read and parse a rotor data file. Throws std::runtime_error with one line.
RotorData load_rotor_data(const std::string& path);

/// data_dir() + "/rotor_data.toml".
std::string rotor_data_path();

/// The shipped file, read once; nullptr when it cannot be read (rotor_data_error() says why).
const RotorData* shipped_rotor_data();
/// Why shipped_rotor_data() is null ("" when it is not).
std::string rotor_data_error();

}  // namespace magnus
