// magnus stability CASE [--set k=v]… [--critical-spin A:B | --critical-reynolds A:B] [--tolerance T]
//                  [--spanwise [--beta A:B:STEP] [--fine-grid N:R]] [--eigensolver NAME] [--output FILE.h5]
//                  [--json]
// The steady state's leading eigenvalues (growth rate, St; stable or not) and, with --spanwise, those of
// three-dimensional disturbances per spanwise wavenumber; or the onset of shedding: the critical spin ratio
// or Reynolds number where the wake's pair crosses the axis; with --spanwise --critical-reynolds, the
// Reynolds number where the flow turns three-dimensional and its spanwise wavelength (with --fine-grid, then
// refined on a finer grid).
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/commands.hpp"
#include "app/spanwise_report.hpp"
#include "base/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/case_keys.hpp"
#include "io/json_output.hpp"
#include "io/stability_file.hpp"
#include "io/sweep_file.hpp"
#include "io/text_format.hpp"
#include "postproc/navier_stokes/critical.hpp"
#include "postproc/navier_stokes/onset_curve.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "postproc/navier_stokes/spanwise_scan.hpp"

namespace magnus {

namespace {

struct StabilityCliOptions {
  std::string case_path, critical, critical_re, tolerance, curve_re, curve_alpha;
  std::string output;  ///< --output: the spectra as an HDF5 file
  std::string beta = "0.5:4:0.5";  ///< --beta: the spanwise wavenumbers β·D, A:B:STEP
  std::string fine_grid;           ///< --fine-grid N:R: the 3D onset refined on n_θ N, R = R·a
  bool spanwise = false, beta_given = false;
  std::string eigensolver = StabilityOptions{}.eigensolver;
  std::vector<std::string> sets;
  bool json = false;
};

/// A finite number, the whole text; throws one line naming the option.
double parse_number(const std::string& text, const std::string& option, const char* expected) {
  size_t end = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &end);
  } catch (const std::exception&) {
    end = 0;
  }
  if (text.empty() || end != text.size() || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{}: expected {}, got \"{}\"", option, expected, cut_input(text)));
  return v;
}

/// --critical-spin A:B or --critical-reynolds A:B (finite, A < B; Re > 0) and --tolerance T (> 0, below
/// B − A), checked before any solve.
struct CriticalRange {
  HopfParameter which = HopfParameter::spin_ratio;
  double A = 0.0, B = 0.0, tolerance = 0.01;
  std::vector<double> others;  ///< --reynolds (with --critical-spin) or --spin-ratio (with --critical-reynolds)
};
CriticalRange parse_critical(const StabilityCliOptions& o) {
  CriticalRange r;
  const bool re = !o.critical_re.empty();
  if (re && !o.critical.empty())
    throw std::invalid_argument("--critical-spin and --critical-reynolds: give one of them (the parameter to move)");
  r.which = re ? HopfParameter::reynolds : HopfParameter::spin_ratio;
  const std::string& text = re ? o.critical_re : o.critical;
  const std::string option = re ? "--critical-reynolds" : "--critical-spin";
  const char* expected = re ? "A:B with two finite Reynolds numbers > 0" : "A:B with two finite spin ratios";
  const size_t colon = text.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument(fmt::format("{}: expected {}, got \"{}\"", option, expected, cut_input(text)));
  r.A = parse_number(text.substr(0, colon), option, expected);
  r.B = parse_number(text.substr(colon + 1), option, expected);
  if (re && !(r.A > 0.0)) throw std::invalid_argument(fmt::format("{} {}: expected {}", option, text, expected));
  if (!(r.A < r.B)) throw std::invalid_argument(fmt::format("{} {}: needs A < B", option, text));
  const std::string& curve = re ? o.curve_alpha : o.curve_re;
  const std::string& wrong = re ? o.curve_re : o.curve_alpha;
  if (!wrong.empty())
    throw std::invalid_argument(re ? "--reynolds: an onset curve in Re steps along α: use --spin-ratio with --critical-reynolds"
                                   : "--spin-ratio: an onset curve in α steps along Re: use --reynolds with --critical-spin");
  if (!curve.empty()) {
    r.others = parse_sweep_range(curve, re ? "--spin-ratio" : "--reynolds").values;
    if (!re && !(r.others.front() > 0.0))
      throw std::invalid_argument("--reynolds " + curve + ": Reynolds numbers must be > 0");
  }
  if (!o.tolerance.empty()) {
    r.tolerance = parse_number(o.tolerance, "--tolerance", "a width T > 0");
    if (!(r.tolerance > 0.0) || !(r.tolerance < r.B - r.A))
      throw std::invalid_argument(fmt::format(
          "--tolerance {}: the width must be > 0 and below B − A = {:g}", o.tolerance, r.B - r.A));
  }
  return r;
}

