#include "io/sweep_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/case_keys.hpp"
#include "io/text_format.hpp"
#include "physics/reference_data.hpp"

namespace magnus {

// ---------------------------------------------------------------------------------------------
// Ranges

namespace {

double parse_number(const std::string& s, const std::string& option, const std::string& text,
                    const char* which) {
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (s.empty() || end != begin + s.size() || errno == ERANGE || !std::isfinite(v))
    throw std::invalid_argument(fmt::format(
        "{} '{}': {} '{}' is not a finite number (expected A:B:STEP, e.g. 0:4:0.5)", option, cut_input(text), which,
        cut_input(s)));
  return v;
}

}  // namespace

SweepRange parse_sweep_range(const std::string& text, const std::string& option) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t k = 0; k <= text.size(); ++k)
    if (k == text.size() || text[k] == ':') {
      parts.push_back(text.substr(start, k - start));
      start = k + 1;
    }
  if (parts.size() != 3)
    throw std::invalid_argument(fmt::format(
        "{} '{}': expected A:B:STEP (from A to B inclusive in steps of STEP), e.g. 0:4:0.5", option, cut_input(text)));
  SweepRange r;
  r.first = parse_number(parts[0], option, text, "A");
  r.last = parse_number(parts[1], option, text, "B");
  r.step = parse_number(parts[2], option, text, "STEP");
  if (!(r.step > 0.0)) throw std::invalid_argument(fmt::format("{} '{}': STEP must be > 0", option, cut_input(text)));
  if (r.first > r.last)
    throw std::invalid_argument(fmt::format("{} '{}': A must not exceed B", option, cut_input(text)));
  const double span = (r.last - r.first) / r.step;
  if (!std::isfinite(span) || span + 1.0 > double(kMaxSweepPoints))
    throw std::invalid_argument(
        fmt::format("{} '{}': {:.3g} points, more than the {} a sweep accepts", option, text,
                    std::isfinite(span) ? std::floor(span * (1 + 1e-12) + 1e-9) + 1 : span, kMaxSweepPoints));
  const long n = long(std::floor(span * (1.0 + 1e-12) + 1e-9)) + 1;
  for (long k = 0; k < n; ++k) {
    // A + k·STEP rounded to 15 significant digits: 0.1·3 becomes 0.3, not 0.30000000000000004.
    const double v = std::strtod(fmt::format("{:.15g}", r.first + double(k) * r.step).c_str(), nullptr);
    r.values.push_back(std::min(v, r.last));
  }
  return r;
}

namespace {

double deg(double rad) { return rad * 180.0 / M_PI; }

/// A pressure difference; round-off below 1e-10 of the dynamic pressure q shows as 0.
std::string pressure_cell(double v, double q) { return cell(std::fabs(v) < 1e-10 * q ? 0.0 : v, "{:.7g}"); }

std::string stagnation_text(const SweepPoint& p) {
  if (p.stagnation.empty()) return "none";
  const std::vector<StagnationPoint>& pts = p.stagnation;  // sorted by θ (find_stagnation_points)
  if (!pts[0].on_surface)
    return fmt::format("{}° at r = {}a (free)", figure(deg(pts[0].theta), "{:.2f}"),
                       figure(pts[0].r / p.scene.radius, "{:.4f}"));
  std::string s;
  for (const auto& q : pts) s += (s.empty() ? "" : ", ") + figure(deg(q.theta), "{:.2f}") + "°";
  return s + " (surface)";
}

std::string range_text(const std::vector<SweepPoint>& pts, const SweepResult& s) {
  if (pts.empty()) return "no points";
  const SweepRow a = sweep_row(s, pts.front()), b = sweep_row(s, pts.back());
  const double x0 = s.variable == SweepVariable::spin_ratio ? a.alpha : a.circulation;
  const double x1 = s.variable == SweepVariable::spin_ratio ? b.alpha : b.circulation;
  return fmt::format("{} … {} ({} point{})", figure(x0, "{:.6g}"), figure(x1, "{:.6g}"), pts.size(),
                     pts.size() == 1 ? "" : "s");
}

}  // namespace

