// The pictures of a navier-stokes result: the vorticity (diverging colours over symmetric limits), the
// forces against time and the wall shear stress, and `magnus plot`'s files for such a result.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

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
