#include "solver/flow_solver.hpp"

#include <chrono>

namespace magnus {

double now_s() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

Method resolve_method(Method requested, const DiscreteOperator&) {
  // θ is uniform and periodic on every grid magnus makes, so the FFT path always applies.
  return requested == Method::automatic ? Method::fft : requested;
}

std::unique_ptr<PsiSolver> make_solver(const PolarGrid& grid, const DiscreteOperator& op,
                                       Method method, int threads, size_t max_bytes) {
  if (resolve_method(method, op) == Method::cholmod) return make_cholmod_solver(grid, op, max_bytes);
  return make_fft_solver(grid, op, threads);
}

std::vector<double> PsiSolver::solve(double U, double Gamma) {
  const double t0 = now_s();
  std::vector<double> psi = solve_boundary(boundary_data(op_, grid_, U, Gamma));
  timing.solve_s += now_s() - t0;
  return psi;
}

std::vector<double> PsiSolver::solve_boundary(const BoundaryData& bd) {
  return unpack_psi(op_, bd, solve_unknowns(assemble_rhs(op_, bd)));
}

std::vector<double> PsiBasis::combine(double U, double Gamma) const {
  std::vector<double> psi(psi_U.size());
  for (size_t k = 0; k < psi.size(); ++k) psi[k] = U * psi_U[k] + Gamma * psi_Gamma[k];
  return psi;
}

PsiBasis solve_basis(PsiSolver& solver) {
  PsiBasis b;
  b.psi_U = solver.solve(1.0, 0.0);
  b.psi_Gamma = solver.solve(0.0, 1.0);
  return b;
}

}  // namespace magnus
