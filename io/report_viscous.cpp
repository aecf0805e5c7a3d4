#include "io/report_viscous.hpp"
#include "physics/checked_cast.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "io/finite.hpp"
#include "io/hdf5_io.hpp"
#include "io/report.hpp"
#include "io/report_scene.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "io/report_steady.hpp"
#include "io/text_format.hpp"
#include "postproc/derived.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "solver/navier_stokes/rotation.hpp"

namespace magnus {

namespace {

std::string num(double v, const char* spec = "{:.6g}") { return figure(v + 0.0, spec); }

std::string wall(double seconds) {
  return seconds < 60.0 ? fmt::format("{:.3g} s", seconds)
                        : fmt::format("{}:{:02d} min", saturate_cast<long>(seconds) / 60,
                                      saturate_cast<long>(seconds) % 60);
}

/// What took the time: Newton's method, the eigenvalue test and the march, each when run ("" if none).
std::string phases_text(const ViscousPart& v) {
  std::string t;
  for (const auto& [name, secs] : {std::pair<const char*, std::optional<double>>{"Newton", v.newton_seconds},
                                   {"eigenvalue test", v.stability_seconds},
                                   {"march", v.newton ? std::nullopt : v.march_seconds}})
    if (secs) t += fmt::format("{}{} {}", t.empty() ? "" : ", ", name, wall(*secs));
  return t;
}

/// What would resolve the wall: the grid with kWallCellsResolved cells across the boundary layer.
std::string resolving_text(const Case& c) {
  const ResolvingGrid need = resolving_grid(c, kWallCellsResolved);
  return fmt::format("grid.n_theta ≥ {:.0f} with grid.n_r = 0, or grid.n_r ≥ {:.0f}", need.n_theta, need.n_r);
}

/// "label          text\n": a summary line, the label in a column of 15.
std::string labelled(const std::string& label, const std::string& text) {
  return fmt::format("{:<15}{}\n", label, text);
}

/// The boundary layer's line: the wall cells across D/√(Re(1 + α²)) and what they mean for the forces.
std::string wall_text(const FlowResult& r, double cells, const std::string& raise) {
  const ViscousPart& v = *r.viscous;
  const bool unresolved = cells < kWallCellsResolved;
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) { s += labelled(label, text); };
  // The boundary layer's thickness scales as D/√Re: the cells across it say how well the wall is resolved.
  if (v.reynolds && *v.reynolds > 0.0) {
    const std::string grade =
        unresolved ? fmt::format(" — not resolved: below {:.0f} cell the forces are not meaningful ({})",
                                 kWallCellsResolved, raise)
        : cells < kWallCellsForTenPercent
            ? fmt::format(
                  " — coarse: below {:.0f} cells C_D can be off by more than 10% (+14% with 4.5 cells at "
                  "Re 100, α 2; raise grid.refine, or leave grid.n_theta and grid.n_r to magnus)",
                  kWallCellsForTenPercent)
        : cells < kWallCellsForPercent
            ? fmt::format(
                  " — coarse: below {:.0f} cells expect C_D errors of a few % (+4.6% with 5.6 cells at "
                  "Re 100, α 1.5; raise grid.refine, or leave grid.n_theta and grid.n_r to magnus)",
                  kWallCellsForPercent)
            : std::string();
    line("", fmt::format("boundary layer: {} wall cells across D/√(Re(1 + α²)){}",
                         cells < kWallCellsResolved ? num(cells, "{:.2g}") : num(cells, "{:.1f}"), grade));
  }
  return s;
}

/// How the run went: Newton's method or the march (steps, Δt, speed), the phases' times, why it stopped.
std::string run_text(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  const ViscousPart& v = *r.viscous;
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) { s += labelled(label, text); };
  const ViscousRatios ratios = viscous_ratios(r);
  const double steps_per_s = ratios.steps_per_second.value_or(0.0);  // this run's steps
  const std::string phases = phases_text(v);
  if (v.newton)
    line("run", fmt::format("steady state by Newton's method, {} ({:.0f} ms){}", wall(r.timing.total_s),
                            1e3 * r.timing.total_s, phases.empty() ? "" : ": " + phases));
  else
    line("run", fmt::format("t = {} s = {} {}, {} steps{} of Δt = {} s ({} {}), {} ({:.0f} steps/s)",
                            num(v.t), fmt_opt(ratios.t_convective, "{:.5g}"), time_unit_name(sc), v.steps,
                            v.steps_resumed > 0 ? fmt::format(" ({} before --resume)", v.steps_resumed) : "",
                            num(v.dt, "{:.4g}"), fmt_opt(ratios.dt_convective, "{:.4g}"), time_unit_name(sc),
                            wall(r.timing.total_s), steps_per_s));
  if (!v.newton && (v.newton_seconds || v.stability_seconds)) line("", "time: " + phases);
  line("", fmt::format("stopped: {}{}", v.status, v.partial ? " — a PARTIAL result (the file says so)" : ""));
  if (!v.converged && !v.partial)
    line("", "not converged: the means below are the last period's (or the last step's); raise time.end");
  return s;
}

