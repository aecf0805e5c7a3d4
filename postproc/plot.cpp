#include "postproc/plot.hpp"

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
#include <mutex>
#include <stdexcept>

#include "postproc/exact.hpp"

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

  // The temporary name, in the target's directory so that rename() is atomic.
  const size_t slash = png.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : png.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? png : png.substr(slash + 1);
  if (base.empty()) fail(png, "the name is a directory");
  std::string tmp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    tmp = dir + "." + base + ".tmp-" + std::to_string(::getpid()) + (attempt ? "-" + std::to_string(attempt) : "");
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(png, std::strerror(errno));
  }
  if (fd < 0) fail(png, "no free temporary name");
  // PLplot takes the FILE* over (and closes it) once plinit has run.
  FILE* file = ::fdopen(fd, "wb");
  if (!file) {
    const int e = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(png, std::strerror(e));
  }
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
    if (std::rename(tmp.c_str(), png.c_str()) != 0) fail(png, std::strerror(errno));
  } catch (const std::exception& e) {
    if (file_owned) std::fclose(file);
    ::unlink(tmp.c_str());
    const std::string what = e.what();
    if (what.rfind("plot: ", 0) == 0) throw;
    fail(png, what);
  }
}

// ---------------------------------------------------------------------------------------------
// Drawing helpers.

/// Character height scaled with the image so that text stays legible at any size.
void text_scale(plstream& pls, PlotSize size, double factor = 1.0) {
  const double s = std::max(0.6, std::min(size.width, size.height) / 800.0);
  pls.schr(0.0, 1.25 * s * factor);
}

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

LegendEntry symbol_entry(std::string text, PLINT pen, const char* glyph, double scale) {
  LegendEntry e;
  e.text = std::move(text);
  e.pen = pen;
  e.symbol = glyph;
  e.symbol_scale = scale;
  return e;
}

void draw_legend(plstream& pls, const std::vector<LegendEntry>& entries, PLINT position, double x = 0.02,
                 double y = 0.02) {
  if (entries.empty()) return;
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
    symbol_scales[k] = e.symbol_scale;
    symbols[k] = e.symbol.empty() ? "" : e.symbol.c_str();
  }
  PLFLT w = 0.0, h = 0.0;
  pls.legend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, position | PL_POSITION_INSIDE, x, y, 0.08,
             kWhite, kBlack, 1, 0, 0, n, opt.data(), 1.0, 0.9, 2.0, 0.0, text_colors.data(), text.data(),
             box_colors.data(), box_patterns.data(), box_scales.data(), box_line_widths.data(),
             line_colors.data(), line_styles.data(), line_widths.data(), symbol_colors.data(),
             symbol_scales.data(), symbol_numbers.data(), symbols.data());
}

