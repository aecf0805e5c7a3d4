#pragma once
// The time stepper's word on a steady state: a weak vortex added to it, marched, and the growth rate of the
// disturbance fitted. Auto and the map ask it where the eigenvalue search cannot judge (it converged
// nothing, or called the state stable while leaving a gap right of its leading eigenvalue).
#include <optional>

#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/stability.hpp"

namespace magnus {

/// The weak off-axis vortex the stepper's test adds to a state: circulation 1e-4·U_ref·D (U_ref = U, or a|ω|
/// in still fluid), radius a/2, at (3a, 0.6a).
void add_weak_vortex(const NsParams& p, NsState& s);

/// The growth rate σ (per D/U_ref) of the weak vortex (add_weak_vortex) added to the steady state and marched
/// `span` D/U_ref by the time stepper (run_unsteady, its own Δt, or span/100 where that would be longer): the
/// least-squares slope of ln‖ζ − ζ_s‖ over the second half. nullopt when the march fails or throws.
std::optional<double> marched_growth_rate(const NsParams& p, const NsState& steady, double span = 30.0);

/// A growth rate's verdict: stable when σ < −margin, unstable when σ > margin, else (or without σ) undecided.
std::optional<bool> sign_verdict(std::optional<double> sigma, double margin);

/// The time stepper's word on a steady state the eigenvalue search could not judge (checked_verdict): σ, the
/// growth rate of a weak vortex added to it and marched kStepperSpan D/U_ref (marched_growth_rate), judged
/// by sign_verdict with kStepperMargin.
struct StepperVerdict {
  std::optional<double> sigma;  ///< U_ref/D; nullopt when the march failed
  double seconds = 0.0;         ///< wall time of the march, s
};
/// D/U_ref. At Re 200, α 6 on the scene's grid the vortex's norm passes a transient bump that peaks near
/// 28 D/U (+0.0115 U/D over 15–30), then decays (−0.0258 U/D over 30–60): the fit starts after it.
constexpr double kStepperSpan = 60.0;
constexpr double kStepperMargin = 2e-3;  ///< U_ref/D

/// The verdict of the time stepper on `steady` (p's grid).
StepperVerdict stepper_verdict(const NsParams& p, const NsState& steady);

/// The eigenvalue search's verdict st on `steady`, checked by the time stepper where the search cannot judge
/// (stepper_verdict, then stored in *asked): a search that converged nothing takes the stepper's verdict
/// (empty when it is undecided); a "stable" that left a gap right of its leading eigenvalue stands unless
/// the vortex grows (at Re 200, α 1.6 on the grid of α 1.9 the growing wake pair sat in such a gap).
std::optional<bool> checked_verdict(const NsParams& p, const NsState& steady, const StabilityResult& st,
                                    std::optional<StepperVerdict>* asked = nullptr);

}  // namespace magnus
