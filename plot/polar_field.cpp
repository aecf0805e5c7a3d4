#include "plot/polar_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace magnus {
namespace {

void check(const PolarField& f) {
  if (f.r.size() < 2 || f.theta.size() < 4 || f.values.size() != f.r.size() * f.theta.size())
    throw std::invalid_argument("plot: the polar field does not match its grid");
}

/// Fourier coefficients (a_k, b_k), k = 0 … n/2, of one ring.
void fourier(const double* ring, size_t n, std::vector<double>& a, std::vector<double>& b) {
  const size_t m = n / 2;
  a.assign(m + 1, 0.0);
  b.assign(m + 1, 0.0);
  for (size_t k = 0; k <= m; ++k) {
    double sa = 0.0, sb = 0.0;
    for (size_t j = 0; j < n; ++j) {
      const double ph = 2.0 * M_PI * double((k * j) % n) / double(n);
      sa += ring[j] * std::cos(ph);
      sb += ring[j] * std::sin(ph);
    }
    a[k] = 2.0 * sa / double(n);
    b[k] = 2.0 * sb / double(n);
  }
}

/// The trigonometric interpolant of the coefficients at θ (n even: the Nyquist term at half weight).
double trig_eval(const std::vector<double>& a, const std::vector<double>& b, size_t n, double th) {
  const size_t m = n / 2;
  double s = 0.5 * a[0];
  for (size_t k = 1; k <= m; ++k) {
    const double w = (n % 2 == 0 && k == m) ? 0.5 : 1.0;
    s += w *
         (a[k] * std::cos(double(k) * th) + (k == m && n % 2 == 0 ? 0.0 : b[k] * std::sin(double(k) * th)));
  }
  return s;
}

/// Cubic Lagrange weights in ln r at r for the 4 rings around it (one-sided at the ends).
void cubic_weights(const std::vector<double>& r, double x, int& i0, double w[4]) {
  const int n = int(r.size());
  const double lx = std::log(std::clamp(x, r.front(), r.back()));
  int i = 0;
  while (i + 1 < n - 1 && r[i + 1] <= std::exp(lx)) ++i;
  const int npts = std::min(4, n);
  i0 = std::clamp(i - 1, 0, n - npts);
  for (int k = 0; k < 4; ++k) w[k] = 0.0;
  for (int k = 0; k < npts; ++k) {
    double p = 1.0;
    for (int m = 0; m < npts; ++m)
      if (m != k) p *= (lx - std::log(r[i0 + m])) / (std::log(r[i0 + k]) - std::log(r[i0 + m]));
    w[k] = p;
  }
}

}  // namespace

PolarField refine_polar_field(const PolarField& f, double r_max, int min_theta) {
  check(f);
  const size_t nt = f.theta.size();
  size_t last = 0;
  while (last + 1 < f.r.size() && f.r[last] < r_max) ++last;
  last = std::max<size_t>(last, 1);
  // Angles: n_θ, or the smallest multiple of n_θ ≥ min_theta (the grid's nodes are kept).
  const size_t mult = nt >= size_t(min_theta) ? 1 : (size_t(min_theta) + nt - 1) / nt;
  const size_t nd = nt * mult;
  const double dxi = 2.0 * M_PI / double(nd);
  std::vector<double> radii;
  for (size_t i = 0; i < last; ++i) {
    const double step = std::log(f.r[i + 1] / f.r[i]);
    const int m = std::max(1, int(std::ceil(step / dxi - 1e-9)));
    for (int k = 0; k < m; ++k) radii.push_back(f.r[i] * std::exp(step * k / m));
  }
  radii.push_back(f.r[last]);

  PolarField out;
  out.r = radii;
  out.theta.resize(nd);
  for (size_t j = 0; j < nd; ++j) out.theta[j] = 2.0 * M_PI * double(j) / double(nd);
  // θ first on every original ring, then ln r on every column.
  std::vector<double> fine(f.r.size() * nd);
  std::vector<double> a, b;
  for (size_t i = 0; i < f.r.size(); ++i) {
    const double* ring = &f.values[i * nt];
    if (mult == 1) {
      std::copy(ring, ring + nt, &fine[i * nd]);
      continue;
    }
    fourier(ring, nt, a, b);
    for (size_t j = 0; j < nd; ++j)
      fine[i * nd + j] = (j % mult == 0) ? ring[j / mult] : trig_eval(a, b, nt, out.theta[j]);
  }
  out.values.assign(radii.size() * nd, 0.0);
  for (size_t q = 0; q < radii.size(); ++q) {
    int i0 = 0;
    double w[4];
    cubic_weights(f.r, radii[q], i0, w);
    for (int k = 0; k < 4; ++k) {
      if (w[k] == 0.0) continue;
      const double* src = &fine[size_t(i0 + k) * nd];
      double* dst = &out.values[q * nd];
      for (size_t j = 0; j < nd; ++j) dst[j] += w[k] * src[j];
    }
  }
  return out;
}

double polar_value(const PolarField& f, double r, double theta) {
  check(f);
  const size_t nt = f.theta.size();
  int i0 = 0;
  double w[4];
  cubic_weights(f.r, r, i0, w);
  std::vector<double> a, b;
  double s = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (w[k] == 0.0) continue;
    fourier(&f.values[size_t(i0 + k) * nt], nt, a, b);
    s += w[k] * trig_eval(a, b, nt, theta);
  }
  return s;
}

}  // namespace magnus
