#include "plot/plot.hpp"

#include <fcntl.h>
#include <plplot.h>
#include <plstream.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fmt/core.h>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "physics/exact.hpp"

namespace magnus {
namespace {

// ---------------------------------------------------------------------------------------------
// Palette (cmap0). Index 0 is the background; every pen is dark enough to read on white.
enum Pen : PLINT {
  kWhite = 0, kBlack = 1, kRed = 2, kBlue = 3, kGreen = 4, kGrey = 5, kOrange = 6, kPurple = 7,
  kLightGrey = 8, kBrown = 9, kTeal = 10, kMagenta = 11, kOlive = 12, kNavy = 13, kDarkGrey = 14,
  kPaleGrey = 15
};
const PLINT kPalR[16] = {255, 0, 200, 20, 0, 150, 220, 110, 190, 120, 0, 170, 110, 0, 70, 225};
const PLINT kPalG[16] = {255, 0, 30, 80, 125, 150, 110, 40, 190, 70, 130, 0, 110, 30, 70, 225};
const PLINT kPalB[16] = {255, 0, 30, 190, 60, 150, 0, 150, 190, 20, 130, 120, 0, 110, 70, 225};

// Colours and markers (UTF-8 glyphs drawn with plstring) cycled through by data series.
const PLINT kSeriesPens[] = {kBlue, kRed, kGreen, kPurple, kOrange, kTeal, kBrown, kMagenta, kOlive, kBlack};
const char* const kMarkers[] = {"●", "■", "▲", "◆", "▼", "○", "□", "△", "◇", "▽"};

/// PLplot escapes text with '#': user text must not start an escape sequence.
std::string plain(const std::string& s) {
  std::string out;
  for (char ch : s) {
    out += ch;
    if (ch == '#') out += '#';
  }
  return out;
}

std::string num(double v, int digits = 3) {
  if (v == 0.0) return "0";
  return fmt::format("{:.{}g}", v, digits);
}

/// 1, 2, 2.5 or 5 × 10^k, at least x.
double nice_step(double x) {
  if (!(x > 0.0) || !std::isfinite(x)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= x * (1.0 - 1e-12)) return m * p;
  return 10.0 * p;
}

// ---------------------------------------------------------------------------------------------
// Output: one PNG page rendered by pngcairo into a temporary file beside the target, checked,
// then renamed.

std::mutex& plplot_mutex() {
  static std::mutex m;
  return m;
}

[[noreturn]] void fail(const std::string& png, const std::string& why) {
  throw std::runtime_error("plot: cannot write " + png + ": " + why);
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

/// The file is a complete PNG of the requested size: signature, IHDR, and IEND last.
std::string check_png(const std::string& path, PlotSize size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "the rendered file cannot be read back";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  if (bytes.size() < 8 + 25 + 12 || std::memcmp(bytes.data(), sig, 8) != 0 ||
      bytes.compare(12, 4, "IHDR") != 0)
    return "PLplot produced no PNG image";
  auto be32 = [&](size_t at) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + at;
    return (unsigned long)b[0] << 24 | (unsigned long)b[1] << 16 | (unsigned long)b[2] << 8 | b[3];
  };
  if (be32(16) != (unsigned long)size.width || be32(20) != (unsigned long)size.height)
    return fmt::format("PLplot produced a {}x{} image instead of {}x{}", be32(16), be32(20), size.width,
                       size.height);
  if (std::memcmp(bytes.data() + bytes.size() - 12, iend, 12) != 0) return "the PNG is truncated (disk full?)";
  return {};
}

/// Renders one page with draw(pls) into png, atomically. draw sees an initialised stream with a white
/// background and the dark palette; PLplot's own error aborts are captured and reported.
template <class Draw>
void render_png(const std::string& png, PlotSize size, Draw&& draw) {
  if (png.empty()) throw std::runtime_error("plot: empty output file name");
  if (size.width < 16 || size.height < 16 || size.width > 16384 || size.height > 16384)
    fail(png, fmt::format("image size {}x{} out of range (16 to 16384 pixels a side)", size.width, size.height));

  std::lock_guard<std::mutex> lock(plplot_mutex());

  std::unique_ptr<AtomicFile> out;
  try {
    out = std::make_unique<AtomicFile>(png);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("plot: ") + e.what());
  }
  const std::string& tmp = out->temp();
  // PLplot takes the FILE* over (and closes it) once plinit has run.
  FILE* file = std::fopen(tmp.c_str(), "wb");
  if (!file) fail(png, std::strerror(errno));
  bool file_owned = true;
  try {
    // An unknown device would make plinit prompt on stdin: check first.
    if (!have_device("pngcairo")) fail(png, "the PLplot pngcairo driver is not installed (plplot-driver-cairo)");
    PLINT errcode = 0;
    char errmsg[1024] = {0};
    {
      plstream pls;
      pls.sError(&errcode, errmsg);  // plabort messages go here instead of stderr
      pls.sdev("pngcairo");
      const std::string geometry = fmt::format("{}x{}", size.width, size.height);
      if (pls.setopt("geometry", geometry.c_str()) != 0) fail(png, "PLplot rejected the geometry " + geometry);
      pls.scmap0(kPalR, kPalG, kPalB, 16);
      pls.scolbg(255, 255, 255);
      pls.sfile(file);
      pls.init();
      file_owned = false;
      if (errcode) fail(png, std::string("PLplot: ") + errmsg);
      pls.col0(kBlack);
      draw(pls);
      if (errcode) fail(png, std::string("PLplot: ") + errmsg);
    }  // ~plstream: end of page, the PNG is written and the file closed
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

// ---------------------------------------------------------------------------------------------
// Drawing helpers.


/// Character height scaled with the image so that text stays legible at any size.
/// Returns the scale set (relative to PLplot's default height).
double text_scale(plstream& pls, PlotSize size, double factor = 1.0) {
  // PLplot's default height is fixed in pixels: grow it gently with the image.
  const double s = 0.9 * factor * std::pow(std::clamp(std::min(size.width, size.height) / 800.0, 0.3, 4.0), 0.6);
  pls.schr(0.0, s);
  return s;
}

/// Marker glyphs are text: their size is set the same way, smaller.
void marker_scale(plstream& pls, PlotSize size, double factor = 1.0) { text_scale(pls, size, 0.55 * factor); }

struct LegendEntry {
  std::string text;
  PLINT pen = kBlack;
  bool line = false;
  PLINT line_style = 1;
  double line_width = 1.5;
  std::string symbol;  // empty: none
  double symbol_scale = 1.0;
};

LegendEntry line_entry(std::string text, PLINT pen, PLINT style, double width) {
  LegendEntry e;
  e.text = std::move(text);
  e.pen = pen;
  e.line = true;
  e.line_style = style;
  e.line_width = width;
  return e;
}

LegendEntry symbol_entry(std::string text, PLINT pen, const char* glyph, double scale = 0.6) {
  LegendEntry e;
  e.text = std::move(text);
  e.pen = pen;
  e.symbol = glyph;
  e.symbol_scale = scale;
  return e;
}

/// A boxed legend on a white background; position is PL_POSITION_* relative to the viewport. The text
/// height is the current one; symbol scales are relative to it. (pllegend's scales are absolute.)
void draw_legend(plstream& pls, const std::vector<LegendEntry>& entries, PLINT position, double x, double y) {
  if (entries.empty()) return;
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
  PLFLT w = 0.0, h = 0.0;
  pls.legend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, position, x, y, 0.07, kWhite, kBlack, 1, 0,
             0, n, opt.data(), 0.8, scale, 2.0, 0.0, text_colors.data(), text.data(), box_colors.data(),
             box_patterns.data(), box_scales.data(), box_line_widths.data(), line_colors.data(),
             line_styles.data(), line_widths.data(), symbol_colors.data(), symbol_scales.data(),
             symbol_numbers.data(), symbols.data());
}

/// Characters as displayed: UTF-8 sequences count once, PLplot escapes (#d, #u, ##) not at all.
size_t display_length(const std::string& t) {
  size_t n = 0;
  for (size_t k = 0; k < t.size(); ++k) {
    const unsigned char ch = static_cast<unsigned char>(t[k]);
    if (ch == '#' && k + 1 < t.size()) {
      ++k;
      if (t[k] == '#') ++n;
      continue;
    }
    if ((ch & 0xC0) != 0x80) ++n;
  }
  return n;
}

/// Estimated legend size as fractions of the viewport, at the current text height (pllegend reports
/// its size only after drawing).
std::pair<double, double> legend_fraction(plstream& pls, const std::vector<LegendEntry>& entries) {
  PLFLT def_mm = 0.0, ht_mm = 0.0, sx0 = 0.0, sx1 = 0.0, sy0 = 0.0, sy1 = 0.0, vx0 = 0.0, vx1 = 0.0, vy0 = 0.0,
        vy1 = 0.0;
  pls.gchr(def_mm, ht_mm);
  pls.gspa(sx0, sx1, sy0, sy1);
  pls.gvpd(vx0, vx1, vy0, vy1);
  const double vw = std::max(1e-9, (vx1 - vx0) * (sx1 - sx0)), vh = std::max(1e-9, (vy1 - vy0) * (sy1 - sy0));
  size_t chars = 0;
  for (const auto& e : entries) chars = std::max(chars, display_length(e.text));
  const double w_mm = double(chars) * 0.62 * ht_mm + 0.07 * vw + 2.5 * ht_mm;
  const double h_mm = double(entries.size()) * 2.0 * ht_mm;
  return {w_mm / vw, h_mm / vh};
}

/// Points along the segment (x0, y0)–(x1, y1), for legend placement.
void sample_segment(std::vector<CurvePoint>& out, double x0, double y0, double x1, double y1, int n = 60) {
  for (int k = 0; k <= n; ++k) out.push_back({x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n});
}

/// The inside corner of the viewport window [x0, x1] × [y0, y1] whose legend box (offset dx, dy,
/// size frac) covers the fewest of the occupied points; ties go to the earlier preference.
PLINT pick_corner(const std::vector<CurvePoint>& occupied, double x0, double x1, double y0, double y1,
                  std::pair<double, double> frac, double dx, double dy, std::initializer_list<PLINT> prefs) {
  PLINT best = *prefs.begin();
  size_t best_count = std::numeric_limits<size_t>::max();
  const double margin = 0.02;
  for (PLINT corner : prefs) {
    const bool right = corner & PL_POSITION_RIGHT, top = corner & PL_POSITION_TOP;
    const double u0 = right ? 1.0 - dx - frac.first : dx, v0 = top ? 1.0 - dy - frac.second : dy;
    const double u1 = u0 + frac.first, v1 = v0 + frac.second;
    size_t count = 0;
    for (const auto& p : occupied) {
      const double u = (p.x - x0) / (x1 - x0), v = (p.y - y0) / (y1 - y0);
      if (u > u0 - margin && u < u1 + margin && v > v0 - margin && v < v1 + margin) ++count;
    }
    if (count < best_count) {
      best = corner;
      best_count = count;
    }
  }
  return best | PL_POSITION_INSIDE;
}

/// Filled circle (polygon) of radius rad at (x, y) in world coordinates; a pen < 0 skips fill or rim.
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

/// Markers (a UTF-8 glyph, centred) at the points; the size comes from the current character height.
void markers(plstream& pls, const std::vector<CurvePoint>& pts, const char* glyph, PLINT pen, bool logx = false,
             bool logy = false) {
  std::vector<PLFLT> x, y;
  for (const auto& p : pts)
    if (usable(p, logx, logy)) {
      x.push_back(logx ? std::log10(p.x) : p.x);
      y.push_back(logy ? std::log10(p.y) : p.y);
    }
  if (x.empty()) return;
  pls.col0(pen);
  pls.string(PLINT(x.size()), x.data(), y.data(), glyph);
}

/// A field on rings i0…i1 of the polar grid as (i1 − i0 + 1, n_θ + 1) arrays for plcont/plshades with
/// pltr2: column n_θ repeats column 0 (θ = 2π, same x, y) so that contours close over the seam and
/// no cell spans it.
struct PolarPatch {
  PLINT nx = 0, ny = 0;
  std::vector<PLFLT> xs, ys, zs;
  std::vector<PLFLT*> xrow, yrow, zrow;
  PLcGrid2 grid{};

