#pragma once
// The run summary of a navier-stokes result: the viscous figures beside the ideal ones for the same scene.
#include <optional>
#include <string>

#include "postproc/result.hpp"

namespace magnus {

/// Scene with ν and Re; grid, Δt and the run (why it stopped, steps, wall time); C_L, C_D, St, S/(2πρa²)
/// viscous against ideal; torque and spin power; separation; whether the 2D flow is real (three_d_text).
std::string viscous_summary_text(const FlowResult& r, const std::string& output_path);

/// The summary's line on the drift still to come of the means (v's *_drift_rel; "" when none is set or
/// all are 0, as an orbit's): the bars it dominates (more than half of the bar) with drift and bar in %, else
/// that it is part of them.
std::string drift_text(const ViscousPart& v);

/// Whether the 2D flow of v is real by the computed 3D onset the run was given (magnus run --onset3d):
/// Re < Re_c(α); undefined without one, or outside the α it spans.
std::optional<bool> two_d_is_real(const ViscousPart& v);

/// The summary's "3D" line: the verdict of the computed onset given (Re against Re_c at α, and the files),
/// "undefined" outside the α it spans, or that none was computed and how to compute one.
std::string three_d_text(const ViscousPart& v, double alpha);

/// Wall cells across D/√(Re(1 + α²)) below which the summary warns. At Re = 100 on R = 100a the mean drag
/// against its grid-converged value (Richardson on 236, 471, 942 rings) was off by +1.2% with 7.1 cells
/// (α = 1, the default grid), +4.6% with 5.6 (α = 1.5) and +14% with 4.5 (α = 2).
constexpr double kWallCellsForPercent = 6.0;
/// Wall cells below which the warning says C_D can be off by more than 10% (+14% with 4.5 cells, α = 2).
constexpr double kWallCellsForTenPercent = 5.0;

/// Wall cells across D/√(Re(1 + α²)) below which the boundary layer is not resolved at all and the forces
/// are not meaningful: n_θ = 8 at Re 200, α 6 (0.04 cells) gave C_L of the wrong sign, Re = 1e9 C_D 0.00001.
constexpr double kWallCellsResolved = 1.0;

/// R/a below which the summary notes that the outer boundary is close for a wake (St moves by more than 1%,
/// the mean forces by 1–9% below 20a). At Re 100, α = 1 on the
/// default grid, against R = 100a: St −0.7% at 50a, −2.6% at 30a, −6% at 20a (C_D −1.8%), −18% at 10a
/// (C_D −9%); R = 2a and 3a came out steady with C_D 0.80 (the shedding wake: 1.10).
constexpr double kOuterRadiusForWake = 50.0;

/// The viscous (Oseen) length D/Re reaches beyond the outer radius R: the forces then depend on R.
bool viscous_length_beyond_grid(const PolarGrid& g, double reynolds);

}  // namespace magnus
