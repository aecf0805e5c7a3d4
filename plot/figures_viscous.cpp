// The figures of a navier-stokes result: the vorticity field, C_L and C_D against time, the wall shear.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "plot/figure_labels.hpp"
#include "plot/figures.hpp"

namespace magnus {

using namespace figure_labels;

VorticityRange vorticity_range(const PolarGrid& g, const std::vector<const std::vector<double>*>& fields,
                               const PlotWindow& w) {
  std::vector<double> mags;
  for (const std::vector<double>* zeta : fields)
    for (int i = 0; i < g.n_r; ++i)
      for (int j = 0; j < g.n_theta; ++j) {
        const double x = g.r[i] / g.a * std::cos(g.theta[j]), y = g.r[i] / g.a * std::sin(g.theta[j]);
        if (w.contains(x, y)) mags.push_back(std::fabs((*zeta)[size_t(i) * g.n_theta + j]));
      }
  std::sort(mags.begin(), mags.end());
  VorticityRange v;
  v.peak = mags.empty() ? 0.0 : mags.back();
  v.limit = mags.empty() ? 0.0 : mags[std::min(mags.size() - 1, size_t(0.98 * double(mags.size())))];
  if (!(v.limit > 0.0)) v.limit = v.peak;
  return v;
}

ContourFieldPicture vorticity_field_picture(const FlowResult& r, const std::vector<double>& zeta,
                                            const std::optional<PlotWindow>& window,
                                            const std::optional<VorticityRange>& range) {
  const PolarGrid& g = r.grid;
  if (zeta.empty()) throw std::runtime_error("plot: the result has no vorticity field");
  if (zeta.size() != size_t(g.nodes())) throw std::runtime_error("plot: the vorticity field does not match the grid");
  ContourFieldPicture p;
  p.view = view_of(r, "vorticity", window);
  p.field = polar(g, zeta);
  p.bar_label = "ζ (1/s)";
  p.zero_contour = false;
  p.diverging = true;
  // The wall's thin layer holds the largest |ζ|; colours over its peak would leave the wake white.
  const VorticityRange v = range ? *range : vorticity_range(g, {&zeta}, p.view.window);
  p.limit = v.limit;
  p.footnote = p.limit < v.peak ? fmt::format(
                                      "red: counter-clockwise (ζ > 0), blue: clockwise;  colours end at "
                                      "±{} 1/s (|ζ| reaches {} 1/s at the wall)",
                                      num(p.limit), num(v.peak))
                                : std::string("red: counter-clockwise (ζ > 0), blue: clockwise");
  return p;
}

ContourFieldPicture vorticity_picture(const FlowResult& r, const std::optional<PlotWindow>& window) {
  return vorticity_field_picture(r, r.fields.vorticity, window, std::nullopt);
}

CurveFigure force_history_figure(const FlowResult& r) {
  if (!r.viscous || r.viscous->history.empty())
    throw std::runtime_error("plot: the result has no force history");
  const ViscousPart& v = *r.viscous;
  const double unit = v.time_unit > 0.0 ? v.time_unit : 1.0;
  CurveFigure f;
  f.page.title = case_title(r.c.title) + ": forces against time, " + flow_label(r);
  f.page.xlabel = v.time_unit <= 0.0 ? "time t (s)" : r.c.scene.speed > 0.0 ? "time t U/D" : "time t a|ω|/D";
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
    PointSet sep{"τ_w = 0 (separation, reattachment)", {}, Colour::red, 0, false, {}};
    for (double th : r.viscous->separation) sep.points.push_back({th * 180.0 / M_PI, 0.0});
    f.points.push_back(std::move(sep));
  }
  return f;
}

}  // namespace magnus
