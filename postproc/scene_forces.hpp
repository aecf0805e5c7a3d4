#pragma once
// A result's forces as an engineer reads them: per metre in the wind frame (lift across the freestream, drag
// along it) and in the world's x, y, the rotor sail's thrust and side force along its course, and the totals
// for the span. Computed here, before any report: io prints them.
#include <optional>

#include "postproc/result.hpp"

namespace magnus {

/// The engineering figures of one result. Potential flow: the surface integral; navier-stokes: the means.
struct SceneForces {
  double lift = 0.0, drag = 0.0;       ///< L across the freestream (CCW of it), D along it, N/m
  WorldForce world;                    ///< F_x, F_y: (D, L) turned by the direction β (world_force), N/m
  std::optional<double> thrust, side;  ///< along the course (ahead +) and across it (port +), N/m
  std::optional<double> lift_total, drag_total, thrust_total, side_total;  ///< × span b, N
  std::optional<double> torque_total;      ///< mean torque × b, N·m (navier-stokes only)
  std::optional<double> spin_power_total;  ///< mean spin power × b, W (navier-stokes only)
};

/// The world's F_x, F_y, thrust, side (with flow.course), the totals (with cylinder.span); empty where not
/// given. A total that is not finite is empty (undefined), never inf.
SceneForces scene_forces(const FlowResult& r);

}  // namespace magnus
