// The FlowResult of a viscous state: fields, surface, forces beside the potential flow's figures, and the
// viscous part from the run's history.
#include <chrono>
#include <cmath>

#include "physics/exact.hpp"
#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/pressure.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

namespace magnus {

namespace {

/// Fields: ψ and ζ as stepped; u from ψ; p from the pressure Poisson equation; Cp on ½ρU²; those the case
/// does not select cleared. wall_p: the pressure field's wall ring (Pa), before any is cleared.
Fields viscous_fields(const Case& c, const NsParams& p, const PolarGrid& g, const NsState& st,
                      std::vector<double>& wall_p) {
  const Scene& sc = c.scene;
  const double U = sc.speed, rho = sc.density;
  const size_t nt = size_t(g.n_theta), n = size_t(g.n_r) * nt;
  const FieldSelection sel = select_fields(c.output.fields, c.model);
  Fields all;
  all.psi = st.psi;
  all.vorticity = st.zeta;
  ns_velocity(g, st.psi, all.u_r, all.u_theta);
  all.u_x.resize(n), all.u_y.resize(n);
  for (size_t i = 0; i < size_t(g.n_r); ++i)
    for (size_t j = 0; j < nt; ++j) {
      const double cs = std::cos(g.theta[j]), sn = std::sin(g.theta[j]), ur = all.u_r[i * nt + j],
                   ut = all.u_theta[i * nt + j];
      all.u_x[i * nt + j] = ur * cs - ut * sn;
      all.u_y[i * nt + j] = ur * sn + ut * cs;
    }
  all.pressure = ns_pressure_field(g, p, rho, sc.pressure_inf, st);
  wall_p.assign(all.pressure.begin(), all.pressure.begin() + long(nt));
  const double q = 0.5 * rho * U * U;
  if (U > 0.0)
    for (double pv : all.pressure) all.cp.push_back((pv - sc.pressure_inf) / q);
  for (const auto& name : field_names())
    if (!sel.has(name)) all.get(name).clear();
  return all;
}

/// Surface: the wall moves with the body; its pressure is the field's wall ring (the θ-integral of
/// μ ζ_ξ fixed by the r-momentum balance), its shear μ(ζ_w − 2ω).
Surface viscous_wall(const Scene& sc, const PolarGrid& g, const ViscousSurface& vs,
                     const std::vector<double>& wall_p) {
  const double a = sc.radius, U = sc.speed, w = sc.spin, q = 0.5 * sc.density * U * U;
  const size_t nt = size_t(g.n_theta);
  Surface s;
  s.theta = g.theta;
  s.u_theta.assign(nt, a * w);
  s.u_mean = a * w;
  s.u_fluct.assign(nt, 0.0);
  // The wall formula's pressure (it converges faster than the field's wall ring, and the forces use it),
  // placed at the field's mean wall pressure (the level the far field fixes).
  double level = 0.0;
  for (double pv : wall_p) level += pv / double(nt);
  s.pressure = vs.pressure;
  for (double& pv : s.pressure) pv += level;
  if (U > 0.0)
    for (double pv : s.pressure) s.cp.push_back((pv - sc.pressure_inf) / q);
  s.shear_stress = vs.tau_w;
  return s;
}

/// Forces: the last step's, and the potential flow's figures for the same scene beside them.
Forces viscous_force_figures(const Scene& sc, const ViscousForces& vf, const Surface& s,
                             const ExactFlow& ideal) {
  const double a = sc.radius, w = sc.spin, rho = sc.density;
  Forces f;
  f.lift = vf.F_y;
  f.drag = vf.F_x;
  f.cl = vf.C_L;
  f.cd = vf.C_D;
  f.lift_kutta_joukowski = ideal.lift(rho);
  f.circulation_measured = 2.0 * M_PI * a * a * w;  // ∮ u_θ a dθ with u_θ = aω: no slip
  f.delta_p_top_bottom =
      periodic_interpolate(s.pressure, M_PI / 2) - periodic_interpolate(s.pressure, 1.5 * M_PI);
  f.delta_p_top_bottom_exact = ideal.delta_p_top_bottom(rho);
  f.delta_p_seed_estimate = seed_delta_p(sc);
  f.magnus_S_exact = 2.0 * M_PI * rho * a * a;
  return f;
}

/// The viscous part's figures of the run: its state, means, amplitudes and St (U > 0), and the ideal
/// figures beside them (also into f: C_L of Kutta–Joukowski and of the seed, S = −L̄/(Uω)).
void set_run_figures(ViscousPart& v, Forces& f, const Scene& sc, const UnsteadyResult& run,
                     const ViscousForces& vf, const ExactFlow& ideal) {
  const double U = sc.speed, w = sc.spin, D = 2.0 * sc.radius, q = 0.5 * sc.density * U * U;
  v.viscosity = sc.viscosity;
  if (U > 0.0) v.reynolds = sc.reynolds();
  v.time_unit = sc.time_unit();
  v.status = run.message;
  v.steady = run.steady, v.periodic = run.periodic, v.converged = run.converged;
  v.partial = run.interrupted || !run.ok;
  v.t = run.state.t, v.dt = run.dt, v.steps = run.steps;
  v.Gamma_R = run.state.Gamma_R;
  v.last = vf;
  if (U > 0.0) {
    v.cl_mean = run.C_L_mean, v.cd_mean = run.C_D_mean, v.cm_mean = run.C_M_mean;
    if (run.periodic) {
      v.cl_amplitude = run.C_L_amplitude, v.cd_amplitude = run.C_D_amplitude;
      if (run.period_confirmed) v.strouhal = run.St, v.period = run.period;  // else undefined (status why)
    }
    v.lift_mean = run.C_L_mean * q * D, v.drag_mean = run.C_D_mean * q * D;
    v.torque_mean = run.C_M_mean * q * D * D;
    f.cl_kutta_joukowski = ideal.cl();
    f.cl_seed_estimate = seed_cl(sc);
    v.cl_ideal = ideal.cl();
    if (w != 0.0) {
      f.magnus_S = -v.lift_mean / (U * w);
      v.magnus_ratio = run.C_L_mean / ideal.cl();
    }
  } else {
    v.torque_mean = run.M_mean;  // U = 0: the torque (no coefficients)
  }
  v.spin_power_mean = -v.torque_mean * w;
}

}  // namespace

FlowResult viscous_result(const Case& c, const NsParams& p, const UnsteadyResult& run,
                          std::vector<Snapshot> snapshots) {
  const auto clock0 = std::chrono::steady_clock::now();
  const Scene& sc = c.scene;
  FlowResult r;
  r.c = c;
  // The rings' map as used (the scene's rule may have chosen it): /parameters tells what was solved.
  r.c.grid.wall_refinement = p.wall_refinement, r.c.grid.wall_layer = p.wall_layer;
  r.grid = ns_grid(p);
  const PolarGrid& g = r.grid;
  const NsState& st = run.state;
  std::vector<double> wall_p;
  r.fields = viscous_fields(c, p, g, st, wall_p);
  const ViscousSurface vs = viscous_surface(g, p, sc.density, st);
  r.surface = viscous_wall(sc, g, vs, wall_p);
  const ViscousForces vf = viscous_forces(g, p, sc.density, st);
  const ExactFlow ideal = exact_flow(sc);
  r.forces = viscous_force_figures(sc, vf, r.surface, ideal);
  ViscousPart& v = r.viscous.emplace();
  set_run_figures(v, r.forces, sc, run, vf, ideal);
  for (double th : separation_angles(vs)) v.separation.push_back(th);
  if (run.steady && sc.speed > 0.0) v.recirculation_length = recirculation_length(g, st);
  v.history = run.history;
  v.snapshots = std::move(snapshots);

  r.timing.solve_s = run.wall_seconds;
  r.timing.postproc_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  r.timing.total_s = r.timing.solve_s + r.timing.postproc_s;
  r.info.method = "fft";
  return r;
}

}  // namespace magnus
