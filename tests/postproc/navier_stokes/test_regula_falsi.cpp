// Regula falsi with the Illinois weights (postproc/navier_stokes/regula_falsi.hpp): on a convex function
// plain regula falsi keeps one end for ever and converges linearly; the halving makes it superlinear.
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>

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

TEST_CASE("[ns][regula-falsi] the bracket search stops at the secant zero, not at a bisection's midpoint",
          "[ns][critical]") {
  int calls = 0;
  // A line: the first secant zero is the root, and the search stops there after one evaluation.
  auto line = [&](double x) -> std::optional<double> { return ++calls, x - 187.48; };
  const BracketRoot a = bracket_root(line, 175.0, -12.48, 200.0, 12.52, 1.0, 8);
  CHECK(a.converged);
  CHECK(a.root == Approx(187.48).margin(1e-9));
  CHECK(calls == 1);  // the secant zero, evaluated once: the estimate did not move
  // Flat, then kinked (a slow mode leads until the 3D mode overtakes it): the mode A search's shape. Its
  // root 187.5 is found to 0.01 within 10 evaluations, and the estimate is the last bracket's secant zero.
  calls = 0;
  auto kinked = [&](double x) -> std::optional<double> {
    ++calls;
    return x < 183.0 ? -0.036 + 0.002 * (x - 175.0) : 0.0024 * (x - 187.5);
  };
  const BracketRoot b = bracket_root(kinked, 175.0, -0.036, 200.0, 0.03, 0.01, 10);
  INFO(calls << " evaluations, root " << b.root << " ± " << b.change << " in [" << b.lo << ", " << b.hi << "]");
  CHECK(b.converged);
  CHECK(b.root == Approx(187.5).margin(0.01));
  CHECK(b.lo <= b.root);
  CHECK(b.root <= b.hi);
  // An evaluation that gives no value stops the search there.
  auto broken = [](double x) -> std::optional<double> {
    if (x > 180.0) return std::nullopt;
    return x - 190.0;
  };
  const BracketRoot c = bracket_root(broken, 150.0, -40.0, 200.0, 10.0, 1.0, 8);
  CHECK(c.failed);
  CHECK_FALSE(c.converged);
  CHECK(c.failed_at == Approx(190.0));
}
