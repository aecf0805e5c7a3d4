#pragma once
// The run summary of a navier-stokes result: the viscous figures beside the ideal ones for the same scene.
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// Scene with ν and Re; grid, Δt and the run (why it stopped, steps, wall time); C_L, C_D, St, S/(2πρa²)
/// viscous against ideal; torque and spin power; separation; a warning above Re ≈ 200 (real flow is 3D).
std::string viscous_summary_text(const FlowResult& r, const std::string& output_path);

/// Re above which 2D laminar flow past a cylinder is no longer what a real cylinder sees.
constexpr double kReynolds3D = 200.0;

/// Wall cells across D/√Re below which the summary warns: at Re = 100, α = 1 the mean drag was 1.9% high with
/// 6 cells (n_θ = 192), 11% with 3 and 23% with 2 (README, validation).
constexpr double kWallCellsForPercent = 6.0;

}  // namespace magnus
