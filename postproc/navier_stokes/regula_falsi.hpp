#pragma once
// Regula falsi on a sign-change bracket with the Illinois weights: the end a step keeps for the second time
// in a row has its value halved, so the root does not crawl towards one end. The onset searches (of
// shedding, critical.hpp, and of three-dimensionality, spanwise_critical.hpp) step by it.

#include <algorithm>
#include <cmath>
#include <optional>

namespace magnus {

/// The zero of the line through (x0, f0) and (x1, f1); their midpoint when f0 = f1.
inline double secant_zero(double x0, double f0, double x1, double f1) {
  return f0 == f1 ? 0.5 * (x0 + x1) : x0 + (x1 - x0) * f0 / (f0 - f1);
}

/// The Illinois weights of a bracket's two ends (0 and 1).
struct Illinois {
  double w[2] = {1.0, 1.0};
  int kept = -1;  ///< the end the last step kept (−1: no step yet)
  /// The next point: secant_zero of the weighted values f0, f1 at x0, x1.
  double root(double x0, double f0, double x1, double f1) const { return secant_zero(x0, w[0] * f0, x1, w[1] * f1); }
  /// A new point replaced end `end` (0 or 1): its weight is 1 again; the other end, kept twice in a row, halves.
  void replaced(int end) {
    const int other = 1 - end;
    w[end] = 1.0;
    if (kept == other) w[other] *= 0.5;
    kept = other;
  }
};

/// Where a bracket search stopped.
struct BracketRoot {
  double root = 0.0;       ///< the secant zero of the last bracket: the best estimate of the root
  double change = 0.0;     ///< how far that estimate last moved, or the bracket's width when smaller
  double lo = 0.0, hi = 0.0;  ///< the last bracket: f < 0 at lo, f > 0 at hi
  bool converged = false;  ///< change < tol
  bool failed = false;     ///< an evaluation gave no value (f returned nullopt); the search stopped there
  double failed_at = 0.0;  ///< where
};

/// The root of f in a sign-change bracket, f(lo) = f_lo < 0 < f(hi) = f_hi (either order of lo, hi), by
/// regula falsi with the Illinois weights; a step that does not halve the bracket is followed by a
/// bisection (a growth rate that is flat and then kinked makes regula falsi crawl). The estimate is the
/// bracket's plain secant zero; the search stops when it moves less than tol, when the bracket is narrower
/// than tol, or after `evaluations` calls of f (x ↦ optional value).
template <class F>
BracketRoot bracket_root(F&& f, double lo, double f_lo, double hi, double f_hi, double tol, int evaluations) {
  BracketRoot r;
  double x[2] = {lo, hi}, fx[2] = {f_lo, f_hi};  // end 0: f < 0, end 1: f > 0
  Illinois weights;
  bool bisect = false;
  r.root = secant_zero(x[0], fx[0], x[1], fx[1]);
  r.change = std::fabs(x[1] - x[0]);
  for (int k = 0; k < evaluations && !(r.change < tol); ++k) {
    const double width = std::fabs(x[1] - x[0]);
    const double next = bisect ? 0.5 * (x[0] + x[1]) : weights.root(x[0], fx[0], x[1], fx[1]);
    const std::optional<double> v = f(next);
    if (!v) {
      r.failed = true, r.failed_at = next;
      break;
    }
    const int end = *v < 0.0 ? 0 : 1;
    x[end] = next, fx[end] = *v;
    weights.replaced(end);
    bisect = !bisect && std::fabs(x[1] - x[0]) > 0.5 * width;
    const double estimate = secant_zero(x[0], fx[0], x[1], fx[1]);
    r.change = std::min(std::fabs(estimate - r.root), std::fabs(x[1] - x[0]));
    r.root = estimate;
  }
  r.lo = x[0], r.hi = x[1];
  r.converged = !r.failed && r.change < tol;
  return r;
}

}  // namespace magnus
