// General path: assemble the symmetric matrix with Eigen, factor it with SuiteSparse CHOLMOD.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <cmath>
#include <stdexcept>

#include "solver/cholmod_solver.hpp"
#include "solver/flow_solver.hpp"

namespace magnus {

namespace {

using SpMat = SparseMatrix;
using Triplet = Eigen::Triplet<double, long>;

/// Circulant row c_m = (1/n)·Σ_k e_k cos(k m Δθ) of the eliminated exterior (k over all n modes).
std::vector<double> exterior_circulant(const DiscreteOperator& op) {
  const int n = op.n_theta;
  std::vector<double> e(n);
  for (int k = 0; k < n; ++k) e[k] = op.exterior(k <= n / 2 ? k : n - k);
  std::vector<double> c(n, 0.0);
  for (int m = 0; m < n; ++m) {
    double s = 0.0;
    for (int k = 0; k < n; ++k) s += e[k] * std::cos(2.0 * M_PI * double((long(k) * m) % n) / n);
    c[m] = s / n;
  }
  return c;
}

}  // namespace

SpMat assemble_matrix(const DiscreteOperator& op, bool lower_only) {
  const int n = op.n_theta, L = op.last_ring();
  const long N = op.unknowns();
  const long c_index = long(L) * n;  // the freestream constant C, if any
  auto idx = [n](int i, int j) { return long(i - 1) * n + ((j % n) + n) % n; };
  std::vector<Triplet> t;
  const bool exact = op.far_field == FarField::exact;
  t.reserve(size_t(N) * (lower_only ? 5 : 9) + (exact ? size_t(n) * n : 2 * size_t(n) + 1));
  // Each row is built from its own equation; symmetry is a property of the stencil, not imposed here.
  auto add = [&t, lower_only](long row, long col, double v) {
    if (v != 0.0 && (!lower_only || col <= row)) t.emplace_back(row, col, v);
  };
  for (int i = 1; i <= L; ++i) {
    const RingStencil& s = op.ring[i];
    for (int j = 0; j < n; ++j) {
      const long row = idx(i, j);
      for (int d = -1; d <= 1; ++d) {
        const int ii = i + d;
        if (ii < 1) continue;  // ψ = 0 on the body
        if (ii > L) {          // the outer ring: C (freestream) or the exterior block (exact)
          if (!exact) add(row, c_index, s.a[d + 1] + 2.0 * s.b[d + 1]);
          continue;
        }
        add(row, idx(ii, j), s.a[d + 1]);
        add(row, idx(ii, j + 1), s.b[d + 1]);
        add(row, idx(ii, j - 1), s.b[d + 1]);
      }
    }
  }
  if (!exact) {
    // Circulation row: n·w·C − w·Σ_j ψ_{L,j} = −Γ − w·Σ_j g_j.
    add(c_index, c_index, double(n) * op.w[L]);
    for (int j = 0; j < n; ++j) add(c_index, idx(L, j), -op.w[L]);
  } else {
    const std::vector<double> c = exterior_circulant(op);
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l) add(idx(L, j), idx(L, l), c[size_t((j - l + n) % n)]);
  }
  SpMat A(N, N);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

namespace {

class CholmodSolver final : public PsiSolver {
 public:
  CholmodSolver(const PolarGrid& grid, const DiscreteOperator& op) : PsiSolver(grid, op) {
    double t0 = now_s();
    A_ = assemble_matrix(op);
    double t1 = now_s();
    timing.assemble_s = t1 - t0;
    llt_.analyzePattern(A_);
    llt_.factorize(A_);
    if (llt_.info() != Eigen::Success)
      throw std::runtime_error("CHOLMOD factorization failed: the matrix is not positive definite "
                               "(status " + std::to_string(llt_.cholmod().status) + ")");
    timing.factor_s = now_s() - t1;
  }

  std::vector<double> solve_unknowns(const std::vector<double>& rhs) override {
    const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), long(rhs.size()));
    Eigen::VectorXd x = llt_.solve(b);
    if (llt_.info() != Eigen::Success) throw std::runtime_error("CHOLMOD solve failed");
    return std::vector<double>(x.data(), x.data() + x.size());
  }

  Method method() const override { return Method::cholmod; }

 private:
  SpMat A_;
  Eigen::CholmodSupernodalLLT<SpMat, Eigen::Lower> llt_;
};

}  // namespace

std::unique_ptr<PsiSolver> make_cholmod_solver(const PolarGrid& grid, const DiscreteOperator& op) {
  return std::make_unique<CholmodSolver>(grid, op);
}

}  // namespace magnus
