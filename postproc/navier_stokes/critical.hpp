#pragma once
// The onset of shedding as a computed point: where the steady state's leading complex pair (the wake's
// Hopf mode) crosses the imaginary axis, Re λ(x) = 0, along the spin ratio x = α (the critical spin α_L
// above which shedding stops) or the Reynolds number x = Re (Re_c, where it starts). The search is a
// secant iteration on Re λ (in α², where Re λ is even in α, SearchVariable), kept inside its sign-change bracket (the secant through the last two points
// when it falls inside, else regula falsi with the Illinois weight), not bisection: it converges
// superlinearly. Every steady state comes by Newton's method from the state
// interpolated between the bracket's ends (else by natural continuation from the nearest state solved, the
// step halved where Newton fails), and only the
// ends of the bracket get a search of their own: between them the pair is tracked by one shift-invert
// search at its predicted position, which keeps the pair whose eigenvector is most nearly parallel to the
// nearer end's (the far field's slow pairs crowd the axis where the wake's pair crosses it, so the pair
// nearest the prediction may be one of them). An end's growing pair is first sought by Arnoldi on the
// linearised march (stepper_eigen.hpp: no factorisation), then tracked there; only where that finds no
// growing pair does an end get the full shift-invert search. A search started from a neighbouring one's
// crossing (HopfStart: the curves of onset_curve.hpp) follows that crossing's pair to both ends instead, or
// (hopf_point_from) steps from a predicted crossing until the growth rate changes sign.
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/stability.hpp"
#include "solver/navier_stokes/stepper_eigen.hpp"

