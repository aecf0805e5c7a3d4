// A small driver of the viscous run, for timing and memory (/usr/bin/time -v) and for the validation
// figures: ns_run Re alpha n_theta R_over_a t_end [cfl] [quiet]. D = 1 m, U = 1 m/s, ρ = 1 kg/m³.
// Environment: NS_REFINE=k the scene's grid (scene_grid(Re, α, k): n_θ, stretched rings; n_theta ignored),
// NS_OUTER_ZERO=1 ζ = 0 all round the outer ring, NS_ORDER=4 advection order 4 in θ and ξ
// (NS_ORDER_THETA, NS_ORDER_XI: one of them), NS_SPLIT_FROM=t0 the mean C_D parts over t ≥ t0.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/core.h>

#include "base/atomic_file.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

int main(int argc, char** argv) {
  using namespace magnus;
  if (argc < 6) {
    std::fprintf(stderr, "usage: ns_run Re alpha n_theta R_over_a t_end [cfl] [quiet]\n");
    return 2;
  }
  NsParams p;
  p.a = 0.5;
  p.U = 1.0;
  p.nu = p.U * 2.0 * p.a / std::atof(argv[1]);
  p.omega = std::atof(argv[2]) * p.U / p.a;
  p.n_theta = std::atoi(argv[3]);
  p.outer_over_a = std::atof(argv[4]);
  if (argc > 6 && std::atof(argv[6]) > 0.0) p.cfl = std::atof(argv[6]);
  if (const char* t = std::getenv("NS_THREADS")) p.threads = std::atoi(t);
  if (const char* t = std::getenv("NS_NR")) p.n_r = std::atoi(t);
  if (const char* k = std::getenv("NS_REFINE")) {
    const SceneGrid sg = scene_grid(std::atof(argv[1]), std::atof(argv[2]), std::atof(k));
    p.n_theta = sg.n_theta, p.wall_refinement = sg.wall_refinement, p.wall_layer = sg.wall_layer;
  }
  if (std::getenv("NS_OUTER_ZERO")) p.outer_vorticity = NsOuterVorticity::zero;
  if (const char* o = std::getenv("NS_ORDER")) p.advection_order = p.advection_order_xi = std::atoi(o);
  if (const char* o = std::getenv("NS_ORDER_THETA")) p.advection_order = std::atoi(o);
  if (const char* o = std::getenv("NS_ORDER_XI")) p.advection_order_xi = std::atoi(o);
  const bool quiet = argc > 7;
  UnsteadyOptions o;
  o.t_end = std::atof(argv[5]);
  if (const char* c = std::getenv("NS_COARSE")) o.coarse_start = std::atoi(c) != 0;
  double next_print = 0.0;
  // NS_SPLIT_FROM=t0: the mean pressure and friction parts of C_D over t ≥ t0 (D/U)
  const double split_from = std::getenv("NS_SPLIT_FROM") ? std::atof(std::getenv("NS_SPLIT_FROM")) : HUGE_VAL;
  double cd_p = 0.0, cd_f = 0.0;
  long n_split = 0;
  o.on_step = [&](const NsState& s, const ViscousForces& f) {
    if (s.t >= split_from && f.C_D_pressure && f.C_D_friction)
      cd_p += *f.C_D_pressure, cd_f += *f.C_D_friction, ++n_split;
    if (quiet || s.t < next_print) return true;
    next_print += 5.0;
    std::printf("t = %7.2f  C_L = %9.5f  C_D = %8.5f  C_M = %9.5f\n", s.t, *f.C_L, *f.C_D, *f.C_M);
    std::fflush(stdout);
    return true;
  };
  const PolarGrid g = ns_grid(p);
  NsState start = impulsive_start(p, g);
  if (std::getenv("NS_BLOB")) add_vortex_blob(g, start, 1.5, 0.3, 0.25, 1e-3);
  const UnsteadyResult r = run_unsteady(p, o, std::move(start));
  std::printf("grid %d x %d, R/a = %.2f, dt = %.5g, steps %ld, wall %.2f s (%.3f ms/step)\n", g.n_r,
              g.n_theta, g.outer_radius() / p.a, r.dt, r.steps, r.wall_seconds,
              1e3 * r.wall_seconds / double(r.steps));
  std::printf("%s; t = %.2f\n", r.message.c_str(), r.state.t);
  const NsStepTimes& tm = r.times;
  std::printf(
      "steps %ld (coarse %ld), %.0f steps/s; seconds: advection %.2f helmholtz %.2f poisson %.2f wall %.2f "
      "other %.2f forces %.2f; CFL at the end %.3f\n",
      r.steps, r.coarse_steps, r.steps_per_second, tm.advection, tm.helmholtz, tm.poisson, tm.wall, tm.other,
      tm.forces, cfl_number(g, r.state.psi, r.dt));
  std::printf("C_L mean %.5f  amp %.5f  C_D mean %.5f  amp %.5f  C_M mean %.5f  St %.5f  (%s)\n", r.C_L_mean,
              r.C_L_amplitude, r.C_D_mean, r.C_D_amplitude, r.C_M_mean, r.St,
              r.steady     ? "steady"
              : r.periodic ? "periodic"
                           : "neither");
  if (n_split > 0)
    std::printf("C_D over t >= %g: pressure %.5f + friction %.5f\n", split_from, cd_p / double(n_split),
                cd_f / double(n_split));
  if (r.steady) std::printf("recirculation length %.4f D\n", recirculation_length(g, r.state));
  if (const char* path = std::getenv("NS_HISTORY")) {  // t, C_L, C_D, C_M per step, written atomically
    std::string text;
    for (const ForceSample& h : r.history)
      text += fmt::format("{:.6f} {:.6f} {:.6f} {:.6f}\n", h.t, h.C_L, h.C_D, h.C_M);
    try {
      write_text_output(path, text);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ns_run: %s\n", e.what());
      return 1;
    }
  }
  return r.ok ? 0 : 1;
}
