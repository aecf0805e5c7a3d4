// magnus: 2D potential flow past a spinning cylinder. Subcommands are thin wrappers over app/run.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "app/run.hpp"

int main(int argc, char** argv) {
  CLI::App app{"magnus: potential flow past a spinning cylinder (Magnus lift, Kutta–Joukowski, the seed estimate)"};
  app.set_version_flag("--version", std::string("magnus ") + MAGNUS_VERSION);
  app.require_subcommand(1);

  std::string case_path, output;
  std::vector<std::string> sets;
  int threads = 1;
  bool quiet = false;
  auto* run = app.add_subcommand("run", "solve a case, write HDF5 (+ XDMF), print a summary");
  run->add_option("case", case_path, "case file (TOML)")->required();
  run->add_option("-o,--output", output, "result file (default: output.file of the case)");
  run->add_option("--set", sets, "override a case key: section.key=value (repeatable)");
  run->add_option("--threads", threads, "threads for the solver")->check(CLI::Range(1, 64));
  run->add_flag("-q,--quiet", quiet, "print nothing on success");

  std::string result_path;
  auto* inspect = app.add_subcommand("inspect", "show what a result file holds");
  inspect->add_option("file", result_path, "result file (HDF5)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "magnus: %s (see magnus --help)\n", e.what());
    return 2;
  }
  try {
    if (*run) return magnus::command_run(case_path, output, sets, threads, quiet);
    if (*inspect) return magnus::command_inspect(result_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "magnus: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
