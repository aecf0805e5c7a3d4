#include "postproc/scene_forces.hpp"

#include <cmath>

namespace magnus {

namespace {

/// v·b, N (or N·m, W); empty without a span or when the product is not finite.
std::optional<double> times(const std::optional<double>& v, double span) {
  if (!v || span <= 0.0 || !std::isfinite(*v * span)) return std::nullopt;
  return *v * span;
}

}  // namespace

SceneForces scene_forces(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  SceneForces f;
  f.lift = r.viscous ? r.viscous->lift_mean : r.forces.lift;
  f.drag = r.viscous ? r.viscous->drag_mean : r.forces.drag;
  f.world = world_force(f.drag, f.lift, sc.direction_deg);
  if (sc.course_deg) {
    const CourseForce c = course_force(f.drag, f.lift, sc.direction_deg, *sc.course_deg);
    f.thrust = c.thrust, f.side = c.side;
  }
  const double b = sc.span;
  f.lift_total = times(f.lift, b);
  f.drag_total = times(f.drag, b);
  f.thrust_total = times(f.thrust, b);
  f.side_total = times(f.side, b);
  if (r.viscous) {
    f.torque_total = times(r.viscous->torque_mean, b);
    f.spin_power_total = times(r.viscous->spin_power_mean, b);
  }
  return f;
}

}  // namespace magnus
