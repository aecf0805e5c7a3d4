// magnus probe FILE x,y [x,y …] [--json] [--csv FILE|-]
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/probe.hpp"
#include "base/atomic_file.hpp"
#include "io/probe.hpp"

namespace magnus {

namespace {

void command_probe(const std::string& file, const std::vector<std::string>& texts, bool json,
                   const std::string& csv) {
  if (json && is_stdout(csv))
    throw std::runtime_error("--json and --csv -: both would go to standard output; name a file for one");
  std::vector<std::pair<double, double>> points;
  for (const auto& t : texts) points.push_back(parse_probe_point(t));
  check_distinct_paths({file}, {csv});
  if (!csv.empty()) check_writable(csv);
  const ProbeTable t = probe_file(file, points);
  if (!csv.empty()) write_text_output(csv, probe_csv(t));
  if (is_stdout(csv)) return;  // stdout carries the CSV alone
  std::fputs((json ? json_text(probe_json(t)) : probe_text(t)).c_str(), stdout);
}

}  // namespace

void add_probe_command(CLI::App& app) {
  struct Options {
    std::string file, csv;
    std::vector<std::string> points;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  auto* probe = app.add_subcommand(
      "probe",
      "velocity (u_x, u_y), pressure and Cp of a result at points x,y in metres, interpolated from the "
      "stored "
      "fields: 4-point (cubic) Lagrange in r and periodic in θ for 2nd-order fields (5-point stencil, "
      "navier-stokes), interpolation error O(h⁴); 6-point (quintic) for the 9-point stencil's 6th-order "
      "fields. A point with r < a or r > R is an error. Negative coordinates: put -- before the points");
  probe->add_option("file", o->file, "result file (HDF5, from magnus run)")->required();
  probe->add_option("points", o->points, "points x,y in metres (e.g. 0.2,0.05)")->required();
  probe->add_flag("--json", o->json, "print one JSON object instead of the table (see docs/scripting.md)");
  output_file(probe->add_option(
      "--csv", o->csv, "write the values as CSV; - for standard output (then nothing else)"));
  add_force_flag(probe);
  probe->callback([o] { command_probe(o->file, o->points, o->json, o->csv); });
}

}  // namespace magnus
