#include "plot/ns_map_plot.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace magnus {

void plot_ns_map(const NsMap& m, const std::string& png, PlotSize size, const std::vector<Onset3d>& onset) {
  if (std::none_of(m.points.begin(), m.points.end(), [](const NsMapPoint& p) { return std::isfinite(p.ratio); }))
    throw std::runtime_error(fmt::format(
        "{}: nothing to draw: S/(2πρa^2) = C_L/C_L,ideal is undefined at every point of this map ({})", png,
        std::all_of(m.alphas.begin(), m.alphas.end(), [](double a) { return a == 0.0; })
            ? "α = 0: the ideal lift is 0"
            : "no point has a lift"));
  const bool by_re = m.continued_in_re();
  static const Colour cycle[] = {Colour::blue,   Colour::red,   Colour::green, Colour::purple,
                                 Colour::orange, Colour::teal,  Colour::brown, Colour::magenta,
                                 Colour::olive,  Colour::black, Colour::grey};
  std::map<int, PointSet> rows;
  for (const auto& p : m.points) {
    if (!std::isfinite(p.ratio)) continue;
    PointSet& s = rows[by_re ? 0 : p.row];
    if (s.label.empty()) {
      s.label = by_re ? fmt::format("α {:g}", p.alpha) : fmt::format("Re {:g}", p.reynolds);
      s.colour = cycle[size_t(p.row) % (sizeof cycle / sizeof cycle[0])];
      s.joined = true;
      s.marker = 0;
    }
    s.points.push_back({by_re ? p.reynolds : p.alpha, p.ratio});
    s.y_error.push_back(std::fabs(p.ratio) * p.cl_rel_estimate);  // the point's own bar (NaN: none)
  }
  PointSet avg;
  avg.label = "time-averaged";
  avg.colour = Colour::black;
  avg.marker = 5;
  for (const auto& p : m.points)
    if (std::isfinite(p.ratio) &&
        (p.source == MapSource::averaged_unstable || p.source == MapSource::averaged_no_steady ||
         p.source == MapSource::orbit))
      avg.points.push_back({by_re ? p.reynolds : p.alpha, p.ratio});
  // The second (one-sided) shedding window and the bistable points, each marked around its point.
  PointSet second, both;
  second.label = "second (one-sided) shedding window";
  second.colour = Colour::black;
  second.marker = 7;  // △
  both.label = "bistable: a shedding orbit coexists";
  both.colour = Colour::black;
  both.marker = 3;  // ◆
  for (const auto& p : m.points) {
    if (!std::isfinite(p.ratio)) continue;
    if (p.regime == double(MapRegime::second_window)) second.points.push_back({by_re ? p.reynolds : p.alpha, p.ratio});
    if (p.regime == double(MapRegime::bistable)) both.points.push_back({by_re ? p.reynolds : p.alpha, p.ratio});
  }
  // Where the computed 3D onset says the flow is three-dimensional: the 2D answer is not the real flow.
  PointSet three;
  three.label = "3D: above the computed onset";
  three.colour = Colour::black;
  three.marker = 6;  // □ around the point
  for (const auto& p : m.points)
    if (const auto real = two_d_is_real(p.reynolds, p.alpha, onset); std::isfinite(p.ratio) && real && !*real)
      three.points.push_back({by_re ? p.reynolds : p.alpha, p.ratio});
  std::vector<PointSet> sets;
  for (auto& [r, s] : rows) sets.push_back(std::move(s));
  if (!avg.points.empty()) sets.push_back(std::move(avg));
  if (!second.points.empty()) sets.push_back(std::move(second));
  if (!both.points.empty()) sets.push_back(std::move(both));
  if (!three.points.empty()) sets.push_back(std::move(three));
  CurvePage page;
  page.title =
      fmt::format("{}: S/(2πρa^2) = C_L/C_L,ideal (n_θ {} × n_r {}; bars: each point's error estimate)",
                  m.base.title, m.n_theta, m.n_r);
  if (!onset.empty()) {
    const auto [lo, hi] = onset_alpha_range(onset);
    page.title += lo == hi ? fmt::format("; □ 3D, computed onset at α {:g}", lo)
                           : fmt::format("; □ 3D, computed onset over α {:g}…{:g}", lo, hi);
  }
  page.xlabel = by_re ? "Reynolds number Re = U·2a/ν" : "spin ratio α = aω/U";
  page.ylabel = "S/(2πρa^2) = C_L / (−2πα)";
  const std::vector<LineCurve> lines;
  plot_curves(page, lines, sets, png, size);
}

}  // namespace magnus
