// The scene's place in the world in the schema table: the spin in rpm, the flow direction, the ship's course,
// the span, and the forces they give (thrust, side force, totals in N). Absent keys are undefined.
#include "postproc/scene_forces.hpp"
#include "io/schema_build.hpp"

namespace magnus::schema_build {

namespace {

/// A figure of scene_forces(r).
AttrSpec force(const char* name, const char* units, const char* description,
               std::optional<double> SceneForces::*m, Models models = Models::all) {
  return only(models, num("/forces", name, units, description,
                          [m](const FlowResult& r) { return scene_forces(r).*m; }));
}

}  // namespace

std::vector<AttrSpec> scene_attributes() {
  const char* P = "/parameters";
  return {
      num(P, "rpm", "1/min", "spin in revolutions per minute, ω·60/(2π)",
          [](const FlowResult& r) { return opt(r.c.scene.rpm()); }),
      num(
          P, "direction", "degree",
          "the world direction the freestream flows towards, CCW from +x (the wind frame's +x)",
          [](const FlowResult& r) { return opt(r.c.scene.direction_deg); },
          [](FlowResult& r, double v) { r.c.scene.direction_deg = v; }),
      num(
          P, "course", "degree", "the ship's course, CCW from +x (undefined when not given)",
          [](const FlowResult& r) { return r.c.scene.course_deg; },
          [](FlowResult& r, double v) { r.c.scene.course_deg = v; }),
      num(
          P, "span", "m", "cylinder span b for the totals (undefined when not given)",
          [](const FlowResult& r) { return r.c.scene.span > 0.0 ? opt(r.c.scene.span) : std::nullopt; },
          [](FlowResult& r, double v) { r.c.scene.span = v; }),
      force("thrust", "N/m",
            "force along the course per unit span, ahead positive (D cos φ − L sin φ, φ = direction − course)",
            &SceneForces::thrust),
      force("side_force", "N/m",
            "force across the course per unit span, to port (CCW of the course) positive (D sin φ + L cos φ)",
            &SceneForces::side),
      force("lift_total", "N", "lift over the span, L·b", &SceneForces::lift_total),
      force("drag_total", "N", "drag over the span, D·b", &SceneForces::drag_total),
      force("thrust_total", "N", "thrust over the span", &SceneForces::thrust_total),
      force("side_force_total", "N", "side force over the span", &SceneForces::side_total),
      force("torque_total", "N*m", "mean torque over the span", &SceneForces::torque_total, Models::viscous),
      force("spin_power_total", "W", "mean power to keep the spin over the span", &SceneForces::spin_power_total,
            Models::viscous),
  };
}

}  // namespace magnus::schema_build