/// Filled circle (polygon) of radius rad at (x, y) in world coordinates, with an outline.
void disc(plstream& pls, double x, double y, double rad, PLINT fill_pen, PLINT edge_pen, double edge_width) {
  const int n = 72;
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

/// Markers at the points (UTF-8 glyph, centred).
void markers(plstream& pls, const std::vector<CurvePoint>& pts, const char* glyph, PLINT pen, bool logx = false,
             bool logy = false) {
  std::vector<PLFLT> x, y;
  for (const auto& p : pts) {
    if ((logx && !(p.x > 0)) || (logy && !(p.y > 0)) || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    x.push_back(logx ? std::log10(p.x) : p.x);
    y.push_back(logy ? std::log10(p.y) : p.y);
  }
  if (x.empty()) return;
  pls.col0(pen);
  pls.string(PLINT(x.size()), x.data(), y.data(), glyph);
}

/// A field on the polar grid as (n_r', n_θ + 1) arrays: column n_θ repeats column 0 (θ = 2π) so
/// that contours close over the seam; only rings up to the first one beyond r_max are kept.
struct PolarPatch {
  PLINT nx = 0, ny = 0;
  std::vector<PLFLT> xs, ys, zs;
  std::vector<PLFLT*> xrow, yrow, zrow;
  PLcGrid2 grid{};

  PolarPatch(const PolarGrid& g, const std::vector<double>& f, double r_max) {
    const int nt = g.n_theta;
    int n_r = 1;
    while (n_r < g.n_r && g.r[n_r - 1] < r_max) ++n_r;
    nx = n_r;
    ny = nt + 1;
    xs.resize(size_t(nx) * ny);
    ys.resize(xs.size());
    zs.resize(xs.size());
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j <= nt; ++j) {
        const int jj = j % nt;
        const size_t q = size_t(i) * ny + j;
        xs[q] = g.r[i] * std::cos(g.theta[jj]);
        ys[q] = g.r[i] * std::sin(g.theta[jj]);
        zs[q] = f[size_t(i) * nt + jj];
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

/// Half-width of the square view window: min(R, 4a).
double view_half_width(const FlowResult& r) { return std::min(r.grid.outer_radius(), 4.0 * r.grid.a); }

/// "α = 1.5" (or the circulation when it is given, or "U = 0").
std::string flow_label(const Case& c) {
  if (c.speed <= 0.0) return fmt::format("U = 0, Γ = {} m²/s", num(c.circulation()));
  std::string s = fmt::format("α = {}", num(c.spin_ratio(), 4));
  if (c.circulation_given) s += fmt::format(", Γ = {} m²/s", num(c.circulation()));
  return s;
}

std::string case_title(const Case& c) { return plain(c.title.empty() ? std::string("Spinning cylinder") : c.title); }

/// Square plot box over |x|, |y| ≤ w with equal scales, inside the given fraction of the page.
void polar_frame(plstream& pls, double w, double right = 0.95) {
  pls.adv(0);
  pls.vpas(0.10, right, 0.10, 0.90, 1.0);
  pls.wind(-w, w, -w, w);
}

void polar_axes(plstream& pls, const std::string& title) {
  pls.col0(kBlack);
  pls.width(1.2);
  pls.box("bcnst", 0.0, 0, "bcnstv", 0.0, 0);
  pls.width(1.0);
  pls.lab("x (m)", "y (m)", title.c_str());
}

/// The body: a grey disc with a black rim.
void cylinder(plstream& pls, double a) { disc(pls, 0.0, 0.0, a, kGrey, kBlack, 2.0); }

/// ψ at (r, θ) from the grid field: periodic cubic in θ on the two rings around r, linear in r.
double psi_at(const PolarGrid& g, const std::vector<double>& psi, double r, double theta) {
  int i = 0;
  while (i + 2 < g.n_r && g.r[i + 1] < r) ++i;
  const int nt = g.n_theta;
  std::vector<double> a(psi.begin() + long(i) * nt, psi.begin() + long(i + 1) * nt);
  std::vector<double> b(psi.begin() + long(i + 1) * nt, psi.begin() + long(i + 2) * nt);
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
  pls.cont(p.z(), p.nx, p.ny, 1, p.nx, 1, p.ny, levels.data(), PLINT(levels.size()), plcallback::tr2,
           p.pltr_data());
  pls.lsty(1);
  pls.width(1.0);
}

/// cmap1: a perceptually ordered dark-blue → teal → yellow ramp (viridis-like).
void sequential_cmap1(plstream& pls) {
  const PLFLT pos[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  const PLFLT r[] = {0.267, 0.230, 0.128, 0.369, 0.993};
  const PLFLT g[] = {0.005, 0.322, 0.567, 0.789, 0.906};
  const PLFLT b[] = {0.329, 0.546, 0.551, 0.383, 0.144};
  pls.scmap1n(256);
  pls.scmap1l(true, 5, pos, r, g, b, nullptr);
}

/// Axis range [lo, hi] padded by a fraction, never empty.
std::pair<double, double> padded(double lo, double hi, double frac = 0.05) {
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
  PolarPatch patch(g, psi, w * std::sqrt(2.0));

  // Levels: evenly spaced multiples of a round step, so that ψ = 0 (body and dividing streamline) is one.
  const auto [lo, hi] = patch.range_in(w);
  const double step = nice_step((hi - lo) / 24.0);
  std::vector<PLFLT> regular;
  if (hi > lo)
    for (long k = long(std::ceil(lo / step)); k <= long(std::floor(hi / step)); ++k)
      if (k != 0) regular.push_back(k * step);

  // A free stagnation point (|α| > 2): the separatrix through it, and closed streamlines
  // between it and the body, which the regular step is too coarse to show.
  std::vector<PLFLT> dividing = {0.0}, closed;
  const StagnationPoint* free_point = nullptr;
  for (const auto& s : r.stagnation)
    if (!s.on_surface) free_point = &s;
  if (free_point) {
    const double ps = psi_at(g, psi, free_point->r, free_point->theta);
    dividing.push_back(ps);
    for (double f : {0.2, 0.4, 0.6, 0.8}) closed.push_back(f * ps);
    // Regular levels inside the closed region would crowd it: those are covered by `closed`.
    regular.erase(std::remove_if(regular.begin(), regular.end(),
                                 [&](double v) { return (v - 0.0) * (v - ps) < 0.0; }),
                  regular.end());
  }

  const std::string title = fmt::format("{}: streamlines, {}", case_title(r.c), flow_label(r.c));
  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    polar_frame(pls, w);
    contour(pls, patch, regular, kBlue, 1.2);
    contour(pls, patch, closed, kPurple, 1.4);
    contour(pls, patch, dividing, kBlack, 2.4);
    cylinder(pls, a);
    const double dot = w / 55.0;
    for (const auto& s : r.stagnation_exact)
      disc(pls, s.r * std::cos(s.theta), s.r * std::sin(s.theta), 1.9 * dot, -1, kBlack, 1.5);
    for (const auto& s : r.stagnation)
      disc(pls, s.r * std::cos(s.theta), s.r * std::sin(s.theta), dot, kRed, kBlack, 1.0);
    polar_axes(pls, title);

    std::vector<LegendEntry> legend;
    legend.push_back(line_entry(fmt::format("ψ contours, step {} m²/s", num(step)), kBlue, 1, 1.2));
    legend.push_back(line_entry(free_point ? "separatrix (through the free stagnation point)" : "dividing streamline ψ = 0",
                                kBlack, 1, 2.4));
    if (free_point) legend.push_back(line_entry("closed streamlines", kPurple, 1, 1.4));
    legend.push_back(symbol_entry("stagnation points: numeric", kRed, "●", 1.0));
    legend.push_back(symbol_entry("exact", kBlack, "○", 1.3));
    text_scale(pls, size, 0.8);
    draw_legend(pls, legend, PL_POSITION_LEFT | PL_POSITION_BOTTOM, 0.01, 0.01);
  });
}

void plot_cp_field(const FlowResult& r, const std::string& png, PlotSize size) {
  const PolarGrid& g = r.grid;
  if (r.fields.cp.empty()) throw std::runtime_error("plot: the result has no cp field");
  if (r.fields.cp.size() != size_t(g.nodes()) || g.n_r < 2 || g.n_theta < 4)
    throw std::runtime_error("plot: the cp field does not match the grid");
  const double w = view_half_width(r);
  PolarPatch patch(g, r.fields.cp, w * std::sqrt(2.0));
  auto [lo, hi] = patch.range_in(w);
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  const int n_shades = 32;
  std::vector<PLFLT> edges(n_shades + 1);
  for (int k = 0; k <= n_shades; ++k) edges[k] = lo + (hi - lo) * k / n_shades;
  // The outermost edges are widened a little so that the extreme nodes are filled too.
  const double eps = 1e-9 * (hi - lo);
  edges.front() -= eps;
  edges.back() += eps;

  const std::string title = fmt::format("{}: pressure coefficient Cp, {}", case_title(r.c), flow_label(r.c));
  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    sequential_cmap1(pls);
    polar_frame(pls, w, 0.84);
    pls.psty(0);
    pls.shades(patch.z(), patch.nx, patch.ny, nullptr, -w, w, -w, w, edges.data(), PLINT(edges.size()), 1.0, 0,
               0.0, plcallback::fill, false, plcallback::tr2, patch.pltr_data());
    // Cp = 0 (local speed = U) as a thin reference line.
    contour(pls, patch, {0.0}, kWhite, 1.0, 2);
    cylinder(pls, r.grid.a);
    const double dot = w / 70.0;
    for (const auto& s : r.stagnation)
      disc(pls, s.r * std::cos(s.theta), s.r * std::sin(s.theta), dot, kRed, kBlack, 1.0);
    polar_axes(pls, title);

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
    pls.colorbar(&cw, &ch, PL_COLORBAR_SHADE, PL_POSITION_RIGHT | PL_POSITION_OUTSIDE | PL_POSITION_VIEWPORT,
                 0.03, 0.0, 0.04, 0.85, kWhite, kBlack, 1, 0.0, 0.0, 0, 0.0, 1, label_opts, labels, 1, axis_opts,
                 ticks, sub_ticks, n_values, values);
  });
}

void plot_surface_cp(const FlowResult& r, const std::string& png, PlotSize size) {
  const Surface& s = r.surface;
  if (s.cp.empty() || r.c.speed <= 0.0)
    throw std::runtime_error("plot: the result has no surface Cp (undefined when U = 0)");
  if (s.theta.size() != s.cp.size()) throw std::runtime_error("plot: surface theta and Cp differ in length");
  const ExactFlow ex = exact_flow(r.c);
  const int n_fine = 721;
  std::vector<PLFLT> tx(n_fine), ty(n_fine);
  for (int k = 0; k < n_fine; ++k) {
    const double th = 2 * M_PI * k / (n_fine - 1);
    tx[k] = th * 180.0 / M_PI;
    ty[k] = ex.cp(ex.a, th);
  }
  std::vector<CurvePoint> pts;
  for (size_t j = 0; j < s.cp.size(); ++j) pts.push_back({s.theta[j] * 180.0 / M_PI, s.cp[j]});
  // Repeat θ = 0 at 360° so the points span the whole axis like the line does.
  if (!pts.empty()) pts.push_back({360.0, s.cp[0]});
  double lo = *std::min_element(ty.begin(), ty.end()), hi = *std::max_element(ty.begin(), ty.end());
  for (const auto& p : pts)
    if (std::isfinite(p.y)) {
      lo = std::min(lo, p.y);
      hi = std::max(hi, p.y);
    }
  const auto [ymin, ymax] = padded(lo, hi, 0.06);
  const std::string title = fmt::format("{}: surface pressure, {}", case_title(r.c), flow_label(r.c));
  const std::string numeric_label = fmt::format("numeric (n#dθ#u = {})", r.grid.n_theta);
  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    pls.adv(0);
    pls.vpor(0.11, 0.95, 0.11, 0.90);
    pls.wind(0.0, 360.0, ymin, ymax);
    pls.col0(kLightGrey);
    pls.box("g", 45.0, 0, "g", 0.0, 0);
    pls.col0(kDarkGrey);
    pls.lsty(2);
    pls.join(0.0, 0.0, 360.0, 0.0);
    pls.lsty(1);
    pls.col0(kBlack);
    pls.width(1.2);
    pls.box("bcnst", 45.0, 3, "bcnstv", 0.0, 0);
    pls.width(1.0);
    pls.lab("θ (degrees, counter-clockwise from +x: 0° rear, 180° front)", "Cp", title.c_str());
    pls.col0(kBlue);
    pls.width(2.0);
    pls.line(n_fine, tx.data(), ty.data());
    pls.width(1.0);
    markers(pls, pts, "●", kRed);
    text_scale(pls, size, 0.85);
    draw_legend(pls,
                {line_entry("exact 1 − (u#dθ#u/U)#u2#d", kBlue, 1, 2.0),
                 symbol_entry(numeric_label, kRed, "●", 1.0)},
                PL_POSITION_RIGHT | PL_POSITION_BOTTOM, 0.02, 0.03);
  });
}

