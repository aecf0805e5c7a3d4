#pragma once
// `magnus inspect`: what a result (magnus-flow) or sweep (magnus-sweep) file holds, as text, with units.
#include <string>

namespace magnus {

/// Every attribute and dataset of a magnus-flow file (units from the schema table, io/schema.hpp), or the
/// parameters and columns of a magnus-sweep file (units and ranges); every value is read back, so a damaged
/// file is reported. Versions 1 and 2. Throws std::runtime_error with one line.
std::string describe_result(const std::string& path);

/// The checks of describe_result without the text: every reader of a result or sweep file (compare, plot,
/// probe, the Python module) refuses what `magnus inspect` refuses: the structure, every attribute, every
/// stored value read back through its checksum (the /mesh views of stored datasets are not read twice).
/// Throws std::runtime_error with one line.
void check_result(const std::string& path);

/// The body surface of a magnus-flow file as CSV, one line per angle θ_j: theta_rad, theta_deg, u_theta_m_s,
/// pressure_Pa, cp (empty where undefined: U = 0) and, for navier-stokes results, tau_w_Pa (wall shear
/// stress). Throws std::runtime_error with one line (a sweep file, a missing or damaged surface).
std::string surface_csv(const std::string& path);

}  // namespace magnus
