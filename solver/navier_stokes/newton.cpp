#include "solver/navier_stokes/newton.hpp"

#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/stages.hpp"

#include <umfpack.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace magnus {

namespace {

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

}  // namespace

SteadyJacobian::SteadyJacobian(const NsParams& p, bool mirror) : p_(p), mirror_(mirror) {
  NsOperator check(p, 1.0);  // the stepper's own parameter checks (and grid)
  grid_ = check.grid();
  h_ = check.d_xi();
  size_ = 2 * grid_.nodes() + 1;
  if (mirror && !(p.omega == 0.0 && p.U > 0.0))
    throw std::invalid_argument("SteadyJacobian: the mirror-symmetric half needs ω = 0 and U > 0");
  const double speed = p.U > 0.0                        ? p.U
                       : std::fabs(p.a * p.omega) > 0.0 ? std::fabs(p.a * p.omega)
                                                        : p.nu / p.a;
  s_psi_ = 1.0 / (speed * p.a);
  s_zeta_ = p.a / speed;
}

SteadyJacobian::~SteadyJacobian() {
  if (numeric_) umfpack_dl_free_numeric(&numeric_);
  if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
}

std::vector<double> SteadyJacobian::pack(const NsState& s) const {
  const size_t nodes = size_t(grid_.nodes());
  if (s.psi.size() != nodes || s.zeta.size() != nodes)
    throw std::invalid_argument("SteadyJacobian: the state does not match the grid (" +
                                std::to_string(nodes) + " nodes)");
  std::vector<double> x(static_cast<size_t>(size_));
  for (size_t q = 0; q < nodes; ++q) x[2 * q] = s.psi[q], x[2 * q + 1] = s.zeta[q];
  x.back() = s.Gamma_R;
  return x;
}

NsState SteadyJacobian::unpack(const std::vector<double>& x) const {
  const size_t nodes = size_t(grid_.nodes());
  NsState s;
  s.psi.resize(nodes), s.zeta.resize(nodes);
  for (size_t q = 0; q < nodes; ++q) s.psi[q] = x[2 * q], s.zeta[q] = x[2 * q + 1];
  s.Gamma_R = x.back();
  return s;
}

