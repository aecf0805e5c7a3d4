// magnus bench CASE [--ladder 32,64,…] [--repeats N] [--method M]… [--stencil S]… [--csv F] [--plot F.png]
#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <map>
#include <memory>

#include "app/commands.hpp"
#include "app/threads.hpp"
#include "io/bench_table.hpp"
#include "io/case_file.hpp"
#include "io/hdf5_io.hpp"
#include "postproc/memory_bandwidth.hpp"
#include "postproc/navier_stokes/bench.hpp"
#include "plot/curves.hpp"

namespace magnus {

namespace {

/// magnus bench on a navier-stokes case: the cost of a time step on a ladder of grids, split into its parts.
void bench_viscous(const Case& c, std::vector<int> ladder, int steps, int threads, const std::string& case_path,
                   const std::string& csv, const std::string& plot) {
  if (!plot.empty())
    throw std::runtime_error("--plot: a navier-stokes bench has no error to plot (its table is the step cost)");
  check_distinct_paths({case_path}, {csv});
  if (!csv.empty()) check_writable(csv);
  if (ladder.empty()) ladder = {c.grid.n_theta / 2 + (c.grid.n_theta / 2) % 2, c.grid.n_theta, 2 * c.grid.n_theta};
  for (int n : ladder)
    if (n % 2) throw std::runtime_error(fmt::format("--ladder: n_theta = {} must be even", n));
  const double bandwidth = triad_bandwidth(threads);  // bytes/s, measured once, before the steps
  const auto rows = run_ns_bench(c, ladder, steps, 20, threads);
  // With --csv - the CSV alone goes to standard output, the table to standard error.
  std::FILE* table = is_stdout(csv) ? stderr : stdout;
  std::fprintf(table,
               "magnus bench — %s (navier-stokes, Re = %.6g, α = %.6g; %d timed steps per grid from the start, "
               "%d thread%s; ms per step and share)\n",
               c.title.c_str(), c.scene.reynolds(), c.scene.spin_ratio(), steps, threads, threads == 1 ? "" : "s");
  std::fputs(ns_bench_table(rows).c_str(), table);
  NsBound bound;
  bound.bytes_per_node = kNsStepBytesPerNode, bound.array_bytes_per_node = kNsStepArrayBytesPerNode;
  bound.bandwidth = bandwidth, bound.cache = double(last_level_cache_bytes()), bound.threads = threads;
  std::fputs(ns_bench_bound(rows, bound).c_str(), table);
  std::fputs("(The error of a whole run against published values, and its wall time, is the README's validation "
             "table: ctest -L validation.)\n",
             table);
  if (!csv.empty()) write_text_output(csv, ns_bench_csv(rows));
}

/// The options of magnus bench as given.
struct BenchArgs {
  std::string case_path, csv, plot;
  std::vector<std::string> sets, methods, stencils;
  std::vector<int> ladder;
  int repeats = 5, threads = 1, steps = 200;
  long cholmod_max = 300000;
};

/// The potential-flow bench's options: the ladder (each rung even), the methods, the stencils, the repeats.
BenchOptions bench_options(const BenchArgs& o) {
  BenchOptions opt;
  if (!o.ladder.empty()) opt.ladder = o.ladder;
  for (int n : opt.ladder)
    if (n % 2) throw std::runtime_error(fmt::format("--ladder: n_theta = {} must be even", n));
  if (!o.methods.empty()) {
    opt.methods.clear();
    for (const auto& m : o.methods) opt.methods.push_back(m == "fft" ? Method::fft : Method::cholmod);
  }
  if (!o.stencils.empty()) {
    opt.stencils.clear();
    for (const auto& s : o.stencils)
      opt.stencils.push_back(s == "9-point" ? StencilKind::nine_point : StencilKind::five_point);
  }
  opt.repeats = o.repeats;
  opt.threads = usable_threads(o.threads);
  opt.cholmod_max_unknowns = o.cholmod_max;
  return opt;
}

/// The Pareto front as a log-log PNG: C_L error against time, one joined point set per method and stencil;
/// the legend goes beside the plot, off the data.
void plot_bench_front(const std::vector<BenchRow>& rows, const std::string& title, const std::string& path) {
  std::map<std::string, PointSet> by;
  for (const auto& r : rows) {
    PointSet& s = by[r.method + " " + r.stencil];
    s.label = r.method + ", " + r.stencil;
    s.joined = true;
    if (r.cl_rel > 0) s.points.push_back({r.total_s * 1e3, r.cl_rel});
  }
  const Colour colours[] = {Colour::blue, Colour::red, Colour::green, Colour::purple};
  std::vector<PointSet> series;
  for (auto& [k, s] : by) {
    s.colour = colours[series.size() % 4];
    s.marker = int(series.size());
    series.push_back(s);
  }
  CurvePage page;
  page.title = "C_L error against time: " + literal_text(title);
  page.xlabel = "time for one lift figure (ms)";
  page.ylabel = "relative C_L error";
  page.log_x = page.log_y = true;
  plot_curves(page, {}, series, path);
}

/// magnus bench on a potential-flow case: speed against error on a ladder of grids per solver and stencil.
void bench_potential(const Case& c, const BenchArgs& o) {
  const BenchOptions opt = bench_options(o);
  check_distinct_paths({o.case_path}, {o.csv, o.plot});
  if (!o.csv.empty()) check_writable(o.csv);
  if (!o.plot.empty()) check_file_writable(o.plot, "the PNG plot");
  const bool tty = ::isatty(2);
  auto progress = [tty](const std::string& text) {
    if (tty) std::fprintf(stderr, "\r\033[K%s", text.c_str());
  };
  const auto rows = run_bench(c, opt, progress);
  if (tty) std::fprintf(stderr, "\r\033[K");
  if (rows.empty())
    throw std::runtime_error(
        "bench: no rung ran (the 9-point stencil needs geometric spacing, or every CHOLMOD "
        "rung is above --cholmod-max-unknowns)");
  std::FILE* table = is_stdout(o.csv) ? stderr : stdout;  // --csv -: the CSV alone on standard output
  std::fprintf(table, "magnus bench — %s (α = %.6g, far field %s, %d thread%s, median of %d)\n",
               c.title.c_str(), c.scene.spin_ratio(), to_string(c.grid.far_field), opt.threads,
               opt.threads == 1 ? "" : "s", opt.repeats);
  std::fputs(bench_table(rows).c_str(), table);
  if (!o.csv.empty()) write_text_output(o.csv, bench_csv(rows));
  if (!o.plot.empty()) plot_bench_front(rows, c.title, o.plot);
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchArgs>();
  auto* b = app.add_subcommand("bench", "speed against error: a ladder of grids for each solver and stencil");
  // Options of one model only: given to the other, they are refused rather than ignored.
  static const char* const potential_only[] = {"--repeats", "--method", "--stencil", "--cholmod-max-unknowns"};
  b->add_option("case", o->case_path, "case file (TOML)")->required();
  b->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  b->add_option("--ladder", o->ladder, "n_theta of each rung (default 32,64,…,1024)")
      ->delimiter(',')
      ->check(CLI::Range(8, 1 << 20));
  b->add_option("--repeats", o->repeats, "median over this many runs per rung (default 5)")
      ->check(CLI::Range(1, 1000));
  b->add_option("--method", o->methods, "cholmod and/or fft (default both)")
      ->delimiter(',')
      ->check(CLI::IsMember({"cholmod", "fft"}));
  b->add_option("--stencil", o->stencils, "5-point and/or 9-point (default both)")
      ->delimiter(',')
      ->check(CLI::IsMember({"5-point", "9-point"}));
  b->add_option("--cholmod-max-unknowns", o->cholmod_max, "skip larger CHOLMOD rungs (default 300000)")
      ->check(CLI::Range(1L, 1L << 40));
  b->add_option("--threads", o->threads, "threads for the solver")->check(CLI::Range(1, 64));
  b->add_option("--steps", o->steps, "navier-stokes: timed steps per rung (default 200)")->check(CLI::Range(1, 1000000));
  output_file(b->add_option("--csv", o->csv, "write the table as CSV"));
  add_force_flag(b);
  output_file(b->add_option("--plot", o->plot, "write a log-log PNG of C_L error against time (the Pareto front)"));
  b->callback([o, b] {
    Case c = load_case(o->case_path, o->sets);
    retitle_for_overrides(c, o->case_path, o->sets);
    if (c.model == FlowModel::navier_stokes) {
      for (const char* k : potential_only)
        if (b->count(k))
          throw std::runtime_error(fmt::format(
              "{}: only used by a potential-flow bench ({} is navier-stokes: its bench times the steps)", k,
              o->case_path));
      bench_viscous(c, o->ladder, o->steps, usable_threads(o->threads), o->case_path, o->csv, o->plot);
      return;
    }
    if (b->count("--steps"))
      throw std::runtime_error(
          fmt::format("--steps: only used by a navier-stokes bench ({} is potential flow)", o->case_path));
    bench_potential(c, *o);
  });
}

}  // namespace magnus