void plot_sweep(const std::string& title, const std::vector<CurvePoint>& numeric,
                const std::vector<ReferenceSet>& references, const std::string& png, PlotSize size) {
  // Ranges: every point, the model lines over the α range, and Prandtl's bound on the side of the data.
  double xlo = 0.0, xhi = 2.5, ylo = 0.0, yhi = 0.0;
  bool any = false;
  auto take = [&](const CurvePoint& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    if (!any) xlo = xhi = p.x;
    any = true;
    xlo = std::min(xlo, p.x);
    xhi = std::max(xhi, p.x);
  };
  for (const auto& p : numeric) take(p);
  for (const auto& set : references)
    for (const auto& p : set.points) take(p);
  if (!any || xhi - xlo < 1e-12) {
    xlo = std::min(xlo, 0.0);
    xhi = std::max(xhi, 2.5);
  }
  xlo = std::min(xlo, 0.0);
  for (double x : {xlo, xhi}) {
    ylo = std::min({ylo, -2 * M_PI * x, -4 * x});
    yhi = std::max({yhi, -2 * M_PI * x, -4 * x});
  }
  auto yr = [&](const CurvePoint& p) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) {
      ylo = std::min(ylo, p.y);
      yhi = std::max(yhi, p.y);
    }
  };
  for (const auto& p : numeric) yr(p);
  for (const auto& set : references)
    for (const auto& p : set.points) yr(p);
  const double bound = 4 * M_PI;
  if (ylo < 0.0) ylo = std::min(ylo, -bound);
  if (yhi > 0.0) yhi = std::max(yhi, bound);
  const auto [x0, x1] = padded(xlo, xhi, 0.03);
  const auto [y0, y1] = padded(ylo, yhi, 0.06);

  render_png(png, size, [&](plstream& pls) {
    text_scale(pls, size);
    pls.adv(0);
    pls.vpor(0.11, 0.95, 0.11, 0.90);
    pls.wind(x0, x1, y0, y1);
    pls.col0(kLightGrey);
    pls.box("g", 0.0, 0, "g", 0.0, 0);
    pls.col0(kDarkGrey);
    pls.join(x0, 0.0, x1, 0.0);
    // Prandtl's bound |C_L| = 4π and the spin ratio α = ±2 where it is reached.
    pls.col0(kOrange);
    pls.width(1.8);
    pls.lsty(3);
    for (double b : {-bound, bound})
      if (b >= y0 && b <= y1) pls.join(x0, b, x1, b);
    for (double al : {-2.0, 2.0})
      if (al >= x0 && al <= x1) pls.join(al, y0, al, y1);
    pls.lsty(1);
    for (double al : {-2.0, 2.0})
      if (al >= x0 && al <= x1) pls.ptex(al + 0.01 * (x1 - x0), y0 + 0.04 * (y1 - y0), 0.0, 1.0, 0.0, "α = 2");
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
    pls.col0(kBlack);
    pls.width(1.2);
    pls.box("bcnst", 0.0, 0, "bcnstv", 0.0, 0);
    pls.width(1.0);
    pls.lab("spin ratio α = aω/U", "lift coefficient C#dL#u", plain(title).c_str());

    std::vector<LegendEntry> legend;
    legend.push_back(line_entry("Kutta–Joukowski  C#dL#u = −2πα", kBlue, 1, 2.0));
    legend.push_back(line_entry("seed estimate  C#dL#u = −4α", kGreen, 2, 2.0));
    legend.push_back(line_entry("Prandtl's bound  |C#dL#u| = 4π", kOrange, 3, 1.8));
    // Reference sets first, numeric on top.
    std::vector<std::string> ref_labels;
    for (size_t k = 0; k < references.size(); ++k) {
      const PLINT pen = kSeriesPens[(k + 2) % std::size(kSeriesPens)];
      const char* glyph = kMarkers[(k + 1) % std::size(kMarkers)];
      text_scale(pls, size, 1.1);
      markers(pls, references[k].points, glyph, pen);
      legend.push_back(symbol_entry(plain(references[k].label), pen, glyph, 1.1));
    }
    text_scale(pls, size, 1.0);
    markers(pls, numeric, "●", kRed);
    if (!numeric.empty()) legend.push_back(symbol_entry("numeric (potential flow)", kRed, "●", 1.0));
    text_scale(pls, size, 0.8);
    // C_L falls with α: the top right is always clear of the lines.
    draw_legend(pls, legend, PL_POSITION_RIGHT | PL_POSITION_TOP, 0.02, 0.02);
  });
}

