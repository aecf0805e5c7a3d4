#include "postproc/potential/bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "postproc/potential/pipeline.hpp"

namespace magnus {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

BenchRow run_rung(const Case& c, const BenchOptions& opt) {
  std::vector<double> setup, factor, solve, post;
  BenchRow row;
  row.method = to_string(c.solver.method);
  row.stencil = to_string(c.solver.stencil);
  row.n_theta = c.grid.n_theta;
  const int repeats = std::max(1, opt.repeats);
  for (int rep = 0; rep < repeats; ++rep) {
    const double t0 = now_s();
    const Discretization d = discretize(c, opt.threads);  // grid, operator, factor
    const double t1 = now_s();
    const std::vector<double> psi = d.solver->solve(c.scene.speed, c.scene.Gamma());
    const double t2 = now_s();
    const Surface s = compute_surface(d.grid, c.scene, psi, derivative_order(c.solver.stencil));
    const Forces f = compute_forces(c.scene, s);
    const double t3 = now_s();
    // The solver's own clock gives the factorization; everything else before the solve (memory guard,
    // grid, stencil rows, assembly) is setup.
    const double factor_s = d.solver->timing.factor_s;
    setup.push_back(t1 - t0 - factor_s);
    factor.push_back(factor_s);
    solve.push_back(t2 - t1);
    post.push_back(t3 - t2);
    if (rep == 0) {
      const Errors e =
          compute_errors(c.scene, psi, exact_flow(c.scene).psi_field(d.grid.r, d.grid.theta), s, f);
      row.n_r = d.grid.n_r;
      row.unknowns = d.solver->op().unknowns();
      row.cl_rel = *e.cl_rel;  // U > 0: run_bench refuses U = 0
      row.psi_rel = e.psi_max_rel;
      row.cp_abs = e.cp_surface_max_abs.value_or(0.0);
    }
  }
  row.setup_s = median(setup);
  row.factor_s = median(factor);
  row.solve_s = median(solve);
  row.post_s = median(post);
  row.total_s = row.setup_s + row.factor_s + row.solve_s + row.post_s;
  return row;
}

}  // namespace

std::vector<BenchRow> run_bench(const Case& base, const BenchOptions& opt,
                                const std::function<void(const std::string&)>& progress) {
  if (!(base.scene.speed > 0.0))
    throw std::runtime_error(
        "bench: flow.speed = 0: C_L and its error are undefined without a freestream; "
        "bench needs flow.speed > 0");
  std::vector<BenchRow> rows;
  size_t total = opt.methods.size() * opt.stencils.size() * opt.ladder.size(), done = 0;
  for (Method m : opt.methods)
    for (StencilKind st : opt.stencils) {
      if (st == StencilKind::nine_point && base.grid.spacing != Spacing::geometric) {
        done += opt.ladder.size();
        continue;  // the 9-point stencil needs uniform ξ
      }
      const BenchRow* prev = nullptr;
      for (int n : opt.ladder) {
        ++done;
        Case c = base;
        c.solver.method = m;
        c.solver.stencil = st;
        c.grid.n_theta = n;
        c.grid.n_r = 0;
        c.output.fields = std::vector<std::string>{};
        const GridShape g = grid_shape(c.grid);
        const long unknowns = g.n_r * g.n_theta;
        if (m == Method::cholmod && unknowns > opt.cholmod_max_unknowns) continue;
        if (progress)
          progress(fmt::format("bench {}/{}: {} {} n_θ = {} ({} unknowns)", done, total, to_string(m),
                               to_string(st), n, unknowns));
        BenchRow row = run_rung(c, opt);
        if (prev) {
          const double ratio = std::log(double(row.n_theta) / prev->n_theta);
          if (row.cl_rel > 0 && prev->cl_rel > 0) row.order_cl = std::log(prev->cl_rel / row.cl_rel) / ratio;
          if (row.psi_rel > 0 && prev->psi_rel > 0)
            row.order_psi = std::log(prev->psi_rel / row.psi_rel) / ratio;
        }
        rows.push_back(row);
        prev = &rows.back();
      }
    }
  return rows;
}

}  // namespace magnus
