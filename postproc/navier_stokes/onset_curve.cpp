#include "postproc/navier_stokes/onset_curve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/hopf_steady.hpp"

namespace magnus {

HopfParameter other_parameter(HopfParameter which) {
  return which == HopfParameter::spin_ratio ? HopfParameter::reynolds : HopfParameter::spin_ratio;
}

namespace {

/// The crossing predicted at v from the crossings (v_i, x_i) found in a row before it: the last one after
/// one; after more, extrapolated in u = var.u(x) along the polynomial through the last two or three (a line,
/// or a parabola: near the onset without spin α_L² grows linearly with Re − Re_c, and the curve bends);
/// clamped to [A, B].
double predicted_crossing(const std::vector<std::pair<double, double>>& found, double v, double A, double B,
                          SearchVariable var) {
  const size_t n = std::min<size_t>(found.size(), 3);
  double u = 0.0;
  for (size_t i = found.size() - n; i < found.size(); ++i) {  // Lagrange's form
    double w = 1.0;
    for (size_t j = found.size() - n; j < found.size(); ++j)
      if (j != i) w *= (v - found[j].first) / (found[i].first - found[j].first);
    u += w * var.u(found[i].second);
  }
  return std::clamp(var.x(u), A, B);
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
        const double at = predicted_crossing(found, v, A, B, search_variable(which, A, B));
        HopfStart start = last;
        if (found.size() >= 2)  // Newton from the crossing's state extrapolated along the last two
          start.state = blend(before, last.state, 1.0 + (v - found.back().first) / (found.back().first - found[found.size() - 2].first));
        const auto t0 = std::chrono::steady_clock::now();
        try {
          pt.point = hopf_point_from(q, which, at, A, B, o, start);
        } catch (const std::exception& e) {  // the pair lost on the way (another mode followed, say)
          pt.restarted = e.what();
          pt.point = hopf_point(q, which, A, B, o);  // the ends' own searches over [A, B], as the first point's
          pt.point.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
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
