#pragma once
// Regula falsi on a sign-change bracket with the Illinois weights: the end a step keeps for the second time
// in a row has its value halved, so the root does not crawl towards one end. The onset searches (of
// shedding, critical.hpp, and of three-dimensionality, spanwise_critical.hpp) step by it.

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

}  // namespace magnus
