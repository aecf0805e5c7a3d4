#include "plot/figures.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/reference_file.hpp"
#include "io/result_reader.hpp"
#include "physics/exact.hpp"

namespace magnus {

PlotSize parse_plot_size(const std::string& text) {
  const auto x = text.find_first_of("xX");
  auto part = [&](const std::string& s) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) return -1;
    return std::atoi(s.c_str());
  };
  const int w = x == std::string::npos ? -1 : part(text.substr(0, x));
  const int h = x == std::string::npos ? -1 : part(text.substr(x + 1));
  if (w < 0 || h < 0)
    throw std::invalid_argument(
        fmt::format("--size '{}': expected WIDTHxHEIGHT in pixels, e.g. 900x700", text));
  if (w < 16 || h < 16 || w > 16384 || h > 16384)
    throw std::invalid_argument(fmt::format("--size '{}': each side must be 16 to 16384 pixels", text));
  return {w, h};
}

namespace {

std::string num(double v, int digits = 3) { return v == 0.0 ? "0" : fmt::format("{:.{}g}", v, digits); }

/// "α = 1.5" (with the circulation when it is given, or "U = 0").
std::string flow_label(const Case& c) {
  if (c.scene.speed <= 0.0) return fmt::format("U = 0, Γ = {} m²/s", num(c.scene.Gamma()));
  std::string s = fmt::format("α = {}", num(c.scene.spin_ratio(), 4));
  if (c.scene.circulation_given) s += fmt::format(", Γ = {} m²/s", num(c.scene.Gamma()));
  return s;
}

/// flow_label, with the Reynolds number of a navier-stokes result.
std::string flow_label(const FlowResult& r) {
  std::string s = flow_label(r.c);
  if (r.viscous && r.viscous->reynolds) s += fmt::format(", Re = {}", num(*r.viscous->reynolds, 4));
  return s;
}

/// θ in degrees over one turn, for the surface plots.
void theta_axis(CurvePage& p) {
  p.xlabel = "θ (degrees, counter-clockwise from +x: 0° rear, 180° front)";
  p.fixed_x = true;
  p.x_min = 0.0;
  p.x_max = 360.0;
  p.x_tick = 45.0;
  p.x_subticks = 3;
}

std::string case_title(const std::string& title) {
  return literal_text(title.empty() ? std::string("Spinning cylinder") : title);
}

FieldView view_of(const FlowResult& r, const std::string& what) {
  FieldView v;
  v.title = case_title(r.c.title) + ": " + what + ", " + flow_label(r);
  v.unit = r.grid.a;
  v.half_width = view_half_width(r);
  v.body_radius = 1.0;
  return v;
}

PolarField polar(const PolarGrid& g, const std::vector<double>& values) { return {g.r, g.theta, values}; }

CurvePoint in_units(const StagnationPoint& s, double a) {
  return {s.r / a * std::cos(s.theta), s.r / a * std::sin(s.theta)};
}

bool inside(const CurvePoint& p, double w) { return std::fabs(p.x) <= w && std::fabs(p.y) <= w; }

}  // namespace

double view_half_width(const FlowResult& r) {
  const double a = r.grid.a, R = r.grid.outer_radius() / a;
  double w = std::min(R, 4.0);
  for (const auto* set : {&r.stagnation, &r.stagnation_exact})
    for (const auto& s : *set)
      if (!s.on_surface) w = std::max(w, std::min(R, 1.2 * s.r / a));
  return w;
}

StreamlinePicture streamline_picture(const FlowResult& r) {
  const PolarGrid& g = r.grid;
  if (r.fields.psi.size() != size_t(g.nodes()) || g.n_r < 2 || g.n_theta < 4)
    throw std::runtime_error("plot: the result has no psi field");
  StreamlinePicture p;
  p.view = view_of(r, "streamlines");
  p.psi = polar(g, r.fields.psi);
  const double w = p.view.half_width;
  for (const auto& s : r.stagnation) {
    const CurvePoint q = in_units(s, g.a);
    if (inside(q, w)) {
      p.numeric_points.push_back(q);
      if (!s.on_surface) {
        p.has_saddle = true;
        p.saddle = q;
      }
    } else {
      p.notes.push_back(
          fmt::format("numeric stagnation point at r = {}a: outside the window", num(s.r / g.a)));
    }
  }
  for (const auto& s : r.stagnation_exact) {
    const CurvePoint q = in_units(s, g.a);
    if (inside(q, w))
      p.exact_points.push_back(q);
    else
      p.notes.push_back(fmt::format("exact stagnation point at r = {}a: outside the window", num(s.r / g.a)));
  }
  return p;
}

