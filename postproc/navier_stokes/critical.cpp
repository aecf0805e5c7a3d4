#include "postproc/navier_stokes/critical.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/hopf_steady.hpp"
#include "postproc/navier_stokes/regula_falsi.hpp"
#include "solver/navier_stokes/stepper_eigen.hpp"

namespace magnus {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// A followed pair whose eigenvector is less parallel than this to the one it follows is taken for another
/// mode (the far field's slow pairs crowd the axis where the wake's pair crosses it).
constexpr double kFollowOverlap = 0.5;

/// e's eigenvalues by one shift-invert search at `near` (U/D), and its mode: with `like` (the pair's
/// eigenvector at a neighbouring point) the pair whose eigenvector is most nearly parallel to it, from an
/// Arnoldi started there (11 vectors, at most two restarts); else, or when no pair is parallel enough, the
/// pair nearest `near`. sharp: `near` is already within about 0.01 U/D of the pair (the march's estimate, or
/// extrapolated from two points of the pair), so the nearest Ritz value alone must converge, from the fewest
/// vectors (16).
void track(const NsParams& p, HopfParameter which, HopfEvaluation& e, std::complex<double> near,
           const HopfOptions& o, bool sharp = false, const std::vector<std::complex<double>>* like = nullptr) {
  const bool follow = like && !like->empty();
  StabilityOptions so;
  so.eigensolver = o.full.eigensolver;
  so.shifts = {near};
  so.extra_shifts = 0;
  so.want = sharp || follow ? 1 : 2;
  so.krylov = follow ? 11 : sharp ? 16 : o.track_krylov;
  if (follow)
    so.follow = *like, so.restarts = 2;
  else
    so.follow_near = near;
  // Following: the pair alone is wanted, so 11 vectors (leading_eigenvalues keeps count + 10 at least).
  e.stability = leading_eigenvalues(with_parameter(p, which, e.x), e.state, follow ? 1 : o.count, so);
  StabilityResult& r = e.stability;
  if (follow && !(r.followed_overlap >= kFollowOverlap && r.followed.imag() > 0.0)) {
    const double seconds = r.seconds, overlap = r.followed_overlap;
    track(p, which, e, near, o, sharp);  // another mode: the pair nearest the prediction instead
    e.stability.seconds += seconds;
    e.overlap = overlap;  // not followed
    return;
  }
  e.mode = r.followed.imag() > 0.0 ? r.followed : 0.0;
  e.vector = std::move(r.followed_vector);
  r.followed_vector.clear();
  e.overlap = r.followed_overlap;
  e.tracked = true;
}

/// The steady state at x (steady_at) and how long Newton took; no eigenvalues yet.
HopfEvaluation steady_point(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                            const NsState* guess, bool potential_first = false) {
  if (!(p.U > 0.0)) throw std::invalid_argument("onset of shedding: flow.speed must be > 0 (α = aω/U, Re = 2aU/ν)");
  HopfEvaluation e;
  e.x = x;
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<NsState> s = steady_at(p, which, x, from, guess, potential_first);
  e.newton_seconds = seconds_since(t0);
  e.converged = s.has_value();
  if (e.converged) e.state = std::move(*s);
  return e;
}

/// e's eigenvalues by the full search, and its leading pair as the mode.
void full_search(const NsParams& p, HopfParameter which, HopfEvaluation& e, const HopfOptions& o) {
  e.stability = leading_eigenvalues(with_parameter(p, which, e.x), e.state, o.count, o.full);
  e.mode = e.stability.leading_pair().value_or(0.0);
  e.tracked = false;
}

/// e's growing pair without the full search: the linearised march's rightmost growing pair (Arnoldi,
/// stepper_eigen.hpp), then the Jacobian's pair nearest it by one tracked shift. False, e's eigenvalues
/// unset, when the march finds no growing pair, or the Jacobian's nearest pair does not grow or lies more than
/// 0.05 U/D from it (another mode: the full search decides then).
bool seeded_search(const NsParams& p, HopfParameter which, HopfEvaluation& e, const HopfOptions& o) {
  if (!o.seed_ends) return false;
  const StepperEigenResult r = stepper_eigenvalues(with_parameter(p, which, e.x), e.state, o.seed);
  const auto pair = r.leading_pair();
  if (!pair || pair->real() <= 0.0) return false;
  HopfEvaluation t = e;
  track(p, which, t, *pair, o, true);
  if (t.mode == 0.0 || t.growth() < 0.0 || std::abs(t.mode - *pair) > 0.05) return false;
  t.stability.seconds += r.seconds;
  t.seeded = true;
  e = std::move(t);
  return true;
}

}  // namespace

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
    track(p, which, e, *near, o);
  else
    full_search(p, which, e, o);
  return e;
}

