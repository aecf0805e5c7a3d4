// The pictures of a navier-stokes result: the vorticity (diverging colours over symmetric limits), the
// forces against time and the wall shear stress, and `magnus plot`'s files for such a result.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "app/plot_files.hpp"
#include "io/hdf5_io.hpp"
#include "io/viscous_fixture.hpp"
#include "plot/curves.hpp"
#include "plot/field_plots.hpp"
#include "plot/figures.hpp"
#include "plot/png_image.hpp"
#include "support.hpp"

using namespace magnus;
using test::Image;

namespace {

/// Pixels inside the box that are neither white nor near-grey: the picture holds colour.
int coloured_pixels(const Image& img, const PlotFrame& f) {
  int n = 0;
  for (int y = int(f.box.y0) + 2; y < int(f.box.y1) - 2; ++y)
    for (int x = int(f.box.x0) + 2; x < int(f.box.x1) - 2; ++x) {
      const int r = img.at(x, y, 0), g = img.at(x, y, 1), b = img.at(x, y, 2);
      n += std::max({r, g, b}) - std::min({r, g, b}) > 40;
    }
  return n;
}

bool reddish(const Image& img, double x, double y) {
  return img.at(int(x), int(y), 0) > img.at(int(x), int(y), 2) + 40;
}
bool bluish(const Image& img, double x, double y) {
  return img.at(int(x), int(y), 2) > img.at(int(x), int(y), 0) + 40;
}

}  // namespace

TEST_CASE("vorticity: diverging colours over symmetric limits, red where ζ > 0, blue where ζ < 0",
          "[plot][viscous]") {
  const FlowResult r = test::viscous_result_by_hand(1.0, 64, 32, 0);
  const std::string dir = test::temp_dir("plot-vorticity");
  const ContourFieldPicture pic = vorticity_picture(r);
  CHECK(pic.diverging);
  CHECK(pic.limit > 0.0);
  const PlotFrame f = plot_contour_field(pic, dir + "/v.png", {900, 700});
  const Image img = test::read_png(dir + "/v.png");
  REQUIRE(img.width == 900);
  REQUIRE(img.height == 700);
  CHECK(f.bar_lo == Approx(-f.bar_hi));
  CHECK(f.bar_hi == Approx(pic.limit));
  CHECK(coloured_pixels(img, f) > 2000);
  CHECK(coloured_pixels(img.blank(), f) == 0);
  // The colours where the field says: find nodes of strong ζ of each sign in the window, off the body.
  int checked = 0, right = 0, wrong = 0;
  for (int i = 2; i < r.grid.n_r; ++i)
    for (int j = 0; j < r.grid.n_theta; ++j) {
      const double rr = r.grid.r[i] / r.grid.a, th = r.grid.theta[j];
      const double x = rr * std::cos(th), y = rr * std::sin(th);
      if (std::fabs(x) > 3.8 || std::fabs(y) > 3.8 || rr < 1.15) continue;
      const double z = r.fields.vorticity[size_t(i) * r.grid.n_theta + j];
      if (std::fabs(z) < 0.4 * pic.limit) continue;
      ++checked;
      const bool red = reddish(img, f.px(x), f.py(y)), blue = bluish(img, f.px(x), f.py(y));
      right += z > 0 ? red : blue;
      wrong += z > 0 ? blue : red;
    }
  CHECK(checked > 10);
  CHECK(right >= 0.9 * checked);
  CHECK(wrong == 0);
  // The body is drawn: grey at the centre.
  const int cx = int(f.px(0.0)), cy = int(f.py(0.0));
  CHECK(std::abs(img.at(cx, cy, 0) - img.at(cx, cy, 2)) < 20);
  CHECK(img.at(cx, cy, 0) < 235);

  FlowResult none = r;
  none.fields.vorticity.clear();
  REQUIRE_THROWS_WITH(vorticity_picture(none), "plot: the result has no vorticity field");
}

