#pragma once
// Everything one run produces, post-processed from ψ: what the files and the summary show.
#include <string>
#include <vector>
#include <optional>

#include "postproc/potential/fields.hpp"
#include "postproc/potential/forces.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

/// Wall-clock seconds per phase of a run.
struct Timing {
  double total_s = 0.0, assemble_s = 0.0, factor_s = 0.0, solve_s = 0.0, postproc_s = 0.0;
};

/// What a run reports besides the fields: which method ran, the grid choice, the error estimate.
struct RunInfo {
  std::string method = "fft";
  std::string grid_choice;         ///< how the grid was chosen (tolerance mode)
  double estimated_cl_rel = -1.0;  ///< a-posteriori estimate, < 0 if none
  int threads = 1;
};

/// One stored state of a navier-stokes run (output.snapshots): an XDMF time series plays them.
struct Snapshot {
  double t = 0.0;                        ///< time, s
  std::vector<double> psi, vorticity;    ///< ψ (m²/s), ζ (1/s), (n_r, n_θ) row-major
};

/// What the navier-stokes model adds to a result. Means and amplitudes are over the last whole shedding
/// period when the flow is periodic, else the last step's values.
struct ViscousPart {
  double viscosity = 0.0;                ///< ν, m²/s
  std::optional<double> reynolds;        ///< U·2a/ν (undefined when U = 0)
  double time_unit = 0.0;                ///< D/U_ref, s (U_ref = U, or a|ω| when U = 0)
  std::string status;                    ///< why the run stopped (steady, converged, t_end, interrupted…)
  bool steady = false, periodic = false, converged = false;
  bool newton = false;                   ///< a steady state by Newton's method (not marched in time)
  bool partial = false;                  ///< interrupted (Ctrl-C) or stopped on an error before the end
  double t = 0.0;                        ///< the time reached, s
  double dt = 0.0;                       ///< the last time step, s
  long steps = 0;                        ///< time steps from rest, over every run it resumed
  long steps_resumed = 0;                ///< of steps, those the checkpoint it resumed from had taken
  double Gamma_R = 0.0;                  ///< circulation on the outer ring r = R, m²/s
  ViscousForces last;                    ///< forces at the last step (pressure and friction parts)
  std::optional<double> cl_mean, cd_mean, cm_mean, cl_amplitude, cd_amplitude;
  std::optional<double> strouhal;        ///< f·D/U from the lift signal (periodic only)
  std::optional<double> period;          ///< shedding period, s (periodic only)
  double lift_mean = 0.0, drag_mean = 0.0, torque_mean = 0.0;  ///< N/m, N/m, N·m/m
  double spin_power_mean = 0.0;          ///< −M̄ω, W/m
  std::optional<double> cl_ideal;        ///< potential flow's C_L for the same scene, −2πα
  std::optional<double> magnus_ratio;    ///< S(Re, α)/(2πρa²) = C_L,mean / C_L,ideal (undefined at α = 0)
  std::vector<double> separation;        ///< angles where τ_w = 0, rad in [0, 2π)
  std::optional<double> recirculation_length;  ///< behind the body along +x, over D (steady flow)
  /// Leading eigenvalue λ of the steady state's linear stability (time.mode = "auto"), U/D: Re λ is the
  /// growth rate, Im λ/(2π) the Strouhal number of the growing (or decaying) wake mode.
  std::optional<double> eigenvalue_real, eigenvalue_imag;
  /// Its eigenvector's relative residual ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖): the evidence that λ is an eigenvalue.
  std::optional<double> eigenvalue_residual;
  /// Wall time of the phases of a run, s: Newton's method, the eigenvalue test, the march (each when run).
  std::optional<double> newton_seconds, stability_seconds, march_seconds;
  std::vector<ForceSample> history;      ///< one sample per step
  std::vector<Snapshot> snapshots;       ///< the last output.snapshots states, oldest first
  /// time.mode = "steady": the grids solved, Newton's residuals, the Richardson values (state moved out).
  std::optional<SteadyStudy> steady_study;
  /// Estimated discretisation error of cl_mean, cd_mean, strouhal, relative (1): |f − f_2h|/|f| against a
  /// companion run on the grid twice as coarse (Roache's GCI, safety 3, order 2: 3|Δ|/(2² − 1) = |Δ|), plus
  /// the means' spread when they had not converged and the drift still to come of a periodic run's means; absent when undefined (error_note says why).
  std::optional<double> cl_mean_rel_estimate, cd_mean_rel_estimate, strouhal_rel_estimate;
  bool means_converged = true;              ///< the means (or steady values) had converged when it stopped
  std::optional<double> means_spread_rel;   ///< the spread added when they had not (largest of C_L, C_D, St)
  /// The drift still to come of the last periods' means in each estimate (means_drift, relative; periodic
  /// runs only).
  std::optional<double> cl_mean_drift_rel, cd_mean_drift_rel, strouhal_drift_rel;
  int companion_n_theta = 0, companion_n_r = 0;  ///< the companion's grid (0: no companion run)
  std::optional<double> companion_seconds;       ///< the companion's wall time, s
  std::string error_method;                      ///< how the estimate was formed ("" when none was)
  std::string error_note;                        ///< why a part of it is undefined ("" when all are defined)
  /// grid.tolerance: whether every defined estimate met it (absent without a tolerance), and how the grid
  /// was found when the first one did not meet it.
  std::optional<bool> tolerance_met;
  std::string tolerance_note;
  /// The computed 3D onset given to the run (magnus run --onset3d FILE.h5…): Re_c at this run's α, linear in
  /// α between the files' points; absent without files, or outside the α they span.
  std::optional<double> onset3d_reynolds;
  std::optional<double> onset3d_alpha_min, onset3d_alpha_max;  ///< the α the files span (absent: none given)
  std::string onset3d_files;                                   ///< the files, comma-separated ("": none)
};

struct FlowResult {
  Case c;
  PolarGrid grid;
  Fields fields;
  Surface surface;
  Forces forces;
  Errors errors;
  /// Numeric and exact: θ in [0, 2π), sorted by θ as postprocess computes them (read_result keeps the order
  /// a file stores).
  std::vector<StagnationPoint> stagnation, stagnation_exact;
  Timing timing;
  RunInfo info;
  std::optional<ViscousPart> viscous;  ///< present for navier-stokes results
};

/// Fields, surface, forces, stagnation points and errors from the superposition basis ψ_U, ψ_Γ
/// (ψ = U·ψ_U + Γ·ψ_Γ; the surface split of surface_from_basis keeps the forces free of ε·α round-off).
FlowResult postprocess(const PolarGrid& g, const Case& c, const std::vector<double>& psi_U,
                       const std::vector<double>& psi_Gamma, const FieldSelection& sel);

/// The exact free stagnation point when the numeric flow has none because it lies beyond the grid's outer
/// radius (r_s > R): why the numeric list is empty; empty otherwise.
std::optional<StagnationPoint> stagnation_outside_grid(const FlowResult& r);

}  // namespace magnus
