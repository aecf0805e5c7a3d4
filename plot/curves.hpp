#pragma once
// Curve plots: labelled lines and labelled point sets on linear or log-log axes (C_L against α or Γ,
// surface Cp against θ, error against time). The caller builds every curve (models, exact solutions,
// reference data); the plot only draws them, with the legend outside the data.
#include <string>
#include <vector>

#include "plot/plot.hpp"

namespace magnus {

/// A labelled line through its points (a model, an exact solution, a bound).
struct LineCurve {
  std::string label;  ///< legend text (plplot_text markup); "" keeps it out of the legend
  std::vector<CurvePoint> points;
  Colour colour = Colour::blue;
  LineStyle style = LineStyle::solid;
  double width = 2.0;  ///< pen width (PLplot units)
};

/// A labelled set of markers, optionally joined by a line (one series of a benchmark).
struct PointSet {
  std::string label;  ///< legend text (plplot_text markup)
  std::vector<CurvePoint> points;
  Colour colour = Colour::red;
  int marker = 0;       ///< 0 ●, 1 ■, 2 ▲, 3 ◆, 4 ▼, 5 ○, 6 □, 7 △ …
  bool joined = false;  ///< draw a line through the points in order
  /// ± bars in y (absolute, same units as y), one per point; empty: none; a NaN entry: no bar there.
  /// Drawn on a linear y axis only.
  std::vector<double> y_error;
};

/// The page of a curve plot: texts (plplot_text markup, units in the labels) and axes.
struct CurvePage {
  std::string title, xlabel, ylabel;
  bool log_x = false, log_y = false;  ///< log10 axes (non-positive values are skipped)
  double x_tick = 0.0;                ///< major tick spacing on x (0: PLplot's choice)
  int x_subticks = 0;                 ///< minor ticks per major tick (0: PLplot's choice)
  bool fixed_x = false;               ///< use [x_min, x_max] as the x range instead of the data's
  double x_min = 0.0, x_max = 1.0;
  bool zero_line = true;  ///< a thin line at y = 0 when it is inside the window
};

/// Draws the lines (in order, under the points) and the point sets; the window fits every usable
/// point; the legend goes beside the plot box (right on a wide page, below on a narrow one), never over
/// the data. Throws std::runtime_error when nothing is drawable. Returns where it drew.
PlotFrame plot_curves(const CurvePage& page, const std::vector<LineCurve>& lines,
                      const std::vector<PointSet>& points, const std::string& png, PlotSize size = {});

}  // namespace magnus
