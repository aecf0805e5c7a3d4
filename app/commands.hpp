#pragma once
// Subcommands of magnus: each file app/cmd_*.cpp registers one, with a callback that runs it.
// A callback throws std::exception with one line on failure; main prints it and exits non-zero.
#include <CLI/CLI.hpp>

#include "base/output_owner.hpp"

namespace magnus {

void add_run_command(CLI::App& app);
void add_inspect_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_plot_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_probe_command(CLI::App& app);
void add_merge_command(CLI::App& app);
void add_stability_command(CLI::App& app);

/// --force on a command that writes files: replace an existing output that magnus did not write.
inline void add_force_flag(CLI::App* cmd) {
  cmd->add_flag_callback(
      "--force", [] { set_replace_any_file(true); },
      "replace existing output files even if magnus did not write them (by default only its own outputs, "
      "and empty files, are replaced)");
}

/// An output-file option: an empty name is refused (it would silently mean "no file" or the default).
inline CLI::Option* output_file(CLI::Option* opt) {
  return opt->check(CLI::Validator(
      [](std::string& name) { return name.empty() ? std::string("an empty file name: name a file") : ""; },
      "FILE"));
}

/// Every subcommand.
inline void add_commands(CLI::App& app) {
  add_run_command(app);
  add_inspect_command(app);
  add_sweep_command(app);
  add_compare_command(app);
  add_plot_command(app);
  add_bench_command(app);
  add_probe_command(app);
  add_merge_command(app);
  add_stability_command(app);
}

}  // namespace magnus
