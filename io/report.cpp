#include "io/report.hpp"

#include <fmt/core.h>

#include <cmath>

#include "io/hdf5_io.hpp"
#include "io/text_format.hpp"

namespace magnus {

std::string fmt_opt(const std::optional<double>& v, const char* spec) {
  return v ? fmt::format(fmt::runtime(spec), *v) : std::string("undefined");
}

namespace {

std::string deg(double rad) { return fmt::format("{:.3f}°", rad * 180.0 / M_PI); }

std::string points(const std::vector<StagnationPoint>& pts, double a) {
  if (pts.empty()) return "none";
  std::string s;
  for (const auto& p : pts) {
    if (!s.empty()) s += ", ";
    s += p.on_surface ? fmt::format("θ = {} on the surface", deg(p.theta))
                      : fmt::format("θ = {}, r = {:.6g} m = {:.6g} a (free)", deg(p.theta), p.r, p.r / a);
  }
  return s;
}

}  // namespace

std::string summary_text(const FlowResult& r, const std::string& output_path) {
  const Case& c = r.c;
  const PolarGrid& g = r.grid;
  const Forces& f = r.forces;
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) {
    s += fmt::format("{:<15}{}\n", label, text);
  };
  s += fmt::format("magnus {} — {}\n", MAGNUS_VERSION, c.title);
  line("case", fmt::format("a = {:.6g} m, ω = {:.6g} rad/s, U = {:.6g} m/s, α = aω/U = {}, ρ = {:.6g} kg/m³",
                           c.scene.radius, c.scene.spin, c.scene.speed, c.scene.speed > 0 ? fmt::format("{:.6g}", c.scene.spin_ratio()) : "undefined",
                           c.scene.density));
  line("circulation", fmt::format("Γ = {:.8g} m²/s ({})", c.scene.Gamma(),
                                  c.scene.circulation_given ? "given" : "spin model, Γ = 2πa²ω"));
  const double R = g.outer_radius() / g.a;
  line("grid", fmt::format("n_θ × n_r = {} × {} ({} nodes), {} spacing, R/a = {:.6g}{}, far field {}",
                           g.n_theta, g.n_r, g.nodes(), to_string(g.spacing), R,
                           std::fabs(R / c.grid.outer_radius - 1) > 1e-12
                               ? fmt::format(" (asked {:.6g}, rounded up to whole square cells)", c.grid.outer_radius) : "",
                           to_string(c.grid.far_field)));
  if (!r.info.grid_choice.empty()) line("", r.info.grid_choice);
  line("solver", fmt::format("{}, {} stencil, {} thread{}", r.info.method, to_string(c.solver.stencil), r.info.threads,
                             r.info.threads == 1 ? "" : "s"));
  line("timing", fmt::format("assemble {}, factor {}, solve {} (ψ_U and ψ_Γ), post-process {}; total {}", ms(r.timing.assemble_s),
                             ms(r.timing.factor_s), ms(r.timing.solve_s), ms(r.timing.postproc_s),
                             ms(r.timing.total_s)));
  s += "\n";
  line("lift F_y", fmt::format("{:.10g} N/m   (Kutta–Joukowski −ρUΓ = {:.10g} N/m)", f.lift, f.lift_kutta_joukowski));
  line("drag F_x", fmt::format("{:.3g} N/m   (d'Alembert: 0)", f.drag));
  if (f.cl) {
    line("C_L", fmt::format("numeric {:.10g}   Kutta–Joukowski {:.10g}   seed estimate {:.10g}", *f.cl,
                            *f.cl_kutta_joukowski, *f.cl_seed_estimate));
    const double kj = *f.cl_kutta_joukowski, seed = *f.cl_seed_estimate;
    line("", fmt::format("numeric/KJ − 1 = {}   KJ/seed = {}",
                         kj != 0 ? fmt::format("{:.3e}", *f.cl / kj - 1) : "undefined (Γ = 0)",
                         seed != 0 ? fmt::format("{:.6f} (π/2 = {:.6f})", kj / seed, M_PI / 2) : "undefined (ω = 0)"));
    line("C_D", fmt::format("{:.3e}", *f.cd));
  } else {
    line("C_L, C_D", "undefined (U = 0: no dynamic pressure to scale by)");
  }
  line("ΔP top−bottom", fmt::format("numeric {:.8g} Pa   exact 4ρUΓ/(2πa) = {:.8g} Pa   seed 2ρUaω = {:.8g} Pa",
                                    f.delta_p_top_bottom, f.delta_p_top_bottom_exact, f.delta_p_seed_estimate));
  if (f.delta_p_seed_estimate != 0.0)
    line("", fmt::format("numeric/seed = {:.6f}: potential flow doubles the shoulder speed (2U, not U)",
                         f.delta_p_top_bottom / f.delta_p_seed_estimate));
  line("Magnus S", fmt::format("numeric {} kg/m   exact 2πρa² = {:.8g} kg/m   seed 4ρa² = {:.8g} kg/m",
                               fmt_opt(f.magnus_S, "{:.8g}"), f.magnus_S_exact, 4.0 * c.scene.density * c.scene.radius * c.scene.radius));
  line("stagnation", "numeric " + points(r.stagnation, c.scene.radius));
  line("", "exact   " + points(r.stagnation_exact, c.scene.radius));
  s += "\n";
  line("errors", fmt::format("ψ max rel {:.3e}   Cp surface max abs {}   C_L rel {:.3e}   Γ rel {:.3e}",
                             r.errors.psi_max_rel, fmt_opt(r.errors.cp_surface_max_abs, "{:.3e}"), r.errors.cl_rel,
                             r.errors.circulation_rel));
  if (r.info.estimated_cl_rel >= 0.0)
    line("", fmt::format("C_L rel estimated (a posteriori) {:.3e}", r.info.estimated_cl_rel));
  if (!output_path.empty()) line("output", fmt::format("{} (+ {} for ParaView)", output_path, xdmf_path(output_path)));
  return s;
}

}  // namespace magnus