std::vector<double> SteadyJacobian::residual(const std::vector<double>& x) const {
  if (x.size() != size_t(size_)) throw std::invalid_argument("SteadyJacobian::residual: wrong size");
  const int nr = grid_.n_r, n = grid_.n_theta, iN = nr - 1;
  const double dth = grid_.d_theta, R = grid_.outer_radius();
  const double a2 = p_.a * p_.a, h = h_, hN = grid_.d_xi(iN - 1), q2N = (hN / dth) * (hN / dth);
  const NsState s = unpack(x);
  // The time step's stages without the time derivative: its advection, Laplacian and outer-ring flux.
  // Each ring's rows are scaled by h_i² (ring_width; the outer ring's: Δξ_{N−1/2}²).
  std::vector<double> N(size_t(nr) * n);
  advection_field(grid_, p_, s.psi.data(), s.zeta.data(), N.data());
  auto P = [&](int i, int j) { return s.psi[size_t(i) * n + j]; };
  auto Z = [&](int i, int j) { return s.zeta[size_t(i) * n + j]; };
  auto row = [n](const std::vector<double>& f, int i) { return f.data() + size_t(i) * n; };
  std::vector<double> F(static_cast<size_t>(size_));
  const WallClosureRow c = wall_closure_row(grid_, p_);
  for (int j = 0; j < n; ++j) {
    F[2 * j] = P(0, j) * s_psi_;
    F[2 * j + 1] = (c.c1 * P(1, j) - c.c2 * P(2, j) + c.cw * Z(0, j) + h * a2 * p_.omega * c.kappa) * s_psi_;
  }
  for (int i = 1; i < iN; ++i) {
    const XiFlux xf = xi_flux(grid_, i);
    const double hi2 = xf.h * xf.h, q2 = hi2 / (dth * dth), Jh2 = hi2 * grid_.r[i] * grid_.r[i];
    const double h2_nu = hi2 / p_.nu, h2_s = hi2 * absorbing_shift(grid_, p_, i);
    for (int j = 0; j < n; ++j) {
      const int e = east(j, n), w = west(j, n);
      const size_t q = size_t(i) * n + j;
      const SecondDifferences dp =
          second_differences(row(s.psi, i - 1), row(s.psi, i), row(s.psi, i + 1), j, e, w, xf);
      const SecondDifferences dz =
          second_differences(row(s.zeta, i - 1), row(s.zeta, i), row(s.zeta, i + 1), j, e, w, xf);
      F[2 * q] = (dp.xi + q2 * dp.theta + Jh2 * Z(i, j)) * s_psi_;
      F[2 * q + 1] = (dz.xi + q2 * dz.theta - h2_s * Z(i, j) - h2_nu * N[q]) * s_zeta_;
    }
  }
  for (int j = 0; j < n; ++j) {
    const int e = east(j, n), w = west(j, n);
    const size_t q = size_t(iN) * n + j;
    const double g = p_.U * R * std::sin(grid_.theta[j]) - x.back() / (2.0 * M_PI);
    F[2 * q] = (2.0 * (P(iN - 1, j) - P(iN, j)) + q2N * (P(iN, e) - 2.0 * P(iN, j) + P(iN, w)) +
                hN * hN * R * R * Z(iN, j) + 2.0 * hN * g) *
               s_psi_;
    const bool out = outflow(p_, psi_theta(row(s.psi, iN), j, n, dth));
    F[2 * q + 1] = (out ? Z(iN, j) - Z(iN - 1, j) : Z(iN, j)) * s_zeta_;
  }
  const double flux = circulation_flux(grid_, p_, s.psi.data(), s.zeta.data());
  F.back() = flux * hN / (2.0 * M_PI * p_.nu) * s_zeta_;
  return F;
}

void SteadyJacobian::build_half() {
  const int nr = grid_.n_r, n = grid_.n_theta, m = n / 2 - 1;  // nodes 0 < θ_j < π per ring
  half_size_ = 2L * nr * m;
  half_of_.assign(size_t(size_), -1);
  half_sign_.assign(size_t(size_), 0);
  for (int i = 0; i < nr; ++i)
    for (int j = 1; j < n; ++j) {
      if (2 * j == n) continue;  // on the axis: odd values are 0 there
      const bool upper = 2 * j < n;
      const long h = long(i) * m + (upper ? j : n - j) - 1;
      for (int c = 0; c < 2; ++c) {
        const size_t q = size_t(2 * (long(i) * n + j) + c);
        half_of_[q] = 2 * h + c;
        half_sign_[q] = upper ? 1 : -1;
      }
    }
  std::vector<long> ti, tj;
  half_from_.clear(), half_entry_sign_.clear();
  for (long col = 0; col < size_; ++col) {
    if (half_of_[size_t(col)] < 0) continue;
    for (long t = Ap_[size_t(col)]; t < Ap_[size_t(col) + 1]; ++t) {
      const long row = Ai_[size_t(t)];
      if (half_sign_[size_t(row)] != 1) continue;  // the rows of the upper half only
      ti.push_back(half_of_[size_t(row)]), tj.push_back(half_of_[size_t(col)]);
      half_from_.push_back(t), half_entry_sign_.push_back(half_sign_[size_t(col)]);
    }
  }
  triplet_pattern(half_size_, ti, tj, Hp_, Hi_, half_to_);
  Hx_.assign(Hi_.size(), 0.0);
}

