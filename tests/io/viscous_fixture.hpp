#pragma once
// A navier-stokes FlowResult built by hand (no time marching): the potential flow's fields on a small
// polar grid, a wake-like vorticity, a shedding force history and a few stored states. For the tests of
// what files, viewers, plots and compare do with a viscous result; the numbers are plausible, not solved.
#include <cmath>
#include <vector>

#include "mesh/polar_grid.hpp"
#include "physics/exact.hpp"
#include "postproc/result.hpp"

namespace magnus::test {

/// Re = 100, α = alpha, a = 0.1 m, U = 1 m/s on an n_θ × n_r log-polar grid (R = 20a), `states` snapshots.
inline FlowResult viscous_result_by_hand(double alpha = 1.0, int n_theta = 32, int n_r = 16, int states = 4) {
  Case c;
  c.title = "NS by hand";
  c.model = FlowModel::navier_stokes;
  c.scene.radius = 0.1;
  c.scene.speed = 1.0;
  c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  c.scene.density = 1.0;
  c.scene.viscosity = c.scene.speed * 2 * c.scene.radius / 100.0;
  c.grid.n_theta = n_theta;
  c.grid.n_r = n_r;
  c.grid.outer_radius = 20.0;
  c.time.end = 50.0;
  c.output.snapshots = states;
  c.source_text = "title = \"NS by hand\"\n[model]\nflow = \"navier-stokes\"\n";

  FlowResult r;
  r.c = c;
  r.grid = make_grid(c.scene.radius, c.grid.outer_radius, n_r, n_theta, Spacing::geometric);
  const PolarGrid& g = r.grid;
  const double a = g.a, U = c.scene.speed, w = c.scene.spin, nu = c.scene.viscosity, rho = c.scene.density;
  const ExactFlow ex = exact_flow(c.scene);
  const size_t n = size_t(g.nodes());
  Fields& f = r.fields;
  for (auto* v : {&f.psi, &f.u_r, &f.u_theta, &f.u_x, &f.u_y, &f.pressure, &f.cp, &f.vorticity}) v->resize(n);
  // A wake: vorticity of both signs behind the body (θ near 0), decaying away from it; phase `ph` turns it.
  auto zeta = [&](double rr, double th, double ph) {
    const double d = (rr - a) / a;
    return U / a * std::exp(-0.3 * d) * (4.0 * std::exp(-3.0 * d) * std::sin(th) + std::cos(th / 2 + ph)) *
           std::exp(-2.0 * (1 - std::cos(th)));
  };
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j) {
      const size_t q = size_t(i) * g.n_theta + j;
      const double r0 = g.r[i], th = g.theta[j];
      f.psi[q] = ex.psi(r0, th);
      f.u_r[q] = U * (1 - a * a / (r0 * r0)) * std::cos(th);
      f.u_theta[q] = -U * (1 + a * a / (r0 * r0)) * std::sin(th) + ex.Gamma / (2 * M_PI * r0);
      f.u_x[q] = f.u_r[q] * std::cos(th) - f.u_theta[q] * std::sin(th);
      f.u_y[q] = f.u_r[q] * std::sin(th) + f.u_theta[q] * std::cos(th);
      const double q2 = f.u_r[q] * f.u_r[q] + f.u_theta[q] * f.u_theta[q];
      f.pressure[q] = c.scene.pressure_inf + 0.5 * rho * (U * U - q2);
      f.cp[q] = 1 - q2 / (U * U);
      f.vorticity[q] = zeta(r0, th, 0.0);
    }
  Surface& s = r.surface;
  s.theta = g.theta;
  for (int j = 0; j < g.n_theta; ++j) {
    const double th = g.theta[j], u = -2 * U * std::sin(th) + a * w;
    s.u_theta.push_back(u);
    s.pressure.push_back(0.5 * rho * (U * U - u * u));
    s.cp.push_back(1 - u * u / (U * U));
    s.shear_stress.push_back(rho * nu * (zeta(a, th, 0.0) - 2 * w));
  }

  ViscousPart v;
  v.viscosity = nu;
  v.reynolds = U * 2 * a / nu;
  v.time_unit = 2 * a / U;
  v.status = "periodic means converged";
  v.periodic = v.converged = true;
  v.steps = 400;
  v.dt = 0.1 * v.time_unit;
  v.t = v.steps * v.dt;
  const double St = 0.1658, cl0 = 0.0 - 2.5 * alpha, cd0 = 1.108;
  for (long k = 0; k <= v.steps; ++k) {
    ForceSample h;
    h.t = k * v.dt;
    const double ph = 2 * M_PI * St * h.t / v.time_unit, grow = 1 - std::exp(-h.t / (10 * v.time_unit));
    h.C_L = cl0 * grow + 0.36 * grow * std::sin(ph);
    h.C_D = cd0 + 0.5 * std::exp(-h.t / (2 * v.time_unit)) + 0.02 * grow * std::sin(2 * ph);
    h.C_M = -0.05 * alpha;
    const double q = 0.5 * rho * U * U * 2 * a;
    h.F_y = h.C_L * q;
    h.F_x = h.C_D * q;
    h.M = h.C_M * q * 2 * a;
    v.history.push_back(h);
  }
  v.cl_mean = cl0;
  v.cd_mean = cd0;
  v.cm_mean = -0.05 * alpha;
  v.cl_amplitude = 0.36;
  v.cd_amplitude = 0.02;
  v.strouhal = St;
  v.period = v.time_unit / St;
  v.lift_mean = cl0 * 0.5 * rho * U * U * 2 * a;
  v.drag_mean = cd0 * 0.5 * rho * U * U * 2 * a;
  v.cl_ideal = -2 * M_PI * alpha;
  if (alpha != 0.0) v.magnus_ratio = cl0 / (-2 * M_PI * alpha);
  v.separation = {0.3, 2.9};
  v.last.C_L = v.history.back().C_L;
  v.last.C_D = v.history.back().C_D;
  for (int k = 0; k < states; ++k) {
    Snapshot sn;
    sn.t = v.t - (states - 1 - k) * 0.25 * v.time_unit;
    sn.psi = f.psi;
    sn.vorticity.resize(n);
    for (int i = 0; i < g.n_r; ++i)
      for (int j = 0; j < g.n_theta; ++j)
        sn.vorticity[size_t(i) * g.n_theta + j] = zeta(g.r[i], g.theta[j], 0.7 * (k + 1));
    for (size_t q = 0; q < n; ++q) sn.psi[q] += 0.01 * (k + 1) * U * a;  // tell the states apart
    v.snapshots.push_back(std::move(sn));
  }
  r.viscous = std::move(v);
  return r;
}

}  // namespace magnus::test
