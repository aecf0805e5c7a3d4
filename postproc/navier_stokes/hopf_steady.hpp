#pragma once
// The steady state at one point x of a Hopf search (critical.hpp): by Newton's method (chord steps while
// they contract ten-fold) from a guess, by natural continuation from a converged neighbouring point of
// the same search (the step halved where Newton fails), from the potential flow, or continued from a safe
// point where Newton reaches none from the potential flow.
#include <optional>

#include "postproc/navier_stokes/critical.hpp"

namespace magnus {

/// a + w·(b − a) in ψ, ζ and Γ_R (the rest a's): between two steady states of one grid for 0 ≤ w ≤ 1, beyond
/// b for w > 1 (a Newton start, interpolated or extrapolated).
NsState blend(const NsState& a, const NsState& b, double w);

/// The steady state at x: Newton from `guess` (a state of other parameters on the same grid, or one
/// interpolated between two), else from `from` by continuation, else from the potential flow, else
/// continued from a safe point (at this α from Re = 60 for a spin search above it, then from α = 0 or
/// Re = 20). potential_first: the potential flow before the continuation (at the far end of a wide bracket
/// one Newton solve from it, 7.5 s at Re 50, α 2.6, where continuation from α 0.05 took 97 s). nullopt
/// when none converges.
std::optional<NsState> steady_at(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                                 const NsState* guess, bool potential_first = false);

}  // namespace magnus
