#pragma once
// `magnus probe FILE x,y …`: velocity, pressure and Cp of a stored result at points given in metres,
// interpolated from the stored fields (postproc/probe.hpp: 4-point Lagrange in r and θ for 2nd-order
// fields, 6-point for the 9-point stencil's 6th-order ones), as a table, CSV or JSON (io/probe.hpp).
#include <string>
#include <utility>
#include <vector>

#include "io/probe.hpp"

namespace magnus {

/// "x,y" (two finite numbers in metres). Throws std::invalid_argument with one line naming the text.
std::pair<double, double> parse_probe_point(const std::string& text);

/// Probe a magnus-flow file at points (x, y) in metres. Throws one line: an unreadable file, a field the
/// file does not hold, a point outside the grid (naming the point).
ProbeTable probe_file(const std::string& path, const std::vector<std::pair<double, double>>& points);

}  // namespace magnus
