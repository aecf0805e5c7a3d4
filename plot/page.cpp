#include "plot/page.hpp"

#include <plplot.h>

#include <fmt/core.h>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "base/output_owner.hpp"
#include "plot/png_output.hpp"

namespace magnus {

std::string plplot_text(const std::string& t) {
  std::string out;
  for (size_t k = 0; k < t.size(); ++k) {
    const char ch = t[k];
    if (ch == '#') {
      out += "##";
    } else if (ch == '\\' && k + 1 < t.size() && (t[k + 1] == '_' || t[k + 1] == '^')) {
      out += t[++k];
    } else if ((ch == '_' || ch == '^') && k + 1 < t.size()) {
      const std::string open = ch == '_' ? "#d" : "#u", close = ch == '_' ? "#u" : "#d";
      size_t end;
      std::string body;
      if (t[k + 1] == '{' && (end = t.find('}', k + 2)) != std::string::npos) {
        body = t.substr(k + 2, end - k - 2);
        k = end;
      } else {
        size_t n = 1;  // one character: a whole UTF-8 sequence
        while (k + 1 + n < t.size() && (static_cast<unsigned char>(t[k + 1 + n]) & 0xC0) == 0x80) ++n;
        body = t.substr(k + 1, n);
        k += n;
      }
      out += open + plplot_text(body) + close;
    } else {
      out += ch;
    }
  }
  return out;
}

std::string literal_text(const std::string& t) {
  std::string out;
  for (char ch : t) {
    if (ch == '_' || ch == '^') out += '\\';
    out += ch;
  }
  return out;
}

namespace page {
namespace {

const PLINT kPalR[16] = {255, 0, 200, 20, 0, 150, 220, 110, 190, 120, 0, 170, 110, 0, 70, 225};
const PLINT kPalG[16] = {255, 0, 30, 80, 125, 150, 110, 40, 190, 70, 130, 0, 110, 30, 70, 225};
const PLINT kPalB[16] = {255, 0, 30, 190, 60, 150, 0, 150, 190, 20, 130, 120, 0, 110, 70, 225};

std::mutex& plplot_mutex() {
  static std::mutex m;
  return m;
}

[[noreturn]] void fail(const std::string& png, const std::string& why) {
  throw std::runtime_error("plot: cannot write '" + png + "': " + why);
}

bool have_device(const char* name) {
  const int capacity = 256;
  std::vector<const char*> menu(capacity, nullptr), dev(capacity, nullptr);
  const char** pm = menu.data();
  const char** pd = dev.data();
  int n = capacity;
  plgDevs(&pm, &pd, &n);
  for (int i = 0; i < n; ++i)
    if (dev[i] && std::strcmp(dev[i], name) == 0) return true;
  return false;
}

/// Page size in pixels of the page being drawn, and its body text height in pixels.
PlotSize g_size;

/// Characters as displayed: UTF-8 sequences count once, PLplot escapes (#d, #u, ##) not at all.
double display_length(const std::string& t) {
  double n = 0;
  for (size_t k = 0; k < t.size(); ++k) {
    const unsigned char ch = static_cast<unsigned char>(t[k]);
    if (ch == '#' && k + 1 < t.size()) {
      ++k;
      if (t[k] == '#') n += 1;
      continue;
    }
    if ((ch & 0xC0) != 0x80) n += 1;
  }
  return n;
}

}  // namespace

PLINT pen(Colour c) {
  switch (c) {
    case Colour::blue:
      return kBlue;
    case Colour::red:
      return kRed;
    case Colour::green:
      return kGreen;
    case Colour::purple:
      return kPurple;
    case Colour::orange:
      return kOrange;
    case Colour::teal:
      return kTeal;
    case Colour::brown:
      return kBrown;
    case Colour::magenta:
      return kMagenta;
    case Colour::olive:
      return kOlive;
    case Colour::black:
      return kBlack;
    case Colour::grey:
      return kDarkGrey;
  }
  return kBlack;
}

std::string num(double v, int digits) {
  if (v == 0.0) return "0";
  return fmt::format("{:.{}g}", v, digits);
}

double nice_step(double x) {
  if (!(x > 0.0) || !std::isfinite(x)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= x * (1.0 - 1e-12)) return m * p;
  return 10.0 * p;
}

void render_png(const std::string& png, PlotSize size, const std::function<void(plstream&)>& draw) {
  if (png.empty()) throw std::runtime_error("plot: empty output file name");
  if (size.width < 16 || size.height < 16 || size.width > 16384 || size.height > 16384)
    fail(png,
         fmt::format("image size {}x{} out of range (16 to 16384 pixels a side)", size.width, size.height));

  std::lock_guard<std::mutex> lock(plplot_mutex());
  std::unique_ptr<AtomicFile> out;
  try {
    out = std::make_unique<AtomicFile>(png);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("plot: ") + e.what());
  }
  const std::string& tmp = out->temp();
  // PLplot takes the FILE* over (and closes it) once plinit has run.
  PngSink sink;
  FILE* file = open_png_sink(sink, tmp);
  if (!file) fail(png, std::strerror(errno));
  bool file_owned = true;
  try {
    // An unknown device would make plinit prompt on stdin: check first.
    if (!have_device("pngcairo"))
      fail(png, "the PLplot pngcairo driver is not installed (plplot-driver-cairo)");
    PLINT errcode = 0;
    char errmsg[1024] = {0};
    {
      plstream pls;
      pls.sError(&errcode, errmsg);  // plabort messages go here instead of stderr
      pls.sdev("pngcairo");
      const std::string geometry = fmt::format("{}x{}", size.width, size.height);
      if (pls.setopt("geometry", geometry.c_str()) != 0)
        fail(png, "PLplot rejected the geometry " + geometry);
      pls.scmap0(kPalR, kPalG, kPalB, 16);
      pls.scolbg(255, 255, 255);
      pls.sfile(file);
      pls.init();
      file_owned = false;
      if (errcode) fail(png, std::string("PLplot: ") + errmsg);
      g_size = size;
      pls.adv(0);
      pls.vpor(0.0, 1.0, 0.0, 1.0);
      pls.col0(kBlack);
      set_text(pls);
      draw(pls);
      if (errcode) fail(png, std::string("PLplot: ") + errmsg);
    }  // ~plstream: end of page, the PNG is written and the file closed
    if (sink.error) fail(png, std::strerror(sink.error));  // e.g. "No space left on device"
    errno = 0;
    if (!mark_png_file(tmp)) fail(png, errno ? std::strerror(errno) : "cannot mark the image as magnus's");
    const std::string bad = check_png(tmp, size);
    if (!bad.empty()) fail(png, bad);
    out->commit();
  } catch (const std::exception& e) {
    if (file_owned) std::fclose(file);
    const std::string what = e.what();
    if (what.rfind("plot: ", 0) == 0) throw;
    fail(png, what);
  }
}

void set_text(plstream& pls, double factor) {
  PLFLT sx0 = 0, sx1 = 0, sy0 = 0, sy1 = 0, def_mm = 0, ht_mm = 0;
  pls.gspa(sx0, sx1, sy0, sy1);
  pls.gchr(def_mm, ht_mm);
  const double px_per_mm = (sx1 > sx0) ? g_size.width / (sx1 - sx0) : 3.5;
  // Body text: 1.8% of the page's smaller dimension (a 4:3 page's width counts as its height), at least 8 px.
  const double body_px = std::max(8.0, 0.018 * std::min(double(g_size.width) * 0.75, double(g_size.height)));
  const double want_mm = factor * body_px / px_per_mm;
  pls.schr(0.0, def_mm > 0 ? want_mm / def_mm : 1.0);
}

double line_fraction_y(plstream& pls) {
  PLFLT sx0 = 0, sx1 = 0, sy0 = 0, sy1 = 0, def_mm = 0, ht_mm = 0;
  pls.gspa(sx0, sx1, sy0, sy1);
  pls.gchr(def_mm, ht_mm);
  return sy1 > sy0 ? ht_mm / (sy1 - sy0) : 0.02;
}

double line_fraction_x(plstream& pls) {
  PLFLT sx0 = 0, sx1 = 0, sy0 = 0, sy1 = 0, def_mm = 0, ht_mm = 0;
  pls.gspa(sx0, sx1, sy0, sy1);
  pls.gchr(def_mm, ht_mm);
  return sx1 > sx0 ? ht_mm / (sx1 - sx0) : 0.02;
}

double text_width_fraction(plstream& pls, const std::string& t) {
  return display_length(t) * 0.72 * line_fraction_x(pls);  // generous: no string metrics in PLplot 5
}

LegendEntry line_entry(std::string text, PLINT p, PLINT style, double width) {
  LegendEntry e;
  e.text = std::move(text);
  e.pen = p;
  e.line = true;
  e.line_style = style;
  e.line_width = width;
  return e;
}

LegendEntry symbol_entry(std::string text, PLINT p, const char* glyph, double scale) {
  LegendEntry e;
  e.text = std::move(text);
  e.pen = p;
  e.symbol = glyph;
  e.symbol_scale = scale;
  return e;
}

LegendEntry text_entry(std::string text) {
  LegendEntry e;
  e.text = std::move(text);
  return e;
}

namespace {
constexpr double kLegendPlotWidth = 0.07;  // the line sample, fraction of the page width (the viewport)
}

std::pair<double, double> legend_size(plstream& pls, const std::vector<LegendEntry>& entries, int columns) {
  double chars = 0;
  for (const auto& e : entries) chars = std::max(chars, display_length(e.text));
  const int rows = int((entries.size() + columns - 1) / columns);
  const double lx = line_fraction_x(pls), ly = line_fraction_y(pls);
  const double col_w = chars * 0.75 * lx + kLegendPlotWidth + 3.0 * lx;
  return {columns * col_w, (rows * 2.2 + 1.2) * ly};
}

std::vector<double> draw_legend(plstream& pls, const std::vector<LegendEntry>& entries, double x, double y,
                                int columns) {
  if (entries.empty()) return {};
  pls.vpor(0.0, 1.0, 0.0, 1.0);
  pls.wind(0.0, 1.0, 0.0, 1.0);
  PLFLT def_mm = 0.0, ht_mm = 0.0;
  pls.gchr(def_mm, ht_mm);
  const double scale = def_mm > 0.0 ? ht_mm / def_mm : 1.0;
  const PLINT n = PLINT(entries.size());
  std::vector<PLINT> opt(n), text_colors(n, kBlack), line_colors(n), line_styles(n), symbol_colors(n),
      symbol_numbers(n, 1), box_colors(n, 0), box_patterns(n, 0);
  std::vector<PLFLT> line_widths(n), symbol_scales(n), box_scales(n, 0.0), box_line_widths(n, 0.0);
  std::vector<const char*> text(n), symbols(n);
  for (PLINT k = 0; k < n; ++k) {
    const auto& e = entries[k];
    opt[k] = (e.line ? PL_LEGEND_LINE : 0) | (e.symbol.empty() ? 0 : PL_LEGEND_SYMBOL);
    if (!opt[k]) opt[k] = PL_LEGEND_NONE;
    text[k] = e.text.c_str();
    line_colors[k] = e.pen;
    line_styles[k] = e.line_style;
    line_widths[k] = e.line_width;
    symbol_colors[k] = e.pen;
    symbol_scales[k] = e.symbol_scale * scale;
    symbols[k] = e.symbol.c_str();
  }
  const PLINT rows = PLINT((n + columns - 1) / columns);
  PLFLT w = 0.0, h = 0.0;
  pls.legend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX | (columns > 1 ? PL_LEGEND_ROW_MAJOR : 0),
             PL_POSITION_LEFT | PL_POSITION_TOP | PL_POSITION_INSIDE | PL_POSITION_VIEWPORT, x, 1.0 - y,
             kLegendPlotWidth, kWhite, kBlack, 1, rows, columns, n, opt.data(), 0.8, scale, 2.0, 0.0,
             text_colors.data(), text.data(), box_colors.data(), box_patterns.data(), box_scales.data(),
             box_line_widths.data(), line_colors.data(), line_styles.data(), line_widths.data(),
             symbol_colors.data(), symbol_scales.data(), symbol_numbers.data(), symbols.data());
  return {x, x + w, y - h, y};
}

