// Regula falsi with the Illinois weights (postproc/navier_stokes/regula_falsi.hpp): on a convex function
// plain regula falsi keeps one end for ever and converges linearly; the halving makes it superlinear.
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/regula_falsi.hpp"

using namespace magnus;

namespace {

/// Steps of regula falsi on f(x) = e^x − 2 over [0, 3] until |x − ln 2| < 1e-12 (at most 200).
int steps_to_root(bool illinois) {
  auto f = [](double x) { return std::exp(x) - 2.0; };
  double x[2] = {0.0, 3.0}, fx[2] = {f(0.0), f(3.0)};
  Illinois w;
  for (int k = 1; k <= 200; ++k) {
    const double m = illinois ? w.root(x[0], fx[0], x[1], fx[1]) : secant_zero(x[0], fx[0], x[1], fx[1]);
    if (std::fabs(m - std::log(2.0)) < 1e-12) return k;
    const int end = (f(m) < 0.0) == (fx[0] < 0.0) ? 0 : 1;
    x[end] = m, fx[end] = f(m);
    w.replaced(end);
  }
  return 201;
}

}  // namespace

TEST_CASE("[ns][regula-falsi] the secant zero, and the Illinois weights halve the end kept twice",
          "[ns][critical]") {
  CHECK(secant_zero(1.0, -1.0, 3.0, 1.0) == 2.0);
  CHECK(secant_zero(1.0, 2.0, 3.0, 2.0) == 2.0);  // a flat line: the midpoint
  Illinois w;
  w.replaced(0);  // end 1 kept once: no halving yet
  CHECK(w.w[1] == 1.0);
  w.replaced(0);  // kept twice in a row: halved
  CHECK(w.w[1] == 0.5);
  w.replaced(1);  // end 1 replaced: its weight is 1 again
  CHECK(w.w[1] == 1.0);
  CHECK(w.w[0] == 1.0);
  // On e^x − 2 plain regula falsi keeps x = 3 and crawls; Illinois reaches 1e-12 in a few steps.
  const int plain = steps_to_root(false), fast = steps_to_root(true);
  INFO("plain " << plain << ", Illinois " << fast);
  CHECK(plain > 40);
  CHECK(fast < 15);
}
