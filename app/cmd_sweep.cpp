// magnus sweep CASE (--spin-ratio A:B:STEP | --circulation A:B:STEP) [--set k=v]… [--csv FILE]
//              [-o FILE.h5] [--plot FILE.png] [--size WxH] [--threads N] [-q]
// navier-stokes: magnus sweep CASE --spin-ratio A:B:STEP [--reynolds A:B:STEP] [--shard K/N] [--steady-only]
//               magnus sweep CASE --reynolds A:B:STEP …  (the case's spin ratio, continued in Re)
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>

#include "app/commands.hpp"
#include "app/plot_files.hpp"
#include "io/case_file.hpp"
#include "io/case_keys.hpp"
#include "io/hdf5_io.hpp"
#include "io/json_output.hpp"
#include "io/ns_sweep_file.hpp"
#include "io/reference_file.hpp"
#include "io/rotor_data.hpp"
#include "io/sweep_file.hpp"
#include "plot/curves.hpp"
#include "plot/ns_map_plot.hpp"

namespace magnus {

namespace {

/// The options of `magnus sweep`: exactly one of spin_ratio / circulation non-empty.
struct SweepOptions {
  std::string case_path, spin_ratio, circulation, csv, output, plot, size, reynolds, shard;
  std::vector<std::string> sets;
  int threads = 1;
  bool quiet = false, json = false, steady_only = false, no_error_bars = false, orbits = false;
  std::string stability = "eigenvalues";
};

/// Before solving: the outputs are writable, none overwrites the case or another output, and only the CSV
/// may be "-" (standard output). Throws one line naming the path.
void check_outputs(const SweepOptions& o) {
  check_distinct_paths({o.case_path}, {o.csv, o.output, o.plot});
  check_writable(o.csv);
  check_file_writable(o.output, "the HDF5 sweep file");
  check_file_writable(o.plot, "the PNG plot");
}

/// "K/N" with 1 ≤ K ≤ N (whole numbers); throws std::invalid_argument with one line.
std::pair<int, int> parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  auto whole = [&](const std::string& s, int& v) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) return false;
    v = std::stoi(s);
    return true;
  };
  int k = 0, n = 0;
  if (slash == std::string::npos || !whole(text.substr(0, slash), k) || !whole(text.substr(slash + 1), n) ||
      k < 1 || k > n)
    throw std::invalid_argument(
        fmt::format("--shard '{}': expected K/N with whole numbers 1 ≤ K ≤ N (e.g. 2/4)", cut_input(text)));
  return {k, n};
}

/// The navier-stokes path: continuation of the steady branch per Re row, the S(Re, α) map.
void command_ns_sweep(const SweepOptions& o, const Case& c, const SweepRange& alphas) {
  NsMapOptions mo;
  mo.alphas = alphas.values;
  if (!o.reynolds.empty()) mo.reynolds = parse_sweep_range(o.reynolds, "--reynolds").values;
  for (double re : mo.reynolds)
    if (!(re >= kNsMinReynolds))
      throw std::invalid_argument(fmt::format(
          "--reynolds {}: Re = {:g} is below {:g}, the floor of the navier-stokes model (the viscous length D/Re "
          "would exceed {:g} D)",
          o.reynolds, re, kNsMinReynolds, 1.0 / kNsMinReynolds));
  if (!o.shard.empty()) std::tie(mo.shard, mo.shards) = parse_shard(o.shard);
  // Bad shards fail before any solve.
  shard_rows(mo.reynolds.empty() ? 1 : int(mo.reynolds.size()), mo.shard, mo.shards);
  if (o.json && is_stdout(o.csv))
    throw std::runtime_error("--json and --csv -: both would go to standard output; name a file for one");
  if (!o.quiet && !o.json && is_stdout(o.csv))
    throw std::runtime_error("--csv -: add -q (the table also goes to standard output)");
  check_outputs(o);
  const PlotSize size = o.size.empty() ? PlotSize{} : parse_plot_size(o.size);
  if (!o.plot.empty() && std::all_of(mo.alphas.begin(), mo.alphas.end(), [](double a) { return a == 0.0; }))
    throw std::runtime_error(fmt::format(
        "--plot {}: the plot shows S/(2πρa²) = C_L/C_L,ideal, undefined at α = 0 (the ideal lift is 0): "
        "give spin ratios above 0, or leave out --plot",
        o.plot));
  if (o.orbits && o.steady_only)
    throw std::runtime_error("--orbits and --steady-only: --orbits computes the shedding points that --steady-only "
                             "leaves out; give one of them");
  mo.threads = o.threads;
  mo.orbits = o.orbits;
  if (!o.steady_only) {
    mo.stability = make_stability_hook(o.stability == "march" ? StabilityMethod::march : StabilityMethod::eigenvalues);
    mo.stability_method = o.stability;
  }
  mo.average_unstable = !o.steady_only;
  mo.error_estimate = !o.no_error_bars;
  if (!o.quiet)
    mo.on_point = [](const NsMapPoint& p) {
      const std::string orbit =
          fmt::format(", the shedding orbit (from {}, {:.0f} periods of time steps)", p.orbit_start, p.orbit_periods);
      std::fprintf(stderr, "magnus: Re %g, α %.4g: %s%s (%.2f s)\n", p.reynolds, p.alpha,
                   p.converged ? "steady" : (p.fold ? "fold" : "no steady state"),
                   p.regime == double(MapRegime::bistable)
                       ? ", stable, and the shedding orbit continued here persists: bistable"
                   : p.source == MapSource::marched_steady ? ", unstable: marched from rest to another steady state"
                   : p.source == MapSource::orbit        ? orbit.c_str()
                   : p.source == MapSource::steady || p.source == MapSource::none ? ""
                                                                                 : ", time-averaged",
                   p.seconds);
    };
  const NsMap m = ns_map(c, mo);
  // The plot first: it is the one output that can still find nothing to draw (no point with a lift).
  if (!o.plot.empty()) plot_ns_map(m, o.plot, size);
  if (!o.csv.empty()) write_text_output(o.csv, ns_map_csv(m));
  if (!o.output.empty()) write_ns_map_hdf5(m, o.output);
  std::vector<std::string> written;
  for (const std::string* p : {&o.csv, &o.output, &o.plot})
    if (!p->empty() && !is_stdout(*p)) written.push_back(*p);
  if (o.json) {
    std::fputs(ns_map_json(m, written).c_str(), stdout);
    return;
  }
  if (o.quiet) return;
  std::string text = ns_map_table(m);
  if (!written.empty()) {
    std::string list;
    for (const auto& w : written) list += (list.empty() ? "" : ", ") + w;
    text += fmt::format("\n{:<13}{}\n", "output", list);
  }
  std::fputs(text.c_str(), stdout);
}

