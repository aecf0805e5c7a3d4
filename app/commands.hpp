#pragma once
// Subcommands of magnus: each file app/cmd_*.cpp registers one, with a callback that runs it.
// A callback throws std::exception with one line on failure; main prints it and exits non-zero.
#include <CLI/CLI.hpp>

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
