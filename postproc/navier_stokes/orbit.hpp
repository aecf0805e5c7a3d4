#pragma once
// A shedding state as a periodic orbit (solver/navier_stokes/periodic_orbit.hpp) instead of a long march:
// a short march from the start until the lift's first periods look alike, its period from the lift's mean
// crossings, then Newton–GMRES shooting on the period map, and the orbit's summary (means, amplitudes, St)
// from one period of its forces, in the march's terms (UnsteadyResult).
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "postproc/navier_stokes/unsteady.hpp"
#include "solver/navier_stokes/floquet.hpp"
#include "solver/navier_stokes/periodic_orbit.hpp"

namespace magnus {

/// How long the short march runs and how the orbit is sought.
struct OrbitRunOptions {
  double t_end = 200.0;       ///< the short march gives up here, s (no shedding by then: an error)
  double rho = 1.0;           ///< density for the forces, kg/m³
  /// The short march stops when the last march_periods + 1 periods of C_L agree with the last one in
  /// amplitude and length to this (relative): near the onset the means agree long before the growth ends.
  double march_tol = 1e-2;
  int march_periods = 2;
  /// The short march never stops before this time, s; < 0: when the starting vortex has left the domain,
  /// (R − a)/U + 10 D/U (UnsteadyOptions::t_min): its circulation is far from the orbit and Newton's
  /// linear model holds poorly while it is in the domain.
  double t_min = -1.0;
  OrbitOptions orbit;         ///< tolerance, iterations (orbit.steps 0: N = ⌈T/Δt_march⌉)
  /// After every step of the short march (a progress line, Ctrl-C: false stops it); may be empty.
  std::function<bool(const NsState&, const ViscousForces&)> on_step;
};

/// The short march, the orbit, and the orbit's summary in the march's terms.
struct OrbitRun {
  UnsteadyResult march;   ///< the short march from the start
  OrbitResult orbit;      ///< the Newton–GMRES solve
  /// One period of the orbit: state = its state after the period (t = T); history: its N + 1 samples over
  /// [0, T]; means over the period (the trapezoidal rule, exact for the periodic samples), amplitudes
  /// (max − min)/2 with each extreme refined by the parabola through its sample and the two beside it;
  /// period = T, St = D/(U T); steps and wall_seconds of the whole (march, orbit and the summary's own steps:
  /// none when it kept the solve's last period); converged = the orbit's.
  UnsteadyResult result;
};

/// The smallest C_L amplitude, relative to max(1, |mean C_L|), of an orbit that is taken for shedding
/// (below it the orbit is the steady state; near the onset at Re ≈ 47 the amplitude grows as √(Re − Re_c)
/// and is ~0.05 two units of Re above it).
constexpr double kOrbitMinAmplitude = 1e-4;

/// Whether an orbit's summary is of a shedding orbit: its C_L amplitude at least
/// kOrbitMinAmplitude·max(1, |mean C_L|) (below it the orbit is the steady state, a fixed point of every
/// period map).
bool orbit_sheds(const UnsteadyResult& r);

/// Short march from `start`, then the orbit (p: the run's parameters; p.dt is ignored by the orbit, whose
/// Δt is T/N). Throws std::runtime_error with one line when the march fails, does not shed (steady, no
/// period by t_end, or an orbit that is the steady state) or is interrupted; a Newton solve that stalls
/// returns with result.converged = false.
OrbitRun periodic_orbit_run(const NsParams& p, const OrbitRunOptions& o, NsState start);

/// The relative size of a start on the Hopf mode (hopf_start): the mode's largest vorticity is this
/// fraction of the steady state's. Large enough that the short march does not spend its time growing the
/// mode out of round-off, small enough to stay near the steady state's unstable manifold.
constexpr double kHopfStartSize = 0.02;

/// A short march's start near the shedding orbit's onset: the unstable steady state plus the real part of
/// the growing pair's mode (ψ, ζ on every node as NsState, Γ_R; max |ζ_mode| = 1, as StabilityResult holds
/// it), scaled so that its largest vorticity is size·max|ζ_steady| (1/s). No starting vortex has to leave
/// the domain, and the mirror symmetry is broken by the mode itself: the march may stop as soon as the
/// lift's periods agree (OrbitRunOptions::t_min = 0). The AB2 history is left empty (Euler first step).
/// Throws std::invalid_argument for a mode of another size than the state.
NsState hopf_start(const NsState& steady, const std::vector<std::complex<double>>& mode_psi,
                   const std::vector<std::complex<double>>& mode_zeta, std::complex<double> mode_Gamma_R,
                   double size = kHopfStartSize);

/// One period of an orbit as its solve stepped it last: the forces at its N + 1 states (t = 0 … T) and its
/// end state. The solve's last period is that of the state it returns, so its summary needs no more steps.
struct OrbitPeriod {
  std::vector<ForceSample> history;
  NsState end;
};

/// Sets o.on_residual_step so that `period` holds the last period the solve steps, its forces with density
/// rho (kg/m³) on p's grid. `period` must outlive the solve.
void keep_last_period(const NsParams& p, double rho, OrbitOptions& o, OrbitPeriod& period);

/// The summary of one period of a converged orbit in the march's terms (OrbitRun::result without the steps
/// and seconds of the march and the solve): from `period` when it holds the orbit's N + 1 samples
/// (keep_last_period), else from one more period of steps. Its `steps` are the steps it took: 0, or N.
UnsteadyResult orbit_summary(const NsParams& p, const OrbitResult& orbit, double rho,
                             const OrbitPeriod* period = nullptr);

/// The orbit as the base of a Floquet analysis: its Fourier series with K harmonics, summed over its own N
/// steps of one period (t = nT/N, n = 0…N−1) without keeping the states.
PeriodicBase orbit_series(const NsParams& p, const OrbitResult& orbit, int K = 8);

/// Extremes of periodic samples y (uniform in time): max and min, each refined by the parabola through it
/// and its two neighbours (cyclic), in y's units.
void periodic_extremes(const std::vector<double>& y, double& lo, double& hi);

/// The Newton history in one line: "residual 3.1e-03 → 4.2e-06 (GMRES 21) → …; T = … D/U, N = …".
std::string orbit_history_text(const OrbitResult& orbit, double time_unit);

}  // namespace magnus
