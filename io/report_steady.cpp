#include "io/report_steady.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace magnus {

std::optional<int> significant_digits(double v, double e) {
  if (!(std::fabs(v) > 0.0) || !(e > 0.0) || !std::isfinite(v) || !std::isfinite(e)) return std::nullopt;
  const int lead = int(std::floor(std::log10(std::fabs(v))));  // the first digit's decade
  int d = 0;
  while (d < 15 && e < 0.5 * std::pow(10.0, lead - d)) ++d;  // the (d+1)-th digit's half unit
  return d;
}

namespace {

/// "1.4958 ± 0.0012": the value to the error's second significant digit.
std::string with_error(double v, double e) {
  if (!(e > 0.0)) return fmt::format("{:.6g} ± 0", v);
  const int decimals = std::clamp(1 - int(std::floor(std::log10(e))), 0, 12);
  return fmt::format("{:.{}f} ± {:.{}f}", v, decimals, e, decimals);
}

std::string richardson_line(const char* name, const Richardson& r, const std::string& grids) {
  std::string s = fmt::format("{} = {} (Richardson, grids {}, ", name, with_error(r.value, r.error), grids);
  s += r.observed ? fmt::format("observed order {:.2f})", r.order) : std::string("order 2 assumed)");
  if (const auto d = significant_digits(r.value, r.error)) s += fmt::format(": {} significant digits", *d);
  return s;
}

}  // namespace

std::string steady_study_text(const ViscousPart& v) {
  if (!v.steady_study) return "";
  const SteadyStudy& st = *v.steady_study;
  std::string s;
  auto line = [&s](const std::string& label, const std::string& text) {
    s += fmt::format("{:<15}{}\n", label, text);
  };
  line("grid study", fmt::format("{:<12}{:>10}{:>12}{:>9}   {}", "n_θ × n_r", "C_D", "C_L", "L/D",
                                 "Newton: scaled residual per step (factorisations, s)"));
  std::string grids;  // the three Richardson uses
  for (size_t k = st.levels.size() >= 3 ? st.levels.size() - 3 : 0; k < st.levels.size(); ++k)
    grids += (grids.empty() ? "" : "/") + std::to_string(st.levels[k].n_theta);
  for (const SteadyLevel& lv : st.levels) {
    std::string res;
    for (double r : lv.newton.residuals) res += fmt::format(" {:.1e}", r);
    line("", fmt::format("{:<12}{:>10.5f}{:>12.5f}{:>9.4f}  {} ({}, {:.2f} s)",
                         fmt::format("{} × {}", lv.n_theta, lv.n_r), lv.C_D, lv.C_L + 0.0, lv.recirculation, res,
                         lv.newton.factorisations, lv.newton.wall_seconds));
  }
  if (st.C_D) line("Richardson", richardson_line("C_D", *st.C_D, grids));
  if (st.C_L && std::fabs(st.C_L->finest) > 1e-6) {
    Richardson cl = *st.C_L;
    cl.value = std::fabs(cl.value), cl.finest = std::fabs(cl.finest);
    line("", richardson_line("|C_L|", cl, grids));
  }
  if (st.recirculation && st.recirculation->finest > 0.0)
    line("", richardson_line("L/D", *st.recirculation, grids));
  return s;
}

}  // namespace magnus