namespace magnus {

/// The parameter a Hopf search moves.
enum class HopfParameter {
  spin_ratio,  ///< α = aω/U (ω = αU/a changes; Re fixed)
  reynolds     ///< Re = 2aU/ν (ν = 2aU/Re changes; α fixed)
};

/// "spin ratio α" or "Reynolds number Re", for messages.
const char* hopf_parameter_name(HopfParameter which);

/// p with the parameter set to x: ω = x·U/a (spin ratio) or ν = 2aU/x (Reynolds number).
NsParams with_parameter(const NsParams& p, HopfParameter which, double x);

/// The variable a search solves in, u: α² for the spin ratio over a range that reaches down near α = 0
/// (0 ≤ A < B − A: the flow at −α is the mirror image of the flow at α, so Re λ is a smooth, even function
/// of α, flat in α near α = 0 but nearly linear in α²), else u = x (away from α = 0 the square only adds
/// curvature: at Re 100 over 1.6:2.2 the growth rate is already convex in α).
struct SearchVariable {
  bool squared = false;  ///< u = x² (else u = x)
  double u(double x) const { return squared ? x * x : x; }
  double x(double u) const { return squared ? std::sqrt(std::max(u, 0.0)) : u; }
};

/// The search variable of `which` over the range [A, B].
SearchVariable search_variable(HopfParameter which, double A, double B);

/// One point of the search: its steady state and that state's eigenvalues.
struct HopfEvaluation {
  double x = 0.0;          ///< the parameter's value (α or Re)
  bool converged = false;  ///< Newton reached a steady state (else stability is empty)
  NsState state;           ///< the steady state (the last iterate when not converged)
  StabilityResult stability;
  double newton_seconds = 0.0;  ///< wall time of the Newton solves (continuation steps included), s
  std::complex<double> mode;    ///< the tracked pair's member with Im λ > 0, U/D (0 when none was found)
  bool tracked = false;         ///< the eigenvalues from one shift at the predicted pair, not the full search
  bool seeded = false;          ///< that shift placed at the pair the linearised march found (stepper_eigen.hpp)
  /// The tracked pair's eigenvector (SteadyJacobian's unknowns; empty when it was not tracked): the next
  /// point's search starts from it and keeps the pair most nearly parallel to it.
  std::vector<std::complex<double>> vector;
  /// |f^H x|/(‖f‖‖x‖) with the vector f it followed; 1 when tracked without one (the pair nearest the
  /// prediction), 0 after the full search alone; below 0.5 after following, no pair was parallel enough and
  /// the mode is the pair nearest the prediction.
  double overlap = 0.0;
  /// Re λ of the tracked pair, U/D: the slow real far-field modes near −0.002 would otherwise bias the crossing.
  double growth() const { return mode.real(); }
};

/// Where a search starts from a neighbouring one's crossing (other parameters, the same grid): Newton from
/// its steady state, and both ends' pairs followed from its pair (one shift each at λ, the eigenvector most
/// nearly parallel to `vector` kept) instead of searched for.
struct HopfStart {
  NsState state;                               ///< a steady state near the crossing
  std::complex<double> lambda;                 ///< its wake pair (Im λ > 0), U/D
  std::vector<std::complex<double>> vector;    ///< that pair's eigenvector (empty: Newton's start only)
  /// d(Re λ)/du across the crossing's final bracket (u of SearchVariable), U/D per unit of u; 0: unknown.
  /// In the u of the range that search ran over: a search started from it must run over the same range
  /// (the curves of onset_curve.hpp do).
  double slope = 0.0;
};

/// The crossing Re λ(x_c) = 0 and how it was found.
struct HopfPoint {
  HopfParameter parameter = HopfParameter::spin_ratio;
  double x_c = 0.0;              ///< the crossing: the secant root inside the final bracket
  double lo = 0.0, hi = 0.0;     ///< final bracket: Re λ changes sign between them
  double change = 0.0;           ///< |x_c − the previous secant root|: the search's own error estimate
  std::complex<double> lambda;   ///< the pair at x_c (interpolated), U/D: Im λ = 2π·St of the onset
  HopfEvaluation at_a, at_b;     ///< the first sign-change bracket: the ends asked for, or stepped to (states dropped)
  std::vector<HopfEvaluation> evaluations;  ///< every point solved, in order (states dropped)
  double seconds = 0.0;          ///< wall time, s
  HopfStart next;                ///< the evaluation nearest x_c: a start for a neighbouring search
  /// Strouhal number of the onset, |Im λ|/(2π) (λ in U/D).
  double strouhal() const;
};

/// How the search stops and tracks.
struct HopfOptions {
  double tol = 0.01;   ///< stop when the secant root moves by at most tol/2, or the bracket is ≤ tol
  int max_evaluations = 24;
  int count = 6;       ///< eigenvalues kept per full search
  int track_krylov = 24;  ///< Arnoldi vectors of a tracking search (one shift at the predicted pair)
  /// The full search at the ends, auto's cheaper one: the pair wanted leads at the unstable end. Its shifts
  /// on two threads (a search's points are solved one after another).
  StabilityOptions full = lone_search(quick_stability_options());
  /// Seek a growing pair at the ends first by Arnoldi on the linearised march, then one tracked shift there
  /// (at Re 100 on the scene's grid: 25 products and 17 solves instead of five shifts and 529 solves).
  bool seed_ends = true;
  /// That Arnoldi: the march over 2 D/U per product (|μ| = e^{2 Re λ}; frequencies up to Im λ·D/U = π/2),
  /// stopped when the leading pair's estimate is 6% of |μ|: its λ is then within about 0.01 U/D (at Re 100,
  /// α 1.6: 0.006 after 25 products; the estimate bounds the residual, not the eigenvalue's error), and the
  /// tracked shift there finds the Jacobian's.
  StepperEigenOptions seed = [] {
    StepperEigenOptions s;
    s.tol = 6e-2;
    return s;
  }();
};

/// The steady state at parameter value x and its eigenvalues. The state: Newton from `guess` (a state of
/// other parameters on the same grid, or one interpolated between two) when given; else by continuation
/// from `from` (a converged point of the same search) in steps halved where Newton fails; else Newton from
/// potential_guess, then by continuation from the safe end (α = 0, or Re = 20). Newton takes chord steps
/// (NewtonOptions::chord_ratio 0.1) while they contract ten-fold. The eigenvalues: the full search when `track` is empty, else one
/// shift-invert search at *track (U/D), whose pair nearest it is the mode. Throws std::invalid_argument
/// when U = 0.
HopfEvaluation hopf_evaluation(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                               const std::optional<std::complex<double>>& track, const HopfOptions& o = {},
                               const NsState* guess = nullptr);

/// No crossing on [A, B]: the same pair's growth rate (U/D) has one sign at both ends.
struct NoCrossing : std::invalid_argument {
  double A, growth_a, B, growth_b;
  NoCrossing(const std::string& what, double a, double ga, double b, double gb)
      : std::invalid_argument(what), A(a), growth_a(ga), B(b), growth_b(gb) {}
};

/// The crossing on [A, B] (A < B). Throws NoCrossing (one line, with both growth rates) when Re λ has the
/// same sign at A and B, and std::runtime_error when no steady state or no pair is found at some x.
/// progress (optional) is called after each point; start (optional): a neighbouring search's crossing
/// (HopfStart; where its pair cannot be followed at an end, that end gets its own search).
HopfPoint hopf_point(const NsParams& p, HopfParameter which, double A, double B, const HopfOptions& o = {},
                     const std::function<void(const HopfEvaluation&)>& progress = {},
                     const HopfStart* start = nullptr);

/// The crossing near `at` (A ≤ at ≤ B), started from a neighbouring search's crossing (HopfStart with its
/// vector and slope): the steady state at `at` with start's pair followed there, then steps along the secant
/// of Re λ in u (first with start's slope, then through the last two points), each 1.25 times the distance
/// to the predicted root, at least tol/2 and at most (B − A)/4 in x, until Re λ changes sign (at most four
/// steps); the last two points are the bracket the secant search refines. A prediction within tol/3 of the
/// crossing costs two steady states. Where the pair is not followed at `at`, the search runs as hopf_point's
/// over [at − (B − A)/8, at + (B − A)/8] ∩ [A, B] with start's state alone. Throws NoCrossing (the last two
/// points) when four steps, or steps reaching A or B, keep one sign, and std::runtime_error when a step's
/// pair is not followed (another mode) or no step stays inside [A, B].
HopfPoint hopf_point_from(const NsParams& p, HopfParameter which, double at, double A, double B,
                          const HopfOptions& o, const HopfStart& start,
                          const std::function<void(const HopfEvaluation&)>& progress = {});

}  // namespace magnus