void plot_loglog(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                 const std::vector<Series>& series, const std::string& png, PlotSize size) {
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const auto& s : series)
    for (const auto& p : s.points)
      if (p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y)) {
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
    pls.vpor(0.12, 0.95, 0.11, 0.90);
    pls.wind(xlo, xhi, ylo, yhi);
    pls.col0(kLightGrey);
    pls.box("ghl", 0.0, 0, "ghl", 0.0, 0);
    pls.col0(kBlack);
    pls.width(1.2);
    pls.box("bcnstl", 0.0, 0, "bcnstvl", 0.0, 0);
    pls.width(1.0);
    pls.lab(plain(xlabel).c_str(), plain(ylabel).c_str(), plain(title).c_str());
    std::vector<LegendEntry> legend;
    for (size_t k = 0; k < series.size(); ++k) {
      const PLINT pen = kSeriesPens[k % std::size(kSeriesPens)];
      const char* glyph = kMarkers[k % std::size(kMarkers)];
      std::vector<PLFLT> x, y;
      for (const auto& p : series[k].points)
        if (p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y)) {
          x.push_back(std::log10(p.x));
          y.push_back(std::log10(p.y));
        }
      pls.col0(pen);
      pls.width(1.6);
      if (x.size() > 1) pls.line(PLINT(x.size()), x.data(), y.data());
      pls.width(1.0);
      markers(pls, series[k].points, glyph, pen, true, true);
      LegendEntry e = line_entry(plain(series[k].label), pen, 1, 1.6);
      e.symbol = glyph;
      legend.push_back(e);
    }
    text_scale(pls, size, 0.8);
    draw_legend(pls, legend, PL_POSITION_RIGHT | PL_POSITION_TOP, 0.02, 0.02);
  });
}

}  // namespace magnus
