// The plots are checked on their pixels (decoded with libpng): where the data land, which contour
// levels are drawn, the colour bar's range, text kept off the image's edges. Each check is a function
// that a blank or shifted image fails (asserted too, so that no check passes vacuously).
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/exact.hpp"
#include "plot/curves.hpp"
#include "plot/field_plots.hpp"
#include "plot/figures.hpp"
#include "plot/png_image.hpp"
#include "postproc/potential/pipeline.hpp"
#include "support.hpp"

using namespace magnus;
using test::Image;

namespace {

/// The spin-ratio-α case (radius a, U = 10 m/s) on an n_θ grid (n_r: square cells, or as given).
FlowResult small_result(double alpha, double a = 0.1, int n_theta = 64, int n_r = 0) {
  Case c;
  c.title = "Plot_test";
  c.scene.radius = a;
  c.scene.speed = 10.0;
  c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  c.grid.n_theta = n_theta;
  c.grid.n_r = n_r;
  return run_case(c);
}

/// Entries of a directory other than . and .. (hidden ones included).
std::vector<std::string> dir_entries(const std::string& dir) {
  std::vector<std::string> out;
  FILE* p = ::popen(("ls -A '" + dir + "'").c_str(), "r");
  if (!p) return out;
  char line[4096];
  while (std::fgets(line, sizeof line, p)) {
    std::string s(line);
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    if (!s.empty()) out.push_back(s);
  }
  ::pclose(p);
  return out;
}

/// A marker of the predicate's colour within 4 px of each point (axis units) of the frame.
bool marks_at(const Image& img, const PlotFrame& f, const std::vector<CurvePoint>& pts,
              bool (Image::*pred)(int, int) const) {
  for (const auto& p : pts)
    if (!img.near(f.px(p.x), f.py(p.y), 4, [&](int x, int y) { return (img.*pred)(x, y); })) return false;
  return !pts.empty();
}

/// The box's frame lines are where the frame says: dark pixels along ≥ 90% of each side.
bool frame_drawn(const Image& img, const PlotFrame& f) {
  int hits = 0, n = 0;
  for (double t = 0.05; t <= 0.95; t += 0.01) {
    const double x = f.box.x0 + t * (f.box.x1 - f.box.x0), y = f.box.y0 + t * (f.box.y1 - f.box.y0);
    auto dk = [&](int u, int v) { return img.dark(u, v); };
    hits += img.near(x, f.box.y0, 2, dk) + img.near(x, f.box.y1, 2, dk) + img.near(f.box.x0, y, 2, dk) +
            img.near(f.box.x1, y, 2, dk);
    n += 4;
  }
  return hits >= 0.9 * n;
}

/// Nothing is drawn within `margin` pixels of the image's edges (text is not cut off).
bool clear_edges(const Image& img, int margin = 2) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if ((x < margin || y < margin || x >= img.width - margin || y >= img.height - margin) &&
          img.inked(x, y))
        return false;
  return true;
}

/// Δψ of the regular levels: the gap between the first two levels (the regular ones come first).
double level_step(const PlotFrame& f) {
  return f.levels.size() > 1 ? std::fabs(f.levels[1] - f.levels[0]) : 1.0;
}

