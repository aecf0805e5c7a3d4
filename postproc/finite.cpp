#include "postproc/finite.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace magnus {

std::string first_non_finite(const FlowResult& r) {
  const Forces& f = r.forces;
  const std::vector<std::pair<const char*, std::optional<double>>> figures = {
      {"lift F_y", f.lift},
      {"drag F_x", f.drag},
      {"C_L", f.cl},
      {"C_D", f.cd},
      {"C_L Kutta–Joukowski", f.cl_kutta_joukowski},
      {"C_L seed estimate", f.cl_seed_estimate},
      {"lift Kutta–Joukowski −ρUΓ", f.lift_kutta_joukowski},
      {"ΔP top−bottom", f.delta_p_top_bottom},
      {"ΔP top−bottom exact", f.delta_p_top_bottom_exact},
      {"ΔP seed estimate", f.delta_p_seed_estimate},
      {"circulation measured", f.circulation_measured},
      {"Magnus S", f.magnus_S},
      {"Magnus S exact", f.magnus_S_exact},
      {"circulation Γ", r.c.scene.Gamma()},
      {"error ψ max rel", r.errors.psi_max_rel},
      {"error Cp surface max abs", r.errors.cp_surface_max_abs},
      {"error C_L rel", r.errors.cl_rel},
      {"error Γ rel", r.errors.circulation_rel}};
  for (const auto& [name, v] : figures)
    if (v && !std::isfinite(*v)) return name;
  for (const auto* pts : {&r.stagnation, &r.stagnation_exact})
    for (const auto& p : *pts)
      if (!std::isfinite(p.r) || !std::isfinite(p.theta)) return "a stagnation point";
  const auto bad = [](const std::vector<double>& v) {
    for (size_t q = 0; q < v.size(); ++q)
      if (!std::isfinite(v[q])) return q;
    return v.size();
  };
  const size_t n_theta = size_t(r.grid.n_theta);
  for (const auto& name : field_names()) {
    const std::vector<double>& v = r.fields.get(name);
    if (const size_t q = bad(v); q < v.size())
      return fmt::format("field {} at (i, j) = ({}, {})", name, q / n_theta, q % n_theta);
  }
  const Surface& s = r.surface;
  for (const auto& [name, v] :
       {std::pair{"surface u_theta", &s.u_theta}, std::pair{"surface pressure", &s.pressure},
        std::pair{"surface cp", &s.cp}, std::pair{"surface cp exact", &s.cp_exact}})
    if (const size_t q = bad(*v); q < v->size()) return fmt::format("{} at j = {}", name, q);
  for (const auto& [name, v] : {std::pair{"grid r", &r.grid.r}, std::pair{"grid θ", &r.grid.theta}})
    if (const size_t q = bad(*v); q < v->size()) return fmt::format("{} at {}", name, q);
  return "";
}

void check_finite(const FlowResult& r) {
  const std::string what = first_non_finite(r);
  if (!what.empty())
    throw std::runtime_error(fmt::format(
        "{} is not finite (NaN or infinite: the inputs are beyond double precision); nothing was written",
        what));
}

}  // namespace magnus