std::string eig_text(const std::complex<double>& l) {
  return fmt::format("{} {}i   St {}", figure(l.real(), "{:+.5f}"), figure(l.imag(), "{:+.5f}"),
                     figure(eigen_strouhal(l), "{:.4f}"));
}

Json eig_json(const StabilityResult& s) {
  Json a = Json::array();
  for (size_t k = 0; k < s.eigenvalues.size(); ++k) {
    const auto& l = s.eigenvalues[k];
    a.push_back({{"growth_rate", l.real()},
                 {"frequency", l.imag()},
                 {"strouhal", eigen_strouhal(l)},
                 {"residual", k < s.residuals.size() ? Json(s.residuals[k]) : Json()}});
  }
  return a;
}

/// The evidence of the search: each shift (U/D), what it accepted, the disk it covers; and the coverage.
Json search_json(const StabilityResult& s) {
  Json a = Json::array();
  for (const auto& sh : s.shifts)
    a.push_back({{"shift_real", sh.sigma.real()},
                 {"shift_imag", sh.sigma.imag()},
                 {"found", sh.found},
                 {"radius", sh.radius},
                 {"converged", sh.converged},
                 {"restarts", sh.restarts}});
  return {{"shifts", a}, {"covered", s.covered}};
}

/// One line per shift: where it sat and how far around it every eigenvalue was found.
std::string search_text(const StabilityResult& s) {
  std::string t;
  for (const auto& sh : s.shifts)
    t += fmt::format("               σ = {:+.3f} {:+.3f}i: {} accepted, all within {:.3f} found{}\n", sh.sigma.real(),
                     sh.sigma.imag(), sh.found, sh.radius, sh.converged ? "" : " (nearest not all converged)");
  t += fmt::format("coverage       {}\n",
                   s.covered ? "the disks cover the strip from the leading eigenvalue to Re λ = 0, 0 ≤ Im λ ≤ the "
                               "highest shift: nothing between it and the axis was left unseen there"
                             : "NOT COVERED: an eigenvalue right of the leading one may have been missed");
  return t;
}

/// Each point the search solved, in order: its value, the tracked pair's growth rate and frequency (U/D),
/// whether it was tracked (seeded by the march, or followed by its eigenvector: the overlap), and what it
/// cost (Newton and eigenvalue seconds, shifted solves).
Json points_json(const HopfPoint& h) {
  Json a = Json::array();
  for (const HopfEvaluation& e : h.evaluations)
    a.push_back({{"value", e.x},
                 {"growth_rate", e.growth()},
                 {"frequency", e.mode.imag()},
                 {"tracked", e.tracked},
                 {"seeded", e.seeded},
                 {"overlap", e.overlap},
                 {"newton_seconds", e.newton_seconds},
                 {"eigenvalue_seconds", e.stability.seconds},
                 {"solves", e.stability.solves}});
  return a;
}

