#include "plot/ns_map_plot.hpp"

#include <fmt/core.h>

#include <cmath>
#include <map>

namespace magnus {

void plot_ns_map(const NsMap& m, const std::string& png, PlotSize size) {
  static const Colour cycle[] = {Colour::blue,   Colour::red,   Colour::green, Colour::purple,
                                 Colour::orange, Colour::teal,  Colour::brown, Colour::magenta,
                                 Colour::olive,  Colour::black, Colour::grey};
  std::map<int, PointSet> rows;
  std::vector<PointSet> averaged;
  for (const auto& p : m.points) {
    if (!std::isfinite(p.ratio)) continue;
    PointSet& s = rows[p.row];
    if (s.label.empty()) {
      s.label = fmt::format("Re {:g}", p.reynolds);
      s.colour = cycle[size_t(p.row) % (sizeof cycle / sizeof cycle[0])];
      s.joined = true;
      s.marker = 0;
    }
    s.points.push_back({p.alpha, p.ratio});
  }
  PointSet avg;
  avg.label = "time-averaged";
  avg.colour = Colour::black;
  avg.marker = 5;
  for (const auto& p : m.points)
    if (std::isfinite(p.ratio) &&
        (p.source == MapSource::averaged_unstable || p.source == MapSource::averaged_no_steady))
      avg.points.push_back({p.alpha, p.ratio});
  std::vector<PointSet> sets;
  for (auto& [r, s] : rows) sets.push_back(std::move(s));
  if (!avg.points.empty()) sets.push_back(std::move(avg));
  CurvePage page;
  page.title =
      fmt::format("{}: S/(2πρa^2) = C_L/C_L,ideal (n_θ {} × n_r {})", m.base.title, m.n_theta, m.n_r);
  page.xlabel = "spin ratio α = aω/U";
  page.ylabel = "S/(2πρa^2) = C_L / (−2πα)";
  const std::vector<LineCurve> lines;
  plot_curves(page, lines, sets, png, size);
}

}  // namespace magnus