PixelRect to_pixels(PlotSize size, double x0, double x1, double y0, double y1) {
  return {x0 * size.width, x1 * size.width, (1.0 - y1) * size.height, (1.0 - y0) * size.height};
}

PlotFrame frame_of(plstream& pls, PlotSize size) {
  PLFLT vx0 = 0, vx1 = 0, vy0 = 0, vy1 = 0, wx0 = 0, wx1 = 0, wy0 = 0, wy1 = 0;
  pls.gvpd(vx0, vx1, vy0, vy1);
  pls.gvpw(wx0, wx1, wy0, wy1);
  PlotFrame f;
  f.box = to_pixels(size, vx0, vx1, vy0, vy1);
  f.x0 = wx0;
  f.x1 = wx1;
  f.y0 = wy0;
  f.y1 = wy1;
  return f;
}

void frame_axes(plstream& pls, const char* xopt, const char* yopt, const std::string& xlabel,
                const std::string& ylabel, const std::string& title, double xtick, PLINT nxsub) {
  pls.col0(kBlack);
  pls.width(1.2);
  pls.box(xopt, xtick, nxsub, yopt, 0.0, 0);
  pls.width(1.0);
  pls.mtex("b", 3.3, 0.5, 0.5, xlabel.c_str());
  pls.mtex("l", 4.2, 0.5, 0.5, ylabel.c_str());
  if (title.empty()) return;
  // Centred on the page, 1.8 lines above the box; smaller when it would not fit the page's width.
  PLFLT vx0 = 0, vx1 = 0, vy0 = 0, vy1 = 0, def_mm = 0, ht_mm = 0;
  pls.gvpd(vx0, vx1, vy0, vy1);
  pls.gchr(def_mm, ht_mm);
  const double len = text_width_fraction(pls, title), room = 0.96;
  if (len > room) pls.schr(0.0, ht_mm / def_mm * room / len);
  const double box = vx1 - vx0;
  pls.mtex("t", 1.6, box > 0 ? (0.5 - vx0) / box : 0.5, 0.5, title.c_str());
  pls.schr(0.0, ht_mm / def_mm);
}

