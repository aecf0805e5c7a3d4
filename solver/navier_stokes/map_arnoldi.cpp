// Arnoldi on a linear map given as a product (map_arnoldi.hpp).
#include "solver/navier_stokes/map_arnoldi.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <stdexcept>

namespace magnus {

namespace {

/// The Ritz pairs of the k × k Hessenberg H (H(k, k − 1) the next subdiagonal), largest |μ| first, with
/// their vectors y in the Krylov basis.
void ritz_pairs(const Eigen::MatrixXd& H, int k, std::vector<MapRitz>& ritz, std::vector<Eigen::VectorXcd>& y) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(H.topLeftCorner(k, k));
  std::vector<int> order(static_cast<size_t>(k));
  for (int j = 0; j < k; ++j) order[size_t(j)] = j;
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return std::abs(es.eigenvalues()(a)) > std::abs(es.eigenvalues()(b)); });
  ritz.clear(), y.clear();
  for (int j : order) {
    const Eigen::VectorXcd v = es.eigenvectors().col(j);
    ritz.push_back({es.eigenvalues()(j), std::abs(H(k, k - 1) * v(k - 1)) / v.norm()});
    y.push_back(v / v.norm());
  }
}

}  // namespace

MapArnoldiResult map_arnoldi(const std::function<std::vector<double>(const std::vector<double>&)>& P, size_t n,
                             const MapArnoldiOptions& o,
                             const std::function<bool(const std::vector<MapRitz>&)>& done) {
  if (n == 0 || o.krylov < 1) throw std::invalid_argument("map_arnoldi: needs n > 0 and at least one vector");
  MapArnoldiResult res;
  const int m = o.krylov;
  Eigen::MatrixXd V(Eigen::Index(n), m + 1), H = Eigen::MatrixXd::Zero(m + 1, m);
  std::vector<double> v = o.start;
  if (v.size() != n) {
    std::mt19937 rng(o.seed);
    std::normal_distribution<double> gauss;
    v.resize(n);
    for (double& z : v) z = gauss(rng);
  }
  v = P(v), ++res.products;
  Eigen::Map<Eigen::VectorXd> vm(v.data(), Eigen::Index(n));
  V.col(0) = vm / vm.norm();
  std::vector<Eigen::VectorXcd> y;
  int k = 0;
  while (k < m) {
    std::vector<double> x(V.col(k).data(), V.col(k).data() + n);
    std::vector<double> w = P(x);
    ++res.products;
    Eigen::Map<Eigen::VectorXd> wm(w.data(), Eigen::Index(n));
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd h = V.leftCols(k + 1).transpose() * wm;
      wm -= V.leftCols(k + 1) * h;
      H.col(k).head(k + 1) += h;
    }
    H(k + 1, k) = wm.norm();
    ++k;
    if (!(H(k, k - 1) > 1e-14 * H.col(k - 1).head(k).norm())) break;
    V.col(k) = wm / H(k, k - 1);
    if (k < o.min_vectors || !done) continue;
    ritz_pairs(H, k, res.ritz, y);
    if (done(res.ritz)) break;
  }
  ritz_pairs(H, k, res.ritz, y);
  const Eigen::VectorXd x = V.leftCols(k) * y.front().real();
  res.leading.assign(x.data(), x.data() + n);
  return res;
}

}  // namespace magnus
