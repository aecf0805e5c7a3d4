#include "solver/gmres.hpp"

#include <cmath>

namespace magnus {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

double norm2(const std::vector<double>& a) { return std::sqrt(dot(a, a)); }

namespace {

/// Orthogonalise w against the basis V (modified Gram–Schmidt, twice), the coefficients into h[0…k].
void orthogonalise(const std::vector<std::vector<double>>& V, std::vector<double>& w, std::vector<double>& h) {
  for (int pass = 0; pass < 2; ++pass)
    for (size_t j = 0; j < V.size(); ++j) {
      const double c = dot(V[j], w);
      h[j] += c;
      for (size_t i = 0; i < w.size(); ++i) w[i] -= c * V[j][i];
    }
}

/// Apply the rotations so far to column h (size k + 2), then make the one that zeroes h[k + 1].
void rotate(std::vector<double>& h, std::vector<double>& cs, std::vector<double>& sn, int k) {
  for (int j = 0; j < k; ++j) {
    const double t = cs[j] * h[j] + sn[j] * h[j + 1];
    h[j + 1] = -sn[j] * h[j] + cs[j] * h[j + 1];
    h[j] = t;
  }
  const double r = std::hypot(h[k], h[k + 1]);
  cs[k] = r > 0.0 ? h[k] / r : 1.0;
  sn[k] = r > 0.0 ? h[k + 1] / r : 0.0;
  h[k] = r;
  h[k + 1] = 0.0;
}

}  // namespace

GmresResult gmres(const std::function<void(const std::vector<double>&, std::vector<double>&)>& apply,
                  const std::vector<double>& b, std::vector<double>& x, double tol, int max_iter) {
  GmresResult res;
  const size_t n = b.size();
  x.assign(n, 0.0);
  const double beta = norm2(b);
  if (!(beta > 0.0)) {
    res.converged = true;
    return res;
  }
  std::vector<std::vector<double>> V{b}, H;  // basis; columns of the rotated Hessenberg matrix
  for (double& v : V[0]) v /= beta;
  std::vector<double> g{beta}, cs, sn, w(n);
  int k = 0;
  for (; k < max_iter; ++k) {
    apply(V[size_t(k)], w);
    std::vector<double> h(size_t(k) + 2, 0.0);
    orthogonalise(V, w, h);
    const double wn = norm2(w);  // rotate() overwrites h[k + 1]: keep the norm for the next basis vector
    h[size_t(k) + 1] = wn;
    cs.push_back(0.0), sn.push_back(0.0), g.push_back(0.0);
    rotate(h, cs, sn, k);
    g[size_t(k) + 1] = -sn[size_t(k)] * g[size_t(k)];
    g[size_t(k)] *= cs[size_t(k)];
    H.push_back(h);
    res.residual = std::fabs(g[size_t(k) + 1]) / beta;
    if (res.residual <= tol || !(wn > 1e-300)) {
      ++k;
      break;
    }
    for (double& v : w) v /= wn;
    V.push_back(w);
  }
  res.iterations = k;
  res.converged = res.residual <= tol;
  // Back substitution R y = g, then x = V y.
  std::vector<double> y(size_t(k), 0.0);
  for (int i = k - 1; i >= 0; --i) {
    double s = g[size_t(i)];
    for (int j = i + 1; j < k; ++j) s -= H[size_t(j)][size_t(i)] * y[size_t(j)];
    y[size_t(i)] = H[size_t(i)][size_t(i)] != 0.0 ? s / H[size_t(i)][size_t(i)] : 0.0;
  }
  for (int j = 0; j < k; ++j)
    for (size_t i = 0; i < n; ++i) x[i] += y[size_t(j)] * V[size_t(j)][i];
  return res;
}

}  // namespace magnus
