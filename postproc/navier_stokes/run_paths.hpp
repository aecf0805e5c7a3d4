#pragma once
// The paths of a viscous run, each in its own file; run_viscous (run.cpp) checks the case and takes one:
// Newton's method alone (time.mode "steady") or the choice of time.mode "auto" before marching
// (run_steady.cpp), the march in time (run_march.cpp), the result of a state (viscous_result.cpp).
#include <complex>
#include <optional>
#include <string>

#include "postproc/navier_stokes/stepper_verdict.hpp"
#include "postproc/navier_stokes/run.hpp"

namespace magnus {

/// What time.mode = "auto" decided before marching (empty `steady` when it marches), and what it cost.
struct AutoChoice {
  std::optional<FlowResult> steady;
  std::string why;  ///< for the status line of a marched run
  std::optional<std::complex<double>> eigenvalue;
  std::optional<double> eigenvalue_residual;  ///< its ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖)
  std::optional<double> newton_seconds, stability_seconds;  ///< s, when run
};

/// time.mode = "steady": Newton's method on the time stepper's discrete steady equations on four grids
/// (a quarter, half, two thirds and all of the case's spacing), each from the previous one's state (the
/// first from the potential flow with circulation), and C_D, C_L, L/D extrapolated from the last three
/// (Richardson); a checkpoint's state is solved on the case's grid alone. The result has one history sample.
FlowResult steady_by_newton(const Case& c, const NsParams& p, const PolarGrid& g, const Checkpoint* resume);

/// "by the time stepper, a weak vortex added to it decays at −0.0258 U/D over 30–60 D/U" (or grows, or
/// neither, or the march failed): for the status line.
std::string stepper_text(const StepperVerdict& v, const Scene& s);

/// time.mode = "auto" (see auto_plan): Newton from the potential flow; a converged state that is linearly
/// stable (leading eigenvalue Re λ < 0), or one where steady flow is certain, is the result; otherwise the
/// flow is marched in time. error_estimate: a companion Newton solve on the grid twice as coarse beside it
/// gives a steady result its error estimate.
AutoChoice auto_steady(const Case& c, const NsParams& p, const PolarGrid& g, bool error_estimate);

/// The march in time from rest (or from the checkpoint `resume`) to time.end, unit = D/U_ref (s): snapshots
/// and checkpoints as the case asks, hooks called after every step; `choice` (what "auto" found before)
/// goes into the status and the times. Throws std::invalid_argument for a time.end before the checkpoint, a
/// checkpoint of another grid, a Δt above the start's stability limit or a march of more than kNsMaxSteps.
FlowResult march(const Case& c, const NsParams& p, const PolarGrid& g, double unit, const ViscousHooks& hooks,
                 const Checkpoint* resume, const AutoChoice& choice);

/// time.mode = "periodic": a short march from rest (broken symmetry), then the orbit by Newton–GMRES
/// shooting (orbit.hpp), its period's summary as the result, the Newton history in the status. Throws
/// std::invalid_argument with a checkpoint to resume or without a freestream; std::runtime_error when the
/// flow does not shed.
FlowResult periodic_by_shooting(const Case& c, const NsParams& p, const PolarGrid& g, double unit,
                                const ViscousHooks& hooks, const Checkpoint* resume);

/// A weak vortex (Γ = 0.1% of U·D) off the axis behind the body: it breaks the mirror symmetry of the
/// start so that a flow that sheds starts shedding (round-off alone takes hundreds of D/U at α = 0).
void break_symmetry(const NsParams& p, const PolarGrid& g, NsState& s);

}  // namespace magnus
