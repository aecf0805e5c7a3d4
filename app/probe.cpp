#include "app/probe.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "io/case_keys.hpp"
#include "postproc/potential/fields.hpp"
#include "postproc/probe.hpp"

namespace magnus {

std::pair<double, double> parse_probe_point(const std::string& text) {
  const size_t comma = text.find(',');
  auto number = [&](const std::string& s, double& v) {
    const char* begin = s.c_str();
    char* end = nullptr;
    errno = 0;
    v = std::strtod(begin, &end);
    return !s.empty() && end == begin + s.size() && errno != ERANGE && std::isfinite(v);
  };
  double x = 0.0, y = 0.0;
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos ||
      !number(text.substr(0, comma), x) || !number(text.substr(comma + 1), y))
    throw std::invalid_argument(fmt::format(
        "point '{}': expected x,y in metres (two finite numbers, e.g. 0.2,-0.05)", cut_input(text)));
  return {x, y};
}

ProbeTable probe_file(const std::string& path, const std::vector<std::pair<double, double>>& points) {
  const ProbeFields d = read_probe_fields(path);
  const PolarGrid& g = d.grid;
  ProbeTable t;
  t.file = path;
  t.model = d.model;
  t.stencil = d.stencil;
  t.field_order =
      derivative_order(t.stencil == "9-point" ? StencilKind::nine_point : StencilKind::five_point);
  t.points = probe_points(t.field_order);
  t.radius = g.a;
  const double beta = d.direction_deg;
  for (const auto& [x, y] : points) {
    const WorldForce w = rotate_deg(x, y, -beta);
    const ProbeStencil s = probe_stencil(g, w.x, w.y, t.points);
    ProbeSample q;
    q.x = x, q.y = y, q.r = s.r, q.theta = beta == 0.0 ? s.theta : std::atan2(y, x);
    if (q.theta < 0.0) q.theta += 2.0 * M_PI;
    q.u_x = probe_value(s, d.u_x, g.n_theta);
    q.u_y = probe_value(s, d.u_y, g.n_theta);
    q.pressure = probe_value(s, d.pressure, g.n_theta);
    if (!d.cp.empty()) q.cp = probe_value(s, d.cp, g.n_theta);
    t.samples.push_back(q);
  }
  return t;
}

}  // namespace magnus