TEST_CASE("forces against time: C_L and C_D of the history in D/U, the means and the ideal",
          "[plot][viscous]") {
  const FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 0);
  const CurveFigure fig = force_history_figure(r);
  REQUIRE(fig.lines.size() >= 4);
  const ViscousPart& v = *r.viscous;
  // A history longer than 10 D/U is drawn from t = 2 D/U on (the impulsive start's peak left out).
  size_t first = 0;
  const bool skip = v.history.back().t / v.time_unit > 10.0;
  while (skip && v.history[first].t / v.time_unit < 2.0) ++first;
  CHECK(fig.lines[0].points.size() == v.history.size() - first);
  CHECK(fig.lines[0].points.front().x >= (skip ? 2.0 : 0.0));
  CHECK(fig.lines[0].points.back().x == Approx(v.history.back().t / v.time_unit));
  CHECK(fig.lines[0].points.back().y == v.history.back().C_L);
  CHECK(fig.lines[1].points[7].y == v.history[first + 7].C_D);
  bool ideal = false;
  for (const auto& l : fig.lines) ideal = ideal || (l.points.size() == 2 && l.points[0].y == *v.cl_ideal);
  CHECK(ideal);
  const std::string dir = test::temp_dir("plot-history");
  const PlotFrame f = plot_curves(fig.page, fig.lines, fig.points, dir + "/h.png", {1000, 600});
  const Image img = test::read_png(dir + "/h.png");
  CHECK(img.width == 1000);
  CHECK(img.height == 600);
  // The last C_L sample is drawn in red where it belongs; the window spans the run's time.
  CHECK(img.near(f.px(fig.lines[0].points.back().x) - 3, f.py(fig.lines[0].points.back().y), 3,
                 [&](int x, int y) { return img.red(x, y); }));
  CHECK(f.x1 >= v.history.back().t / v.time_unit);
  FlowResult none = r;
  none.viscous->history.clear();
  REQUIRE_THROWS_AS(force_history_figure(none), std::runtime_error);
}

TEST_CASE("a partial result's pictures say so in their titles", "[plot][viscous]") {
  FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 0);
  CHECK(force_history_figure(r).page.title.find("partial") == std::string::npos);
  r.viscous->partial = true;
  const std::string mark = ", Re = 100 (partial)";
  CHECK(force_history_figure(r).page.title.find(mark) != std::string::npos);
  CHECK(shear_stress_figure(r).page.title.find(mark) != std::string::npos);
  CHECK(surface_cp_figure(r).page.title.find(mark) != std::string::npos);
  CHECK(vorticity_picture(r).view.title.find(mark) != std::string::npos);
  CHECK(streamline_picture(r).view.title.find(mark) != std::string::npos);
  CHECK(cp_picture(r).view.title.find(mark) != std::string::npos);
}

TEST_CASE("wall shear stress against θ, with the separation points", "[plot][viscous]") {
  const FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 0);
  const CurveFigure fig = shear_stress_figure(r);
  REQUIRE(fig.lines.size() == 1);
  CHECK(fig.lines[0].points.size() == r.surface.shear_stress.size() + 1);
  REQUIRE(fig.points.size() == 1);
  CHECK(fig.points[0].points.size() == 2);
  const std::string dir = test::temp_dir("plot-shear");
  const PlotFrame f = plot_curves(fig.page, fig.lines, fig.points, dir + "/s.png", {800, 600});
  const Image img = test::read_png(dir + "/s.png");
  CHECK(img.width == 800);
  CHECK(img.near(f.px(0.3 * 180 / M_PI), f.py(0.0), 4, [&](int x, int y) { return img.red(x, y); }));
}

TEST_CASE("magnus plot of a navier-stokes file: vorticity, forces, shear and the usual pictures",
          "[plot][viscous]") {
  const std::string dir = test::temp_dir("plot-ns-file");
  const FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 2);
  write_result(r, dir + "/ns.h5");
  const PlotOutcome o = plot_result_file(dir + "/ns.h5", dir + "/out", {640, 480});
  CAPTURE(o.skipped);
  for (const char* name : {"streamlines", "cp", "surface_cp", "vorticity", "forces", "shear"}) {
    const std::string png = dir + "/out/ns_" + name + ".png";
    CAPTURE(png);
    CHECK(std::find(o.written.begin(), o.written.end(), png) != o.written.end());
    CHECK(test::png_size(png) == std::pair<unsigned long, unsigned long>{640, 480});
    const Image img = test::read_png(png);
    int ink = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) ink += img.inked(x, y);
    CHECK(ink > 5000);
  }
  CHECK(o.skipped.empty());
}

