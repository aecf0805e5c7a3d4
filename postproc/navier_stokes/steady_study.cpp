#include "postproc/navier_stokes/steady_study.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "postproc/navier_stokes/forces.hpp"

namespace magnus {

namespace {

/// The p with (h1^p − h2^p)/(h2^p − h3^p) = (f1 − f2)/(f2 − f3) in [1, 4] (bisection), or none: the
/// differences change sign or the ratio needs an order outside [1, 4].
std::optional<double> observed_order(double f1, double f2, double f3, double h1, double h2, double h3) {
  const double d12 = f1 - f2, d23 = f2 - f3;
  if (!(d12 * d23 > 0.0)) return std::nullopt;
  const double q = d12 / d23;
  auto g = [&](double p) { return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p)) - q; };
  double lo = 1.0, hi = 4.0;
  if (g(lo) * g(hi) > 0.0) return std::nullopt;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(lo) * g(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double extrapolate(double coarse, double fine, double h_coarse, double h_fine, double p) {
  return fine + (fine - coarse) / (std::pow(h_coarse / h_fine, p) - 1.0);
}

}  // namespace

Richardson richardson(const std::vector<double>& f, const std::vector<double>& h) {
  const size_t n = f.size();
  if (n < 2 || h.size() != n) throw std::invalid_argument("richardson: needs two or more grids, one h per value");
  for (size_t k = 1; k < n; ++k)
    if (!(h[k] < h[k - 1])) throw std::invalid_argument("richardson: the spacings must decrease");
  Richardson r;
  r.finest = f[n - 1];
  if (n >= 3) {
    if (const auto p = observed_order(f[n - 3], f[n - 2], f[n - 1], h[n - 3], h[n - 2], h[n - 1])) {
      r.order = *p;
      r.observed = true;
    }
  }
  r.value = extrapolate(f[n - 2], f[n - 1], h[n - 2], h[n - 1], r.order);
  // With an observed order: how far the value moves if the order were the formal 2 (the grids are not yet
  // in the asymptotic range while the two differ). Without one: the whole correction f* − f_N.
  // At least a tenth of the correction: an observed order that happens to be 2 says little more.
  r.error = r.observed ? std::max(std::fabs(r.value - extrapolate(f[n - 2], f[n - 1], h[n - 2], h[n - 1], 2.0)),
                                  0.1 * std::fabs(r.value - r.finest))
                       : std::fabs(r.value - r.finest);
  return r;
}

NsParams level_params(const NsParams& p, double scale) {
  if (!(scale > 0.0 && scale <= 1.0)) throw std::invalid_argument("steady study: a grid scale must be in (0, 1]");
  if (scale == 1.0) return p;
  NsParams q = p;
  const PolarGrid fine = ns_grid(p);
  q.n_theta = std::max(8, 2 * int(std::lround(0.5 * scale * p.n_theta)));
  q.n_r = std::max(4, int(std::lround(scale * (fine.n_r - 1))) + 1);
  return q;
}

NsState interpolate_state(const PolarGrid& from, const NsState& s, const PolarGrid& to) {
  const int nc = from.n_theta, nf = to.n_theta, nrc = from.n_r, nrf = to.n_r;
  if (nrc < 4) throw std::invalid_argument("interpolate_state: the coarse grid needs four rings or more");
  // θ: the coarse ring's DFT c_k (k = 0 … nc/2), evaluated at the fine angles; cosine/sine tables once.
  const int kmax = nc / 2;
  std::vector<double> cs(size_t(kmax + 1) * nc), sn(size_t(kmax + 1) * nc);
  for (int k = 0; k <= kmax; ++k)
    for (int j = 0; j < nc; ++j) {
      const double a = 2.0 * M_PI * double((long(k) * j) % nc) / nc;
      cs[size_t(k) * nc + j] = std::cos(a), sn[size_t(k) * nc + j] = std::sin(a);
    }
  std::vector<double> cf(size_t(kmax + 1) * nf), sf(size_t(kmax + 1) * nf);
  for (int k = 0; k <= kmax; ++k)
    for (int j = 0; j < nf; ++j) {
      const double a = k * to.theta[j];
      cf[size_t(k) * nf + j] = std::cos(a), sf[size_t(k) * nf + j] = std::sin(a);
    }
  auto theta_up = [&](const std::vector<double>& v) {
    std::vector<double> out(size_t(nrc) * nf, 0.0), re(kmax + 1), im(kmax + 1);
    for (int i = 0; i < nrc; ++i) {
      const double* row = &v[size_t(i) * nc];
      for (int k = 0; k <= kmax; ++k) {
        double a = 0.0, b = 0.0;
        for (int j = 0; j < nc; ++j) a += row[j] * cs[size_t(k) * nc + j], b += row[j] * sn[size_t(k) * nc + j];
        const double w = (k == 0 || 2 * k == nc) ? 1.0 : 2.0;  // ±k folded into one real term
        re[k] = w * a / nc, im[k] = w * b / nc;
      }
      double* o = &out[size_t(i) * nf];
      for (int k = 0; k <= kmax; ++k) {
        // The Nyquist mode (k = nc/2) split evenly between ±k: its cosine only.
        for (int j = 0; j < nf; ++j)
          o[j] += re[k] * cf[size_t(k) * nf + j] + (2 * k == nc ? 0.0 : im[k] * sf[size_t(k) * nf + j]);
      }
    }
    return out;
  };
  const std::vector<double> psi = theta_up(s.psi), zeta = theta_up(s.zeta);
  NsState out;
  out.psi.resize(size_t(nrf) * nf), out.zeta.resize(size_t(nrf) * nf);
  out.Gamma_R = s.Gamma_R;
  for (int i = 0; i < nrf; ++i) {
    // Cubic Lagrange in ξ through the four coarse rings around ξ_i (any ξ spacing).
    const double x = std::min(to.xi[i], from.xi.back());
    const int below = int(std::upper_bound(from.xi.begin(), from.xi.end(), x) - from.xi.begin()) - 1;
    const int i0 = std::clamp(below - 1, 0, nrc - 4);
    double w[4];
    for (int m = 0; m < 4; ++m) {
      w[m] = 1.0;
      for (int l = 0; l < 4; ++l)
        if (l != m) w[m] *= (x - from.xi[i0 + l]) / (from.xi[i0 + m] - from.xi[i0 + l]);
    }
    for (int j = 0; j < nf; ++j) {
      double a = 0.0, b = 0.0;
      for (int m = 0; m < 4; ++m) a += w[m] * psi[size_t(i0 + m) * nf + j], b += w[m] * zeta[size_t(i0 + m) * nf + j];
      out.psi[size_t(i) * nf + j] = a, out.zeta[size_t(i) * nf + j] = b;
    }
  }
  for (int j = 0; j < nf; ++j) out.psi[size_t(j)] = 0.0;  // the wall streamline, exactly
  return out;
}

namespace {

/// The part of a state odd in θ (ψ, ζ at θ_{n−j} the negatives of those at θ_j, 0 on the axis θ = 0, π;
/// Γ_R = 0): the symmetric start of a mirror solve, exactly.
NsState odd_part(const PolarGrid& g, NsState s) {
  const int n = g.n_theta;
  for (std::vector<double>* f : {&s.psi, &s.zeta})
    for (int i = 0; i < g.n_r; ++i) {
      double* row = &(*f)[size_t(i) * n];
      row[0] = row[n / 2] = 0.0;
      for (int j = 1; 2 * j < n; ++j) {
        const double odd = 0.5 * (row[j] - row[n - j]);
        row[j] = odd, row[n - j] = -odd;
      }
    }
  s.Gamma_R = 0.0;
  return s;
}

}  // namespace

namespace {

/// Newton on the grid of q from `start` (a state on that grid), and the level's figures.
SteadyLevel solve_level(const NsParams& q, bool mirror, NsState start, const NewtonOptions& no) {
  SteadyJacobian jac(q, mirror);
  const PolarGrid& g = jac.grid();
  if (mirror) start = odd_part(g, std::move(start));
  SteadyLevel lv;
  lv.n_theta = g.n_theta, lv.n_r = g.n_r;
  lv.h = std::sqrt(g.d_theta * std::log(g.r[1] / g.r[0]));
  lv.newton = solve_steady(jac, start, no);
  if (!lv.newton.converged) return lv;
  const ViscousForces f = viscous_forces(g, q, 1.0, lv.newton.state);
  lv.C_D = f.C_D.value_or(0.0), lv.C_L = f.C_L.value_or(0.0);
  if (q.U > 0.0) lv.recirculation = recirculation_length(g, lv.newton.state);
  return lv;
}

/// A study's levels in sequence: each starts from the last converged level's state (or the guess, or the
/// potential flow), and its result is taken into the study.
struct Sequencer {
  const NsParams& p;
  const SteadyStudyOptions& o;
  const NsState* guess;
  SteadyStudy& st;
  std::mutex report;  // on_iteration from two threads, one call at a time
  NsState prev;       // the last converged level's state, on prev_grid
  PolarGrid prev_grid;
  bool have_prev = false;
  std::string skipped;  // the coarse levels without a steady state