/// The fraction of blue contour pixels (away from the body) that lie on one of the frame's levels of
/// psi(r, θ), within 2 pixels times |∇ψ|; the count of pixels is returned too.
template <class Psi>
std::pair<double, int> contours_on(const Image& img, const PlotFrame& f, double a, Psi psi) {
  const double step = level_step(f);
  const double per_px = (f.x1 - f.x0) / (f.box.x1 - f.box.x0) * a;  // m per pixel
  int good = 0, n = 0;
  for (int y = int(f.box.y0) + 3; y < int(f.box.y1) - 3; ++y)
    for (int x = int(f.box.x0) + 3; x < int(f.box.x1) - 3; ++x) {
      if (!img.blue(x, y)) continue;
      const double X = (f.x0 + (x + 0.5 - f.box.x0) / (f.box.x1 - f.box.x0) * (f.x1 - f.x0)) * a;
      const double Y = (f.y1 - (y + 0.5 - f.box.y0) / (f.box.y1 - f.box.y0) * (f.y1 - f.y0)) * a;
      const double r = std::hypot(X, Y), th = std::atan2(Y, X);
      if (r < 1.1 * a) continue;
      const double p = psi(r, th), h = 0.5 * per_px;
      const double gx = (psi(std::hypot(X + h, Y), std::atan2(Y, X + h)) -
                         psi(std::hypot(X - h, Y), std::atan2(Y, X - h))) /
                        (2 * h);
      const double gy = (psi(std::hypot(X, Y + h), std::atan2(Y + h, X)) -
                         psi(std::hypot(X, Y - h), std::atan2(Y - h, X))) /
                        (2 * h);
      double d = 1e300;
      for (double level : f.levels) d = std::min(d, std::fabs(p - level));
      ++n;
      if (d <= 2.0 * per_px * std::hypot(gx, gy) + 0.02 * step) ++good;
    }
  return {n ? double(good) / n : 0.0, n};
}

std::pair<double, int> contours_match(const Image& img, const PlotFrame& f, const ExactFlow& ex) {
  return contours_on(img, f, ex.a, [&](double r, double th) { return ex.psi(r, th); });
}

/// Height in pixels of the lowest band of dark rows below the box, across the middle third of the box
/// (the x-axis label, or the footnote under it).
int lowest_text_band(const Image& img, const PlotFrame& f) {
  int bottom = -1, top = -1;
  const int below = f.legend.empty() || f.legend.y0 < f.box.y1 ? img.height : int(f.legend.y0) - 1;
  for (int y = below - 1; y > int(f.box.y1) + 2; --y) {
    bool any = false;
    for (int x = int(f.box.x0 + (f.box.x1 - f.box.x0) / 3); x < int(f.box.x1 - (f.box.x1 - f.box.x0) / 3);
         ++x)
      any = any || img.dark(x, y);
    if (any && bottom < 0) bottom = y;
    if (any) top = y;
    if (!any && bottom >= 0) break;
  }
  return bottom < 0 ? 0 : bottom - top + 1;
}

}  // namespace

TEST_CASE("streamlines: markers on the exact stagnation points, contours on the exact ψ levels", "[plot]") {
  const std::string dir = test::temp_dir("plot-stream");
  for (double alpha : {1.0, 3.0}) {
    CAPTURE(alpha);
    const FlowResult r = small_result(alpha);
    const std::string png = dir + "/s.png";
    const PlotFrame f = plot_streamlines(streamline_picture(r), png, {900, 700});
    const Image img = test::read_png(png);
    REQUIRE(img.width == 900);
    // Axes in x/a over min(R, 4a): a centred square box.
    CHECK(f.x1 == Approx(4.0));
    CHECK(std::fabs(0.5 * (f.box.x0 + f.box.x1) - 450.0) <= 2.0);
    CHECK(std::fabs((f.box.x1 - f.box.x0) - (f.box.y1 - f.box.y0)) <= 2.0);
    CHECK(frame_drawn(img, f));
    // The sign convention: CCW spin, flow towards +x: sinθ_s = α/2 on the body (30° and 150° at α = 1), or
    // one free point on the +y axis at r_s = a(α + √(α² − 4))/2.
    std::vector<CurvePoint> expect, mirror;
    if (alpha < 2) {
      const double th = std::asin(alpha / 2);
      expect = {{std::cos(th), std::sin(th)}, {-std::cos(th), std::sin(th)}};
      mirror = {{std::cos(th), -std::sin(th)}};
    } else {
      const double rs = (alpha + std::sqrt(alpha * alpha - 4)) / 2;
      expect = {{0.0, rs}};
      mirror = {{0.0, -rs}};
    }
    CHECK(marks_at(img, f, expect, &Image::red));
    CHECK(marks_at(img, f, expect, &Image::dark));  // the exact point's ring
    CHECK_FALSE(marks_at(img, f, mirror, &Image::red));
    // Contour levels: multiples of Δψ, the pixels where ψ says.
    const auto [good, n] = contours_match(img, f, exact_flow(r.c.scene));
    CHECK(n > 3000);
    CHECK(good > 0.95);
    CHECK(clear_edges(img));
    // Negative controls: a shifted or a blank image fails the same checks.
    const Image moved = img.shifted(12, 9), blank = img.blank();
    CHECK_FALSE(marks_at(moved, f, expect, &Image::red));
    const auto shifted_match = contours_match(img.shifted(0, 5), f, exact_flow(r.c.scene));
    CHECK(shifted_match.first < 0.8);
    CHECK_FALSE(frame_drawn(moved, f));
    CHECK_FALSE(frame_drawn(blank, f));
    CHECK(contours_match(blank, f, exact_flow(r.c.scene)).second == 0);
    CHECK_FALSE(clear_edges(img.shifted(-img.width / 2, 0)));
  }
  for (const auto& e : dir_entries(dir)) CHECK(e.find(".tmp-") == std::string::npos);
}

