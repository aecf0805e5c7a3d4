#pragma once
// Time-periodic states directly: Newton's method on the period map by shooting. The AB2/CN scheme
// (operator.hpp) with a fixed step Δt = T/N is a map S on its state x = (ζ, ψ, N^{n−1}, Γ_R, dΓ_R/dt^{n−1});
// the period map is Φ_T = S^N. A periodic orbit of period T is a root of
//     F(x, T) = Φ_T(x) − x = 0,     ⟨ẋ₀, x − x₀⟩ = 0,
// the second (the phase condition) pinning where on the orbit x lies: no step along the flow ẋ₀ of the
// current iterate x₀ (ẋ₀ ≈ (S(x₀) − x₀)/Δt). Each Newton step solves the bordered system
//     [ M − I   ∂Φ/∂T ] [δx]   [ −F ]
//     [ ẋ₀ᵀ       0   ] [δT] = [  0 ],      M = ∂Φ_T/∂x (the monodromy matrix),
// by GMRES (solver/gmres.hpp) whose products M v are finite differences of the time stepper,
// (Φ_T(x + εv) − Φ_T(x))/ε: one period of time steps per product. ∂Φ/∂T is one more period on an operator
// of Δt = (T + δT)/N. (The flow at the period's end, f(Φ_T(x)), one step instead of a period, is not it:
// with N fixed a longer T is a longer Δt, and the change that makes to the scheme's own orbit, of the order
// of its time error, the flow leaves out. Tried, it turned Newton's quadratic convergence linear, a factor
// of 60 a step, and cost more periods than it saved.) The unknowns are scaled by D and U (ζ by D/U, ψ by
// 1/(UD), N by 1/U², Γ_R by 1/(UD), its rate by 1/U², T by U/D) so that one ε suits every block. The fixed
// point is the scheme's own periodic orbit at Δt = T/N: the state a long march tends to, to the time error
// of Δt alone.
#include <functional>
#include <string>
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// One Newton iteration of the orbit solve.
struct OrbitIterate {
  int newton = 0;              ///< iteration (0: the start)
  double residual = 0.0;       ///< ‖Φ_T(x)_ζ − x_ζ‖/‖x_ζ‖ of the vorticity (what ψ, N follow from), 1
  double T = 0.0;              ///< period, s
  int krylov = 0;              ///< GMRES products of the solve that led here (0 at the start)
  double krylov_residual = 0;  ///< that solve's relative residual of the bordered system, 1
  double damping = 1.0;        ///< the fraction of the Newton step taken to reach this iterate
};

/// How the orbit is sought.
struct OrbitOptions {
  int steps = 0;             ///< N, time steps per period (Δt = T/N); > 0
  double tol = 1e-9;         ///< converged when the residual ≤ tol
  int max_newton = 10;       ///< Newton iterations at most
  int max_krylov = 150;      ///< GMRES products per Newton iteration at most
  double forcing_max = 0.1;  ///< GMRES's relative tolerance: min(forcing_max, 10·residual), ≥ 1e-7
  /// After each iteration's residual is known (a progress line); may be empty.
  std::function<void(const OrbitIterate&)> on_iterate;
  /// After each period of time steps (every GMRES product), with its last state; false stops the solve
  /// (std::runtime_error: Ctrl-C). May be empty.
  std::function<bool(const NsState&)> on_period;
  /// Each state of each period whose residual is taken (not the GMRES products): k = 0 its start (t = 0),
  /// then k = 1 … N after each step. The last period reported is that of the returned state, so a caller
  /// may keep its samples instead of stepping the orbit once more (orbit.hpp). May be empty.
  std::function<void(int k, int N, const NsState&)> on_residual_step;
};

/// What the orbit solve reached.
struct OrbitResult {
  NsState state;                      ///< the orbit's state at phase 0 (t = 0), the AB2 history with it
  double T = 0.0;                     ///< period, s
  int steps = 0;                      ///< N: Δt = T/N
  bool converged = false;             ///< residual ≤ tol
  double residual = 0.0;              ///< the last residual (OrbitIterate::residual)
  std::vector<OrbitIterate> history;  ///< every iterate, the start first
  long time_steps = 0;                ///< time steps taken in all: periods × N (ẋ₀ is a residual's first step)
  int krylov_total = 0;               ///< GMRES products in all
  std::string message;                ///< why it stopped
};

/// N steps of op from s (each new state to on_step, if given); next.t counts on from s.t.
NsState period_map(const NsOperator& op, const NsState& s, int N,
                   const std::function<void(const NsState&)>& on_step = {});

/// Newton–GMRES shooting from (start, T0) (start: a state near the orbit, e.g. from a short march, with its
/// N^{n−1}; T0, s: the period of its lift). Throws std::invalid_argument for N ≤ 0, T0 ≤ 0 or a state of
/// another grid; a time step that fails (CFL above the limit, non-finite fields) or on_period's stop
/// propagates as std::runtime_error. Does not throw when Newton stalls: converged = false, message.
OrbitResult solve_periodic_orbit(const NsParams& p, const NsState& start, double T0, const OrbitOptions& o);

/// One step of natural continuation: the orbit of p (a neighbouring Re or α) from a converged orbit of
/// other parameters on the same grid, its state and period the start; N = o.steps, or near's when
/// o.steps ≤ 0 (a larger N where p's CFL limit asks for a shorter Δt than near's T/N).
OrbitResult continue_orbit(const NsParams& p, const OrbitResult& near, OrbitOptions o);

}  // namespace magnus
