#pragma once
// Steady viscous states continued along the spin ratio, and the S(Re, α) map built from them.
//
// One Reynolds number is one row: its steady branch is walked in α with one SteadyJacobian (the symbolic
// LU analysis is done once per row). The steady equations F(x; ω) are affine in ω (ω enters only the wall
// rows, through Thom's ψ_ξ = −a²ω), so the row keeps ∂F/∂ω once and runs its own Newton iteration with
// F(x; ω_k) = F(x; ω_0) + (ω_k − ω_0)·∂F/∂ω on the row's Jacobian. Each point starts from the secant
// extrapolation of the two previous solutions. When that Newton fails, the row switches to pseudo-arclength
// continuation (Keller) from the last converged point towards the target α; if the branch tangent's α
// component changes sign on the way (a fold), the branch turns back before the target: the point is marked
// (fold) and gets no steady state. Rows are independent: they run in parallel and are the unit of a shard.
// A map of one spin ratio over several Re is one branch continued in Re instead: its rows run in order, each
// starting from the previous row's steady state.
//
// Per point: steady forces (C_L, C_D, C_M and their pressure and friction parts), the ideal C_L = −2πα,
// the ratio C_L/C_L,ideal = S/(2πρa²), and "stable" from a stability hook. A point whose steady state is
// unstable (or that has none) is marched in time from rest (run_case on its case) and reports what the
// march gives: the time-averaged C_L, C_D, C_M and St of a shedding wake, or the steady state the march
// settles on, and is marked so; with NsMapOptions::orbits it is first sought as its periodic orbit
// (map_orbits.hpp), and the means over one period are reported.
#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/scene.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// A stability hook's verdict on a steady state.
struct StabilityVerdict {
  std::optional<bool> stable;  ///< true stable, false unstable, empty when undecided
  /// The leading eigenvalue when it is a growing pair (the wake's Hopf mode; Im λ > 0 member, U/D), with its
  /// mode as StabilityResult holds it (ψ, ζ row-major, Γ_R; max |ζ| = 1): the start of the shedding orbit
  /// (hopf_start). Empty when the hook found none (or does not compute modes).
  std::optional<std::complex<double>> pair;
  std::vector<std::complex<double>> mode_psi, mode_zeta;
  std::complex<double> mode_Gamma_R;
  StabilityVerdict(std::optional<bool> s = std::nullopt) : stable(s) {}  // NOLINT: a bare verdict converts
};

/// Linear stability of a steady state.
using StabilityHook = std::function<StabilityVerdict(const NsParams&, const NsState&)>;

/// The time stepper's verdict (marched_growth_rate, stepper_verdict.hpp): stable when σ·D/U < −margin,
/// unstable when > margin, else undecided. A cheap verdict (the linearised time stepper's growth, measured);
/// make_stability_hook's default is the Jacobian's leading eigenvalues.
std::optional<bool> stability_by_marching(const NsParams& p, const NsState& steady, double span = 30.0,
                                          double margin = 2e-3);

/// Where a map point's reported C_L, C_D, C_M come from. A point whose continued steady state is unstable
/// (or that has none) is marched in time from rest: the flow then sheds (time-averaged), or settles on a
/// stable steady state of its own, another branch than the continued one (marched_steady); or, with
/// NsMapOptions::orbits, it is its shedding orbit (orbit).
enum class MapSource {
  steady = 0,
  averaged_unstable = 1,
  averaged_no_steady = 2,
  none = 3,
  marched_steady = 4,
  orbit = 5  ///< the means over one period of the shedding orbit, by shooting (NsMapOptions::orbits)
};
const char* to_string(MapSource);

/// What the flow does at a map point (NsMapPoint::regime).
enum class MapRegime {
  steady = 0,         ///< a stable steady state (the continued one, or the one a march from rest settles on)
  shedding = 1,       ///< the wake sheds (the first window: from the onset of shedding up to α_L)
  second_window = 2,  ///< shedding again after a steady stretch of the row, at under half the first window's
                      ///< frequency: the one-sided "second shedding mode" of high spin
  bistable = 3        ///< a stable steady state and a shedding orbit coexist (--orbits: the row's orbit,
                      ///< continued into the point, persists, forwards past α_L or backwards below a
                      ///< subcritical Hopf point; its own stability is not tested; the steady values are
                      ///< reported)
};

