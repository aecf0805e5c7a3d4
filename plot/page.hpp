#pragma once
// Internal to plot/: one PNG page (PLplot pngcairo through an atomic file), text sized with the image,
// the palette, legends, frames and markers. Included only by plot/*.cpp (it needs PLplot's headers).
#include <plstream.h>

#include <functional>
#include <string>
#include <vector>

#include "plot/plot.hpp"

namespace magnus::page {

/// Palette (cmap0). Index 0 is the background; every pen is dark enough to read on white.
enum Pen : PLINT {
  kWhite = 0,
  kBlack = 1,
  kRed = 2,
  kBlue = 3,
  kGreen = 4,
  kGrey = 5,
  kOrange = 6,
  kPurple = 7,
  kLightGrey = 8,
  kBrown = 9,
  kTeal = 10,
  kMagenta = 11,
  kOlive = 12,
  kNavy = 13,
  kDarkGrey = 14,
  kPaleGrey = 15
};

/// The pen of a public colour.
PLINT pen(Colour c);

/// "0.25", "1e+03": a number with a few significant digits.
std::string num(double v, int digits = 3);

/// 1, 2, 2.5 or 5 × 10^k, at least x.
double nice_step(double x);

/// Renders one page with draw(pls) into png, atomically, and checks the PNG. draw sees an initialised
/// stream with a white background, the palette, the text height of the page and the whole page as
/// its subpage; PLplot's own errors are captured and reported.
void render_png(const std::string& png, PlotSize size, const std::function<void(plstream&)>& draw);

/// Character height (PLplot's, mm) for text `factor` × the page's body text: grows with the image so
/// that the same picture reads the same at 400×300 and 1920×1080.
void set_text(plstream& pls, double factor = 1.0);

/// Body text line height as a fraction of the page height / width (for layout).
double line_fraction_y(plstream& pls);
double line_fraction_x(plstream& pls);

/// Estimated width of text (PLplot markup) as a fraction of the page width at the current height.
double text_width_fraction(plstream& pls, const std::string& plplot_markup);

/// One legend line.
struct LegendEntry {
  std::string text;  ///< PLplot text
  PLINT pen = kBlack;
  bool line = false;
  PLINT line_style = 1;
  double line_width = 1.5;
  std::string symbol;  ///< empty: none
  double symbol_scale = 1.0;
};
/// A legend line showing a line.
LegendEntry line_entry(std::string text, PLINT pen, PLINT style, double width);
/// A legend line showing a marker.
LegendEntry symbol_entry(std::string text, PLINT pen, const char* glyph, double scale = 0.6);
/// A legend line of text only.
LegendEntry text_entry(std::string text);

/// Estimated legend size (width, height) as fractions of the page at the current text height.
std::pair<double, double> legend_size(plstream& pls, const std::vector<LegendEntry>& entries,
                                      int columns = 1);

/// Draws a boxed legend with its top-left corner at (x, y), fractions of the page (y upwards); returns
/// the box drawn (fractions: x0, x1, y0, y1). Leaves the whole page as the viewport.
std::vector<double> draw_legend(plstream& pls, const std::vector<LegendEntry>& entries, double x, double y,
                                int columns = 1);

/// The box in pixels of a rectangle given as page fractions (x0, x1, y0, y1; y upwards).
PixelRect to_pixels(PlotSize size, double x0, double x1, double y0, double y1);

/// The current viewport and window as a PlotFrame.
PlotFrame frame_of(plstream& pls, PlotSize size);

/// Frame, ticks and the axis labels (PLplot text) of the current viewport; the title centred on the
/// page above the box, made smaller when it would not fit the page width.
void frame_axes(plstream& pls, const char* xopt, const char* yopt, const std::string& xlabel,
                const std::string& ylabel, const std::string& title, double xtick = 0.0, PLINT nxsub = 0);

/// Filled circle of radius rad at (x, y) in world coordinates; a pen < 0 skips fill or rim.
void disc(plstream& pls, double x, double y, double rad, PLINT fill_pen, PLINT edge_pen, double edge_width);

/// Markers (a UTF-8 glyph, centred) at the points (log10 taken on log axes); size from the text height.
void markers(plstream& pls, const std::vector<CurvePoint>& pts, const char* glyph, PLINT pen,
             bool logx = false, bool logy = false);

/// True when the point can be drawn (finite, positive on a log axis).
bool usable(const CurvePoint& p, bool logx, bool logy);

/// Axis range [lo, hi] padded by a fraction, never empty.
std::pair<double, double> padded(double lo, double hi, double frac);

}  // namespace magnus::page
