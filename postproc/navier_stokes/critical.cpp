#include "postproc/navier_stokes/critical.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace magnus {

SpinStability spin_stability(const NsParams& base, double alpha, const NsState* guess, int count) {
  if (!(base.U > 0.0)) throw std::invalid_argument("critical spin ratio: flow.speed must be > 0 (α = aω/U)");
  NsParams p = base;
  p.omega = alpha * p.U / p.a;
  SpinStability s;
  s.alpha = alpha;
  const auto t0 = std::chrono::steady_clock::now();
  SteadyJacobian jac(p);
  NewtonResult nr;
  if (guess) {
    NsState g = *guess;  // the neighbour's vorticity, this α's wall condition follows from Newton
    nr = solve_steady(jac, g);
  }
  if (!guess || !nr.converged) nr = solve_steady(jac, potential_guess(p, jac.grid()));
  s.newton_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.converged = nr.converged;
  s.state = std::move(nr.state);
  if (s.converged) s.stability = leading_eigenvalues(p, s.state, count);
  return s;
}

CriticalSpin critical_spin(const NsParams& p, double A, double B, double tol,
                           const std::function<void(const SpinStability&)>& progress) {
  if (!std::isfinite(A) || !std::isfinite(B))
    throw std::invalid_argument(fmt::format("--critical-spin A:B needs finite spin ratios (got {}:{})", A, B));
  if (!(A < B)) throw std::invalid_argument(fmt::format("--critical-spin A:B needs A < B (got {}:{})", A, B));
  if (!(tol > 0.0)) throw std::invalid_argument(fmt::format("--tolerance must be > 0 (got {})", tol));
  const auto t0 = std::chrono::steady_clock::now();
  CriticalSpin c;
  auto solve = [&](double alpha, const NsState* guess) {
    SpinStability s = spin_stability(p, alpha, guess);
    if (!s.converged)
      throw std::runtime_error(fmt::format("critical spin ratio: Newton's method found no steady state at α = {:g}", alpha));
    if (s.stability.eigenvalues.empty())
      throw std::runtime_error(
          fmt::format("critical spin ratio: no eigenvalue converged at α = {:g} ({})", alpha, s.stability.message));
    if (progress) progress(s);
    SpinStability copy = s;
    copy.state = {};
    c.evaluations.push_back(std::move(copy));
    return s;
  };
  SpinStability lo = solve(A, nullptr);
  SpinStability hi = solve(B, &lo.state);
  c.at_a = lo, c.at_b = hi;
  c.at_a.state = {}, c.at_b.state = {};
  if ((lo.growth() < 0.0) == (hi.growth() < 0.0))
    throw std::invalid_argument(fmt::format(
        "--critical-spin {:g}:{:g}: the leading growth rate does not change sign (Re λ·D/U = {:.4g} at α = {:g}, "
        "{:.4g} at α = {:g}): widen or move the bracket",
        A, B, lo.growth(), A, hi.growth(), B));
  while (hi.alpha - lo.alpha > tol) {
    const double mid = 0.5 * (lo.alpha + hi.alpha);
    SpinStability m = solve(mid, &lo.state);
    ((m.growth() < 0.0) == (lo.growth() < 0.0) ? lo : hi) = std::move(m);
  }
  c.lo = lo.alpha, c.hi = hi.alpha;
  const double gl = lo.growth(), gh = hi.growth();
  c.alpha_c = gl == gh ? 0.5 * (c.lo + c.hi) : c.lo + (c.hi - c.lo) * gl / (gl - gh);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c;
}

}  // namespace magnus
