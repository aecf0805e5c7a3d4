#pragma once
// The onset of shedding as a curve: the Hopf point of critical.hpp at each value of the other parameter,
// α_L(Re) (the spin ratio where shedding stops, at each Reynolds number) or Re_c(α) (the Reynolds number
// where it starts, at each spin ratio). Each point continues from the last: Newton from its steady state,
// the secant search inside a bracket around its crossing, widened until the growth rate changes sign.
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
/// next one around the last crossing (half-width max(4·tol, (B − A)/8), doubled up to B − A while Re λ
/// keeps its sign; a point that fails is reported and the next starts over on [A, B]). progress
/// (optional): after each point.
std::vector<OnsetPoint> onset_curve(const NsParams& p, HopfParameter which, double A, double B,
                                    const std::vector<double>& others, const HopfOptions& o = {},
                                    const std::function<void(const OnsetPoint&)>& progress = {});

}  // namespace magnus
