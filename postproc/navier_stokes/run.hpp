#pragma once
// The navier-stokes chain, written once: case → parameters → time marching from rest (or from a
// checkpoint) → the last state post-processed into a FlowResult with its viscous part (fields, surface,
// forces, means, history, snapshots), beside the potential-flow figures for the same scene.
// run.cpp checks the case and takes one path (run_paths.hpp): Newton's method and the choice of time.mode
// "auto" in run_steady.cpp, the march in run_march.cpp; the FlowResult of a state in viscous_result.cpp.
#include <cstddef>
#include <functional>

#include "postproc/result.hpp"

namespace magnus {

/// The convective time unit's name: "D/U", or "D/(a|ω|)" for a cylinder spinning in still fluid (U = 0).
const char* time_unit_name(const Scene& s);
/// The rate unit's name (eigenvalues, growth rates): "U/D", or "a|ω|/D" when U = 0.
const char* rate_unit_name(const Scene& s);

/// The viscous model's parameters of a case (SI): a, U, ω, ν, R/a, n_θ, n_r, Δt (s) and the CFL number.
NsParams ns_params(const Case& c);

/// A run's state at a checkpoint: enough to go on as if it had not stopped.
struct Checkpoint {
  NsState state;
  std::vector<ForceSample> history;
  std::vector<Snapshot> snapshots;
  long steps = 0;  ///< time steps from rest to state, over every run before (0 if the file does not say)
};

/// What a viscous run tells its caller while it runs (each may be empty).
struct ViscousHooks {
  /// After every step (a progress line; Ctrl-C): false stops the run, the result is then partial.
  std::function<bool(const NsState&, const ViscousForces&)> on_step;
  /// Every time.checkpoint_interval (convective units) of simulated time, and when a run is interrupted
  /// (not when it fails: the last good checkpoint stays).
  std::function<void(const Checkpoint&)> on_checkpoint;
  /// time.mode = "auto" marches at once, without its Newton solve and stability test: the caller (the
  /// S map) already knows that the steady state Newton would find is unstable, or that there is none.
  bool march_at_once = false;
  /// The memory a run may need, bytes (0: what is free): the resolvability check and grid.tolerance's grid.
  size_t max_bytes = 0;
  /// Run a companion on the grid twice as coarse beside the run, for the error estimate of its mean C_L,
  /// mean C_D and St (postproc/navier_stokes/error_estimate.hpp); the S map and sweeps set it false.
  bool error_estimate = true;
  /// Polled while a finished run (marched or periodic) waits for its companion: false (a Ctrl-C) stops the
  /// companion and leaves the error bar undefined instead of waiting; may be empty (wait).
  std::function<bool()> keep_going;
};

/// What time.mode = "auto" does first, decided from Re and α alone before any solve.
enum class AutoStart {
  search,       ///< Newton from potential flow, then the eigenvalue test of the state it finds
  newton_only,  ///< steady flow is certain here: Newton alone (no eigenvalue test); march if it fails
  march,        ///< shedding is certain here: march at once
};
struct AutoPlan {
  AutoStart start = AutoStart::search;
  std::string why;  ///< the reason, for the status line ("" for search)
};
/// march: Re ≥ 60 with α ≤ 1 (Re_c ≈ 47 at α = 0; the critical spin ratio rises with Re, ≈ 1.9 at Re 100).
/// newton_only: Re ≤ 35 with |α| ≤ 3: below the onset of shedding (Re_c ≈ 46–47 at α = 0, and spin only
/// delays it; the coarse map grid, n_θ 48 at R = 20a, already sheds at Re 40 with growth +0.0002 U/D, but
/// finds Re 30 and 35 stable at α 0…3; the one-sided shedding near α = 5 opens only from Re 100). Else
/// search.
AutoPlan auto_plan(const NsParams& p);

/// Throws std::invalid_argument (one line naming the key) for a case the model refuses: time.dt above the
/// stability limit of the start, a scene whose boundary layer no grid in memory resolves (check_resolvable),
/// U = 0 and ω = 0, a time.end
/// before the time of the checkpoint it resumes (time.mode "steady" does not march: any time.end).
/// threads: for the advection and the mode solves (≥ 1; on 2 cores a second thread gained about 4%).
FlowResult run_viscous(const Case& c, const ViscousHooks& hooks = {}, const Checkpoint* resume = nullptr,
                       int threads = 1);

/// The FlowResult of a state: fields (ψ, u, p, Cp, ζ), surface (u_θ, p, Cp, τ_w), forces and the viscous
/// part from the run's history (means, amplitudes, St, separation, the ideal figures).
FlowResult viscous_result(const Case& c, const NsParams& p, const UnsteadyResult& run,
                          std::vector<Snapshot> snapshots);

}  // namespace magnus