/// The onset of shedding over the range: the crossing, its bracket and the pair at each end asked for.
void critical_report(const NsParams& p, const CriticalRange& range, const std::string& eigensolver, bool json,
                     std::string& text, Json& j) {
  const bool spin = range.which == HopfParameter::spin_ratio;
  const char* x = spin ? "α" : "Re";
  HopfOptions ho;
  ho.tol = range.tolerance;
  ho.full.eigensolver = eigensolver;
  const HopfPoint h = hopf_point(p, range.which, range.A, range.B, ho, [&](const HopfEvaluation& e) {
    if (!json)
      std::fprintf(stderr, "  %s = %-9.6g growth rate %+.6f U/D, St %.4f  (%s%s)\n", x, e.x, e.growth(),
                   eigen_strouhal(e.mode), e.growth() < 0.0 ? "stable" : "unstable",
                   e.seeded    ? ", the pair from the march's Arnoldi"
                   : e.tracked ? ", the pair tracked"
                               : "");
  });
  const double alpha = p.a * p.omega / p.U;
  text += fmt::format("critical {:<5} {:.4f} ± {:.1g}  ({}; bracket [{:.4f}, {:.4f}], {} steady states, {:.1f} s)\n",
                      x, h.x_c, std::max(h.change, 1e-12),
                      spin ? fmt::format("Re {:.4g}", p.reynolds()) : fmt::format("α {:g}", alpha), h.lo, h.hi,
                      h.evaluations.size(), h.seconds);
  text += fmt::format("onset          the wake's pair {}: St {:.4f} at the crossing\n", eig_text(h.lambda),
                      h.strouhal());
  text += "leading pair   λ·D/U at the ends of the range asked for\n";
  for (const HopfEvaluation* e : {&h.at_a, &h.at_b})
    text += fmt::format("at {} = {:<7g} {}  ({})\n", x, e->x, eig_text(e->mode), e->growth() < 0.0 ? "decays" : "grows");
  j = {{"reynolds", p.reynolds()},
       {"spin_ratio", alpha},
       {"parameter", spin ? "spin_ratio" : "reynolds"},
       {spin ? "critical_spin_ratio" : "critical_reynolds", h.x_c},
       {"change", h.change},
       {"bracket", {h.lo, h.hi}},
       {"onset_growth_rate", h.lambda.real()},
       {"onset_frequency", h.lambda.imag()},
       {"onset_strouhal", h.strouhal()},
       {"evaluations", h.evaluations.size()},
       {"points", points_json(h)},
       {"at_a", {{"value", range.A}, {"stable", h.at_a.growth() < 0.0}, {"eigenvalues", eig_json(h.at_a.stability)}}},
       {"at_b", {{"value", range.B}, {"stable", h.at_b.growth() < 0.0}, {"eigenvalues", eig_json(h.at_b.stability)}}},
       {"seconds", h.seconds}};
}