ContourFieldPicture cp_picture(const FlowResult& r) {
  const PolarGrid& g = r.grid;
  if (r.fields.cp.empty()) throw std::runtime_error("plot: the result has no cp field");
  if (r.fields.cp.size() != size_t(g.nodes()))
    throw std::runtime_error("plot: the cp field does not match the grid");
  ContourFieldPicture p;
  p.view = view_of(r, "pressure coefficient");
  p.field = polar(g, r.fields.cp);
  p.bar_label = "Cp";
  for (const auto& s : r.stagnation) {
    const CurvePoint q = in_units(s, g.a);
    if (inside(q, p.view.half_width)) p.points.push_back(q);
  }
  p.footnote =
      r.viscous ? "dashed: Cp = 0" : "dashed: Cp = 0 (|u| = U);  red dots: stagnation points (Cp = 1)";
  return p;
}

ContourFieldPicture vorticity_picture(const FlowResult& r) {
  const PolarGrid& g = r.grid;
  if (r.fields.vorticity.empty()) throw std::runtime_error("plot: the result has no vorticity field");
  if (r.fields.vorticity.size() != size_t(g.nodes()))
    throw std::runtime_error("plot: the vorticity field does not match the grid");
  ContourFieldPicture p;
  p.view = view_of(r, "vorticity");
  p.field = polar(g, r.fields.vorticity);
  p.bar_label = "ζ (1/s)";
  p.zero_contour = false;
  p.diverging = true;
  // The wall's thin layer holds the largest |ζ|; colours over its peak would leave the wake white.
  const double w = p.view.half_width * g.a;
  std::vector<double> mags;
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j) {
      const double x = g.r[i] * std::cos(g.theta[j]), y = g.r[i] * std::sin(g.theta[j]);
      if (std::fabs(x) <= w && std::fabs(y) <= w)
        mags.push_back(std::fabs(r.fields.vorticity[size_t(i) * g.n_theta + j]));
    }
  std::sort(mags.begin(), mags.end());
  const double peak = mags.empty() ? 0.0 : mags.back();
  p.limit = mags.empty() ? 0.0 : mags[std::min(mags.size() - 1, size_t(0.98 * double(mags.size())))];
  if (!(p.limit > 0.0)) p.limit = peak;
  p.footnote = p.limit < peak ? fmt::format(
                                    "red: counter-clockwise (ζ > 0), blue: clockwise;  colours end at "
                                    "±{} 1/s (|ζ| reaches {} 1/s at the wall)",
                                    num(p.limit), num(peak))
                              : std::string("red: counter-clockwise (ζ > 0), blue: clockwise");
  return p;
}

