// A map row's shedding points as periodic orbits, continued along the row (map_orbits.hpp).
#include "postproc/navier_stokes/map_orbits.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/navier_stokes/steady_study.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

namespace {

/// A found orbit and its summary (means over one period, amplitude, St), with the periods it cost.
struct FoundOrbit {
  OrbitResult orbit;
  UnsteadyResult summary;
  double periods = 0.0;
};

/// s shifted by to − from (the steady branch's change between two points, when both exist on s's grid: an
/// orbit's mean moves with it); s unchanged otherwise.
void shift_state(NsState& s, const NsState* from, const NsState* to) {
  const size_t nodes = s.psi.size();
  if (!from || !to || from->psi.size() != nodes || to->psi.size() != nodes) return;
  for (size_t i = 0; i < s.psi.size(); ++i) s.psi[i] += to->psi[i] - from->psi[i];
  for (size_t i = 0; i < s.zeta.size(); ++i) s.zeta[i] += to->zeta[i] - from->zeta[i];
  s.Gamma_R += to->Gamma_R - from->Gamma_R;
}

/// Newton from a neighbouring orbit of the same grid (no march), its state shifted by shift_to − shift_from
/// (the steady branch's change between the two points, when both have one: the orbit's mean moves with it).
/// N puts Δt = T/N at the target CFL number p.cfl of the shifted state, as a march would (the orbit is the
/// scheme's at that Δt, and a march's Δt moves with the flow: kept from the neighbour, the means of Re 100,
/// α 0.25 on the map's grid moved 0.1%). Where a step still passes the CFL limit, N grows by a fifth and
/// Newton starts again (at most three times). Empty when it stalls, collapses or a step fails.
std::optional<FoundOrbit> continued(const NsParams& p, OrbitResult near, const NsState* shift_from,
                                    const NsState* shift_to, OrbitOptions oo, double rho) {
  shift_state(near.state, shift_from, shift_to);
  FoundOrbit f;
  const double rate = step_rate(p, ns_grid(p), near.state);
  oo.steps = rate > 0.0 ? std::max(8, int(std::ceil(near.T * rate / p.cfl))) : near.steps;
  OrbitPeriod last;
  keep_last_period(p, rho, oo, last);
  for (int attempt = 0;; ++attempt) {
    try {
      f.orbit = continue_orbit(p, near, oo);
      if (!f.orbit.converged) return std::nullopt;
      f.summary = orbit_summary(p, f.orbit, rho, &last);
      break;
    } catch (const CflExceeded&) {
      if (attempt == 3) return std::nullopt;
      oo.steps = int(std::ceil(1.2 * oo.steps));
    } catch (const std::exception&) {  // non-finite fields, a state of another grid: start afresh instead
      return std::nullopt;
    }
  }
  if (!orbit_sheds(f.summary)) return std::nullopt;  // Newton found the steady state
  f.periods = double(f.orbit.time_steps + f.summary.steps) / f.orbit.steps;
  return f;
}

/// A map point's orbit runs: the short march gives up at its case's time.end, Newton to o.orbit_tol.
OrbitRunOptions point_orbit_options(const Case& point_case, const NsMapOptions& o) {
  OrbitRunOptions ro;
  ro.t_end = point_case.time.end * point_case.scene.time_unit();
  ro.rho = point_case.scene.density;
  ro.orbit.tol = o.orbit_tol;
  return ro;
}

/// A short march from `start` (t_min: see OrbitRunOptions), then Newton. Empty when the march finds no
/// shedding period, Newton stalls, or the orbit is the steady state.
std::optional<FoundOrbit> from_march(const NsParams& p, const OrbitRunOptions& ro, NsState start) {
  try {
    OrbitRun run = periodic_orbit_run(p, ro, std::move(start));
    if (!run.orbit.converged) return std::nullopt;
    FoundOrbit f{std::move(run.orbit), std::move(run.result), 0.0};
    f.periods = double(f.summary.steps) / f.orbit.steps;
    return f;
  } catch (const std::runtime_error&) {  // steady, no period, the steady state, a failed step
    return std::nullopt;
  }
}

}  // namespace