  NsParams level(size_t k) const { return level_params(p, o.scales[k]); }

  NewtonOptions options(size_t k) {
    NewtonOptions no = o.newton;
    no.on_iteration = nullptr;
    if (st.levels.empty() && o.plain_first) no.chord_ratio = 0.0;
    if (o.on_iteration)
      no.on_iteration = [this, k](int it, double r) {
        const std::lock_guard<std::mutex> lock(report);
        o.on_iteration(int(k), it, r);
      };
    return no;
  }

  NsState start_on(size_t k, const NsParams& q) const {
    const PolarGrid g = ns_grid(q);
    return have_prev ? interpolate_state(prev_grid, prev, g) : guess && k == 0 ? *guess : potential_guess(q, g);
  }

  /// Takes level k's result: false when the study stops there (the case's own grid did not converge).
  bool accept(size_t k, SteadyLevel lv) {
    const bool last = k + 1 == o.scales.size();
    if (!lv.newton.converged && !last) {  // a coarse grid without a steady state: the next from scratch
      skipped += fmt::format("{}{} x {}", skipped.empty() ? "" : ", ", lv.n_theta, lv.n_r);
      have_prev = false;
      return true;
    }
    if (!lv.newton.converged) {
      st.message = fmt::format("grid {} x {} (level {} of {}): {}", lv.n_theta, lv.n_r, k + 1, o.scales.size(),
                               lv.newton.message);
      st.levels.push_back(std::move(lv));
      return false;
    }
    if (!last)
      prev = std::move(lv.newton.state), prev_grid = ns_grid(level(k)), have_prev = true;
    else
      st.state = std::move(lv.newton.state);
    lv.newton.state = NsState{};
    st.levels.push_back(std::move(lv));
    return true;
  }