CurveFigure force_history_figure(const FlowResult& r) {
  if (!r.viscous || r.viscous->history.empty())
    throw std::runtime_error("plot: the result has no force history");
  const ViscousPart& v = *r.viscous;
  const double unit = v.time_unit > 0.0 ? v.time_unit : 1.0;
  CurveFigure f;
  f.page.title = case_title(r.c.title) + ": forces against time, " + flow_label(r);
  f.page.xlabel = v.time_unit > 0.0 ? "time t U/D" : "time t (s)";
  if (v.time_unit > 0.0 && v.history.back().t / unit > 10.0)
    f.page.xlabel += " (from 2: the impulsive start's force peak is left out)";
  f.page.ylabel = "C_L, C_D (on ½ρU^2·D)";
  LineCurve cl{"C_L", {}, Colour::red, LineStyle::solid, 1.8},
      cd{"C_D", {}, Colour::blue, LineStyle::solid, 1.8};
  // At most ~4000 points a curve: a long run's every step would only repeat pixels.
  const size_t n = v.history.size(), stride = std::max<size_t>(1, n / 4000);
  // The impulsive start's force grows like 1/√t as t → 0 (C_D ≈ 50 at the first step): the first 2 D/U
  // are left out so that the shedding is readable.
  const double t_skip = v.time_unit > 0.0 && v.history.back().t / unit > 10.0 ? 2.0 : 0.0;
  for (size_t k = 0; k < n; k += stride) {
    const ForceSample& h = v.history[k];
    if (h.t / unit < t_skip) continue;
    cl.points.push_back({h.t / unit, h.C_L});
    cd.points.push_back({h.t / unit, h.C_D});
  }
  if ((n - 1) % stride != 0) {
    cl.points.push_back({v.history.back().t / unit, v.history.back().C_L});
    cd.points.push_back({v.history.back().t / unit, v.history.back().C_D});
  }
  const double t0 = std::max(v.history.front().t / unit, t_skip), t1 = v.history.back().t / unit;
  f.lines.push_back(std::move(cl));
  f.lines.push_back(std::move(cd));
  if (v.cl_mean)
    f.lines.push_back({fmt::format("mean C_L = {}", num(*v.cl_mean, 4)),
                       {{t0, *v.cl_mean}, {t1, *v.cl_mean}},
                       Colour::red,
                       LineStyle::dashed,
                       1.2});
  if (v.cd_mean)
    f.lines.push_back({fmt::format("mean C_D = {}", num(*v.cd_mean, 4)),
                       {{t0, *v.cd_mean}, {t1, *v.cd_mean}},
                       Colour::blue,
                       LineStyle::dashed,
                       1.2});
  if (v.cl_ideal && *v.cl_ideal != 0.0)
    f.lines.push_back({fmt::format("potential flow C_L = −2πα = {}", num(*v.cl_ideal, 4)),
                       {{t0, *v.cl_ideal}, {t1, *v.cl_ideal}},
                       Colour::grey,
                       LineStyle::dotted,
                       1.6});
  return f;
}

CurveFigure shear_stress_figure(const FlowResult& r) {
  const Surface& s = r.surface;
  if (s.shear_stress.empty()) throw std::runtime_error("plot: the result has no wall shear stress");
  if (s.theta.size() != s.shear_stress.size())
    throw std::runtime_error("plot: surface theta and shear stress differ in length");
  CurveFigure f;
  f.page.title = case_title(r.c.title) + ": wall shear stress, " + flow_label(r);
  theta_axis(f.page);
  f.page.ylabel = "τ_w = μ(ζ_w − 2ω) (Pa)";
  LineCurve tau{fmt::format("τ_w, n_θ = {}", s.theta.size()), {}, Colour::blue, LineStyle::solid, 2.0};
  for (size_t j = 0; j < s.theta.size(); ++j)
    tau.points.push_back({s.theta[j] * 180.0 / M_PI, s.shear_stress[j]});
  tau.points.push_back({360.0, s.shear_stress[0]});
  f.lines.push_back(std::move(tau));
  if (r.viscous && !r.viscous->separation.empty()) {
    PointSet sep{"τ_w = 0 (separation, reattachment)", {}, Colour::red, 0, false};
    for (double th : r.viscous->separation) sep.points.push_back({th * 180.0 / M_PI, 0.0});
    f.points.push_back(std::move(sep));
  }
  return f;
}

CurveFigure surface_cp_figure(const FlowResult& r) {
  const Surface& s = r.surface;
  if (s.cp.empty() || r.c.scene.speed <= 0.0)
    throw std::runtime_error("plot: the result has no surface Cp (undefined when U = 0)");
  if (s.theta.size() != s.cp.size()) throw std::runtime_error("plot: surface theta and Cp differ in length");
  CurveFigure f;
  f.page.title = case_title(r.c.title) + ": surface pressure, " + flow_label(r);
  theta_axis(f.page);
  f.page.ylabel = "Cp = (p − p_∞) / (½ρU^2)";
  // The exact surface Cp of this scene's circulation (spin or given): 1 − (u_θ(a, θ)/U)² (for a
  // navier-stokes result, the ideal beside the real).
  const ExactFlow ex = exact_flow(r.c.scene);
  LineCurve exact{r.viscous ? "potential flow, 1 − (u_θ/U)^2" : "exact, 1 − (u_θ/U)^2",
                  {},
                  Colour::blue,
                  LineStyle::solid,
                  2.0};
  const int n_fine = 721;
  for (int k = 0; k < n_fine; ++k) {
    const double th = 2 * M_PI * k / (n_fine - 1);
    exact.points.push_back({th * 180.0 / M_PI, ex.cp(ex.a, th)});
  }
  // At most ~90 markers: on a fine grid every node would merge into a band hiding the line.
  const size_t n = s.cp.size(), stride = std::max<size_t>(1, (n + 89) / 90);
  PointSet numeric;
  const char* what = r.viscous ? "navier-stokes" : "numeric";
  numeric.label = stride == 1 ? fmt::format("{}, n_θ = {}", what, n)
                              : fmt::format("{}, n_θ = {} (one node in {})", what, n, stride);
  for (size_t j = 0; j < n; j += stride) numeric.points.push_back({s.theta[j] * 180.0 / M_PI, s.cp[j]});
  numeric.points.push_back({360.0, s.cp[0]});  // θ = 0 again at 360°, like the line
  f.lines.push_back(std::move(exact));
  f.points.push_back(std::move(numeric));
  return f;
}