  PolarPatch(const PolarGrid& g, const std::vector<double>& f, int i0, int i1) {
    const int nt = g.n_theta;
    i0 = std::clamp(i0, 0, g.n_r - 2);
    i1 = std::clamp(i1, i0 + 1, g.n_r - 1);
    nx = i1 - i0 + 1;
    ny = nt + 1;
    xs.resize(size_t(nx) * ny);
    ys.resize(xs.size());
    zs.resize(xs.size());
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j <= nt; ++j) {
        const int jj = j % nt;
        const size_t q = size_t(i) * ny + j;
        xs[q] = g.r[i0 + i] * std::cos(g.theta[jj]);
        ys[q] = g.r[i0 + i] * std::sin(g.theta[jj]);
        zs[q] = f[size_t(i0 + i) * nt + jj];
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

  /// Range of the field over the nodes inside the square |x|, |y| ≤ w.
  std::pair<double, double> range_in(double w) const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (size_t q = 0; q < zs.size(); ++q)
      if (std::fabs(xs[q]) <= w && std::fabs(ys[q]) <= w && std::isfinite(zs[q])) {
        lo = std::min(lo, zs[q]);
        hi = std::max(hi, zs[q]);
      }
    return {lo, hi};
  }
};

/// Index of the last ring with r_i ≤ r (0 if none).
int ring_at_or_below(const PolarGrid& g, double r) {
  int i = 0;
  while (i + 1 < g.n_r && g.r[i + 1] <= r) ++i;
  return i;
}

/// Index of the first ring with r_i ≥ r (n_r − 1 if none).
int ring_at_or_above(const PolarGrid& g, double r) {
  int i = 0;
  while (i + 1 < g.n_r && g.r[i] < r) ++i;
  return i;
}

/// Half-width of the square view window: min(R, 4a).
double view_half_width(const FlowResult& r) { return std::min(r.grid.outer_radius(), 4.0 * r.grid.a); }

/// "α = 1.5" (with the circulation when it is given, or "U = 0").
std::string flow_label(const Case& c) {
  if (c.scene.speed <= 0.0) return fmt::format("U = 0, Γ = {} m²/s", num(c.scene.Gamma()));
  std::string s = fmt::format("α = {}", num(c.scene.spin_ratio(), 4));
  if (c.scene.circulation_given) s += fmt::format(", Γ = {} m²/s", num(c.scene.Gamma()));
  return s;
}

std::string case_title(const Case& c) { return plain(c.title.empty() ? std::string("Spinning cylinder") : c.title); }

/// Square plot box over |x|, |y| ≤ w with equal scales, within [0.09, right] of the page width.
void square_frame(plstream& pls, double w, double right, double bottom = 0.10) {
  pls.adv(0);
  pls.vpas(0.09, right, bottom, 0.91, 1.0);
  pls.wind(-w, w, -w, w);
}

void frame_axes(plstream& pls, const char* xopt, const char* yopt, const std::string& xlabel,
                const std::string& ylabel, const std::string& title) {
  pls.col0(kBlack);
  pls.width(1.2);
  pls.box(xopt, 0.0, 0, yopt, 0.0, 0);
  pls.width(1.0);
  pls.lab(xlabel.c_str(), ylabel.c_str(), "");
  if (title.empty()) return;
  // The title as pllab places it (2 lines above the box, centred on it), but moved sideways, or made
  // smaller, so that it stays on the page when the box is off-centre (a legend beside it).
  PLFLT def_mm = 0.0, ht_mm = 0.0, sx0 = 0.0, sx1 = 0.0, sy0 = 0.0, sy1 = 0.0, vx0 = 0.0, vx1 = 0.0, vy0 = 0.0,
        vy1 = 0.0;
  pls.gchr(def_mm, ht_mm);
  pls.gspa(sx0, sx1, sy0, sy1);
  pls.gvpd(vx0, vx1, vy0, vy1);
  const double page = sx1 - sx0, box0 = vx0 * page, box = (vx1 - vx0) * page, margin = 1.5 * ht_mm;
  double len = double(display_length(title)) * 0.7 * ht_mm;  // estimated generously (no string metrics)
  const bool shrink = page > 0.0 && len > page - 2 * margin;
  if (shrink) {
    pls.schr(0.0, ht_mm / def_mm * (page - 2 * margin) / len);
    len = page - 2 * margin;
  }
  const double centre = std::clamp(box0 + 0.5 * box, margin + 0.5 * len, std::max(margin + 0.5 * len, page - margin - 0.5 * len));
  pls.mtex("t", 2.0, box > 0.0 ? (centre - box0) / box : 0.5, 0.5, title.c_str());
  if (shrink) pls.schr(0.0, ht_mm / def_mm);
}

/// The body: a grey disc with a black rim.
void cylinder(plstream& pls, double a) { disc(pls, 0.0, 0.0, a, kGrey, kBlack, 2.0); }

/// ψ at (r, θ) from the grid field: periodic cubic in θ on the two rings around r, linear in r.
double psi_at(const PolarGrid& g, const std::vector<double>& psi, double r, double theta) {
  const int i = std::min(ring_at_or_below(g, r), g.n_r - 2);
  const int nt = g.n_theta;
  const std::vector<double> a(psi.begin() + long(i) * nt, psi.begin() + long(i + 1) * nt);
  const std::vector<double> b(psi.begin() + long(i + 1) * nt, psi.begin() + long(i + 2) * nt);
  const double fa = periodic_interpolate(a, theta), fb = periodic_interpolate(b, theta);
  const double t = std::clamp((r - g.r[i]) / (g.r[i + 1] - g.r[i]), 0.0, 1.0);
  return fa + t * (fb - fa);
}

void contour(plstream& pls, PolarPatch& p, const std::vector<PLFLT>& levels, PLINT pen, double width,
             PLINT style = 1) {
  if (levels.empty()) return;
  pls.col0(pen);
  pls.width(width);
  pls.lsty(style);
  // plcont index ranges are 1-based and inclusive.
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

/// Axis range [lo, hi] padded by a fraction, never empty.
std::pair<double, double> padded(double lo, double hi, double frac) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (hi - lo <= 1e-12 * std::max(1.0, std::fabs(hi))) {
    const double d = std::max(1.0, std::fabs(hi)) * 0.1;
    return {lo - d, hi + d};
  }
  const double d = (hi - lo) * frac;
  return {lo - d, hi + d};
}

}  // namespace

// -------------------------------------------------------------------------------------------------

void plot_streamlines(const FlowResult& r, const std::string& png, PlotSize size) {
  const PolarGrid& g = r.grid;
  const auto& psi = r.fields.psi;
  if (psi.size() != size_t(g.nodes()) || g.n_r < 2 || g.n_theta < 4)
    throw std::runtime_error("plot: the result has no psi field");
  const double a = g.a, w = view_half_width(r);
  const int i_view = ring_at_or_above(g, w * std::sqrt(2.0));  // the window's corners
  PolarPatch all(g, psi, 0, i_view);

  // Levels: multiples of a round step, so that ψ = 0 (the body, and the dividing streamline
  // while the stagnation points are on the surface) is one of them.
  const auto [lo, hi] = all.range_in(w);
  const double step = nice_step((hi - lo) / 24.0);
  std::vector<PLFLT> regular;
  if (hi > lo)
    for (long k = long(std::ceil(lo / step)); k <= long(std::floor(hi / step)); ++k)
      if (k != 0) regular.push_back(k * step);

  // |α| > 2: one free stagnation point, a saddle at r_s. The separatrix ψ = ψ_s through it encloses
  // the closed streamlines, 0 < ψ/ψ_s < 1 at r < r_s; the same values at r > r_s are open streamlines.
  std::vector<PLFLT> dividing = {0.0}, closed, open_inner;
  const StagnationPoint* saddle = nullptr;
  for (const auto& s : r.stagnation)
    if (!s.on_surface) saddle = &s;
  std::unique_ptr<PolarPatch> inner, outer;
  if (saddle) {
    const double ps = psi_at(g, psi, saddle->r, saddle->theta);
    dividing.push_back(ps);
    for (double f : {0.2, 0.4, 0.6, 0.8}) closed.push_back(f * ps);
    const int i_s = ring_at_or_below(g, saddle->r);
    inner = std::make_unique<PolarPatch>(g, psi, 0, i_s);
    outer = std::make_unique<PolarPatch>(g, psi, i_s, std::max(i_view, i_s + 1));
    auto between = [&](double v) { return v * (v - ps) < 0.0; };  // strictly between 0 and ψ_s
    for (double v : regular)
      if (between(v)) open_inner.push_back(v);
    regular.erase(std::remove_if(regular.begin(), regular.end(), between), regular.end());
  }

  // The legend goes right of the square box when the page is wide enough, else inside it.
  const bool legend_outside = size.width >= 1.2 * size.height;
  const std::string title = fmt::format("{}: streamlines, {}", case_title(r.c), flow_label(r.c));
  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    square_frame(pls, w, legend_outside ? 0.64 : 0.96);
    contour(pls, all, regular, kBlue, 1.2);
    if (saddle) {
      contour(pls, *outer, open_inner, kBlue, 1.2);
      contour(pls, *inner, closed, kPurple, 1.4);
    }
    contour(pls, all, dividing, kBlack, 2.4);
    cylinder(pls, a);
    const double dot = w / 60.0;
    for (const auto& s : r.stagnation_exact)
      disc(pls, s.r * std::cos(s.theta), s.r * std::sin(s.theta), 2.0 * dot, -1, kBlack, 1.5);
    for (const auto& s : r.stagnation)
      disc(pls, s.r * std::cos(s.theta), s.r * std::sin(s.theta), dot, kRed, kBlack, 1.0);
    frame_axes(pls, "bcnst", "bcnstv", "x (m)", "y (m)", title);

    std::vector<LegendEntry> legend;
    legend.push_back(line_entry(fmt::format("ψ contours, Δψ = {} m²/s", num(step)), kBlue, 1, 1.2));
    if (saddle) {
      legend.push_back(line_entry("separatrix ψ = ψ#ds#u", kBlack, 1, 2.4));
      legend.push_back(line_entry("closed streamlines", kPurple, 1, 1.4));
    } else if (!r.stagnation.empty()) {
      legend.push_back(line_entry("dividing streamline ψ = 0", kBlack, 1, 2.4));
    }
    if (!r.stagnation.empty()) legend.push_back(symbol_entry("stagnation point, numeric", kRed, "●", 0.75));
    if (!r.stagnation_exact.empty()) legend.push_back(symbol_entry("stagnation point, exact", kBlack, "○", 1.3));
    text_scale(pls, size, 0.8);
    if (legend_outside)
      draw_legend(pls, legend, PL_POSITION_RIGHT | PL_POSITION_OUTSIDE, 0.02, 0.0);
    else
      draw_legend(pls, legend, PL_POSITION_LEFT | PL_POSITION_BOTTOM | PL_POSITION_INSIDE, 0.01, 0.01);
  });
}

