#pragma once
// The run driver of the viscous model: time steps from a start state to t_end, or until the flow is
// steady or its periodic means have converged; keeps the force history; finds the shedding period
// (upward mean crossings of C_L, checked against its spectrum: postproc/navier_stokes/periodic.hpp), the means and
// amplitudes over the last whole period, and St = f·D/U.
#include <functional>
#include <string>
#include <vector>

#include "postproc/navier_stokes/forces.hpp"

namespace magnus {

/// How long to run and when to stop early.
struct UnsteadyOptions {
  double t_end = 200.0;         ///< end time, s
  double rho = 1.0;             ///< density for the forces, kg/m³
  double mean_tol = 1e-3;       ///< periodic: stop when the last periods' means of C_L, C_D differ < this·max(1, |C|)
  int converged_periods = 3;    ///< …over this many consecutive periods (and their lengths by < mean_tol)
  /// …and the drift still to come of the last periods' means (means_drift) is below mean_tol·max(1, |C|)
  /// for C_L, C_D and mean_tol·T for the period T: a slow monotone drift agrees period to period long before
  /// the means have arrived.
  bool stop_on_drift = true;
  /// Stop a shedding run instead when its last converged_periods + 1 lift periods agree with the last one
  /// in amplitude and length to mean_tol (relatively): near the onset the means agree long before the
  /// growth has ended (the short march before a periodic orbit).
  bool settle_amplitudes = false;
  double steady_tol = 1e-5;     ///< steady: stop when C_L, C_D vary < this over steady_window
  double steady_window = 10.0;  ///< in convective times D/U
  /// Never stop before this time, s; < 0: (R − a)/U + 10·D/U, when the starting vortex (shed at the
  /// impulsive start, carrying the opposite of the bound circulation) has left the domain — until then it
  /// tilts the force by its induced velocity ~Γ/(2πUt) and the means drift too slowly to be caught.
  double t_min = -1.0;
  /// Warm start (opt-in): when the run starts at t = 0 with no history on a grid of n_θ ≥ 96, first run the
  /// case on the grid with half the points each way until its periodic means agree to 10·mean_tol (or it is
  /// steady), interpolate its vorticity onto the full grid and go on; convergence tests use full-grid
  /// periods only (after t_fine). Off by default: at Re 100, α = 1, 235 × 128 it cost 14000 steps against
  /// 9950 from rest (the coarse grid's far wake takes ~R/U to leave and keeps the periods irregular).
  bool coarse_start = false;
  /// Called after every step (a progress line, a checkpoint, a snapshot); may be empty. Returning false
  /// stops the run there (Ctrl-C): the result is then marked interrupted.
  std::function<bool(const NsState&, const ViscousForces&)> on_step;
  /// If set: kept equal to the steps taken so far (both grids), for on_step to read.
  long* steps_taken = nullptr;
};

/// One sample of the force history.
struct ForceSample {
  double t = 0.0;                ///< s
  bool has_coefficients = true;  ///< false when U = 0: C_L, C_D, C_M are then 0, not defined
  double C_L = 0.0, C_D = 0.0, C_M = 0.0;
  double F_x = 0.0, F_y = 0.0, M = 0.0;  ///< N/m, N/m, N·m/m
};

/// The sample of a state at time t (s) with its forces: the coefficients when defined (else 0 and
/// has_coefficients = false).
ForceSample force_sample(double t, const ViscousForces& f);

/// Whether two periods' means f0, f1 of a force coefficient agree to tol: |f₁ − f₀| < tol·max(1, |f₁|),
/// relative for a coefficient above 1 (a lift of 26 at high spin agrees to 1e-3 of itself, not to 4e-5 of
/// itself), absolute below (a lift near 0 without spin).
bool means_agree(double f0, double f1, double tol);

/// Periodic stop rule: the last converged_periods + 1 periods of h from index first_fine on agree (means of
/// C_L, C_D by means_agree and lengths to mean_tol, relatively), with stop_on_drift the drift still to come
/// of their means (means_drift) is below mean_tol·max(1, |C|) and mean_tol·T, and the spectrum of the last
/// periods peaks at the same frequency (a false period never stops it); with settle_amplitudes, the lift's
/// amplitudes and periods agree instead.
bool periods_agree(const std::vector<ForceSample>& h, size_t first_fine, const UnsteadyOptions& o);

/// What a run reached.
struct UnsteadyResult {
  NsState state;                     ///< the last state
  std::vector<ForceSample> history;  ///< one sample per step
  bool steady = false;               ///< forces stopped changing
  bool periodic = false;             ///< at least two periods found
  bool converged = false;            ///< steady, or periodic means converged
  bool ok = true;                    ///< false: stopped on an error (see message)
  bool interrupted = false;          ///< on_step asked to stop (a partial result)
  std::string message;               ///< why it stopped; a clamped Δt; an error
  std::string error;                 ///< the error alone when !ok (else "")
  double period = 0.0;               ///< shedding period (C_L mean crossings), s
  double St = 0.0;                   ///< Strouhal number D/(U·period); 0: undefined
  /// The crossings' period agrees with the spectrum's peak (else St = 0, not converged, period_note why).
  bool period_confirmed = true;
  std::string period_note;  ///< why St is undefined ("" when the period is confirmed)
  double C_L_mean = 0.0, C_D_mean = 0.0, C_M_mean = 0.0;  ///< over the last period (or last sample)
  double C_L_amplitude = 0.0, C_D_amplitude = 0.0;        ///< (max − min)/2 over the last period
  double dt = 0.0;                                        ///< the last time step, s
  long steps = 0;                                         ///< time steps, both grids
  double wall_seconds = 0.0;
  /// false when U = 0 (a spinning cylinder in still fluid): the C_* fields, St and the amplitudes are 0
  /// and undefined; the forces and the torque are in history (F_x, F_y, M) and M_mean.
  bool has_coefficients = true;
  double reference_speed = 0.0;  ///< U, or a|ω| when U = 0: times D/U_ref and the CFL floor use it, m/s
  double M_mean = 0.0;           ///< torque per span over the last period (or the last sample), N·m/m
  double t_fine = 0.0;           ///< when the full grid took over (0: no warm start), s
  long coarse_steps = 0;         ///< steps of the warm start on the coarse grid
  NsStepTimes times;             ///< wall seconds per part of the steps (both grids), and steps
  double steps_per_second = 0.0;
};

/// The Δt a run uses: params.dt if set and below the limit Δt(kNsCflLimit), else from params.cfl; `note`
/// says when an asked Δt was clamped.
double choose_time_step(const NsParams& p, const PolarGrid& g, const NsState& s, std::string* note);

/// The rate r (1/s) whose product with Δt advance() compares with kNsCflLimit, or a bound above it:
/// cfl_number's (every ring; of ψ − ψ_ref when the rotation is implicit) and the wall ring's |ω|/Δθ (not
/// when the rotation is implicit). A march of magnus's own Δt keeps r·Δt near p.cfl.
double step_rate(const NsParams& p, const PolarGrid& g, const NsState& s);

/// Run from `start` (e.g. impulsive_start, or a checkpoint's state with its `history` so far). U = 0 is a
/// spinning cylinder in still fluid (needs ω ≠ 0): the time unit and the CFL floor use U_ref = a|ω|, no
/// coefficients. Throws std::invalid_argument when U = 0 and ω = 0 (nothing moves) or U < 0; never
/// throws on a failing flow: ok = false, message (time and likely cause).
UnsteadyResult run_unsteady(const NsParams& p, const UnsteadyOptions& o, NsState start,
                            std::vector<ForceSample> history = {});

/// Period, means and amplitudes of a history's last whole period of C_L (between upward mean crossings),
/// the period checked against the spectrum (period_confirmed, period_note). Returns false when fewer than
/// two crossings are found, or U ≤ 0 (no coefficients). D and U give St.
bool analyse_periodic(const std::vector<ForceSample>& h, double D, double U, UnsteadyResult& out);

}  // namespace magnus
