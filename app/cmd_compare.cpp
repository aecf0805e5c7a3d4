// magnus compare FILE… [--csv FILE]
#include <memory>

#include "app/commands.hpp"
#include "io/compare.hpp"

namespace magnus {

void add_compare_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> files;
    std::string csv;
  };
  auto o = std::make_shared<Options>();
  auto* compare =
      app.add_subcommand("compare",
                         "lift coefficients and errors of several results side by side (navier-stokes: the "
                         "viscous means beside the ideal; — where a row is not of a file's model)");
  compare->add_option("files", o->files, "result files (HDF5, from magnus run)")->required();
  compare->add_option("--csv", o->csv, "write the comparison as CSV (one row per file)");
  compare->callback([o] { command_compare(o->files, o->csv); });
}

}  // namespace magnus
