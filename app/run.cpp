#include "app/run.hpp"

#include <fmt/core.h>

#include <cstdio>

#include "app/case_file.hpp"
#include "postproc/hdf5_io.hpp"
#include "postproc/report.hpp"
#include "solver/flow_solver.hpp"

namespace magnus {

FlowResult run_case(const Case& c, int threads) {
  const double t0 = now_s();
  const PolarGrid grid = make_grid(c);                                      // make grid
  const DiscreteOperator op = make_operator(grid, c.stencil, c.far_field);  // stencils and closures
  const auto solver = make_solver(grid, op, c.method, threads);             // assemble and factor
  const std::vector<double> psi = solver->solve(c.speed, c.circulation());  // solve
  const double t1 = now_s();
  FlowResult r = postprocess(grid, c, psi, select_fields(c.output_fields));  // fields, forces, errors
  r.timing.assemble_s = solver->timing.assemble_s;
  r.timing.factor_s = solver->timing.factor_s;
  r.timing.solve_s = solver->timing.solve_s;
  r.timing.postproc_s = now_s() - t1;
  r.timing.total_s = now_s() - t0;
  r.info.method = to_string(solver->method());
  r.info.threads = threads;
  return r;
}

void command_run(const std::string& case_path, const std::string& output, const std::vector<std::string>& sets,
                int threads, bool quiet) {
  Case c = load_case(case_path, sets);
  if (!output.empty()) {
    c.output_file = output;
    c.source_text = to_toml(c);
  }
  check_writable(c.output_file);  // fail before solving, not after
  FlowResult r = run_case(c, threads);
  write_result(r, c.output_file);
  if (!quiet) std::fputs(summary_text(r, c.output_file).c_str(), stdout);
}

void command_inspect(const std::string& path) {
  std::fputs(describe_result(path).c_str(), stdout);
}

}  // namespace magnus