TEST_CASE("a coarse grid is drawn from its interpolant: smooth contours on the exact levels", "[plot]") {
  // 12 × 9: the contours of the raw grid would be polygons of 30° chords.
  const FlowResult r = small_result(1.0, 0.1, 12, 9);
  const std::string dir = test::temp_dir("plot-coarse");
  const PlotFrame f = plot_streamlines(streamline_picture(r), dir + "/c.png", {900, 700});
  const Image img = test::read_png(dir + "/c.png");
  // The contours follow the interpolant of the grid's ψ (the drawing is smooth between the nodes, where
  // 30° chords would stray by up to 0.14 r), and a shifted drawing does not.
  PolarField pf{r.grid.r, r.grid.theta, r.fields.psi};
  auto interp = [&](double rr, double th) { return polar_value(pf, rr, th); };
  const auto [good, n] = contours_on(img, f, r.grid.a, interp);
  CHECK(n > 3000);
  CHECK(good > 0.95);
  CHECK(contours_on(img.shifted(0, 5), f, r.grid.a, interp).first < 0.8);
  // The interpolant reproduces the grid's values at its nodes and a smooth field between them.
  const PolarField fine = refine_polar_field(pf, r.grid.outer_radius());
  CHECK(fine.theta.size() >= 256);
  CHECK(fine.values[3] == Approx(pf.values[0]).margin(1e-12));  // 12 → 264 angles: node 0 is kept
  const ExactFlow ex = exact_flow(r.c.scene);
  const double rr = 1.7 * r.grid.a, th = 0.4;
  CHECK(polar_value(pf, rr, th) == Approx(ex.psi(rr, th)).margin(0.05 * r.c.scene.speed * r.grid.a));
}

TEST_CASE("a free stagnation point far out widens the window (α = 10)", "[plot]") {
  const FlowResult r = small_result(10.0);
  const double rs = (10.0 + std::sqrt(96.0)) / 2;  // 9.90 a, inside R = 20a
  const std::string dir = test::temp_dir("plot-alpha10");
  const StreamlinePicture pic = streamline_picture(r);
  CHECK(pic.notes.empty());
  CHECK(pic.view.window.x1 == Approx(std::min(20.0, 1.2 * rs)).epsilon(2e-3));
  CHECK(pic.view.window.y0 == Approx(-pic.view.window.x1));
  const PlotFrame f = plot_streamlines(pic, dir + "/s.png", {800, 800});
  const Image img = test::read_png(dir + "/s.png");
  CHECK(marks_at(img, f, {{0.0, rs}}, &Image::red));
  CHECK(clear_edges(img));
}

