#include "solver/navier_stokes/stability.hpp"

#include <umfpack.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <stdexcept>
#include <thread>

#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/shift_invert.hpp"
#include "solver/work_queue.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

/// Points of the strip Re λ_lead ≤ Re λ ≤ x_hi, 0 ≤ Im λ ≤ y_hi (U/D) outside every shift's disk, on a
/// grid of spacing 0.01 U/D: the rightmost such point (the first found at the largest Re), if any.
std::optional<cplx> uncovered(const std::vector<ShiftSearch>& searches, double unit, double x_lo, double x_hi,
                              double y_hi) {
  std::optional<cplx> gap;
  const double step = 0.01;
  for (double x = x_hi; x >= x_lo - 1e-12; x -= step)
    for (double y = 0.0; y <= y_hi + 1e-12; y += step) {
      bool in = false;
      for (const auto& sr : searches) in = in || std::abs(cplx(x, y) - sr.sigma / unit) < sr.radius / unit;
      if (!in) return cplx(x, y);
    }
  return gap;
}

/// The diagonal of M in J x = λ M x (see ns_stability.hpp): the time stepper's dynamic rows.
std::vector<double> mass_matrix(const NsParams& p, const SteadyJacobian& jac, const NsState& steady) {
  const PolarGrid& g = jac.grid();
  const int nr = g.n_r, n = g.n_theta;
  std::vector<double> m(size_t(jac.size()), 0.0);
  for (int i = 1; i < nr - 1; ++i) {
    const double h = g.ring_width(i);  // ring i's rows are scaled by h_i² (newton.cpp)
    for (int j = 0; j < n; ++j)
      m[2 * (size_t(i) * n + j) + 1] = jac.zeta_row_scale() * h * h * g.r[i] * g.r[i] / p.nu;
  }
  const double h = g.d_xi(nr - 2);  // the outer ring's spacing
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
  return m;
}

/// The leading eigenvector x into res's mode fields, normalised to max |ζ| = 1 (real and positive there);
/// node q's ψ and ζ are x[stride·q] and x[stride·q + 1], Γ_R the last unknown.
void set_mode(StabilityResult& res, const std::vector<cplx>& x, size_t nodes, size_t stride) {
  res.mode_psi.resize(nodes), res.mode_zeta.resize(nodes);
  double zmax = 0.0;
  size_t qmax = 0;
  for (size_t q = 0; q < nodes; ++q)
    if (std::abs(x[stride * q + 1]) > zmax) zmax = std::abs(x[stride * q + 1]), qmax = q;
  const cplx scale = zmax > 0.0 ? std::abs(x[stride * qmax + 1]) / x[stride * qmax + 1] / zmax : 1.0;
  for (size_t q = 0; q < nodes; ++q)
    res.mode_psi[q] = x[stride * q] * scale, res.mode_zeta[q] = x[stride * q + 1] * scale;
  res.mode_Gamma_R = x.back() * scale;
}

/// f^H x.
cplx dot(const std::vector<cplx>& f, const std::vector<cplx>& x) {
  cplx s = 0.0;
  for (size_t q = 0; q < f.size(); ++q) s += std::conj(f[q]) * x[q];
  return s;
}

/// Of `found` (Im λ ≥ 0 members), the eigenpair StabilityOptions::follow or follow_near picks, into res's
/// `followed` fields.
void follow_mode(const std::vector<Eigenpair>& found, const StabilityOptions& o, double unit, StabilityResult& res) {
  const std::vector<cplx>& f = o.follow;
  const double nf = std::sqrt(std::real(dot(f, f)));
  double best = HUGE_VAL;
  for (const Eigenpair& e : found) {
    if (!f.empty()) {
      if (e.x.size() != f.size() || !(nf > 0.0)) continue;
      const double overlap = std::abs(dot(f, e.x)) / (nf * std::sqrt(std::real(dot(e.x, e.x))));
      if (overlap > res.followed_overlap)
        res.followed_overlap = overlap, res.followed = e.lambda / unit, res.followed_vector = e.x;
    } else if (o.follow_near && e.lambda.imag() > 0.0 && std::abs(e.lambda / unit - *o.follow_near) < best) {
      best = std::abs(e.lambda / unit - *o.follow_near);
      res.followed_overlap = 1.0, res.followed = e.lambda / unit, res.followed_vector = e.x;
    }
  }
}

