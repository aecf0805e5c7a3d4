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

}  // namespace

PlotFrame plot_curves(const CurvePage& pg, const std::vector<LineCurve>& lines,
                      const std::vector<PointSet>& points, const std::string& png, PlotSize size) {
  using namespace page;
  const bool lx = pg.log_x, ly = pg.log_y;
  double sx = 1.0, sy = 1.0;  // a linear axis shows v·sx (v·sy): its power of ten is in its label
  auto tx = [lx, &sx](double v) { return lx ? std::log10(v) : v * sx; };
  auto ty = [ly, &sy](double v) { return ly ? std::log10(v) : v * sy; };
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  auto take = [&](const CurvePoint& p) {
    if (!usable(p, lx, ly)) return;
    if (pg.fixed_x && (p.x < pg.x_min || p.x > pg.x_max)) return;
    xlo = std::min(xlo, tx(p.x));
    xhi = std::max(xhi, tx(p.x));
    ylo = std::min(ylo, ty(p.y));
    yhi = std::max(yhi, ty(p.y));
  };
  for (const auto& l : lines)
    for (const auto& p : l.points) take(p);
  for (const auto& s : points)
    for (const auto& p : s.points) take(p);
  if (!(xhi >= xlo)) throw std::runtime_error("plot: nothing to draw in " + png + " (no usable data)");
  double x0, x1, y0, y1;
  if (pg.fixed_x) {
    x0 = tx(pg.x_min);
    x1 = tx(pg.x_max);
  } else {
    auto p = padded(xlo, xhi, 0.03);
    if (lx && xhi - xlo < 1.0) p = {0.5 * (xlo + xhi) - 0.55, 0.5 * (xlo + xhi) + 0.55};
    x0 = p.first;
    x1 = p.second;
  }
  {
    auto p = padded(ylo, yhi, 0.05);
    if (ly && yhi - ylo < 1.0) p = {0.5 * (ylo + yhi) - 0.55, 0.5 * (ylo + yhi) + 0.55};
    y0 = p.first;
    y1 = p.second;
  }
  const int ex = lx ? 0 : axis_scale::exponent(x0, x1), ey = ly ? 0 : axis_scale::exponent(y0, y1);
  sx = std::pow(10.0, -ex);
  sy = std::pow(10.0, -ey);
  x0 *= sx, x1 *= sx, y0 *= sy, y1 *= sy;
  const std::string xlabel = axis_scale::label(pg.xlabel, ex), ylabel = axis_scale::label(pg.ylabel, ey);
  auto scaled = [&](const std::vector<CurvePoint>& pts) {
    std::vector<CurvePoint> out = pts;
    for (auto& p : out) {
      if (!lx) p.x *= sx;
      if (!ly) p.y *= sy;
    }
    return out;
  };

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
    pls.wind(x0, x1, y0, y1);
    pls.col0(kLightGrey);
    pls.box(lx ? "gl" : "g", pg.x_tick * sx, pg.x_subticks, ly ? "gl" : "g", 0.0, 0);
    if (pg.zero_line && !ly && y0 < 0.0 && y1 > 0.0) {
      pls.col0(kDarkGrey);
      pls.join(x0, 0.0, x1, 0.0);
    }
    for (const auto& l : lines) {
      std::vector<PLFLT> x, y;
      for (const auto& p : l.points)
        if (usable(p, lx, ly)) {
          x.push_back(tx(p.x));
          y.push_back(ty(p.y));
        }
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
        for (const auto& p : s.points)
          if (usable(p, lx, ly)) {
            x.push_back(tx(p.x));
            y.push_back(ty(p.y));
          }
        pls.col0(pen(s.colour));
        pls.width(1.6);
        if (x.size() > 1) pls.line(PLINT(x.size()), x.data(), y.data());
        pls.width(1.0);
      }
      set_text(pls, 0.55);
      markers(pls, scaled(s.points), kMarkers[s.marker % std::size(kMarkers)], pen(s.colour), lx, ly);
    }
    set_text(pls);
    frame_axes(pls, lx ? "bcnstl" : "bcnst", ly ? "bcnstvl" : "bcnstv", plplot_text(xlabel),
               plplot_text(ylabel), plplot_text(pg.title), pg.x_tick * sx, pg.x_subticks);
    frame = frame_of(pls, size);
    // The window in the data's units (px, py take data values), with the scales the labels show.
    frame.x0 /= sx, frame.x1 /= sx, frame.y0 /= sy, frame.y1 /= sy;
    frame.x_exponent = ex;
    frame.y_exponent = ey;
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
