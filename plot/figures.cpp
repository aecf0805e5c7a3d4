#include "plot/figures.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/exact.hpp"
#include "plot/figure_labels.hpp"
#include "plot/figures_rotor.hpp"

namespace magnus {

namespace {

using namespace figure_labels;

CurvePoint in_units(const StagnationPoint& s, double a) {
  return {s.r / a * std::cos(s.theta), s.r / a * std::sin(s.theta)};
}

bool inside(const CurvePoint& p, const PlotWindow& w) { return w.contains(p.x, p.y); }

}  // namespace

StreamlinePicture streamline_picture(const FlowResult& r, const std::optional<PlotWindow>& window) {
  const PolarGrid& g = r.grid;
  if (r.fields.psi.size() != size_t(g.nodes()) || g.n_r < 2 || g.n_theta < 4)
    throw std::runtime_error("plot: the result has no psi field");
  StreamlinePicture p;
  p.view = view_of(r, "streamlines", window);
  p.psi = polar(g, r.fields.psi);
  const PlotWindow& w = p.view.window;
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

ContourFieldPicture cp_picture(const FlowResult& r, const std::optional<PlotWindow>& window) {
  const PolarGrid& g = r.grid;
  if (r.fields.cp.empty()) throw std::runtime_error("plot: the result has no cp field");
  if (r.fields.cp.size() != size_t(g.nodes()))
    throw std::runtime_error("plot: the cp field does not match the grid");
  ContourFieldPicture p;
  p.view = view_of(r, "pressure coefficient", window);
  p.field = polar(g, r.fields.cp);
  p.bar_label = "Cp";
  for (const auto& s : r.stagnation) {
    const CurvePoint q = in_units(s, g.a);
    if (inside(q, p.view.window)) p.points.push_back(q);
  }
  p.footnote =
      r.viscous ? "dashed: Cp = 0" : "dashed: Cp = 0 (|u| = U);  red dots: stagnation points (Cp = 1)";
  return p;
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

namespace {

/// The scene at one x of a sweep: a spin ratio (spin model) or a given circulation with the base spin.
Scene scene_at(const LiftSweep& s, double x) {
  Scene sc = s.base;
  if (s.by_circulation) {
    sc.circulation_given = true;
    sc.circulation_value = x;
  } else {
    sc.circulation_given = false;
    sc.spin = x * s.base.speed / s.base.radius;
  }
  return sc;
}

/// Kutta–Joukowski over [xlo, xhi], and the seed estimate: −4α, or in a circulation sweep the constant
/// −4aω/U of the fixed spin (none when ω = 0).
void add_model_lines(CurveFigure& f, const LiftSweep& s, double xlo, double xhi) {
  const bool by_gamma = s.by_circulation;
  LineCurve kj{by_gamma ? "Kutta–Joukowski, C_L = −Γ/(Ua)" : "Kutta–Joukowski, C_L = −2πα",
               {},
               Colour::blue,
               LineStyle::solid,
               2.0};
  for (double x : {xlo, xhi}) kj.points.push_back({x, exact_flow(scene_at(s, x)).cl()});
  f.lines.push_back(kj);
  if (!by_gamma) {
    LineCurve seed{"seed estimate, C_L = −4α", {}, Colour::green, LineStyle::dashed, 2.0};
    for (double x : {xlo, xhi}) seed.points.push_back({x, seed_cl(scene_at(s, x))});
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
}

/// Prandtl's bound |C_L| = 4π (where the two stagnation points merge on the top, α = 2) on the side(s) of
/// the data and the lines drawn so far, with a vertical line where Kutta–Joukowski reaches it.
void add_prandtl_bound(CurveFigure& f, const LiftSweep& s, double xlo, double xhi) {
  const bool by_gamma = s.by_circulation;
  Scene merge = s.base;
  merge.circulation_given = false;
  merge.spin = 2.0 * s.base.speed / s.base.radius;
  const double x_merge = by_gamma ? merge.Gamma() : merge.spin_ratio();
  const double bound = std::fabs(exact_flow(merge).cl());
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
      vline.points = {{xm, sign < 0 ? std::min(ylo, -bound) : 0.0},
                      {xm, sign < 0 ? 0.0 : std::max(yhi, bound)}};
      f.lines.push_back(vline);
    }
  }
}

/// The viscous reference datasets measured within a factor 3 of the scene's Re (re = 0: all of them),
/// clipped to α in [xlo, xhi], each in its colour and marker.
void add_reference_points(CurveFigure& f, const ViscousReference& reference, double re, double xlo,
                          double xhi) {
  int k = 0;
  const Colour colours[] = {Colour::teal, Colour::purple, Colour::brown, Colour::olive, Colour::magenta};
  for (const auto& d : reference.datasets) {
    if (re > 0.0 && !(d.reynolds >= re / 3.0 && d.reynolds <= 3.0 * re)) {
      ++k;
      continue;
    }
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

}  // namespace

CurveFigure lift_figure(const LiftSweep& s, const ViscousReference* reference, const RotorData* rotor) {
  CurveFigure f;
  const bool by_gamma = s.by_circulation;
  const double U = s.base.speed;
  std::string grid;
  if (s.n_theta > 0) grid = fmt::format(", n_θ × n_r = {} × {}", s.n_theta, s.n_r);
  f.page.title = fmt::format("{}: lift against {} (potential flow{})", case_title(s.title),
                             by_gamma ? "circulation" : "spin ratio", grid);
  f.page.xlabel = by_gamma ? "circulation Γ (m^2/s)" : "spin ratio α = aω/U";
  f.page.ylabel = "lift coefficient C_L = L/(½ρU^2·2a), lift L ⊥ U";
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
  add_model_lines(f, s, xlo, xhi);
  add_prandtl_bound(f, s, xlo, xhi);
  // The scene's Re (0: no viscosity, no Re): reference data measured at another Re are left out.
  const double re = s.base.viscosity > 0.0 && U > 0.0 ? s.base.reynolds() : 0.0;
  if (reference && !by_gamma) add_reference_points(f, *reference, re, xlo, xhi);
  if (rotor && !by_gamma)
    add_rotor_overlays(f, *rotor, re, xlo, xhi);
  PointSet numeric{"numeric (potential flow)", {}, Colour::red, 0, false, {}};
  for (size_t k = 0; k < s.x.size() && k < s.cl.size(); ++k) numeric.points.push_back({s.x[k], s.cl[k]});
  f.points.push_back(std::move(numeric));
  return f;
}

}  // namespace magnus