/// The figures beside the ideal ones: C_L, C_D, St, lift, drag, S (a finding only where resolved), torque.
std::string figures_text(const FlowResult& r, bool unresolved) {
  const Scene& sc = r.c.scene;
  const ViscousPart& v = *r.viscous;
  const bool moving = sc.speed > 0.0;
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) { s += labelled(label, text); };
  s += "\n";
  s += fmt::format("{:<15}{:<40}{}\n", "", "viscous (this run)", "ideal (potential flow, same scene)");
  auto row = [&](const std::string& label, const std::string& a, const std::string& b) {
    std::string cell = fmt::format("{:<40}", a);  // a column of 40, and a space before b when a fills it
    if (!b.empty() && cell.back() != ' ') cell += ' ';
    s += fmt::format("{:<15}{}{}\n", label, cell, b);
  };
  const char* kind = v.steady ? "(steady)" : "(mean)";  // a steady flow's mean is its value
  if (moving) {
    const std::string amp =
        v.cl_amplitude ? fmt::format(" ± {} (amplitude)", fmt_opt(v.cl_amplitude, "{:.4f}")) : "";
    row("C_L", fmt::format("{} {}{}", fmt_opt(v.cl_mean, "{:.5f}"), kind, amp),
        fmt::format("{} (−2πα)   seed −4α = {}", fmt_opt(v.cl_ideal, "{:.5f}"),
                    fmt_opt(r.forces.cl_seed_estimate, "{:.5f}")));
    row("C_D", fmt::format("{} {}", fmt_opt(v.cd_mean, "{:.5f}"), kind), "0 (d'Alembert)");
    row("",
        fmt::format("last step: pressure {} + friction {}", fmt_opt(v.last.C_D_pressure, "{:.4f}"),
                    fmt_opt(v.last.C_D_friction, "{:.4f}")),
        "");
    row("St = fD/U",
        v.strouhal   ? fmt_opt(v.strouhal, "{:.5f}")
        : v.steady   ? "steady (no shedding)"
        : v.periodic ? "undefined (the period is not confirmed: see stopped)"
                     : "no period found",
        "— (no wake)");
    row("lift", fmt::format("{} N/m {}, across the flow", num(v.lift_mean, "{:.6g}"), kind),
        fmt::format("{} N/m (−ρUΓ)", num(r.forces.lift_kutta_joukowski, "{:.6g}")));
    row("drag", fmt::format("{} N/m {}, along the flow", num(v.drag_mean, "{:.6g}"), kind), "0 N/m");
    row("Magnus S",
        r.forces.magnus_S ? fmt::format("{} kg/m", fmt_opt(r.forces.magnus_S, "{:.6g}")) : "undefined",
        fmt::format("2πρa² = {} kg/m", fmt_opt(r.forces.magnus_S_exact, "{:.6g}")));
    // A finding only where the model holds: resolved, and 2D laminar flow is what a real cylinder sees.
    const std::string ratio = fmt_opt(v.magnus_ratio, "{:.4f}"), re = fmt_opt(v.reynolds, "{:.4g}"),
                      al = num(sc.spin_ratio(), "{:.4g}");
    line(
        "S/(2πρa²)",
        !v.magnus_ratio ? std::string("undefined (ω = 0: no Magnus lift to compare)")
        : unresolved    ? ratio + " — not meaningful: the boundary layer is not resolved (see the verdict)"
        : two_d_is_real(v) == std::optional<bool>(true)
            ? fmt::format("{}: the share of the ideal lift a real cylinder gets at Re = {}, α = {}", ratio,
                          re, al)
            : fmt::format("{}: the 2D laminar model's share of the ideal lift at Re = {}, α = {} ({})", ratio,
                          re, al,
                          two_d_is_real(v) ? "not a real cylinder's: its flow is three-dimensional there"
                                           : "a real cylinder's where its flow stays 2D: see 3D"));
  } else {
    line("C_L, C_D", "undefined (U = 0: no dynamic pressure to scale by); forces in N/m below");
    line("forces", fmt::format("F_x = {} N/m, F_y = {} N/m (last step)", num(v.last.F_x, "{:.4g}"),
                               num(v.last.F_y, "{:.4g}")));
  }
  line("torque", fmt::format("{} N·m/m {}, spin power −Mω = {} W/m", num(v.torque_mean, "{:.6g}"), kind,
                             num(v.spin_power_mean, "{:.6g}")));
  if (!moving) {  // still fluid: the potential vortex u_θ = a²ω/r is an exact viscous solution too
    const ViscousRatios ratios = viscous_ratios(r);
    line("", fmt::format("steady potential vortex: −4πμa²ω = {} N·m/m (this run: {:+.2f}%)",
                         num(*ratios.torque_potential_vortex, "{:.6g}"),
                         100.0 * ratios.torque_over_potential_vortex_minus_1.value_or(0.0)));
  }
  return s;
}