void SteadyJacobian::factor(const std::vector<double>& x) {
  if (x.size() != size_t(size_)) throw std::invalid_argument("SteadyJacobian::factor: wrong size");
  assemble(x);
  if (mirror_) {
    if (Hp_.empty()) build_half();
    std::fill(Hx_.begin(), Hx_.end(), 0.0);
    for (size_t e = 0; e < half_from_.size(); ++e)
      Hx_[size_t(half_to_[e])] += half_entry_sign_[e] * Ax_[size_t(half_from_[e])];
  }
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_dl_defaults(control);
  // Nested dissection orders this grid's LU with 0.63 times the fill of UMFPACK's default AMD/COLAMD (2.6M
  // against 4.2M nonzeros at 118 x 96) and factors it ~1.5 times faster: the grid's own (grid_order), given
  // to UMFPACK by symbolic_in_grid_order.
  if (!symbolic_) {
    const auto t0 = clock_type::now();
    const long nf = factored_size();
    const long status = symbolic_in_grid_order(
        nf,
        grid_order(grid_.n_r, grid_.n_theta, mirror_, advection_reach(p_.advection_order),
                   advection_reach(p_.advection_order_xi)),
        [&](const double* ctl, const long* q) {
          double inf[UMFPACK_INFO];
          return q ? umfpack_dl_qsymbolic(nf, nf, fp(), fi(), fx(), q, &symbolic_, ctl, inf)
                   : umfpack_dl_symbolic(nf, nf, fp(), fi(), fx(), &symbolic_, ctl, inf);
        });
    symbolic_s_ = seconds_since(t0);
    if (status != UMFPACK_OK) {
      symbolic_ = nullptr;
      throw std::runtime_error(umfpack_error("symbolic analysis (Newton's Jacobian)", status));
    }
  } else {
    symbolic_s_ = 0.0;
  }
  if (numeric_) umfpack_dl_free_numeric(&numeric_);
  const auto t0 = clock_type::now();
  const SingleThreadBlas one_thread;
  const long status = umfpack_dl_numeric(fp(), fi(), fx(), symbolic_, &numeric_, control, info);
  numeric_s_ = seconds_since(t0);
  if (status != UMFPACK_OK) {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    numeric_ = nullptr;
    throw std::runtime_error(umfpack_error("numeric factorisation (Newton's Jacobian)", status));
  }
  lu_nnz_ = long(info[UMFPACK_LNZ] + info[UMFPACK_UNZ]);
}

std::vector<double> SteadyJacobian::solve(const std::vector<double>& b, bool transpose) const {
  if (!numeric_) throw std::logic_error("SteadyJacobian::solve before factor");
  if (b.size() != size_t(size_)) throw std::invalid_argument("SteadyJacobian::solve: wrong size");
  if (mirror_ && transpose) throw std::logic_error("SteadyJacobian::solve: no transpose on the mirror half");
  // Mirror: the upper half's rows of b in, the odd extension of the half solution out (axis and Γ_R: 0).
  std::vector<double> bh, yh(mirror_ ? size_t(half_size_) : 0);
  if (mirror_) {
    bh.resize(size_t(half_size_));
    for (long q = 0; q < size_; ++q)
      if (half_sign_[size_t(q)] == 1) bh[size_t(half_of_[size_t(q)])] = b[size_t(q)];
  }
  std::vector<double> y(b.size(), 0.0);
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_dl_defaults(control);
  control[UMFPACK_IRSTEP] = 0;  // no iterative refinement: Newton corrects the step's error (3x faster)
  const SingleThreadBlas one_thread;
  const long status =
      umfpack_dl_solve(transpose ? UMFPACK_At : UMFPACK_A, fp(), fi(), fx(), mirror_ ? yh.data() : y.data(),
                       mirror_ ? bh.data() : b.data(), numeric_, control, info);
  if (status != UMFPACK_OK) throw std::runtime_error(umfpack_error("solve (Newton's Jacobian)", status));
  if (mirror_)
    for (long q = 0; q < size_; ++q)
      if (half_of_[size_t(q)] >= 0) y[size_t(q)] = half_sign_[size_t(q)] * yh[size_t(half_of_[size_t(q)])];
  return y;
}

