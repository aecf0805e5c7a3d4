// The frames of a wake film: a snapshot's vorticity over the film's colour range above the forces
// against time with the snapshot's time marked.
#include "plot/film.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace magnus {

namespace {

const std::vector<Snapshot>& snapshots_of(const FlowResult& r) {
  if (!r.viscous || r.viscous->snapshots.empty()) throw std::runtime_error("plot: the result has no snapshots");
  return r.viscous->snapshots;
}

/// C_L and C_D at time t (s), linear between the history's samples (the ends beyond them).
std::pair<double, double> forces_at(const std::vector<ForceSample>& h, double t) {
  const auto after = std::lower_bound(h.begin(), h.end(), t,
                                      [](const ForceSample& s, double time) { return s.t < time; });
  if (after == h.begin()) return {h.front().C_L, h.front().C_D};
  if (after == h.end()) return {h.back().C_L, h.back().C_D};
  const ForceSample &b = *after, &a = *(after - 1);
  const double s = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1.0;
  return {a.C_L + s * (b.C_L - a.C_L), a.C_D + s * (b.C_D - a.C_D)};
}

}  // namespace

VorticityRange film_vorticity_range(const FlowResult& r, const PlotWindow& w) {
  std::vector<const std::vector<double>*> fields;
  for (const Snapshot& s : snapshots_of(r)) {
    if (s.vorticity.size() != size_t(r.grid.nodes()))
      throw std::runtime_error("plot: a snapshot's vorticity does not match the grid");
    fields.push_back(&s.vorticity);
  }
  return vorticity_range(r.grid, fields, w);
}

std::string film_time_label(const FlowResult& r, double t) {
  const double unit = r.viscous ? r.viscous->time_unit : 0.0;
  return unit > 0.0 ? fmt::format("t = {:.2f} D/U", t / unit) : fmt::format("t = {:.4g} s", t);
}

ContourFieldPicture film_vorticity_picture(const FlowResult& r, size_t k, const PlotWindow& w,
                                           const VorticityRange& range) {
  const Snapshot& s = snapshots_of(r).at(k);
  ContourFieldPicture p = vorticity_field_picture(r, s.vorticity, w, range);
  p.view.title += ",  " + film_time_label(r, s.t);
  return p;
}

CurveFigure film_force_figure(const FlowResult& r, double t) {
  CurveFigure f = force_history_figure(r);
  // Under the vorticity, whose title names the case: a short title and x label, and the curves that move
  // (potential flow's C_L, far below, would squeeze them).
  f.page.title = "C_L and C_D against time; the black line: this frame";
  f.page.xlabel = f.page.xlabel.substr(0, f.page.xlabel.find(" (from"));
  f.lines.erase(std::remove_if(f.lines.begin(), f.lines.end(),
                               [](const LineCurve& l) { return l.label.rfind("potential flow", 0) == 0; }),
                f.lines.end());
  const double unit = r.viscous->time_unit > 0.0 ? r.viscous->time_unit : 1.0;
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (const LineCurve& l : f.lines)
    for (const CurvePoint& p : l.points) {
      lo = any ? std::min(lo, p.y) : p.y;
      hi = any ? std::max(hi, p.y) : p.y;
      any = true;
    }
  const auto [cl, cd] = forces_at(r.viscous->history, t);
  f.lines.push_back({"", {{t / unit, lo}, {t / unit, hi}}, Colour::black, LineStyle::solid, 1.5});
  f.points.push_back({"", {{t / unit, cl}}, Colour::red, 0, false, {}});
  f.points.push_back({"", {{t / unit, cd}}, Colour::blue, 0, false, {}});
  return f;
}

std::pair<PlotSize, PlotSize> film_panel_sizes(PlotSize size) {
  const int top = std::max(16, std::min(size.height - 16, 2 * int(0.275 * size.height + 0.5)));
  return {{size.width, top}, {size.width, size.height - top}};
}

PlotFrame draw_film_frame(const FlowResult& r, size_t k, const PlotWindow& w, const VorticityRange& range,
                          PlotSize size, const std::string& top_png, const std::string& bottom_png) {
  const auto [top, bottom] = film_panel_sizes(size);
  const PlotFrame frame = plot_contour_field(film_vorticity_picture(r, k, w, range), top_png, top);
  const CurveFigure f = film_force_figure(r, snapshots_of(r).at(k).t);
  plot_curves(f.page, f.lines, f.points, bottom_png, bottom);
  return frame;
}

}  // namespace magnus
