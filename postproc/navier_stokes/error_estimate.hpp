#pragma once
// The error bar of every viscous run: a companion run on the grid twice as coarse, beside the run on the
// second core, and the relative difference of their mean C_L, mean C_D and St (Roache's grid-convergence
// index with safety factor 3 and order 2, 3·|f_h − f_2h|/(2² − 1) = |f_h − f_2h|), plus the spread of the
// means between the last periods when they had not converged when the run stopped.
#include <atomic>
#include <cmath>
#include <functional>
#include <future>
#include <memory>
#include <string>

#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

struct ViscousPart;

/// The companion's fewest points in θ: below it the run is not a grid of the same flow.
constexpr int kCompanionMinTheta = 8;
/// …and its fewest rings (the grid and the interpolation onto it need four).
constexpr int kCompanionMinRings = 4;
/// |f_h| below which a coefficient counts as 0 (C_L at α = 0): a relative error of it is undefined.
constexpr double kEstimateZero = 1e-3;

/// The parameters of the grid twice as coarse as `fine` (the grid of p): every field copied, n_θ/2 (even)
/// and (n_r − 1)/2 + 1 rings (R, the ring map, the orders the same).
NsParams companion_params(const NsParams& p, const PolarGrid& fine);

/// Why a run gets no companion ("" when it does): U = 0 (no coefficients), a resumed run, a companion grid
/// below kCompanionMinTheta or kCompanionMinRings.
std::string companion_refusal(const NsParams& p, const PolarGrid& fine, bool resumed);

/// Relative spread of the means that had not converged: max − min of the last periods' means of C_L, C_D
/// and of their lengths (St), each over |f|; with no period, the drift |f(t) − f(t − window)|/|f| of the
/// last window (s). 0 where undefined.
struct MeansSpread {
  double cl = 0.0, cd = 0.0, st = 0.0;
};
MeansSpread means_spread(const UnsteadyResult& run, int periods, double window);

/// The relative drift still to come of a periodic run's means (means_drift of its last kDriftPeriods
/// periods): of C_L and C_D over |C| (0 when |C| < kEstimateZero), of St as the period's over T (1). All 0
/// when the run is not periodic.
MeansSpread means_drift_rel(const UnsteadyResult& run);

/// e = |f_h − f_2h|/|f_h| + spread (relative, 1; spread: what the means' spread and drift add): Roache's
/// GCI 3·|f_h − f_2h|/(2² − 1) for order 2 on a grid ratio 2, the safety factor 3 covering an order that is
/// not yet 2. Undefined when |f_h| < kEstimateZero
/// or either value is not finite.
std::optional<double> relative_estimate(double f_h, double f_2h, double spread);

/// Whether a companion's orbit (coarse) is the run's orbit on the coarser grid, not another branch (near
/// α = 5 a march from rest could settle on another shedding mode): both shed, St within 30% and the C_L
/// amplitude within a factor 2.
bool same_orbit(const UnsteadyResult& run, const UnsteadyResult& coarse);

/// Records the companion in v: its grid (pc's n_θ × n_r), its wall seconds, and the method line "from a
/// companion {what} on n_θ × n_r[ (coarser in the rings only)]: |f − f_coarse|, 3× the Richardson estimate".
void record_companion(ViscousPart& v, const char* what, const NsParams& pc, bool rings_only, double seconds);

/// The estimates of v (cl_mean_rel_estimate, …, means_converged, means_spread_rel, the drifts,
/// error_note) from the run `fine` and its companion `coarse` (U > 0): each bar |f − f_coarse|/|f| + the
/// spread (when the means had not converged) + the drift still to come (always, when periodic); undefined,
/// with the reason in error_note, when the companion failed or was stopped before the run's time, or the
/// run was interrupted.
void estimate_from_companion(ViscousPart& v, const UnsteadyResult& fine, const UnsteadyResult& coarse,
                             const MeansSpread& spread, const MeansSpread& drift = {});

/// A companion run (a march, or a periodic orbit: postproc/navier_stokes/run_periodic.cpp) on its own
/// thread; its destructor stops it at once (the future then waits for it).
struct CompanionRun {
  std::atomic<double> stop_at{HUGE_VAL};  ///< it stops at its first step (or period) at or past this time, s
  std::future<UnsteadyResult> result;
  ~CompanionRun() { stop_at = -HUGE_VAL; }
};

/// Starts run_unsteady(pc, o, start) on a thread of its own (pc.threads = 1, no hooks): it stops when its
/// own criteria say so, or at stop_at.
std::unique_ptr<CompanionRun> start_companion(NsParams pc, UnsteadyOptions o, NsState start);

/// The companion stopped at the time t_end (s) the run ended at — at once if it is past it, else once it
/// gets there (a companion behind the run, on a loaded machine, catches up; t_end = +∞: when it ends by its
/// own criteria) — and its result (interrupted when it was stopped; t_end = −∞: at once, for a run that was
/// interrupted). keep_going, when set, is polled first and then while it runs: once it says stop (a Ctrl-C
/// after the run ended) the companion is stopped and its result is a failure, interrupted, naming why.
UnsteadyResult finish_companion(CompanionRun& m, double t_end, const std::function<bool()>& keep_going = {});

}  // namespace magnus
