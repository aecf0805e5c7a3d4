#include "postproc/navier_stokes/onset_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/hopf_steady.hpp"
#include "postproc/navier_stokes/regula_falsi.hpp"

namespace magnus {

HopfParameter other_parameter(HopfParameter which) {
  return which == HopfParameter::spin_ratio ? HopfParameter::reynolds : HopfParameter::spin_ratio;
}

namespace {

/// The crossing at one value of the other parameter: over [centre − half, centre + half] first (clamped to
/// [A, B]); where the growth rate keeps its sign there, the next bracket runs from the end nearer zero past
/// the secant root through both ends (half again as far, at least the same width), at most three times;
/// start: the last point's crossing.
HopfPoint crossing_near(const NsParams& q, HopfParameter which, double centre, double half, double A, double B,
                        const HopfOptions& o, const HopfStart* start) {
  double lo = std::max(A, centre - half), hi = std::min(B, centre + half);
  for (int moves = 0;; ++moves) {
    if (which == HopfParameter::reynolds) lo = std::max(lo, 1.0);
    try {
      return hopf_point(q, which, lo, hi, o, {}, start);
    } catch (const NoCrossing& e) {
      if (moves == 3 || (lo <= A && hi >= B)) throw;
      const bool above = std::fabs(e.growth_b) < std::fabs(e.growth_a);  // the root lies beyond that end
      const double from = above ? e.B : e.A, root = secant_zero(e.A, e.growth_a, e.B, e.growth_b);
      const double reach = std::max(hi - lo, 1.5 * std::fabs(root - from));
      lo = above ? from : std::max(A, from - reach);
      hi = above ? std::min(B, from + reach) : from;
      if (!(hi > lo)) throw;
    }
  }
}

/// Where the next crossing is sought, from the crossings (v, x_c) found in a row before it: about the last
/// one, half-width (B − A)/8, with one; along the line through the last two, half-width half their
/// distance, with two; and with three or more, half-width twice the error of that line's prediction of the
/// last one (the curve's curvature); at least 4·tol and at most (B − A)/8 each time (farther from the last
/// crossing its pair is less nearly parallel to the ends').
std::pair<double, double> next_bracket(const std::vector<std::pair<double, double>>& found, double v, double A,
                                       double B, double tol) {
  const size_t n = found.size();
  const auto& [v1, x1] = found[n - 1];
  if (n == 1) return {x1, std::max(4.0 * tol, (B - A) / 8.0)};
  const auto line = [&](size_t i, double at) {  // the line through points i − 1 and i, at `at`
    const auto &[va, xa] = found[i - 1];
    const auto &[vb, xb] = found[i];
    return xb + (xb - xa) * (at - vb) / (vb - va);
  };
  const double centre = std::clamp(line(n - 1, v), A, B);
  const double half = n == 2 ? 0.5 * std::fabs(x1 - found[n - 2].second) : 2.0 * std::fabs(x1 - line(n - 2, v1));
  return {centre, std::clamp(half, 4.0 * tol, (B - A) / 8.0)};
}

}  // namespace

std::vector<OnsetPoint> onset_curve(const NsParams& p, HopfParameter which, double A, double B,
                                    const std::vector<double>& others, const HopfOptions& o,
                                    const std::function<void(const OnsetPoint&)>& progress) {
  const HopfParameter step = other_parameter(which);
  std::vector<OnsetPoint> curve;
  HopfStart last;
  NsState before;                                // the crossing's state before `last`'s, when found in a row
  std::vector<std::pair<double, double>> found;  // (other, crossing) of the points found in a row
  for (const double v : others) {
    OnsetPoint pt;
    pt.other = v;
    const NsParams q = with_parameter(p, step, v);
    try {
      if (found.empty()) {
        pt.point = hopf_point(q, which, A, B, o);
      } else {
        const auto [centre, half] = next_bracket(found, v, A, B, o.tol);
        HopfStart start = last;
        if (found.size() >= 2)  // Newton from the crossing's state extrapolated along the last two
          start.state = blend(before, last.state, 1.0 + (v - found.back().first) / (found.back().first - found[found.size() - 2].first));
        pt.point = crossing_near(q, which, centre, half, A, B, o, &start);
      }
      pt.found = true;
      before = std::move(last.state);
      last = std::move(pt.point.next);
      pt.point.next = {};
      found.emplace_back(v, pt.point.x_c);
    } catch (const std::exception& e) {
      pt.message = e.what();
      found.clear();
    }
    if (progress) progress(pt);
    curve.push_back(std::move(pt));
  }
  return curve;
}

}  // namespace magnus
