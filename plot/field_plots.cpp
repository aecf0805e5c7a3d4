#include "plot/field_plots.hpp"

#include <fmt/core.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "plot/axis_scale.hpp"
#include "plot/page.hpp"

namespace magnus {
namespace {

using namespace page;

/// A field on rings i0…i1 as (i1 − i0 + 1, n_θ + 1) arrays for plcont/plshades with pltr2, in axis
/// units: column n_θ repeats column 0 (θ = 2π) so that contours close over the seam.
struct PolarPatch {
  PLINT nx = 0, ny = 0;
  std::vector<PLFLT> xs, ys, zs;
  std::vector<PLFLT*> xrow, yrow, zrow;
  PLcGrid2 grid{};

  PolarPatch(const PolarField& f, double unit, int i0, int i1) {
    const int nr = int(f.r.size()), nt = int(f.theta.size());
    i0 = std::clamp(i0, 0, nr - 2);
    i1 = std::clamp(i1, i0 + 1, nr - 1);
    nx = i1 - i0 + 1;
    ny = nt + 1;
    xs.resize(size_t(nx) * ny);
    ys.resize(xs.size());
    zs.resize(xs.size());
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j <= nt; ++j) {
        const int jj = j % nt;
        const size_t q = size_t(i) * ny + j;
        xs[q] = f.r[i0 + i] / unit * std::cos(f.theta[jj]);
        ys[q] = f.r[i0 + i] / unit * std::sin(f.theta[jj]);
        zs[q] = f.values[size_t(i0 + i) * nt + jj];
      }
    for (int i = 0; i < nx; ++i) {
      xrow.push_back(&xs[size_t(i) * ny]);
      yrow.push_back(&ys[size_t(i) * ny]);
      zrow.push_back(&zs[size_t(i) * ny]);
    }
    grid.xg = xrow.data();
    grid.yg = yrow.data();
    grid.zg = nullptr;
    grid.nx = nx;
    grid.ny = ny;
  }
  PolarPatch(const PolarPatch&) = delete;
  PolarPatch& operator=(const PolarPatch&) = delete;

  const PLFLT* const* z() const { return zrow.data(); }
  void* pltr_data() { return &grid; }

  /// Range of the field over the nodes inside the window.
  std::pair<double, double> range_in(const PlotWindow& w) const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (size_t q = 0; q < zs.size(); ++q)
      if (w.contains(xs[q], ys[q]) && std::isfinite(zs[q])) {
        lo = std::min(lo, zs[q]);
        hi = std::max(hi, zs[q]);
      }
    return {lo, hi};
  }
};

/// Index of the last ring with r_i ≤ r (0 if none).
int ring_at_or_below(const std::vector<double>& r, double x) {
  int i = 0;
  while (i + 1 < int(r.size()) && r[i + 1] <= x) ++i;
  return i;
}

void contour(plstream& pls, PolarPatch& p, const std::vector<PLFLT>& levels, PLINT pen_, double width,
             PLINT style = 1) {
  if (levels.empty()) return;
  pls.col0(pen_);
  pls.width(width);
  pls.lsty(style);
  pls.cont(p.z(), p.nx, p.ny, 1, p.nx, 1, p.ny, levels.data(), PLINT(levels.size()), plcallback::tr2,
           p.pltr_data());
  pls.lsty(1);
  pls.width(1.0);
}

