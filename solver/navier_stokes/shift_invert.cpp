#include "solver/navier_stokes/shift_invert.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "solver/navier_stokes/shifted_lu.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;
using cvec = std::vector<cplx>;

/// Swaps the adjacent diagonal entries i, i+1 of the upper-triangular T (T ← GᴴTG, Q ← QG with G a plane
/// rotation whose first column is T's eigenvector for T(i+1, i+1)): the Schur form stays a Schur form.
void swap_schur(Eigen::MatrixXcd& T, Eigen::MatrixXcd& Q, int i) {
  const cplx x1 = T(i, i + 1), x2 = T(i + 1, i + 1) - T(i, i);
  const double r = std::hypot(std::abs(x1), std::abs(x2));
  if (r == 0.0) return;
  const cplx c = x1 / r, s = x2 / r;
  const Eigen::Index n = T.cols();
  for (Eigen::Index j = 0; j < n; ++j) {  // rows i, i+1 by Gᴴ = [[c̄, s̄], [−s, c]]
    const cplx a = T(i, j), b = T(i + 1, j);
    T(i, j) = std::conj(c) * a + std::conj(s) * b, T(i + 1, j) = -s * a + c * b;
  }
  auto cols = [&](Eigen::MatrixXcd& A) {  // columns i, i+1 by G = [[c, −s̄], [s, c̄]]
    for (Eigen::Index r2 = 0; r2 < A.rows(); ++r2) {
      const cplx a = A(r2, i), b = A(r2, i + 1);
      A(r2, i) = a * c + b * s, A(r2, i + 1) = -a * std::conj(s) + b * std::conj(c);
    }
  };
  cols(T), cols(Q);
  T(i + 1, i) = 0.0;
}

/// The eigenvector of the upper-triangular T for its diagonal entry T(r, r), entries 0…r (back substitution).
Eigen::VectorXcd triangular_eigenvector(const Eigen::MatrixXcd& T, int r) {
  Eigen::VectorXcd y = Eigen::VectorXcd::Zero(r + 1);
  y(r) = 1.0;
  const cplx t = T(r, r);
  for (int i = r - 1; i >= 0; --i) {
    cplx d = T(i, i) - t;
    if (std::abs(d) < 1e-14 * std::abs(t)) d = 1e-14 * std::abs(t);  // a repeated Ritz value
    y(i) = -T.block(i, i + 1, 1, r - i).transpose().cwiseProduct(y.segment(i + 1, r - i)).sum() / d;
  }
  return y / y.norm();
}

/// Orders the Schur form T = QᴴHQ so that its diagonal (the Ritz values μ) falls in |μ| from the largest.
void sort_schur(Eigen::MatrixXcd& T, Eigen::MatrixXcd& Q) {
  const int k = int(T.rows());
  for (int pos = 0; pos < k; ++pos) {
    int best = pos;
    for (int j = pos + 1; j < k; ++j)
      if (std::abs(T(j, j)) > std::abs(T(best, best))) best = j;
    for (int j = best - 1; j >= pos; --j) swap_schur(T, Q, j);
  }
}

/// The Arnoldi basis V and the projected matrix H of A·V_k = V_k·H_k + v_k·h_k (Krylov–Schur form: H's
/// leading block is upper triangular after a restart, with a full row below it).
struct Krylov {
  Eigen::MatrixXcd V, H;
  int m = 0;  ///< columns kept (the next one to expand)
};

