#include "solver/navier_stokes/shift_invert.hpp"

#include <umfpack.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/lu.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;
using cvec = std::vector<cplx>;

double norm(const cvec& v) {
  double s = 0.0;
  for (const cplx& z : v) s += std::norm(z);
  return std::sqrt(s);
}

/// J − σM in UMFPACK's split complex form, factored; solves (J − σM) y = b.
class ShiftedLu {
 public:
  ShiftedLu(const SteadyJacobian& jac, const std::vector<double>& m, cplx sigma, void** symbolic) {
    // J's pattern with a diagonal entry in every column that M touches (the Γ_R column has none in J).
    const long n = jac.size();
    const std::vector<long>&Jp = jac.col_ptr(), &Ji = jac.row_index();
    const std::vector<double>& Jx = jac.values();
    Ap_.assign(size_t(n) + 1, 0);
    for (long c = 0; c < n; ++c) {
      bool diag = false;
      for (long t = Jp[size_t(c)]; t < Jp[size_t(c) + 1]; ++t) {
        const long r = Ji[size_t(t)];
        if (!diag && m[size_t(c)] != 0.0 && r >= c) {
          if (r > c) Ai_.push_back(c), Ax_.push_back(0.0), Az_.push_back(0.0);
          diag = true;
        }
        Ai_.push_back(r), Ax_.push_back(Jx[size_t(t)]), Az_.push_back(0.0);
      }
      if (!diag && m[size_t(c)] != 0.0) Ai_.push_back(c), Ax_.push_back(0.0), Az_.push_back(0.0);
      Ap_[size_t(c) + 1] = long(Ai_.size());
      if (m[size_t(c)] == 0.0) continue;
      for (long t = Ap_[size_t(c)]; t < Ap_[size_t(c) + 1]; ++t)
        if (Ai_[size_t(t)] == c) {
          Ax_[size_t(t)] -= sigma.real() * m[size_t(c)];
          Az_[size_t(t)] -= sigma.imag() * m[size_t(c)];
        }
    }
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_zl_defaults(control);
    // The grid's nested-dissection order, as for the real Jacobian (J − σM has J's pattern).
    if (!*symbolic) {
      const long st = symbolic_in_grid_order(
          n,
          grid_order(jac.grid().n_r, jac.grid().n_theta, false, advection_reach(jac.params().advection_order),
                     advection_reach(jac.params().advection_order_xi)),
          [&](const double* ctl, const long* q) {
            double inf[UMFPACK_INFO];
            return q ? umfpack_zl_qsymbolic(n, n, Ap_.data(), Ai_.data(), Ax_.data(), Az_.data(), q, symbolic,
                                            ctl, inf)
                     : umfpack_zl_symbolic(n, n, Ap_.data(), Ai_.data(), Ax_.data(), Az_.data(), symbolic,
                                           ctl, inf);
          });
      if (st != UMFPACK_OK) {
        *symbolic = nullptr;
        throw std::runtime_error("leading_eigenvalues: UMFPACK symbolic analysis failed (status " +
                                 std::to_string(st) + ")");
      }
    }
    const SingleThreadBlas one_thread;
    const long st = umfpack_zl_numeric(Ap_.data(), Ai_.data(), Ax_.data(), Az_.data(), *symbolic, &numeric_,
                                       control, info);
    if (st != UMFPACK_OK) {
      if (numeric_) umfpack_zl_free_numeric(&numeric_);
      throw std::runtime_error("leading_eigenvalues: UMFPACK factorisation of J − σM failed (status " +
                               std::to_string(st) +
                               (st == UMFPACK_WARNING_singular_matrix ? ": singular" : "") + ")");
    }
  }
  ~ShiftedLu() {
    if (numeric_) umfpack_zl_free_numeric(&numeric_);
  }
  ShiftedLu(const ShiftedLu&) = delete;
  ShiftedLu& operator=(const ShiftedLu&) = delete;

  /// y = (J − σM)⁻¹ b.
  cvec solve(const cvec& b) const {
    const size_t n = b.size();
    std::vector<double> bx(n), bz(n), yx(n), yz(n);
    for (size_t q = 0; q < n; ++q) bx[q] = b[q].real(), bz[q] = b[q].imag();
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_zl_defaults(control);
    // No iterative refinement: Arnoldi needs (J − σM)⁻¹ only to the accuracy its residual test checks, and
    // refinement cost two more solves (and a residual) for each of the few hundred solves per state.
    control[UMFPACK_IRSTEP] = 0;
    const long st = umfpack_zl_solve(UMFPACK_A, Ap_.data(), Ai_.data(), Ax_.data(), Az_.data(), yx.data(),
                                     yz.data(), bx.data(), bz.data(), numeric_, control, info);
    if (st != UMFPACK_OK)
      throw std::runtime_error("leading_eigenvalues: UMFPACK solve failed (status " + std::to_string(st) +
                               ")");
    cvec y(n);
    for (size_t q = 0; q < n; ++q) y[q] = {yx[q], yz[q]};
    return y;
  }

