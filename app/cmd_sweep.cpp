// magnus sweep CASE (--spin-ratio A:B:STEP | --circulation A:B:STEP) [--set k=v]… [--csv FILE]
//              [-o FILE.h5] [--plot FILE.png] [--size WxH] [--threads N] [-q]
#include <memory>

#include "app/commands.hpp"
#include "app/sweep.hpp"

namespace magnus {

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  auto* sweep = app.add_subcommand(
      "sweep", "lift against spin ratio (or circulation) by superposition: two solves for any number of points");
  sweep->add_option("case", o->case_path, "case file (TOML)")->required();
  auto* spin = sweep->add_option("--spin-ratio", o->spin_ratio, "spin ratios α = aω/U: A:B:STEP (A ≤ B, STEP > 0)");
  auto* circ = sweep->add_option("--circulation", o->circulation,
                                 "circulations Γ (m²/s) for circulation.model = \"given\": A:B:STEP");
  spin->excludes(circ);
  sweep->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  sweep->add_option("--csv", o->csv, "write the table as CSV");
  sweep->add_option("-o,--output", o->output, "write the table as HDF5 (format magnus-sweep)");
  sweep->add_option("--plot", o->plot, "draw C_L(α) as PNG");
  sweep->add_option("--size", o->size, "PNG size WxH in pixels (default 1000x800)");
  sweep->add_option("--threads", o->threads, "threads for the solver")->check(CLI::Range(1, 64));
  sweep->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  sweep->callback([o] { command_sweep(*o); });
}

}  // namespace magnus