/// Extends the factorisation to k columns (classical Gram–Schmidt twice); false on an invariant subspace
/// (then k is lowered to the columns built).
template <class Op>
bool expand(Krylov& K, int& k, const Op& op) {
  const Eigen::Index n = K.V.rows();
  cvec col(static_cast<size_t>(n));
  for (int j = K.m; j < k; ++j) {
    for (Eigen::Index q = 0; q < n; ++q) col[size_t(q)] = K.V(q, j);
    const cvec wv = op(col);
    Eigen::VectorXcd w = Eigen::Map<const Eigen::VectorXcd>(wv.data(), n);
    for (int sweep = 0; sweep < 2; ++sweep) {
      const Eigen::VectorXcd h = K.V.leftCols(j + 1).adjoint() * w;
      w.noalias() -= K.V.leftCols(j + 1) * h;
      K.H.col(j).head(j + 1) += h;
    }
    const double beta = w.norm();
    K.H(j + 1, j) = beta;
    if (beta <= 1e-14 * K.H.col(j).norm()) {
      k = j + 1;
      return false;
    }
    K.V.col(j + 1) = w / beta;
  }
  return true;
}

}  // namespace

ShiftSearch shift_invert_arnoldi(const EigenProblem& ep, cplx sigma, int want, int krylov, int max_restarts,
                                 double tol, void** symbolic, std::mt19937& rng, const cvec* first) {
  ShiftSearch out;
  out.sigma = sigma;
  const ShiftedLu lu(ep, sigma, symbolic);
  const size_t n = size_t(ep.n);
  const std::vector<double>& m = ep.m;
  auto op = [&](const cvec& v) {
    ++out.solves;
    cvec b(n);
    for (size_t q = 0; q < n; ++q) b[q] = m[q] * v[q];
    return lu.solve(b);
  };
  std::normal_distribution<double> gauss;
  cvec start(n);
  if (first && first->size() == n)
    start = *first;
  else
    for (auto& z : start) z = {gauss(rng), gauss(rng)};
  start = op(start);  // in the range of the operator: no component along the infinite eigenvalues
  const int k_max = krylov_vectors(krylov, want);
  const int keep = std::min(k_max - 10, want + k_max / 4);  // Ritz vectors kept at a restart
  Krylov K;
  K.V.resize(Eigen::Index(n), k_max + 1);
  K.H = Eigen::MatrixXcd::Zero(k_max + 1, k_max);
  const double s0 = Eigen::Map<const Eigen::VectorXcd>(start.data(), Eigen::Index(n)).norm();
  if (!(s0 > 0.0)) return out;
  for (size_t q = 0; q < n; ++q) K.V(Eigen::Index(q), 0) = start[q] / s0;
  for (;; ++out.restarts) {
    int k = k_max;
    const bool full = expand(K, k, op);
    // Ritz values μ of H_k, nearest σ (largest |μ|) first, and the Schur vectors that span them.
    Eigen::ComplexSchur<Eigen::MatrixXcd> cs(K.H.topLeftCorner(k, k));
    Eigen::MatrixXcd T = cs.matrixT(), Q = cs.matrixU();
    sort_schur(T, Q);
    // Test the nearest Ritz pairs on J itself, nearest first (the disk of `radius`; farther ones that pass
    // are kept too).
    std::vector<RitzValue> ritz;
    for (int r = 0; r < std::min(k, ritz_tested(want)); ++r)
      ritz.push_back({T(r, r), [&, r] {
                        const Eigen::VectorXcd xv =
                            K.V.leftCols(k) * (Q.leftCols(r + 1) * triangular_eigenvector(T, r));
                        return cvec(xv.data(), xv.data() + xv.size());
                      }});
    accept_ritz_values(ep, ritz, want, tol, out);
    if (out.converged || !full || out.restarts >= max_restarts) break;
    // Krylov–Schur restart: keep the `keep` nearest Schur vectors, A·(V Q_p) = (V Q_p)·T_p + v_k·(h_k Q_p).
    const Eigen::MatrixXcd Vp = K.V.leftCols(k) * Q.leftCols(keep);
    const Eigen::RowVectorXcd b = K.H.row(k).head(k) * Q.leftCols(keep);
    K.V.col(keep) = K.V.col(k);
    K.V.leftCols(keep) = Vp;
    K.H.setZero();
    K.H.topLeftCorner(keep, keep) = T.topLeftCorner(keep, keep).triangularView<Eigen::Upper>();
    K.H.row(keep).head(keep) = b;
    K.m = keep;
  }
  return out;
}

}  // namespace magnus