/// The onset curve: one line per value of the other parameter, the crossing or why none was found.
void curve_report(const NsParams& p, const CriticalRange& range, const std::string& eigensolver, bool json,
                  std::string& text, Json& j) {
  const bool spin = range.which == HopfParameter::spin_ratio;
  const char *x = spin ? "α_L" : "Re_c", *other = spin ? "Re" : "α";
  HopfOptions ho;
  ho.tol = range.tolerance;
  ho.full.eigensolver = eigensolver;
  text += fmt::format("onset curve    {}({}): where the wake's pair crosses the axis (shedding {} above it)\n", x, other,
                      spin ? "stops" : "starts");
  text += fmt::format("{:>8}  {:>9}  {:>8}  {:>8}  {:>7}  {:>8}\n", other, x, "±", "St", "points", "time s");
  Json rows = Json::array();
  const auto t0 = std::chrono::steady_clock::now();
  onset_curve(p, range.which, range.A, range.B, range.others, ho, [&](const OnsetPoint& pt) {
    const HopfPoint& h = pt.point;
    const std::string line =
        pt.found ? fmt::format("{:>8.4g}  {:>9.4f}  {:>8.1g}  {:>8.4f}  {:>7}  {:>8.1f}{}", pt.other, h.x_c,
                               std::max(h.change, 1e-12), h.strouhal(), h.evaluations.size(), h.seconds,
                               pt.restarted.empty() ? "" : "  (searched over the whole range: the step from the last point failed)")
                 : fmt::format("{:>8.4g}  not found: {}", pt.other, pt.message);
    if (!json) std::fprintf(stderr, "%s\n", line.c_str());
    text += line + "\n";
    rows.push_back(pt.found ? Json{{spin ? "reynolds" : "spin_ratio", pt.other},
                                   {spin ? "critical_spin_ratio" : "critical_reynolds", h.x_c},
                                   {"change", h.change},
                                   {"onset_strouhal", h.strouhal()},
                                   {"bracket", {h.lo, h.hi}},
                                   {"evaluations", h.evaluations.size()},
                                   {"points", points_json(h)},
                                   {"seconds", h.seconds},
                                   {"restarted", pt.restarted.empty() ? Json() : Json(pt.restarted)}}
                            : Json{{spin ? "reynolds" : "spin_ratio", pt.other}, {"undefined", pt.message}});
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  text += fmt::format("total          {:.1f} s\n", seconds);
  j = {{"parameter", spin ? "spin_ratio" : "reynolds"}, {"curve", rows}, {"seconds", seconds}};
}

/// --fine-grid N:R against the case's grid p: the overrides that give that grid (fine_grid_overrides).
std::vector<std::string> fine_grid_sets(const std::string& text, const NsParams& p) {
  const size_t colon = text.find(':');
  const std::string what = "--fine-grid " + cut_input(text);
  if (colon == std::string::npos)
    throw std::invalid_argument(what + ": expected N:R (n_θ and R/a), e.g. 192:60");
  const char* expected = "N:R (n_θ and R/a), e.g. 192:60";
  return fine_grid_overrides(parse_number(text.substr(0, colon), "--fine-grid", expected),
                             parse_number(text.substr(colon + 1), "--fine-grid", expected), p, what);
}

/// The refusals of --beta, --fine-grid and --output (critical: an onset search), before anything is solved;
/// the wavenumbers β·D of --spanwise (none without it).
std::vector<double> spanwise_options(const StabilityCliOptions& o, bool critical) {
  if (o.beta_given && !o.spanwise) throw std::invalid_argument("--beta: only used with --spanwise");
  if (!o.fine_grid.empty() && !(critical && o.spanwise))
    throw std::invalid_argument(
        "--fine-grid: only used with --spanwise --critical-reynolds A:B (the 3D onset search)");
  if (!o.output.empty()) {
    if (critical && !o.spanwise)
      throw std::invalid_argument(
          "--output: the file holds eigenvalues and 3D spectra, not the 2D onset search");
    check_distinct_paths({o.case_path}, {o.output});
    check_file_writable(o.output, "the HDF5 stability file");
  }
  if (!o.spanwise) return {};
  const std::vector<double> beta_D = parse_sweep_range(o.beta, "--beta").values;
  if (!(beta_D.front() >= 0.0))
    throw std::invalid_argument("--beta " + o.beta + ": wavenumbers β·D must be ≥ 0");
  return beta_D;
}

/// The case's parameters on the grid --fine-grid names (none without it).
std::optional<NsParams> fine_grid_params(const StabilityCliOptions& o, const NsParams& p) {
  if (o.fine_grid.empty()) return std::nullopt;
  std::vector<std::string> sets = o.sets;
  for (const std::string& x : fine_grid_sets(o.fine_grid, p)) sets.push_back(x);
  try {
    return ns_params(load_case(o.case_path, sets));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--fine-grid " + cut_input(o.fine_grid) + ": " + e.what());
  }
}

void command_stability(const StabilityCliOptions& o) {
  const bool critical = !o.critical.empty() || !o.critical_re.empty();
  if (!critical && !o.tolerance.empty())
    throw std::invalid_argument("--tolerance: only used with --critical-spin A:B or --critical-reynolds A:B");
  if (!critical && (!o.curve_re.empty() || !o.curve_alpha.empty()))
    throw std::invalid_argument(std::string(o.curve_re.empty() ? "--spin-ratio" : "--reynolds") +
                                ": an onset curve needs --critical-spin A:B (with --reynolds) or --critical-reynolds A:B "
                                "(with --spin-ratio)");
  const CriticalRange range = critical ? parse_critical(o) : CriticalRange{};
  if (critical && o.spanwise && (range.which != HopfParameter::reynolds || !range.others.empty()))
    throw std::invalid_argument("--spanwise: the 3D onset is searched in Re only: with --critical-reynolds A:B, "
                                "not --critical-spin or an onset curve");
  const std::vector<double> beta_D = spanwise_options(o, critical);
  if (!known_eigensolver(o.eigensolver))
    throw std::invalid_argument(fmt::format("--eigensolver {}: unknown eigensolver (expected {})",
                                            cut_input(o.eigensolver), eigensolver_names()));
  Case c = load_case(o.case_path, o.sets);
  retitle_for_overrides(c, o.case_path, o.sets);
  if (c.model != FlowModel::navier_stokes)
    throw std::runtime_error(o.case_path + ": magnus stability needs model.flow = \"navier-stokes\"");
  check_resolvable(c);
  const NsParams p = ns_params(c);
  if (!(p.U > 0.0)) throw std::runtime_error(o.case_path + ": flow.speed must be > 0 (eigenvalues in U/D)");
  const double alpha = p.a * p.omega / p.U;
  std::string text;
  Json j;
  if (!critical) {
    HopfEvaluation s;
    try {
      s = steady_stability(p, o.eigensolver);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(o.case_path + ": " + e.what());
    }
    const StabilityResult& st = s.stability;
    text += fmt::format("steady state   Re {:.4g}, α {:g}: Newton {:.2f} s, eigenvalues {:.2f} s ({} shifted "
                        "solves, {})\n",
                        p.reynolds(), alpha, s.newton_seconds, st.seconds, st.solves, o.eigensolver);
    text += "eigenvalues    λ·D/U (growth rate, frequency), rightmost first; residual ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖)\n";
    for (size_t k = 0; k < st.eigenvalues.size(); ++k)
      text += "               " + eig_text(st.eigenvalues[k]) +
              (k < st.residuals.size() ? fmt::format("   residual {:.1e}", st.residuals[k]) : "") + "\n";
    text += "shifts         σ·D/U of the shift-invert searches\n" + search_text(st);
    text += fmt::format("verdict        {} (leading growth rate {} U/D{}){}\n",
                        st.stable ? "STABLE: the steady flow persists" : "UNSTABLE: the wake sheds",
                        figure(st.growth_rate(), "{:+.5f}"),
                        st.eigenvalues.front().imag() != 0.0 ? fmt::format(", St {:.4f}", st.strouhal()) : "",
                        st.covered ? "" : "; not verified: see the coverage line");
    j = {{"reynolds", p.reynolds()}, {"spin_ratio", alpha}, {"stable", st.stable}, {"eigenvalues", eig_json(st)},
         {"seconds", s.newton_seconds + st.seconds}, {"solves", st.solves}, {"eigensolver", o.eigensolver},
         {"search", search_json(st)}};
    // The 3D stability of the flow that is there: the steady state when it is stable, else the shedding orbit.
    if (o.spanwise) j["spanwise"] = spanwise_report(p, s, beta_D, o.eigensolver, o.json, text);
  } else if (o.spanwise) {
    const std::optional<NsParams> fine = fine_grid_params(o, p);
    j = spanwise_critical_report(p, beta_D, range.A, range.B, range.tolerance, o.eigensolver, o.json, text,
                                 fine ? &*fine : nullptr);
  } else if (range.others.empty()) {
    critical_report(p, range, o.eigensolver, o.json, text, j);
  } else {
    curve_report(p, range, o.eigensolver, o.json, text, j);
  }
  if (!o.output.empty()) {
    write_stability_hdf5(o.output, j, c.title, c.source_text);
    text += fmt::format("output         {}\n", o.output);
  }
  if (o.json)
    std::fputs((json_text(j) + "\n").c_str(), stdout);
  else
    std::fputs(text.c_str(), stdout);
}

}  // namespace

void add_stability_command(CLI::App& app) {
  auto o = std::make_shared<StabilityCliOptions>();
  auto* cmd = app.add_subcommand(
      "stability", "linear stability of the steady viscous state: leading eigenvalues, or the onset of shedding in α or Re");
  cmd->add_option("case", o->case_path, "case file (TOML, model.flow = \"navier-stokes\")")->required();
  cmd->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  cmd->add_option("--critical-spin", o->critical,
                  "the spin ratio in A:B where shedding stops (the wake's pair crosses the axis; secant search)");
  cmd->add_option("--critical-reynolds", o->critical_re,
                  "the Reynolds number in A:B where shedding starts, at the case's spin ratio (with --spanwise: where the "
                  "flow turns three-dimensional)");
  cmd->add_option("--reynolds", o->curve_re,
                  "with --critical-spin: the curve α_L(Re) over Reynolds numbers A:B:STEP, each point continued from the last");
  cmd->add_option("--spin-ratio", o->curve_alpha,
                  "with --critical-reynolds: the curve Re_c(α) over spin ratios A:B:STEP");
  cmd->add_option("--tolerance", o->tolerance,
                  "how closely the crossing is found: the secant root's last move, or the bracket (default 0.01)");
  cmd->add_flag("--spanwise", o->spanwise,
                "also the 3D stability: the leading eigenvalue for disturbances ∝ e^{iβz} per wavenumber, the most "
                "unstable wavelength and whether the spanwise-uniform (2D) flow is stable");
  cmd->add_option("--beta", o->beta, "with --spanwise: the wavenumbers β·D as A:B:STEP (default 0.5:4:0.5)")
      ->each([o](const std::string&) { o->beta_given = true; });
  cmd->add_option(
      "--fine-grid", o->fine_grid,
      "with --spanwise --critical-reynolds: then refine the onset on n_θ N, R = R·a (N:R, e.g. 192:60): two "
      "scans there at once, at the onset found and 2% above it, at its wavenumber");
  cmd->add_option("--eigensolver", o->eigensolver,
                  "each shift's search: arnoldi (hand-written Krylov–Schur) or arpack (ARPACK-ng); default " +
                      StabilityOptions{}.eigensolver);
  cmd->add_option("--output", o->output,
                  "write the eigenvalues and the 3D spectra (or the 3D onset search) to this HDF5 file");
  cmd->add_flag("--json", o->json, "print one JSON object instead of the table");
  cmd->callback([o] { command_stability(*o); });
}

}  // namespace magnus