/// The searches' eigenpairs into res (λ in U/D): each shift with its disk, the reach of the nearest
/// search, the eigenvalues without repeats, rightmost first, a complex one followed by its conjugate (at
/// most count), their residuals, the leading eigenvector as the mode, and the pair o follows (follow_mode).
void gather_eigenpairs(std::vector<ShiftSearch>& searches, double unit, int count, size_t nodes, size_t stride,
                       const StabilityOptions& o, StabilityResult& res) {
  std::vector<Eigenpair> all;
  double reach = -1.0;
  for (auto& sr : searches) {
    res.shifts.push_back({sr.sigma / unit, int(sr.found.size()), sr.radius / unit, sr.converged, sr.restarts});
    double far = 0.0;
    for (const auto& e : sr.found) far = std::max(far, std::abs(e.lambda - sr.sigma) / unit);
    if (!sr.found.empty()) reach = reach < 0.0 ? far : std::min(reach, far);
    for (auto& e : sr.found) all.push_back(std::move(e));
  }

  // Im λ ≥ 0 representatives, without repeats; then each complex one followed by its conjugate.
  std::vector<Eigenpair> uniq;
  for (auto& e : all) {
    if (e.lambda.imag() < 0.0) {
      e.lambda = std::conj(e.lambda);
      for (auto& z : e.x) z = std::conj(z);
    }
    bool seen = false;
    for (auto& u : uniq)
      if (std::abs(u.lambda - e.lambda) <= 1e-6 * (unit + std::abs(e.lambda))) {
        seen = true;
        if (e.residual < u.residual) u.residual = e.residual;
      }
    if (!seen) uniq.push_back(std::move(e));
  }
  std::stable_sort(uniq.begin(), uniq.end(),
                   [](const Eigenpair& u, const Eigenpair& v) { return u.lambda.real() > v.lambda.real(); });
  for (const auto& e : uniq) {
    const cplx l = e.lambda / unit;
    const bool real = std::fabs(l.imag()) <= 1e-8 * (1.0 + std::abs(l));
    res.eigenvalues.push_back(real ? cplx(l.real(), 0.0) : l);
    res.residuals.push_back(e.residual);
    if (!real) res.eigenvalues.push_back(std::conj(l)), res.residuals.push_back(e.residual);
  }
  if (res.eigenvalues.size() > size_t(count)) res.eigenvalues.resize(size_t(count)), res.residuals.resize(size_t(count));
  res.reach = std::max(reach, 0.0);
  if (!uniq.empty()) set_mode(res, uniq.front().x, nodes, stride);
  follow_mode(uniq, o, unit, res);
}

/// One line: stable or not, the leading eigenvalue, its growth rate and St, and whether the strip right of
/// it was covered.
std::string verdict_message(const StabilityResult& res) {
  if (res.eigenvalues.empty()) return "no eigenvalue converged (shift-invert Arnoldi)";
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s: leading eigenvalue %.4g %+.4gi (U/D), growth rate %.4g, St %.4g%s",
                res.stable ? "stable" : "unstable", res.eigenvalues.front().real(), res.eigenvalues.front().imag(),
                res.growth_rate(), res.strouhal(),
                res.covered ? "" : " (the search did not cover the strip right of it: not verified)");
  return buf;
}

}  // namespace

std::string eigensolver_names() { return "arnoldi, arpack"; }

bool known_eigensolver(const std::string& name) { return name == "arnoldi" || name == "arpack"; }

double stability_speed(const NsParams& p) {
  return p.U > 0.0 ? p.U : std::fabs(p.a * p.omega) > 0.0 ? std::fabs(p.a * p.omega) : p.nu / p.a;
}

std::optional<std::complex<double>> rightmost_pair(const std::vector<std::complex<double>>& eigenvalues) {
  for (const auto& l : eigenvalues)
    if (l.imag() > 0.0) return l;
  return std::nullopt;
}

std::optional<std::complex<double>> StabilityResult::leading_pair() const { return rightmost_pair(eigenvalues); }

double StabilityResult::strouhal() const {
  return eigenvalues.empty() ? 0.0 : eigen_strouhal(eigenvalues.front());
}

StabilityOptions quick_stability_options() {
  StabilityOptions o;
  o.restarts = 4, o.extra_shifts = 0;
  return o;
}

StabilityOptions lone_search(StabilityOptions o) {
  o.threads = std::thread::hardware_concurrency() >= 2 ? 2 : 1;
  return o;
}

StabilityResult leading_eigenvalues(const NsParams& p, const NsState& steady, int count) {
  return leading_eigenvalues(p, steady, count, StabilityOptions{});
}

EigenProblem stability_problem(const NsParams& p, const NsState& steady) {
  SteadyJacobian jac(p);
  jac.assemble(jac.pack(steady));
  EigenProblem ep;
  ep.n = jac.size();
  ep.Ap = jac.col_ptr(), ep.Ai = jac.row_index(), ep.Ax = jac.values();
  ep.m = mass_matrix(p, jac, steady);
  ep.order = grid_order(jac.grid().n_r, jac.grid().n_theta, false, advection_reach(p.advection_order),
                        advection_reach(p.advection_order_xi));
  return ep;
}