TEST_CASE("the Cp colour range follows the data: the bar spans the field's minimum", "[plot]") {
  const FlowResult r = small_result(4.0);
  const std::string dir = test::temp_dir("plot-cp");
  const std::string png = dir + "/cp.png";
  const PlotFrame f = plot_contour_field(cp_picture(r), png, {1000, 800});
  const Image img = test::read_png(png);
  // Exact minimum on the body's bottom: 1 − (α + 2)² = −35 (no clipping at −8).
  CHECK(f.bar_lo == Approx(-35.0).epsilon(0.03));
  CHECK(f.bar_hi == Approx(1.0).epsilon(0.05));
  REQUIRE_FALSE(f.colour_bar.empty());
  CHECK(f.colour_bar.x0 > f.box.x1);
  // The bar's bottom colour is the colour just under the body (the field's minimum); its top differs.
  const int bx = int(0.5 * (f.colour_bar.x0 + f.colour_bar.x1));
  auto colour = [&](const Image& im, int x, int y) {
    return std::vector<int>{im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)};
  };
  auto dist = [](const std::vector<int>& p, const std::vector<int>& q) {
    return std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]);
  };
  auto check_bar = [&](const Image& im) {
    const auto bottom = colour(im, bx, int(f.colour_bar.y1) - 2),
               top = colour(im, bx, int(f.colour_bar.y0) + 2);
    const auto under_body = colour(im, int(f.px(0.0)), int(f.py(-1.03)));
    return dist(bottom, under_body) < 60 && dist(bottom, top) > 200;
  };
  CHECK(check_bar(img));
  CHECK_FALSE(check_bar(img.blank()));
  CHECK_FALSE(check_bar(img.shifted(0, 40)));
  CHECK(clear_edges(img));
}

TEST_CASE("slide and thumbnail sizes: centred square window, text inside the image, scaled", "[plot]") {
  const FlowResult r = small_result(1.0);
  const std::string dir = test::temp_dir("plot-sizes");
  const CurveFigure surface = surface_cp_figure(r);
  int previous_band = 0;
  for (const PlotSize size : {PlotSize{400, 300}, PlotSize{900, 700}, PlotSize{1920, 1080}}) {
    CAPTURE(size.width, size.height);
    const double body = std::max(8.0, 0.018 * std::min(0.75 * size.width, double(size.height)));
    for (int k = 0; k < 3; ++k) {
      CAPTURE(k);
      const std::string png = dir + "/p" + std::to_string(k) + ".png";
      const PlotFrame f = k == 0   ? plot_streamlines(streamline_picture(r), png, size)
                          : k == 1 ? plot_contour_field(cp_picture(r), png, size)
                                   : plot_curves(surface.page, surface.lines, surface.points, png, size);
      const Image img = test::read_png(png);
      CHECK(clear_edges(img));
      CHECK(frame_drawn(img, f));
      if (k < 2) {
        CHECK(std::fabs(0.5 * (f.box.x0 + f.box.x1) - 0.5 * size.width) <= 2.0);
        CHECK(std::fabs((f.box.x1 - f.box.x0) - (f.box.y1 - f.box.y0)) <= 2.0);
      }
      // The lowest text line (x label, or the Cp footnote) is on the image and about body-text high.
      const int band = lowest_text_band(img, f);
      CHECK(band >= 0.6 * body);
      CHECK(band <= 3.0 * body);
      if (k == 0) {
        CHECK(band >= previous_band);
        previous_band = band;
      }
      // The legend, when there is one, is off the plot box and has text in it.
      if (!f.legend.empty()) {
        const bool apart = f.legend.x0 >= f.box.x1 || f.legend.y0 >= f.box.y1 || f.legend.x1 <= f.box.x0 ||
                           f.legend.y1 <= f.box.y0;
        CHECK(apart);
      }
    }
  }
}

TEST_CASE("axes in units of the radius: the same picture for a = 1 µm and a = 1 km", "[plot]") {
  const std::string dir = test::temp_dir("plot-units");
  for (double a : {1e-6, 1e3}) {
    CAPTURE(a);
    const FlowResult r = small_result(1.0, a);
    const PlotFrame f = plot_streamlines(streamline_picture(r), dir + "/s.png", {900, 700});
    const Image img = test::read_png(dir + "/s.png");
    CHECK(f.x0 == Approx(-4.0));
    CHECK(f.x1 == Approx(4.0));
    CHECK(marks_at(img, f, {{std::cos(M_PI / 6), 0.5}}, &Image::red));
    CHECK(clear_edges(img));
  }
}