void plot_cp_field(const FlowResult& r, const std::string& png, PlotSize size) {
  const PolarGrid& g = r.grid;
  if (r.fields.cp.empty()) throw std::runtime_error("plot: the result has no cp field");
  if (r.fields.cp.size() != size_t(g.nodes()) || g.n_r < 2 || g.n_theta < 4)
    throw std::runtime_error("plot: the cp field does not match the grid");
  const double w = view_half_width(r);
  PolarPatch patch(g, r.fields.cp, 0, ring_at_or_above(g, w * std::sqrt(2.0)));
  auto [lo, hi] = patch.range_in(w);
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  // Colours resolve Cp down to −8 (|u| = 3U); faster flow near the shoulders of a fast-spinning
  // cylinder (Cp down to 1 − (|α| + 2)²) gets the darkest colour, shown as a cap on the colour bar.
  const double clip = -8.0;
  const bool capped = lo < clip && hi > clip;
  const double c0 = capped ? clip : lo;
  const int n_shades = 30;
  std::vector<PLFLT> edges(n_shades + 1);
  for (int k = 0; k <= n_shades; ++k) edges[k] = c0 + (hi - c0) * k / n_shades;
  const double eps = 1e-9 * (hi - lo);  // so that the extreme nodes are filled too
  if (!capped) edges.front() -= eps;
  edges.back() += eps;

  const std::string title = fmt::format("{}: pressure coefficient, {}", case_title(r.c), flow_label(r.c));
  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    sequential_cmap1(pls);
    square_frame(pls, w, 0.84, 0.14);
    pls.psty(0);
    const double cap_colour = 0.0;
    if (capped) {
      pls.shade(patch.z(), patch.nx, patch.ny, nullptr, -w, w, -w, w, lo - eps, clip, 1, cap_colour, 1.0, 0, 0.0,
                0, 0.0, plcallback::fill, false, plcallback::tr2, patch.pltr_data());
      pls.scmap1_range(0.1, 1.0);
    }
    pls.shades(patch.z(), patch.nx, patch.ny, nullptr, -w, w, -w, w, edges.data(), PLINT(edges.size()), 1.0, 0,
               0.0, plcallback::fill, false, plcallback::tr2, patch.pltr_data());
    // Cp = 0: the local speed equals U.
    contour(pls, patch, {0.0}, kBlack, 1.0, 2);
    cylinder(pls, g.a);
    const double dot = w / 70.0;
    for (const auto& s : r.stagnation)
      disc(pls, s.r * std::cos(s.theta), s.r * std::sin(s.theta), dot, kRed, kBlack, 1.0);
    frame_axes(pls, "bcnst", "bcnstv", "x (m)", "y (m)", title);
    text_scale(pls, size, 0.8);
    pls.mtex("b", 5.6, 0.0, 0.0, "dashed: Cp = 0 (|u| = U);  red dots: stagnation points (Cp = 1)");

    // Colour bar to the right of the plot box.
    text_scale(pls, size, 0.85);
    const char* axis_opts[] = {"bcvtm"};
    const char* labels[] = {"Cp"};
    PLINT label_opts[] = {PL_COLORBAR_LABEL_TOP};
    PLFLT ticks[] = {0.0};
    PLINT sub_ticks[] = {0};
    PLINT n_values[] = {PLINT(edges.size())};
    const PLFLT* values[] = {edges.data()};
    PLFLT cw = 0.0, ch = 0.0;
    const PLINT opt = PL_COLORBAR_SHADE | (capped ? PL_COLORBAR_CAP_LOW : 0);
    pls.colorbar(&cw, &ch, opt, PL_POSITION_RIGHT | PL_POSITION_OUTSIDE | PL_POSITION_VIEWPORT, 0.03, 0.0, 0.04,
                 0.80, kWhite, kBlack, 1, cap_colour, 0.0, 0, 0.0, 1, label_opts, labels, 1, axis_opts, ticks,
                 sub_ticks, n_values, values);
    pls.scmap1_range(0.0, 1.0);
  });
}