/// One point of the map. Undefined values are NaN.
struct NsMapPoint {
  int row = 0, column = 0;                 ///< index of Re and of α in the map's axes
  double reynolds = 0.0, alpha = 0.0;      ///< Re = U·2a/ν, α = aω/U
  bool converged = false;                  ///< the steady branch reached this α
  bool fold = false;                       ///< the branch turned back (a fold) before this α
  int newton_steps = 0;                    ///< Newton steps (plain and corrector steps of arclength)
  int arclength_steps = 0;                 ///< pseudo-arclength steps needed to reach this α
  std::optional<bool> stable;              ///< of the steady state (empty: not decided or no hook)
  MapSource source = MapSource::none;      ///< what cl, cd, cm are
  double cl, cd, cm;                       ///< the reported coefficients (steady or time-averaged)
  double cl_steady, cd_steady, cm_steady;  ///< the steady state's, NaN without one
  double cl_pressure, cl_friction, cd_pressure, cd_friction;  ///< the steady state's parts
  double strouhal;                                            ///< time-averaged periodic points only
  double cl_ideal;                                            ///< potential flow, −2πα
  double ratio;  ///< cl / cl_ideal = S/(2πρa²) (NaN at α = 0)
  /// The point's own error bars, relative: |f − f_c|/|f| against the same point on the grid twice as
  /// coarse (a steady state: Newton there from this one; a marched point: its companion march, plus the
  /// spread of means that had not converged). NaN where undefined (|f| < 1e-3, no companion).
  double cl_rel_estimate, cd_rel_estimate, strouhal_rel_estimate;
  /// 1 when the bars are within the default grid's design tolerances (C_L and St 1%, C_D 2%), 0 when one
  /// is not, NaN when C_D's bar is undefined.
  double meets_tolerance;
  /// MapRegime as a number (NaN: not classified, when stability was not decided or nothing was found).
  double regime;
  double seconds = 0.0;  ///< wall time of this point (steady, stability, averaging)
  /// An orbit point only (not written to the map's files): how its orbit started ("continued", "hopf mode",
  /// "rest") and the periods of time steps it cost (short march, Newton's residuals and GMRES products; the
  /// summary reuses the last residual's period).
  std::string orbit_start;
  double orbit_periods = 0.0;
};

/// What to compute.
struct NsMapOptions {
  std::vector<double> alphas;    ///< α, ascending (the continuation direction)
  std::vector<double> reynolds;  ///< Re; empty: the case's own
  int shard = 1, shards = 1;     ///< compute only rows r with r % shards == shard − 1
  int threads = 1;               ///< rows computed at once (std::thread)
  StabilityHook stability;       ///< empty: stable undefined (then no averaging either)
  /// How `stability` decides, kept with the map: "eigenvalues", "march", or "none" (no hook).
  std::string stability_method = "none";
  bool average_unstable = true;  ///< march unstable points and points without a steady state from rest
  bool error_estimate = true;    ///< each point's error bars from the grid twice as coarse (NsMapPoint)
  /// A shedding point (steady state unstable, or none) as its periodic orbit by Newton–GMRES shooting
  /// instead of a march from rest: continued from the row's previous point when that was an orbit too (in a
  /// map continued in Re, from the previous Re's),
  /// else from the steady state plus its growing pair's mode (hopf_start), else from rest; a point where no
  /// orbit is found (the start settles, or Newton stalls) is marched from rest as without this option.
  bool orbits = false;
  double orbit_tol = 1e-7;       ///< the orbits' Newton residual (OrbitOptions::tol)
  double newton_tol = 1e-10;     ///< scaled max-norm residual
  int newton_max = 12;           ///< Newton steps per solve before arclength takes over
  int max_arclength_steps = 40;  ///< per gap between two α
  int corrector_max = 8;         ///< Newton steps of an arclength corrector (and of its landing)
  /// Progress, after each point (called from the worker threads, one at a time).
  std::function<void(const NsMapPoint&)> on_point;
};

