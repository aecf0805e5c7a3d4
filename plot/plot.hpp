#pragma once
// What every picture shares: the image size, data points, colours and line styles, the text markup,
// and where a picture was drawn (PlotFrame: the plot box in pixels and the window it shows), which
// callers and tests use to find data on the image. Pictures are PNG files written by PLplot
// (pngcairo); every file appears only when complete (temporary name beside it, then renamed); a
// failure throws std::runtime_error naming the file and leaves no file behind. Calls are serialised
// (PLplot keeps global state). No physics here: callers pass the curves and fields.
#include <string>
#include <vector>

namespace magnus {

/// Image size in pixels.
struct PlotSize {
  int width = 1000, height = 800;
};

/// One (x, y) data point, in the units of the plot's axes.
struct CurvePoint {
  double x, y;
};

/// Colours of lines and markers (all dark enough to read on white).
enum class Colour { blue, red, green, purple, orange, teal, brown, magenta, olive, black, grey };

/// How a line is drawn.
enum class LineStyle { solid, dashed, dotted };

/// A rectangle in pixels, x to the right and y downwards from the image's top-left corner.
struct PixelRect {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  /// True when the rectangle has an area.
  bool empty() const { return !(x1 > x0 && y1 > y0); }
};

/// Where a picture was drawn: the plot box, the window it shows (in the data's units, whatever power of
/// ten the axis labels show it in), and the boxes of the legend and the colour bar (empty when none).
struct PlotFrame {
  PixelRect box;                          ///< the plot box (its frame lines)
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  ///< axis range shown in the box (log10 on a log axis)
  PixelRect legend;                       ///< the legend's box
  PixelRect colour_bar;                   ///< the colour bar's shaded strip
  double bar_lo = 0, bar_hi = 0;          ///< the values at the bottom and top of the colour bar
  std::vector<double> levels;             ///< contour levels drawn (field plots)
  /// The axes and the colour bar show value·10^−k: the powers of ten written into their labels (0: none).
  int x_exponent = 0, y_exponent = 0, bar_exponent = 0;
  std::string xlabel, ylabel, bar_label;  ///< the labels as drawn (plplot_text markup input)
  /// Pixel column of axis value x (inside the box when x0 ≤ x ≤ x1).
  double px(double x) const { return box.x0 + (x - x0) / (x1 - x0) * (box.x1 - box.x0); }
  /// Pixel row of axis value y.
  double py(double y) const { return box.y1 - (y - y0) / (y1 - y0) * (box.y1 - box.y0); }
};

/// Text for labels and titles: "_x" or "_{…}" is a subscript, "^x" or "^{…}" a superscript, "\_" and
/// "\^" are literal; translated to PLplot's escapes ("#d…#u", "#u…#d", "##" for '#').
std::string plplot_text(const std::string& text);

/// Escapes user text (a case title) so that plplot_text shows it literally.
std::string literal_text(const std::string& text);

}  // namespace magnus