CurveFigure lift_figure(const LiftSweep& s, const ViscousReference* reference) {
  CurveFigure f;
  const bool by_gamma = s.by_circulation;
  const double a = s.base.radius, U = s.base.speed;
  std::string grid;
  if (s.n_theta > 0) grid = fmt::format(", n_θ × n_r = {} × {}", s.n_theta, s.n_r);
  f.page.title = fmt::format("{}: lift against {} (potential flow{})", case_title(s.title),
                             by_gamma ? "circulation" : "spin ratio", grid);
  f.page.xlabel = by_gamma ? "circulation Γ (m^2/s)" : "spin ratio α = aω/U";
  f.page.ylabel = "lift coefficient C_L = F_y / (½ρU^2·2a)";
  double xlo = 0.0, xhi = 0.0;
  bool any = false;
  for (double x : s.x)
    if (std::isfinite(x)) {
      xlo = any ? std::min(xlo, x) : x;
      xhi = any ? std::max(xhi, x) : x;
      any = true;
    }
  if (!any) throw std::runtime_error("plot: the sweep has no points");
  if (!by_gamma) xlo = std::min(xlo, 0.0);

  // The scene at one x: a spin ratio (spin model) or a given circulation with the base spin.
  auto scene_at = [&](double x) {
    Scene sc = s.base;
    if (by_gamma) {
      sc.circulation_given = true;
      sc.circulation_value = x;
    } else {
      sc.circulation_given = false;
      sc.spin = x * U / a;
    }
    return sc;
  };
  // Where the two stagnation points merge on the top (Prandtl's bound on potential-flow lift).
  Scene merge = s.base;
  merge.circulation_given = false;
  merge.spin = 2.0 * U / a;
  const double x_merge = by_gamma ? merge.Gamma() : merge.spin_ratio();
  const double bound = std::fabs(exact_flow(merge).cl());

  LineCurve kj{by_gamma ? "Kutta–Joukowski, C_L = −Γ/(Ua)" : "Kutta–Joukowski, C_L = −2πα",
               {},
               Colour::blue,
               LineStyle::solid,
               2.0};
  for (double x : {xlo, xhi}) kj.points.push_back({x, exact_flow(scene_at(x)).cl()});
  f.lines.push_back(kj);
  if (!by_gamma) {
    LineCurve seed{"seed estimate, C_L = −4α", {}, Colour::green, LineStyle::dashed, 2.0};
    for (double x : {xlo, xhi}) seed.points.push_back({x, seed_cl(scene_at(x))});
    f.lines.push_back(seed);
  } else if (s.base.spin != 0.0) {
    const double c = seed_cl(s.base);
    LineCurve seed{
        fmt::format("seed estimate −4aω/U = {} (spin ω = {} rad/s, fixed)", num(c), num(s.base.spin)),
        {{xlo, c}, {xhi, c}},
        Colour::green,
        LineStyle::dashed,
        2.0};
    f.lines.push_back(seed);
  }
  // The bound on the side of the data, and where it is reached.
  double ylo = 0.0, yhi = 0.0;
  for (const auto& p : f.lines)
    for (const auto& q : p.points) ylo = std::min(ylo, q.y), yhi = std::max(yhi, q.y);
  for (double c : s.cl)
    if (std::isfinite(c)) ylo = std::min(ylo, c), yhi = std::max(yhi, c);
  LineCurve prandtl{by_gamma ? fmt::format("Prandtl's bound |C_L| = 4π (Γ = ±{} m^2/s)", num(x_merge))
                             : std::string("Prandtl's bound |C_L| = 4π (α = ±2)"),
                    {},
                    Colour::orange,
                    LineStyle::dotted,
                    1.8};
  bool labelled = false;
  for (double sign : {-1.0, 1.0}) {
    const bool side = sign < 0 ? ylo < 0.0 : yhi > 0.0;
    if (!side) continue;
    LineCurve h = prandtl;
    if (labelled) h.label.clear();
    labelled = true;
    h.points = {{xlo, sign * bound}, {xhi, sign * bound}};
    f.lines.push_back(h);
    // KJ meets the bound at x = −sign·x_merge (C_L falls as Γ grows).
    const double xm = -sign * x_merge;
    if (xm >= xlo && xm <= xhi) {
      LineCurve vline = prandtl;
      vline.label.clear();
      vline.points = {{xm, std::min(ylo, -bound)}, {xm, std::max(yhi, bound)}};
      vline.points = {{xm, sign < 0 ? std::min(ylo, -bound) : 0.0},
                      {xm, sign < 0 ? 0.0 : std::max(yhi, bound)}};
      f.lines.push_back(vline);
    }
  }
  if (reference && !by_gamma) {
    int k = 0;
    const Colour colours[] = {Colour::teal, Colour::purple, Colour::brown, Colour::olive, Colour::magenta};
    for (const auto& d : reference->datasets) {
      PointSet ps;
      ps.label = literal_text(d.label);
      ps.colour = colours[k % 5];
      ps.marker = 1 + k % 7;
      for (const auto& p : d.points)
        if (p.alpha >= xlo && p.alpha <= xhi) ps.points.push_back({p.alpha, p.cl});
      ++k;
      if (!ps.points.empty()) f.points.push_back(std::move(ps));
    }
  }
  PointSet numeric{"numeric (potential flow)", {}, Colour::red, 0, false};
  for (size_t k = 0; k < s.x.size() && k < s.cl.size(); ++k) numeric.points.push_back({s.x[k], s.cl[k]});
  f.points.push_back(std::move(numeric));
  return f;
}

