#pragma once
// One point of a Hopf search (critical.hpp): its steady state (hopf_steady.hpp, timed) and the wake's pair
// there, by the full shift-invert search, by one shift at a predicted pair (tracked), following a
// neighbouring point's pair by its eigenvector, or placed by Arnoldi on the linearised march (seeded).
#include <complex>
#include <vector>

#include "postproc/navier_stokes/critical.hpp"

namespace magnus {

/// A followed pair whose eigenvector is less parallel than this to the one it follows is taken for another
/// mode (the far field's slow pairs crowd the axis where the wake's pair crosses it).
constexpr double kFollowOverlap = 0.5;

/// e's eigenvalues by one shift-invert search at `near` (U/D), and its mode: with `like` (the pair's
/// eigenvector at a neighbouring point) the pair whose eigenvector is most nearly parallel to it, from an
/// Arnoldi started there (11 vectors, at most two restarts); else, or when no pair is parallel enough, the
/// pair nearest `near`. sharp: `near` is already within about 0.01 U/D of the pair (the march's estimate, or
/// extrapolated from two points of the pair), so the nearest Ritz value alone must converge, from the fewest
/// vectors (16).
void track_pair(const NsParams& p, HopfParameter which, HopfEvaluation& e, std::complex<double> near,
                const HopfOptions& o, bool sharp = false, const std::vector<std::complex<double>>* like = nullptr);

/// The steady state at x (steady_at) and how long Newton took; no eigenvalues yet.
HopfEvaluation steady_point(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                            const NsState* guess, bool potential_first = false);

/// e's eigenvalues by the full search, and its leading pair as the mode.
void full_search(const NsParams& p, HopfParameter which, HopfEvaluation& e, const HopfOptions& o);

/// e's growing pair without the full search: the linearised march's rightmost growing pair (Arnoldi,
/// stepper_eigen.hpp), then the Jacobian's pair nearest it by one tracked shift. False, e's eigenvalues
/// unset, when the march finds no growing pair, or the Jacobian's nearest pair does not grow or lies more than
/// 0.05 U/D from it (another mode: the full search decides then).
bool seeded_search(const NsParams& p, HopfParameter which, HopfEvaluation& e, const HopfOptions& o);

}  // namespace magnus
