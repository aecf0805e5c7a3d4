#include "solver/ns_stability.hpp"

#include <umfpack.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "solver/arakawa.hpp"
#include "solver/ns_lu.hpp"
#include "solver/ns_newton.hpp"

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

struct Eigenpair {
  cplx lambda;  ///< 1/s
  cvec x;
  double shift_distance;  ///< |λ − σ|, 1/s
};

/// Shift-invert Arnoldi at σ (1/s): up to `count` accepted eigenpairs nearest σ. `solves` counts the solves
/// with J − σM.
std::vector<Eigenpair> arnoldi_at(const SteadyJacobian& jac, const std::vector<double>& m, cplx sigma,
                                  int count, const StabilityOptions& o, void** symbolic, std::mt19937& rng,
                                  int& solves) {
  const ShiftedLu lu(jac, m, sigma, symbolic);
  const size_t n = size_t(jac.size());
  auto op = [&](const cvec& v) {
    ++solves;
    cvec b(n);
    for (size_t q = 0; q < n; ++q) b[q] = m[q] * v[q];
    return lu.solve(b);
  };
  std::normal_distribution<double> gauss;
  cvec start(n);
  for (auto& z : start) z = {gauss(rng), gauss(rng)};
  start = op(start);  // in the range of the operator: no component along the infinite eigenvalues
  const int k_max = std::max(o.krylov, count + 10);
  std::vector<Eigenpair> found;
  // The basis as the columns of one matrix: the Gram–Schmidt projections and the Ritz vectors are then
  // matrix–vector products (vectorised), not loops over complex scalars.
  Eigen::MatrixXcd V(Eigen::Index(n), k_max + 1);
  for (int pass = 0; pass <= o.restarts; ++pass) {
    Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(k_max + 1, k_max);
    const double s0 = norm(start);
    if (!(s0 > 0.0)) break;
    for (size_t q = 0; q < n; ++q) V(Eigen::Index(q), 0) = start[q] / s0;
    int k = 0;
    cvec col(n);
    for (; k < k_max; ++k) {
      for (size_t q = 0; q < n; ++q) col[q] = V(Eigen::Index(q), k);
      const cvec wv = op(col);
      Eigen::VectorXcd w = Eigen::Map<const Eigen::VectorXcd>(wv.data(), Eigen::Index(n));
      // Classical Gram–Schmidt, twice (as stable as modified Gram–Schmidt twice).
      for (int sweep = 0; sweep < 2; ++sweep) {
        const Eigen::VectorXcd h = V.leftCols(k + 1).adjoint() * w;
        w.noalias() -= V.leftCols(k + 1) * h;
        H.col(k).head(k + 1) += h;
      }
      const double beta = w.norm();
      H(k + 1, k) = beta;
      if (beta <= 1e-14 * H.col(k).norm()) {
        ++k;
        break;
      }
      V.col(k + 1) = w / beta;
    }
    Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(H.topLeftCorner(k, k));
    std::vector<int> order(static_cast<size_t>(k));
    for (int i = 0; i < k; ++i) order[size_t(i)] = i;
    std::sort(order.begin(), order.end(),
              [&](int u, int v) { return std::abs(es.eigenvalues()(u)) > std::abs(es.eigenvalues()(v)); });
    cvec next(n, 0.0);  // kept pairs stay in `found`; a restart may find them again (merged later)
    // Check twice as many Ritz values as wanted: on a fine grid a cluster of damped far-field modes can sit
    // nearer the shift than the wake's pair.
    for (int r = 0; r < std::min(k, 2 * count + 4); ++r) {
      const cplx mu = es.eigenvalues()(order[size_t(r)]);
      if (std::abs(mu) == 0.0) continue;
      const Eigen::VectorXcd xv = V.leftCols(k) * es.eigenvectors().col(order[size_t(r)]);
      cvec x(xv.data(), xv.data() + xv.size());
      const cplx lambda = sigma + 1.0 / mu;
      cvec jx = apply_j(jac, x), res(n);
      double mx = 0.0;
      for (size_t q = 0; q < n; ++q) {
        res[q] = jx[q] - lambda * m[q] * x[q];
        mx += std::norm(m[q] * x[q]);
      }
      const double rel = norm(res) / (norm(jx) + std::abs(lambda) * std::sqrt(mx));
      if (rel <= o.tol) {
        found.push_back({lambda, std::move(x), std::abs(lambda - sigma)});
      } else {
        for (size_t q = 0; q < n; ++q) next[q] += x[q];
      }
    }
    // Done once a pass accepted any pair: a restart then mostly finds the same pairs again (at 11 points of
    // the map's grid and 2 of the default grid the first four eigenvalues came out the same with and
    // without it, in two thirds of the time). A pass that accepted none restarts (o.restarts times).
    if (!found.empty() || pass == o.restarts) break;
    if (norm(next) == 0.0) break;
    start = std::move(next);
  }
  return found;
}

}  // namespace

double stability_speed(const NsParams& p) {
  return p.U > 0.0 ? p.U : std::fabs(p.a * p.omega) > 0.0 ? std::fabs(p.a * p.omega) : p.nu / p.a;
}

std::optional<std::complex<double>> StabilityResult::leading_pair() const {
  for (const auto& l : eigenvalues)
    if (l.imag() > 0.0) return l;
  return std::nullopt;
}

double StabilityResult::strouhal() const {
  return eigenvalues.empty() ? 0.0 : std::fabs(eigenvalues.front().imag()) / (2.0 * M_PI);
}

StabilityResult leading_eigenvalues(const NsParams& p, const NsState& steady, int count) {
  return leading_eigenvalues(p, steady, count, StabilityOptions{});
}

