#include "postproc/navier_stokes/critical.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/hopf_steady.hpp"
#include "postproc/navier_stokes/hopf_track.hpp"
#include "postproc/navier_stokes/regula_falsi.hpp"

namespace magnus {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

SearchVariable search_variable(HopfParameter which, double A, double B) {
  return {which == HopfParameter::spin_ratio && A >= 0.0 && A < B - A};
}

const char* hopf_parameter_name(HopfParameter which) {
  return which == HopfParameter::spin_ratio ? "spin ratio α" : "Reynolds number Re";
}

NsParams with_parameter(const NsParams& p, HopfParameter which, double x) {
  NsParams q = p;
  if (which == HopfParameter::spin_ratio)
    q.omega = x * q.U / q.a;
  else
    q.nu = 2.0 * q.a * q.U / x;
  return q;
}

double HopfPoint::strouhal() const { return eigen_strouhal(lambda); }

HopfEvaluation hopf_evaluation(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                               const std::optional<std::complex<double>>& near, const HopfOptions& o,
                               const NsState* guess) {
  HopfEvaluation e = steady_point(p, which, x, from, guess);
  if (!e.converged) return e;
  if (near)
    track_pair(p, which, e, *near, o);
  else
    full_search(p, which, e, o);
  return e;
}

namespace {

/// The bracket of a Hopf search and its Illinois weights; lo is the end at the smaller x. Roots, slopes and
/// pairs are lines in the search variable u.
struct HopfBracket {
  HopfEvaluation lo, hi;
  Illinois weights;  ///< end 0 is lo, end 1 hi
  SearchVariable var;
  double root() const { return var.x(weights.root(var.u(lo.x), lo.growth(), var.u(hi.x), hi.growth())); }
  /// d(Re λ)/du across the bracket, U/D.
  double slope() const { return (hi.growth() - lo.growth()) / (var.u(hi.x) - var.u(lo.x)); }
  /// The next point: the secant through the last two points solved inside the bracket when it falls inside
  /// the current one (superlinear, and blind to the far ends' curvature), else the Illinois root.
  double next_root(const std::vector<std::pair<double, double>>& inside) const {
    if (inside.size() >= 2) {
      const auto &a = inside[inside.size() - 2], &b = inside.back();
      const double s = var.x(secant_zero(var.u(a.first), a.second, var.u(b.first), b.second));
      if (s > std::min(lo.x, hi.x) && s < std::max(lo.x, hi.x)) return s;
    }
    return root();
  }
  /// The unstable side's pairs (x, λ) in the order solved: the mode whose crossing is wanted.
  std::vector<std::pair<double, std::complex<double>>> lineage;
  /// The wanted pair predicted at x, U/D: extrapolated along a line through the two unstable-side points
  /// nearest x (the stable side's nearest pair may be another, damped mode), or the one there is.
  std::complex<double> predict(double x) const {
    auto near = lineage;
    std::sort(near.begin(), near.end(),
              [x](const auto& a, const auto& b) { return std::fabs(a.first - x) < std::fabs(b.first - x); });
    if (near.size() < 2 || near[0].first == near[1].first) return near.front().second;
    const auto &a = near[0], &b = near[1];
    return a.second + (a.second - b.second) * ((var.u(x) - var.u(a.first)) / (var.u(a.first) - var.u(b.first)));
  }
  /// Adds e to the lineage when it grows.
  void note(const HopfEvaluation& e) {
    if (e.growth() >= 0.0) lineage.emplace_back(e.x, e.mode);
  }
  /// The steady state at x by linear interpolation between the ends' (Newton's start there): closer than
  /// the nearer end's by the bracket's curvature term.
  NsState state_at(double x) const { return blend(lo.state, hi.state, (x - lo.x) / (hi.x - lo.x)); }
  /// The pair at x by linear interpolation between the ends, U/D.
  std::complex<double> pair_at(double x) const {
    return lo.mode + (hi.mode - lo.mode) * ((var.u(x) - var.u(lo.x)) / (var.u(hi.x) - var.u(lo.x)));
  }
  /// m replaces the end of its sign; the end kept twice in a row has its growth rate halved (Illinois).
  void replace(HopfEvaluation m) {
    const bool at_lo = (m.growth() < 0.0) == (lo.growth() < 0.0);
    (at_lo ? lo : hi) = std::move(m);
    weights.replaced(at_lo ? 0 : 1);
  }
};

HopfEvaluation without_state(const HopfEvaluation& e) {
  HopfEvaluation c = e;
  c.state = {};
  c.vector = {};
  return c;
}

/// e with its state alone: the pair, its eigenvector and how it was found forgotten.
void forget_pair(HopfEvaluation& e) {
  e.stability = {};
  e.mode = 0.0;
  e.tracked = e.seeded = false;
  e.vector.clear();
  e.overlap = 0.0;
}

using Keep = std::function<void(const HopfEvaluation&)>;

/// One line: the same pair's growth rate (U/D) has one sign, g_a at a and g_b at b.
NoCrossing no_crossing(HopfParameter which, double a, double g_a, double b, double g_b) {
  return NoCrossing(fmt::format("onset of shedding over {} {:g}:{:g}: the leading growth rate does not change sign "
                                "(Re λ·D/U = {:.4g} at {:g}, {:.4g} at {:g}): widen or move the bracket",
                                hopf_parameter_name(which), a, b, g_a, a, g_b, b),
                    a, g_a, b, g_b);
}

/// The ends solved: each checked and recorded by `keep` (A's already when a_kept), noted, and their growth
/// rates required to differ in sign.
HopfBracket checked_ends(HopfBracket k, HopfParameter which, const Keep& keep, bool a_kept = false) {
  if (!a_kept) keep(k.lo);
  keep(k.hi);
  k.note(k.lo), k.note(k.hi);
  if ((k.lo.growth() < 0.0) == (k.hi.growth() < 0.0)) throw no_crossing(which, k.lo.x, k.lo.growth(), k.hi.x, k.hi.growth());
  return k;
}

/// The ends A and B with the same pair at both: the growing pair of the unstable end (seeded_search, or the
/// full search's leading pair), tracked at the other; with `follow`, a neighbouring crossing's pair followed
/// to both instead. Newton starts from `guess` when given. `keep` checks and records each.
HopfBracket hopf_ends(const NsParams& p, HopfParameter which, double A, double B, const HopfOptions& o,
                      const Keep& keep, const NsState* guess, const HopfStart* follow) {
  HopfBracket k;
  k.var = search_variable(which, A, B);
  k.lo = steady_point(p, which, A, nullptr, guess);
  if (!k.lo.converged) keep(k.lo);  // throws: no steady state at A
  if (follow && !follow->vector.empty()) {  // both ends' pairs followed from the neighbouring crossing's
    track_pair(p, which, k.lo, follow->lambda, o, false, &follow->vector);
    const bool lo_followed = k.lo.overlap >= kFollowOverlap && k.lo.mode != 0.0;
    k.hi = steady_point(p, which, B, &k.lo, guess);
    if (k.hi.converged)  // from A's pair where it was followed there
      track_pair(p, which, k.hi, lo_followed ? k.lo.mode : follow->lambda, o, false, lo_followed ? &k.lo.vector : &follow->vector);
    // B's pair where it is not parallel enough to A's: the pair nearest A's, as the searched ends take it.
    if (lo_followed && k.hi.mode != 0.0) return checked_ends(std::move(k), which, keep);
    for (HopfEvaluation* e : {&k.lo, &k.hi}) forget_pair(*e);  // not followed: the ends' own searches
  }
  // The growing pair: at A by the march's Arnoldi, else at B by it, else by the full search (A's first).
  bool a_unstable = seeded_search(p, which, k.lo, o);
  if (!k.hi.converged) k.hi = steady_point(p, which, B, &k.lo, guess, true);
  bool b_done = false;
  if (!a_unstable) {
    b_done = k.hi.converged && seeded_search(p, which, k.hi, o);
    if (!b_done) {
      full_search(p, which, k.lo, o);
      a_unstable = k.lo.mode != 0.0 && k.lo.growth() >= 0.0;
    }
  }
  if (a_unstable) keep(k.lo);
  if (!b_done && k.hi.converged) {
    if (a_unstable)
      track_pair(p, which, k.hi, k.lo.mode, o);
    else
      full_search(p, which, k.hi, o);
  }
  if (!a_unstable && k.lo.converged && k.hi.converged && k.hi.mode != 0.0 && k.hi.growth() >= 0.0)
    track_pair(p, which, k.lo, k.hi.mode, o);  // the stable end's eigenvalues at the mode that turns unstable
  return checked_ends(std::move(k), which, keep, a_unstable);
}

/// hopf_point_from's bracket, stepped from `at` (see there); false when start's pair is not followed at `at`.
/// Throws std::runtime_error when a step's pair is not followed (another mode taken for it: no sign change
/// it shows can be trusted) or no step stays inside [A, B], and NoCrossing after four steps of one sign.
bool stepped_ends(const NsParams& p, HopfParameter which, double at, double A, double B, const HopfOptions& o,
                  const Keep& keep, const HopfStart& start, HopfBracket& k) {
  const SearchVariable& v = k.var;
  HopfEvaluation a = steady_point(p, which, at, nullptr, &start.state);
  if (!a.converged) keep(a);  // throws: no steady state at `at`
  track_pair(p, which, a, start.lambda, o, false, &start.vector);
  if (!(a.overlap >= kFollowOverlap && a.mode != 0.0)) return false;
  keep(a);
  double slope = start.slope;  // d(Re λ)/du
  double before = a.x, g_before = a.growth();  // the point before a (for the message)
  for (int step = 0; step < 4; ++step) {
    const double d = 1.25 * (v.x(v.u(a.x) - a.growth() / slope) - a.x);  // past the predicted root
    if (!std::isfinite(d)) break;
    const double step_x = std::min(std::max(std::fabs(d), 0.5 * o.tol), (B - A) / 4.0);
    const double x = std::clamp(a.x + std::copysign(step_x, d), A, B);
    if (x == a.x) break;  // at an end of [A, B]
    HopfEvaluation b = steady_point(p, which, x, &a, &a.state);
    if (b.converged) track_pair(p, which, b, a.mode, o, false, &a.vector);
    keep(b);
    if (!(b.overlap >= kFollowOverlap))
      throw std::runtime_error(fmt::format("onset of shedding: the pair followed from the last crossing was lost at "
                                           "{} = {:g} (overlap {:.2f})", hopf_parameter_name(which), b.x, b.overlap));
    if ((b.growth() < 0.0) != (a.growth() < 0.0)) {
      const bool a_first = a.x < b.x;
      k.lo = std::move(a_first ? a : b);
      k.hi = std::move(a_first ? b : a);
      k.note(k.lo), k.note(k.hi);
      return true;
    }
    slope = (b.growth() - a.growth()) / (v.u(b.x) - v.u(a.x));
    before = a.x, g_before = a.growth();
    a = std::move(b);
  }
  if (before == a.x)
    throw std::runtime_error(fmt::format("onset of shedding: from the predicted crossing {} = {:g} (Re λ·D/U = {:.4g}) "
                                         "no step toward the root stays inside {:g}:{:g}: widen the range",
                                         hopf_parameter_name(which), a.x, a.growth(), A, B));
  throw no_crossing(which, std::min(before, a.x), before < a.x ? g_before : a.growth(), std::max(before, a.x),
                    before < a.x ? a.growth() : g_before);
}

/// A search's record: `keep` checks each point (a steady state and a pair, else it throws), reports it and
/// adds it to h without its state.
Keep recorder(HopfPoint& h, HopfParameter which, const std::function<void(const HopfEvaluation&)>& progress) {
  return [&h, which, progress](const HopfEvaluation& e) {
    const char* name = hopf_parameter_name(which);
    if (!e.converged)
      throw std::runtime_error(fmt::format("onset of shedding: Newton's method found no steady state at {} = {:g}, "
                                           "continuing from the nearest state solved", name, e.x));
    if (e.mode == 0.0)
      throw std::runtime_error(fmt::format("onset of shedding: no complex pair (the wake's mode) was found at {} = "
                                           "{:g} ({})", name, e.x, e.stability.message));
    if (progress) progress(e);
    h.evaluations.push_back(without_state(e));
  };
}

/// The bracket's crossing by the secant search (HopfBracket::next_root), written into h: its first ends, the
/// crossing, its pair, and the start it leaves for a neighbouring search. slope: |d(Re λ)/dx| the growth
/// rate may change by across the final bracket, ten times over, before the bracket is taken for a jump.
void refine(const NsParams& p, HopfParameter which, const HopfOptions& o, HopfBracket k, double slope,
            const Keep& keep, HopfPoint& h) {
  const char* name = hopf_parameter_name(which);
  h.at_a = without_state(k.lo), h.at_b = without_state(k.hi);
  HopfEvaluation far = k.lo.growth() < 0.0 ? k.lo : k.hi;  // the stable end asked for, with its state
  double root = k.root();
  std::vector<std::pair<double, double>> latest;  // the points solved inside the bracket, (x, Re λ) in order
  for (int repairs = 0;; ++repairs) {
    h.change = k.hi.x - k.lo.x;
    while (k.hi.x - k.lo.x > o.tol && h.change > 0.5 * o.tol && int(h.evaluations.size()) < o.max_evaluations) {
      const HopfEvaluation& from = std::fabs(root - k.lo.x) <= std::fabs(root - k.hi.x) ? k.lo : k.hi;
      // The pair is tracked as predicted from the unstable side's (the stable side's nearest pair may be
      // another, damped mode).
      const NsState between = k.state_at(root);
      HopfEvaluation m = steady_point(p, which, root, &from, &between);
      if (m.converged) track_pair(p, which, m, k.predict(root), o, k.lineage.size() >= 2, &from.vector);
      keep(m);
      k.note(m);
      latest.emplace_back(m.x, m.growth());
      k.replace(std::move(m));
      const double next = k.next_root(latest);
      h.change = std::fabs(next - root);
      root = next;
    }
    // A crossing the secant can trust: across the final bracket the growth rate changes no faster than
    // ten times `slope` (the mean over the ends asked for, or the last crossing's). A jump instead is the stable end's pair being another mode
    // (tracked from a poor prediction: it is tracked again, at most twice), or a fold of the steady branch.
    if (std::fabs(k.hi.growth() - k.lo.growth()) <= 10.0 * slope * (k.hi.x - k.lo.x) + 1e-9) break;
    if (repairs == 2)
      throw std::runtime_error(fmt::format(
          "onset of shedding: the growth rate jumps from {:+.4g} at {} = {:g} to {:+.4g} at {:g} (U/D) instead of "
          "crossing zero: a fold of the steady branch or a change of the tracked mode, not a Hopf point",
          k.lo.growth(), name, k.lo.x, k.hi.growth(), k.hi.x));
    HopfEvaluation& stable = k.lo.growth() < 0.0 ? k.lo : k.hi;
    track_pair(p, which, stable, k.predict(stable.x), o);
    keep(stable);
    if (stable.growth() >= 0.0) {  // the wanted pair still grows there: bracket it with the far end again
      k.note(stable);
      track_pair(p, which, far, k.predict(far.x), o);
      keep(far);
      if (far.growth() >= 0.0)
        throw std::invalid_argument(fmt::format("onset of shedding: the wake's pair still grows at {} = {:g} "
                                                "(Re λ·D/U = {:.4g}): widen or move the bracket",
                                                name, far.x, far.growth()));
      HopfEvaluation grows = std::move(stable);  // the nearer end on the unstable side, far the other
      (far.x > grows.x ? k.lo : k.hi) = std::move(grows);
      (far.x > k.lo.x ? k.hi : k.lo) = far;
    }
    k.weights = Illinois{};
    latest.clear();  // the stable end was tracked again: start the secant afresh
    root = k.root();
  }
  h.x_c = root, h.lo = k.lo.x, h.hi = k.hi.x;
  if (h.lo > h.hi) std::swap(h.lo, h.hi);
  h.lambda = k.pair_at(root);
  const HopfEvaluation& nearest = std::fabs(root - k.lo.x) <= std::fabs(root - k.hi.x) ? k.lo : k.hi;
  h.next = {nearest.state, nearest.mode, nearest.vector, k.slope()};
}

/// |d(Re λ)/dx| between the bracket's ends.
double mean_slope(const HopfBracket& k) { return std::fabs(k.hi.growth() - k.lo.growth()) / (k.hi.x - k.lo.x); }

/// Throws std::invalid_argument (one line) for a bracket [A, B] or a tolerance no search can use.
void check_search(HopfParameter which, double A, double B, const HopfOptions& o) {
  const char* name = hopf_parameter_name(which);
  if (!std::isfinite(A) || !std::isfinite(B) || (which == HopfParameter::reynolds && !(A > 0.0)))
    throw std::invalid_argument(fmt::format("onset of shedding: the {} bracket needs finite values{} (got {}:{})",
                                            name, which == HopfParameter::reynolds ? " > 0" : "", A, B));
  if (!(A < B)) throw std::invalid_argument(fmt::format("onset of shedding: the {} bracket needs A < B (got {}:{})", name, A, B));
  if (!(o.tol > 0.0)) throw std::invalid_argument(fmt::format("--tolerance must be > 0 (got {})", o.tol));
}

}  // namespace

HopfPoint hopf_point(const NsParams& p, HopfParameter which, double A, double B, const HopfOptions& o,
                     const std::function<void(const HopfEvaluation&)>& progress, const HopfStart* start) {
  check_search(which, A, B, o);
  const auto t0 = std::chrono::steady_clock::now();
  HopfPoint h;
  h.parameter = which;
  const Keep keep = recorder(h, which, progress);
  HopfBracket k = hopf_ends(p, which, A, B, o, keep, start ? &start->state : nullptr, start);
  const double slope = mean_slope(k);
  refine(p, which, o, std::move(k), slope, keep, h);
  h.seconds = seconds_since(t0);
  return h;
}

HopfPoint hopf_point_from(const NsParams& p, HopfParameter which, double at, double A, double B,
                          const HopfOptions& o, const HopfStart& start,
                          const std::function<void(const HopfEvaluation&)>& progress) {
  check_search(which, A, B, o);
  if (!(at >= A && at <= B))
    throw std::invalid_argument(fmt::format("onset of shedding: the predicted crossing {} lies outside {}:{}", at, A, B));
  const auto t0 = std::chrono::steady_clock::now();
  HopfPoint h;
  h.parameter = which;
  const Keep keep = recorder(h, which, progress);
  HopfBracket k;
  k.var = search_variable(which, A, B);
  const bool followed = !start.vector.empty() && start.slope != 0.0 && stepped_ends(p, which, at, A, B, o, keep, start, k);
  // The jump test's slope: the last crossing's, in x (du/dx = 2x in α²), not the steps' own bracket's.
  double slope = std::fabs(start.slope) * (k.var.squared ? 2.0 * at : 1.0);
  if (!followed) {  // the ends' own searches about `at`, Newton from start's state
    const double w = (B - A) / 8.0;
    k = hopf_ends(p, which, std::max(A, at - w), std::min(B, at + w), o, keep, &start.state, nullptr);
    k.var = search_variable(which, A, B);
    slope = mean_slope(k);
  }
  refine(p, which, o, std::move(k), slope, keep, h);
  h.seconds = seconds_since(t0);
  return h;
}

}  // namespace magnus
