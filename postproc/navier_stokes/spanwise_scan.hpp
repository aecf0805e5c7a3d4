#pragma once
// Where the 2D answer is real: the leading eigenvalue of a steady state's spanwise problem (spanwise.hpp)
// over a set of wavenumbers β, the most unstable one (a parabola through the three around the largest
// growth rate) and its wavelength λ_z = 2π/β, and the verdict in words.
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "solver/navier_stokes/spanwise.hpp"

namespace magnus {

/// One wavenumber of the scan.
struct SpanwisePoint {
  double beta_D = 0.0;           ///< β·D, dimensionless (λ_z/D = 2π/(β·D))
  std::complex<double> lambda;   ///< the leading eigenvalue, U/D (0 when none converged)
  bool found = false;            ///< an eigenvalue converged
  bool covered = false;          ///< the shifts' disks covered the strip right of it (StabilityResult::covered)
  double seconds = 0.0;          ///< wall time of this wavenumber, s
  int solves = 0;                ///< shifted solves
  double growth() const { return lambda.real(); }
};

/// The scan and its reading.
struct SpanwiseScan {
  std::vector<SpanwisePoint> points;  ///< in the order asked for
  /// The most unstable wavenumber: β·D of the largest growth rate, refined by the parabola through its
  /// neighbours when it lies inside the scan (interior = true), and the growth rate there, U/D.
  double beta_D = 0.0, growth = 0.0;
  bool interior = false;
  bool stationary = false;  ///< the leading eigenvalue at that wavenumber is real
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

/// The vertex (x, y) of the parabola through three points (x_k distinct); the middle point when they are
/// collinear or the vertex leaves [x_0, x_2].
std::pair<double, double> parabola_vertex(const double x[3], const double y[3]);

}  // namespace magnus
