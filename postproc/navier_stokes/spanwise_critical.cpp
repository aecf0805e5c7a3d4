#include "postproc/navier_stokes/spanwise_critical.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "postproc/navier_stokes/regula_falsi.hpp"

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
std::vector<std::vector<double>> nearest_modes(const std::vector<SpanwiseEvaluation>& done, double Re) {
  const SpanwiseEvaluation* near = nullptr;
  for (const SpanwiseEvaluation& e : done)
    if (e.scan.periodic && (!near || std::fabs(e.Re - Re) < std::fabs(near->Re - Re))) near = &e;
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

}  // namespace magnus