std::string sweep_table(const SweepResult& s) {
  const Case& c = s.base;
  const PolarGrid& g = s.grid;
  const bool by_spin = s.variable == SweepVariable::spin_ratio;
  std::string out;
  auto line = [&out](const std::string& label, const std::string& text) {
    out += fmt::format("{:<13}{}\n", label, text);
  };
  out += fmt::format("magnus {} — sweep: {}\n", MAGNUS_VERSION, c.title);
  line("case", fmt::format("a = {:.6g} m, U = {:.6g} m/s, ρ = {:.6g} kg/m³", c.scene.radius, c.scene.speed,
                           c.scene.density));
  if (by_spin)
    line("sweep", fmt::format("spin ratio α = aω/U = {}, spin model Γ = 2πa²ω", range_text(s.points, s)));
  else
    line("sweep", fmt::format("circulation Γ (m²/s) = {}, model \"given\"; α_Γ = Γ/(2πaU); "
                              "spin ω = {:.6g} rad/s (aω/U = {:.6g}) for the seed estimate",
                              range_text(s.points, s), c.scene.spin, c.scene.spin_ratio()));
  line("grid", fmt::format("n_θ × n_r = {} × {}, {} spacing, R/a = {:.6g}, far field {}", g.n_theta, g.n_r,
                           to_string(g.spacing), g.outer_radius() / g.a, to_string(c.grid.far_field)));
  if (!s.grid_choice.empty()) line("", s.grid_choice);
  line("solver",
       fmt::format("{}, {} stencil; superposition ψ = U·ψ_U + Γ·ψ_Γ: one factorization, {} linear solves "
                   "for {} points",
                   s.method, to_string(c.solver.stencil), s.linear_solves, s.points.size()));
  line("timing", fmt::format("assemble {}, factor {}, solve {}, evaluate {}; total {}", ms(s.assemble_s),
                             ms(s.factor_s), ms(s.solve_s), ms(s.evaluate_s), ms(s.total_s)));
  line("columns", "C_L K–J = −Γ/(Ua) (Kutta–Joukowski; −2πα with the spin model), C_L seed = −4aω/U,");
  line(
      "",
      "ΔP = p(a, 90°) − p(a, 270°) (top − bottom), seed ΔP = 2ρUaω; stagnation θ from +x, counter-clockwise");
  out += "\n";
  const std::string head =
      fmt::format("{:>8} {:>10} {:>12} {:>12} {:>12} {:>12} {:>9} {:>10} {:>13} {:>13}  {}",
                  by_spin ? "α" : "α_Γ", "Γ (m²/s)", "C_L numeric", "C_L K–J", "C_L seed", "num/K–J − 1",
                  "K–J/seed", "C_D", "ΔP (Pa)", "seed ΔP (Pa)", "stagnation points");
  out += head + "\n";
  const double q = 0.5 * c.scene.density * c.scene.speed * c.scene.speed;
  for (const auto& p : s.points) {
    const SweepRow w = sweep_row(s, p);
    out += fmt::format("{:>8} {:>10} {:>12} {:>12} {:>12} {:>12} {:>9} {:>10} {:>13} {:>13}  {}\n",
                       cell(w.alpha, "{:.4g}"), cell(w.circulation, "{:.6g}"), cell(w.cl, "{:.6f}"),
                       cell(w.cl_kj, "{:.6f}"), cell(w.cl_seed, "{:.6f}"), cell(w.cl_rel_kj, "{:.2e}"),
                       cell(w.kj_over_seed, "{:.6f}"), cell(w.cd, "{:.1e}"), pressure_cell(w.delta_p, q),
                       pressure_cell(w.delta_p_seed, q), stagnation_text(p));
  }
  return out;
}

