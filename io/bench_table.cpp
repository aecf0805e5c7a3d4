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

namespace {

/// The parts of a step, in table order: name and seconds.
std::vector<std::pair<const char*, double>> parts(const NsStepTimes& t) {
  return {{"advection", t.advection}, {"diffusion", t.helmholtz}, {"Poisson", t.poisson},
          {"wall", t.wall},           {"other", t.other},         {"forces", t.forces}};
}

}  // namespace

std::string ns_bench_table(const std::vector<NsBenchRow>& rows) {
  std::string s = fmt::format("{:>6}{:>6}{:>9}{:>11}{:>9}{:>10}{:>9}", "n_θ", "n_r", "nodes", "Δt (D/U)",
                              "steps/s", "ms/step", "ns/node");
  for (const auto& [name, v] : parts(NsStepTimes{})) {
    (void)v;
    s += fmt::format("{:>17}", name);
  }
  s += "\n";
  for (const auto& r : rows) {
    const double n = double(std::max(r.times.steps, 1L)), total = r.times.total();
    s += fmt::format("{:>6}{:>6}{:>9}{:>11.4g}{:>9.0f}{:>10.3f}{:>9.1f}", r.n_theta, r.n_r, r.nodes,
                     r.dt / r.time_unit, r.steps_per_second(), 1e3 * r.wall_s / n, r.ns_per_node());
    for (const auto& [name, v] : parts(r.times)) {
      (void)name;
      s += fmt::format("{:>17}", fmt::format("{:.3f} ({:.0f}%)", 1e3 * v / n, total > 0 ? 100.0 * v / total : 0.0));
    }
    s += "\n";
  }
  return s;
}

std::string ns_bench_csv(const std::vector<NsBenchRow>& rows) {
  std::string s = "n_theta,n_r,nodes,dt_s,dt_convective,steps,steps_per_s,ms_per_step";
  for (const auto& [name, v] : parts(NsStepTimes{})) {
    (void)v;
    s += fmt::format(",{}_ms", name);
  }
  s += ",ns_per_node\n";
  for (const auto& r : rows) {
    const double n = double(std::max(r.times.steps, 1L));
    s += fmt::format("{},{},{},{:.6e},{:.6e},{},{:.6g},{:.6g}", r.n_theta, r.n_r, r.nodes, r.dt,
                     r.dt / r.time_unit, r.times.steps, r.steps_per_second(), 1e3 * r.wall_s / n);
    for (const auto& [name, v] : parts(r.times)) {
      (void)name;
      s += fmt::format(",{:.6g}", 1e3 * v / n);
    }
    s += fmt::format(",{:.6g}\n", r.ns_per_node());
  }
  return s;
}

std::string ns_bench_bound(const std::vector<NsBenchRow>& rows, const NsBound& b) {
  const std::string measured = fmt::format("{} thread{}", b.threads, b.threads == 1 ? "" : "s");
  if (!(b.bandwidth > 0.0) || !std::isfinite(b.bandwidth))
    return fmt::format("The step moves about {:.0f} bytes per node; the memory bandwidth could not be measured "
                       "(triad, {}).\n", b.bytes_per_node, measured);
  const double bound = 1e9 * b.bytes_per_node / b.bandwidth;  // ns per node
  std::string s = fmt::format("The step moves about {:.0f} bytes per node: at the measured {:.3g} GB/s (triad, {}) "
                              "no step can take less than {:.3g} ns/node",
                              b.bytes_per_node, b.bandwidth * 1e-9, measured, bound);
  const NsBenchRow* big = nullptr;
  for (const auto& r : rows)
    if (!big || r.nodes > big->nodes) big = &r;
  if (!big || !(big->ns_per_node() > 0.0)) return s + ".\n";
  s += fmt::format("; this one takes {:.1f} at n_θ = {} ({:.1f}× the bound)", big->ns_per_node(), big->n_theta,
                   big->ns_per_node() / bound);
  const double arrays = b.array_bytes_per_node * double(big->nodes);
  if (b.cache > 0.0 && arrays < b.cache)
    s += fmt::format(", though its arrays ({:.0f} MB) fit in the {:.0f} MiB last-level cache", arrays * 1e-6,
                     b.cache / double(1 << 20));
  return s + ".\n";
}

}  // namespace magnus
