#pragma once
// Internal to plot/: the power of ten an axis (or a colour bar) is shown in. PLplot labels an axis whose
// numbers are small (|v| < 0.1) or large with a "(×10^k)" of its own, placed above the plot box where the
// title is and often cut off the image; the pictures scale their data themselves instead and write the
// scale into the axis label ("τ_w (10^{-3} Pa)"), so that PLplot never adds one.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace magnus::axis_scale {

/// k such that the axis shows v·10^−k: 0 when max(|lo|, |hi|) is in [0.1, 10⁴) (PLplot prints those
/// plainly), else 3·⌊log10(max|v|)/3⌋, so that the numbers shown run from 1 to 1000. 0 for no range.
inline int exponent(double lo, double hi) {
  const double m = std::max(std::fabs(lo), std::fabs(hi));
  if (!(m > 0.0) || !std::isfinite(m) || (m >= 0.1 && m < 1e4)) return 0;
  return 3 * int(std::floor(std::floor(std::log10(m)) / 3.0));
}

/// The label of an axis shown in units of 10^k: its unit in parentheses at the end gains the factor
/// ("τ_w (Pa)" → "τ_w (10^{-3} Pa)"); a label without one gets " (×10^{k})". k = 0: unchanged.
inline std::string label(const std::string& text, int k) {
  if (k == 0) return text;
  const std::string factor = fmt::format("10^{{{}}}", k);
  if (!text.empty() && text.back() == ')') {
    // The matching '(' of the final ')'.
    int depth = 0;
    for (size_t i = text.size(); i-- > 0;) {
      if (text[i] == ')') ++depth;
      if (text[i] == '(' && --depth == 0) {
        const std::string unit = text.substr(i + 1, text.size() - i - 2);
        // A unit has no '=' or ',' (those are remarks: "(from 2: …)", "(on ½ρU²·D)").
        if (!unit.empty() && unit.find_first_of("=,:") == std::string::npos && unit.size() <= 12)
          return text.substr(0, i + 1) + factor + " " + unit + ")";
        break;
      }
    }
  }
  return text + " (×" + factor + ")";
}

}  // namespace magnus::axis_scale
