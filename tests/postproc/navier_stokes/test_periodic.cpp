// The shedding period of a force history: mean crossings with hysteresis, checked against the spectrum,
// on synthetic lift signals with a kink after the maximum, harmonics, slow drift and a frequency jump.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "postproc/navier_stokes/periodic.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

using namespace magnus;

namespace {

/// Samples of C_L = f(t) (C_D = 1 + 0.1 C_L) on [0, t_end] with a step varying ±30% (as the CFL control
/// does).
std::vector<ForceSample> sampled(const std::function<double(double)>& f, double t_end, double dt0) {
  std::vector<ForceSample> h;
  for (double t = 0.0; t < t_end; t += dt0 * (1.0 + 0.3 * std::sin(7.0 * t))) {
    ForceSample x;
    x.t = t, x.C_L = f(t), x.C_D = 1.0 + 0.1 * x.C_L;
    h.push_back(x);
  }
  return h;
}

/// The mean and (max − min)/2 of f over one period [t0, t0 + T] by fine sampling (10⁵ points).
std::pair<double, double> mean_and_amplitude(const std::function<double(double)>& f, double t0, double T) {
  const int n = 100000;
  double s = 0.0, lo = 1e300, hi = -1e300;
  for (int k = 0; k < n; ++k) {
    const double y = f(t0 + (k + 0.5) * T / n);
    s += y, lo = std::min(lo, y), hi = std::max(hi, y);
  }
  return {s / n, 0.5 * (hi - lo)};
}

}  // namespace

TEST_CASE("[ns] period: a kink after each maximum is no period (St from the mean crossings)", "[ns]") {
  // The Re 80, α = 1 lift: period 7.25 D/U, amplitude 0.043 about −2.31, and a bump 0.73 D/U after each
  // maximum that makes a second local maximum (successive maxima gave a period of 0.73, St 1.37).
  const double T = 7.25, t_max = T / 4.0, t_kink = t_max + 0.73;
  auto f = [&](double t) {
    const double u = std::fmod(t, T);
    return -2.31 + 0.043 * std::sin(2.0 * M_PI * t / T) + 0.01 * std::exp(-std::pow((u - t_kink) / 0.15, 2));
  };
  // The signal has two maxima per period (the old detector's trap).
  const double y0 = f(t_max), y1 = f(t_max + 0.4), y2 = f(t_kink);
  REQUIRE(y1 < y0);
  REQUIRE(y2 > y1);
  const auto h = sampled(f, 120.0, 0.02);
  UnsteadyResult r;
  REQUIRE(analyse_periodic(h, 1.0, 1.0, r));
  CHECK(r.period_confirmed);
  CHECK(r.period_note.empty());
  CHECK(r.period == Approx(T).epsilon(1e-3));
  CHECK(r.St == Approx(1.0 / T).epsilon(1e-3));
  const auto [mean, amp] = mean_and_amplitude(f, 0.0, T);
  CHECK(r.C_L_mean == Approx(mean).epsilon(1e-5));
  CHECK(r.C_L_amplitude == Approx(amp).epsilon(5e-3));
  CHECK(r.C_L_amplitude > 0.04);  // not the kink's little swing
  CHECK(lift_spectral_peak(h, 40.0, 40.0 + 8.0 * T) == Approx(1.0 / T).epsilon(0.01));
}

TEST_CASE("[ns] period: harmonics and a slow drift keep the period and the means", "[ns]") {
  // Fundamental, second and third harmonics (a lobed waveform with inflections) and a drift of the mean by
  // 0.1% of the amplitude per period.
  const double T = 5.1, A = 0.3, drift = 0.001 * A / T;
  auto f = [&](double t) {
    const double ph = 2.0 * M_PI * t / T;
    return 0.5 + A * std::sin(ph) + 0.12 * std::sin(2.0 * ph + 1.0) + 0.05 * std::sin(3.0 * ph) + drift * t;
  };
  const auto h = sampled(f, 80.0, 0.03);
  UnsteadyResult r;
  REQUIRE(analyse_periodic(h, 2.0, 0.5, r));
  CHECK(r.period_confirmed);
  CHECK(r.period == Approx(T).epsilon(2e-3));
  CHECK(r.St == Approx(2.0 / (0.5 * T)).epsilon(2e-3));
  // The last whole period's mean: the waveform's mean at its middle time (the drift is linear).
  const double t_mid = 0.5 * (h.back().t + h.back().t - 2.0 * T);
  CHECK(r.C_L_mean == Approx(0.5 + drift * t_mid).epsilon(2e-3));
  const auto periods = lift_periods(h, 100);
  REQUIRE(periods.size() >= 6);  // the last half of 80 s holds 7 whole crossings-to-crossings of 5.1 s
  for (const PeriodWindow& w : periods) CHECK(w.length() == Approx(T).epsilon(3e-3));
}

TEST_CASE("[ns] period: crossings that disagree with the spectrum leave St undefined", "[ns]") {
  // The frequency jumps from 0.1 to 0.14 at t = 85 (phase continuous): the last period (1/0.14) is not the
  // spectrum's peak over the last periods (near 0.1), so the period is not confirmed.
  auto phase = [](double t) { return t < 85.0 ? 0.1 * t : 8.5 + 0.14 * (t - 85.0); };
  auto f = [&](double t) { return 0.2 * std::sin(2.0 * M_PI * phase(t)); };
  const auto h = sampled(f, 100.0, 0.05);
  UnsteadyResult r;
  REQUIRE(analyse_periodic(h, 1.0, 1.0, r));
  CHECK(r.period == Approx(1.0 / 0.14).epsilon(5e-3));
  CHECK_FALSE(r.period_confirmed);
  CHECK(r.St == 0.0);
  CHECK(r.period_note.find("disagree") != std::string::npos);
  const auto w = lift_periods(h, 8);
  CHECK(period_disagreement(h, w) == r.period_note);
}

TEST_CASE("[ns] period: means agree relatively above 1, absolutely below", "[ns]") {
  // A lift of 26.5 (α = 5) whose periods' means differ by 0.02: 7.5e-4 of itself, inside 1e-3.
  CHECK(means_agree(26.50, 26.52, 1e-3));
  CHECK_FALSE(means_agree(26.50, 26.55, 1e-3));  // 1.9e-3 of itself
  // A drag of 0.3: absolute, 1e-3 of the dynamic pressure's scale.
  CHECK(means_agree(0.3000, 0.3009, 1e-3));
  CHECK_FALSE(means_agree(0.3000, 0.3011, 1e-3));
  // A lift near 0 without spin: absolute.
  CHECK(means_agree(-0.0004, 0.0004, 1e-3));
  CHECK_FALSE(means_agree(-0.0006, 0.0006, 1e-3));
}
