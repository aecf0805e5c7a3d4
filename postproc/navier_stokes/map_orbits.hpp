#pragma once
// The shedding points of a map row as periodic orbits (NsMapOptions::orbits): each orbit is continued from
// the row's previous one, the way the steady branch is, or started from the steady state and its growing
// pair's mode, or from rest; its error bars from the same orbit on the grid twice as coarse, continued
// alongside. continuation_row.cpp calls it for each point whose steady state is unstable or missing.
#include <optional>
#include <utility>
#include <vector>

#include "postproc/navier_stokes/continuation.hpp"
#include "solver/navier_stokes/periodic_orbit.hpp"

namespace magnus {

/// The row's last orbit on the map's grid and on the companion grid (empty after a point that was not an
/// orbit: the next orbit starts afresh).
struct OrbitChain {
  std::optional<OrbitResult> fine, coarse;
  std::optional<NsState> steady;  ///< the steady state at the last orbit's point, if it had one
  int n_theta = 0;                ///< the grid of `fine` (its companion's follows from it)
  std::vector<double> xi;         ///< its rings, ξ = ln(r/a)
  /// Whether the chain's orbits are of grid g (a map continued in Re may change the grid from row to row).
  bool on(const PolarGrid& g) const { return n_theta == g.n_theta && xi == g.xi; }
  /// Holds `orbit` on grid g as the last one, with its point's steady state (null: none).
  void hold(OrbitResult orbit, const NsState* at, const PolarGrid& g) {
    fine = std::move(orbit);
    if (at)
      steady = *at;
    else
      steady.reset();
    n_theta = g.n_theta, xi = g.xi;
  }
};

/// The orbit of map point m at parameters p on the row's grid: continued from chain.fine when it holds the
/// previous column's orbit (its state shifted by the steady branch's change from chain.steady to `steady`
/// where both exist), else a short march from hopf_start(steady, v's mode) when v has a growing pair,
/// else from rest (impulsive start, mirror symmetry broken), then Newton–GMRES shooting to o.orbit_tol. On
/// success sets m's cl, cd, cm (the means over one period), strouhal, source = orbit, orbit_start,
/// orbit_periods, and with
/// o.error_estimate its bars from the same orbit on the companion grid; updates the chain and returns true.
/// Returns false, the chain emptied and m.orbit_start cleared (m's figures untouched), when no orbit is
/// found: the short march settles, no period appears by time.end, Newton stalls, or the orbit is the steady
/// state (the caller marches then).
bool orbit_point(const Case& point_case, const NsParams& p, const NsState* steady, const StabilityVerdict& v,
                 const NsMapOptions& o, OrbitChain& chain, NsMapPoint& m);

/// At a point whose steady state is stable: whether the row's last orbit (chain.fine, the neighbouring
/// column's), continued into p (as orbit_point continues it; with `march`, where that Newton solve fails, a
/// march from the neighbour's orbit state to point_case's time.end, then Newton), persists as a shedding
/// orbit. The forward pass past α_L does not march (a collapsing orbit would march to time.end at every
/// window's end); the backward pass below a subcritical Hopf point does, near the orbits' fold. True: a
/// stable steady state and a shedding orbit coexist there (as past a subcritical Hopf point; the orbit's own
/// stability is not tested), and the chain holds the orbit, so the next column continues it further. False:
/// the chain is emptied. Its periods of time steps go to m.orbit_periods.
bool coexisting_orbit(const Case& point_case, const NsParams& p, const NsState& steady, const NsMapOptions& o,
                      OrbitChain& chain, NsMapPoint& m, bool march = false);

}  // namespace magnus