std::string sweep_csv(const SweepResult& s) {
  std::string out =
      "alpha,circulation_m2_s,lift_N_m,drag_N_m,cl,cl_kutta_joukowski,cl_seed_estimate,cl_over_kj_minus_1,"
      "kj_over_seed,cd,delta_p_top_bottom_Pa,delta_p_seed_estimate_Pa,stagnation_theta1_deg,stagnation_"
      "theta2_deg,"
      "stagnation_r_over_a\n";
  auto v = [](double x) { return std::isfinite(x) ? csv_number(x) : std::string(); };
  for (const auto& p : s.points) {
    const SweepRow w = sweep_row(s, p);
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", v(w.alpha), v(w.circulation),
                       v(w.lift), v(w.drag), v(w.cl), v(w.cl_kj), v(w.cl_seed), v(w.cl_rel_kj),
                       v(w.kj_over_seed), v(w.cd), v(w.delta_p), v(w.delta_p_seed), v(w.stag_theta1_deg),
                       v(w.stag_theta2_deg), v(w.stag_r_over_a));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// HDF5

namespace {

/// The value stored where a column with some defined rows is undefined (netCDF's default fill for doubles;
/// the dataset's `_FillValue` attribute says so, and xarray/netCDF readers mask it).
constexpr double kSweepFillValue = 9.969209968386869e36;

double rad(double degrees) { return degrees * M_PI / 180.0; }

void write_sweep_file(const SweepResult& s, H5Writer& w) {
  const H5Writer::id file = w.file();
  const Case& c = s.base;
  const PolarGrid& g = s.grid;
  const bool by_spin = s.variable == SweepVariable::spin_ratio;
  w.attr(file, "format", "magnus-sweep");
  w.attr(file, "format_version", 2L);
  w.attr(file, "format_version_units", "1");
  w.attr(file, "software_version", MAGNUS_VERSION);
  w.attr(file, "model", "potential");
  w.attr(file, "title", c.title);
  w.attr(file, "case", c.source_text);
  w.attr(file, "variable", by_spin ? "spin_ratio" : "circulation");

  {
    const H5Writer::id p = w.group("/parameters");
    w.attr_with_units(p, "radius", c.scene.radius, "m");
    w.attr_with_units(p, "speed", c.scene.speed, "m/s");
    w.attr_with_units(p, "density", c.scene.density, "kg/m^3");
    w.attr_with_units(p, "pressure_inf", c.scene.pressure_inf, "Pa");
    // The scene's Re for the overlays of `magnus plot` (potential flow itself does not use ν).
    if (c.scene.viscosity > 0.0) w.attr_with_units(p, "viscosity", c.scene.viscosity, "m^2/s");
    w.attr(p, "circulation_model", c.scene.circulation_given ? "given" : "spin");
    if (!by_spin) w.attr_with_units(p, "spin", c.scene.spin, "rad/s");
    w.attr_with_units(p, "outer_radius", g.outer_radius() / g.a, "1");
    w.attr(p, "far_field", to_string(c.grid.far_field));
    w.attr(p, "spacing", to_string(c.grid.spacing));
    w.attr(p, "n_r", long(g.n_r));
    w.attr(p, "n_r_units", "1");
    w.attr(p, "n_theta", long(g.n_theta));
    w.attr(p, "n_theta_units", "1");
    w.attr(p, "method", s.method);
    w.attr(p, "stencil", to_string(c.solver.stencil));
  }
  {
    const H5Writer::id t = w.group("/timing");
    w.attr(t, "linear_solves", long(s.linear_solves));
    w.attr(t, "linear_solves_units", "1");
    for (const auto& [name, v] : {std::pair{"assemble_s", s.assemble_s}, std::pair{"factor_s", s.factor_s},
                                  std::pair{"solve_s", s.solve_s}, std::pair{"evaluate_s", s.evaluate_s},
                                  std::pair{"total_s", s.total_s}})
      w.attr_with_units(t, name, v, "s");
  }
  std::vector<SweepRow> rows;
  for (const auto& p : s.points) rows.push_back(sweep_row(s, p));
  const H5Writer::id G = w.group("/sweep");
  std::vector<std::string> undefined;
  // A column: all rows defined → stored as is; none → not stored, listed in /sweep@undefined; some → the
  // undefined rows hold kSweepFillValue, named by the dataset's _FillValue attribute. Never NaN.
  auto column = [&](const char* name, const std::function<double(const SweepRow&)>& get, const char* units,
                    const std::string& what) {
    std::vector<double> v;
    size_t defined = 0;
    for (const auto& row : rows) {
      const double x = get(row);
      defined += std::isfinite(x) ? 1 : 0;
      v.push_back(std::isfinite(x) ? x : kSweepFillValue);
    }
    if (defined == 0 && !rows.empty()) {
      undefined.push_back(name);
      return;
    }
    w.dataset(G, name, {v.size()}, v.data(), units, what);
    if (defined < v.size()) w.attr(w.open(std::string("/sweep/") + name), "_FillValue", kSweepFillValue);
  };
  column(
      "alpha", [](const SweepRow& r) { return r.alpha; }, "1",
      by_spin ? "spin ratio aω/U" : "equivalent spin ratio Γ/(2πaU)");
  column(
      "circulation", [](const SweepRow& r) { return r.circulation; }, "m^2/s", "circulation Γ");
  column(
      "lift", [](const SweepRow& r) { return r.lift; }, "N/m", "lift per unit span (across the freestream), numeric");
  column(
      "drag", [](const SweepRow& r) { return r.drag; }, "N/m", "drag per unit span (along the freestream), numeric");
  column(
      "cl", [](const SweepRow& r) { return r.cl; }, "1", "lift coefficient, numeric");
  column(
      "cl_kutta_joukowski", [](const SweepRow& r) { return r.cl_kj; }, "1", "Kutta–Joukowski −Γ/(Ua)");
  column(
      "cl_seed_estimate", [](const SweepRow& r) { return r.cl_seed; }, "1", "seed estimate −4aω/U");
  column(
      "cl_over_kj_minus_1", [](const SweepRow& r) { return r.cl_rel_kj; }, "1",
      "numeric / Kutta–Joukowski − 1");
  column(
      "kj_over_seed", [](const SweepRow& r) { return r.kj_over_seed; }, "1",
      "Kutta–Joukowski / seed estimate");
  column(
      "cd", [](const SweepRow& r) { return r.cd; }, "1", "drag coefficient, numeric");
  column(
      "delta_p_top_bottom", [](const SweepRow& r) { return r.delta_p; }, "Pa",
      "p(a, π/2) − p(a, 3π/2), numeric");
  column(
      "delta_p_seed_estimate", [](const SweepRow& r) { return r.delta_p_seed; }, "Pa", "seed estimate 2ρUaω");
  column(
      "stagnation_theta1", [](const SweepRow& r) { return rad(r.stag_theta1_deg); }, "rad",
      "first stagnation point (smallest θ in [0, 2π)), counter-clockwise from +x");
  column(
      "stagnation_theta2", [](const SweepRow& r) { return rad(r.stag_theta2_deg); }, "rad",
      "second surface stagnation point; undefined (fill value) when there is one (free) point");
  column(
      "stagnation_r_over_a", [](const SweepRow& r) { return r.stag_r_over_a; }, "1",
      "radius of the first stagnation point over a: 1 on the surface, > 1 for a free point");
  if (!undefined.empty()) {
    std::string list;
    for (const auto& n : undefined) list += (list.empty() ? "" : ", ") + n;
    w.attr(G, "undefined", list);
  }
}

}  // namespace

void write_sweep_hdf5(const SweepResult& s, const std::string& path) {
  write_hdf5_atomic(path, [&](H5Writer& w) { write_sweep_file(s, w); });
}

/// Viscous reference points within the swept α range beside potential flow's −2πα.
std::string sweep_reference_text(const SweepResult& s, const ViscousReference& ref) {
  if (s.points.empty()) return {};
  const double lo = sweep_row(s, s.points.front()).alpha, hi = sweep_row(s, s.points.back()).alpha;
  std::string rows;
  for (const auto& d : ref.datasets)
    for (const auto& p : d.points) {
      if (p.alpha < lo - 1e-9 || p.alpha > hi + 1e-9) continue;
      rows += fmt::format("{:>8} {:>12} {:>12} {:>12}  {}, {}\n", cell(p.alpha, "{:.4g}"),
                          cell(p.cl, "{:.4f}"), p.cd ? cell(*p.cd, "{:.4f}") : std::string("—"),
                          cell(-2 * M_PI * p.alpha, "{:.4f}"), d.label, d.source);
    }
  if (rows.empty()) return {};
  return fmt::format(
             "\nviscous reference, 2D Navier–Stokes (C_L in magnus's sign; {})\n{:>8} {:>12} {:>12} {:>12}  "
             "{}\n",
             "data/viscous_lift_reference.toml", "α", "C_L viscous", "C_D viscous", "C_L −2πα", "source") +
         rows;
}

}  // namespace magnus