/// The run's estimate of its discretisation error (one line), what is undefined and why, and what the
/// means' spread adds when they had not converged; "" when no estimate was asked (the map's points).
std::string estimate_text(const ViscousPart& v, double tolerance) {
  if (v.error_method.empty() && v.error_note.empty()) return "";
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) { s += labelled(label, text); };
  const bool any = v.cl_mean_rel_estimate || v.cd_mean_rel_estimate || v.strouhal_rel_estimate;
  if (!any) {
    line("error (est.)", "undefined (" + v.error_note + ")");
    return s;
  }
  auto pct = [](const char* name, const std::optional<double>& e) {
    return e ? fmt::format("{} ±{}%", name, num(100.0 * *e, "{:.2f}")) : fmt::format("{} undefined", name);
  };
  std::string parts = pct("C_L", v.cl_mean_rel_estimate) + ", " + pct("C_D", v.cd_mean_rel_estimate);
  if (!v.steady) parts += ", " + pct("St", v.strouhal_rel_estimate);
  line("error (est.)", parts + " (" + v.error_method + ")");
  if (!v.error_note.empty()) line("", "undefined: " + v.error_note);
  if (!v.means_converged && v.means_spread_rel)
    line("", fmt::format("the means had not converged when the run stopped at time.end: the {}, {}%, is part "
                         "of the estimate",
                         v.periodic ? "spread between periods" : "drift over the last window",
                         num(100.0 * *v.means_spread_rel, "{:.2f}")));
  if (const std::string d = drift_text(v); !d.empty()) line("", d);
  if (v.tolerance_met)
    line("", fmt::format("grid.tolerance = {:g}: {}{}", tolerance,
                         *v.tolerance_met ? "met by every estimate" : "NOT met by the estimate above",
                         v.tolerance_note.empty() ? "" : " (" + v.tolerance_note + ")"));
  return s;
}

