#include "postproc/navier_stokes/onset_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace magnus {

HopfParameter other_parameter(HopfParameter which) {
  return which == HopfParameter::spin_ratio ? HopfParameter::reynolds : HopfParameter::spin_ratio;
}

namespace {

/// The crossing at one value of the other parameter: over [lo, hi] first, widened about `centre` while the
/// growth rate keeps its sign (up to `span`); guess: the last point's steady state.
HopfPoint crossing_near(const NsParams& q, HopfParameter which, double centre, double half, double span,
                        const HopfOptions& o, const NsState* guess) {
  const bool re = which == HopfParameter::reynolds;
  for (;;) {
    double lo = centre - half, hi = centre + half;
    if (re) lo = std::max(lo, 1.0);
    try {
      return hopf_point(q, which, lo, hi, o, {}, guess);
    } catch (const std::invalid_argument&) {  // no sign change: widen
      if (2.0 * half >= span) throw;
      half *= 2.0;
    }
  }
}

}  // namespace

std::vector<OnsetPoint> onset_curve(const NsParams& p, HopfParameter which, double A, double B,
                                    const std::vector<double>& others, const HopfOptions& o,
                                    const std::function<void(const OnsetPoint&)>& progress) {
  const HopfParameter step = other_parameter(which);
  std::vector<OnsetPoint> curve;
  NsState last;
  double centre = 0.5 * (A + B);
  bool have = false;
  for (const double v : others) {
    OnsetPoint pt;
    pt.other = v;
    const NsParams q = with_parameter(p, step, v);
    try {
      pt.point = have ? crossing_near(q, which, centre, std::max(4.0 * o.tol, (B - A) / 8.0), B - A, o, &last)
                      : hopf_point(q, which, A, B, o);
      pt.found = true;
      last = std::move(pt.point.state);
      pt.point.state = {};
      centre = pt.point.x_c;
      have = true;
    } catch (const std::exception& e) {
      pt.message = e.what();
      have = false;
      centre = 0.5 * (A + B);
    }
    if (progress) progress(pt);
    curve.push_back(std::move(pt));
  }
  return curve;
}

}  // namespace magnus
