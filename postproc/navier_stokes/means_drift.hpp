#pragma once
// The drift still to come of a converging sequence of period means (C_L, C_D, the period): from the
// differences d_k = m_{k+1} − m_k of the last few whole periods' means. When they keep one sign and decay
// geometrically with ratio q < 1, the rest of the sequence moves by d_last·q/(1 − q); when they do not
// decay, the means move on at the current rate, and the drift over the next `horizon` periods is counted.
// The stop rule of a periodic run asks this to be below the means' tolerance as well as the consecutive
// agreement, and every periodic run adds it to its error bars (postproc/navier_stokes/error_estimate.hpp).
#include <vector>

namespace magnus {

struct PeriodWindow;

/// Periods whose means the drift estimate reads (the last ones, oldest first): 3 differences.
constexpr int kDriftPeriods = 4;
/// Periods ahead over which a drift that does not decay is counted (and the cap of q/(1 − q)).
constexpr double kDriftHorizon = 4.0;

/// The drift still to come (same unit as m) of the sequence m (oldest first; its last kDriftPeriods values
/// are read, differences d_k = m_{k+1} − m_k). When the last two or more differences share a sign (the
/// trailing run of one sign): q and d_last from a least-squares line through log|d_k| over that run (exact
/// for a geometric sequence), drift = |d_last|·min(q/(1 − q), horizon) — horizon·|d| when q ≥ 1, a linear
/// drift. When the last difference changed sign (noise about a level or a slow trend): horizon·|s|, s the
/// least-squares slope of the values read, per period. 0 with fewer than 3 values.
double remaining_drift(const std::vector<double>& m, double horizon = kDriftHorizon);

/// Remaining drift of the period means of C_L and C_D (1) and of the period's length (s), absolute.
struct MeansDrift {
  double cl = 0.0, cd = 0.0, period = 0.0;
};

/// remaining_drift of the means of C_L, C_D and of the lengths of the periods w (oldest first).
MeansDrift means_drift(const std::vector<PeriodWindow>& w, double horizon = kDriftHorizon);

/// The tolerance the periodic stop rule holds the means to: time.mean_tolerance, and without it being
/// larger than a fifth of grid.tolerance τ when one is set (τ > 0), so that the time error leaves the
/// tolerance to the grid: min(mean_tolerance, τ/5) (relative, 1).
double stop_mean_tolerance(double mean_tolerance, double grid_tolerance);

}  // namespace magnus
