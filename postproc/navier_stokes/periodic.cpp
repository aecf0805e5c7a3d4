#include "postproc/navier_stokes/periodic.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

namespace {

/// Means over exactly [t0, t1] of the piecewise-linear history (t0, t1 lie within a sample of b and e:
/// interpolated crossing times, so the window's ends do not jitter with the sampling) and amplitudes.
PeriodWindow window(const std::vector<ForceSample>& h, size_t b, size_t e, double t0, double t1) {
  PeriodWindow w;
  w.t0 = t0;
  w.t1 = t1;
  double T = 0.0, lo_L = h[b].C_L, hi_L = h[b].C_L, lo_D = h[b].C_D, hi_D = h[b].C_D;
  const size_t q0 = b > 0 ? b - 1 : 0, q1 = std::min(e + 1, h.size() - 1);
  for (size_t q = q0; q < q1; ++q) {
    const double ta = h[q].t, tb = h[q + 1].t;
    const double u0 = std::max(ta, t0), u1 = std::min(tb, t1);
    if (!(u1 > u0) || !(tb > ta)) continue;
    auto at = [&](double u, double ForceSample::*f) {
      const double x = (u - ta) / (tb - ta);
      return (1.0 - x) * (h[q].*f) + x * (h[q + 1].*f);
    };
    const double du = u1 - u0;
    T += du;
    w.C_L += 0.5 * du * (at(u0, &ForceSample::C_L) + at(u1, &ForceSample::C_L));
    w.C_D += 0.5 * du * (at(u0, &ForceSample::C_D) + at(u1, &ForceSample::C_D));
    w.C_M += 0.5 * du * (at(u0, &ForceSample::C_M) + at(u1, &ForceSample::C_M));
    w.M += 0.5 * du * (at(u0, &ForceSample::M) + at(u1, &ForceSample::M));
  }
  for (size_t q = b; q <= e; ++q) {
    lo_L = std::min(lo_L, h[q].C_L), hi_L = std::max(hi_L, h[q].C_L);
    lo_D = std::min(lo_D, h[q].C_D), hi_D = std::max(hi_D, h[q].C_D);
  }
  if (T > 0.0) w.C_L /= T, w.C_D /= T, w.C_M /= T, w.M /= T;
  w.amp_L = 0.5 * (hi_L - lo_L);
  w.amp_D = 0.5 * (hi_D - lo_D);
  return w;
}

/// C_L at time t of the piecewise-linear history (clamped to its ends); q: a sample index at or before t,
/// advanced as t grows.
double lift_at(const std::vector<ForceSample>& h, double t, size_t& q) {
  while (q + 1 < h.size() && h[q + 1].t <= t) ++q;
  if (q + 1 >= h.size() || !(h[q + 1].t > h[q].t)) return h[q].C_L;
  const double x = std::clamp((t - h[q].t) / (h[q + 1].t - h[q].t), 0.0, 1.0);
  return (1.0 - x) * h[q].C_L + x * h[q + 1].C_L;
}

}  // namespace