TEST_CASE("curve plots: the points where the data say, the legend off the data", "[plot]") {
  const std::string dir = test::temp_dir("plot-curves");
  // A log-log benchmark (the Pareto plot): the best point bottom right, where a corner legend would go.
  std::vector<PointSet> series = {
      {"fft, 5-point", {{0.04, 4e-3}, {0.1, 3e-4}, {0.7, 2e-5}, {3.0, 5e-6}}, Colour::blue, 0, true, {}},
      {"cholmod, 9-point", {{0.5, 4e-7}, {3.0, 7e-9}, {15.0, 1e-10}, {80.0, 1e-13}}, Colour::red, 1, true, {}}};
  CurvePage page;
  page.title = "C_L error against time";
  page.xlabel = "time (ms)";
  page.ylabel = "relative C_L error";
  page.log_x = page.log_y = true;
  for (const PlotSize size : {PlotSize{1000, 800}, PlotSize{700, 800}}) {
    const PlotFrame f = plot_curves(page, {}, series, dir + "/b.png", size);
    const Image img = test::read_png(dir + "/b.png");
    REQUIRE_FALSE(f.legend.empty());
    CHECK((f.legend.x0 >= f.box.x1 || f.legend.y0 >= f.box.y1));
    int ink = 0;
    for (int y = int(f.legend.y0) + 3; y < int(f.legend.y1) - 3; ++y)
      for (int x = int(f.legend.x0) + 3; x < int(f.legend.x1) - 3; ++x) ink += img.dark(x, y);
    CHECK(ink > 50);
    const CurvePoint best{std::log10(80.0), -13.0};
    CHECK(marks_at(img, f, {best}, &Image::red));
    CHECK_FALSE(marks_at(img.shifted(15, 0), f, {best}, &Image::red));
    CHECK(clear_edges(img));
  }
  // Nothing positive on log axes: an error, and no file.
  REQUIRE_THROWS_AS(plot_curves(page, {}, {{"zero", {{0.0, 1.0}}, Colour::blue, 0, false, {}}}, dir + "/e.png"),
                    std::runtime_error);
  std::ifstream probe(dir + "/e.png");
  CHECK_FALSE(probe.good());
}

TEST_CASE("text markup: subscripts render as subscripts, user text literally", "[plot]") {
  CHECK(plplot_text("n_θ × n_r") == "n#dθ#u × n#dr#u");
  CHECK(plplot_text("C_L = F_{y}/(½ρU^2·2a)") == "C#dL#u = F#dy#u/(½ρU#u2#d·2a)");
  CHECK(plplot_text("#") == "##");
  CHECK(plplot_text(literal_text("spin_ratio_1^2")) == "spin_ratio_1^2");
}

