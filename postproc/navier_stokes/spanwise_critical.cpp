#include "postproc/navier_stokes/spanwise_critical.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <tuple>

#include "postproc/navier_stokes/regula_falsi.hpp"
#include "solver/work_queue.hpp"

namespace magnus {

std::optional<double> onset_reynolds(double alpha, const std::vector<Onset3d>& curve) {
  std::vector<Onset3d> c = curve;
  std::sort(c.begin(), c.end(), [](const Onset3d& a, const Onset3d& b) { return a.alpha < b.alpha; });
  for (size_t k = 0; k < c.size(); ++k) {
    if (std::fabs(alpha - c[k].alpha) <= 1e-9) return c[k].Re_c;
    if (k + 1 < c.size() && alpha > c[k].alpha && alpha < c[k + 1].alpha) {
      const double w = (alpha - c[k].alpha) / (c[k + 1].alpha - c[k].alpha);
      return (1.0 - w) * c[k].Re_c + w * c[k + 1].Re_c;
    }
  }
  return std::nullopt;
}

std::pair<double, double> onset_alpha_range(const std::vector<Onset3d>& curve) {
  const auto [lo, hi] = std::minmax_element(curve.begin(), curve.end(),
                                            [](const Onset3d& a, const Onset3d& b) { return a.alpha < b.alpha; });
  return {lo->alpha, hi->alpha};
}

void set_onset3d(ViscousPart& v, double alpha, const std::vector<Onset3d>& curve,
                 const std::vector<std::string>& files) {
  if (curve.empty()) return;
  std::tie(v.onset3d_alpha_min, v.onset3d_alpha_max) = onset_alpha_range(curve);
  v.onset3d_reynolds = onset_reynolds(alpha, curve);
  v.onset3d_files.clear();
  for (const std::string& f : files) v.onset3d_files += (v.onset3d_files.empty() ? "" : ", ") + f;
}

std::optional<bool> two_d_is_real(double Re, double alpha, const std::vector<Onset3d>& curve) {
  const std::optional<double> Re_c = onset_reynolds(alpha, curve);
  if (!Re_c) return std::nullopt;
  return Re < *Re_c;
}

double SpanwiseCritical::wavelength_D() const { return spanwise_wavelength_D(beta_D); }

namespace {

/// The scan at Reynolds number Re (the steady state and its 2D eigenvalues first, as the CLI does).
SpanwiseEvaluation evaluate(const NsParams& p, const std::vector<double>& beta_D, double Re,
                            const std::string& eigensolver, const std::vector<std::vector<double>>& starts) {
  const auto t0 = std::chrono::steady_clock::now();
  const NsParams q = with_parameter(p, HopfParameter::reynolds, Re);
  SpanwiseEvaluation e;
  e.Re = Re;
  e.scan = spanwise_stability(q, steady_stability(q, eigensolver), beta_D, eigensolver, {}, starts);
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

/// Arnoldi's starts at Re: the Floquet modes of the orbit scanned nearest to it (none before the first).
/// The scan of `done` nearest Re among those for which keep(scan) holds (nullptr when none does).
template <class Keep>
const SpanwiseEvaluation* nearest_scan(const std::vector<SpanwiseEvaluation>& done, double Re, Keep keep) {
  const SpanwiseEvaluation* near = nullptr;
  for (const SpanwiseEvaluation& e : done)
    if (keep(e.scan) && (!near || std::fabs(e.Re - Re) < std::fabs(near->Re - Re))) near = &e;
  return near;
}

bool periodic(const SpanwiseScan& s) { return s.periodic; }

std::vector<std::vector<double>> nearest_modes(const std::vector<SpanwiseEvaluation>& done, double Re) {
  const SpanwiseEvaluation* near = nearest_scan(done, Re, periodic);
  std::vector<std::vector<double>> starts;
  if (near)
    for (const SpanwisePoint& pt : near->scan.points) starts.push_back(pt.mode);
  return starts;
}

bool defined(const SpanwiseScan& s) {
  for (const SpanwisePoint& pt : s.points)
    if (pt.found) return true;
  return false;
}

}  // namespace

SpanwiseCritical spanwise_critical(const NsParams& p, const std::vector<double>& beta_D, double Re_a, double Re_b,
                                   double tol, const std::string& eigensolver, int max_evaluations,
                                   const std::function<void(const SpanwiseEvaluation&)>& on_evaluation) {
  if (!(Re_a > 0.0) || !(Re_a < Re_b) || !std::isfinite(Re_b))
    throw std::invalid_argument(fmt::format("spanwise_critical: needs 0 < Re_a < Re_b (got {}, {})", Re_a, Re_b));
  if (!(tol > 0.0)) throw std::invalid_argument("spanwise_critical: the tolerance must be > 0");
  const auto t0 = std::chrono::steady_clock::now();
  SpanwiseCritical c;
  // A scan that fails (no steady state, an orbit not found) ends the search, naming its Reynolds number.
  auto run = [&](double Re) -> const SpanwiseEvaluation& {
    try {
      c.evaluations.push_back(evaluate(p, beta_D, Re, eigensolver, nearest_modes(c.evaluations, Re)));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fmt::format("the 3D onset search at Re {:.5g}: {}", Re, e.what()));
    }
    if (on_evaluation) on_evaluation(c.evaluations.back());
    return c.evaluations.back();
  };
  auto finish = [&] {
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return c;
  };
  SpanwiseEvaluation a = run(Re_a), b = run(Re_b);
  if (!defined(a.scan) || !defined(b.scan)) {
    c.message = "no growth rate converged at an end of the range";
    return finish();
  }
  if (!(a.scan.growth < 0.0 && b.scan.growth > 0.0)) {
    c.message = fmt::format("the most unstable growth rate does not cross zero in [{:g}, {:g}] ({:+.4f} and "
                            "{:+.4f} U/D at the ends)",
                            Re_a, Re_b, a.scan.growth, b.scan.growth);
    return finish();
  }
  // A scan whose growth rate is undefined ends the search (its Reynolds number named).
  auto growth = [&](double Re) -> std::optional<double> {
    const SpanwiseEvaluation& m = run(Re);
    return defined(m.scan) ? std::optional<double>(m.scan.growth) : std::nullopt;
  };
  const BracketRoot r = bracket_root(growth, Re_a, a.scan.growth, Re_b, b.scan.growth, tol, max_evaluations - 2);
  if (r.failed) {
    c.message = fmt::format("no growth rate converged at Re {:.5g}", r.failed_at);
    return finish();
  }
  c.lo = r.lo, c.hi = r.hi, c.Re_c = r.root, c.change = r.change;
  // The most unstable wavenumber at the root: linear in Re between the bracket's scans.
  auto beta_at = [&](double Re) {
    for (const SpanwiseEvaluation& e : c.evaluations)
      if (e.Re == Re) return e.scan.beta_D;
    return 0.0;
  };
  const double w = (c.Re_c - c.lo) / (c.hi - c.lo);
  c.beta_D = (1.0 - w) * beta_at(c.lo) + w * beta_at(c.hi);
  c.found = r.converged;
  if (!c.found) c.message = fmt::format("not converged to ±{:g} in {} scans", tol, max_evaluations);
  return finish();
}

namespace {

/// The mode of scan e at the wavenumber nearest β·D, sampled from grid `from` onto `to` (empty: none).
std::vector<double> prolonged_mode(const SpanwiseEvaluation& e, double beta_D, const PolarGrid& from,
                                   const PolarGrid& to) {
  const SpanwisePoint* best = nullptr;
  for (const SpanwisePoint& pt : e.scan.points)
    if (!pt.mode.empty() && (!best || std::fabs(pt.beta_D - beta_D) < std::fabs(best->beta_D - beta_D)))
      best = &pt;
  return best ? spanwise_prolong(from, to, best->mode) : std::vector<double>{};
}

/// How far a scan's growth rate may be from its Floquet multiplier's limit, U/D: Arnoldi's stopping rule in
/// |μ|, max(kFloquetTolerance, kFloquetRelative·|1 − |μ||), over |μ|·T (growth = ln|μ|/T); 0 for a steady
/// base (converged eigenvalues).
double growth_tolerance(const SpanwiseScan& s) {
  if (!s.periodic) return 0.0;
  double mu = 0.0;
  for (const SpanwisePoint& pt : s.points) mu = std::max(mu, std::abs(pt.multiplier));
  if (!(mu > 0.0 && s.T > 0.0)) return 0.0;
  return std::max(kFloquetTolerance, kFloquetRelative * std::fabs(1.0 - mu)) / (mu * s.T);
}

/// g'' = 2(s₁₂ − s₀₁)/(Re₂ − Re₀), the second divided difference of the growth rate over the three coarse
/// scans nearest Re (s₀₁, s₁₂ the slopes between them, (U/D) per unit of Re), (U/D) per unit of Re²; 0 with
/// fewer than three.
double growth_curvature(const SpanwiseCritical& c, double Re) {
  std::vector<const SpanwiseEvaluation*> e;
  for (const SpanwiseEvaluation& x : c.evaluations)
    if (defined(x.scan)) e.push_back(&x);
  if (e.size() < 3) return 0.0;
  std::sort(e.begin(), e.end(),
            [Re](auto* a, auto* b) { return std::fabs(a->Re - Re) < std::fabs(b->Re - Re); });
  std::sort(e.begin(), e.begin() + 3, [](auto* a, auto* b) { return a->Re < b->Re; });
  const double s01 = (e[1]->scan.growth - e[0]->scan.growth) / (e[1]->Re - e[0]->Re);
  const double s12 = (e[2]->scan.growth - e[1]->scan.growth) / (e[2]->Re - e[1]->Re);
  return 2.0 * (s12 - s01) / (e[2]->Re - e[0]->Re);
}

/// The fine grid's two scans at Re[0] and Re[1] at once (one thread each), each started from the coarse
/// mode nearest it; a scan that fails leaves its message in `failed`.
void fine_scans(const NsParams& coarse, const SpanwiseCritical& c, const NsParams& fine,
                const std::string& eigensolver, const double Re[2], SpanwiseFine& f, std::string failed[2]) {
  const PolarGrid gc = ns_grid(coarse), gf = ns_grid(fine);
  const SpanwiseEvaluation* at_root = nearest_scan(c.evaluations, c.Re_c, defined);
  const bool orbit = at_root && at_root->scan.periodic;
  f.evaluations.resize(2);
  for_each_index(2, 2, [&](size_t k) {
    try {
      NsParams q = with_parameter(fine, HopfParameter::reynolds, Re[k]);
      q.threads = 1;  // the two scans share the cores
      const SpanwiseEvaluation* near = nearest_scan(c.evaluations, Re[k], periodic);  // its Floquet modes
      const std::vector<std::vector<double>> start = {near ? prolonged_mode(*near, c.beta_D, gc, gf)
                                                           : std::vector<double>{}};
      const auto t = std::chrono::steady_clock::now();
      SpanwiseEvaluation& e = f.evaluations[k];
      e.Re = Re[k];
      e.scan = orbit ? floquet_scan(q, {c.beta_D}, 300.0 * 2.0 * q.a / q.U, {}, start)
                     : evaluate(q, {c.beta_D}, Re[k], eigensolver, start).scan;
      e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    } catch (const std::exception& x) {
      failed[k] = fmt::format("the fine grid's 3D scan at Re {:.5g}: {}", Re[k], x.what());
    }
  });
}

}  // namespace

std::vector<std::string> fine_grid_overrides(double n, double R_over_a, const NsParams& p,
                                             const std::string& what) {
  if (!(n >= 8.0 && n <= 4096.0 && n == std::floor(n) && int(n) % 2 == 0))
    throw std::invalid_argument(what + ": n_θ must be an even whole number in [8, 4096]");
  if (!(R_over_a > 1.0 && R_over_a <= 1e4)) throw std::invalid_argument(what + ": R/a must be in (1, 10000]");
  if (int(n) < p.n_theta || R_over_a < p.outer_over_a || (int(n) == p.n_theta && R_over_a == p.outer_over_a))
    throw std::invalid_argument(
        fmt::format("{}: must be finer than the case's grid (n_θ {}, R = {:g}a): n_θ and "
                    "R/a at least the case's, not both the same",
                    what, p.n_theta, p.outer_over_a));
  return {fmt::format("grid.n_theta={}", int(n)), fmt::format("domain.outer_radius={:.17g}", R_over_a),
          "grid.n_r=0"};
}

FineRoot fine_onset(double Re_1, double g_1, double Re_2, double g_2, double curvature) {
  FineRoot r;
  const double d = Re_2 - Re_1, s = (g_2 - g_1) / d;
  if (!(d > 0.0) || !(s > 0.0)) return r;
  r.line = Re_1 - g_1 / s;
  // g(Re_1 + u) = A u² + B u + g_1 with A = ½g'', B = s − ½g''·d; the zero where g rises is
  // u = −2g_1/(B + √(B² − 4Ag_1)).
  const double A = 0.5 * curvature, B = s - A * d, disc = B * B - 4.0 * A * g_1;
  const double denom = disc >= 0.0 ? B + std::sqrt(disc) : 0.0;
  const double u = denom > 0.0 ? -2.0 * g_1 / denom : 0.0;
  r.parabola = denom > 0.0 && std::fabs(Re_1 + u - r.line) <= d;
  r.Re_c = r.parabola ? Re_1 + u : r.line;
  // The parabola: its correction to the line. The line alone: its own error at its zero x,
  // ½|g''|·|(x − Re_1)(x − Re_2)|/s.
  r.correction = r.parabola ? std::fabs(r.Re_c - r.line)
                            : 0.5 * std::fabs(curvature * (r.line - Re_1) * (r.line - Re_2)) / s;
  r.found = true;
  return r;
}

SpanwiseFine spanwise_critical_fine(const NsParams& coarse, const SpanwiseCritical& c, const NsParams& fine,
                                    const std::string& eigensolver) {
  if (!c.found) throw std::invalid_argument("spanwise_critical_fine: the coarse search found no onset");
  const auto t0 = std::chrono::steady_clock::now();
  SpanwiseFine f;
  f.beta_D = c.beta_D;
  const double Re[2] = {c.Re_c, 1.02 * c.Re_c};
  std::string failed[2];
  fine_scans(coarse, c, fine, eigensolver, Re, f, failed);
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& m : failed)
    if (!m.empty()) {
      f.message = m;
      return f;
    }
  const SpanwiseScan &a = f.evaluations[0].scan, &b = f.evaluations[1].scan;
  for (const SpanwiseEvaluation& e : f.evaluations)
    if (!defined(e.scan) || (e.scan.periodic && !e.scan.points.front().covered)) {
      f.message = fmt::format("the fine grid's growth rate at Re {:.5g} did not converge", e.Re);
      return f;
    }
  const FineRoot r = fine_onset(Re[0], a.growth, Re[1], b.growth, growth_curvature(c, c.Re_c));
  if (!r.found) {
    f.message = fmt::format("the fine grid's growth rate does not rise with Re ({:+.5f} at Re {:.5g}, "
                            "{:+.5f} at {:.5g})",
                            a.growth, Re[0], b.growth, Re[1]);
    return f;
  }
  f.Re_c = r.Re_c, f.line_Re_c = r.line;
  // ∂x/∂g_1 = −g_2ΔRe/Δg², ∂x/∂g_2 = g_1ΔRe/Δg² for the line's zero x, each growth rate off by its tolerance.
  const double dRe = Re[1] - Re[0], dg = b.growth - a.growth;
  const double tolerance_part =
      (std::fabs(b.growth) * growth_tolerance(a) + std::fabs(a.growth) * growth_tolerance(b)) * dRe /
      (dg * dg);
  f.bar = tolerance_part + r.correction;
  f.extrapolated = f.Re_c < Re[0] - 0.5 * dRe || f.Re_c > Re[1] + 0.5 * dRe;
  f.found = true;
  return f;
}

}  // namespace magnus