/// `--reynolds` alone: a navier-stokes case's own spin ratio, continued in Re.
void command_ns_reynolds_sweep(const SweepOptions& o) {
  Case c = load_case(o.case_path, o.sets);
  retitle_for_overrides(c, o.case_path, o.sets);
  if (c.model != FlowModel::navier_stokes)
    throw std::runtime_error(fmt::format(
        "{}: --reynolds alone sweeps a navier-stokes case; a potential case needs --spin-ratio or --circulation",
        o.case_path));
  if (!(c.scene.speed > 0.0))
    throw std::runtime_error("flow.speed: a sweep in Re needs U > 0 (Re = U·2a/ν)");
  SweepRange alpha;
  alpha.values = {c.scene.spin_ratio()};
  alpha.first = alpha.last = alpha.values.front();
  command_ns_sweep(o, c, alpha);
}

void command_sweep(const SweepOptions& o) {
  const bool by_spin = !o.spin_ratio.empty();
  if (!by_spin && o.circulation.empty() && !o.reynolds.empty()) return command_ns_reynolds_sweep(o);
  if (by_spin == !o.circulation.empty())
    throw std::invalid_argument(
        "sweep: give exactly one of --spin-ratio A:B:STEP and --circulation A:B:STEP (or, for a "
        "navier-stokes case, --reynolds A:B:STEP alone)");
  const SweepRange range =
      parse_sweep_range(by_spin ? o.spin_ratio : o.circulation, by_spin ? "--spin-ratio" : "--circulation");
  const PlotSize size = o.size.empty() ? PlotSize{} : parse_plot_size(o.size);
  // The sweep sets the spin (or Γ) itself: the file need not state one. Given first, the file's own spin
  // key (if any) and --set still replace it (one key of the spin group replaces the others).
  std::vector<std::string> sets;
  if (by_spin) sets.push_back(fmt::format("cylinder.spin_ratio={}", range.values.front()));
  sets.insert(sets.end(), o.sets.begin(), o.sets.end());
  Case c = load_case(o.case_path, sets);
  retitle_for_overrides(c, o.case_path, o.sets);  // the user's --set, not the sweep's own spin
  if (c.model == FlowModel::navier_stokes) {
    if (!by_spin)
      throw std::runtime_error("--circulation: a navier-stokes sweep varies the spin ratio (--spin-ratio)");
    return command_ns_sweep(o, c, range);
  }
  if (!o.reynolds.empty() || !o.shard.empty() || o.steady_only || o.stability != "eigenvalues" || o.no_error_bars ||
      o.orbits)
    throw std::runtime_error(fmt::format(
        "{}: --reynolds, --shard, --steady-only, --stability, --no-error-bars and --orbits need a navier-stokes case",
        o.case_path));
  if (o.json && is_stdout(o.csv))
    throw std::runtime_error("--json and --csv -: both would go to standard output; name a file for one");
  // Fail before solving, not after.
  check_outputs(o);
  const SweepResult s =
      by_spin ? sweep_spin_ratio(c, range.values, o.threads) : sweep_circulation(c, range.values, o.threads);

  std::optional<ViscousReference> ref;
  std::string ref_error;
  if (by_spin) {
    try {
      ref = load_viscous_reference(viscous_reference_path());
    } catch (const std::exception& e) {
      ref_error = e.what();
    }
  }
  if (!o.csv.empty()) write_text_output(o.csv, sweep_csv(s));
  if (!o.output.empty()) write_sweep_hdf5(s, o.output);
  if (!o.plot.empty()) {
    // The curves come from physics/ (lift_figure): the plot only draws them.
    LiftSweep l;
    l.by_circulation = !by_spin;
    l.base = s.base.scene;
    l.title = s.base.title;
    l.n_theta = s.grid.n_theta;
    l.n_r = s.grid.n_r;
    for (const auto& p : s.points) {
      const SweepRow w = sweep_row(s, p);
      l.x.push_back(by_spin ? w.alpha : w.circulation);
      l.cl.push_back(w.cl);
    }
    const CurveFigure f = lift_figure(l, ref ? &*ref : nullptr, shipped_rotor_data());
    plot_curves(f.page, f.lines, f.points, o.plot, size);
  }
  if (!ref_error.empty() && (!o.quiet || !o.plot.empty()))
    std::fprintf(stderr, "magnus: note: viscous reference data not shown: %s\n", ref_error.c_str());
  if (o.quiet) return;
  std::vector<std::string> written;
  for (const std::string* p : {&o.csv, &o.output, &o.plot})
    if (!p->empty()) written.push_back(*p);
  if (o.json) {
    std::fputs(json_text(sweep_json(s, ref ? &*ref : nullptr, written)).c_str(), stdout);
    return;
  }
  std::string text = sweep_table(s);
  if (ref) text += sweep_reference_text(s, *ref);
  if (!written.empty()) {
    std::string list;
    for (const auto& w : written) list += (list.empty() ? "" : ", ") + w;
    text += fmt::format("\n{:<13}{}\n", "output", list);
  }
  std::fputs(text.c_str(), stdout);
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  auto* sweep = app.add_subcommand(
      "sweep",
      "lift against spin ratio (or circulation) by superposition: two solves for any number of points");
  sweep->add_option("case", o->case_path, "case file (TOML)")->required();
  auto* spin =
      sweep->add_option("--spin-ratio", o->spin_ratio, "spin ratios α = aω/U: A:B:STEP (A ≤ B, STEP > 0)");
  auto* circ = sweep->add_option("--circulation", o->circulation,
                                 "circulations Γ (m²/s) for circulation.model = \"given\": A:B:STEP");
  spin->excludes(circ);
  sweep->add_option("--reynolds", o->reynolds,
                    "navier-stokes: Reynolds numbers A:B:STEP, one continuation row each (the S(Re, α) map); "
                    "alone: the case's spin ratio continued in Re");
  sweep->add_option("--shard", o->shard,
                    "navier-stokes: compute only the K-th of N interleaved slices of the Re rows (K/N)");
  sweep->add_flag("--steady-only", o->steady_only,
                  "navier-stokes: the steady branch only (no stability test, no time averages)");
  sweep->add_flag("--no-error-bars", o->no_error_bars,
                  "navier-stokes: no per-point error bars (they cost a steady solve on the grid twice as coarse, "
                  "and a companion march beside each marched point)");
  sweep->add_flag("--orbits", o->orbits,
                  "navier-stokes: each shedding point as its periodic orbit (Newton–GMRES shooting), continued "
                  "from the previous α's orbit or started on the growing mode, instead of a march from rest");
  sweep->add_option("--stability", o->stability,
                    "navier-stokes: eigenvalues (the Jacobian's leading pair, default) or march (the linearised "
                    "time stepper's growth: cheaper on coarse grids)")
      ->check(CLI::IsMember({"eigenvalues", "march"}));
  sweep->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  output_file(sweep->add_option("--csv", o->csv, "write the table as CSV"));
  add_force_flag(sweep);
  output_file(sweep->add_option("-o,--output", o->output, "write the table as HDF5 (format magnus-sweep)"));
  output_file(sweep->add_option("--plot", o->plot, "draw C_L(α) as PNG"));
  sweep->add_option("--size", o->size, "PNG size WxH in pixels (default 1000x800)");
  sweep
      ->add_option("--threads", o->threads,
                   "threads for the solver (navier-stokes: Re rows computed at once)")
      ->check(CLI::Range(1, 64));
  auto* quiet = sweep->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  sweep
      ->add_flag("--json", o->json,
                 "print one JSON object instead of the table: every figure with its units (see "
                 "docs/scripting.md)")
      ->excludes(quiet);
  sweep->callback([o] { command_sweep(*o); });
}

}  // namespace magnus
