#pragma once
// `magnus probe`'s formats: the grid and fields it reads of a result file, and its table, CSV and JSON of
// the probed points (the interpolation is app/probe.hpp's, through postproc/probe.hpp).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/json_output.hpp"
#include "mesh/polar_grid.hpp"

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

/// What probe reads of a result file: its model and stencil, the grid in the wind frame (r, θ; a = r[0]),
/// the stored (n_r, n_θ) fields and the flow direction β.
struct ProbeFields {
  std::string model, stencil;                  ///< "potential" | "navier-stokes"; "5-point" | "9-point"
  PolarGrid grid;                              ///< r, θ, n_r, n_θ and a only
  std::vector<double> u_x, u_y, pressure, cp;  ///< m/s, Pa, 1 (world frame); cp empty when not stored
  double direction_deg = 0.0;                  ///< β, deg
};

/// Read a magnus-flow file's grid and fields. Throws one line: an unreadable file (what inspect refuses), a
/// field the file does not hold, a field of the wrong size.
ProbeFields read_probe_fields(const std::string& path);

/// The table printed on stdout.
std::string probe_text(const ProbeTable& t);
/// CSV: one header line (names with units) and one line per point; an undefined Cp is empty.
std::string probe_csv(const ProbeTable& t);
/// JSON (io/json_output.hpp's convention).
Json probe_json(const ProbeTable& t);

}  // namespace magnus
