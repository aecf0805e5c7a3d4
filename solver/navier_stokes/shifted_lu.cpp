#include "solver/navier_stokes/shifted_lu.hpp"

#include <umfpack.h>

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

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

/// J x with the real matrix applied to the real and imaginary parts.
cvec apply_j(const EigenProblem& ep, const cvec& x) {
  std::vector<double> re(x.size()), im(x.size());
  for (size_t q = 0; q < x.size(); ++q) re[q] = x[q].real(), im[q] = x[q].imag();
  const std::vector<double> jr = ep.multiply(re), ji = ep.multiply(im);
  cvec y(x.size());
  for (size_t q = 0; q < x.size(); ++q) y[q] = {jr[q], ji[q]};
  return y;
}

}  // namespace

std::vector<double> EigenProblem::multiply(const std::vector<double>& x) const {
  if (x.size() != size_t(n)) throw std::invalid_argument("EigenProblem::multiply: wrong size");
  std::vector<double> y(x.size(), 0.0);
  multiply_add(x, 1.0, y);
  return y;
}

void EigenProblem::multiply_add(const std::vector<double>& x, double c, std::vector<double>& y) const {
  for (long col = 0; col < n; ++col) {
    const double xc = c * x[size_t(col)];
    if (xc == 0.0) continue;
    for (long t = Ap[size_t(col)]; t < Ap[size_t(col) + 1]; ++t) y[size_t(Ai[size_t(t)])] += Ax[size_t(t)] * xc;
  }
}

void shifted_matrix(const EigenProblem& ep, cplx sigma, std::vector<long>& Ap, std::vector<long>& Ai,
                    std::vector<double>& Ax, std::vector<double>& Az) {
  const long n = ep.n;
  const std::vector<long>&Jp = ep.Ap, &Ji = ep.Ai;
  const std::vector<double>& Jx = ep.Ax;
  const std::vector<double>& m = ep.m;
  Ap.assign(size_t(n) + 1, 0);
  Ai.clear(), Ax.clear(), Az.clear();
  for (long c = 0; c < n; ++c) {
    bool diag = false;
    for (long t = Jp[size_t(c)]; t < Jp[size_t(c) + 1]; ++t) {
      const long r = Ji[size_t(t)];
      if (!diag && m[size_t(c)] != 0.0 && r >= c) {
        if (r > c) Ai.push_back(c), Ax.push_back(0.0), Az.push_back(0.0);
        diag = true;
      }
      Ai.push_back(r), Ax.push_back(Jx[size_t(t)]), Az.push_back(0.0);
    }
    if (!diag && m[size_t(c)] != 0.0) Ai.push_back(c), Ax.push_back(0.0), Az.push_back(0.0);
    Ap[size_t(c) + 1] = long(Ai.size());
    if (m[size_t(c)] == 0.0) continue;
    for (long t = Ap[size_t(c)]; t < Ap[size_t(c) + 1]; ++t)
      if (Ai[size_t(t)] == c) {
        Ax[size_t(t)] -= sigma.real() * m[size_t(c)];
        Az[size_t(t)] -= sigma.imag() * m[size_t(c)];
      }
  }
}

ShiftedLu::ShiftedLu(const EigenProblem& ep, cplx sigma, void** symbolic) {
  const long n = ep.n;
  shifted_matrix(ep, sigma, Ap_, Ai_, Ax_, Az_);
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_zl_defaults(control);
  // The problem's order (the grid's nested dissection, as for the real Jacobian: J − σM has J's pattern).
  // Searches at several shifts may start at once: the first makes the analysis, the others wait for it
  // (one lock for every search: an analysis takes about a second, a search tens).
  static std::mutex analysis;
  std::unique_lock<std::mutex> lock(analysis);
  if (!*symbolic) {
    const long st = symbolic_in_grid_order(
        n, ep.order,
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
  lock.unlock();
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

ShiftedLu::~ShiftedLu() {
  if (numeric_) umfpack_zl_free_numeric(&numeric_);
}

cvec ShiftedLu::solve(const cvec& b) const {
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

/// ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖): the relative residual of an eigenpair of J x = λ M x.
double relative_residual(const EigenProblem& ep, cplx lambda, const cvec& x) {
  const cvec jx = apply_j(ep, x);
  const std::vector<double>& m = ep.m;
  double r2 = 0.0, mx = 0.0;
  for (size_t q = 0; q < x.size(); ++q) {
    r2 += std::norm(jx[q] - lambda * m[q] * x[q]);
    mx += std::norm(m[q] * x[q]);
  }
  return std::sqrt(r2) / (norm(jx) + std::abs(lambda) * std::sqrt(mx));
}

void accept_ritz_values(const EigenProblem& ep, const std::vector<RitzValue>& ritz, int want, double tol,
                        ShiftSearch& out) {
  out.found.clear();
  out.radius = 0.0;
  bool unbroken = true;
  int nearest_ok = 0;
  for (const RitzValue& rv : ritz) {
    if (std::abs(rv.mu) == 0.0) break;
    cvec x = rv.vector ? rv.vector() : cvec{};
    const cplx lambda = out.sigma + 1.0 / rv.mu;
    const double rel = x.empty() ? HUGE_VAL : relative_residual(ep, lambda, x);
    unbroken = unbroken && rel <= tol;
    if (unbroken) out.radius = 1.0 / std::abs(rv.mu), ++nearest_ok;
    if (rel <= tol) out.found.push_back({lambda, std::move(x), rel});
  }
  out.converged = nearest_ok >= want;
}

}  // namespace magnus
