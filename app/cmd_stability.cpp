// magnus stability CASE [--set k=v]… [--critical-spin A:B] [--tolerance T] [--json]
// The steady state's leading eigenvalues (growth rate, St; stable or not), or the critical spin ratio.
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/commands.hpp"
#include "io/case_file.hpp"
#include "io/case_keys.hpp"
#include "io/json_output.hpp"
#include "io/text_format.hpp"
#include "postproc/navier_stokes/critical.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "postproc/navier_stokes/run.hpp"

namespace magnus {

namespace {

struct StabilityCliOptions {
  std::string case_path, critical, tolerance;
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

/// --critical-spin A:B (finite, A < B) and --tolerance T (> 0, below B − A), checked before any solve.
struct CriticalRange {
  double A = 0.0, B = 0.0, tolerance = 0.01;
};
CriticalRange parse_critical(const StabilityCliOptions& o) {
  CriticalRange r;
  const size_t colon = o.critical.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("--critical-spin: expected A:B (two spin ratios), got \"" + o.critical + "\"");
  r.A = parse_number(o.critical.substr(0, colon), "--critical-spin", "A:B with two finite spin ratios");
  r.B = parse_number(o.critical.substr(colon + 1), "--critical-spin", "A:B with two finite spin ratios");
  if (!(r.A < r.B))
    throw std::invalid_argument(fmt::format("--critical-spin {}: needs A < B", o.critical));
  if (!o.tolerance.empty()) {
    r.tolerance = parse_number(o.tolerance, "--tolerance", "a bracket width T > 0");
    if (!(r.tolerance > 0.0) || !(r.tolerance < r.B - r.A))
      throw std::invalid_argument(fmt::format(
          "--tolerance {}: the bracket width must be > 0 and below B − A = {:g}", o.tolerance, r.B - r.A));
  }
  return r;
}

std::string eig_text(const std::complex<double>& l) {
  return fmt::format("{} {}i   St {}", figure(l.real(), "{:+.5f}"), figure(l.imag(), "{:+.5f}"),
                     figure(std::fabs(l.imag()) / (2.0 * M_PI), "{:.4f}"));
}

Json eig_json(const StabilityResult& s) {
  Json a = Json::array();
  for (size_t k = 0; k < s.eigenvalues.size(); ++k) {
    const auto& l = s.eigenvalues[k];
    a.push_back({{"growth_rate", l.real()},
                 {"frequency", l.imag()},
                 {"strouhal", std::fabs(l.imag()) / (2.0 * M_PI)},
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

void command_stability(const StabilityCliOptions& o) {
  if (o.critical.empty() && !o.tolerance.empty())
    throw std::invalid_argument("--tolerance: only used with --critical-spin A:B (the bisection's bracket width)");
  const CriticalRange range = o.critical.empty() ? CriticalRange{} : parse_critical(o);
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
  if (o.critical.empty()) {
    const SpinStability s = spin_stability(p, alpha, nullptr, 6);
    if (!s.converged)
      throw std::runtime_error(fmt::format("{}: Newton's method found no steady state (Re {:.4g}, α {:g})",
                                           o.case_path, p.reynolds(), alpha));
    const StabilityResult& st = s.stability;
    if (st.eigenvalues.empty()) throw std::runtime_error(o.case_path + ": " + st.message);
    text += fmt::format("steady state   Re {:.4g}, α {:g}: Newton {:.2f} s, eigenvalues {:.2f} s ({} shifted "
                        "solves)\n",
                        p.reynolds(), alpha, s.newton_seconds, st.seconds, st.solves);
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
         {"seconds", s.newton_seconds + st.seconds}, {"solves", st.solves}, {"search", search_json(st)}};
  } else {
    const double A = range.A, B = range.B;
    const CriticalSpin cs = critical_spin(p, A, B, range.tolerance, [&](const SpinStability& s) {
      if (!o.json)
        std::fprintf(stderr, "  α = %-9.5g growth rate %+.5f U/D  (%s)\n", s.alpha, s.growth(),
                     s.growth() < 0.0 ? "stable" : "unstable");
    });
    text += fmt::format("critical α     {:.4f}  (Re {:.4g}; bracket [{:.4f}, {:.4f}], {} steady states, {:.1f} s)\n",
                        cs.alpha_c, p.reynolds(), cs.lo, cs.hi, cs.evaluations.size(), cs.seconds);
    const auto pair = [](const SpinStability& s) { return s.stability.leading_pair().value_or(s.stability.eigenvalues.front()); };
    text += "leading pair   λ·D/U at the ends of the bracket asked for\n";
    text += fmt::format("at α = {:<7g} {}  ({})\n", A, eig_text(pair(cs.at_a)),
                        cs.at_a.growth() < 0.0 ? "decays" : "grows");
    text += fmt::format("at α = {:<7g} {}  ({})\n", B, eig_text(pair(cs.at_b)),
                        cs.at_b.growth() < 0.0 ? "decays" : "grows");
    j = {{"reynolds", p.reynolds()},
         {"critical_spin_ratio", cs.alpha_c},
         {"bracket", {cs.lo, cs.hi}},
         {"at_a", {{"spin_ratio", A}, {"stable", cs.at_a.stability.stable}, {"eigenvalues", eig_json(cs.at_a.stability)}}},
         {"at_b", {{"spin_ratio", B}, {"stable", cs.at_b.stability.stable}, {"eigenvalues", eig_json(cs.at_b.stability)}}},
         {"seconds", cs.seconds}};
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
      "stability", "linear stability of the steady viscous state: leading eigenvalues, or the critical spin ratio");
  cmd->add_option("case", o->case_path, "case file (TOML, model.flow = \"navier-stokes\")")->required();
  cmd->add_option("--set", o->sets, "override a case key: section.key=value (repeatable)");
  cmd->add_option("--critical-spin", o->critical, "bisect on the growth rate over spin ratios A:B");
  cmd->add_option("--tolerance", o->tolerance, "bracket width of the critical spin ratio (default 0.01)");
  cmd->add_flag("--json", o->json, "print one JSON object instead of the table");
  cmd->callback([o] { command_stability(*o); });
}

}  // namespace magnus