LiftSweep read_lift_sweep(const std::string& path) {
  const ResultFile f(path, {"magnus-sweep"});
  LiftSweep s;
  s.by_circulation = f.has_attr("/", "variable") && f.attr_string("/", "variable") == "circulation";
  const std::string xcol = s.by_circulation ? "/sweep/circulation" : "/sweep/alpha";
  s.x = f.dataset(xcol);
  s.cl = f.dataset("/sweep/cl");
  if (s.x.size() != s.cl.size())
    throw std::runtime_error(fmt::format("'{}': /sweep columns differ in length", path));
  auto param = [&](const char* name, double dflt) {
    return f.has_attr("/parameters", name) ? f.attr_double("/parameters", name) : dflt;
  };
  s.base.radius = param("radius", 0.0);
  s.base.speed = param("speed", 0.0);
  if (!(s.base.radius > 0.0) || !(s.base.speed > 0.0))
    throw std::runtime_error(fmt::format("'{}': /parameters radius and speed must be positive", path));
  s.base.spin = param("spin", 0.0);
  s.base.circulation_given = s.by_circulation;
  s.title = f.has_attr("/", "title") ? f.attr_string("/", "title") : std::string();
  s.n_theta = int(param("n_theta", 0.0));
  s.n_r = int(param("n_r", 0.0));
  return s;
}

namespace {

std::string stem_of(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string output_base(const std::string& path, const std::string& dir_in) {
  namespace fs = std::filesystem;
  std::string dir = dir_in;
  if (dir.empty()) {
    dir = fs::path(path).parent_path().string();
    if (dir.empty()) dir = ".";
  } else {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
      if (fs::exists(dir, ec)) throw std::runtime_error(fmt::format("-o '{}': not a directory", dir));
      fs::create_directories(dir, ec);
      if (ec)
        throw std::runtime_error(fmt::format("-o '{}': cannot create the directory: {}", dir, ec.message()));
    }
  }
  return (fs::path(dir) / stem_of(path)).string();
}

}  // namespace

