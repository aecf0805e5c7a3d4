#include "app/run.hpp"

#include <fmt/core.h>

#include <cstdio>

#include "app/adapt.hpp"
#include "app/case_file.hpp"
#include "postproc/hdf5_io.hpp"
#include "postproc/report.hpp"
#include "solver/flow_solver.hpp"
#include "solver/memory.hpp"

namespace magnus {

FlowResult run_case(const Case& requested, int threads, size_t max_bytes) {
  const double t0 = now_s();
  Case c = requested;
  GridChoice choice;
  if (c.tolerance > 0.0) {  // only what the scene needs: the grid the tolerance asks for
    choice = choose_grid(c, threads);
    c.n_theta = choice.n_theta;
    c.n_r = 0;
    c.stencil = choice.stencil;
  }
  const double t_choice = now_s() - t0;
  const FieldSelection sel = select_fields(c.output_fields);
  int fields = 0;
  for (bool on : sel.on) fields += on;
  check_case_memory(c, c.method == Method::cholmod ? Method::cholmod : Method::fft, fields, max_bytes);
  const PolarGrid grid = make_grid(c);                                      // make grid
  const double t_op = now_s();
  const DiscreteOperator op = make_operator(grid, c.stencil, c.far_field);  // stencils and closures
  const double op_s = now_s() - t_op;
  const Method method = resolve_method(c.method, op);
  const auto solver = make_solver(grid, op, method, threads, max_bytes);     // assemble and factor
  const PsiBasis basis = solve_basis(*solver);                              // solve ψ_U, ψ_Γ
  const double t1 = now_s();
  FlowResult r = postprocess(grid, c, basis.psi_U, basis.psi_Gamma, sel);
  r.timing.assemble_s = op_s + solver->timing.assemble_s;
  r.timing.factor_s = solver->timing.factor_s;
  r.timing.solve_s = solver->timing.solve_s;
  r.timing.postproc_s = now_s() - t1;
  r.timing.total_s = now_s() - t0;
  r.info.method = to_string(solver->method());
  r.info.threads = threads;
  if (c.tolerance > 0.0) {
    r.info.estimated_cl_rel = choice.estimated_cl_rel;
    r.info.grid_choice = fmt::format("chosen for C_L tolerance {:.3g}: n_θ = {}, {} stencil (grids tried {}, {:.3g} ms)",
                                     c.tolerance, c.n_theta, to_string(c.stencil), choice.trail, t_choice * 1e3);
  }
  return r;
}

void command_run(const std::string& case_path, const std::string& output, const std::vector<std::string>& sets,
                int threads, bool quiet, size_t max_bytes) {
  Case c = load_case(case_path, sets);
  if (!output.empty()) {
    c.output_file = output;
    c.source_text = to_toml(c);
  }
  // Fail before solving, not after: the result, its sidecar, and neither overwriting the case.
  check_distinct_paths({case_path}, {c.output_file, xdmf_path(c.output_file)});
  check_writable(c.output_file);
  check_writable(xdmf_path(c.output_file));
  FlowResult r = run_case(c, threads, max_bytes);
  write_result(r, c.output_file);
  if (!quiet) std::fputs(summary_text(r, c.output_file).c_str(), stdout);
}

void command_inspect(const std::string& path) {
  std::fputs(describe_result(path).c_str(), stdout);
}

}  // namespace magnus
