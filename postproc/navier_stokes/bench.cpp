#include "postproc/navier_stokes/bench.hpp"

#include <chrono>

#include "postproc/navier_stokes/forces.hpp"
#include "postproc/navier_stokes/run.hpp"

namespace magnus {

std::vector<NsBenchRow> run_ns_bench(const Case& c, const std::vector<int>& ladder, int steps, int warmup,
                                     int threads) {
  using clock = std::chrono::steady_clock;
  std::vector<NsBenchRow> rows;
  for (int n : ladder) {
    NsParams p = ns_params(c);
    p.threads = threads;
    p.n_theta = n;
    const PolarGrid g = ns_grid(p);
    NsState cur = impulsive_start(p, g), nxt;
    const double dt = cfl_time_step(p, g, cur.psi, p.cfl);
    const NsOperator op(p, dt);
    NsBenchRow row;
    row.n_theta = g.n_theta, row.n_r = g.n_r, row.nodes = long(g.nodes()), row.dt = dt;
    row.time_unit = c.scene.time_unit();
    for (int k = 0; k < warmup; ++k) {
      advance(op, cur, nxt);
      std::swap(cur, nxt);
    }
    const auto t0 = clock::now();
    for (int k = 0; k < steps; ++k) {
      advance(op, cur, nxt, &row.times);
      std::swap(cur, nxt);
      const auto f0 = clock::now();
      const ViscousForces f = viscous_forces(g, p, c.scene.density, cur);
      (void)f;
      row.times.forces += std::chrono::duration<double>(clock::now() - f0).count();
    }
    row.wall_s = std::chrono::duration<double>(clock::now() - t0).count();
    rows.push_back(row);
  }
  return rows;
}

}  // namespace magnus