std::vector<double> SteadyJacobian::multiply(const std::vector<double>& x) const {
  if (Ap_.empty()) throw std::logic_error("SteadyJacobian::multiply before factor");
  if (mirror_) throw std::logic_error("SteadyJacobian::multiply: the mirror half keeps half the rows");
  if (x.size() != size_t(size_)) throw std::invalid_argument("SteadyJacobian::multiply: wrong size");
  std::vector<double> y(x.size(), 0.0);
  for (long c = 0; c < size_; ++c)
    for (long t = Ap_[size_t(c)]; t < Ap_[size_t(c) + 1]; ++t)
      y[size_t(Ai_[size_t(t)])] += Ax_[size_t(t)] * x[size_t(c)];
  return y;
}

NsState potential_guess(const NsParams& p, const PolarGrid& g) {
  NsState s;
  const int nr = g.n_r, n = g.n_theta;
  const double a2 = p.a * p.a;
  s.psi.resize(size_t(nr) * n);
  s.zeta.assign(size_t(nr) * n, 0.0);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < n; ++j)
      s.psi[size_t(i) * n + j] =
          p.U * (g.r[i] - a2 / g.r[i]) * std::sin(g.theta[j]) - a2 * p.omega * std::log(g.r[i] / p.a);
  s.Gamma_R = 2.0 * M_PI * a2 * p.omega;
  return s;
}

NewtonResult solve_steady(SteadyJacobian& jac, const NsState& guess, const NewtonOptions& o) {
  const auto t0 = clock_type::now();
  NewtonResult res;
  std::vector<double> x = jac.pack(guess);
  std::vector<double> F = jac.residual(x);
  double r = max_abs(F);
  res.residuals.push_back(r);
  if (o.on_iteration) o.on_iteration(0, r);
  bool fresh = false;  // the factors are of an earlier iterate (a chord step may use them)
  for (int it = 1; it <= o.max_iterations && !(r <= o.tol) && std::isfinite(r); ++it) {
    if (o.chord_ratio > 0.0 && fresh) {
      std::vector<double> xc = jac.solve(F);
      for (size_t q = 0; q < x.size(); ++q) xc[q] = x[q] - xc[q];
      std::vector<double> Fc = jac.residual(xc);
      const double rc = max_abs(Fc);
      if (rc <= o.chord_ratio * r) {  // accepted: the old factors still contract fast enough
        x.swap(xc), F.swap(Fc), r = rc;
        res.residuals.push_back(r);
        res.iterations = it;
        ++res.chord_steps;
        if (o.on_iteration) o.on_iteration(it, r);
        continue;
      }
    }
    try {
      jac.factor(x);
    } catch (const std::runtime_error& e) {
      res.message = e.what();
      break;
    }
    fresh = true;
    ++res.factorisations;
    res.factor_seconds += jac.symbolic_seconds() + jac.numeric_seconds();
    const std::vector<double> dx = jac.solve(F);
    for (size_t q = 0; q < x.size(); ++q) x[q] -= dx[q];
    F = jac.residual(x);
    r = max_abs(F);
    res.residuals.push_back(r);
    res.iterations = it;
    if (o.on_iteration) o.on_iteration(it, r);
  }
  res.converged = r <= o.tol;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3e", r);
  const std::string steps =
      std::to_string(res.iterations) + " steps (" + std::to_string(res.factorisations) + " factorisations)";
  if (!res.message.empty())
    res.message += " after " + steps;
  else if (res.converged)
    res.message = "converged in " + steps + ", residual " + buf;
  else if (!std::isfinite(r))
    res.message = "the Newton iterate turned non-finite after " + steps;
  else
    res.message = "not converged after " + steps + ": residual " + buf;
  res.state = jac.unpack(x);
  res.wall_seconds = seconds_since(t0);
  return res;
}

NewtonResult solve_steady(const NsParams& p, const NsState& guess, const NewtonOptions& o) {
  const auto t0 = clock_type::now();
  SteadyJacobian jac(p);
  NewtonResult res = solve_steady(jac, guess, o);
  res.wall_seconds = seconds_since(t0);
  return res;
}

}  // namespace magnus
