#include "postproc/navier_stokes/means_drift.hpp"

#include <algorithm>
#include <cmath>

#include "postproc/navier_stokes/periodic.hpp"

namespace magnus {

namespace {

/// Least-squares line y ≈ a + b·k through (k, y_k), k = 0, 1, …: {a, b}.
std::pair<double, double> line_fit(const std::vector<double>& y) {
  const double n = double(y.size()), k_mean = 0.5 * (n - 1.0);
  double y_mean = 0.0;
  for (double v : y) y_mean += v / n;
  double sxy = 0.0, sxx = 0.0;
  for (size_t k = 0; k < y.size(); ++k) {
    sxy += (double(k) - k_mean) * (y[k] - y_mean);
    sxx += (double(k) - k_mean) * (double(k) - k_mean);
  }
  const double b = sxx > 0.0 ? sxy / sxx : 0.0;
  return {y_mean - b * k_mean, b};
}

}  // namespace

double remaining_drift(const std::vector<double>& m, double horizon) {
  if (m.size() < 3) return 0.0;
  const std::vector<double> x(m.end() - std::min<long>(long(m.size()), kDriftPeriods), m.end());
  std::vector<double> d;
  for (size_t k = 1; k < x.size(); ++k) d.push_back(x[k] - x[k - 1]);
  size_t run = 1;  // the trailing differences of the last one's sign (a 0 ends the run)
  while (run < d.size() && d[d.size() - 1 - run] * d.back() > 0.0) ++run;
  if (run < 2 || d.back() == 0.0) return horizon * std::fabs(line_fit(x).second);
  std::vector<double> log_d;
  for (size_t k = d.size() - run; k < d.size(); ++k) log_d.push_back(std::log(std::fabs(d[k])));
  const auto [a, b] = line_fit(log_d);
  const double q = std::exp(b), d_last = std::exp(a + b * double(run - 1));
  return d_last * (q < 1.0 ? std::min(q / (1.0 - q), horizon) : horizon);
}

MeansDrift means_drift(const std::vector<PeriodWindow>& w, double horizon) {
  std::vector<double> L, D, T;
  for (const PeriodWindow& p : w) L.push_back(p.C_L), D.push_back(p.C_D), T.push_back(p.length());
  return {remaining_drift(L, horizon), remaining_drift(D, horizon), remaining_drift(T, horizon)};
}

double stop_mean_tolerance(double mean_tolerance, double grid_tolerance) {
  return grid_tolerance > 0.0 ? std::min(mean_tolerance, grid_tolerance / 5.0) : mean_tolerance;
}

}  // namespace magnus
