#include "plot/curves.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "plot/axis_scale.hpp"
#include "plot/page.hpp"

namespace magnus {
namespace {

const char* const kMarkers[] = {"●", "■", "▲", "◆", "▼", "○", "□", "△", "◇", "▽"};

PLINT style_of(LineStyle s) { return s == LineStyle::dashed ? 2 : s == LineStyle::dotted ? 3 : 1; }

/// The axes of a curve plot: log10 or linear, the window as drawn and the linear axes' scales.
struct CurveAxes {
  bool lx = false, ly = false;            ///< log10 axes
  double sx = 1.0, sy = 1.0;              ///< a linear axis shows v·sx (v·sy): its power of ten is in its label
  int ex = 0, ey = 0;                     ///< sx = 10^−ex, sy = 10^−ey
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  ///< the window in the axes' units (log10 v, or v·sx)
  double tx(double v) const { return lx ? std::log10(v) : v * sx; }
  double ty(double v) const { return ly ? std::log10(v) : v * sy; }
};

/// The window that fits every usable point and its ± bar (x fixed when the page says so), padded, and the powers of ten
/// the linear axes' labels show. Throws std::runtime_error when no point is usable.
CurveAxes curve_axes(const CurvePage& pg, const std::vector<LineCurve>& lines,
                     const std::vector<PointSet>& points, const std::string& png) {
  using namespace page;
  CurveAxes a;
  a.lx = pg.log_x;
  a.ly = pg.log_y;
  const bool lx = a.lx, ly = a.ly;
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  auto take = [&](const CurvePoint& p) {
    if (!usable(p, lx, ly)) return;
    if (pg.fixed_x && (p.x < pg.x_min || p.x > pg.x_max)) return;
    xlo = std::min(xlo, a.tx(p.x));
    xhi = std::max(xhi, a.tx(p.x));
    ylo = std::min(ylo, a.ty(p.y));
    yhi = std::max(yhi, a.ty(p.y));
  };
  for (const auto& l : lines)
    for (const auto& p : l.points) take(p);
  for (const auto& s : points)
    for (size_t i = 0; i < s.points.size(); ++i) {
      take(s.points[i]);
      const double e = i < s.y_error.size() ? std::fabs(s.y_error[i]) : 0.0;
      if (!ly && std::isfinite(e) && usable(s.points[i], lx, ly))  // the bars stay inside the window
        take({s.points[i].x, s.points[i].y - e}), take({s.points[i].x, s.points[i].y + e});
    }
  if (!(xhi >= xlo)) throw std::runtime_error("plot: nothing to draw in " + png + " (no usable data)");
  if (pg.fixed_x) {
    a.x0 = a.tx(pg.x_min);
    a.x1 = a.tx(pg.x_max);
  } else {
    auto p = padded(xlo, xhi, 0.03);
    if (lx && xhi - xlo < 1.0) p = {0.5 * (xlo + xhi) - 0.55, 0.5 * (xlo + xhi) + 0.55};
    a.x0 = p.first;
    a.x1 = p.second;
  }
  {
    auto p = padded(ylo, yhi, 0.05);
    if (ly && yhi - ylo < 1.0) p = {0.5 * (ylo + yhi) - 0.55, 0.5 * (ylo + yhi) + 0.55};
    a.y0 = p.first;
    a.y1 = p.second;
  }
  a.ex = lx ? 0 : axis_scale::exponent(a.x0, a.x1);
  a.ey = ly ? 0 : axis_scale::exponent(a.y0, a.y1);
  a.sx = std::pow(10.0, -a.ex);
  a.sy = std::pow(10.0, -a.ey);
  a.x0 *= a.sx, a.x1 *= a.sx, a.y0 *= a.sy, a.y1 *= a.sy;
  return a;
}

/// The points on the axes' scales (a log axis keeps its values: markers take log10 themselves).
std::vector<CurvePoint> scaled(const CurveAxes& a, const std::vector<CurvePoint>& pts) {
  std::vector<CurvePoint> out = pts;
  for (auto& p : out) {
    if (!a.lx) p.x *= a.sx;
    if (!a.ly) p.y *= a.sy;
  }
  return out;
}

/// One legend entry per labelled line and point set, in drawing order.
std::vector<page::LegendEntry> curve_legend(const std::vector<LineCurve>& lines,
                                            const std::vector<PointSet>& points) {
  using namespace page;
  std::vector<LegendEntry> legend;
  for (const auto& l : lines)
    if (!l.label.empty())
      legend.push_back(line_entry(plplot_text(l.label), pen(l.colour), style_of(l.style), l.width));
  for (const auto& s : points) {
    if (s.label.empty()) continue;
    LegendEntry e =
        symbol_entry(plplot_text(s.label), pen(s.colour), kMarkers[s.marker % std::size(kMarkers)], 0.6);
    if (s.joined) {
      e.line = true;
      e.line_width = 1.6;
    }
    legend.push_back(e);
  }
  return legend;
}

/// The usable points of pts on the axes (x, y in the window's units).
void on_axes(const CurveAxes& a, const std::vector<CurvePoint>& pts, std::vector<PLFLT>& x,
             std::vector<PLFLT>& y) {
  for (const auto& p : pts)
    if (page::usable(p, a.lx, a.ly)) {
      x.push_back(a.tx(p.x));
      y.push_back(a.ty(p.y));
    }
}

/// The ± y bars of a point set (linear y axis; a NaN bar or an unusable point draws none).
void error_bars(plstream& pls, const CurveAxes& a, const PointSet& s) {
  if (a.ly || s.y_error.empty()) return;
  pls.col0(page::pen(s.colour));
  for (size_t i = 0; i < s.points.size() && i < s.y_error.size(); ++i) {
    const CurvePoint& p = s.points[i];
    const double e = s.y_error[i];
    if (!std::isfinite(e) || !page::usable(p, a.lx, a.ly)) continue;
    PLFLT x = a.tx(p.x), lo = a.ty(p.y - std::fabs(e)), hi = a.ty(p.y + std::fabs(e));
    pls.erry(1, &x, &lo, &hi);
  }
}

/// The lines (in order), then the point sets over them (joined ones with their line).
void draw_curves(plstream& pls, const CurveAxes& a, const std::vector<LineCurve>& lines,
                 const std::vector<PointSet>& points) {
  using namespace page;
  for (const auto& l : lines) {
    std::vector<PLFLT> x, y;
    on_axes(a, l.points, x, y);
    if (x.size() < 2) continue;
    pls.col0(pen(l.colour));
    pls.width(l.width);
    pls.lsty(style_of(l.style));
    pls.line(PLINT(x.size()), x.data(), y.data());
    pls.lsty(1);
    pls.width(1.0);
  }
  for (const auto& s : points) {
    if (s.joined) {
      std::vector<PLFLT> x, y;
      on_axes(a, s.points, x, y);
      pls.col0(pen(s.colour));
      pls.width(1.6);
      if (x.size() > 1) pls.line(PLINT(x.size()), x.data(), y.data());
      pls.width(1.0);
    }
    set_text(pls, 0.55);
    markers(pls, scaled(a, s.points), kMarkers[s.marker % std::size(kMarkers)], pen(s.colour), a.lx, a.ly);
    error_bars(pls, a, s);
  }
}

}  // namespace

PlotFrame plot_curves(const CurvePage& pg, const std::vector<LineCurve>& lines,
                      const std::vector<PointSet>& points, const std::string& png, PlotSize size) {
  using namespace page;
  const CurveAxes a = curve_axes(pg, lines, points, png);
  const bool lx = a.lx, ly = a.ly;
  const std::string xlabel = axis_scale::label(pg.xlabel, a.ex), ylabel = axis_scale::label(pg.ylabel, a.ey);
  const std::vector<LegendEntry> legend = curve_legend(lines, points);

  PlotFrame frame;
  render_png(png, size, [&](plstream& pls) {
    // Layout in text lines: title above, tick labels and the x label below, y tick labels and label left.
    const double lyf = line_fraction_y(pls), lxf = line_fraction_x(pls);
    set_text(pls, 0.8);
    const auto [lw, lh] = legend_size(pls, legend, 1);
    set_text(pls);
    const double left = 7.0 * lxf, top = 1.0 - 4.0 * lyf;
    double right = 1.0 - 2.5 * lxf, bottom = 5.0 * lyf;
    const bool beside = !legend.empty() && size.width >= 1.15 * size.height && lw < 0.3;
    int columns = 1;
    double legend_h = 0.0;
    if (beside) {
      right = 1.0 - lw - 3.0 * lxf;
    } else if (!legend.empty()) {
      columns = legend.size() > 2 && 2 * lw < 1.0 - 2 * lxf ? 2 : 1;
      set_text(pls, 0.8);
      legend_h = legend_size(pls, legend, columns).second;
      set_text(pls);
      bottom += legend_h + 0.5 * lyf;
    }
    pls.vpor(left, right, bottom, top);
    pls.wind(a.x0, a.x1, a.y0, a.y1);
    pls.col0(kLightGrey);
    pls.box(lx ? "gl" : "g", pg.x_tick * a.sx, pg.x_subticks, ly ? "gl" : "g", 0.0, 0);
    if (pg.zero_line && !ly && a.y0 < 0.0 && a.y1 > 0.0) {
      pls.col0(kDarkGrey);
      pls.join(a.x0, 0.0, a.x1, 0.0);
    }
    draw_curves(pls, a, lines, points);
    set_text(pls);
    frame_axes(pls, lx ? "bcnstl" : "bcnst", ly ? "bcnstvl" : "bcnstv", plplot_text(xlabel),
               plplot_text(ylabel), plplot_text(pg.title), pg.x_tick * a.sx, pg.x_subticks);
    frame = frame_of(pls, size);
    // The window in the data's units (px, py take data values), with the scales the labels show.
    frame.x0 /= a.sx, frame.x1 /= a.sx, frame.y0 /= a.sy, frame.y1 /= a.sy;
    frame.x_exponent = a.ex;
    frame.y_exponent = a.ey;
    frame.xlabel = xlabel;
    frame.ylabel = ylabel;
    if (!legend.empty()) {
      set_text(pls, 0.8);
      std::vector<double> r;
      if (beside)
        r = draw_legend(pls, legend, right + 1.5 * lxf, top, 1);
      else
        r = draw_legend(pls, legend, left, legend_h + 0.6 * lyf, columns);
      if (r.size() == 4) frame.legend = to_pixels(size, r[0], r[1], r[2], r[3]);
    }
  });
  return frame;
}

}  // namespace magnus