void plot_surface_cp(const FlowResult& r, const std::string& png, PlotSize size) {
  const Surface& s = r.surface;
  if (s.cp.empty() || r.c.scene.speed <= 0.0)
    throw std::runtime_error("plot: the result has no surface Cp (undefined when U = 0)");
  if (s.theta.size() != s.cp.size()) throw std::runtime_error("plot: surface theta and Cp differ in length");
  const ExactFlow ex = exact_flow(r.c.scene);
  const int n_fine = 721;
  std::vector<PLFLT> tx(n_fine), ty(n_fine);
  for (int k = 0; k < n_fine; ++k) {
    const double th = 2 * M_PI * k / (n_fine - 1);
    tx[k] = th * 180.0 / M_PI;
    ty[k] = ex.cp(ex.a, th);
  }
  // At most ~90 markers: on a fine grid every node would merge into a band hiding the line.
  const size_t n = s.cp.size(), stride = std::max<size_t>(1, (n + 89) / 90);
  std::vector<CurvePoint> pts;
  for (size_t j = 0; j < n; j += stride) pts.push_back({s.theta[j] * 180.0 / M_PI, s.cp[j]});
  pts.push_back({360.0, s.cp[0]});  // θ = 0 again at 360°, like the line
  double lo = *std::min_element(ty.begin(), ty.end()), hi = *std::max_element(ty.begin(), ty.end());
  for (double v : s.cp)
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  const auto [ymin, ymax] = padded(lo, hi, 0.06);
  const std::string title = fmt::format("{}: surface pressure, {}", case_title(r.c), flow_label(r.c));
  const std::string numeric_label =
      stride == 1 ? fmt::format("numeric, n#dθ#u = {}", n) : fmt::format("numeric, n#dθ#u = {} (one node in {})", n, stride);
  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    pls.adv(0);
    pls.vpor(0.12, 0.96, 0.12, 0.91);
    pls.wind(0.0, 360.0, ymin, ymax);
    pls.col0(kLightGrey);
    pls.box("g", 45.0, 0, "g", 0.0, 0);
    pls.col0(kDarkGrey);
    pls.join(0.0, 0.0, 360.0, 0.0);
    pls.col0(kBlack);
    pls.width(1.2);
    pls.box("bcnst", 45.0, 3, "bcnstv", 0.0, 0);
    pls.width(1.0);
    pls.lab("θ (degrees, counter-clockwise from +x: 0° rear, 180° front)", "Cp = (p − p#d∞#u) / (½ρU#u2#d)",
            title.c_str());
    pls.col0(kBlue);
    pls.width(2.0);
    pls.line(n_fine, tx.data(), ty.data());
    pls.width(1.0);
    marker_scale(pls, size);
    markers(pls, pts, "●", kRed);
    text_scale(pls, size, 0.85);
    const std::vector<LegendEntry> legend = {line_entry("exact, 1 − (u#dθ#u/U)#u2#d", kBlue, 1, 2.0),
                                             symbol_entry(numeric_label, kRed, "●", 0.65)};
    std::vector<CurvePoint> occupied;
    for (int k = 0; k < n_fine; ++k) occupied.push_back({tx[k], ty[k]});
    const PLINT corner = pick_corner(occupied, 0.0, 360.0, ymin, ymax, legend_fraction(pls, legend), 0.02, 0.03,
                                     {PL_POSITION_RIGHT | PL_POSITION_BOTTOM, PL_POSITION_LEFT | PL_POSITION_BOTTOM,
                                      PL_POSITION_RIGHT | PL_POSITION_TOP, PL_POSITION_LEFT | PL_POSITION_TOP});
    draw_legend(pls, legend, corner, 0.02, 0.03);
  });
}

