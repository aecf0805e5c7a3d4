#pragma once
// Field plots on the polar grid: streamlines (ψ contours) and a filled-contour field with its colour
// bar. The window (a rectangle) is centred on the page with equal scales on both axes; axes are in a length
// unit chosen by the caller (e.g. the radius: x/a), so that no axis needs an exponent.
#include <string>
#include <vector>

#include "plot/plot.hpp"
#include "plot/polar_field.hpp"

namespace magnus {

/// A rectangle of the plane in axis units: x0 ≤ x ≤ x1, y0 ≤ y ≤ y1.
struct PlotWindow {
  double x0 = -4.0, x1 = 4.0, y0 = -4.0, y1 = 4.0;
  /// The square |x|, |y| ≤ w.
  static PlotWindow square(double w) { return {-w, w, -w, w}; }
  /// True when (x, y) is inside (edges included).
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

/// The view of a field plot; lengths in axis units (a field's r is divided by `unit`). The box shows the
/// window with equal scales on both axes.
struct FieldView {
  std::string title;  ///< plplot_text markup
  std::string xlabel = "x/a", ylabel = "y/a";
  double unit = 1.0;         ///< one axis unit in the field's length unit (the radius: axes in x/a)
  PlotWindow window;         ///< what the box shows (axis units)
  double body_radius = 1.0;  ///< the body, a grey disc at the origin (axis units)
};

/// What a streamline picture shows.
struct StreamlinePicture {
  FieldView view;
  PolarField psi;                          ///< the streamfunction (r in the field's length unit)
  std::string psi_unit = "m²/s";           ///< unit of ψ, for the legend's Δψ
  std::vector<CurvePoint> numeric_points;  ///< stagnation points from the solution (axis units)
  std::vector<CurvePoint> exact_points;    ///< stagnation points of the exact flow (axis units)
  bool has_saddle = false;                 ///< a free stagnation point: the separatrix through it is drawn
  CurvePoint saddle{0.0, 0.0};             ///< that point (axis units)
  std::vector<std::string> notes;          ///< extra legend lines, text only (plplot_text markup)
};

/// ψ contours at multiples of a round Δψ (ψ = 0, the body and the dividing streamline, among them),
/// the separatrix and closed streamlines around a saddle, the body, and the stagnation points (numeric:
/// red dots, exact: black rings); the legend beside the window or below it. Contours are drawn from
/// refine_polar_field, not from the raw grid. Returns where it drew, with every level drawn.
PlotFrame plot_streamlines(const StreamlinePicture& pic, const std::string& png, PlotSize size = {});

/// What a filled-contour field picture shows.
struct ContourFieldPicture {
  FieldView view;
  PolarField field;                ///< the field (r in the field's length unit)
  std::string bar_label = "Cp";    ///< colour bar label (plplot_text markup)
  bool zero_contour = true;        ///< a dashed contour at 0
  std::vector<CurvePoint> points;  ///< points marked with red dots (axis units)
  std::string footnote;            ///< one line under the plot (plplot_text markup)
  /// A diverging colour map (blue, white at 0, red) over symmetric limits ±limit, for a signed field such as
  /// the vorticity; values beyond the limits take the end colours.
  bool diverging = false;
  double limit = 0.0;  ///< diverging: the colour range ±limit; 0: ±max|value| inside the window
};

/// Shades of a diverging map over ±limit: an odd number, so that the middle shade, |value| < limit/41,
/// has the zero colour (white) and round-off (ζ ~ 1e-9 in a free stream) is not coloured by its sign.
constexpr int kDivergingShades = 41;

/// The field as filled contours whose colour range is the field's range inside the window (no
/// clipping), or ±limit with a diverging map, with a labelled colour bar spanning it. Returns where it drew
/// (bar_lo, bar_hi: the bar's range).
PlotFrame plot_contour_field(const ContourFieldPicture& pic, const std::string& png, PlotSize size = {});

}  // namespace magnus