TEST_CASE("a wall shear stress of hundredths of a pascal: its scale in the label, none from PLplot",
          "[plot][viscous]") {
  FlowResult r = test::viscous_result_by_hand(1.0, 64, 16, 0);
  // Re = 100 in water: τ_w from −0.022 to 0.018 Pa.
  for (size_t j = 0; j < r.surface.theta.size(); ++j)
    r.surface.shear_stress[j] = 0.02 * std::sin(r.surface.theta[j]) - 0.002;
  const CurveFigure fig = shear_stress_figure(r);
  const std::string dir = test::temp_dir("plot-shear-scale");
  const PlotFrame f = plot_curves(fig.page, fig.lines, fig.points, dir + "/s.png", {900, 700});
  CHECK(f.y_exponent == -3);
  CHECK(f.x_exponent == 0);
  CHECK(f.ylabel == "τ_w = μ(ζ_w − 2ω) (10^{-3} Pa)");
  // The window is in pascals (px, py take the data), its numbers shown in mPa: tens, not hundredths.
  CHECK(f.y0 <= -0.022);
  CHECK(f.y1 >= 0.018);
  CHECK(f.y1 < 0.03);
  const Image img = test::read_png(dir + "/s.png");
  auto blue = [&](int x, int y) { return img.blue(x, y); };
  CHECK(img.near(f.px(90.0), f.py(0.018), 3, blue));
  CHECK(img.near(f.px(270.0), f.py(-0.022), 3, blue));
  CHECK(!img.near(f.px(90.0), f.py(-0.022), 3, blue));
  // PLplot writes its own "(×10^-2)" above the box, left of the title: nothing may be drawn there.
  int ink = 0;
  for (int y = 0; y < int(f.box.y0) - 10; ++y)
    for (int x = 0; x < int(f.box.x0) - 2; ++x) ink += img.dark(x, y);
  CHECK(ink == 0);
}

TEST_CASE("axis scales: small and large numbers in a power of ten written into the label", "[plot]") {
  const std::string dir = test::temp_dir("plot-axis-scale");
  CurvePage page;
  page.title = "scales";
  page.xlabel = "distance (m)";
  page.ylabel = "C_L, C_D (on ½ρU^2·D)";
  LineCurve line{"", {}, Colour::blue, LineStyle::solid, 2.0};
  for (int k = 0; k <= 20; ++k) line.points.push_back({2e5 * k / 20.0, 3e-6 * std::sin(k / 3.0)});
  const PlotFrame f = plot_curves(page, {line}, {}, dir + "/c.png", {800, 600});
  CHECK(f.x_exponent == 3);
  CHECK(f.y_exponent == -6);
  CHECK(f.xlabel == "distance (10^{3} m)");
  CHECK(f.ylabel == "C_L, C_D (on ½ρU^2·D) (×10^{-6})");
  CHECK(f.x1 == Approx(2e5 * 1.03).epsilon(1e-6));
  const Image img = test::read_png(dir + "/c.png");
  const CurvePoint p = line.points[7];
  CHECK(img.near(f.px(p.x), f.py(p.y), 3, [&](int x, int y) { return img.blue(x, y); }));
  // Ordinary numbers keep their labels.
  for (auto& q : line.points) q.y *= 1e6;
  const PlotFrame g = plot_curves(page, {line}, {}, dir + "/d.png", {800, 600});
  CHECK(g.y_exponent == 0);
  CHECK(g.ylabel == page.ylabel);
}

TEST_CASE("the vorticity's colour bar takes a power of ten of its own", "[plot][viscous]") {
  FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 0);
  for (auto& z : r.fields.vorticity) z *= 1e-4;
  const std::string dir = test::temp_dir("plot-bar-scale");
  const ContourFieldPicture pic = vorticity_picture(r);
  const PlotFrame f = plot_contour_field(pic, dir + "/v.png", {900, 700});
  CHECK(f.bar_hi == Approx(pic.limit));
  CHECK(f.bar_exponent == 3 * int(std::floor(std::floor(std::log10(pic.limit)) / 3.0)));
  CHECK(f.bar_exponent < 0);
  CHECK(f.bar_label == "ζ (10^{" + std::to_string(f.bar_exponent) + "} 1/s)");
}

TEST_CASE("the plot window: parsed in one line, checked against the grid, the default follows an unsteady wake",
          "[plot][viscous]") {
  const PlotWindow w = parse_plot_window("-5:25,-6:6");
  CHECK(w.x0 == -5.0);
  CHECK(w.x1 == 25.0);
  CHECK(w.y0 == -6.0);
  CHECK(w.y1 == 6.0);
  CHECK(parse_plot_window("-1.5e0:2,0:0.5").y1 == 0.5);
  for (const char* bad : {"", "1:2", "-5:25,-6", "-5:25,-6:6,1", "5:-5,-6:6", "-5:25,6:6", "a:b,c:d",
                          "nan:1,0:1", "-5:25;-6:6", "0:1e7,0:1e6", "0:100,0:1", "-5:25,-6:6 "}) {
    INFO(bad);
    try {
      parse_plot_window(bad);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      CHECK(what.rfind("--window '" + std::string(bad) + "': ", 0) == 0);
      CHECK(what.find('\n') == std::string::npos);
    }
  }
  FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 0);  // R = 20a, shedding
  const PlotWindow d = view_window(r);
  CHECK(d.x0 == -5.0);
  CHECK(d.x1 == 20.0);  // 25a, clipped to R
  CHECK(d.y0 == -6.0);
  CHECK(d.y1 == 6.0);
  REQUIRE_THROWS_AS(window_for(r, PlotWindow{21, 30, -1, 1}), std::invalid_argument);
  REQUIRE_THROWS_AS(window_for(r, PlotWindow{15, 30, 15, 20}), std::invalid_argument);  // corner at 21.2a
  CHECK(window_for(r, PlotWindow{10, 30, -1, 1}).x1 == 30.0);
  r.viscous->steady = true;
  CHECK(view_window(r).x1 == 4.0);
  CHECK(view_window(r).y0 == -4.0);
}

