// One shift's search by ARPACK-ng instead of the hand-written Krylov–Schur Arnoldi: the implicitly restarted
// Arnoldi method in complex arithmetic (znaupd/zneupd) driven by reverse communication, mode 1 on
// OP = (J − σM)⁻¹M with the same complex LU, which = "LM" (the Ritz values μ of largest modulus are the
// eigenvalues λ = σ + 1/μ nearest σ).
#include <arpack/arpack.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "solver/navier_stokes/shift_invert.hpp"
#include "solver/navier_stokes/shifted_lu.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;
using cvec = std::vector<cplx>;

/// ARPACK keeps its state between reverse-communication calls in Fortran SAVE variables: one search at a
/// time in the process (the S(Re, α) map computes rows in threads).
std::mutex arpack_mutex;

/// ARPACK's own workspace for n unknowns and ncv Arnoldi vectors (sizes from znaupd's documentation).
struct ArpackWork {
  ArpackWork(a_int n, a_int ncv)
      : v(size_t(n) * size_t(ncv)), workd(3 * size_t(n)), workl(size_t(3 * ncv * ncv + 5 * ncv)),
        rwork(size_t(ncv)) {}
  cvec v, workd, workl;
  std::vector<double> rwork;
  a_int iparam[11] = {}, ipntr[14] = {};
};

/// The Ritz values of the last Arnoldi factorisation that ARPACK did not count converged (its test
/// |bound| ≤ tol·max(ε^{2/3}, |μ|)): they can only end the disk. No vectors.
std::vector<RitzValue> unconverged_ritz_values(const ArpackWork& w, a_int ncv, double tol) {
  std::vector<RitzValue> out;
  const double eps23 = std::pow(DBL_EPSILON, 2.0 / 3.0);
  for (a_int j = 0; j < ncv; ++j) {
    const cplx mu = w.workl[size_t(w.ipntr[5] - 1 + j)], bound = w.workl[size_t(w.ipntr[7] - 1 + j)];
    if (std::abs(bound) > tol * std::max(eps23, std::abs(mu))) out.push_back({mu, {}});
  }
  return out;
}

}  // namespace

ShiftSearch shift_invert_arpack(const EigenProblem& ep, cplx sigma, int want, int krylov, int max_restarts,
                                double tol, double arpack_tol, void** symbolic, std::mt19937& rng) {
  ShiftSearch out;
  out.sigma = sigma;
  const ShiftedLu lu(ep, sigma, symbolic);
  const a_int n = a_int(ep.n);
  const std::vector<double>& m = ep.m;
  const size_t nn = size_t(n);
  auto op = [&](const cplx* x, cplx* y) {  // y = (J − σM)⁻¹ M x
    ++out.solves;
    cvec b(nn);
    for (size_t q = 0; q < nn; ++q) b[q] = m[q] * x[q];
    const cvec r = lu.solve(b);
    std::copy(r.begin(), r.end(), y);
  };
  std::normal_distribution<double> gauss;
  cvec start(nn), resid(nn);
  for (auto& z : start) z = {gauss(rng), gauss(rng)};
  op(start.data(), resid.data());  // in the range of the operator: no component along the infinite eigenvalues
  const a_int ncv = std::min<a_int>(n, krylov_vectors(krylov, want));
  const a_int nev = std::min<a_int>(ncv - 2, ritz_tested(want));
  ArpackWork w(n, ncv);
  w.iparam[0] = 1;                 // exact shifts
  w.iparam[2] = max_restarts;  // it stops after the (max_restarts + 1)th factorisation (iter > mxiter)
  w.iparam[3] = 1;                 // block size
  w.iparam[6] = 1;                 // mode 1: OP x = μ x, the standard inner product
  const a_int lworkl = a_int(w.workl.size());
  a_int ido = 0, info = 1;  // info 1: resid is the start vector
  const std::lock_guard<std::mutex> lock(arpack_mutex);
  for (;;) {
    arpack::naupd(ido, arpack::bmat::identity, n, arpack::which::largest_magnitude, nev, arpack_tol, resid.data(),
                  ncv, w.v.data(), n, w.iparam, w.ipntr, w.workd.data(), w.workl.data(), lworkl, w.rwork.data(),
                  info);
    if (ido != -1 && ido != 1) break;
    op(&w.workd[size_t(w.ipntr[0] - 1)], &w.workd[size_t(w.ipntr[1] - 1)]);
  }
  out.restarts = std::max(0, int(w.iparam[2]) - 1);
  // info 1 (the iteration limit) and 3 (no shift could be applied) leave the converged part usable.
  if (info < 0)
    throw std::runtime_error("leading_eigenvalues: ARPACK znaupd failed (info " + std::to_string(info) + ")");
  std::vector<RitzValue> ritz = unconverged_ritz_values(w, ncv, arpack_tol);
  const a_int nconv = w.iparam[4];
  if (nconv > 0) {
    cvec d(size_t(nev) + 1), workev(2 * size_t(ncv));
    std::vector<a_int> select(static_cast<size_t>(ncv), 0);
    // The Ritz vectors overwrite the first nconv columns of V (allowed by zneupd).
    arpack::neupd(1, arpack::howmny::ritz_vectors, select.data(), d.data(), w.v.data(), n, cplx(0.0), workev.data(),
                  arpack::bmat::identity, n, arpack::which::largest_magnitude, nev, arpack_tol, resid.data(), ncv,
                  w.v.data(), n, w.iparam, w.ipntr, w.workd.data(), w.workl.data(), lworkl, w.rwork.data(), info);
    if (info != 0)
      throw std::runtime_error("leading_eigenvalues: ARPACK zneupd failed (info " + std::to_string(info) + ")");
    for (a_int j = 0; j < nconv; ++j)
      ritz.push_back({d[size_t(j)], [&w, nn, j] {
                        const auto col = w.v.begin() + std::ptrdiff_t(size_t(j) * nn);
                        return cvec(col, col + std::ptrdiff_t(nn));
                      }});
  }
  std::stable_sort(ritz.begin(), ritz.end(),
                   [](const RitzValue& a, const RitzValue& b) { return std::abs(a.mu) > std::abs(b.mu); });
  if (ritz.size() > size_t(nev)) ritz.resize(size_t(nev));
  accept_ritz_values(ep, ritz, want, tol, out);
  return out;
}

}  // namespace magnus