/// Separation, recirculation, the steady study, stability, and the notes on Re, D/Re and R.
std::string findings_text(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  const ViscousPart& v = *r.viscous;
  const PolarGrid& g = r.grid;
  const bool moving = sc.speed > 0.0;
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) { s += labelled(label, text); };
  std::string sep;
  for (double th : v.separation) sep += (sep.empty() ? "" : ", ") + fmt::format("{:.2f}°", th * 180.0 / M_PI);
  line("separation", sep.empty() ? "none (no point where the wall flow leaves the wall)"
                                 : "θ = " + sep + (v.steady ? " (steady" : " (last step") +
                                       "; τ_w changes sign from + to −)");
  if (v.recirculation_length)
    line("recirculation", *v.recirculation_length > 0.0
                              ? fmt::format("L/D = {:.4f} (steady)", *v.recirculation_length)
                              : std::string("none (no bubble behind the body; steady)"));
  s += steady_study_text(v);
  if (const auto st = viscous_ratios(r).eigen_strouhal; v.eigenvalue_real && v.eigenvalue_imag)
    line("stability", fmt::format("steady state's leading eigenvalue λ·{} = {:+.5f} {:+.5f}i ({}; St {})",
                                  time_unit_name(sc), *v.eigenvalue_real, *v.eigenvalue_imag,
                                  *v.eigenvalue_real < 0.0 ? "stable" : "unstable: it sheds",
                                  st ? fmt::format("{:.4f}", *st) : std::string("undefined (U = 0)")));
  if (v.reynolds) line("3D", three_d_text(v, sc.spin_ratio()));
  // The viscous (Oseen) length D/Re: beyond R the outer boundary cuts into it, and the forces depend on R.
  if (v.reynolds && viscous_length_beyond_grid(g, *v.reynolds))
    line("note",
         fmt::format("the viscous length D/Re = {} D reaches beyond the grid (R = {} D): the forces "
                     "depend on R (raise domain.outer_radius)",
                     num(1.0 / *v.reynolds, "{:.3g}"), num(g.outer_radius() / (2.0 * g.a), "{:.3g}")));
  // A near outer boundary: the wake's vortices reach it before they have decayed (README: measured
  // R-dependence).
  if (moving && g.outer_radius() < kOuterRadiusForWake * (1.0 - 1e-9) * g.a)
    line(
        "note",
        fmt::format("the outer boundary R = {} D is close for a wake: at Re 100, α = 1, against R = 50 D, St "
                    "moved by −0.7% at R = 25 D, −2.6% at 15 D, −6% at 10 D (C_D −1.8%), −18% at 5 D (C_D "
                    "−9%), and at R ≤ 1.5 D the flow came out steady (C_D 0.80 against 1.10); raise "
                    "domain.outer_radius (default 100 = 50 D)",
                    num(g.outer_radius() / (2.0 * g.a), "{:.3g}")));
  return s;
}

}  // namespace

std::string drift_text(const ViscousPart& v) {
  struct Part {
    const char* name;
    const std::optional<double>& drift;
    const std::optional<double>& bar;
  };
  const Part parts[] = {{"C_L", v.cl_mean_drift_rel, v.cl_mean_rel_estimate},
                        {"C_D", v.cd_mean_drift_rel, v.cd_mean_rel_estimate},
                        {"St", v.strouhal_drift_rel, v.strouhal_rel_estimate}};
  std::string most, largest;
  double d_max = -1.0;
  for (const Part& p : parts) {
    if (!p.drift) continue;
    if (*p.drift > d_max) d_max = *p.drift, largest = p.name;
    if (p.bar && *p.drift > 0.5 * *p.bar)
      most += fmt::format("{}{} ({}% of ±{}%)", most.empty() ? "" : ", ", p.name, num(100.0 * *p.drift, "{:.3f}"),
                          num(100.0 * *p.bar, "{:.3f}"));
  }
  if (d_max <= 0.0) return "";  // none, or an orbit's: periodic by construction, nothing drifts
  if (!most.empty())
    return "the means were still drifting when the run stopped: the drift still to come is most of the bar "
           "of " + most;
  return fmt::format("the drift still to come of the last periods' means, at most {}% ({}), is part of the estimate",
                     num(100.0 * d_max, "{:.3f}"), largest);
}

std::optional<bool> two_d_is_real(const ViscousPart& v) {
  if (!v.reynolds || !v.onset3d_reynolds) return std::nullopt;
  return *v.reynolds < *v.onset3d_reynolds;
}

std::string three_d_text(const ViscousPart& v, double alpha) {
  if (!v.onset3d_alpha_min || !v.onset3d_alpha_max)
    return "whether this 2D flow is real is not computed for this run: magnus stability CASE --spanwise "
           "--critical-reynolds A:B --output F.h5 finds the 3D onset, magnus run CASE --onset3d F.h5 applies it";
  const std::string span = *v.onset3d_alpha_min == *v.onset3d_alpha_max
                               ? fmt::format("α = {:.4g} only", *v.onset3d_alpha_min)
                               : fmt::format("α {:.4g} to {:.4g}", *v.onset3d_alpha_min, *v.onset3d_alpha_max);
  if (!v.onset3d_reynolds || !v.reynolds)
    return fmt::format("undefined at α = {:.4g}: the computed 3D onset given covers {} ({})", alpha, span,
                       v.onset3d_files);
  if (*two_d_is_real(v))
    return fmt::format("2D flow is real here: Re = {:.6g} is below the computed 3D onset Re_c = {:.5g} at α = "
                       "{:.4g} ({})",
                       *v.reynolds, *v.onset3d_reynolds, alpha, v.onset3d_files);
  return fmt::format("Re = {:.6g} is not below the computed 3D onset Re_c = {:.5g} at α = {:.4g} ({}): real flow "
                     "is three-dimensional here; this is the 2D laminar answer, not the real one",
                     *v.reynolds, *v.onset3d_reynolds, alpha, v.onset3d_files);
}

