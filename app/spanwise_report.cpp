#include "app/spanwise_report.hpp"

#include <fmt/core.h>

#include <cstdio>

#include "io/text_format.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "postproc/navier_stokes/spanwise_scan.hpp"

namespace magnus {

Json spanwise_report(const NsParams& p, const HopfEvaluation& ss, const std::vector<double>& beta_D,
                     const std::string& eigensolver, bool json, std::string& text) {
  const bool steady = ss.stability.stable;
  auto line = [steady](const SpanwisePoint& pt) {
    if (!pt.found) return fmt::format("{:>8.4g}  {:>9}  undefined: no eigenvalue converged", pt.beta_D, "");
    return fmt::format("{:>8.4g}  {:>9}  {:>+10.5f}  {:>+10.5f}  {:>7}  {:>7.1f}{}", pt.beta_D,
                       pt.beta_D > 0.0 ? fmt::format("{:.4g}", spanwise_wavelength_D(pt.beta_D)) : "∞", pt.lambda.real(),
                       pt.lambda.imag(), pt.solves, pt.seconds, pt.covered ? "" : steady ? "  (strip not covered)" : "  (multiplier not converged)");
  };
  const std::string head = fmt::format("{:>8}  {:>9}  {:>10}  {:>10}  {:>7}  {:>7}", "β·D", "λ_z/D", "growth",
                                       "frequency", steady ? "solves" : "steps", "time s");
  const char* what = steady ? "the leading eigenvalue λ·D/U of the steady state"
                            : "the shedding orbit's Floquet exponent ln(μ)·D/(U T) of the leading multiplier μ";
  if (!json) std::fprintf(stderr, "spanwise scan: %s per wavenumber\n%s\n", what, head.c_str());
  auto progress = [&](const SpanwisePoint& pt) {
    if (!json) std::fprintf(stderr, "%s\n", line(pt).c_str());
  };
  const SpanwiseScan s = spanwise_stability(p, ss, beta_D, eigensolver, progress);
  text += fmt::format("spanwise       {} for disturbances ∝ e^{{iβz}}, per wavenumber{}\n", what,
                      steady ? "" : fmt::format(" (period T = {:.4f} D/U)", s.T)) +
          head + "\n";
  Json rows = Json::array();
  for (const SpanwisePoint& pt : s.points) {
    text += line(pt) + "\n";
    Json row = pt.found ? Json{{"beta_D", pt.beta_D},
                                   {"wavelength_D", pt.beta_D > 0.0 ? Json(spanwise_wavelength_D(pt.beta_D)) : Json()},
                                   {"growth_rate", pt.lambda.real()},
                                   {"frequency", pt.lambda.imag()},
                                   {"covered", pt.covered},
                                   {"solves", pt.solves},
                                   {"seconds", pt.seconds}}
                            : Json{{"beta_D", pt.beta_D}, {"undefined", "no eigenvalue converged"}};
    if (pt.found && !steady) row["multiplier_real"] = pt.multiplier.real(), row["multiplier_imag"] = pt.multiplier.imag();
    rows.push_back(row);
  }
  text += "3D verdict     " + s.verdict + "\n";
  text += fmt::format("accuracy       {}\n", kSpanwiseAccuracyNote);

  Json j = {{"base", steady ? "steady" : "periodic"}, {"points", rows}, {"stable", s.stable}, {"verdict", s.verdict},
            {"accuracy_note", kSpanwiseAccuracyNote}};
  if (!steady) j["period_D_over_U"] = s.T;
  if (!s.points.empty() && s.beta_D > 0.0) {
    j["most_unstable_beta_D"] = s.beta_D;
    j["most_unstable_wavelength_D"] = s.wavelength_D();
    j["most_unstable_growth_rate"] = s.growth;
    j["stationary"] = s.stationary;
    j["inside_scan"] = s.interior;
  }
  return j;
}

namespace {

/// The onset on the fine grid from the search c (spanwise_critical_fine): its two scans (lines as `line`
/// makes them) and its onset appended to text, progress to stderr unless json; its JSON object returned.
template <class Line>
Json fine_grid_report(const NsParams& p, const SpanwiseCritical& c, const NsParams& fine,
                      const std::string& eigensolver, bool json, const Line& line, std::string& text) {
  const PolarGrid g = ns_grid(fine);
  const std::string grid = fmt::format("n_θ {} × {} rings, R = {:g}a", g.n_theta, g.n_r, fine.outer_over_a);
  Json j = {{"n_theta", g.n_theta}, {"n_r", g.n_r}, {"outer_radius_over_a", fine.outer_over_a}};
  if (!c.found) {
    text += "fine grid      not run: the search on the case's grid found no onset\n";
    j["found"] = false, j["undefined"] = "the search on the case's grid found no onset";
    return j;
  }
  if (!json)
    std::fprintf(stderr, "fine grid (%s): Re %.5g and %.5g at once, β·D %.4g\n", grid.c_str(), c.Re_c,
                 1.02 * c.Re_c, c.beta_D);
  const SpanwiseFine f = spanwise_critical_fine(p, c, fine, eigensolver);
  text += "fine grid      " + grid + ": the two scans\n";
  Json rows = Json::array();
  for (const SpanwiseEvaluation& e : f.evaluations) {
    if (e.scan.points.empty()) continue;  // a scan that failed (f.message names it)
    text += line(e) + "\n";
    if (!json) std::fprintf(stderr, "%s\n", line(e).c_str());
    rows.push_back(
        {{"reynolds", e.Re}, {"growth_rate", e.scan.growth}, {"beta_D", f.beta_D}, {"seconds", e.seconds}});
  }
  j["evaluations"] = rows, j["seconds"] = f.seconds, j["found"] = f.found;
  if (f.found) {
    text += fmt::format("critical Re    {:.2f} ± {:.2g} on the fine grid (its two scans, the coarse "
                        "curvature; {:.1f} s){}\n",
                        f.Re_c, f.bar, f.seconds,
                        f.extrapolated ? "; extrapolated: outside its two scans" : "");
    j["critical_reynolds"] = f.Re_c, j["error_estimate"] = f.bar, j["beta_D"] = f.beta_D;
    j["line_critical_reynolds"] = f.line_Re_c, j["extrapolated"] = f.extrapolated;
  } else {
    text += "critical Re    undefined on the fine grid: " + f.message + "\n";
    j["undefined"] = f.message;
  }
  return j;
}

}  // namespace

Json spanwise_critical_report(const NsParams& p, const std::vector<double>& beta_D, double Re_a, double Re_b,
                              double tol, const std::string& eigensolver, bool json, std::string& text,
                              const NsParams* fine) {
  auto line = [](const SpanwiseEvaluation& e) {
    const SpanwiseScan& s = e.scan;
    return fmt::format("{:>9.5g}  {:>8}  {:>10}  {:>9}  {:>8}  {:>7.1f}", e.Re, s.periodic ? "orbit" : "steady",
                       figure(s.growth, "{:+.5f}"), figure(s.beta_D, "{:.4g}"),
                       s.beta_D > 0.0 ? fmt::format("{:.4g}", s.wavelength_D()) : "∞", e.seconds);
  };
  const std::string head = fmt::format("{:>9}  {:>8}  {:>10}  {:>9}  {:>8}  {:>7}", "Re", "base", "growth", "β·D",
                                       "λ_z/D", "time s");
  if (!json) std::fprintf(stderr, "3D onset: the most unstable growth rate (U/D) per Reynolds number\n%s\n", head.c_str());
  const SpanwiseCritical c = spanwise_critical(p, beta_D, Re_a, Re_b, tol, eigensolver, 10, [&](const SpanwiseEvaluation& e) {
    if (!json) std::fprintf(stderr, "%s\n", line(e).c_str());
  });
  const double alpha = p.a * p.omega / p.U;
  text += fmt::format("3D onset       the most unstable spanwise growth rate per Reynolds number, α {:g}\n", alpha) +
          head + "\n";
  Json rows = Json::array();
  for (const SpanwiseEvaluation& e : c.evaluations) {
    text += line(e) + "\n";
    rows.push_back({{"reynolds", e.Re},
                    {"base", e.scan.periodic ? "periodic" : "steady"},
                    {"growth_rate", e.scan.growth},
                    {"beta_D", e.scan.beta_D},
                    {"inside_scan", e.scan.interior},
                    {"seconds", e.seconds}});
  }
  Json j = {{"spin_ratio", alpha}, {"evaluations", rows}, {"seconds", c.seconds}, {"found", c.found}};
  if (c.found) {
    const std::string mode = c.beta_D > 0.0 ? fmt::format("3D mode at λ_z = {:.3g} D (β·D = {:.3g})", c.wavelength_D(), c.beta_D)
                                            : std::string("β = 0: a 2D mode");
    text += fmt::format("critical Re    {:.2f} ± {:.2g} (bracket [{:.2f}, {:.2f}]): {}; the 2D flow is real below "
                        "it ({} scans, {:.1f} s)\n",
                        c.Re_c, c.change, c.lo, c.hi, mode, c.evaluations.size(), c.seconds);
    j["critical_reynolds"] = c.Re_c, j["change"] = c.change, j["bracket"] = {c.lo, c.hi};
    j["beta_D"] = c.beta_D, j["wavelength_D"] = c.beta_D > 0.0 ? Json(c.wavelength_D()) : Json();
  } else {
    text += "critical Re    undefined: " + c.message + "\n";
    j["undefined"] = c.message;
  }
  if (fine) j["fine_grid"] = fine_grid_report(p, c, *fine, eigensolver, json, line, text);
  text += fmt::format("accuracy       {}\n", kSpanwiseAccuracyNote);
  j["accuracy_note"] = kSpanwiseAccuracyNote;
  return j;
}

}  // namespace magnus