/// The map (or the shard of it that was computed).
struct NsMap {
  Case base;                 ///< the resolved case
  int n_theta = 0, n_r = 0;  ///< the grid
  double outer_over_a = 0.0;
  std::vector<double> alphas, reynolds;  ///< the whole map's axes
  int shard = 1, shards = 1;
  std::string stability_method = "none";  ///< "eigenvalues", "march" or "none"; "" in files that predate it
  bool averaged = true;                   ///< unstable points were marched (not --steady-only)
  bool orbits = false;                    ///< shedding points as periodic orbits (NsMapOptions::orbits)
  std::vector<NsMapPoint> points;         ///< the computed rows, row-major (row, then column)
  int threads = 1;
  double total_s = 0.0;
  /// One spin ratio and several Reynolds numbers: the branch is continued in Re (each row starts from the
  /// previous row's steady state), not in α.
  bool continued_in_re() const { return alphas.size() == 1 && reynolds.size() > 1; }
};

/// Whether a point's bars are within the default grid's design tolerances (C_L and St kRuleTolerance = 1%,
/// C_D 2%): 1 yes, 0 when one is not, NaN when a reported value has no bar (C_L counts only when
/// |C_L| ≥ 1e-3, where a relative bar is defined; St only for a shedding point).
double meets_tolerance(const NsMapPoint& m);

/// The case of one map point: the base with ω = αU/a and ν = U·2a/Re (flow.reynolds = Re).
Case map_point_case(const Case& base, double reynolds, double alpha);

/// Rows of the map in shard k of n (1 ≤ k ≤ n ≤ number of rows). Throws std::invalid_argument (one line).
std::vector<int> shard_rows(int rows, int shard, int shards);

/// The map: every row of the shard, `threads` rows at a time. Throws std::invalid_argument for a case that
/// is not navier-stokes, U = 0, unsorted α, Re ≤ 0, or a bad shard.
NsMap ns_map(const Case& c, const NsMapOptions& o);

/// How a map decides stability: the leading eigenvalues of the steady Jacobian (solver/ns_stability:
/// shift-invert Arnoldi, exact for the discrete equations), or stability_by_marching (cheaper on coarse
/// grids, can be undecided when the growth rate is within its margin of 0).
enum class StabilityMethod { eigenvalues, march };

/// The stability hook of a method: its verdict's stable is true, false, or empty when undecided or failed;
/// with eigenvalues it also carries the growing pair and its mode when the leading eigenvalue is one.
StabilityHook make_stability_hook(StabilityMethod m = StabilityMethod::eigenvalues);

// --- pseudo-arclength continuation on an abstract problem F(x, λ) = 0 (tested on known curves) ---

/// F, ∂F/∂λ and linear solves with J = ∂F/∂x. factor(x, λ) precedes solve(b) = J⁻¹b at that point.
struct ArclengthProblem {
  std::function<std::vector<double>(const std::vector<double>&, double)> residual;
  std::function<std::vector<double>(const std::vector<double>&, double)> d_lambda;
  std::function<void(const std::vector<double>&, double)> factor;
  std::function<std::vector<double>(const std::vector<double>&)> solve;
  std::function<double(const std::vector<double>&)> norm;  ///< of a residual (max-norm when empty)
  std::vector<double> weight;  ///< inner product Σ w_i dx_i dy_i + dλ dμ (empty: w = 1)
};

/// A point on the curve with its unit tangent (in the weighted norm), oriented.
struct ArclengthPoint {
  std::vector<double> x;
  double lambda = 0.0;
  std::vector<double> tx;
  double tl = 0.0;
};

/// The tangent at a solution (x, λ): J z = −∂F/∂λ, t = (z, 1)/|·|, oriented along `towards` (its sign: +1
/// increasing λ; or the previous tangent's direction when `previous` is given).
ArclengthPoint arclength_tangent(const ArclengthProblem& f, const std::vector<double>& x, double lambda,
                                 double towards, const ArclengthPoint* previous = nullptr);

/// One step of length ds: predictor along the tangent, Newton corrector on F = 0 and
/// ⟨t, (x − x0, λ − λ0)⟩ = ds (bordering). Returns false when the corrector does not converge to tol in
/// max_iter steps; iterations counts its Newton steps.
bool arclength_step(const ArclengthProblem& f, const ArclengthPoint& from, double ds, double tol,
                    int max_iter, ArclengthPoint& to, int& iterations);

}  // namespace magnus