PlotOutcome plot_result_file(const std::string& path, const std::string& dir, PlotSize size) {
  PlotOutcome out;
  // A sweep file draws C_L(α) (or C_L(Γ)); anything else goes to the result reader and its messages.
  bool sweep = false;
  try {
    sweep = ResultFile(path, {"magnus-sweep"}).format() == "magnus-sweep";
  } catch (const std::exception&) {
    sweep = false;  // not a sweep: the result reader below says what it is
  }
  if (sweep) {
    const LiftSweep s = read_lift_sweep(path);
    std::optional<ViscousReference> ref;
    if (!s.by_circulation) try {
        ref = load_viscous_reference(viscous_reference_path());
      } catch (const std::exception& e) {
        out.skipped.push_back(std::string("viscous reference data not shown: ") + e.what());
      }
    const CurveFigure f = lift_figure(s, ref ? &*ref : nullptr);
    const std::string png = output_base(path, dir) + "_cl.png";
    plot_curves(f.page, f.lines, f.points, png, size);
    out.written.push_back(png);
    return out;
  }
  const FlowResult r = read_result(path);
  const std::string base = output_base(path, dir);
  const double U = r.c.scene.speed;
  if (r.fields.psi.empty()) {
    out.skipped.push_back(
        fmt::format("streamlines skipped: '{}' has no /fields/psi (see output.fields)", path));
  } else {
    plot_streamlines(streamline_picture(r), base + "_streamlines.png", size);
    out.written.push_back(base + "_streamlines.png");
  }
  if (r.fields.cp.empty()) {
    out.skipped.push_back(
        U > 0.0 ? fmt::format("Cp field skipped: '{}' has no /fields/cp (see output.fields)", path)
                : std::string("Cp field skipped: Cp is undefined when U = 0"));
  } else {
    plot_contour_field(cp_picture(r), base + "_cp.png", size);
    out.written.push_back(base + "_cp.png");
  }
  if (r.surface.cp.empty() || !(U > 0.0)) {
    out.skipped.push_back(U > 0.0 ? fmt::format("surface Cp skipped: '{}' has no /surface/cp", path)
                                  : std::string("surface Cp skipped: Cp is undefined when U = 0"));
  } else {
    const CurveFigure f = surface_cp_figure(r);
    plot_curves(f.page, f.lines, f.points, base + "_surface_cp.png", size);
    out.written.push_back(base + "_surface_cp.png");
  }
  if (r.viscous) {
    if (r.fields.vorticity.empty()) {
      out.skipped.push_back(
          fmt::format("vorticity skipped: '{}' has no /fields/vorticity (see output.fields)", path));
    } else {
      plot_contour_field(vorticity_picture(r), base + "_vorticity.png", size);
      out.written.push_back(base + "_vorticity.png");
    }
    if (r.viscous->history.empty()) {
      out.skipped.push_back(fmt::format("forces against time skipped: '{}' has no /history", path));
    } else {
      const CurveFigure f = force_history_figure(r);
      plot_curves(f.page, f.lines, f.points, base + "_forces.png", size);
      out.written.push_back(base + "_forces.png");
    }
    if (r.surface.shear_stress.empty()) {
      out.skipped.push_back(
          fmt::format("wall shear stress skipped: '{}' has no /surface/shear_stress", path));
    } else {
      const CurveFigure f = shear_stress_figure(r);
      plot_curves(f.page, f.lines, f.points, base + "_shear.png", size);
      out.written.push_back(base + "_shear.png");
    }
  }
  if (out.written.empty()) {
    std::string why;
    for (const auto& s : out.skipped) why += (why.empty() ? "" : "; ") + s;
    throw std::runtime_error(fmt::format("nothing to plot in '{}': {}", path, why));
  }
  return out;
}

void command_plot(const std::string& path, const std::string& dir, const std::string& size, bool quiet) {
  const PlotSize sz = size.empty() ? PlotSize{} : parse_plot_size(size);
  const PlotOutcome o = plot_result_file(path, dir, sz);
  for (const auto& s : o.skipped) std::fprintf(stderr, "magnus: note: %s\n", s.c_str());
  if (!quiet)
    for (const auto& w : o.written) std::printf("%s\n", w.c_str());
}

}  // namespace magnus
