#pragma once
// Double → integer conversions defined for every double. Converting a value outside the integer type's range
// (or NaN, ±inf) is undefined behaviour in C++; the sanitizer build traps it (-fsanitize=float-cast-overflow).
// Every conversion of a value that is not bounded by construction goes through one of these.
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace magnus {

/// Whether x, truncated toward zero, is a value of the integer type T (false for NaN and ±inf).
template <class T>
bool fits_integer(double x) {
  // The bounds as doubles: min is a power of two (exact); max + 1 is one too (max itself may not be).
  const double lo = double(std::numeric_limits<T>::min());
  const double hi_excl = 2.0 * double(std::numeric_limits<T>::max() / 2 + 1);
  return x > lo - 1.0 && x < hi_excl;
}

/// x truncated toward zero as T, clamped to T's range; NaN gives 0. For figures shown or estimated (an ETA,
/// a predicted grid size) where a value beyond the range only means "very large".
template <class T>
T saturate_cast(double x) {
  if (std::isnan(x)) return T(0);
  if (fits_integer<T>(x)) return static_cast<T>(x);
  return x < 0.0 ? std::numeric_limits<T>::min() : std::numeric_limits<T>::max();
}

/// x truncated toward zero as T; throws std::out_of_range naming `what` when x is NaN, ±inf or beyond T's
/// range (a value read from a file, a count derived from the input).
template <class T>
T checked_cast(double x, const std::string& what) {
  if (!fits_integer<T>(x)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    throw std::out_of_range(what + ": " + text + " is out of range for an integer");
  }
  return static_cast<T>(x);
}

}  // namespace magnus
