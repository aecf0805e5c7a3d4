#pragma once
// The onset of shedding as a curve: the Hopf point of critical.hpp at each value of the other parameter,
// α_L(Re) (the spin ratio where shedding stops, at each Reynolds number) or Re_c(α) (the Reynolds number
// where it starts, at each spin ratio). Each point continues from the last: Newton from its steady state,
// the last crossing's pair followed by its eigenvector to the new ends (no search of their own), and the
// secant search inside a bracket about the crossing extrapolated from the last two, as wide as that
// extrapolation's error on the last point, moved past the secant root of its ends while the growth rate
// keeps its sign over it.
#include <functional>
#include <string>
#include <vector>

#include "postproc/navier_stokes/critical.hpp"

namespace magnus {

/// The parameter an onset curve steps along: the one a Hopf search of `which` does not move.
HopfParameter other_parameter(HopfParameter which);

/// One point of the curve.
struct OnsetPoint {
  double other = 0.0;   ///< the value of the stepped parameter (Re for α_L(Re), α for Re_c(α))
  bool found = false;   ///< a crossing was found (else `message` says why)
  HopfPoint point;      ///< the crossing (states dropped)
  std::string message;  ///< why no crossing was found
};

/// The crossing in `which` for each value of `others` (in order), the first searched over [A, B], each
/// next one started from the last (HopfStart) in a bracket about the predicted crossing: after one point
/// found, about it with half-width (B − A)/8; after two, on the line through them with half their
/// distance; after more, twice the line's error in predicting the last point; between 4·tol and (B − A)/8.
/// Where Re λ keeps its sign there, the bracket moves past the secant root through its ends (at most three
/// times). A point that fails is reported and the next starts over on [A, B].
/// progress (optional): after each point.
std::vector<OnsetPoint> onset_curve(const NsParams& p, HopfParameter which, double A, double B,
                                    const std::vector<double>& others, const HopfOptions& o = {},
                                    const std::function<void(const OnsetPoint&)>& progress = {});

}  // namespace magnus
