#include "postproc/navier_stokes/spanwise_scan.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "solver/work_queue.hpp"
#include "solver/navier_stokes/floquet.hpp"

namespace magnus {

double spanwise_wavelength_D(double beta_D) { return beta_D > 0.0 ? 2.0 * M_PI / beta_D : 0.0; }

double SpanwiseScan::wavelength_D() const { return spanwise_wavelength_D(beta_D); }

std::pair<double, double> parabola_vertex(const double x[3], const double y[3]) {
  // Divided differences: y = y0 + d1 (x − x0) + d2 (x − x0)(x − x1).
  const double d01 = (y[1] - y[0]) / (x[1] - x[0]), d12 = (y[2] - y[1]) / (x[2] - x[1]);
  const double d2 = (d12 - d01) / (x[2] - x[0]);
  if (!(d2 < 0.0)) return {x[1], y[1]};  // not a maximum
  const double xv = 0.5 * (x[0] + x[1]) - d01 / (2.0 * d2);
  if (!(xv >= x[0] && xv <= x[2])) return {x[1], y[1]};
  return {xv, y[0] + d01 * (xv - x[0]) + d2 * (xv - x[0]) * (xv - x[1])};
}

namespace {

/// The most unstable wavenumber of the scan's points (sorted by β), the verdict.
void read_scan(SpanwiseScan& s) {
  std::vector<const SpanwisePoint*> found;
  for (const auto& pt : s.points)
    if (pt.found) found.push_back(&pt);
  if (found.empty()) {
    s.verdict = "undefined: no eigenvalue converged at any wavenumber";
    return;
  }
  std::sort(found.begin(), found.end(), [](auto* a, auto* b) { return a->beta_D < b->beta_D; });
  size_t k = 0;
  for (size_t q = 1; q < found.size(); ++q)
    if (found[q]->growth() > found[k]->growth()) k = q;
  s.beta_D = found[k]->beta_D, s.growth = found[k]->growth();
  s.stationary = s.periodic ? found[k]->multiplier.imag() == 0.0 && found[k]->multiplier.real() > 0.0
                             : found[k]->lambda.imag() == 0.0;
  s.interior = k > 0 && k + 1 < found.size();
  if (s.interior) {
    const double x[3] = {found[k - 1]->beta_D, found[k]->beta_D, found[k + 1]->beta_D};
    const double y[3] = {found[k - 1]->growth(), found[k]->growth(), found[k + 1]->growth()};
    std::tie(s.beta_D, s.growth) = parabola_vertex(x, y);
  }
  s.stable = true;
  for (auto* pt : found) s.stable = s.stable && pt->growth() < 0.0;
  const std::string where =
      s.beta_D > 0.0 ? fmt::format("λ_z = {:.3g} D (β·D = {:.3g})", s.wavelength_D(), s.beta_D) : "β = 0 (2D)";
  const std::string edge = s.interior ? "" : ", at the end of the wavenumbers scanned";
  if (s.stable)
    s.verdict = fmt::format("spanwise-uniform flow is stable to 3D disturbances at the wavenumbers scanned "
                            "(least stable {}, growth rate {:+.4f} U/D{})",
                            where, s.growth, edge);
  else if (s.beta_D > 0.0)
    s.verdict = fmt::format("spanwise-uniform flow is unstable to a {} 3D mode at {}, growth rate {:+.4f} U/D{}",
                            s.periodic ? (s.stationary ? "synchronous" : "non-synchronous")
                                       : (s.stationary ? "stationary" : "oscillating"),
                            where, s.growth, edge);
  else
    s.verdict = fmt::format("unstable to 2D disturbances first (β = 0, growth rate {:+.4f} U/D)", s.growth);
}

/// Without a start of its own, wavenumber i starts from the mode of the nearest wavenumber already done
/// on this orbit (none yet: empty, a random start).
std::vector<double> nearest_done_mode(const std::vector<SpanwisePoint>& points, const std::vector<bool>& done,
                                      size_t i, std::mutex& mutex) {
  const std::lock_guard<std::mutex> lock(mutex);
  size_t best = points.size();
  for (size_t k = 0; k < points.size(); ++k)
    if (done[k] && !points[k].mode.empty() &&
        (best == points.size() || std::fabs(points[k].beta_D - points[i].beta_D) <
                                      std::fabs(points[best].beta_D - points[i].beta_D)))
      best = k;
  return best < points.size() ? points[best].mode : std::vector<double>{};
}

}  // namespace

SpanwiseScan spanwise_scan(const NsParams& p, const NsState& steady, const std::vector<double>& beta_D,
                           const StabilityOptions& o, const std::function<void(const SpanwisePoint&)>& on_point) {
  if (beta_D.empty()) throw std::invalid_argument("spanwise_scan: no wavenumbers");
  for (double b : beta_D)
    if (!(b >= 0.0) || !std::isfinite(b))
      throw std::invalid_argument(fmt::format("spanwise_scan: β·D must be finite and ≥ 0 (got {})", b));
  SpanwiseScan s;
  const double D = 2.0 * p.a;
  for (double b : beta_D) {
    const StabilityResult r = spanwise_eigenvalues(p, steady, b / D, 6, o);
    SpanwisePoint pt;
    pt.beta_D = b, pt.found = !r.eigenvalues.empty(), pt.covered = r.covered;
    if (pt.found) pt.lambda = r.eigenvalues.front();
    pt.seconds = r.seconds, pt.solves = r.solves;
    s.points.push_back(pt);
    if (on_point) on_point(pt);
  }
  read_scan(s);
  return s;
}

SpanwiseScan floquet_scan(const NsParams& p, const std::vector<double>& beta_D, double t_end,
                          const std::function<void(const SpanwisePoint&)>& on_point,
                          const std::vector<std::vector<double>>& starts) {
  if (beta_D.empty()) throw std::invalid_argument("floquet_scan: no wavenumbers");
  const PolarGrid g = ns_grid(p);
  NsState start = impulsive_start(p, g);
  break_symmetry(p, g, start);
  OrbitRunOptions ro;
  ro.t_end = t_end;
  const OrbitRun run = periodic_orbit_run(p, ro, std::move(start));
  if (!run.orbit.converged)
    throw std::runtime_error("the shedding orbit did not converge (" + run.orbit.message + ")");
  const double T = run.orbit.T, unit = stability_speed(p) / (2.0 * p.a);  // U/D in 1/s
  // Phase 0 where the wake's first harmonic peaks, the same on every orbit: a neighbouring Reynolds
  // number's modes then start Arnoldi near the answer.
  const PeriodicBase base = canonical_phase(orbit_series(p, run.orbit));
  SpanwiseScan s;
  s.periodic = true, s.T = T * unit;
  s.points.resize(beta_D.size());
  for (size_t k = 0; k < beta_D.size(); ++k) s.points[k].beta_D = beta_D[k];
  // The wavenumbers on the cores at once, each its own stepper; reported in order as they finish.
  std::mutex mutex;
  size_t reported = 0;
  std::vector<bool> done(beta_D.size(), false);
  std::string error;
  for_each_index(beta_D.size(), std::max(1u, std::thread::hardware_concurrency()), [&](size_t i) {
    FloquetOptions fo;
    fo.krylov = 30, fo.tolerance = kFloquetTolerance, fo.relative = kFloquetRelative;
    fo.start = i < starts.size() ? starts[i] : nearest_done_mode(s.points, done, i, mutex);
    SpanwisePoint pt;
    pt.beta_D = beta_D[i];
    try {
      const FloquetResult r = floquet_multipliers(p, base, beta_D[i] / (2.0 * p.a), fo);
      pt.found = !r.multipliers.empty() && r.multipliers.front() != 0.0;
      if (pt.found) {
        pt.multiplier = r.multipliers.front();
        pt.lambda = std::log(pt.multiplier) / (T * unit);
        pt.covered = fo.met(pt.multiplier, r.residuals.front());
        pt.mode = r.mode;
      }
      pt.seconds = r.seconds, pt.solves = r.periods * r.steps;
    } catch (const std::exception& e) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (error.empty()) error = fmt::format("β·D = {:g}: {}", beta_D[i], e.what());
      return;
    }
    const std::lock_guard<std::mutex> lock(mutex);
    s.points[i] = std::move(pt), done[i] = true;
    for (; reported < done.size() && done[reported]; ++reported)
      if (on_point) on_point(s.points[reported]);
  });
  if (!error.empty()) throw std::runtime_error(error);
  read_scan(s);
  return s;
}

