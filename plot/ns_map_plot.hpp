#pragma once
// The viscous S(Re, α) map as curves: S/(2πρa²) = C_L/C_L,ideal against α, one curve per Reynolds number.
#include <string>

#include "plot/curves.hpp"
#include "postproc/navier_stokes/continuation.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"

namespace magnus {

/// One joined point set per Re row (colours cycle): ● steady points, ○ time-averaged ones; points without
/// a ratio (α = 0, undefined) are left out. A map of one α continued in Re is one curve against Re.
/// With a computed 3D onset curve, the points above it (where the 2D flow is not real) are framed □ and the
/// title says over which α the curve was computed.
/// Throws std::runtime_error (one line saying why) when no point has a ratio.
void plot_ns_map(const NsMap& m, const std::string& png, PlotSize size = {}, const std::vector<Onset3d>& onset = {});

}  // namespace magnus
