#include "io/report.hpp"

#include <fmt/core.h>

#include <cmath>

#include "io/finite.hpp"
#include "io/hdf5_io.hpp"
#include "io/report_scene.hpp"
#include "io/report_viscous.hpp"
#include "io/text_format.hpp"
#include "postproc/derived.hpp"

namespace magnus {

std::string fmt_opt(const std::optional<double>& v, const char* spec) {
  return v ? figure(*v, spec) : std::string("undefined");
}

namespace {

std::string deg(double rad) { return fmt::format("{:.3f}°", rad * 180.0 / M_PI); }

/// The points, in the result's order (θ in [0, 2π), ascending).
std::string points(const std::vector<StagnationPoint>& sorted, double a) {
  if (sorted.empty()) return "none";
  std::string s;
  for (const auto& p : sorted) {
    if (!s.empty()) s += ", ";
    s += p.on_surface ? fmt::format("θ = {} on the surface", deg(p.theta))
                      : fmt::format("θ = {}, r = {:.6g} m = {:.6g} a (free)", deg(p.theta), p.r, p.r / a);
  }
  return s;
}

/// "none", and why when the exact free point lies beyond the grid's outer radius R.
std::string numeric_points(const FlowResult& r) {
  const double a = r.c.scene.radius, R = r.grid.outer_radius();
  if (const auto p = stagnation_outside_grid(r))
    return fmt::format("none: the free point lies outside the grid (exact r_s/a = {:.6g}, grid R/a = {:.6g})",
                       p->r / a, R / a);
  return points(r.stagnation, a);
}

/// A number as {spec} would print it, with −0 printed as 0.
std::string num(double v, const char* spec = "{:.6g}") { return fmt::format(fmt::runtime(spec), v + 0.0); }

/// The seed estimates lift from ω: with a given Γ and no spin it says nothing (with the spin model, ω = 0 →
/// 0).
bool seed_defined(const Scene& sc) { return sc.spin != 0.0 || !sc.circulation_given; }

}  // namespace

namespace {

/// "case", "Reynolds", "circulation", "grid", "solver", "timing": the scene, the grid and the solve.
std::string setup_lines(const FlowResult& r) {
  const Case& c = r.c;
  const PolarGrid& g = r.grid;
  const Scene& sc = c.scene;
  const bool given = sc.circulation_given, moving = sc.speed > 0.0;
  // α = aω/U is the spin's ratio; with a given Γ the flow has the effective α_Γ = Γ/(2πaU) instead.
  std::string alpha = moving ? num(sc.spin_ratio()) : "undefined (U = 0)";
  if (const auto alpha_Gamma = derived_ratios(r).alpha_Gamma)
    alpha += fmt::format(", α_Γ = Γ/(2πaU) = {} (the given Γ sets the flow)", num(*alpha_Gamma));
  // The spin as given: in rev/min beside ω when cylinder.rpm set it.
  std::string s = summary_line(
      "case", fmt::format("a = {} m, ω = {} rad/s{}, U = {} m/s, α = aω/U = {}, ρ = {} kg/m³", num(sc.radius),
                          num(sc.spin), sc.rpm_given ? fmt::format(" ({} rpm)", num(*sc.rpm_given)) : "",
                          num(sc.speed), alpha, num(sc.density)));
  s += reynolds_line(sc);
  s += summary_line("circulation", fmt::format("Γ = {} m²/s ({})", num(sc.Gamma(), "{:.8g}"),
                                               given ? "given, not from the spin" : "spin model, Γ = 2πa²ω"));
  const double R = g.outer_radius() / g.a;
  s += summary_line(
      "grid",
      fmt::format("n_θ × n_r = {} × {} ({} nodes), {} spacing, R/a = {:.6g}{}, far field {}", g.n_theta,
                  g.n_r, g.nodes(), to_string(g.spacing), R,
                  std::fabs(R / c.grid.outer_radius - 1) > 1e-12
                      ? fmt::format(" (asked {:.6g}, rounded up to whole square cells)", c.grid.outer_radius)
                      : "",
                  to_string(c.grid.far_field)));
  if (!r.info.grid_choice.empty()) s += summary_line("", r.info.grid_choice);
  s += summary_line("solver",
                    fmt::format("{}, {} stencil, {} thread{}", r.info.method, to_string(c.solver.stencil),
                                r.info.threads, r.info.threads == 1 ? "" : "s"));
  s += summary_line("timing",
                    fmt::format("assemble {}, factor {}, solve {} (ψ_U and ψ_Γ), post-process {}; total {}",
                                ms(r.timing.assemble_s), ms(r.timing.factor_s), ms(r.timing.solve_s),
                                ms(r.timing.postproc_s), ms(r.timing.total_s)));
  return s;
}

/// "lift", "drag", "C_L", "C_D": the forces in the flow's frame and the lift coefficient three ways.
std::string lift_lines(const FlowResult& r) {
  const Forces& f = r.forces;
  const Scene& sc = r.c.scene;
  const bool given = sc.circulation_given, spinning = sc.spin != 0.0;
  std::string s;
  // Lift and drag in the flow's frame (across and along the freestream): the direction leaves them unchanged.
  s += summary_line("lift", fmt::format("{} N/m across the freestream   (Kutta–Joukowski −ρUΓ = {} N/m)",
                                        num(f.lift, "{:.10g}"), num(f.lift_kutta_joukowski, "{:.10g}")));
  s += summary_line("drag",
                    fmt::format("{} N/m along the freestream   (d'Alembert: 0)", num(f.drag, "{:.3g}")));
  if (!f.cl) return s + summary_line("C_L, C_D", "undefined (U = 0: no dynamic pressure to scale by)");
  const DerivedRatios d = derived_ratios(r);
  s += summary_line("C_L",
                    fmt::format("numeric {}   Kutta–Joukowski {}   seed estimate {}{}", num(*f.cl, "{:.10g}"),
                                num(*f.cl_kutta_joukowski, "{:.10g}"),
                                seed_defined(sc) ? num(*f.cl_seed_estimate, "{:.10g}") : "undefined (ω = 0)",
                                given && spinning ? " (−4α: from ω, not from the given Γ)" : ""));
  s += summary_line(
      "", fmt::format("numeric/KJ − 1 = {}   KJ/seed = {}",
                      d.cl_over_kj_minus_1 ? num(*d.cl_over_kj_minus_1, "{:.3e}") : "undefined (Γ = 0)",
                      !d.kj_over_seed ? "undefined (ω = 0)"
                      : given         ? fmt::format("{} (= α_Γ·π/(2α): π/2 only when Γ = 2πa²ω)",
                                                    num(*d.kj_over_seed, "{:.6f}"))
                              : fmt::format("{} (π/2 = {:.6f})", num(*d.kj_over_seed, "{:.6f}"), M_PI / 2)));
  return s + summary_line("C_D", num(*f.cd, "{:.3e}"));
}

/// "ΔP top−bottom" and "Magnus S": numeric, exact and the seed estimate.
std::string pressure_lines(const FlowResult& r) {
  const Forces& f = r.forces;
  const Scene& sc = r.c.scene;
  const bool given = sc.circulation_given, moving = sc.speed > 0.0, spinning = sc.spin != 0.0;
  std::string s = summary_line(
      "ΔP top−bottom",
      fmt::format("numeric {} Pa   exact 4ρUΓ/(2πa) = {} Pa   seed 2ρUaω = {}",
                  num(f.delta_p_top_bottom, "{:.8g}"), num(f.delta_p_top_bottom_exact, "{:.8g}"),
                  seed_defined(sc) ? num(f.delta_p_seed_estimate, "{:.8g}") + " Pa" : "undefined (ω = 0)"));
  const DerivedRatios d = derived_ratios(r);
  if (d.delta_p_over_seed) {
    const double ratio = *d.delta_p_over_seed;
    s += summary_line(
        "", given ? fmt::format("numeric/seed = {}: the given Γ, not the spin, sets ΔP (exact 2α_Γ/α)",
                                num(ratio, "{:.6f}"))
                  : fmt::format("numeric/seed = {}: potential flow doubles the shoulder speed (2U, not U)",
                                num(ratio, "{:.6f}")));
  }
  const std::string s_exact =
      !given     ? fmt::format("exact 2πρa² = {} kg/m", fmt_opt(f.magnus_S_exact, "{:.8g}"))
      : spinning ? fmt::format("exact ρΓ/ω = {} kg/m (the given Γ)", fmt_opt(f.magnus_S_exact, "{:.8g}"))
                 : "exact ρΓ/ω = undefined (ω = 0)";
  return s + summary_line("Magnus S", fmt::format("numeric {}{}   {}   seed 4ρa² = {} kg/m",
                                                  fmt_opt(f.magnus_S, "{:.8g}"),
                                                  f.magnus_S ? " kg/m"
                                                  : !moving  ? " (U = 0)"
                                                             : " (ω = 0)",
                                                  s_exact, num(d.magnus_S_seed, "{:.8g}")));
}

}  // namespace

std::string summary_text(const FlowResult& r, const std::string& output_path) {
  if (r.viscous) return viscous_summary_text(r, output_path);
  check_finite(r);  // nothing that is not finite is printed
  std::string s = fmt::format("magnus {} — {}\n", MAGNUS_VERSION, r.c.title);
  s += setup_lines(r) + "\n" + lift_lines(r) + pressure_lines(r);
  s += summary_line("stagnation", "numeric " + numeric_points(r));
  s += summary_line("", "exact   " + points(r.stagnation_exact, r.c.scene.radius));
  s += scene_lines(r);
  s += inviscid_bound_lines(r);
  s += "\n";
  s += summary_line(
      "errors",
      fmt::format("ψ max rel {}   Cp surface max abs {}   C_L rel {}   Γ rel {}",
                  num(r.errors.psi_max_rel, "{:.3e}"), fmt_opt(r.errors.cp_surface_max_abs, "{:.3e}"),
                  fmt_opt(r.errors.cl_rel, "{:.3e}"), num(r.errors.circulation_rel, "{:.3e}")));
  if (r.info.estimated_cl_rel >= 0.0)
    s += summary_line("", fmt::format("C_L rel estimated (a posteriori) {:.3e}", r.info.estimated_cl_rel));
  if (!output_path.empty())
    s += summary_line("output", fmt::format("{} (+ {} for ParaView)", output_path, xdmf_path(output_path)));
  return s;
}

}  // namespace magnus