StabilityResult leading_eigenvalues(const NsParams& p, const NsState& steady, int count,
                                    const StabilityOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (count < 1) throw std::invalid_argument("leading_eigenvalues: count must be ≥ 1");
  if (o.shifts.empty()) throw std::invalid_argument("leading_eigenvalues: no shifts");
  SteadyJacobian jac(p);
  const std::vector<double> x0 = jac.pack(steady);
  jac.factor(x0);  // assembles J at the state (its real LU is not used)
  const PolarGrid& g = jac.grid();
  const int nr = g.n_r, n = g.n_theta;
  const double h = jac.d_xi();
  std::vector<double> m(size_t(jac.size()), 0.0);
  for (int i = 1; i < nr - 1; ++i)
    for (int j = 0; j < n; ++j)
      m[2 * (size_t(i) * n + j) + 1] = jac.zeta_row_scale() * h * h * g.r[i] * g.r[i] / p.nu;
  // The stepper's outer ring: ζ_t = −(ψ_θ/R²)(ζ_N − ζ_{N−1})/h where the wake leaves (row s_ζ(ζ_N −
  // ζ_{N−1})), and dΓ_R/dt = the flux (row s_ζ·h/(2πν)·flux): dynamic rows, slow ones. Treated as algebraic
  // they would tie Γ_R to the tiny far-field vorticity at once, which the stepper does not.
  const double R = g.outer_radius();
  if (p.outer_vorticity == NsOuterVorticity::inflow_outflow)
    for (int j = 0; j < n; ++j) {
      const size_t base = size_t(nr - 1) * n;
      const double p_theta =
          (steady.psi[base + size_t((j + 1) % n)] - steady.psi[base + size_t((j + n - 1) % n)]) /
          (2.0 * g.d_theta);
      if (p_theta > 0.0) m[2 * (base + j) + 1] = -jac.zeta_row_scale() * h * R * R / p_theta;
    }
  m.back() = jac.zeta_row_scale() * h / (2.0 * M_PI * p.nu);
  const double unit = stability_speed(p) / (2.0 * p.a);  // U/D in 1/s

  StabilityResult res;
  std::vector<Eigenpair> all;
  void* symbolic = nullptr;
  std::mt19937 rng(o.seed);
  double reach = -1.0;
  try {
    for (const cplx& s : o.shifts) {
      std::vector<Eigenpair> f = arnoldi_at(jac, m, s * unit, count, o, &symbolic, rng, res.solves);
      double far = 0.0;
      for (const auto& e : f) far = std::max(far, e.shift_distance / unit);
      if (!f.empty()) reach = reach < 0.0 ? far : std::min(reach, far);
      for (auto& e : f) all.push_back(std::move(e));
    }
  } catch (...) {
    if (symbolic) umfpack_zl_free_symbolic(&symbolic);
    throw;
  }
  if (symbolic) umfpack_zl_free_symbolic(&symbolic);

  // Im λ ≥ 0 representatives, without repeats; then each complex one followed by its conjugate.
  std::vector<Eigenpair> uniq;
  for (auto& e : all) {
    if (e.lambda.imag() < 0.0) {
      e.lambda = std::conj(e.lambda);
      for (auto& z : e.x) z = std::conj(z);
    }
    bool seen = false;
    for (const auto& u : uniq)
      seen = seen || std::abs(u.lambda - e.lambda) <= 1e-6 * (unit + std::abs(e.lambda));
    if (!seen) uniq.push_back(std::move(e));
  }
  std::stable_sort(uniq.begin(), uniq.end(),
                   [](const Eigenpair& u, const Eigenpair& v) { return u.lambda.real() > v.lambda.real(); });
  for (const auto& e : uniq) {
    const cplx l = e.lambda / unit;
    const bool real = std::fabs(l.imag()) <= 1e-8 * (1.0 + std::abs(l));
    res.eigenvalues.push_back(real ? cplx(l.real(), 0.0) : l);
    if (!real) res.eigenvalues.push_back(std::conj(l));
  }
  if (res.eigenvalues.size() > size_t(count)) res.eigenvalues.resize(size_t(count));
  res.reach = std::max(reach, 0.0);
  if (!uniq.empty()) {
    const cvec& x = uniq.front().x;
    const size_t nodes = size_t(g.nodes());
    res.mode_psi.resize(nodes), res.mode_zeta.resize(nodes);
    double zmax = 0.0;
    size_t qmax = 0;
    for (size_t q = 0; q < nodes; ++q)
      if (std::abs(x[2 * q + 1]) > zmax) zmax = std::abs(x[2 * q + 1]), qmax = q;
    const cplx scale = zmax > 0.0 ? std::abs(x[2 * qmax + 1]) / x[2 * qmax + 1] / zmax : 1.0;
    for (size_t q = 0; q < nodes; ++q)
      res.mode_psi[q] = x[2 * q] * scale, res.mode_zeta[q] = x[2 * q + 1] * scale;
    res.mode_Gamma_R = x.back() * scale;
  }
  res.stable = !res.eigenvalues.empty() && res.eigenvalues.front().real() < 0.0;
  char buf[160];
  if (res.eigenvalues.empty()) {
    res.message = "no eigenvalue converged (shift-invert Arnoldi)";
  } else {
    std::snprintf(buf, sizeof buf, "%s: leading eigenvalue %.4g %+.4gi (U/D), growth rate %.4g, St %.4g",
                  res.stable ? "stable" : "unstable", res.eigenvalues.front().real(),
                  res.eigenvalues.front().imag(), res.growth_rate(), res.strouhal());
    res.message = buf;
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace magnus