void plot_sweep(const std::string& title, const std::vector<CurvePoint>& numeric,
                const std::vector<ReferenceSet>& references, const std::string& png, PlotSize size,
                const std::string& xlabel) {
  // Ranges: every point, the model lines over the α range, and Prandtl's bound on the side of the data.
  double xlo = 0.0, xhi = 0.0, ylo = 0.0, yhi = 0.0;
  bool any = false;
  auto take = [&](const CurvePoint& p) {
    if (!usable(p, false, false)) return;
    if (!any) xlo = xhi = p.x;
    any = true;
    xlo = std::min(xlo, p.x);
    xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y);
    yhi = std::max(yhi, p.y);
  };
  for (const auto& p : numeric) take(p);
  for (const auto& set : references)
    for (const auto& p : set.points) take(p);
  xlo = std::min(xlo, 0.0);
  if (xhi - xlo < 0.5) xhi = xlo + 2.5;
  for (double x : {xlo, xhi}) {
    ylo = std::min({ylo, -2 * M_PI * x, -4 * x});
    yhi = std::max({yhi, -2 * M_PI * x, -4 * x});
  }
  const double bound = 4 * M_PI;
  if (ylo < 0.0) ylo = std::min(ylo, -bound);
  if (yhi > 0.0) yhi = std::max(yhi, bound);
  const auto [x0, x1] = padded(xlo, xhi, 0.03);
  const auto [y0, y1] = padded(ylo, yhi, 0.05);

  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    pls.adv(0);
    pls.vpor(0.12, 0.96, 0.12, 0.91);
    pls.wind(x0, x1, y0, y1);
    pls.col0(kLightGrey);
    pls.box("g", 0.0, 0, "g", 0.0, 0);
    pls.col0(kDarkGrey);
    pls.join(x0, 0.0, x1, 0.0);
    // Prandtl's bound |C_L| = 4π, reached by potential flow at |α| = 2.
    pls.col0(kOrange);
    pls.width(1.8);
    pls.lsty(3);
    for (double b : {-bound, bound})
      if (b >= y0 && b <= y1) pls.join(x0, b, x1, b);
    for (double al : {-2.0, 2.0})
      if (al >= x0 && al <= x1) pls.join(al, y0, al, y1);
    pls.lsty(1);
    pls.width(1.0);
    text_scale(pls, size, 0.85);
    pls.col0(kOrange);
    for (double al : {-2.0, 2.0})
      if (al >= x0 && al <= x1) {
        const std::string t = al > 0 ? "α = 2" : "α = −2";
        const double b = al > 0 ? -bound : bound;  // where Kutta–Joukowski meets the bound
        pls.ptex(al + 0.012 * (x1 - x0), b + 0.02 * (y1 - y0), 1.0, 0.0, 0.0, t.c_str());
      }
    // Kutta–Joukowski and the seed's estimate.
    const PLFLT lx[2] = {x0, x1};
    PLFLT ly[2] = {-2 * M_PI * x0, -2 * M_PI * x1};
    pls.col0(kBlue);
    pls.width(2.0);
    pls.line(2, lx, ly);
    ly[0] = -4 * x0;
    ly[1] = -4 * x1;
    pls.col0(kGreen);
    pls.lsty(2);
    pls.line(2, lx, ly);
    pls.lsty(1);
    pls.width(1.0);
    text_scale(pls, size);
    frame_axes(pls, "bcnst", "bcnstv", xlabel.empty() ? std::string("spin ratio α = aω/U") : plain(xlabel),
               "lift coefficient C#dL#u", plain(title));

    std::vector<LegendEntry> legend;
    legend.push_back(line_entry("Kutta–Joukowski, C#dL#u = −2πα", kBlue, 1, 2.0));
    legend.push_back(line_entry("seed estimate, C#dL#u = −4α", kGreen, 2, 2.0));
    legend.push_back(line_entry("Prandtl's bound, |C#dL#u| = 4π", kOrange, 3, 1.8));
    // Reference sets first, numeric on top.
    for (size_t k = 0; k < references.size(); ++k) {
      const PLINT pen = kSeriesPens[(k + 2) % std::size(kSeriesPens)];
      const char* glyph = kMarkers[(k + 1) % std::size(kMarkers)];
      marker_scale(pls, size, 1.2);
      markers(pls, references[k].points, glyph, pen);
      legend.push_back(symbol_entry(plain(references[k].label), pen, glyph, 0.7));
    }
    marker_scale(pls, size);
    markers(pls, numeric, "●", kRed);
    if (!numeric.empty()) legend.push_back(symbol_entry("numeric (potential flow)", kRed, "●", 0.6));
    text_scale(pls, size, 0.8);
    std::vector<CurvePoint> occupied;
    for (const auto& p : numeric) occupied.push_back(p);
    for (const auto& set : references) occupied.insert(occupied.end(), set.points.begin(), set.points.end());
    sample_segment(occupied, x0, -2 * M_PI * x0, x1, -2 * M_PI * x1);
    sample_segment(occupied, x0, -4 * x0, x1, -4 * x1);
    // C_L falls with α: below the lines on the left is usually clear.
    const PLINT corner = pick_corner(occupied, x0, x1, y0, y1, legend_fraction(pls, legend), 0.02, 0.03,
                                     {PL_POSITION_LEFT | PL_POSITION_BOTTOM, PL_POSITION_RIGHT | PL_POSITION_TOP,
                                      PL_POSITION_RIGHT | PL_POSITION_BOTTOM, PL_POSITION_LEFT | PL_POSITION_TOP});
    draw_legend(pls, legend, corner, 0.02, 0.03);
  });
}

