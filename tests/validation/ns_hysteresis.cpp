// A small driver for the README's bistability figures: one march through a list of spin ratios, each
// starting from where the last one ended, so that a shedding orbit is carried into a spin ratio where a
// march from rest would not find it:
//     ns_hysteresis Re n_theta R_over_a alpha_1 t_1 [alpha_2 t_2 …]
// The case is `magnus run cases/s_map.toml` with flow.reynolds = Re, grid.n_theta = n_theta and
// domain.outer_radius = R_over_a (a = 0.5 m, U = 1 m/s: D/U = 1 s): alpha_1 from rest for t_1 D/U, then
// alpha_k for t_k D/U more. One line per spin ratio: the range of C_L over its last 150 D/U (a swing near 0:
// the orbit is gone), its St and the seconds it took.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include "io/case_file.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/navier_stokes/unsteady.hpp"

int main(int argc, char** argv) {
  using namespace magnus;
  if (argc < 6 || argc % 2 != 0) {
    std::fprintf(stderr, "usage: ns_hysteresis Re n_theta R_over_a alpha_1 t_1 [alpha_2 t_2 …]\n");
    return 2;
  }
  const std::string Re = argv[1], n_theta = argv[2], R = argv[3];
  auto params = [&](const std::string& alpha) {
    const Case c =
        parse_case("[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = " + alpha +
                       "\n[flow]\nspeed = 1.0\nreynolds = " + Re + "\n[domain]\nouter_radius = " + R +
                       "\n[grid]\nn_theta = " + n_theta + "\n[time]\nmode = \"unsteady\"\n",
                   "ns_hysteresis");
    NsParams p = ns_params(c);
    apply_scene_grid(c, p);
    p.threads = 1;
    return p;
  };
  const NsParams first = params(argv[4]);
  NsState s = impulsive_start(first, ns_grid(first));
  break_symmetry(first, ns_grid(first), s);  // as a run from rest starts
  double t_end = 0.0;
  for (int k = 4; k + 1 < argc; k += 2) {
    const NsParams p = params(argv[k]);
    t_end += std::atof(argv[k + 1]);
    UnsteadyOptions o;
    o.t_end = t_end;
    o.steady_tol = 0.0, o.mean_tol = 0.0;  // march to t_end
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    o.on_step = [&](const NsState& st, const ViscousForces& f) {
      if (st.t > t_end - 150.0 && f.C_L) lo = std::min(lo, *f.C_L), hi = std::max(hi, *f.C_L);
      return true;
    };
    const UnsteadyResult r = run_unsteady(p, o, std::move(s));
    s = r.state;
    std::printf(
        "alpha %s to t = %.0f D/U: C_L over the last 150 D/U in [%.5f, %.5f] (swing %.3g), St %.5f, %.1f s\n",
        argv[k], s.t, lo, hi, hi - lo, r.St, r.wall_seconds);
    std::fflush(stdout);
  }
  return 0;
}
