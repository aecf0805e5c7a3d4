#pragma once
// The onset of three-dimensionality: the Reynolds number, at the case's spin ratio, where the most unstable
// spanwise wavenumber's growth rate crosses zero (the spanwise-uniform flow stops being real), and that
// wavenumber. Each Reynolds number is one spanwise_stability scan: of the steady state when it is stable,
// else of the shedding orbit. The crossing is found by regula falsi (Illinois) on the scan's growth rate,
// with a bisection after any step that does not halve the bracket.
#include <functional>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "postproc/navier_stokes/spanwise_scan.hpp"
#include "postproc/result.hpp"

namespace magnus {

/// One Reynolds number of the search and its scan.
struct SpanwiseEvaluation {
  double Re = 0.0;
  SpanwiseScan scan;
  double seconds = 0.0;  ///< wall time of the steady state, its 2D eigenvalues and the scan, s
};

/// The crossing.
struct SpanwiseCritical {
  bool found = false;        ///< the growth rate changed sign inside [Re_a, Re_b] and the search converged
  std::string message;       ///< why not, when !found
  double Re_c = 0.0;         ///< the critical Reynolds number (the last regula falsi root)
  double change = 0.0;       ///< |last move of the root|, or the bracket when that is smaller
  double lo = 0.0, hi = 0.0; ///< the last bracket (growth rate < 0 at lo, > 0 at hi)
  double beta_D = 0.0;       ///< the most unstable β·D at the crossing (linear in Re between lo and hi)
  double wavelength_D() const;  ///< 2π/(β·D): the critical spanwise wavelength in D (0: undefined)
  std::vector<SpanwiseEvaluation> evaluations;  ///< in the order solved
  double seconds = 0.0;
};

/// The crossing in [Re_a, Re_b] (0 < Re_a < Re_b) to within tol (> 0, in Re) at the wavenumbers beta_D;
/// at most max_evaluations scans. on_evaluation after each. Throws std::invalid_argument for a bad range.
SpanwiseCritical spanwise_critical(const NsParams& p, const std::vector<double>& beta_D, double Re_a, double Re_b,
                                   double tol, const std::string& eigensolver, int max_evaluations = 10,
                                   const std::function<void(const SpanwiseEvaluation&)>& on_evaluation = {});

/// The onset on a finer grid, from a search on a coarser one (spanwise_critical_fine).
struct SpanwiseFine {
  bool found = false;
  std::string message;                          ///< why not, when !found (a scan that failed, named by Re)
  std::vector<SpanwiseEvaluation> evaluations;  ///< the fine grid's two scans, the lower Re first
  /// The fine grid's onset, fine_onset of its two scans with the coarse search's curvature g'' (the second
  /// difference of its three scans nearest its onset).
  double Re_c = 0.0;
  double line_Re_c = 0.0;  ///< the straight line's zero through the two scans (g'' = 0)
  /// Its error estimate in Re: what the two growth rates' Arnoldi tolerance (kFloquetTolerance,
  /// kFloquetRelative) may move the line's zero by, plus FineRoot::correction. It leaves out the grid's own
  /// error and that of keeping the coarse wavenumber.
  double bar = 0.0;
  bool extrapolated = false;  ///< Re_c lies more than half the scans' spacing outside them
  double beta_D = 0.0;        ///< the wavenumber scanned: the coarse search's at its onset
  double seconds = 0.0;       ///< wall time of the two scans (at once), s
};

/// The zero of a growth rate g(Re) known at two Reynolds numbers, with a curvature g'' from elsewhere.
struct FineRoot {
  bool found = false;  ///< Re_1 < Re_2 and g rises between them
  double line = 0.0;   ///< the straight line's zero, Re_1 − g_1(Re_2 − Re_1)/(g_2 − g_1)
  /// The parabola through both with curvature g'' has a zero where it rises, within Re_2 − Re_1 of the
  /// line's.
  bool parabola = false;
  double Re_c = 0.0;  ///< the parabola's zero when it has one, else the line's
  /// |Re_c − line| for the parabola; for the line alone its error ½|g''|·|(x − Re_1)(x − Re_2)|/s at its zero
  /// x (s the line's slope).
  double correction = 0.0;
};

/// The zero of g(Re) = g_1 + s(Re − Re_1) + ½g''(Re − Re_1)(Re − Re_2), s = (g_2 − g_1)/(Re_2 − Re_1), where
/// it rises (g in U/D, g'' = curvature in (U/D) per unit of Re²).
FineRoot fine_onset(double Re_1, double g_1, double Re_2, double g_2, double curvature);

/// The 3D onset on the grid of `fine` from the search c (found) on the grid of `coarse`: the fine grid's
/// scans at c.Re_c and 2% above it, at c's wavenumber only, both at once (one thread each), each Floquet
/// Arnoldi started from the coarse mode of the scan nearest its Re (at the wavenumber nearest c's), sampled
/// onto the fine grid (spanwise_prolong). Where the coarse scan nearest c.Re_c was of a shedding orbit, the
/// fine scans go straight to the orbit (no steady state and 2D eigenvalues first). A scan that fails, or a
/// Floquet multiplier that does not converge, leaves it not found with the reason. Throws
/// std::invalid_argument when c was not found.
SpanwiseFine spanwise_critical_fine(const NsParams& coarse, const SpanwiseCritical& c, const NsParams& fine,
                                    const std::string& eigensolver);

/// The case overrides that give the fine grid of spanwise_critical_fine, n_θ n and R = R_over_a·a (its rings
/// following n_θ: grid.n_r = 0), from p's grid. Throws std::invalid_argument, one line starting with `what`
/// (how the user gave it), unless n is an even whole number in [8, 4096] and R_over_a in (1, 10000], neither
/// below p's and not both equal to them.
std::vector<std::string> fine_grid_overrides(double n, double R_over_a, const NsParams& p,
                                             const std::string& what);

/// A computed point of the 3D onset curve: at spin ratio α the flow turns three-dimensional at Re_c.
struct Onset3d {
  double alpha = 0.0, Re_c = 0.0;
};

/// The computed onset Re_c(α) at spin ratio α: linear in α between the curve's points (sorted or not; one
/// point answers only at its own α, to 1e-9). Undefined (nullopt) outside the α the curve spans.
std::optional<double> onset_reynolds(double alpha, const std::vector<Onset3d>& curve);

/// The smallest and largest spin ratio of the curve's points (a non-empty curve).
std::pair<double, double> onset_alpha_range(const std::vector<Onset3d>& curve);

/// Set v's onset3d_* from the computed curve (read from files) at spin ratio α: Re_c there, the α it spans
/// and the files' names. An empty curve leaves them unset.
void set_onset3d(ViscousPart& v, double alpha, const std::vector<Onset3d>& curve,
                 const std::vector<std::string>& files);

/// Whether the 2D flow at (Re, α) is real by the computed onset curve: Re < onset_reynolds(α, curve);
/// undefined where that is.
std::optional<bool> two_d_is_real(double Re, double alpha, const std::vector<Onset3d>& curve);

}  // namespace magnus
