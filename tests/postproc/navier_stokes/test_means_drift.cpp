// The drift still to come of a run's period means (postproc/navier_stokes/means_drift.hpp) on synthetic
// sequences (geometric decay with a known limit, a linear drift, noise), the stop rule that asks it to be
// small (periods_agree) on a slowly drifting synthetic force history, the error bar that adds it, and the
// tolerance the stop rule holds the means to under grid.tolerance.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "io/report_viscous.hpp"
#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/means_drift.hpp"
#include "postproc/navier_stokes/periodic.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

using namespace magnus;

namespace {

/// m_k = m_inf + A·q^k, k = 0 … n − 1: converges to m_inf.
std::vector<double> geometric(double m_inf, double A, double q, int n) {
  std::vector<double> m;
  for (int k = 0; k < n; ++k) m.push_back(m_inf + A * std::pow(q, k));
  return m;
}

/// n values of a fixed pseudo-random sequence in [−1, 1] (a linear congruential generator, seed 7).
std::vector<double> noise(int n) {
  std::vector<double> x;
  unsigned long s = 7;
  for (int k = 0; k < n; ++k) {
    s = (1103515245UL * s + 12345UL) % 2147483648UL;
    x.push_back(2.0 * double(s) / 2147483648.0 - 1.0);
  }
  return x;
}

/// A shedding force history on [0, t_end] (s): C_L = −2.5 + 0.35 sin(2πt/T), C_D = 1.09 + 0.02 sin(4πt/T)
/// + rate·t/T (rate: the drift of the C_D means per period), sampled every T/200.
std::vector<ForceSample> shedding(double T, double t_end, double rate) {
  std::vector<ForceSample> h;
  for (double t = 0.0; t < t_end; t += T / 200.0) {
    ForceSample x;
    x.t = t;
    x.C_L = -2.5 + 0.35 * std::sin(2.0 * M_PI * t / T);
    x.C_D = 1.09 + 0.02 * std::sin(4.0 * M_PI * t / T) + rate * t / T;
    h.push_back(x);
  }
  return h;
}

}  // namespace

TEST_CASE("remaining_drift: a geometric decay gives the distance to its limit exactly", "[drift]") {
  // q = 0.5: q/(1 − q) = 1 < the horizon; the rest of the sequence moves by d_last·q/(1 − q) = m_inf − m_last.
  for (double q : {0.3, 0.5, 0.7}) {
    const std::vector<double> m = geometric(1.09, -0.004, q, 9);
    const double exact = std::fabs(m.back() - 1.09);
    CHECK(remaining_drift(m) == Approx(exact).epsilon(1e-9));
    // Rising towards its limit: the same.
    CHECK(remaining_drift(geometric(-2.5, 0.01, q, 9)) == Approx(0.01 * std::pow(q, 8)).epsilon(1e-9));
  }
  // q = 0.9: q/(1 − q) = 9 is capped at the horizon (4 periods at the last rate).
  const std::vector<double> slow = geometric(1.0, 0.01, 0.9, 9);
  CHECK(remaining_drift(slow) == Approx(kDriftHorizon * std::fabs(slow[8] - slow[7])).epsilon(1e-9));
  CHECK(remaining_drift(slow) < std::fabs(slow.back() - 1.0));
  // An earlier turn (the start-up transient) before the last kDriftPeriods values is not read.
  std::vector<double> turned = {1.2, 0.9};
  for (double x : geometric(1.09, -0.004, 0.5, 6)) turned.push_back(x);
  CHECK(remaining_drift(turned) == Approx(0.004 * std::pow(0.5, 5)).epsilon(1e-9));
}

TEST_CASE("remaining_drift: a linear drift counts the horizon's periods at its rate", "[drift]") {
  std::vector<double> m;
  for (int k = 0; k < 8; ++k) m.push_back(1.09 - 5e-4 * k);  // −0.05% a period: the refine-2 run's C_D
  CHECK(remaining_drift(m) == Approx(kDriftHorizon * 5e-4).epsilon(1e-9));
  CHECK(remaining_drift(m, 2.0) == Approx(2.0 * 5e-4).epsilon(1e-9));
  // Fewer than 3 values: no difference of differences, no estimate.
  CHECK(remaining_drift({1.0, 1.1}) == 0.0);
  CHECK(remaining_drift({}) == 0.0);
}

TEST_CASE("remaining_drift: noise about a level stays at the noise's size, a drift under noise is found",
          "[drift]") {
  const std::vector<double> e = noise(40);
  // Noise of amplitude 1e-4 about 1.09: the estimate of each window of kDriftPeriods is below horizon × the
  // largest step the noise can make (2e-4 a period), and the level itself (1.09) is nowhere near it.
  double largest = 0.0;
  for (int n = kDriftPeriods; n <= 40; ++n) {
    std::vector<double> m;
    for (int k = 0; k < n; ++k) m.push_back(1.09 + 1e-4 * e[size_t(k)]);
    largest = std::max(largest, remaining_drift(m));
  }
  CHECK(largest > 0.0);
  CHECK(largest <= kDriftHorizon * 2e-4);
  // A drift of 1e-3 a period under noise of 1e-5: the differences keep their sign, the rate is found to the
  // noise's share.
  std::vector<double> m;
  for (int k = 0; k < 10; ++k) m.push_back(1.09 + 1e-3 * k + 1e-5 * e[size_t(k)]);
  CHECK(remaining_drift(m) == Approx(kDriftHorizon * 1e-3).epsilon(0.05));
}

