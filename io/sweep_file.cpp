#include "io/sweep_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/schema_files.hpp"
#include "io/schema_io.hpp"
#include "io/case_keys.hpp"
#include "io/text_format.hpp"
#include "physics/reference_data.hpp"
#include "postproc/derived.hpp"

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

/// Root, /parameters and /timing from the table, then one column per dataset in /sweep (undefined rows:
/// the fill value; a column undefined at every point: not stored, listed in /sweep@undefined).
void write_sweep_file(const SweepResult& s, H5Writer& w) {
  FileGroups g{w};
  write_attrs(attr_values(sweep_attributes(), s, Shown::file_only), g);
  std::vector<SweepRow> rows;
  for (const auto& p : s.points) rows.push_back(sweep_row(s, p));
  g("/sweep");  // the group, also when there are no points
  write_columns(g, "/sweep", sweep_columns(s.variable), rows, Gaps::fill_or_omit);
  write_undefined(g);
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
                          cell(cl_ideal(p.alpha), "{:.4f}"), d.label, d.source);
    }
  if (rows.empty()) return {};
  return fmt::format(
             "\nviscous reference, 2D Navier–Stokes (C_L in magnus's sign; {})\n{:>8} {:>12} {:>12} {:>12}  "
             "{}\n",
             "data/viscous_lift_reference.toml", "α", "C_L viscous", "C_D viscous", "C_L −2πα", "source") +
         rows;
}

}  // namespace magnus