  bool solve_in_turn(size_t k) {
    const NsParams q = level(k);
    return accept(k, solve_level(q, st.mirror, start_on(k, q), options(k)));
  }

  /// Levels ka < kb at once, both from the current start: ka beside, as a run's companion is.
  bool solve_together(size_t ka, size_t kb) {
    const NsParams qa = level(ka), qb = level(kb);
    std::future<SteadyLevel> side =
        std::async(std::launch::async, [qa, mirror = st.mirror, start = start_on(ka, qa), no = options(ka)]() mutable {
          return solve_level(qa, mirror, std::move(start), no);
        });
    SteadyLevel b = solve_level(qb, st.mirror, start_on(kb, qb), options(kb));  // a throw waits for side
    accept(ka, side.get());  // not the last level: never stops the study
    return accept(kb, std::move(b));
  }
};

/// The Richardson values and the one-line account of a study whose every level converged.
void conclude(SteadyStudy& st, const NsParams& p, const std::string& skipped) {
  st.converged = true;
  if (p.U > 0.0 && st.levels.size() >= 2) {
    std::vector<double> h, cd, cl, lr;
    for (const SteadyLevel& lv : st.levels)
      h.push_back(lv.h), cd.push_back(lv.C_D), cl.push_back(lv.C_L), lr.push_back(lv.recirculation);
    st.C_D = richardson(cd, h);
    st.C_L = richardson(cl, h);
    st.recirculation = richardson(lr, h);
  }
  int steps = 0, factors = 0;
  for (const SteadyLevel& lv : st.levels) steps += lv.newton.iterations, factors += lv.newton.factorisations;
  st.message = fmt::format("{} grids, {} Newton steps ({} factorisations)", st.levels.size(), steps, factors);
  if (st.mirror) st.message += ", each on the mirror-symmetric half";
  if (!skipped.empty()) st.message += "; not converged on " + skipped + ", left out";
}

}  // namespace

SteadyStudy steady_study(const NsParams& p, const SteadyStudyOptions& o, const NsState* guess) {
  const auto t0 = std::chrono::steady_clock::now();
  if (o.scales.empty() || o.scales.back() != 1.0)
    throw std::invalid_argument("steady study: the last grid scale must be 1 (the case's grid)");
  for (size_t k = 1; k < o.scales.size(); ++k)
    if (!(o.scales[k] > o.scales[k - 1])) throw std::invalid_argument("steady study: grid scales must increase");
  SteadyStudy st;
  st.mirror = o.mirror && p.omega == 0.0 && p.U > 0.0;  // every level has the case's ω and U
  std::vector<size_t> ks;  // the levels solved (the coarse ones too coarse to say anything left out)
  for (size_t k = 0; k < o.scales.size(); ++k) {
    const NsParams q = level_params(p, o.scales[k]);
    if (k + 1 < o.scales.size() && (q.n_theta < kMinStudyTheta || ns_grid(q).n_r < kMinStudyRings)) continue;
    ks.push_back(k);
  }
  // The last two levels side by side, both from the level before them, on a machine with two cores.
  const bool two_cores = std::thread::hardware_concurrency() >= 2;
  const size_t together = o.overlap && two_cores && ks.size() >= 3 ? ks.size() - 2 : ks.size();
  Sequencer seq{p, o, guess, st, {}, {}, {}, false, {}};
  bool going = true;
  for (size_t u = 0; going && u < together; ++u) going = seq.solve_in_turn(ks[u]);
  if (going && together < ks.size()) going = seq.solve_together(ks[together], ks[together + 1]);
  if (going) conclude(st, p, seq.skipped);
  st.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return st;
}

}  // namespace magnus
