// The steady state at a point of a Hopf search (hopf_steady.hpp): Newton from a guess, natural
// continuation from a converged neighbour, the potential flow, or continuation from a safe point.
#include "postproc/navier_stokes/hopf_steady.hpp"

#include <cmath>

namespace magnus {

namespace {

/// Newton at x from `guess` (potential_guess when null); the result's state either way.
NewtonResult newton_at(const NsParams& p, HopfParameter which, double x, const NsState* guess) {
  const NsParams q = with_parameter(p, which, x);
  SteadyJacobian jac(q);
  NewtonOptions no;
  no.chord_ratio = 0.1;  // the last steps on earlier factors while they contract ten-fold (same tolerance)
  return solve_steady(jac, guess ? *guess : potential_guess(q, jac.grid()), no);
}

/// Natural continuation from the converged (x0, s0) to x: Newton at each step from the last state, the step
/// halved where Newton fails, down to 1/64 of the way. Returns the state at x, or nullopt.
std::optional<NsState> continue_to(const NsParams& p, HopfParameter which, double x0, NsState s0, double x) {
  const double min_step = std::fabs(x - x0) / 64.0;
  double step = x - x0;
  while (x0 != x) {
    const double x1 = std::fabs(step) >= std::fabs(x - x0) ? x : x0 + step;
    NewtonResult r = newton_at(p, which, x1, &s0);
    if (r.converged) {
      x0 = x1, s0 = std::move(r.state);
      continue;
    }
    step *= 0.5;
    if (std::fabs(step) < min_step) return std::nullopt;
  }
  return s0;
}

/// The steady state at x where Newton from the potential flow fails: continued from a safe point, first in
/// Re at this α from Re = 60 (a spin search above it: at Re 200 Newton reaches no state from the potential
/// flow at any α up to 1.6), then in the searched parameter from α = 0 or Re = 20.
std::optional<NsState> steady_from_safe(const NsParams& p, HopfParameter which, double x) {
  if (which == HopfParameter::spin_ratio && p.reynolds() > 60.0) {
    const NsParams at_x = with_parameter(p, which, x);
    NewtonResult s = newton_at(at_x, HopfParameter::reynolds, 60.0, nullptr);
    if (s.converged)
      if (auto r = continue_to(at_x, HopfParameter::reynolds, 60.0, std::move(s.state), p.reynolds())) return r;
  }
  const double safe = which == HopfParameter::spin_ratio ? 0.0 : std::min(20.0, x);
  if (safe == x) return std::nullopt;
  NewtonResult s = newton_at(p, which, safe, nullptr);
  if (!s.converged) return std::nullopt;
  return continue_to(p, which, safe, std::move(s.state), x);
}

}  // namespace

NsState blend(const NsState& a, const NsState& b, double w) {
  NsState s = a;
  for (size_t q = 0; q < s.psi.size(); ++q) s.psi[q] += w * (b.psi[q] - a.psi[q]), s.zeta[q] += w * (b.zeta[q] - a.zeta[q]);
  s.Gamma_R += w * (b.Gamma_R - a.Gamma_R);
  return s;
}

std::optional<NsState> steady_at(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                                 const NsState* guess, bool potential_first) {
  if (guess) {
    NewtonResult g = newton_at(p, which, x, guess);
    if (g.converged) return std::move(g.state);
  }
  const bool continues = from && from->converged;
  if (potential_first || !continues) {
    NewtonResult r = newton_at(p, which, x, nullptr);
    if (r.converged) return std::move(r.state);
  }
  if (continues) return continue_to(p, which, from->x, from->state, x);
  return steady_from_safe(p, which, x);
}

}  // namespace magnus
