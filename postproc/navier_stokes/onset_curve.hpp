#pragma once
// The onset of shedding as a curve: the Hopf point of critical.hpp at each value of the other parameter,
// α_L(Re) (the spin ratio where shedding stops, at each Reynolds number) or Re_c(α) (the Reynolds number
// where it starts, at each spin ratio). Each point continues from the last: Newton from its steady state,
// the last crossing's pair followed by its eigenvector (no search of its own) to the crossing extrapolated
// from the last ones, then secant steps from there until the growth rate changes sign
// (critical.hpp's hopf_point_from).
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
  /// Why the search stepped from the last point failed, when it did: the point was then searched over
  /// [A, B] with ends of its own (its seconds include both).
  std::string restarted;
};

/// The crossing in `which` for each value of `others` (in order), the first searched over [A, B], each
/// next one stepped from the last (hopf_point_from with its HopfStart) from the predicted crossing: after
/// one point found, that crossing; after more, extrapolated in the search variable u along the line
/// through the last two or the parabola through the last three. Where that search fails (the pair lost on
/// the way), the point is searched over [A, B] as the first one is; a point that fails then is reported and
/// the next starts over on [A, B].
/// progress (optional): after each point.
std::vector<OnsetPoint> onset_curve(const NsParams& p, HopfParameter which, double A, double B,
                                    const std::vector<double>& others, const HopfOptions& o = {},
                                    const std::function<void(const OnsetPoint&)>& progress = {});

}  // namespace magnus