TEST_CASE("lift figures: the curves come from physics, the seed of a circulation sweep is constant",
          "[plot]") {
  Scene base;
  base.radius = 0.1;
  base.speed = 10.0;
  base.spin = 50.0;  // α = 0.5
  LiftSweep spin;
  spin.x = {0.0, 1.0, 2.0, 3.0};
  spin.cl = {0.0, -2 * M_PI, -4 * M_PI, -6 * M_PI};
  spin.base = base;
  spin.title = "spin_sweep";
  const CurveFigure fs = lift_figure(spin, nullptr);
  CHECK(fs.page.xlabel.find("α") != std::string::npos);
  REQUIRE(fs.lines.size() >= 3);
  CHECK(fs.lines[0].points.back().y == Approx(-6 * M_PI));   // Kutta–Joukowski −2πα at α = 3
  CHECK(fs.lines[1].points.back().y == Approx(-12.0));       // seed −4α
  CHECK(fs.lines[2].points.front().y == Approx(-4 * M_PI));  // Prandtl's bound
  CHECK(fs.page.title.find("spin\\_sweep") != std::string::npos);

  LiftSweep circ = spin;
  circ.by_circulation = true;
  circ.base.circulation_given = true;
  circ.x = {-5.0, 0.0, 5.0};
  circ.cl = {5.0, 0.0, -5.0};
  const CurveFigure fc = lift_figure(circ, nullptr);
  CHECK(fc.page.xlabel.find("Γ (m^2/s)") != std::string::npos);
  CHECK(fc.lines[0].points.front().y == Approx(5.0 / (10.0 * 0.1)));  // −Γ/(Ua)
  REQUIRE(fc.lines[1].label.find("seed") != std::string::npos);
  CHECK(fc.lines[1].points.front().y == Approx(-2.0));  // −4aω/U, whatever Γ
  CHECK(fc.lines[1].points.back().y == Approx(-2.0));
  circ.base.spin = 0.0;
  for (const auto& l : lift_figure(circ, nullptr).lines) CHECK(l.label.find("seed") == std::string::npos);

  // Drawn: the numeric points where they belong.
  const std::string dir = test::temp_dir("plot-lift");
  const PlotFrame f = plot_curves(fc.page, fc.lines, fc.points, dir + "/l.png", {900, 700});
  const Image img = test::read_png(dir + "/l.png");
  CHECK(marks_at(img, f, {{-5.0, 5.0}, {5.0, -5.0}}, &Image::red));
  CHECK(clear_edges(img));
}

TEST_CASE("surface Cp: the exact curve of a given circulation is 1 − (−2 sinθ + Γ/(2πaU))²", "[plot]") {
  Case c;
  c.scene.radius = 0.1;
  c.scene.speed = 10.0;
  c.scene.spin = 0.0;
  c.scene.circulation_given = true;
  c.scene.circulation_value = 3.0;
  c.grid.n_theta = 64;
  const FlowResult r = run_case(c);
  const CurveFigure f = surface_cp_figure(r);
  REQUIRE(f.lines.size() == 1);
  for (const auto& p : f.lines[0].points) {
    const double th = p.x * M_PI / 180.0, u = -2 * std::sin(th) + 3.0 / (2 * M_PI * 0.1 * 10.0);
    CHECK(p.y == Approx(1 - u * u).margin(1e-9));
  }
}

TEST_CASE("an unwritable plot path throws one line naming the file and leaves nothing", "[plot]") {
  const FlowResult r = small_result(1.0);
  const std::string dir = test::temp_dir("plot-unwritable");
  const std::string missing = dir + "/no/such/dir/stream.png";
  try {
    plot_streamlines(streamline_picture(r), missing);
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK(what.find(missing) != std::string::npos);
    CHECK(what.find('\n') == std::string::npos);
  }
  // An unwritable place even for root (CI runs as root): a path beneath a regular file.
  const std::string ro = dir + "/ro";
  { std::ofstream(ro) << "a plain file"; }
  REQUIRE_THROWS_AS(plot_streamlines(streamline_picture(r), ro + "/stream.png"), std::runtime_error);
  // The target is a directory: the rename fails, the temporary is removed.
  const std::string as_dir = dir + "/taken.png";
  REQUIRE(::mkdir(as_dir.c_str(), 0755) == 0);
  const CurveFigure s = surface_cp_figure(r);
  REQUIRE_THROWS_AS(plot_curves(s.page, s.lines, s.points, as_dir), std::runtime_error);
  FlowResult no_cp = r;
  no_cp.fields.cp.clear();
  REQUIRE_THROWS_WITH(cp_picture(no_cp), "plot: the result has no cp field");
  REQUIRE_THROWS_AS(plot_streamlines(streamline_picture(r), dir + "/tiny.png", {4, 4}), std::runtime_error);
  const auto left = dir_entries(dir);
  CHECK(left.size() == 2);  // ro and taken.png, no temporaries
  for (const auto& e : left) CHECK(e.find(".tmp-") == std::string::npos);
}