void plot_loglog(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                 const std::vector<Series>& series, const std::string& png, PlotSize size) {
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const auto& s : series)
    for (const auto& p : s.points)
      if (usable(p, true, true)) {
        xlo = std::min(xlo, std::log10(p.x));
        xhi = std::max(xhi, std::log10(p.x));
        ylo = std::min(ylo, std::log10(p.y));
        yhi = std::max(yhi, std::log10(p.y));
      }
  if (!(xhi >= xlo)) throw std::runtime_error("plot: nothing to draw in " + png + " (no positive data)");
  // At least one decade on each axis, padded.
  auto widen = [](double& lo, double& hi) {
    if (hi - lo < 1.0) {
      const double mid = 0.5 * (lo + hi);
      lo = mid - 0.5;
      hi = mid + 0.5;
    }
    const double d = 0.05 * (hi - lo);
    lo -= d;
    hi += d;
  };
  widen(xlo, xhi);
  widen(ylo, yhi);

  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    pls.adv(0);
    pls.vpor(0.13, 0.96, 0.12, 0.91);
    pls.wind(xlo, xhi, ylo, yhi);
    pls.col0(kLightGrey);
    pls.box("gl", 0.0, 0, "gl", 0.0, 0);
    frame_axes(pls, "bcnstl", "bcnstvl", plain(xlabel), plain(ylabel), plain(title));
    std::vector<LegendEntry> legend;
    for (size_t k = 0; k < series.size(); ++k) {
      const PLINT pen = kSeriesPens[k % std::size(kSeriesPens)];
      const char* glyph = kMarkers[k % std::size(kMarkers)];
      std::vector<PLFLT> x, y;
      for (const auto& p : series[k].points)
        if (usable(p, true, true)) {
          x.push_back(std::log10(p.x));
          y.push_back(std::log10(p.y));
        }
      pls.col0(pen);
      pls.width(1.6);
      if (x.size() > 1) pls.line(PLINT(x.size()), x.data(), y.data());
      pls.width(1.0);
      marker_scale(pls, size);
      markers(pls, series[k].points, glyph, pen, true, true);
      LegendEntry e = line_entry(plain(series[k].label), pen, 1, 1.6);
      e.symbol = glyph;
      e.symbol_scale = 0.6;
      legend.push_back(e);
    }
    text_scale(pls, size, 0.8);
    std::vector<CurvePoint> occupied;
    for (const auto& s : series) {
      bool first = true;
      CurvePoint prev{0.0, 0.0};
      for (const auto& p : s.points)
        if (usable(p, true, true)) {
          const CurvePoint q{std::log10(p.x), std::log10(p.y)};
          if (!first) sample_segment(occupied, prev.x, prev.y, q.x, q.y, 30);
          occupied.push_back(q);
          prev = q;
          first = false;
        }
    }
    const PLINT corner = pick_corner(occupied, xlo, xhi, ylo, yhi, legend_fraction(pls, legend), 0.02, 0.02,
                                     {PL_POSITION_RIGHT | PL_POSITION_TOP, PL_POSITION_LEFT | PL_POSITION_BOTTOM,
                                      PL_POSITION_RIGHT | PL_POSITION_BOTTOM, PL_POSITION_LEFT | PL_POSITION_TOP});
    draw_legend(pls, legend, corner, 0.02, 0.02);
  });
}

}  // namespace magnus
