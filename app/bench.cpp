#include "app/bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "postproc/forces.hpp"
#include "solver/flow_solver.hpp"
#include "solver/memory.hpp"

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
  row.method = to_string(c.method);
  row.stencil = to_string(c.stencil);
  row.n_theta = c.n_theta;
  const int repeats = std::max(1, opt.repeats);
  for (int rep = 0; rep < repeats; ++rep) {
    const double t0 = now_s();
    if (rep == 0) check_case_memory(c, c.method, 0, 0);
    const PolarGrid grid = make_grid(c);
    const DiscreteOperator op = make_operator(grid, c.stencil, c.far_field);
    const double t1 = now_s();
    const auto solver = make_solver(grid, op, c.method, opt.threads);
    const double t2 = now_s();
    const std::vector<double> psi = solver->solve(c.speed, c.circulation());
    const double t3 = now_s();
    const int order = derivative_order(c.stencil);
    const Surface s = compute_surface(grid, c, psi, order);
    const Forces f = compute_forces(c, s);
    const double t4 = now_s();
    // Assembly is part of setup; the solver's own clock splits it from the factorization.
    setup.push_back(t1 - t0 + solver->timing.assemble_s);
    factor.push_back(t2 - t1 - solver->timing.assemble_s);
    solve.push_back(t3 - t2);
    post.push_back(t4 - t3);
    if (rep == 0) {
      const Errors e = compute_errors(c, psi, exact_flow(c).psi_field(grid), s, f);
      row.n_r = grid.n_r;
      row.unknowns = op.unknowns();
      row.cl_rel = e.cl_rel;
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

std::string cell(double v, const char* spec) { return std::isnan(v) ? "—" : fmt::format(fmt::runtime(spec), v); }

}  // namespace

std::vector<BenchRow> run_bench(const Case& base, const BenchOptions& opt,
                                const std::function<void(const std::string&)>& progress) {
  std::vector<BenchRow> rows;
  size_t total = opt.methods.size() * opt.stencils.size() * opt.ladder.size(), done = 0;
  for (Method m : opt.methods)
    for (StencilKind st : opt.stencils) {
      if (st == StencilKind::nine_point && base.spacing != Spacing::geometric) {
        done += opt.ladder.size();
        continue;  // the 9-point stencil needs uniform ξ
      }
      const BenchRow* prev = nullptr;
      for (int n : opt.ladder) {
        ++done;
        Case c = base;
        c.method = m;
        c.stencil = st;
        c.n_theta = n;
        c.n_r = 0;
        c.output_fields = std::vector<std::string>{};
        const GridShape g = grid_shape(c);
        const long unknowns = g.n_r * g.n_theta;
        if (m == Method::cholmod && unknowns > opt.cholmod_max_unknowns) continue;
        if (progress)
          progress(fmt::format("bench {}/{}: {} {} n_θ = {} ({} unknowns)", done, total, to_string(m),
                               to_string(st), n, unknowns));
        BenchRow row = run_rung(c, opt);
        if (prev) {
          const double ratio = std::log(double(row.n_theta) / prev->n_theta);
          if (row.cl_rel > 0 && prev->cl_rel > 0) row.order_cl = std::log(prev->cl_rel / row.cl_rel) / ratio;
          if (row.psi_rel > 0 && prev->psi_rel > 0) row.order_psi = std::log(prev->psi_rel / row.psi_rel) / ratio;
        }
        rows.push_back(row);
        prev = &rows.back();
      }
    }
  return rows;
}

std::string bench_table(const std::vector<BenchRow>& rows) {
  std::string s = fmt::format("{:<8}{:<9}{:>6}{:>6}{:>10}{:>11}{:>11}{:>11}{:>11}{:>11}{:>11}{:>11}{:>11}{:>7}{:>7}\n",
                              "method", "stencil", "n_θ", "n_r", "unknowns", "setup ms", "factor ms", "solve ms",
                              "forces ms", "total ms", "C_L rel", "ψ rel", "Cp abs", "p C_L", "p ψ");
  for (const auto& r : rows)
    s += fmt::format("{:<8}{:<9}{:>6}{:>6}{:>10}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.2e}{:>11.2e}{:>11.2e}{:>7}{:>7}\n",
                     r.method, r.stencil, r.n_theta, r.n_r, r.unknowns, r.setup_s * 1e3, r.factor_s * 1e3,
                     r.solve_s * 1e3, r.post_s * 1e3, r.total_s * 1e3, r.cl_rel, r.psi_rel, r.cp_abs,
                     cell(r.order_cl, "{:.2f}"), cell(r.order_psi, "{:.2f}"));
  return s;
}

std::string bench_csv(const std::vector<BenchRow>& rows) {
  std::string s = "method,stencil,n_theta,n_r,unknowns,setup_s,factor_s,solve_s,forces_s,total_s,cl_rel,psi_max_rel,"
                  "cp_surface_max_abs,order_cl,order_psi\n";
  auto opt = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{:.4f}", v); };
  for (const auto& r : rows)
    s += fmt::format("{},{},{},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{},{}\n", r.method, r.stencil,
                     r.n_theta, r.n_r, r.unknowns, r.setup_s, r.factor_s, r.solve_s, r.post_s, r.total_s, r.cl_rel,
                     r.psi_rel, r.cp_abs, opt(r.order_cl), opt(r.order_psi));
  return s;
}

}  // namespace magnus
