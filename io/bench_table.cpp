#include "io/bench_table.hpp"

#include <fmt/core.h>

#include <cmath>

#include "io/text_format.hpp"

namespace magnus {

std::string bench_table(const std::vector<BenchRow>& rows) {
  std::string s =
      fmt::format("{:<8}{:<9}{:>6}{:>6}{:>10}{:>11}{:>11}{:>11}{:>11}{:>11}{:>11}{:>11}{:>11}{:>7}{:>7}\n",
                  "method", "stencil", "n_θ", "n_r", "unknowns", "setup ms", "factor ms", "solve ms",
                  "forces ms", "total ms", "C_L rel", "ψ rel", "Cp abs", "p C_L", "p ψ");
  for (const auto& r : rows)
    s += fmt::format(
        "{:<8}{:<9}{:>6}{:>6}{:>10}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.2e}{:>11.2e}{:>11.2e}{:"
        ">7}{:>7}\n",
        r.method, r.stencil, r.n_theta, r.n_r, r.unknowns, r.setup_s * 1e3, r.factor_s * 1e3, r.solve_s * 1e3,
        r.post_s * 1e3, r.total_s * 1e3, r.cl_rel, r.psi_rel, r.cp_abs, cell(r.order_cl, "{:.2f}"),
        cell(r.order_psi, "{:.2f}"));
  return s;
}

std::string bench_csv(const std::vector<BenchRow>& rows) {
  std::string s =
      "method,stencil,n_theta,n_r,unknowns,setup_s,factor_s,solve_s,forces_s,total_s,cl_rel,psi_max_rel,"
      "cp_surface_max_abs,order_cl,order_psi\n";
  auto opt = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{:.4f}", v); };
  for (const auto& r : rows)
    s += fmt::format("{},{},{},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{},{}\n",
                     r.method, r.stencil, r.n_theta, r.n_r, r.unknowns, r.setup_s, r.factor_s, r.solve_s,
                     r.post_s, r.total_s, r.cl_rel, r.psi_rel, r.cp_abs, opt(r.order_cl), opt(r.order_psi));
  return s;
}

}  // namespace magnus
