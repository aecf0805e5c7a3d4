#include "app/sweep.hpp"

#include <fmt/core.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>

#include "app/adapt.hpp"
#include "app/case_file.hpp"
#include "app/plot_command.hpp"
#include "app/reference_data.hpp"
#include "postproc/hdf5_io.hpp"
#include "postproc/plot.hpp"
#include "solver/flow_solver.hpp"
#include "solver/memory.hpp"

namespace magnus {

// ---------------------------------------------------------------------------------------------
// Ranges

namespace {

double parse_number(const std::string& s, const std::string& option, const std::string& text, const char* which) {
  const char* begin = s.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (s.empty() || end != begin + s.size() || errno == ERANGE || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{} '{}': {} '{}' is not a finite number (expected A:B:STEP, e.g. 0:4:0.5)",
                                            option, text, which, s));
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
    throw std::invalid_argument(
        fmt::format("{} '{}': expected A:B:STEP (from A to B inclusive in steps of STEP), e.g. 0:4:0.5", option, text));
  SweepRange r;
  r.first = parse_number(parts[0], option, text, "A");
  r.last = parse_number(parts[1], option, text, "B");
  r.step = parse_number(parts[2], option, text, "STEP");
  if (!(r.step > 0.0)) throw std::invalid_argument(fmt::format("{} '{}': STEP must be > 0", option, text));
  if (r.first > r.last) throw std::invalid_argument(fmt::format("{} '{}': A must not exceed B", option, text));
  const double span = (r.last - r.first) / r.step;
  if (!std::isfinite(span) || span + 1.0 > double(kMaxSweepPoints))
    throw std::invalid_argument(fmt::format("{} '{}': {:.3g} points, more than the {} a sweep accepts", option, text,
                                            std::isfinite(span) ? std::floor(span * (1 + 1e-12) + 1e-9) + 1 : span,
                                            kMaxSweepPoints));
  const long n = long(std::floor(span * (1.0 + 1e-12) + 1e-9)) + 1;
  for (long k = 0; k < n; ++k) {
    // A + k·STEP rounded to 15 significant digits: 0.1·3 becomes 0.3, not 0.30000000000000004.
    const double v = std::strtod(fmt::format("{:.15g}", r.first + double(k) * r.step).c_str(), nullptr);
    r.values.push_back(std::min(v, r.last));
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// Solving

namespace {

/// Forwards to the real solver and counts the right-hand sides it solves: proof that a sweep solves
/// twice, however many points it has.
class CountingSolver : public PsiSolver {
 public:
  CountingSolver(const PolarGrid& grid, std::unique_ptr<PsiSolver> inner)
      : PsiSolver(grid, inner->op()), inner_(std::move(inner)) {}
  std::vector<double> solve_unknowns(const std::vector<double>& rhs) override {
    ++count;
    return inner_->solve_unknowns(rhs);
  }
  std::vector<double> solve_boundary(const BoundaryData& bd) override {
    ++count;
    return inner_->solve_boundary(bd);  // the solver's own (possibly faster) path
  }
  Method method() const override { return inner_->method(); }
  const PsiSolver& inner() const { return *inner_; }
  int count = 0;

 private:
  std::unique_ptr<PsiSolver> inner_;
};

SweepResult sweep_cases(const Case& base, const std::vector<Case>& cases, SweepVariable variable, int threads) {
  const double t0 = now_s();
  SweepResult s;
  s.base = base;
  s.variable = variable;
  check_case_memory(base, base.method == Method::cholmod ? Method::cholmod : Method::fft, 0, 0);
  s.grid = make_grid(base);
  const DiscreteOperator op = make_operator(s.grid, base.stencil, base.far_field);
  CountingSolver solver(s.grid, make_solver(s.grid, op, base.method, std::max(1, threads)));
  const PsiBasis pb = solve_basis(solver);  // the only two solves of the sweep
  const FlowBasis fb = flow_basis(s.grid, pb.psi_U, pb.psi_Gamma, derivative_order(base.stencil));
  const double t1 = now_s();

  s.points.resize(cases.size());
  const size_t n_threads = std::clamp<size_t>(size_t(std::max(1, threads)), 1, std::max<size_t>(1, cases.size() / 64));
  auto work = [&](size_t from, size_t to) {
    for (size_t k = from; k < to; ++k) s.points[k] = evaluate(fb, cases[k]);
  };
  if (n_threads <= 1) {
    work(0, cases.size());
  } else {
    std::vector<std::thread> pool;
    const size_t chunk = (cases.size() + n_threads - 1) / n_threads;
    for (size_t t = 0; t < n_threads; ++t)
      pool.emplace_back(work, std::min(cases.size(), t * chunk), std::min(cases.size(), (t + 1) * chunk));
    for (auto& th : pool) th.join();
  }

  s.method = to_string(solver.method());
  s.linear_solves = solver.count;
  s.assemble_s = solver.inner().timing.assemble_s;
  s.factor_s = solver.inner().timing.factor_s;
  s.solve_s = solver.timing.solve_s;
  s.evaluate_s = now_s() - t1;
  s.total_s = now_s() - t0;
  return s;
}

/// The base case for the points: the per-point copies need not carry the TOML text. With
/// grid.tolerance the grid and stencil are chosen once, at α = 1 (Γ = 2πaU): the relative lift error
/// of a grid is the same at every α (lift is linear in Γ at fixed U).
Case point_template(const Case& c, SweepVariable variable, int threads, std::string& choice) {
  Case p = c;
  p.source_text.clear();
  if (c.tolerance > 0.0) {
    Case probe = p;
    if (variable == SweepVariable::spin_ratio) probe.spin = c.speed / c.radius;
    else probe.circulation_value = 2.0 * M_PI * c.radius * c.speed;
    const GridChoice g = choose_grid(probe, std::max(1, threads));
    p.n_theta = g.n_theta;
    p.n_r = 0;
    p.stencil = g.stencil;
    choice = fmt::format("chosen for C_L tolerance {:.3g}: n_θ = {}, {} stencil (estimate {:.3g}; grids tried {})",
                         c.tolerance, g.n_theta, to_string(g.stencil), g.estimated_cl_rel, g.trail);
  }
  return p;
}

}  // namespace

namespace {
/// Sweep the point cases and record the case as asked, with the grid and stencil that ran.
SweepResult finish_sweep(const Case& c, const Case& t, const std::vector<Case>& cases, SweepVariable v, int threads,
                         const std::string& choice) {
  SweepResult s = sweep_cases(t, cases, v, threads);
  s.base = c;  // with its TOML text
  s.base.n_theta = t.n_theta;
  s.base.n_r = t.n_r;
  s.base.stencil = t.stencil;
  s.grid_choice = choice;
  return s;
}
}  // namespace

SweepResult sweep_spin_ratio(const Case& c, const std::vector<double>& alphas, int threads) {
  if (!(c.speed > 0.0))
    throw std::invalid_argument("a spin-ratio sweep needs flow.speed > 0: with U = 0 the spin ratio α = aω/U is undefined");
  if (c.circulation_given)
    throw std::invalid_argument(
        "--spin-ratio varies the spin, but circulation.model = \"given\" fixes Γ: use --circulation A:B:STEP instead");
  std::vector<Case> cases;
  cases.reserve(alphas.size());
  std::string choice;
  const Case t = point_template(c, SweepVariable::spin_ratio, threads, choice);
  for (double alpha : alphas) {
    Case p = t;
    p.spin = alpha * c.speed / c.radius;
    cases.push_back(std::move(p));
  }
  return finish_sweep(c, t, cases, SweepVariable::spin_ratio, threads, choice);
}

SweepResult sweep_circulation(const Case& c, const std::vector<double>& circulations, int threads) {
  if (!(c.speed > 0.0))
    throw std::invalid_argument("a circulation sweep needs flow.speed > 0: with U = 0 the lift coefficients are undefined");
  if (!c.circulation_given)
    throw std::invalid_argument(
        "--circulation needs circulation.model = \"given\" (add --set circulation.model=given), or use --spin-ratio");
  std::vector<Case> cases;
  cases.reserve(circulations.size());
  std::string choice;
  const Case t = point_template(c, SweepVariable::circulation, threads, choice);
  for (double g : circulations) {
    Case p = t;
    p.circulation_value = g;
    cases.push_back(std::move(p));
  }
  return finish_sweep(c, t, cases, SweepVariable::circulation, threads, choice);
}

// ---------------------------------------------------------------------------------------------
// Rows, table, CSV

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
double deg(double rad) { return rad * 180.0 / M_PI; }
/// θ in [0, 2π): a zero found in the last interval before the seam can land on 2π itself.
double wrap(double theta) {
  double t = std::fmod(theta, 2.0 * M_PI);
  if (t < 0.0) t += 2.0 * M_PI;
  return 2.0 * M_PI - t < 1e-9 ? 0.0 : t;
}
/// Stagnation points with θ in [0, 2π), sorted by θ.
std::vector<StagnationPoint> sorted_points(const std::vector<StagnationPoint>& in) {
  std::vector<StagnationPoint> pts = in;
  for (auto& q : pts) q.theta = wrap(q.theta);
  std::sort(pts.begin(), pts.end(), [](const auto& x, const auto& y) { return x.theta < y.theta; });
  return pts;
}
}  // namespace

SweepRow sweep_row(const SweepResult& s, const SweepPoint& p) {
  const Case& c = p.c;
  const Forces& f = p.forces;
  SweepRow w{};
  w.circulation = c.circulation();
  w.alpha = s.variable == SweepVariable::spin_ratio ? c.spin_ratio()
                                                    : w.circulation / (2.0 * M_PI * c.radius * c.speed);
  w.lift = f.lift;
  w.drag = f.drag;
  w.cl = f.cl.value_or(kNaN);
  w.cl_kj = f.cl_kutta_joukowski.value_or(kNaN);
  w.cl_seed = f.cl_seed_estimate.value_or(kNaN);
  w.cl_rel_kj = f.cl && f.cl_kutta_joukowski && *f.cl_kutta_joukowski != 0.0 ? *f.cl / *f.cl_kutta_joukowski - 1.0 : kNaN;
  w.kj_over_seed = f.cl_kutta_joukowski && f.cl_seed_estimate && *f.cl_seed_estimate != 0.0
                       ? *f.cl_kutta_joukowski / *f.cl_seed_estimate
                       : kNaN;
  w.cd = f.cd.value_or(kNaN);
  w.delta_p = f.delta_p_top_bottom;
  w.delta_p_seed = f.delta_p_seed_estimate;
  w.stag_theta1_deg = w.stag_theta2_deg = w.stag_r_over_a = kNaN;
  const std::vector<StagnationPoint> pts = sorted_points(p.stagnation);
  if (!pts.empty()) {
    w.stag_theta1_deg = deg(pts[0].theta);
    w.stag_r_over_a = pts[0].r / c.radius;
    if (pts.size() > 1) w.stag_theta2_deg = deg(pts[1].theta);
  }
  return w;
}

namespace {

std::string cell(double v, const char* spec) {
  if (!std::isfinite(v)) return "—";
  std::string s = fmt::format(fmt::runtime(spec), v);
  // A value that rounds to zero is shown without a sign ("0.000000", not "-0.000000").
  if (s[0] == '-' && s.find_first_of("123456789", 1) == std::string::npos) s.erase(0, 1);
  return s;
}

/// A pressure difference; round-off below 1e-10 of the dynamic pressure q shows as 0.
std::string pressure_cell(double v, double q) { return cell(std::fabs(v) < 1e-10 * q ? 0.0 : v, "{:.7g}"); }

std::string stagnation_text(const SweepPoint& p) {
  if (p.stagnation.empty()) return "none";
  const std::vector<StagnationPoint> pts = sorted_points(p.stagnation);
  if (!pts[0].on_surface) return fmt::format("{:.2f}° at r = {:.4f}a (free)", deg(pts[0].theta), pts[0].r / p.c.radius);
  std::string s;
  for (const auto& q : pts) s += (s.empty() ? "" : ", ") + fmt::format("{:.2f}°", deg(q.theta));
  return s + " (surface)";
}

std::string ms(double s) { return s < 1.0 ? fmt::format("{:.3g} ms", s * 1e3) : fmt::format("{:.3g} s", s); }

std::string range_text(const std::vector<SweepPoint>& pts, const SweepResult& s) {
  if (pts.empty()) return "no points";
  const SweepRow a = sweep_row(s, pts.front()), b = sweep_row(s, pts.back());
  const double x0 = s.variable == SweepVariable::spin_ratio ? a.alpha : a.circulation;
  const double x1 = s.variable == SweepVariable::spin_ratio ? b.alpha : b.circulation;
  return fmt::format("{:.6g} … {:.6g} ({} point{})", x0, x1, pts.size(), pts.size() == 1 ? "" : "s");
}

}  // namespace

std::string sweep_table(const SweepResult& s) {
  const Case& c = s.base;
  const PolarGrid& g = s.grid;
  const bool by_spin = s.variable == SweepVariable::spin_ratio;
  std::string out;
  auto line = [&out](const std::string& label, const std::string& text) { out += fmt::format("{:<13}{}\n", label, text); };
  out += fmt::format("magnus {} — sweep: {}\n", MAGNUS_VERSION, c.title);
  line("case", fmt::format("a = {:.6g} m, U = {:.6g} m/s, ρ = {:.6g} kg/m³", c.radius, c.speed, c.density));
  if (by_spin)
    line("sweep", fmt::format("spin ratio α = aω/U = {}, spin model Γ = 2πa²ω", range_text(s.points, s)));
  else
    line("sweep", fmt::format("circulation Γ (m²/s) = {}, model \"given\"; α_Γ = Γ/(2πaU); "
                              "spin ω = {:.6g} rad/s (aω/U = {:.6g}) for the seed estimate",
                              range_text(s.points, s), c.spin, c.spin_ratio()));
  line("grid", fmt::format("n_θ × n_r = {} × {}, {} spacing, R/a = {:.6g}, far field {}", g.n_theta, g.n_r,
                           to_string(g.spacing), g.outer_radius() / g.a, to_string(c.far_field)));
  if (!s.grid_choice.empty()) line("", s.grid_choice);
  line("solver", fmt::format("{}, {} stencil; superposition ψ = U·ψ_U + Γ·ψ_Γ: one factorization, {} linear solves "
                             "for {} points",
                             s.method, to_string(c.stencil), s.linear_solves, s.points.size()));
  line("timing", fmt::format("assemble {}, factor {}, solve {}, evaluate {}; total {}", ms(s.assemble_s),
                             ms(s.factor_s), ms(s.solve_s), ms(s.evaluate_s), ms(s.total_s)));
  line("columns", "C_L K–J = −Γ/(Ua) (Kutta–Joukowski; −2πα with the spin model), C_L seed = −4aω/U,");
  line("", "ΔP = p(a, 90°) − p(a, 270°) (top − bottom), seed ΔP = 2ρUaω; stagnation θ from +x, counter-clockwise");
  out += "\n";
  const std::string head =
      fmt::format("{:>8} {:>10} {:>12} {:>12} {:>12} {:>12} {:>9} {:>10} {:>13} {:>13}  {}", by_spin ? "α" : "α_Γ", "Γ (m²/s)",
                  "C_L numeric", "C_L K–J", "C_L seed", "num/K–J − 1", "K–J/seed", "C_D", "ΔP (Pa)", "seed ΔP (Pa)",
                  "stagnation points");
  out += head + "\n";
  const double q = 0.5 * c.density * c.speed * c.speed;
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
      "kj_over_seed,cd,delta_p_top_bottom_Pa,delta_p_seed_estimate_Pa,stagnation_theta1_deg,stagnation_theta2_deg,"
      "stagnation_r_over_a\n";
  auto v = [](double x) { return std::isfinite(x) ? fmt::format("{:.17g}", x) : std::string(); };
  for (const auto& p : s.points) {
    const SweepRow w = sweep_row(s, p);
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", v(w.alpha), v(w.circulation), v(w.lift),
                       v(w.drag), v(w.cl), v(w.cl_kj), v(w.cl_seed), v(w.cl_rel_kj), v(w.kj_over_seed), v(w.cd),
                       v(w.delta_p), v(w.delta_p_seed), v(w.stag_theta1_deg), v(w.stag_theta2_deg),
                       v(w.stag_r_over_a));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// HDF5

namespace {

void write_sweep_file(const SweepResult& s, H5Writer& w) {
  const H5Writer::id file = w.file();
  const Case& c = s.base;
  const PolarGrid& g = s.grid;
  const bool by_spin = s.variable == SweepVariable::spin_ratio;
  w.attr(file, "format", "magnus-sweep");
  w.attr(file, "format_version", 1L);
  w.attr(file, "software_version", MAGNUS_VERSION);
  w.attr(file, "title", c.title);
  w.attr(file, "case", c.source_text);
  w.attr(file, "variable", by_spin ? "spin_ratio" : "circulation");
  w.attr(file, "undefined", "NaN marks an undefined value (e.g. cl_over_kj_minus_1 at Γ = 0, a second "
                             "stagnation point when there is one free point)");

  {
    const H5Writer::id p = w.group("/parameters");
    w.attr(p, "radius", c.radius);
    w.attr(p, "speed", c.speed);
    w.attr(p, "density", c.density);
    w.attr(p, "pressure_inf", c.pressure_inf);
    w.attr(p, "circulation_model", c.circulation_given ? "given" : "spin");
    if (!by_spin) w.attr(p, "spin", c.spin);
    w.attr(p, "outer_radius", g.outer_radius() / g.a);
    w.attr(p, "far_field", to_string(c.far_field));
    w.attr(p, "spacing", to_string(c.spacing));
    w.attr(p, "n_r", long(g.n_r));
    w.attr(p, "n_theta", long(g.n_theta));
    w.attr(p, "method", s.method);
    w.attr(p, "stencil", to_string(c.stencil));
    w.attr(p, "units", "radius: m, speed: m/s, density: kg/m^3, pressure_inf: Pa, spin: rad/s, outer_radius: R/a (1)");
  }
  {
    const H5Writer::id t = w.group("/timing");
    w.attr(t, "linear_solves", long(s.linear_solves));
    w.attr(t, "assemble_s", s.assemble_s);
    w.attr(t, "factor_s", s.factor_s);
    w.attr(t, "solve_s", s.solve_s);
    w.attr(t, "evaluate_s", s.evaluate_s);
    w.attr(t, "total_s", s.total_s);
    w.attr(t, "units", "s (wall clock); linear_solves: 1");
  }
  std::vector<SweepRow> rows;
  for (const auto& p : s.points) rows.push_back(sweep_row(s, p));
  auto col = [&](double SweepRow::*m) {
    std::vector<double> v;
    for (const auto& w : rows) v.push_back(w.*m);
    return v;
  };
  const H5Writer::id G = w.group("/sweep");
  auto h5_column = [&w](H5Writer::id g, const char* name, const std::vector<double>& v, const char* units,
                        const char* what) { w.dataset(g, name, {v.size()}, v.data(), units, what); };
  h5_column(G, "alpha", col(&SweepRow::alpha), "1",
            by_spin ? "spin ratio aω/U" : "equivalent spin ratio Γ/(2πaU)");
  h5_column(G, "circulation", col(&SweepRow::circulation), "m^2/s", "circulation Γ");
  h5_column(G, "lift", col(&SweepRow::lift), "N/m", "lift F_y per unit span, numeric");
  h5_column(G, "drag", col(&SweepRow::drag), "N/m", "drag F_x per unit span, numeric");
  h5_column(G, "cl", col(&SweepRow::cl), "1", "lift coefficient, numeric");
  h5_column(G, "cl_kutta_joukowski", col(&SweepRow::cl_kj), "1", "Kutta–Joukowski −Γ/(Ua)");
  h5_column(G, "cl_seed_estimate", col(&SweepRow::cl_seed), "1", "seed estimate −4aω/U");
  h5_column(G, "cl_over_kj_minus_1", col(&SweepRow::cl_rel_kj), "1", "numeric / Kutta–Joukowski − 1");
  h5_column(G, "kj_over_seed", col(&SweepRow::kj_over_seed), "1", "Kutta–Joukowski / seed estimate");
  h5_column(G, "cd", col(&SweepRow::cd), "1", "drag coefficient, numeric");
  h5_column(G, "delta_p_top_bottom", col(&SweepRow::delta_p), "Pa", "p(a, 90°) − p(a, 270°), numeric");
  h5_column(G, "delta_p_seed_estimate", col(&SweepRow::delta_p_seed), "Pa", "seed estimate 2ρUaω");
  h5_column(G, "stagnation_theta1", col(&SweepRow::stag_theta1_deg), "degree",
            "first stagnation point (smallest θ), counter-clockwise from +x");
  h5_column(G, "stagnation_theta2", col(&SweepRow::stag_theta2_deg), "degree",
            "second surface stagnation point; NaN when there is one (free) point");
  h5_column(G, "stagnation_r_over_a", col(&SweepRow::stag_r_over_a), "1",
            "radius of the first stagnation point over a: 1 on the surface, > 1 for a free point");
}

}  // namespace

void write_sweep_hdf5(const SweepResult& s, const std::string& path) {
  write_hdf5_atomic(path, [&](H5Writer& w) { write_sweep_file(s, w); });
}

// ---------------------------------------------------------------------------------------------
// The command

namespace {

/// Viscous reference points within the swept α range beside potential flow's −2πα.
std::string reference_text(const SweepResult& s, const ViscousReference& ref) {
  if (s.points.empty()) return {};
  const double lo = sweep_row(s, s.points.front()).alpha, hi = sweep_row(s, s.points.back()).alpha;
  std::string rows;
  for (const auto& d : ref.datasets)
    for (const auto& p : d.points) {
      if (p.alpha < lo - 1e-9 || p.alpha > hi + 1e-9) continue;
      rows += fmt::format("{:>8} {:>12} {:>12} {:>12}  {}, {}\n", cell(p.alpha, "{:.4g}"), cell(p.cl, "{:.4f}"),
                          p.cd ? cell(*p.cd, "{:.4f}") : std::string("—"), cell(-2 * M_PI * p.alpha, "{:.4f}"),
                          d.label, d.source);
    }
  if (rows.empty()) return {};
  return fmt::format("\nviscous reference, 2D Navier–Stokes (C_L in magnus's sign; {})\n{:>8} {:>12} {:>12} {:>12}  {}\n",
                     "data/viscous_lift_reference.toml", "α", "C_L viscous", "C_D viscous", "C_L −2πα", "source") +
         rows;
}

}  // namespace

void command_sweep(const SweepOptions& o) {
  const bool by_spin = !o.spin_ratio.empty();
  if (by_spin == !o.circulation.empty())
    throw std::invalid_argument("sweep: give exactly one of --spin-ratio A:B:STEP and --circulation A:B:STEP");
  const SweepRange range =
      parse_sweep_range(by_spin ? o.spin_ratio : o.circulation, by_spin ? "--spin-ratio" : "--circulation");
  const PlotSize size = o.size.empty() ? PlotSize{} : parse_plot_size(o.size);
  Case c = load_case(o.case_path, o.sets);
  // Fail before solving, not after.
  check_distinct_paths({o.case_path}, {o.csv, o.output, o.plot});
  for (const std::string* p : {&o.csv, &o.output, &o.plot})
    if (!p->empty()) check_writable(*p);
  const SweepResult s =
      by_spin ? sweep_spin_ratio(c, range.values, o.threads) : sweep_circulation(c, range.values, o.threads);

  std::optional<ViscousReference> ref;
  std::string ref_error;
  if (by_spin) {
    try {
      ref = load_viscous_reference(viscous_reference_path());
    } catch (const std::exception& e) {
      ref_error = e.what();
    }
  }
  if (!o.csv.empty()) write_text_atomic(o.csv, sweep_csv(s));
  if (!o.output.empty()) write_sweep_hdf5(s, o.output);
  if (!o.plot.empty()) {
    std::vector<CurvePoint> numeric;
    for (const auto& p : s.points) {
      const SweepRow w = sweep_row(s, p);
      numeric.push_back({w.alpha, w.cl});
    }
    std::vector<ReferenceSet> sets;
    if (ref)
      for (const auto& d : ref->datasets) {
        ReferenceSet set{d.label, {}};
        for (const auto& p : d.points) set.points.push_back({p.alpha, p.cl});
        sets.push_back(std::move(set));
      }
    const std::string title = fmt::format("Lift against {} (potential flow, n_θ × n_r = {} × {})",
                                          by_spin ? "spin ratio" : "circulation", s.grid.n_theta, s.grid.n_r);
    plot_sweep(title, numeric, sets, o.plot, size,
               by_spin ? std::string() : std::string("equivalent spin ratio Γ/(2πaU)"));
  }
  if (!ref_error.empty() && (!o.quiet || !o.plot.empty()))
    std::fprintf(stderr, "magnus: note: viscous reference data not shown: %s\n", ref_error.c_str());
  if (o.quiet) return;
  std::string text = sweep_table(s);
  if (ref) text += reference_text(s, *ref);
  std::vector<std::string> written;
  for (const std::string* p : {&o.csv, &o.output, &o.plot})
    if (!p->empty()) written.push_back(*p);
  if (!written.empty()) {
    std::string list;
    for (const auto& w : written) list += (list.empty() ? "" : ", ") + w;
    text += fmt::format("\n{:<13}{}\n", "output", list);
  }
  std::fputs(text.c_str(), stdout);
}

}  // namespace magnus
