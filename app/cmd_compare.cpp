// magnus compare FILE… [--csv FILE] [--json]
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/compare.hpp"
#include "base/atomic_file.hpp"
#include "io/compare.hpp"
#include "io/json_output.hpp"

namespace magnus {

namespace {

/// `magnus compare --json`: the JSON on stdout instead of the table; the CSV as without --json.
void command_compare_json(const std::vector<std::string>& paths, const std::string& csv) {
  if (is_stdout(csv))
    throw std::runtime_error("--json and --csv -: both would go to standard output; name a file for one");
  check_distinct_paths(paths, {csv});
  if (!csv.empty()) check_writable(csv);
  const Comparison c = compare_results(paths);
  const std::string text = json_text(compare_json(paths, c));
  if (!csv.empty()) write_text_output(csv, c.csv);
  std::fputs(text.c_str(), stdout);
}

}  // namespace

void add_compare_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> files;
    std::string csv;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  auto* compare =
      app.add_subcommand("compare",
                         "lift coefficients and errors of several results side by side (navier-stokes: the "
                         "viscous means beside the ideal; — where a row is not of a file's model)");
  compare->add_option("files", o->files, "result files (HDF5, from magnus run)")->required();
  output_file(compare->add_option("--csv", o->csv, "write the comparison as CSV (one row per file)"));
  add_force_flag(compare);
  compare->add_flag("--json", o->json,
                    "print one JSON object instead of the table: per file every stored figure with its "
                    "units, and the parameters that differ (see docs/scripting.md)");
  compare->callback([o] {
    if (o->json)
      command_compare_json(o->files, o->csv);
    else
      command_compare(o->files, o->csv);
  });
}

}  // namespace magnus