std::vector<PeriodWindow> lift_periods(const std::vector<ForceSample>& h, size_t last, size_t first) {
  if (h.size() < first + 3 || last == 0) return {};
  // The analysis span: the last half (in time) of the samples from `first`.
  const double t_half = 0.5 * (h[first].t + h.back().t);
  size_t b = first;
  while (b + 1 < h.size() && h[b].t < t_half) ++b;
  if (h.size() - b < 3) return {};
  double lo = h[b].C_L, hi = h[b].C_L, sum = 0.0, span = 0.0;
  for (size_t q = b; q < h.size(); ++q) {
    lo = std::min(lo, h[q].C_L), hi = std::max(hi, h[q].C_L);
    if (q > b) {
      const double dt = h[q].t - h[q - 1].t;
      sum += 0.5 * dt * (h[q].C_L + h[q - 1].C_L), span += dt;
    }
  }
  if (!(span > 0.0) || !(hi - lo > 2e-5)) return {};
  const double level = sum / span, band = 0.3 * 0.5 * (hi - lo);
  // Schmitt trigger: armed below level − band; a crossing of the level while armed is a candidate, kept
  // when C_L goes on above level + band.
  std::vector<size_t> idx;  // the sample at or after each crossing
  std::vector<double> t_cross;
  bool armed = false, have_candidate = false;
  size_t cand_q = 0;
  double cand_t = 0.0;
  for (size_t q = b; q < h.size(); ++q) {
    const double y = h[q].C_L;
    if (y < level - band) armed = true, have_candidate = false;
    if (!armed || q == b) continue;
    const double y0 = h[q - 1].C_L;
    if (y0 < level && y >= level) {
      have_candidate = true, cand_q = q;
      cand_t = h[q - 1].t + (level - y0) / (y - y0) * (h[q].t - h[q - 1].t);
    }
    if (have_candidate && y > level + band) {
      idx.push_back(cand_q), t_cross.push_back(cand_t);
      armed = have_candidate = false;
    }
  }
  std::vector<PeriodWindow> out;
  const size_t n0 = idx.size() > last + 1 ? idx.size() - last - 1 : 0;
  for (size_t k = n0; k + 1 < idx.size(); ++k) {
    PeriodWindow w = window(h, idx[k], idx[k + 1], t_cross[k], t_cross[k + 1]);
    if (w.amp_L > 1e-5) out.push_back(w);  // a steady flow's round-off wiggles are no period
  }
  return out;
}

double lift_spectral_peak(const std::vector<ForceSample>& h, double t0, double t1) {
  constexpr int M = 1024;
  if (h.size() < 8 || !(t1 > t0)) return 0.0;
  std::vector<double> x(M);
  size_t q = 0;
  while (q + 1 < h.size() && h[q + 1].t <= t0) ++q;
  const double dt = (t1 - t0) / M;
  for (int k = 0; k < M; ++k) x[k] = lift_at(h, t0 + (k + 0.5) * dt, q);
  // Remove the least-squares line (a slow drift would leak into the low bins), then Hann.
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (int k = 0; k < M; ++k) sx += k, sy += x[k], sxx += double(k) * k, sxy += k * x[k];
  const double slope = (M * sxy - sx * sy) / (M * sxx - sx * sx), icpt = (sy - slope * sx) / M;
  for (int k = 0; k < M; ++k) x[k] = (x[k] - icpt - slope * k) * (0.5 - 0.5 * std::cos(2.0 * M_PI * k / M));
  std::vector<double> c(M), s(M), logp(M / 2 + 1);
  for (int k = 0; k < M; ++k) c[k] = std::cos(2.0 * M_PI * k / M), s[k] = std::sin(2.0 * M_PI * k / M);
  int best = 1;
  for (int f = 0; f <= M / 2; ++f) {
    double re = 0.0, im = 0.0;
    for (int k = 0, a = 0; k < M; ++k, a = (a + f) & (M - 1)) re += x[k] * c[a], im -= x[k] * s[a];
    logp[f] = std::log(re * re + im * im + 1e-300);
    if (f >= 1 && logp[f] > logp[best]) best = f;
  }
  double shift = 0.0;
  if (best < M / 2) {
    const double d = logp[best - 1] - 2.0 * logp[best] + logp[best + 1];
    if (d < 0.0) shift = std::clamp(0.5 * (logp[best - 1] - logp[best + 1]) / d, -0.5, 0.5);
  }
  return (best + shift) / (t1 - t0);
}

std::string period_disagreement(const std::vector<ForceSample>& h, const std::vector<PeriodWindow>& w) {
  if (w.size() < 3) return "";  // too short for a spectrum that can tell (a run is not converged then)
  const double T = w.back().length();
  const double f_s = lift_spectral_peak(h, w[w.size() > 8 ? w.size() - 8 : 0].t0, w.back().t1);
  if (f_s > 0.0 && std::fabs(f_s * T - 1.0) <= kPeriodAgreement) return "";
  return fmt::format(
      "the period of C_L's mean crossings ({:.5g} s) and its spectrum's peak ({}) disagree: St undefined", T,
      f_s > 0.0 ? fmt::format("{:.5g} s", 1.0 / f_s) : std::string("none"));
}

}  // namespace magnus