TEST_CASE("the vorticity down the wake: a wide window shows it with equal scales", "[plot][viscous]") {
  FlowResult r = test::viscous_result_by_hand(1.0, 64, 32, 0);
  // Two shear layers down the wake: ζ < 0 above the axis, ζ > 0 below, out to x = 14a.
  for (int i = 0; i < r.grid.n_r; ++i)
    for (int j = 0; j < r.grid.n_theta; ++j) {
      const double rr = r.grid.r[i] / r.grid.a, x = rr * std::cos(r.grid.theta[j]), y = rr * std::sin(r.grid.theta[j]);
      r.fields.vorticity[size_t(i) * r.grid.n_theta + j] = x > 0.0 ? -5.0 * y * std::exp(-y * y / 4.0) : 0.0;
    }
  const std::string dir = test::temp_dir("plot-wake-window");
  const ContourFieldPicture pic = vorticity_picture(r, PlotWindow{-5, 15, -4, 4});
  const PlotFrame f = plot_contour_field(pic, dir + "/v.png", {1000, 800});
  CHECK(f.x0 == -5.0);
  CHECK(f.x1 == 15.0);
  CHECK(f.y0 == -4.0);
  CHECK(f.y1 == 4.0);
  // Equal scales: the box is 20/8 as wide as it is high.
  CHECK((f.box.x1 - f.box.x0) / (f.box.y1 - f.box.y0) == Approx(20.0 / 8.0).epsilon(0.01));
  // The bar and its numbers stay on the page.
  CHECK(f.colour_bar.x1 < 1000 - 30);
  const Image img = test::read_png(dir + "/v.png");
  // The wake behind x = 4a (the old window's edge) is coloured where the field says.
  int checked = 0, right = 0;
  for (int i = 0; i < r.grid.n_r; ++i)
    for (int j = 0; j < r.grid.n_theta; ++j) {
      const double rr = r.grid.r[i] / r.grid.a, th = r.grid.theta[j];
      const double x = rr * std::cos(th), y = rr * std::sin(th);
      if (x < 5.0 || x > 14.5 || std::fabs(y) > 3.8) continue;
      const double z = r.fields.vorticity[size_t(i) * r.grid.n_theta + j];
      if (std::fabs(z) < 0.2 * pic.limit) continue;
      ++checked;
      right += z > 0 ? reddish(img, f.px(x), f.py(y)) : bluish(img, f.px(x), f.py(y));
    }
  CHECK(checked > 5);
  CHECK(right >= 0.9 * checked);
}

TEST_CASE("round-off vorticity in the free stream has the zero colour, not a tint of its sign",
          "[plot][viscous]") {
  FlowResult r = test::viscous_result_by_hand(1.0, 64, 32, 0);
  const PolarGrid& g = r.grid;
  // Real vorticity near the body; beyond r = 3a only round-off of alternating sign.
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j)
      if (g.r[i] > 3.0 * g.a) r.fields.vorticity[size_t(i) * g.n_theta + j] = (i + j) % 2 ? 3e-9 : -3e-9;
  r.viscous->steady = true;  // the ±4a window
  const std::string dir = test::temp_dir("plot-roundoff");
  const ContourFieldPicture pic = vorticity_picture(r);
  REQUIRE(pic.limit > 1e-3);
  const PlotFrame f = plot_contour_field(pic, dir + "/v.png", {900, 700});
  const Image img = test::read_png(dir + "/v.png");
  int neutral = 0, tinted = 0;
  for (double x = -3.8; x <= 3.8; x += 0.1)
    for (double y : {-3.7, -3.5, 3.5, 3.7}) {
      const int px = int(f.px(x)), py = int(f.py(y));
      const int cr = img.at(px, py, 0), cg = img.at(px, py, 1), cb = img.at(px, py, 2);
      const bool grey = std::abs(cr - cb) <= 3 && std::abs(cr - cg) <= 3 && cr > 235;
      neutral += grey;
      tinted += !grey;
    }
  CHECK(neutral > 200);
  CHECK(tinted == 0);
}
