#include "io/report_scene.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "io/reference_file.hpp"
#include "io/report.hpp"
#include "io/rotor_data.hpp"
#include "postproc/derived.hpp"
#include "postproc/scene_forces.hpp"

namespace magnus {

namespace {

/// A number as {spec} would print it, with −0 printed as 0.
std::string num(double v, const char* spec = "{:.6g}") { return fmt::format(fmt::runtime(spec), v + 0.0); }

/// "Stojković et al. 2002" from a label "viscous, Re = 100 (Stojković et al. 2002)"; else the label.
std::string who(const std::string& label) {
  const size_t open = label.rfind('('), close = label.rfind(')');
  return open != std::string::npos && close != std::string::npos && close > open + 1
             ? label.substr(open + 1, close - open - 1)
             : label;
}

/// An angle in degrees as given: "90°".
std::string deg(double d) { return num(d, "{:.6g}") + "°"; }

}  // namespace

std::string summary_line(const std::string& label, const std::string& text) {
  return fmt::format("{:<15}{}\n", label, text);
}

std::optional<NearestReference> nearest_reference(const Scene& sc, const ViscousReference& ref) {
  if (sc.speed <= 0.0) return std::nullopt;
  const double alpha = sc.spin_ratio(), a = std::fabs(alpha), re = sc.reynolds();
  std::optional<NearestReference> best;
  double best_da = 0.0, best_dre = 0.0;
  for (const auto& d : ref.datasets)
    for (const auto& p : d.points) {
      const double da = std::fabs(std::fabs(p.alpha) - a);
      const double dre = re > 0.0 && d.reynolds > 0.0 ? std::fabs(std::log(re / d.reynolds)) : 0.0;
      if (da > kReferenceAlphaReach) continue;
      if (best && (da > best_da || (da == best_da && dre >= best_dre))) continue;
      const double sign = (alpha < 0.0) == (p.alpha < 0.0) ? 1.0 : -1.0;
      best = NearestReference{sign * p.alpha + 0.0, d.reynolds, sign * p.cl + 0.0, d.label, d.source};
      best_da = da, best_dre = dre;
    }
  return best;
}

const ViscousReference* shipped_reference() {
  static const std::optional<ViscousReference> ref = []() -> std::optional<ViscousReference> {
    try {
      return load_viscous_reference(viscous_reference_path());
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }();
  return ref ? &*ref : nullptr;
}

std::string newtons(double v, const char* unit) {
  const double m = std::fabs(v);
  const std::string base = num(v, "{:.6g}") + " " + unit;
  if (m >= 1e6) return fmt::format("{} ({} M{})", base, num(v / 1e6, "{:.4g}"), unit);
  if (m >= 1e3) return fmt::format("{} ({} k{})", base, num(v / 1e3, "{:.4g}"), unit);
  return base;
}

std::string scene_lines(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  const SceneForces f = scene_forces(r);
  const char* per = r.viscous ? " (means)" : "";
  std::string s;
  if (sc.direction_deg != 0.0) {
    s += summary_line(
        "direction",
        fmt::format("freestream towards {} (CCW from +x); x, y, u_x, u_y in this world frame, θ from "
                    "the freestream",
                    deg(sc.direction_deg)));
    // Lift and drag are in the flow's frame; the world's components of the same force beside them.
    const WorldForce& w = f.world;
    s += summary_line("", fmt::format("force in the world frame: F_x = {} N/m, F_y = {} N/m{}",
                                      num(w.x, "{:.6g}"), num(w.y, "{:.6g}"), per));
  }
  if (f.thrust)
    s += summary_line(
        "course", fmt::format("{}: thrust {} N/m (ahead +), side force {} N/m (to port +){}",
                              deg(*sc.course_deg), num(*f.thrust, "{:.8g}"), num(*f.side, "{:.6g}"), per));
  if (sc.span > 0.0) {
    std::string t = fmt::format("b = {} m: lift {}, drag {}", num(sc.span), newtons(*f.lift_total),
                                newtons(*f.drag_total));
    if (f.thrust_total) t += fmt::format(", thrust {}, side force {}", newtons(*f.thrust_total), newtons(*f.side_total));
    s += summary_line("span", t);
    if (f.torque_total)
      s += summary_line("", fmt::format("torque {}, spin power {}", newtons(*f.torque_total, "N·m"),
                                        newtons(*f.spin_power_total, "W")));
  }
  return s;
}

std::string reynolds_line(const Scene& sc) {
  if (sc.viscosity <= 0.0) return "";
  return summary_line("Reynolds",
                      sc.speed > 0.0
                          ? fmt::format("Re = U·2a/ν = {} (ν = {} m²/s; potential flow does not use it)",
                                        num(sc.reynolds(), "{:.6g}"), num(sc.viscosity))
                          : fmt::format("undefined (U = 0; ν = {} m²/s)", num(sc.viscosity)));
}

std::string inviscid_bound_lines(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  std::string s;
  if (sc.speed <= 0.0 || !r.forces.cl) return s;
  s += summary_line("ideal",
                    "potential flow is the inviscid upper bound: a real (viscous) cylinder gets less lift "
                    "and some drag");
  const ViscousReference* ref = shipped_reference();
  if (!ref) return s + summary_line("", "viscous reference: the data file cannot be read");
  if (const auto n = nearest_reference(sc, *ref)) {
    const std::optional<double> share = share_of_ideal_lift(n->cl, n->alpha);
    s += summary_line(
        "", fmt::format("viscous reference at Re = {}, α = {}: C_L = {} = {} of −2πα ({}, {}){}",
                        num(n->reynolds), num(n->alpha), num(n->cl, "{:.4g}"),
                        share ? num(*share, "{:.3f}") : "—", who(n->label), n->source,
                        sc.viscosity > 0.0 && std::fabs(std::log(sc.reynolds() / n->reynolds)) > std::log(2.0)
                            ? fmt::format(" — not this Re ({})", num(sc.reynolds(), "{:.3g}"))
                            : ""));
  } else {
    double amax = 0.0;
    std::string res;
    for (const auto& d : ref->datasets) {
      for (const auto& p : d.points) amax = std::max(amax, std::fabs(p.alpha));
      const std::string re = num(d.reynolds);
      if (res.find(re) == std::string::npos) res += (res.empty() ? "" : ", ") + re;
    }
    s += summary_line(
        "", fmt::format("viscous reference: none within Δα = {} of α = {} (tabulated: |α| ≤ {} at Re = {})",
                        kReferenceAlphaReach, num(sc.spin_ratio(), "{:.4g}"), num(amax), res));
  }
  return s + rotor_lines(sc);
}

std::string rotor_lines(const Scene& sc) {
  if (!(sc.span > 0.0) || sc.speed <= 0.0) return "";
  const RotorData* data = shipped_rotor_data();
  if (!data) return "\n" + summary_line("rotor data", "cannot be read: " + rotor_data_error());
  const double re = sc.viscosity > 0.0 ? sc.reynolds() : 0.0;
  // The block's heading goes on the "rotor data" label; its lines are indented under it.
  const std::string block = rotor_comparison_text(*data, re, sc.spin_ratio(), sc.span / (2.0 * sc.radius));
  std::string out;
  size_t start = 0;
  for (size_t end; (end = block.find('\n', start)) != std::string::npos; start = end + 1)
    out += summary_line(start == 0 ? "rotor data" : "", block.substr(start, end - start));
  return out;
}

}  // namespace magnus