HopfEvaluation steady_stability(const NsParams& p, const std::string& eigensolver) {
  HopfOptions honest;  // the converged search: every shift to convergence, shifts added for gaps
  honest.full = lone_search(StabilityOptions{});
  honest.full.eigensolver = eigensolver;
  const double alpha = p.a * p.omega / p.U;
  HopfEvaluation s = hopf_evaluation(p, HopfParameter::spin_ratio, alpha, nullptr, std::nullopt, honest);
  if (!s.converged)
    throw std::runtime_error(
        fmt::format("Newton's method found no steady state (Re {:.4g}, α {:g})", p.reynolds(), alpha));
  if (s.stability.eigenvalues.empty()) throw std::runtime_error(s.stability.message);
  return s;
}

SpanwiseScan spanwise_stability(const NsParams& p, const HopfEvaluation& steady, const std::vector<double>& beta_D,
                                const std::string& eigensolver, const std::function<void(const SpanwisePoint&)>& on_point,
                                const std::vector<std::vector<double>>& starts) {
  if (!steady.stability.stable) return floquet_scan(p, beta_D, 300.0 * 2.0 * p.a / p.U, on_point, starts);
  StabilityOptions o = quick_stability_options();  // per wavenumber: the default shifts, no extra ones
  o.eigensolver = eigensolver;
  return spanwise_scan(p, steady.state, beta_D, o, on_point);
}

}  // namespace magnus
