// magnus run CASE [-o FILE] [--set k=v]… [--threads N] [--onset3d F.h5]… [-q]
#include <fmt/core.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

#include "app/commands.hpp"
#include "app/run_viscous.hpp"
#include "app/threads.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "io/case_keys.hpp"
#include "io/case_file.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/json_output.hpp"
#include "base/output_lock.hpp"
#include "io/output_size.hpp"
#include "io/stability_file.hpp"
#include "io/report.hpp"
#include "io/result_reader.hpp"
#include "solver/memory.hpp"

namespace magnus {

namespace {

/// A navier-stokes run's checkpoint beside its result (OUTPUT.checkpoint.h5), before the run: writable,
/// locked (another output may have the same checkpoint: r.h5, r.hdf), not another scene's unless resumed;
/// then the free space for both (before the checkpoint is read).
void prepare_checkpoint(const Case& c, bool resume, size_t max_bytes, std::optional<OutputLock>& lock) {
  const std::string ckpt = checkpoint_path(c.output.file);
  check_writable(ckpt);
  lock.emplace(ckpt);
  if (!resume) {  // a run from rest overwrites only a checkpoint of its own scene
    const std::string foreign = foreign_checkpoint(ckpt, c);
    if (!foreign.empty()) throw std::runtime_error(foreign);
  }
  // The memory first: the output's size is estimated on the grid itself, which must fit.
  check_resolvable(c, max_bytes);
  check_grid_memory(c, ns_params(c), max_bytes);
  check_output_space(c, c.output.file);
}

void command_run(const std::string& case_path, const std::string& output,
                 const std::vector<std::string>& sets, int threads, bool quiet, size_t max_bytes, bool resume,
                 bool json, const std::vector<std::string>& onset_files) {
  Case c = load_case(case_path, sets);
  RunHooks hooks;
  give_onset3d(hooks, c, onset_files, "--onset3d");  // read (and refused) before solving
  retitle_for_overrides(c, case_path, sets);
  if (!output.empty()) {
    c.output.file = output;
    c.source_text = to_toml(c);
  }
  // Fail before solving, not after: the result, its sidecar, and neither overwriting the case.
  check_distinct_paths({case_path}, {c.output.file, xdmf_path(c.output.file)});
  check_file_writable(c.output.file, "the HDF5 result");
  check_writable(xdmf_path(c.output.file));
  // For the length of the run: a second run to the same output (or checkpoint) is refused, naming this one.
  const OutputLock lock(c.output.file);
  std::optional<OutputLock> checkpoint_lock;
  hooks.threads = threads;
  hooks.max_bytes = max_bytes;
  if (c.model == FlowModel::navier_stokes) {
    prepare_checkpoint(c, resume, max_bytes, checkpoint_lock);
  } else {
    if (resume)
      throw std::runtime_error("--resume: only a navier-stokes case has checkpoints to resume from");
    // The grid first (a tolerance search picks it), then the free space for its file, then the solve.
    hooks.on_plan = [&c](const Case& planned) { check_output_space(planned, c.output.file); };
  }
  int stopped_by = 0;
  const FlowResult r = run_and_report(c, case_path, resume, quiet || json, hooks, &stopped_by);
  // The JSON shows what the summary shows: the result in memory, as the file holds it.
  if (json) std::fputs(json_text(result_json(r, c.output.file)).c_str(), stdout);
  if (stopped_by) throw Interrupted{stopped_by};
}

/// `magnus inspect`: the text (or JSON) on stdout; --surface-csv writes the surface as CSV (atomically, or
/// on stdout for "-", and then stdout carries the CSV alone).
void command_inspect(const std::string& path, bool json, const std::string& surface) {
  if (json && is_stdout(surface))
    throw std::runtime_error(
        "--json and --surface-csv -: both would go to standard output; name a file for one");
  check_distinct_paths({path}, {surface});
  if (!surface.empty()) check_writable(surface);
  // The whole file is read and checked first (inspect's text or JSON), then the CSV written.
  const std::string text = is_stdout(surface) ? std::string()
                           : json             ? json_text(inspect_json(path))
                                              : describe_result(path);
  if (!surface.empty()) write_text_output(surface, surface_csv(path));
  std::fputs(text.c_str(), stdout);
}

}  // namespace

void add_run_command(CLI::App& app) {
  struct Options {
    std::string case_path, output;
    std::vector<std::string> sets;
    int threads = 1;
    bool quiet = false, resume = false, json = false;
    std::string tolerance;
    std::string max_memory;
    std::vector<std::string> onset3d;
  };
  auto o = std::make_shared<Options>();
  auto* run = app.add_subcommand("run", "solve a case, write HDF5 (+ XDMF), print a summary");
  run->add_option("case", o->case_path, "case file (TOML)")->required();
  output_file(run->add_option("-o,--output", o->output, "result file (default: output.file of the case)"));
  add_force_flag(run);
  run->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  run->add_option("--threads", o->threads, "threads for the solver")->check(CLI::Range(1, 64));
  auto* quiet = run->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  run->add_flag("--json", o->json,
                "print one JSON object instead of the summary: every figure with its units ({\"value\": V, "
                "\"units\": U}, null where undefined); see docs/scripting.md")
      ->excludes(quiet);
  run->add_flag("--resume", o->resume,
                "navier-stokes: go on from the case's checkpoint (OUTPUT.checkpoint.h5) instead of from rest");
  run->add_option(
      "--tolerance", o->tolerance,
      "target relative C_L error, 1e-14 to 0.1: choose the smallest grid and stencil (supersedes the "
      "file's grid)");
  run->add_option("--max-memory", o->max_memory, "refuse a run that would need more memory (e.g. 2G, 512M)");
  run->add_option("--onset3d", o->onset3d,
                  "navier-stokes: a computed 3D onset (magnus stability --spanwise --critical-reynolds --output "
                  "FILE.h5; repeat for more α): the summary says whether this 2D flow is real");
  run->callback([o] {
    size_t max_bytes = 0;
    if (!o->max_memory.empty()) {
      try {
        max_bytes = parse_bytes(o->max_memory);
      } catch (const std::exception& e) {
        throw std::runtime_error("--max-memory " + cut_input(o->max_memory) + ": " + e.what());
      }
    }
    std::vector<std::string> sets = o->sets;
    if (!o->tolerance.empty()) {
      char* end = nullptr;
      const double tol = std::strtod(o->tolerance.c_str(), &end);
      if (end == o->tolerance.c_str() || *end != '\0' || !(tol >= 1e-14 && tol <= 0.1))
        throw std::runtime_error(
            fmt::format("--tolerance {}: must be between {:g} and {:g}", cut_input(o->tolerance), 1e-14, 0.1));
      sets.push_back(fmt::format("grid.tolerance={}", tol));
    }
    command_run(o->case_path, o->output, sets, usable_threads(o->threads), o->quiet, max_bytes, o->resume,
                o->json, o->onset3d);
  });
}

void add_inspect_command(CLI::App& app) {
  struct Options {
    std::string path, surface;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  auto* inspect = app.add_subcommand("inspect", "show what a result or sweep file holds, with units");
  inspect->add_option("file", o->path, "result or sweep file (HDF5)")->required();
  inspect->add_flag("--json", o->json, "print one JSON object instead of the text (see docs/scripting.md)");
  add_force_flag(inspect);
  output_file(inspect->add_option("--surface-csv", o->surface,
                      "write the body surface as CSV (θ in rad and degrees, u_θ, p, Cp; τ_w for "
                      "navier-stokes); - for standard output"));
  inspect->callback([o] { command_inspect(o->path, o->json, o->surface); });
}

}  // namespace magnus