bool viscous_length_beyond_grid(const PolarGrid& g, double reynolds) {
  return reynolds > 0.0 && 2.0 * g.a / reynolds > g.outer_radius();
}

std::string viscous_summary_text(const FlowResult& r, const std::string& output_path) {
  check_finite(r);  // nothing that is not finite is printed
  const Case& c = r.c;
  const ViscousPart& v = *r.viscous;
  const PolarGrid& g = r.grid;
  const Scene& sc = c.scene;
  std::string s = fmt::format("magnus {} — {}\n", MAGNUS_VERSION, c.title);
  // Forces that mean nothing are said so first, before any figure could be read as a finding.
  const double cells = viscous_ratios(r).wall_cells.value_or(1e300);
  const bool unresolved = cells < kWallCellsResolved;
  const std::string raise = cells < kWallCellsForPercent ? resolving_text(c) : std::string();
  if (unresolved)
    s += labelled("verdict",
                  fmt::format("NOT RESOLVED: {} wall cells across the boundary layer D/√(Re(1 + α²)), "
                              "below {:.0f}: the forces below are not meaningful ({} gives one cell)",
                              num(cells, "{:.2g}"), kWallCellsResolved, raise));
  s += labelled("case",
                fmt::format("a = {} m, ω = {} rad/s, U = {} m/s, α = aω/U = {}, ρ = {} kg/m³", num(sc.radius),
                            num(sc.spin), num(sc.speed),
                            sc.speed > 0.0 ? num(sc.spin_ratio()) : "undefined (U = 0)", num(sc.density)));
  s += labelled("", fmt::format("ν = {} m²/s, Re = U·2a/ν = {}", num(sc.viscosity),
                                v.reynolds ? num(*v.reynolds, "{:.6g}") : "undefined (U = 0)"));
  s += labelled(
      "model",
      fmt::format("navier-stokes: 2D incompressible laminar, vorticity–streamfunction, no slip held "
                  "exactly{}; advection order {} in θ, {} in ξ (solver.advection_order, advection_order_xi){}",
                  c.solver.wall_closure == "jensen" ? " (Jensen's second-order wall closure)" : "",
                  c.solver.advection_order, c.solver.advection_order_xi,
                  rotation_implicit(ns_params(c)) ? "; the spin's vortex implicit (solver.implicit_rotation)" : ""));
  const std::string rings =
      c.grid.wall_refinement > 1.0
          ? fmt::format("rings clustered at the wall (Δξ {:.3g}× finer there, over ξ ≈ {:.2g})",
                        c.grid.wall_refinement, c.grid.wall_layer)
          : std::string("geometric spacing (uniform in ξ)");
  s += labelled("grid", fmt::format("n_θ × n_r = {} × {} ({} nodes), {}, R/a = {:.6g}", g.n_theta, g.n_r,
                                    g.nodes(), rings, g.outer_radius() / g.a));
  if (c.grid.absorbing_layer > 0.0)
    s += labelled("", fmt::format("absorbing layer from r/a = {:.6g} to R: the vorticity fades at up to {:.3g} {} "
                                  "(domain.absorbing_layer, absorbing_strength)",
                                  c.grid.absorbing_layer, c.grid.absorbing_strength, rate_unit_name(c.scene)));
  s += labelled("", scene_grid_text(c));
  s += wall_text(r, cells, raise);
  s += run_text(r);
  s += figures_text(r, unresolved);
  s += estimate_text(v, c.grid.tolerance);
  s += scene_lines(r);  // direction, a rotor sail's course, the span's totals
  s += findings_text(r);
  if (!output_path.empty())
    s += labelled("output", fmt::format("{} (+ {} for ParaView)", output_path, xdmf_path(output_path)));
  return s;
}

}  // namespace magnus
