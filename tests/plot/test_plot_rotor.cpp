// The rotor-sail data on the lift-sweep figure: which datasets are drawn for a scene's Re, and how.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "io/reference_file.hpp"
#include "io/rotor_data.hpp"
#include "plot/figures.hpp"
#include "plot/figures_rotor.hpp"
#include "png_image.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

const std::string kPath = std::string(MAGNUS_SOURCE_DIR) + "/data/rotor_data.toml";

LiftSweep rotor_sweep(double viscosity) {
  LiftSweep s;
  s.base.radius = 2.5;
  s.base.speed = 12.0;
  s.base.viscosity = viscosity;
  s.title = "rotor";
  for (int k = 0; k <= 10; ++k) {
    s.x.push_back(0.5 * k);
    s.cl.push_back(-2 * M_PI * 0.5 * k);
  }
  return s;
}

int count_label(const CurveFigure& f, const std::string& text) {
  int n = 0;
  for (const auto& l : f.lines) n += l.label.find(text) != std::string::npos;
  for (const auto& p : f.points) n += p.label.find(text) != std::string::npos;
  return n;
}

}  // namespace

TEST_CASE("lift figure: rotor data drawn when their Re fits the scene's, all when there is no Re", "[plot]") {
  const RotorData r = load_rotor_data(kPath);
  // No viscosity: potential flow has no Re, so every dataset is drawn, each labelled with its own Re.
  const CurveFigure all = lift_figure(rotor_sweep(0.0), nullptr, &r);
  for (const char* name : {"Prandtl 1926", "Bordogna", "2D CFD", "3D CFD", "Tillig"}) {
    INFO(name);
    CHECK(count_label(all, name) == 1);
  }
  CHECK(count_label(all, "Re = 3.6·10") == 1);  // the label is escaped for PLplot
  CHECK(count_label(all, "Re not stated") == 3);
  // The fit is a dashed line through −|C_L|(α) over α in [0, 5]; tables are hollow markers.
  const LineCurve* fit = nullptr;
  for (const auto& l : all.lines)
    if (l.label.find("Tillig") != std::string::npos) fit = &l;
  REQUIRE(fit);
  CHECK(fit->style == LineStyle::dashed);
  CHECK(fit->points.front().x == 0.0);
  CHECK(fit->points.back().x == Approx(5.0));
  CHECK(fit->points.back().y == Approx(-12.228).margin(1e-3));
  for (const auto& p : all.points)
    if (p.label.find("Östman") != std::string::npos) {
      CHECK(p.marker >= 5);
      CHECK(p.points.back().x == 5.0);  // α = 6 and 8 are outside the sweep
    }

  // The rotor-sail scene with air's viscosity: Re = 12·5/1.5e-5 = 4·10^6 draws the full-scale fit only.
  const CurveFigure air = lift_figure(rotor_sweep(1.5e-5), nullptr, &r);
  CHECK(count_label(air, "Tillig") == 1);
  CHECK(count_label(air, "Bordogna") == 0);
  CHECK(count_label(air, "Prandtl 1926") == 0);
  // Re = 3.6·10^5 (ν = 1.667e-4 m²/s): Bordogna et al. and the full-scale fit (1·10^6 ≤ 3·3.6·10^5).
  const CurveFigure tunnel = lift_figure(rotor_sweep(12.0 * 5.0 / 3.6e5), nullptr, &r);
  CHECK(count_label(tunnel, "Bordogna") == 1);
  CHECK(count_label(tunnel, "Tillig") == 1);
  CHECK(count_label(tunnel, "Östman") == 0);
  // A circulation sweep has no spin ratio axis: no rotor data.
  LiftSweep circ = rotor_sweep(0.0);
  circ.by_circulation = true;
  CHECK(count_label(lift_figure(circ, nullptr, &r), "Tillig") == 0);

  // Drawn: the fit's dashed line and the markers show; nothing runs off the picture.
  const std::string dir = test::temp_dir("plot-rotor");
  const PlotFrame f = plot_curves(all.page, all.lines, all.points, dir + "/r.png", {1000, 800});
  const test::Image img = test::read_png(dir + "/r.png");
  CHECK(img.width == 1000);
  CHECK(!f.legend.empty());
  // The Östman 2D markers at α = 2 and 4 (|C_L| 5.93, 10.77), within a few pixels.
  auto inked_near = [&](double x, double y) {
    const double cx = f.px(x), cy = f.py(y);
    for (int dx = -4; dx <= 4; ++dx)
      for (int dy = -4; dy <= 4; ++dy)
        if (img.inked(int(cx) + dx, int(cy) + dy)) return true;
    return false;
  };
  CHECK(inked_near(2.0, -5.93));
  CHECK(inked_near(4.0, -10.77));
}

TEST_CASE("lift figure: the Re = 100 viscous reference only beside a scene of its Re", "[plot]") {
  const ViscousReference ref = load_viscous_reference(viscous_reference_path());
  REQUIRE(ref.datasets.size() >= 2);
  for (const auto& d : ref.datasets) REQUIRE(d.reynolds == 100.0);
  // The rotor sail: Re = 12·5/1.5e-5 = 4·10^6, far from 100: no Re = 100 points.
  const CurveFigure rotor = lift_figure(rotor_sweep(1.5e-5), &ref, nullptr);
  CHECK(count_label(rotor, "Re = 100") == 0);
  // Re = 12·5/0.6 = 100: both tables, each naming its Re.
  const CurveFigure re100 = lift_figure(rotor_sweep(0.6), &ref, nullptr);
  CHECK(count_label(re100, "Re = 100") == int(ref.datasets.size()));
  // Re = 250 is within a factor 3 of 100; Re = 400 is not.
  CHECK(count_label(lift_figure(rotor_sweep(12.0 * 5.0 / 250.0), &ref, nullptr), "Re = 100") ==
        int(ref.datasets.size()));
  CHECK(count_label(lift_figure(rotor_sweep(12.0 * 5.0 / 400.0), &ref, nullptr), "Re = 100") == 0);
  // No viscosity, no Re: all of them, labelled with their Re.
  CHECK(count_label(lift_figure(rotor_sweep(0.0), &ref, nullptr), "Re = 100") == int(ref.datasets.size()));
}

TEST_CASE("lift figure: C_L is labelled by the flow's frame, not by a world axis", "[plot]") {
  // With flow.direction = 90 the lift points along −x: "F_y" would name the wrong force.
  const CurveFigure f = lift_figure(rotor_sweep(1.5e-5), nullptr, nullptr);
  CHECK(f.page.ylabel.find("F_y") == std::string::npos);
  CHECK(f.page.ylabel.find("lift L ⊥ U") != std::string::npos);
}
