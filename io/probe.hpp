#pragma once
// `magnus probe FILE x,y …`: velocity, pressure and Cp of a stored result at points given in metres,
// interpolated from the stored fields (postproc/probe.hpp: 4-point Lagrange in r and θ for 2nd-order
// fields, 6-point for the 9-point stencil's 6th-order ones), as a table, CSV or JSON.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/json_output.hpp"

namespace magnus {

/// One probed point.
struct ProbeSample {
  double x = 0.0, y = 0.0;      ///< m
  double r = 0.0, theta = 0.0;  ///< m, rad in [0, 2π)
  double u_x = 0.0, u_y = 0.0;  ///< m/s
  double pressure = 0.0;        ///< Pa
  std::optional<double> cp;     ///< undefined when U = 0 (the file holds no Cp field)
};

struct ProbeTable {
  std::string file, model, stencil;
  double radius = 0.0;  ///< a, m
  int field_order = 2;  ///< order of the stored fields
  int points = 4;       ///< interpolation points per direction
  std::vector<ProbeSample> samples;
};

/// "x,y" (two finite numbers in metres). Throws std::invalid_argument with one line naming the text.
std::pair<double, double> parse_probe_point(const std::string& text);

/// Probe a magnus-flow file at points (x, y) in metres. Throws one line: an unreadable file, a field the
/// file does not hold, a point outside the grid (naming the point).
ProbeTable probe_file(const std::string& path, const std::vector<std::pair<double, double>>& points);

/// The table printed on stdout.
std::string probe_text(const ProbeTable& t);
/// CSV: one header line (names with units) and one line per point; an undefined Cp is empty.
std::string probe_csv(const ProbeTable& t);
/// JSON (io/json_output.hpp's convention).
Json probe_json(const ProbeTable& t);

}  // namespace magnus