StabilityResult leading_eigenvalues(const NsParams& p, const NsState& steady, int count,
                                    const StabilityOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  check_stability_options(count, o);
  const EigenProblem ep = stability_problem(p, steady);
  const double unit = stability_speed(p) / (2.0 * p.a);  // U/D in 1/s
  StabilityResult res = search_eigenvalues(ep, unit, count, o, size_t(steady.psi.size()), 2);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

void check_stability_options(int count, const StabilityOptions& o) {
  if (count < 1) throw std::invalid_argument("leading_eigenvalues: count must be ≥ 1");
  if (o.shifts.empty()) throw std::invalid_argument("leading_eigenvalues: no shifts");
  if (o.threads < 1) throw std::invalid_argument("leading_eigenvalues: threads must be ≥ 1");
  if (!known_eigensolver(o.eigensolver))
    throw std::invalid_argument("leading_eigenvalues: unknown eigensolver \"" + o.eigensolver + "\" (expected " +
                                eigensolver_names() + ")");
}

StabilityResult search_eigenvalues(const EigenProblem& ep, double unit, int count, const StabilityOptions& o,
                                   size_t nodes, size_t stride) {
  const auto t0 = std::chrono::steady_clock::now();
  StabilityResult res;
  void* symbolic = nullptr;
  std::vector<ShiftSearch> searches;
  const bool arpack = o.eigensolver == "arpack";
  // Shift k's search, its start vector from a generator of its own (seed, k): the same on any thread.
  auto search_at = [&](cplx s_unit, unsigned k) {
    std::seed_seq seq{o.seed, k};
    std::mt19937 rng(seq);
    const int krylov = std::max(o.krylov, count + 10);
    return arpack ? shift_invert_arpack(ep, s_unit * unit, o.want, krylov, o.restarts, o.tol, o.arpack_tol,
                                        &symbolic, rng)
                  : shift_invert_arnoldi(ep, s_unit * unit, o.want, krylov, o.restarts, o.tol, &symbolic, rng,
                                         o.follow.empty() ? nullptr : &o.follow);
  };
  auto search = [&](cplx s_unit) {
    searches.push_back(search_at(s_unit, unsigned(searches.size())));
    res.solves += searches.back().solves;
  };
  // The given shifts on o.threads threads (the first to factor makes the symbolic analysis the others
  // reuse), kept in the order given.
  auto given_shifts = [&] {
    std::vector<ShiftSearch> found(o.shifts.size());
    for_each_index(found.size(), size_t(o.threads),
                   [&](size_t k) { found[k] = search_at(o.shifts[k], unsigned(k)); });
    for (auto& r : found) {
      res.solves += r.solves;
      searches.push_back(std::move(r));
    }
  };
  // The rightmost accepted eigenvalue so far, U/D (−∞ when none).
  auto rightmost = [&] {
    double x = -HUGE_VAL;
    for (const auto& sr : searches)
      for (const auto& e : sr.found) x = std::max(x, e.lambda.real() / unit);
    return x;
  };
  try {
    given_shifts();
    // The check that nothing lies right of the leading eigenvalue unseen: the strip from it to the
    // imaginary axis (the stability boundary), up to the highest shift's frequency, must lie inside the
    // shifts' disks. (Disks centred right of the axis that cover a point on it cover as much right of it.)
    // A gap gets a shift of its own (at most o.extra_shifts).
    // The extra shifts sit on the default shifts' line at the gap's frequency: on the axis itself, amid the
    // slow real modes and the far field's dense damped pairs, a shift's disk shrinks to a few hundredths.
    double x_line = 0.0, y_hi = 0.0;
    for (const cplx& s : o.shifts) x_line = std::max(x_line, s.real()), y_hi = std::max(y_hi, s.imag());
    for (int extra = 0;; ++extra) {
      const double lead = rightmost();
      const auto gap = uncovered(searches, unit, std::isfinite(lead) ? std::min(lead, 0.0) : -0.3, 0.0, y_hi);
      res.covered = !gap;
      if (!gap || extra >= o.extra_shifts) break;
      search({x_line, gap->imag()});
    }
  } catch (...) {
    if (symbolic) umfpack_zl_free_symbolic(&symbolic);
    throw;
  }
  if (symbolic) umfpack_zl_free_symbolic(&symbolic);
  gather_eigenpairs(searches, unit, count, nodes, stride, o, res);
  res.stable = !res.eigenvalues.empty() && res.eigenvalues.front().real() < 0.0;
  res.message = verdict_message(res);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace magnus
