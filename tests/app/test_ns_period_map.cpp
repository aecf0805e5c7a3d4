// The shedding period on every point of a coarse map, end to end: each point's St and C_L amplitude, as
// `magnus run` reports them, against what the test finds itself in the stored force history (the peak of
// its own discrete Fourier transform, the half peak-to-peak over whole periods), with no use of magnus's
// period detector.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/result_reader.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// Frequency (1/s) of the largest |DFT| of C_L over the samples with t ≥ t0, scanned on a fine grid of
/// frequencies from 2/T to 200/T (T the window), the mean removed; trapezoidal sums on the uneven samples.
double dft_peak(const std::vector<ForceSample>& h, double t0) {
  std::vector<const ForceSample*> w;
  for (const auto& s : h)
    if (s.t >= t0) w.push_back(&s);
  REQUIRE(w.size() > 100);
  const double T = w.back()->t - w.front()->t;
  double mean = 0.0;
  for (size_t k = 1; k < w.size(); ++k) mean += 0.5 * (w[k]->C_L + w[k - 1]->C_L) * (w[k]->t - w[k - 1]->t);
  mean /= T;
  double best_f = 0.0, best_p = -1.0;
  for (double f = 2.0 / T; f <= 200.0 / T; f += 0.01 / T) {
    double re = 0.0, im = 0.0;
    for (size_t k = 1; k < w.size(); ++k) {
      const double dt = w[k]->t - w[k - 1]->t, a = w[k]->C_L - mean, b = w[k - 1]->C_L - mean;
      re += 0.5 * dt * (a * std::cos(2 * M_PI * f * w[k]->t) + b * std::cos(2 * M_PI * f * w[k - 1]->t));
      im += 0.5 * dt * (a * std::sin(2 * M_PI * f * w[k]->t) + b * std::sin(2 * M_PI * f * w[k - 1]->t));
    }
    if (re * re + im * im > best_p) best_p = re * re + im * im, best_f = f;
  }
  return best_f;
}

}  // namespace

TEST_CASE("every shedding point of a coarse map: St at its own history's spectral peak, the amplitude its "
          "half peak-to-peak",
          "[app][ns][period]") {
  const std::string dir = test::temp_dir("ns-period-map");
  const std::string s_map = std::string(MAGNUS_SOURCE_DIR) + "/cases/s_map.toml";
  int shedding = 0;
  for (const double re : {80.0, 100.0})  // Re 80: a kink after each maximum fooled maxima
    for (const double alpha : {0.0, 0.5, 1.0}) {
      CAPTURE(re, alpha);
      const std::string out = dir + "/p.h5";
      const auto o = test::magnus_cmd({"run", s_map, "-o", out, "-q", "--force", "--set",
                                       "flow.reynolds=" + std::to_string(re), "--set",
                                       "cylinder.spin_ratio=" + std::to_string(alpha), "--set",
                                       "time.mode=unsteady", "--set", "time.end=400"},
                                      dir);
      INFO(o.err);
      REQUIRE(o.status == 0);
      const FlowResult r = read_result(out);
      const ViscousPart& v = *r.viscous;
      REQUIRE(v.status == "periodic means converged");
      REQUIRE(v.strouhal);  // D = 1 m, U = 1 m/s: St = f
      ++shedding;
      // The last 60 D/U (60 s here): some eight shedding cycles of the settled wake (near onset the
      // frequency still drifts earlier on, as the amplitude saturates).
      const double t0 = v.history.back().t - 60.0;
      const double f = dft_peak(v.history, t0);
      CHECK(*v.strouhal == Approx(f).epsilon(0.02));
      // The amplitude: half of max − min of C_L over whole periods at the end (the last 2/f seconds).
      double lo = 1e300, hi = -1e300;
      for (const auto& s : v.history)
        if (s.t >= v.history.back().t - 2.0 / f) lo = std::min(lo, s.C_L), hi = std::max(hi, s.C_L);
      CHECK(*v.cl_amplitude == Approx(0.5 * (hi - lo)).epsilon(0.05));
    }
  CHECK(shedding == 6);
}
