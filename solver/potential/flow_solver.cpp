#include "solver/potential/flow_solver.hpp"

#include <chrono>

namespace magnus {

double now_s() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

Method resolve_method(Method requested) { return requested == Method::automatic ? Method::fft : requested; }

std::unique_ptr<PsiSolver> make_solver(const PolarGrid& grid, const DiscreteOperator& op, Method method,
                                       int threads, size_t max_bytes) {
  if (resolve_method(method) == Method::cholmod) return make_cholmod_solver(grid, op, max_bytes);
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

std::vector<double> superpose(double U, const std::vector<double>& f_U, double Gamma,
                              const std::vector<double>& f_Gamma) {
  std::vector<double> f(f_U.size());
  for (size_t k = 0; k < f.size(); ++k) f[k] = U * f_U[k] + Gamma * f_Gamma[k];
  return f;
}

std::vector<double> PsiBasis::combine(double U, double Gamma) const {
  return superpose(U, psi_U, Gamma, psi_Gamma);
}

PsiBasis solve_basis(PsiSolver& solver) {
  PsiBasis b;
  b.psi_U = solver.solve(1.0, 0.0);
  b.psi_Gamma = solver.solve(0.0, 1.0);
  return b;
}

}  // namespace magnus