void disc(plstream& pls, double x, double y, double rad, PLINT fill_pen, PLINT edge_pen, double edge_width) {
  const int n = 90;
  std::vector<PLFLT> px(n + 1), py(n + 1);
  for (int k = 0; k <= n; ++k) {
    px[k] = x + rad * std::cos(2 * M_PI * k / n);
    py[k] = y + rad * std::sin(2 * M_PI * k / n);
  }
  if (fill_pen >= 0) {
    pls.col0(fill_pen);
    pls.psty(0);
    pls.fill(n, px.data(), py.data());
  }
  if (edge_pen >= 0) {
    pls.col0(edge_pen);
    pls.width(edge_width);
    pls.line(n + 1, px.data(), py.data());
    pls.width(1.0);
  }
}

bool usable(const CurvePoint& p, bool logx, bool logy) {
  return std::isfinite(p.x) && std::isfinite(p.y) && (!logx || p.x > 0) && (!logy || p.y > 0);
}

void markers(plstream& pls, const std::vector<CurvePoint>& pts, const char* glyph, PLINT p, bool logx,
             bool logy) {
  std::vector<PLFLT> x, y;
  for (const auto& q : pts)
    if (usable(q, logx, logy)) {
      x.push_back(logx ? std::log10(q.x) : q.x);
      y.push_back(logy ? std::log10(q.y) : q.y);
    }
  if (x.empty()) return;
  pls.col0(p);
  pls.string(PLINT(x.size()), x.data(), y.data(), glyph);
}

std::pair<double, double> padded(double lo, double hi, double frac) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (hi - lo <= 1e-12 * std::max(1.0, std::fabs(hi))) {
    const double d = std::max(1.0, std::fabs(hi)) * 0.1;
    return {lo - d, hi + d};
  }
  const double d = (hi - lo) * frac;
  return {lo - d, hi + d};
}

}  // namespace page
}  // namespace magnus