bool coexisting_orbit(const Case& point_case, const NsParams& p, const NsState& steady, const NsMapOptions& o,
                      OrbitChain& chain, NsMapPoint& m, bool march) {
  const PolarGrid g = ns_grid(p);
  std::optional<FoundOrbit> f;
  if (chain.fine && chain.on(g)) {
    const NsState* from = chain.steady ? &*chain.steady : nullptr;
    OrbitRunOptions ro = point_orbit_options(point_case, o);
    f = continued(p, *chain.fine, from, from ? &steady : nullptr, ro.orbit, ro.rho);
    if (!f && march) {
      // Newton from the neighbour fails near a fold of the orbits (the step is too long there): a march
      // from the neighbour's orbit instead, which settles on this point's orbit where a stable one is near,
      // and decays to the steady state where none is (then no period: empty).
      ro.t_min = 0.0;  // no starting vortex to wait for
      NsState start = chain.fine->state;
      shift_state(start, from, from ? &steady : nullptr);
      start.N_prev.clear();  // the neighbour's advection history is not this point's: AB2 starts with Euler
      f = from_march(p, ro, std::move(start));
    }
  }
  if (!f) {
    chain = {};
    return false;
  }
  m.orbit_start = "continued";
  m.orbit_periods = f->periods;
  chain.hold(std::move(f->orbit), &steady, g);
  chain.coarse.reset();  // no bars here: the next orbit point's companion starts afresh
  return true;
}

bool orbit_point(const Case& point_case, const NsParams& p, const NsState* steady, const StabilityVerdict& v,
                 const NsMapOptions& o, OrbitChain& chain, NsMapPoint& m) {
  const double rho = point_case.scene.density;
  const OrbitRunOptions ro = point_orbit_options(point_case, o);
  const PolarGrid g = ns_grid(p);
  if (chain.fine && !chain.on(g)) chain = {};  // another Re's grid
  std::optional<FoundOrbit> f;
  const bool shift = chain.steady && steady;
  if (chain.fine) {
    f = continued(p, *chain.fine, shift ? &*chain.steady : nullptr, steady, ro.orbit, rho);
    m.orbit_start = "continued";
  }
  if (!f && steady && v.pair) {
    OrbitRunOptions from_mode = ro;
    from_mode.t_min = 0.0;  // no starting vortex to wait for
    f = from_march(p, from_mode, hopf_start(*steady, v.mode_psi, v.mode_zeta, v.mode_Gamma_R));
    m.orbit_start = "hopf mode";
  }
  if (!f) {
    NsState start = impulsive_start(p, g);
    break_symmetry(p, g, start);
    f = from_march(p, ro, std::move(start));
    m.orbit_start = "rest";
  }
  if (!f) {
    chain = {};
    m.orbit_start.clear();
    return false;
  }
  const UnsteadyResult& s = f->summary;
  m.source = MapSource::orbit;
  m.cl = s.C_L_mean, m.cd = s.C_D_mean, m.cm = s.C_M_mean;
  m.strouhal = s.St > 0.0 ? s.St : std::nan("");
  m.orbit_periods = f->periods;
  // The bars: the same orbit on the grid twice as coarse, continued from its own previous one, else
  // started from this orbit interpolated there (a short march: it is near its orbit already).
  std::optional<FoundOrbit> c;
  if (o.error_estimate && companion_refusal(p, g, false).empty()) {
    const NsParams pc = companion_params(p, g);
    const PolarGrid gc = ns_grid(pc);
    if (chain.coarse) {
      std::optional<NsState> from, to;  // the steady shift on the companion's grid
      if (shift) from = interpolate_state(g, *chain.steady, gc), to = interpolate_state(g, *steady, gc);
      c = continued(pc, *chain.coarse, shift ? &*from : nullptr, shift ? &*to : nullptr, ro.orbit, rho);
    }
    if (!c) {
      OrbitRunOptions near = ro;
      near.t_min = 0.0;
      c = from_march(pc, near, interpolate_state(g, f->orbit.state, gc));
    }
  }
  if (c) {
    const UnsteadyResult& sc = c->summary;
    m.cl_rel_estimate = relative_estimate(s.C_L_mean, sc.C_L_mean, 0.0).value_or(std::nan(""));
    m.cd_rel_estimate = relative_estimate(s.C_D_mean, sc.C_D_mean, 0.0).value_or(std::nan(""));
    m.strouhal_rel_estimate = relative_estimate(s.St, sc.St, 0.0).value_or(std::nan(""));
    chain.coarse = std::move(c->orbit);
  } else {
    m.cl_rel_estimate = m.cd_rel_estimate = m.strouhal_rel_estimate = std::nan("");
    chain.coarse.reset();
  }
  chain.hold(std::move(f->orbit), steady, g);
  return true;
}

}  // namespace magnus
