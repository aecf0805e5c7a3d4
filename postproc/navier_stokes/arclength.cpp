// Pseudo-arclength continuation (Keller) on an abstract F(x, λ) = 0, solved by bordering: the extended
// system [J  F_λ; tₓᵀW  t_λ] is never formed, each corrector step is two solves with J.
#include <algorithm>
#include <cmath>

#include "postproc/navier_stokes/continuation.hpp"

namespace magnus {

namespace {

double wdot(const ArclengthProblem& f, const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) s += (f.weight.empty() ? 1.0 : f.weight[i]) * a[i] * b[i];
  return s;
}

double rnorm(const ArclengthProblem& f, const std::vector<double>& r) {
  if (f.norm) return f.norm(r);
  double m = 0.0;
  for (double v : r) m = std::max(m, std::isfinite(v) ? std::fabs(v) : HUGE_VAL);
  return m;
}

}  // namespace

ArclengthPoint arclength_tangent(const ArclengthProblem& f, const std::vector<double>& x, double lambda,
                                 double towards, const ArclengthPoint* previous) {
  f.factor(x, lambda);
  std::vector<double> z = f.d_lambda(x, lambda);
  for (double& v : z) v = -v;
  z = f.solve(z);
  ArclengthPoint t;
  t.x = x;
  t.lambda = lambda;
  const double len = std::sqrt(wdot(f, z, z) + 1.0);
  t.tx.resize(z.size());
  for (size_t i = 0; i < z.size(); ++i) t.tx[i] = z[i] / len;
  t.tl = 1.0 / len;
  double sign = towards < 0.0 ? -1.0 : 1.0;
  if (previous) sign = wdot(f, t.tx, previous->tx) + t.tl * previous->tl < 0.0 ? -1.0 : 1.0;
  if (sign < 0.0) {
    for (double& v : t.tx) v = -v;
    t.tl = -t.tl;
  }
  return t;
}

bool arclength_step(const ArclengthProblem& f, const ArclengthPoint& from, double ds, double tol,
                    int max_iter, ArclengthPoint& to, int& iterations) {
  const size_t n = from.x.size();
  std::vector<double> x(n);
  for (size_t i = 0; i < n; ++i) x[i] = from.x[i] + ds * from.tx[i];
  double lambda = from.lambda + ds * from.tl;
  iterations = 0;
  for (;;) {
    const std::vector<double> r = f.residual(x, lambda);
    std::vector<double> dx(n);
    for (size_t i = 0; i < n; ++i) dx[i] = x[i] - from.x[i];
    const double g = wdot(f, from.tx, dx) + from.tl * (lambda - from.lambda) - ds;
    const double res = rnorm(f, r);
    if (!std::isfinite(res)) return false;
    if (res <= tol && std::fabs(g) <= tol * std::max(1.0, std::fabs(ds))) break;
    if (iterations >= max_iter) return false;
    ++iterations;
    // J a = −F, J b = −F_λ; δλ from the arclength row, δx = a + δλ b.
    f.factor(x, lambda);
    std::vector<double> a = f.solve(r), b = f.d_lambda(x, lambda);
    b = f.solve(b);
    for (size_t i = 0; i < n; ++i) a[i] = -a[i], b[i] = -b[i];
    const double den = wdot(f, from.tx, b) + from.tl;
    if (!(std::fabs(den) > 0.0)) return false;
    const double dl = (-g - wdot(f, from.tx, a)) / den;
    for (size_t i = 0; i < n; ++i) x[i] += a[i] + dl * b[i];
    lambda += dl;
  }
  to.x = std::move(x);
  to.lambda = lambda;
  return true;
}

}  // namespace magnus
