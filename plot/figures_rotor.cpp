#include "plot/figures_rotor.hpp"

#include <algorithm>

#include "plot/figure_labels.hpp"

namespace magnus {

int add_rotor_overlays(CurveFigure& f, const RotorData& data, double re, double xlo, double xhi) {
  const Colour colours[] = {Colour::black, Colour::magenta, Colour::brown, Colour::grey, Colour::olive};
  int k = 0, added = 0;
  for (const auto& d : data.datasets) {
    const Colour colour = colours[k % 5];
    const int marker = 5 + k % 5;  // hollow markers: ○ □ △ ◇ ▽ (the Re = 100 tables use filled ones)
    ++k;
    if (!rotor_fits_reynolds(d, re)) continue;
    const std::string label = literal_text(d.label + ", " + rotor_reynolds_text(d));
    if (!d.cl_poly.empty()) {
      const double a0 = std::max(xlo, d.alpha_min), a1 = std::min(xhi, d.alpha_max);
      if (!(a1 > a0)) continue;
      LineCurve line{label, {}, colour, LineStyle::dashed, 1.6};
      const int n = std::max(2, int(100.0 * (a1 - a0) / std::max(xhi - xlo, 1e-12)) + 1);
      for (int j = 0; j < n; ++j) {
        const double a = a0 + (a1 - a0) * j / (n - 1);
        if (const auto v = rotor_value(d, a)) line.points.push_back({a, v->cl});
      }
      if (line.points.size() < 2) continue;
      f.lines.push_back(std::move(line));
      ++added;
      continue;
    }
    PointSet ps;
    ps.label = label;
    ps.colour = colour;
    ps.marker = marker;
    for (const auto& p : d.points)
      if (p.alpha >= xlo && p.alpha <= xhi) ps.points.push_back({p.alpha, p.cl});
    if (ps.points.empty()) continue;
    f.points.push_back(std::move(ps));
    ++added;
  }
  return added;
}

}  // namespace magnus