TEST_CASE("means_drift: of the periods' C_L, C_D means and lengths", "[drift]") {
  std::vector<PeriodWindow> w;
  for (int k = 0; k < 6; ++k) {
    PeriodWindow p;
    p.t0 = 6.0 * k, p.t1 = p.t0 + 6.0 + 0.01 * std::pow(0.5, k);
    p.C_L = -2.5, p.C_D = 1.09 - 4e-4 * k;
    w.push_back(p);
  }
  const MeansDrift d = means_drift(w);
  CHECK(d.cl == 0.0);  // no change at all
  CHECK(d.cd == Approx(kDriftHorizon * 4e-4).epsilon(1e-9));
  CHECK(d.period == Approx(0.01 * std::pow(0.5, 5)).epsilon(1e-6));
}

TEST_CASE("stop rule: a slow drift that agrees period to period does not stop the run", "[drift]") {
  const double T = 6.0;
  UnsteadyOptions o;  // mean_tol 1e-3 over converged_periods + 1 = 4 periods
  // C_D drifts by 5e-4 a period (0.046% of 1.09): consecutive periods agree to 1e-3, the old rule stopped.
  const std::vector<ForceSample> drifting = shedding(T, 20.0 * T, 5e-4);
  o.stop_on_drift = false;
  CHECK(periods_agree(drifting, 0, o));
  o.stop_on_drift = true;
  CHECK_FALSE(periods_agree(drifting, 0, o));
  // The same history with settled means stops.
  CHECK(periods_agree(shedding(T, 20.0 * T, 0.0), 0, o));
  // A drift of 1e-4 a period leaves 4e-4 to come: below 1e-3, it stops; at a fifth of grid.tolerance 1e-3
  // (2e-4) it does not.
  const std::vector<ForceSample> slow = shedding(T, 20.0 * T, 1e-4);
  CHECK(periods_agree(slow, 0, o));
  o.mean_tol = stop_mean_tolerance(1e-3, 1e-3);
  CHECK_FALSE(periods_agree(slow, 0, o));
}

TEST_CASE("stop_mean_tolerance: a fifth of grid.tolerance when that is tighter", "[drift]") {
  CHECK(stop_mean_tolerance(1e-3, 0.0) == 1e-3);  // no grid.tolerance
  CHECK(stop_mean_tolerance(1e-3, 5e-4) == Approx(1e-4));
  CHECK(stop_mean_tolerance(1e-3, 0.01) == 1e-3);  // 2e-3 would be looser than time.mean_tolerance
  CHECK(stop_mean_tolerance(1e-4, 1e-3) == 1e-4);
}

TEST_CASE("estimate: the drift still to come is part of every bar, and the summary says when it dominates",
          "[drift]") {
  UnsteadyResult fine, coarse;
  fine.C_L_mean = -2.5, fine.C_D_mean = 1.1, fine.St = 0.165, fine.converged = true, fine.periodic = true;
  coarse.C_L_mean = -2.4995, coarse.C_D_mean = 1.0989, coarse.St = 0.16495;
  ViscousPart v;
  estimate_from_companion(v, fine, coarse, {}, MeansSpread{0.0004, 0.002, 0.0001});
  CHECK(*v.cl_mean_rel_estimate == Approx(0.0005 / 2.5 + 0.0004));
  CHECK(*v.cd_mean_rel_estimate == Approx(0.0011 / 1.1 + 0.002));
  CHECK(*v.strouhal_rel_estimate == Approx(0.00005 / 0.165 + 0.0001));
  CHECK(*v.cl_mean_drift_rel == 0.0004);
  CHECK(*v.cd_mean_drift_rel == 0.002);
  CHECK(*v.strouhal_drift_rel == 0.0001);
  CHECK_FALSE(v.means_spread_rel);  // converged: no spread, the drift still counts
  // C_L: 0.04% of 0.06%, C_D: 0.2% of 0.3% are most of their bars; St: 0.01% of 0.04% is not.
  const std::string text = drift_text(v);
  CHECK(text.find("most of the bar of C_L (0.040% of ±0.060%), C_D (0.200% of ±0.300%)") != std::string::npos);
  CHECK(text.find("St") == std::string::npos);
  // A small drift is part of the bars, not most of any.
  ViscousPart small;
  estimate_from_companion(small, fine, coarse, {}, MeansSpread{1e-5, 2e-5, 1e-5});
  CHECK(drift_text(small).find("most of") == std::string::npos);
  CHECK(drift_text(small).find("at most 0.002% (C_D), is part of the estimate") != std::string::npos);
  // Not periodic (steady): no drift term at all.
  fine.periodic = false;
  ViscousPart steady;
  estimate_from_companion(steady, fine, coarse, {}, {});
  CHECK_FALSE(steady.cl_mean_drift_rel);
  CHECK_FALSE(steady.strouhal_drift_rel);
  CHECK(drift_text(steady).empty());
}
