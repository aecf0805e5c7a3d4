#pragma once
// Labels and views shared by the figures of a result (plot/figures.cpp, plot/figures_viscous.cpp):
// numbers as the pictures print them, the flow's label, the θ axis, the title and the field window.
// Internal to plot/.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "plot/figures.hpp"

namespace magnus::figure_labels {

inline std::string num(double v, int digits = 3) {
  return v == 0.0 ? "0" : fmt::format("{:.{}g}", v, digits);
}

/// "α = 1.5" (with the circulation when it is given, or "U = 0").
inline std::string flow_label(const Case& c) {
  if (c.scene.speed <= 0.0) return fmt::format("U = 0, Γ = {} m²/s", num(c.scene.Gamma()));
  std::string s = fmt::format("α = {}", num(c.scene.spin_ratio(), 4));
  if (c.scene.circulation_given) s += fmt::format(", Γ = {} m²/s", num(c.scene.Gamma()));
  return s;
}

/// flow_label, with the Reynolds number of a navier-stokes result and " (partial)" for a run stopped before
/// its end (every title of its pictures says so).
inline std::string flow_label(const FlowResult& r) {
  std::string s = flow_label(r.c);
  if (r.viscous && r.viscous->reynolds) s += fmt::format(", Re = {}", num(*r.viscous->reynolds, 4));
  if (r.viscous && r.viscous->partial) s += " (partial)";
  return s;
}

/// θ in degrees over one turn, for the surface plots.
inline void theta_axis(CurvePage& p) {
  p.xlabel = "θ (degrees, counter-clockwise from +x: 0° rear, 180° front)";
  p.fixed_x = true;
  p.x_min = 0.0;
  p.x_max = 360.0;
  p.x_tick = 45.0;
  p.x_subticks = 3;
}

inline std::string case_title(const std::string& title) {
  return literal_text(title.empty() ? std::string("Spinning cylinder") : title);
}

inline FieldView view_of(const FlowResult& r, const std::string& what,
                         const std::optional<PlotWindow>& window) {
  FieldView v;
  v.title = case_title(r.c.title) + ": " + what + ", " + flow_label(r);
  v.unit = r.grid.a;
  v.window = window_for(r, window);
  v.body_radius = 1.0;
  return v;
}

inline PolarField polar(const PolarGrid& g, const std::vector<double>& values) {
  return {g.r, g.theta, values};
}

}  // namespace magnus::figure_labels
