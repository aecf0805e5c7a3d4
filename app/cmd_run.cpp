// magnus run CASE [-o FILE] [--set k=v]… [--threads N] [-q]
#include <memory>

#include "app/commands.hpp"
#include "app/run.hpp"

namespace magnus {

void add_run_command(CLI::App& app) {
  struct Options {
    std::string case_path, output;
    std::vector<std::string> sets;
    int threads = 1;
    bool quiet = false;
  };
  auto o = std::make_shared<Options>();
  auto* run = app.add_subcommand("run", "solve a case, write HDF5 (+ XDMF), print a summary");
  run->add_option("case", o->case_path, "case file (TOML)")->required();
  run->add_option("-o,--output", o->output, "result file (default: output.file of the case)");
  run->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  run->add_option("--threads", o->threads, "threads for the solver")->check(CLI::Range(1, 64));
  run->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  run->callback([o] { command_run(o->case_path, o->output, o->sets, o->threads, o->quiet); });
}

void add_inspect_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto* inspect = app.add_subcommand("inspect", "show what a result file holds");
  inspect->add_option("file", *path, "result file (HDF5)")->required();
  inspect->callback([path] { command_inspect(*path); });
}

}  // namespace magnus