/// cmap1: a perceptually ordered dark-purple → teal → yellow ramp (viridis-like).
void sequential_cmap1(plstream& pls) {
  const PLFLT pos[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  const PLFLT r[] = {0.267, 0.230, 0.128, 0.369, 0.993};
  const PLFLT g[] = {0.005, 0.322, 0.567, 0.789, 0.906};
  const PLFLT b[] = {0.329, 0.546, 0.551, 0.383, 0.144};
  pls.scmap1n(256);
  pls.scmap1l(true, 5, pos, r, g, b, nullptr);
}

/// cmap1: blue → white (at the middle, 0 on symmetric limits) → red, for signed fields (vorticity).
void diverging_cmap1(plstream& pls) {
  const PLFLT pos[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  const PLFLT r[] = {0.085, 0.400, 0.970, 0.860, 0.600};
  const PLFLT g[] = {0.180, 0.570, 0.970, 0.380, 0.020};
  const PLFLT b[] = {0.560, 0.860, 0.970, 0.300, 0.080};
  pls.scmap1n(256);
  pls.scmap1l(true, 5, pos, r, g, b, nullptr);
}

/// The window's box, centred, with equal scales on both axes: top 4 lines for the title, bottom
/// `bottom_lines` for tick labels and the x label (and `extra_bottom`, a page fraction, for a legend
/// below), side margins at least `side` (page fraction) each. Sets the viewport and window.
void window_box(plstream& pls, PlotSize size, const PlotWindow& w, double bottom_lines, double extra_bottom,
                double side) {
  const double ly = line_fraction_y(pls);
  const double top = 1.0 - 4.0 * ly, bottom = bottom_lines * ly + extra_bottom;
  const double W = size.width, H = size.height, aspect = (w.x1 - w.x0) / (w.y1 - w.y0);
  const double room_w = std::max(1.0, W * (1.0 - 2.0 * side)), room_h = std::max(1.0, (top - bottom) * H);
  const double box_w = std::min(room_w, room_h * aspect), box_h = box_w / aspect;
  const double cx = 0.5, cy = 0.5 * (top + bottom);
  pls.vpor(cx - 0.5 * box_w / W, cx + 0.5 * box_w / W, cy - 0.5 * box_h / H, cy + 0.5 * box_h / H);
  pls.wind(w.x0, w.x1, w.y0, w.y1);
}

/// The distance from the origin to the window's farthest corner (axis units).
double reach(const PlotWindow& w) {
  return std::hypot(std::max(std::fabs(w.x0), std::fabs(w.x1)), std::max(std::fabs(w.y0), std::fabs(w.y1)));
}

void check_field(const PolarField& f, const char* what) {
  if (f.r.size() < 2 || f.theta.size() < 4 || f.values.size() != f.r.size() * f.theta.size())
    throw std::runtime_error(fmt::format("plot: the {} field does not match its grid", what));
}

/// The ψ levels of a streamline picture: multiples of a round step (ψ = 0 drawn apart, as the dividing
/// streamline); with a saddle at r_s, the separatrix ψ_s and the closed streamlines inside it, and the
/// patches inside and outside r_s that keep the two families apart.
struct StreamLevels {
  double step = 0.0;                                     ///< Δψ of the regular levels
  std::vector<PLFLT> regular, dividing, closed, open_inner;  ///< open_inner: regular levels between 0 and ψ_s
  std::unique_ptr<PolarPatch> inner, outer;              ///< rings 0…i_s and i_s…i_view (saddle only)
};

StreamLevels stream_levels(const StreamlinePicture& pic, const PolarField& f, const PolarPatch& all,
                           double unit, int i_view) {
  StreamLevels L;
  // Levels: multiples of a round step, so that ψ = 0 (the body, and the dividing streamline while the
  // stagnation points are on the surface) is one of them.
  const auto [lo, hi] = all.range_in(pic.view.window);
  L.step = nice_step((hi - lo) / 24.0);
  const double step = L.step;
  if (hi > lo)
    for (long k = long(std::ceil(lo / step)); k <= long(std::floor(hi / step)); ++k)
      if (k != 0) L.regular.push_back(k * step);

  // A saddle at r_s: the separatrix ψ = ψ_s through it encloses the closed streamlines, 0 < ψ/ψ_s < 1 at
  // r < r_s; the same values at r > r_s are open streamlines.
  L.dividing = {0.0};
  if (pic.has_saddle) {
    const double rs = std::hypot(pic.saddle.x, pic.saddle.y) * unit;
    const double ps = polar_value(pic.psi, rs, std::atan2(pic.saddle.y, pic.saddle.x));
    L.dividing.push_back(ps);
    for (double q : {0.2, 0.4, 0.6, 0.8}) L.closed.push_back(q * ps);
    const int i_s = ring_at_or_below(f.r, rs);
    L.inner = std::make_unique<PolarPatch>(f, unit, 0, i_s);
    L.outer = std::make_unique<PolarPatch>(f, unit, i_s, std::max(i_view, i_s + 1));
    auto between = [&](double x) { return x * (x - ps) < 0.0; };  // strictly between 0 and ψ_s
    for (double x : L.regular)
      if (between(x)) L.open_inner.push_back(x);
    L.regular.erase(std::remove_if(L.regular.begin(), L.regular.end(), between), L.regular.end());
  }
  return L;
}

/// The legend of a streamline picture: the contours' Δψ, the dividing streamline or the separatrix and
/// the closed streamlines, the stagnation points shown, and the notes.
std::vector<LegendEntry> stream_legend(const StreamlinePicture& pic, double step) {
  std::vector<LegendEntry> legend;
  legend.push_back(
      line_entry(plplot_text(fmt::format("ψ contours, Δψ = {} {}", num(step), pic.psi_unit)), kBlue, 1, 1.2));
  if (pic.has_saddle) {
    legend.push_back(line_entry(plplot_text("separatrix ψ = ψ_s"), kBlack, 1, 2.4));
    legend.push_back(line_entry("closed streamlines", kPurple, 1, 1.4));
  } else {
    legend.push_back(line_entry("dividing streamline ψ = 0", kBlack, 1, 2.4));
  }
  if (!pic.numeric_points.empty())
    legend.push_back(symbol_entry("stagnation point, numeric", kRed, "●", 0.75));
  if (!pic.exact_points.empty()) legend.push_back(symbol_entry("stagnation point, exact", kBlack, "○", 1.3));
  for (const auto& n : pic.notes) legend.push_back(text_entry(plplot_text(n)));
  return legend;
}

/// The colour bar of a contour field right of the box (as tall as 80% of it, its label on top) over the
/// shade edges, its numbers in a power of ten of their own; its place and scale recorded in frame.
void colour_bar(plstream& pls, PlotSize size, const std::string& bar_label_in, const std::vector<PLFLT>& edges,
                double lo, double hi, double lx, PlotFrame& frame) {
  PLFLT vx0 = 0, vx1 = 0, vy0 = 0, vy1 = 0;
  pls.gvpd(vx0, vx1, vy0, vy1);  // the box's viewport, set by window_box
  set_text(pls, 0.85);
  // Gap and width of two body lines each (fractions of the box's width: a wide window's box is wide).
  const double bx = 2.0 * lx / (vx1 - vx0), bw = 2.0 * lx / (vx1 - vx0), bh = 0.80;
  const char* axis_opts[] = {"bcvtm"};
  // The bar's numbers in a power of ten of their own (in its label) when they are small or large.
  const int eb = axis_scale::exponent(lo, hi);
  const std::string bar_label = axis_scale::label(bar_label_in, eb);
  const std::string label = plplot_text(bar_label);
  std::vector<PLFLT> shown = edges;
  for (auto& e : shown) e *= std::pow(10.0, -eb);
  const char* labels[] = {label.c_str()};
  PLINT label_opts[] = {PL_COLORBAR_LABEL_TOP};
  PLFLT ticks[] = {0.0};
  PLINT sub_ticks[] = {0};
  PLINT n_values[] = {PLINT(edges.size())};
  const PLFLT* values[] = {shown.data()};
  PLFLT cw = 0.0, ch = 0.0;
  pls.colorbar(&cw, &ch, PL_COLORBAR_SHADE, PL_POSITION_RIGHT | PL_POSITION_OUTSIDE | PL_POSITION_VIEWPORT,
               bx, 0.0, bw, bh, kWhite, kBlack, 1, 0, 0.0, 0, 0.0, 1, label_opts, labels, 1, axis_opts,
               ticks, sub_ticks, n_values, values);
  const double dx = vx1 - vx0, dy = vy1 - vy0, ymid = 0.5 * (vy0 + vy1);
  frame.colour_bar =
      to_pixels(size, vx1 + bx * dx, vx1 + (bx + bw) * dx, ymid - 0.5 * bh * dy, ymid + 0.5 * bh * dy);
  frame.bar_lo = lo;
  frame.bar_hi = hi;
  frame.bar_exponent = eb;
  frame.bar_label = bar_label;
}

/// The field checked against its grid and refined to reach the view's farthest corner.
PolarField refined(const PolarField& field, const FieldView& v, const char* what) {
  check_field(field, what);
  return refine_polar_field(field, reach(v.window) * v.unit);
}

}  // namespace

PlotFrame plot_streamlines(const StreamlinePicture& pic, const std::string& png, PlotSize size) {
  const FieldView& v = pic.view;
  const PlotWindow& w = v.window;
  const double unit = v.unit;
  const PolarField f = refined(pic.psi, v, "psi");
  const int i_view = int(f.r.size()) - 1;
  PolarPatch all(f, unit, 0, i_view);
  const StreamLevels L = stream_levels(pic, f, all, unit, i_view);
  const std::vector<LegendEntry> legend = stream_legend(pic, L.step);

  PlotFrame frame;
  render_png(png, size, [&](plstream& pls) {
    const double lx = line_fraction_x(pls), ly = line_fraction_y(pls);
    set_text(pls, 0.8);
    auto [lw, lh] = legend_size(pls, legend, 1);
    set_text(pls);
    // Beside the box when the page leaves room right of the centred square, else below it.
    const double aspect = (w.x1 - w.x0) / (w.y1 - w.y0);
    const double box_px = std::min((1.0 - 8.5 * ly) * size.height * aspect, size.width * (1.0 - 14.0 * lx));
    const double room = 0.5 * (1.0 - box_px / size.width) - 3.0 * lx;
    const bool beside = lw <= room;
    int columns = 1;
    if (!beside) {
      columns = 2 * lw + 4 * lx < 1.0 ? 2 : 1;
      set_text(pls, 0.8);
      std::tie(lw, lh) = legend_size(pls, legend, columns);
      set_text(pls);
    }
    window_box(pls, size, w, 4.5, beside ? 0.0 : lh + 0.5 * ly, 7.0 * lx);
    contour(pls, all, L.regular, kBlue, 1.2);
    if (pic.has_saddle) {
      contour(pls, *L.outer, L.open_inner, kBlue, 1.2);
      contour(pls, *L.inner, L.closed, kPurple, 1.4);
    }
    contour(pls, all, L.dividing, kBlack, 2.4);
    disc(pls, 0.0, 0.0, v.body_radius, kGrey, kBlack, 2.0);
    const double dot = std::min(w.x1 - w.x0, w.y1 - w.y0) / 120.0;
    for (const auto& s : pic.exact_points) disc(pls, s.x, s.y, 2.0 * dot, -1, kBlack, 1.5);
    for (const auto& s : pic.numeric_points) disc(pls, s.x, s.y, dot, kRed, kBlack, 1.0);
    frame_axes(pls, "bcnst", "bcnstv", plplot_text(v.xlabel), plplot_text(v.ylabel), plplot_text(v.title));
    frame = frame_of(pls, size);
    frame.levels.assign(L.regular.begin(), L.regular.end());
    frame.levels.insert(frame.levels.end(), L.open_inner.begin(), L.open_inner.end());
    frame.levels.insert(frame.levels.end(), L.closed.begin(), L.closed.end());
    frame.levels.insert(frame.levels.end(), L.dividing.begin(), L.dividing.end());
    PLFLT vx0 = 0, vx1 = 0, vy0 = 0, vy1 = 0;
    pls.gvpd(vx0, vx1, vy0, vy1);
    set_text(pls, 0.8);
    const auto r = beside ? draw_legend(pls, legend, vx1 + 2.0 * lx, vy1, 1)
                          : draw_legend(pls, legend, 0.5 - 0.5 * lw, lh + 0.5 * ly, columns);
    if (r.size() == 4) frame.legend = to_pixels(size, r[0], r[1], r[2], r[3]);
  });
  return frame;
}

PlotFrame plot_contour_field(const ContourFieldPicture& pic, const std::string& png, PlotSize size) {
  const FieldView& v = pic.view;
  const PlotWindow& w = v.window;
  const PolarField f = refined(pic.field, v, "contour");
  PolarPatch patch(f, v.unit, 0, int(f.r.size()) - 1);
  auto [lo, hi] = patch.range_in(w);
  const double data_lo = lo, data_hi = hi;
  if (pic.diverging) {
    const double m = pic.limit > 0.0 ? pic.limit : std::max(std::fabs(lo), std::fabs(hi));
    lo = -m;
    hi = m;
  }
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  // A diverging map: an odd number of shades, the middle one (white) straddling 0.
  const int n_shades = pic.diverging ? kDivergingShades : 40;
  std::vector<PLFLT> edges(n_shades + 1);
  for (int k = 0; k <= n_shades; ++k) edges[k] = lo + (hi - lo) * k / n_shades;
  const double eps = 1e-9 * (hi - lo);  // so that the extreme nodes are filled too
  std::vector<PLFLT> fill_edges = edges;
  fill_edges.front() = std::min(lo, data_lo) - eps;  // values beyond a diverging map's limits: end colours
  fill_edges.back() = std::max(hi, data_hi) + eps;

  PlotFrame frame;
  render_png(png, size, [&](plstream& pls) {
    const double lx = line_fraction_x(pls);
    if (pic.diverging)
      diverging_cmap1(pls);
    else
      sequential_cmap1(pls);
    // Right of the box: the bar (7% of the box) and its numbers (~6 characters).
    window_box(pls, size, w, pic.footnote.empty() ? 4.5 : 6.0, 0.0, 8.0 * lx);
    pls.psty(0);
    pls.shades(patch.z(), patch.nx, patch.ny, nullptr, w.x0, w.x1, w.y0, w.y1, fill_edges.data(),
               PLINT(fill_edges.size()), 1.0, 0, 0.0, plcallback::fill, false, plcallback::tr2,
               patch.pltr_data());
    if (pic.zero_contour && lo < 0.0 && hi > 0.0) contour(pls, patch, {0.0}, kBlack, 1.0, 2);
    disc(pls, 0.0, 0.0, v.body_radius, kGrey, kBlack, 2.0);
    const double dot = std::min(w.x1 - w.x0, w.y1 - w.y0) / 140.0;
    for (const auto& s : pic.points) disc(pls, s.x, s.y, dot, kRed, kBlack, 1.0);
    frame_axes(pls, "bcnst", "bcnstv", plplot_text(v.xlabel), plplot_text(v.ylabel), plplot_text(v.title));
    frame = frame_of(pls, size);
    if (!pic.footnote.empty()) {
      set_text(pls, 0.8);
      pls.mtex("b", 5.8, 0.5, 0.5, plplot_text(pic.footnote).c_str());
      set_text(pls);
    }
    colour_bar(pls, size, pic.bar_label, edges, lo, hi, lx, frame);
  });
  return frame;
}

}  // namespace magnus