 private:
  std::vector<long> Ap_, Ai_;
  std::vector<double> Ax_, Az_;
  void* numeric_ = nullptr;
};

/// J x with the real matrix applied to the real and imaginary parts.
cvec apply_j(const SteadyJacobian& jac, const cvec& x) {
  std::vector<double> re(x.size()), im(x.size());
  for (size_t q = 0; q < x.size(); ++q) re[q] = x[q].real(), im[q] = x[q].imag();
  const std::vector<double> jr = jac.multiply(re), ji = jac.multiply(im);
  cvec y(x.size());
  for (size_t q = 0; q < x.size(); ++q) y[q] = {jr[q], ji[q]};
  return y;
}

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

/// ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖): the relative residual of an eigenpair of J x = λ M x.
double relative_residual(const SteadyJacobian& jac, const std::vector<double>& m, cplx lambda, const cvec& x) {
  const cvec jx = apply_j(jac, x);
  double r2 = 0.0, mx = 0.0;
  for (size_t q = 0; q < x.size(); ++q) {
    r2 += std::norm(jx[q] - lambda * m[q] * x[q]);
    mx += std::norm(m[q] * x[q]);
  }
  return std::sqrt(r2) / (norm(jx) + std::abs(lambda) * std::sqrt(mx));
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

ShiftSearch shift_invert_arnoldi(const SteadyJacobian& jac, const std::vector<double>& m, cplx sigma, int want,
                                 int krylov, int max_restarts, double tol, void** symbolic, std::mt19937& rng) {
  ShiftSearch out;
  out.sigma = sigma;
  const ShiftedLu lu(jac, m, sigma, symbolic);
  const size_t n = size_t(jac.size());
  auto op = [&](const cvec& v) {
    ++out.solves;
    cvec b(n);
    for (size_t q = 0; q < n; ++q) b[q] = m[q] * v[q];
    return lu.solve(b);
  };
  std::normal_distribution<double> gauss;
  cvec start(n);
  for (auto& z : start) z = {gauss(rng), gauss(rng)};
  start = op(start);  // in the range of the operator: no component along the infinite eigenvalues
  const int k_max = std::max(krylov, 2 * want + 10);
  const int keep = std::min(k_max - 10, want + k_max / 4);  // Ritz vectors kept at a restart
  Krylov K;
  K.V.resize(Eigen::Index(n), k_max + 1);
  K.H = Eigen::MatrixXcd::Zero(k_max + 1, k_max);
  const double s0 = norm(start);
  if (!(s0 > 0.0)) return out;
  for (size_t q = 0; q < n; ++q) K.V(Eigen::Index(q), 0) = start[q] / s0;
  for (;; ++out.restarts) {
    int k = k_max;
    const bool full = expand(K, k, op);
    // Ritz values μ of H_k, nearest σ (largest |μ|) first, and the Schur vectors that span them.
    Eigen::ComplexSchur<Eigen::MatrixXcd> cs(K.H.topLeftCorner(k, k));
    Eigen::MatrixXcd T = cs.matrixT(), Q = cs.matrixU();
    sort_schur(T, Q);
    // Test the nearest Ritz pairs on J itself, nearest first: everything nearer σ than the first that fails
    // is accepted (the disk of `radius`); farther ones that pass are kept too.
    out.found.clear();
    out.radius = 0.0;
    bool unbroken = true;
    int nearest_ok = 0;
    const int tests = std::min(k, 2 * want + 4);
    for (int r = 0; r < tests; ++r) {
      const cplx mu = T(r, r);
      if (std::abs(mu) == 0.0) break;
      const Eigen::VectorXcd xv = K.V.leftCols(k) * (Q.leftCols(r + 1) * triangular_eigenvector(T, r));
      cvec x(xv.data(), xv.data() + xv.size());
      const cplx lambda = sigma + 1.0 / mu;
      const double rel = relative_residual(jac, m, lambda, x);
      unbroken = unbroken && rel <= tol;
      if (unbroken) out.radius = 1.0 / std::abs(mu), ++nearest_ok;
      if (rel <= tol) out.found.push_back({lambda, std::move(x), rel});
    }
    out.converged = nearest_ok >= want;
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
