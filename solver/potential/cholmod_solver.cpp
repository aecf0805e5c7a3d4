// General path: assemble the symmetric matrix with Eigen, factor it with SuiteSparse CHOLMOD.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "solver/potential/cholmod_solver.hpp"
#include "solver/potential/flow_solver.hpp"
#include "solver/memory.hpp"

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
  const long n_unknowns = op.unknowns();
  const long c_index = long(L) * n;  // the freestream constant C, if any
  auto idx = [n](int i, int j) { return long(i - 1) * n + ((j % n) + n) % n; };
  std::vector<Triplet> t;
  const bool exact = op.far_field == FarField::exact;
  t.reserve(size_t(n_unknowns) * (lower_only ? 5 : 9) + (exact ? size_t(n) * n : 2 * size_t(n) + 1));
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
  SpMat A(n_unknowns, n_unknowns);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

std::vector<long> nested_dissection(const DiscreteOperator& op) {
  const int n = op.n_theta, L = op.last_ring();
  const bool exact = op.far_field == FarField::exact;
  const int rings = exact ? L - 1 : L;  // exact: the outer ring is a clique, ordered last
  std::vector<long> order;
  order.reserve(size_t(op.unknowns()));
  auto node = [n](int i, int j) { return long(i - 1) * n + j; };
  // Rectangle [i0, i1) × [j0, j1) of rings × columns: halves first, their separator last.
  std::function<void(int, int, int, int)> dissect = [&](int i0, int i1, int j0, int j1) {
    const int ni = i1 - i0, nj = j1 - j0;
    if (ni <= 0 || nj <= 0) return;
    if (long(ni) * nj <= 64) {
      for (int i = i0; i < i1; ++i)
        for (int j = j0; j < j1; ++j) order.push_back(node(i, j));
      return;
    }
    if (nj >= ni) {
      const int jm = j0 + nj / 2;
      dissect(i0, i1, j0, jm);
      dissect(i0, i1, jm + 1, j1);
      for (int i = i0; i < i1; ++i) order.push_back(node(i, jm));
    } else {
      const int im = i0 + ni / 2;
      dissect(i0, im, j0, j1);
      dissect(im + 1, i1, j0, j1);
      for (int j = j0; j < j1; ++j) order.push_back(node(im, j));
    }
  };
  // A periodic annulus of rings [i0, i1): cut a ring while it is tall, else open it into two
  // rectangles along the radial lines j = 0 and j = n/2.
  std::function<void(int, int)> annulus = [&](int i0, int i1) {
    if (i1 <= i0) return;
    if (i1 - i0 > n / 2) {
      const int im = i0 + (i1 - i0) / 2;
      annulus(i0, im);
      annulus(im + 1, i1);
      for (int j = 0; j < n; ++j) order.push_back(node(im, j));
      return;
    }
    dissect(i0, i1, 1, n / 2);
    dissect(i0, i1, n / 2 + 1, n);
    for (int j : {0, n / 2})
      for (int i = i0; i < i1; ++i) order.push_back(node(i, j));
  };
  annulus(1, rings + 1);
  if (exact)
    for (int j = 0; j < n; ++j) order.push_back(node(L, j));
  else
    order.push_back(long(L) * n);  // C
  return order;
}

namespace {

/// CHOLMOD's workspace and a factor, freed together.
struct Cholmod {
  cholmod_common c;
  cholmod_factor* L = nullptr;
  Cholmod() { cholmod_l_start(&c); }
  ~Cholmod() {
    if (L) cholmod_l_free_factor(&L, &c);
    cholmod_l_finish(&c);
  }
};

class CholmodSolver final : public PsiSolver {
 public:
  CholmodSolver(const PolarGrid& grid, const DiscreteOperator& op, size_t max_bytes) : PsiSolver(grid, op) {
    double t0 = now_s();
    A_ = assemble_matrix(op);
    std::vector<long> perm = nested_dissection(op);
    double t1 = now_s();
    timing.assemble_s = t1 - t0;
    cholmod_sparse a = Eigen::viewAsCholmod(A_);
    a.stype = -1;  // the lower triangle holds the matrix
    chol_.c.nmethods = 1;
    chol_.c.method[0].ordering = CHOLMOD_GIVEN;
    chol_.c.postorder = 1;
    chol_.c.print = 0;
    chol_.L = cholmod_l_analyze_p(&a, perm.data(), nullptr, 0, &chol_.c);
    if (!chol_.L)
      throw std::runtime_error("CHOLMOD analysis failed (status " + std::to_string(chol_.c.status) + ")");
    // The symbolic factor knows the fill exactly: refuse before the numeric factorization allocates it.
    const size_t factor_bytes =
        chol_.L->is_super ? 8 * (chol_.L->xsize + chol_.L->ssize) : 16 * chol_.L->nzmax;
    check_memory(factor_bytes, max_bytes, "the cholmod factor");
    cholmod_l_factorize(&a, chol_.L, &chol_.c);
    if (chol_.c.status != CHOLMOD_OK || chol_.L->minor < chol_.L->n)
      throw std::runtime_error(
          "CHOLMOD factorization failed: the matrix is not positive definite "
          "(status " +
          std::to_string(chol_.c.status) + ", column " + std::to_string(chol_.L->minor) + ")");
    timing.factor_s = now_s() - t1;
  }

  std::vector<double> solve_unknowns(const std::vector<double>& rhs) override {
    std::vector<double> b = rhs;
    cholmod_dense bd = dense_view(b);
    cholmod_dense* x = cholmod_l_solve(CHOLMOD_A, chol_.L, &bd, &chol_.c);
    if (!x) throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(chol_.c.status) + ")");
    const double* xv = static_cast<const double*>(x->x);
    std::vector<double> out(xv, xv + rhs.size());
    cholmod_l_free_dense(&x, &chol_.c);
    return out;
  }

  Method method() const override { return Method::cholmod; }

 private:
  static cholmod_dense dense_view(std::vector<double>& v) {
    cholmod_dense d{};
    d.nrow = v.size();
    d.ncol = 1;
    d.nzmax = v.size();
    d.d = v.size();
    d.x = v.data();
    d.xtype = CHOLMOD_REAL;
    d.dtype = CHOLMOD_DOUBLE;
    return d;
  }

  SpMat A_;
  Cholmod chol_;
};

}  // namespace

std::unique_ptr<PsiSolver> make_cholmod_solver(const PolarGrid& grid, const DiscreteOperator& op,
                                               size_t max_bytes) {
  return std::make_unique<CholmodSolver>(grid, op, max_bytes);
}

}  // namespace magnus
