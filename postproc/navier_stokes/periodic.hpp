#pragma once
// The shedding period of a force history and its whole-period statistics. The period is the time between
// successive upward crossings of C_L through its mean level, with a hysteresis band so that a kink, a
// harmonic's bump or noise near the level is no crossing (successive maxima are not used: a kink just after
// a maximum makes a second maximum). The spectrum of the same samples cross-checks it: its strongest peak
// must lie at 1/period within kPeriodAgreement, else the period is not trusted.
#include <string>
#include <vector>

namespace magnus {

struct ForceSample;

/// One whole period of C_L, between two successive upward crossings [t0, t1] (s): time means of C_L, C_D,
/// C_M and of the torque M (N·m/m) over exactly [t0, t1], and the amplitudes (max − min)/2 of C_L, C_D.
struct PeriodWindow {
  double t0 = 0.0, t1 = 0.0, C_L = 0.0, C_D = 0.0, C_M = 0.0, M = 0.0, amp_L = 0.0, amp_D = 0.0;
  double length() const { return t1 - t0; }  ///< the period, s
};

/// Relative tolerance |f_spectrum·T − 1| within which the crossings' period T and the spectrum agree.
constexpr double kPeriodAgreement = 0.05;

/// Whole periods of C_L, oldest first (at most `last`), found in the last half (in time) of the samples
/// from index `first` on: upward crossings of the level L (the mean of C_L there), counted only once C_L
/// has been below L − b and then rises above L + b, b = 0.3·(max − min)/2; the crossing time is the linear
/// interpolation where C_L passes L. Periods with (max − min)/2 of C_L ≤ 1e-5 (round-off) are dropped.
std::vector<PeriodWindow> lift_periods(const std::vector<ForceSample>& h, size_t last, size_t first = 0);

/// Frequency (1/s) of the strongest peak of C_L's power spectrum over [t0, t1] (s): the history resampled
/// linearly on 1024 points, its linear trend removed, a Hann window, the DFT's largest bin above 0 refined
/// by a parabola through the log powers. 0 when undefined (fewer than 8 samples or t1 ≤ t0).
double lift_spectral_peak(const std::vector<ForceSample>& h, double t0, double t1);

/// The crossings' period T (s) checked against the spectrum of the last up-to-8 whole periods: "" when the
/// peak frequency f_s satisfies |f_s·T − 1| ≤ kPeriodAgreement, else the reason (both periods).
std::string period_disagreement(const std::vector<ForceSample>& h, const std::vector<PeriodWindow>& w);

}  // namespace magnus
