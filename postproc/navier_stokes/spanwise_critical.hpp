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
