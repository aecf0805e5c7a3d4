// The window of a result's field pictures: the default (around the body, or down the wake of an unsteady
// navier-stokes result) and the one `magnus plot --window` asks for.
#include <fmt/core.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "plot/figures.hpp"

namespace magnus {

double view_half_width(const FlowResult& r) {
  const double a = r.grid.a, R = r.grid.outer_radius() / a;
  double w = std::min(R, 4.0);
  for (const auto* set : {&r.stagnation, &r.stagnation_exact})
    for (const auto& s : *set)
      if (!s.on_surface) w = std::max(w, std::min(R, 1.2 * s.r / a));
  return w;
}

PlotWindow view_window(const FlowResult& r) {
  if (!r.viscous || r.viscous->steady) return PlotWindow::square(view_half_width(r));
  // The wake of a shedding cylinder: 5a upstream to 25a downstream (+x in the wind frame), ±6a across.
  const double R = r.grid.outer_radius() / r.grid.a;
  return {-std::min(R, 5.0), std::min(R, 25.0), -std::min(R, 6.0), std::min(R, 6.0)};
}

PlotWindow parse_plot_window(const std::string& text) {
  auto bad = [&](const std::string& why) {
    return std::invalid_argument(fmt::format("--window '{}': {}", text, why));
  };
  const char* format = "expected X0:X1,Y0:Y1 in units of the radius, e.g. -5:25,-6:6";
  double v[4];
  const char* p = text.c_str();
  for (int k = 0; k < 4; ++k) {
    char* end = nullptr;
    errno = 0;
    v[k] = std::strtod(p, &end);
    if (end == p || errno == ERANGE || !std::isfinite(v[k])) throw bad(format);
    const char want = k == 3 ? '\0' : k == 1 ? ',' : ':';
    if (*end != want) throw bad(format);
    p = end + (k == 3 ? 0 : 1);
  }
  const PlotWindow w{v[0], v[1], v[2], v[3]};
  if (!(w.x1 > w.x0) || !(w.y1 > w.y0)) throw bad("each range must run from low to high (X0 < X1, Y0 < Y1)");
  for (double x : v)
    if (std::fabs(x) > 1e6) throw bad("the values must be within ±10^6 radii");
  const double aspect = (w.x1 - w.x0) / (w.y1 - w.y0);
  if (aspect > 20.0 || aspect < 0.05) throw bad("the window's width/height must be 1/20 to 20");
  return w;
}

PlotWindow window_for(const FlowResult& r, const std::optional<PlotWindow>& asked) {
  if (!asked) return view_window(r);
  const PlotWindow& w = *asked;
  // The point of the window nearest the body's centre must lie on the grid (r ≤ R).
  const double nx = std::clamp(0.0, w.x0, w.x1), ny = std::clamp(0.0, w.y0, w.y1);
  const double R = r.grid.outer_radius() / r.grid.a;
  if (std::hypot(nx, ny) >= R)
    throw std::invalid_argument(fmt::format("--window {}:{},{}:{}: outside the grid, which ends at r = {}a",
                                            w.x0, w.x1, w.y0, w.y1, fmt::format("{:.4g}", R)));
  return w;
}

}  // namespace magnus
