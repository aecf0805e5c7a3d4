#pragma once
// Where the 2D answer is real: the leading eigenvalue of a steady state's spanwise problem (spanwise.hpp),
// or the leading Floquet multiplier μ of a shedding orbit (floquet.hpp; exponent ln μ/T), over a set of
// wavenumbers β, the most unstable one (a parabola through the three around the largest growth rate) and
// its wavelength λ_z = 2π/β, and the verdict in words.
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "postproc/navier_stokes/critical.hpp"
#include "solver/navier_stokes/spanwise.hpp"

namespace magnus {

/// What is known of the spanwise operator's accuracy (README, "Three-dimensional stability"): stated beside
/// every 3D verdict (text, JSON, HDF5 and Python).
inline constexpr const char* kSpanwiseAccuracyNote =
    "steady bases (BiGlobal): within 1% of an independent primitive-variable solver on the Re 60 wake; "
    "shedding orbits (Floquet): the 3D operator is linearised about the 2D model's orbit, which it does not "
    "solve exactly (that orbit's own phase multiplier comes out 0.84 on n_theta 64, not 1), yet mode A's "
    "onset comes out at Re 187.5, wavelength 3.96 D, on n_theta 64 against the published 188.5 and 3.96 D "
    "(README: three-dimensional stability)";

/// A Floquet multiplier counts as found once its Ritz estimate ‖P x − μ x‖ (unit x) is below
/// kFloquetTolerance (near neutral μ then moves by about 2e-4 more: Re 188 mode A, n_θ 64, 4e-5 U/D in
/// growth rate) or below kFloquetRelative·|1 − |μ|| (far from neutral, where the onset search needs its
/// growth rate only roughly: at Re 175, n_θ 64, it came out 30% from an earlier 30-vector estimate).
inline constexpr double kFloquetTolerance = 1e-3, kFloquetRelative = 0.1;

/// The spanwise wavelength λ_z/D = 2π/(β·D) of the wavenumber β·D; 0 (undefined) at β·D ≤ 0.
double spanwise_wavelength_D(double beta_D);

/// One wavenumber of the scan.
struct SpanwisePoint {
  double beta_D = 0.0;           ///< β·D, dimensionless (λ_z/D = 2π/(β·D))
  /// The leading eigenvalue, U/D (0 when none converged); of an orbit the Floquet exponent ln(μ)/T
  /// (its imaginary part arg μ/T: 0 for a synchronous mode, π/T for period doubling).
  std::complex<double> lambda;
  std::complex<double> multiplier;  ///< of an orbit: the leading Floquet multiplier μ (1: neutral); else 0
  bool found = false;            ///< an eigenvalue converged
  /// Steady base: the shifts' disks covered the strip right of it (StabilityResult::covered). Orbit: the
  /// leading multiplier is found (its Ritz estimate within kFloquetTolerance).
  bool covered = false;
  double seconds = 0.0;          ///< wall time of this wavenumber, s
  int solves = 0;                ///< shifted solves
  /// Orbit: the leading multiplier's mode at phase 0 (Arnoldi's start for the same β at a neighbouring
  /// Reynolds number); else empty.
  std::vector<double> mode;
  double growth() const { return lambda.real(); }
};

/// The scan and its reading.
struct SpanwiseScan {
  std::vector<SpanwisePoint> points;  ///< in the order asked for
  /// The most unstable wavenumber: β·D of the largest growth rate, refined by the parabola through its
  /// neighbours when it lies inside the scan (interior = true), and the growth rate there, U/D.
  double beta_D = 0.0, growth = 0.0;
  bool interior = false;
  bool periodic = false;    ///< the base is a shedding orbit (Floquet), not a steady state
  double T = 0.0;           ///< the orbit's period, D/U (periodic only)
  /// Steady base: the leading eigenvalue at that wavenumber is real (a stationary mode). Orbit: the leading
  /// multiplier is real and positive (a synchronous mode, as modes A and B of the cylinder wake).
  bool stationary = false;
  bool stable = false;      ///< every growth rate found is < 0 (false when none was found)
  /// Spanwise wavelength λ_z/D = 2π/(β·D) of the most unstable wavenumber; 0 (undefined) at β = 0.
  double wavelength_D() const;
  std::string verdict;  ///< one sentence: stable, or unstable to a 3D mode at λ_z = … D
};

/// The leading eigenvalue at each β·D of beta_D (≥ 0, finite) about the steady state of p; on_point after
/// each one. Throws std::invalid_argument for an empty or bad list.
SpanwiseScan spanwise_scan(const NsParams& p, const NsState& steady, const std::vector<double>& beta_D,
                           const StabilityOptions& o,
                           const std::function<void(const SpanwisePoint&)>& on_point = {});

/// The shedding orbit of p (a short march from rest, then Newton–GMRES shooting; t_end: the march gives up
/// there, s) and the leading Floquet multiplier at each β·D of beta_D; on_point after each one. Throws
/// std::runtime_error when the flow does not shed or the orbit does not converge.
/// The wavenumbers run on all cores at once (on_point still in order); starts[k], when given, is Arnoldi's
/// start at beta_D[k] (a neighbouring orbit's SpanwisePoint::mode), else the mode of the nearest
/// wavenumber already done. Arnoldi stops at 30 vectors, or once the leading multiplier is found
/// (kFloquetTolerance).
SpanwiseScan floquet_scan(const NsParams& p, const std::vector<double>& beta_D, double t_end,
                          const std::function<void(const SpanwisePoint&)>& on_point = {},
                          const std::vector<std::vector<double>>& starts = {});

/// The steady state of p (Newton, as hopf_evaluation finds it) and its 2D eigenvalues by the converged
/// search (every shift to convergence, shifts added for gaps) with `eigensolver`. Throws std::runtime_error
/// (one line naming Re and α) when no steady state is found or no eigenvalue converged.
HopfEvaluation steady_stability(const NsParams& p, const std::string& eigensolver);

/// The 3D stability of the flow that is there: the spanwise eigenvalues of the steady state when it is
/// stable (spanwise_scan with quick_stability_options and `eigensolver`), else the Floquet multipliers of
/// the shedding orbit (floquet_scan, its short march giving up at 300 D/U).
SpanwiseScan spanwise_stability(const NsParams& p, const HopfEvaluation& steady, const std::vector<double>& beta_D,
                                const std::string& eigensolver,
                                const std::function<void(const SpanwisePoint&)>& on_point = {},
                                const std::vector<std::vector<double>>& starts = {});

/// The vertex (x, y) of the parabola through three points (x_k distinct); the middle point when they are
/// collinear or the vertex leaves [x_0, x_2].
std::pair<double, double> parabola_vertex(const double x[3], const double y[3]);

}  // namespace magnus