namespace {

/// The bracket of a Hopf search and its Illinois weights; lo is the end at the smaller x.
struct HopfBracket {
  HopfEvaluation lo, hi;
  Illinois weights;  ///< end 0 is lo, end 1 hi
  double root() const { return weights.root(lo.x, lo.growth(), hi.x, hi.growth()); }
  /// The next point: the secant through the last two points solved inside the bracket when it falls inside
  /// the current one (superlinear, and blind to the far ends' curvature), else the Illinois root.
  double next_root(const std::vector<std::pair<double, double>>& inside) const {
    if (inside.size() >= 2) {
      const auto &a = inside[inside.size() - 2], &b = inside.back();
      const double s = secant_zero(a.first, a.second, b.first, b.second);
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
    return a.second + (a.second - b.second) * ((x - a.first) / (a.first - b.first));
  }
  /// Adds e to the lineage when it grows.
  void note(const HopfEvaluation& e) {
    if (e.growth() >= 0.0) lineage.emplace_back(e.x, e.mode);
  }
  /// The steady state at x by linear interpolation between the ends' (Newton's start there): closer than
  /// the nearer end's by the bracket's curvature term.
  NsState state_at(double x) const { return blend(lo.state, hi.state, (x - lo.x) / (hi.x - lo.x)); }
  /// The pair at x by linear interpolation between the ends, U/D.
  std::complex<double> pair_at(double x) const { return lo.mode + (hi.mode - lo.mode) * ((x - lo.x) / (hi.x - lo.x)); }
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

/// The ends solved: each checked and recorded by `keep` (A's already when a_kept), noted, and their growth
/// rates required to differ in sign.
HopfBracket checked_ends(HopfBracket k, HopfParameter which, double A, double B,
                         const std::function<void(const HopfEvaluation&)>& keep, bool a_kept = false) {
  if (!a_kept) keep(k.lo);
  keep(k.hi);
  k.note(k.lo), k.note(k.hi);
  if ((k.lo.growth() < 0.0) == (k.hi.growth() < 0.0))
    throw NoCrossing(fmt::format(
                         "onset of shedding over {} {:g}:{:g}: the leading growth rate does not change sign (Re "
                         "λ·D/U = {:.4g} at {:g}, {:.4g} at {:g}): widen or move the bracket",
                         hopf_parameter_name(which), A, B, k.lo.growth(), A, k.hi.growth(), B),
                     A, k.lo.growth(), B, k.hi.growth());
  return k;
}

/// The ends A and B with the same pair at both: the growing pair of the unstable end (seeded_search, or the
/// full search's leading pair), tracked at the other. `keep` checks and records each.
HopfBracket hopf_ends(const NsParams& p, HopfParameter which, double A, double B, const HopfOptions& o,
                      const std::function<void(const HopfEvaluation&)>& keep, const HopfStart* start) {
  HopfBracket k;
  const NsState* guess = start ? &start->state : nullptr;
  k.lo = steady_point(p, which, A, nullptr, guess);
  if (!k.lo.converged) keep(k.lo);  // throws: no steady state at A
  if (start && !start->vector.empty()) {  // both ends' pairs followed from the neighbouring crossing's
    track(p, which, k.lo, start->lambda, o, false, &start->vector);
    const bool lo_followed = k.lo.overlap >= kFollowOverlap && k.lo.mode != 0.0;
    k.hi = steady_point(p, which, B, &k.lo, guess);
    if (k.hi.converged)  // from A's pair where it was followed there
      track(p, which, k.hi, lo_followed ? k.lo.mode : start->lambda, o, false, lo_followed ? &k.lo.vector : &start->vector);
    // B's pair where it is not parallel enough to A's: the pair nearest A's, as the searched ends take it.
    if (lo_followed && k.hi.mode != 0.0) return checked_ends(std::move(k), which, A, B, keep);
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
      track(p, which, k.hi, k.lo.mode, o);
    else
      full_search(p, which, k.hi, o);
  }
  if (!a_unstable && k.lo.converged && k.hi.converged && k.hi.mode != 0.0 && k.hi.growth() >= 0.0)
    track(p, which, k.lo, k.hi.mode, o);  // the stable end's eigenvalues at the mode that turns unstable
  return checked_ends(std::move(k), which, A, B, keep, a_unstable);
}

}  // namespace

HopfPoint hopf_point(const NsParams& p, HopfParameter which, double A, double B, const HopfOptions& o,
                     const std::function<void(const HopfEvaluation&)>& progress, const HopfStart* start) {
  const char* name = hopf_parameter_name(which);
  if (!std::isfinite(A) || !std::isfinite(B) || (which == HopfParameter::reynolds && !(A > 0.0)))
    throw std::invalid_argument(fmt::format("onset of shedding: the {} bracket needs finite values{} (got {}:{})",
                                            name, which == HopfParameter::reynolds ? " > 0" : "", A, B));
  if (!(A < B)) throw std::invalid_argument(fmt::format("onset of shedding: the {} bracket needs A < B (got {}:{})", name, A, B));
  if (!(o.tol > 0.0)) throw std::invalid_argument(fmt::format("--tolerance must be > 0 (got {})", o.tol));
  const auto t0 = std::chrono::steady_clock::now();
  HopfPoint h;
  h.parameter = which;
  auto keep = [&](const HopfEvaluation& e) {
    if (!e.converged)
      throw std::runtime_error(fmt::format("onset of shedding: Newton's method found no steady state at {} = {:g}, "
                                           "continuing from the nearest state solved", name, e.x));
    if (e.mode == 0.0)
      throw std::runtime_error(fmt::format("onset of shedding: no complex pair (the wake's mode) was found at {} = "
                                           "{:g} ({})", name, e.x, e.stability.message));
    if (progress) progress(e);
    h.evaluations.push_back(without_state(e));
  };
  HopfBracket k = hopf_ends(p, which, A, B, o, keep, start);
  h.at_a = without_state(k.lo), h.at_b = without_state(k.hi);
  HopfEvaluation far = k.lo.growth() < 0.0 ? k.lo : k.hi;  // the stable end asked for, with its state
  const double slope = std::fabs(h.at_b.growth() - h.at_a.growth()) / (h.at_b.x - h.at_a.x);
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
      if (m.converged) track(p, which, m, k.predict(root), o, k.lineage.size() >= 2, &from.vector);
      keep(m);
      k.note(m);
      latest.emplace_back(m.x, m.growth());
      k.replace(std::move(m));
      const double next = k.next_root(latest);
      h.change = std::fabs(next - root);
      root = next;
    }
    // A crossing the secant can trust: across the final bracket the growth rate changes no faster than
    // ten times its mean slope over [A, B]. A jump instead is the stable end's pair being another mode
    // (tracked from a poor prediction: it is tracked again, at most twice), or a fold of the steady branch.
    if (std::fabs(k.hi.growth() - k.lo.growth()) <= 10.0 * slope * (k.hi.x - k.lo.x) + 1e-9) break;
    if (repairs == 2)
      throw std::runtime_error(fmt::format(
          "onset of shedding: the growth rate jumps from {:+.4g} at {} = {:g} to {:+.4g} at {:g} (U/D) instead of "
          "crossing zero: a fold of the steady branch or a change of the tracked mode, not a Hopf point",
          k.lo.growth(), name, k.lo.x, k.hi.growth(), k.hi.x));
    HopfEvaluation& stable = k.lo.growth() < 0.0 ? k.lo : k.hi;
    track(p, which, stable, k.predict(stable.x), o);
    keep(stable);
    if (stable.growth() >= 0.0) {  // the wanted pair still grows there: bracket it with the far end again
      k.note(stable);
      track(p, which, far, k.predict(far.x), o);
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
  h.next = {nearest.state, nearest.mode, nearest.vector};
  h.seconds = seconds_since(t0);
  return h;
}

}  // namespace magnus
