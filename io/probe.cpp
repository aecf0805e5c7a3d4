#include "io/probe.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/case_keys.hpp"
#include "io/inspect.hpp"
#include "io/text_format.hpp"
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
    throw std::invalid_argument(
        fmt::format("point '{}': expected x,y in metres (two finite numbers, e.g. 0.2,-0.05)", cut_input(text)));
  return {x, y};
}

ProbeTable probe_file(const std::string& path, const std::vector<std::pair<double, double>>& points) {
  check_result(path);  // what inspect refuses is refused here too
  const ResultFile f(path);
  ProbeTable t;
  t.file = path;
  t.model = f.has_attr("/", "model") ? f.attr_string("/", "model") : "potential";
  t.stencil = f.has_attr("/parameters", "stencil") ? f.attr_string("/parameters", "stencil") : "5-point";
  t.field_order =
      derivative_order(t.stencil == "9-point" ? StencilKind::nine_point : StencilKind::five_point);
  t.points = probe_points(t.field_order);
  for (const char* p : {"/grid/r", "/grid/theta"})
    if (!f.has(p))
      throw std::runtime_error(fmt::format("'{}' is not a complete magnus result: no {}", path, p));
  PolarGrid g;
  g.r = f.dataset("/grid/r");
  g.theta = f.dataset("/grid/theta");
  g.n_r = int(g.r.size());
  g.n_theta = int(g.theta.size());
  if (g.r.empty()) throw std::runtime_error(fmt::format("'{}': /grid/r is empty", path));
  g.a = g.r.front();
  t.radius = g.a;
  const size_t n = g.r.size() * g.theta.size();
  auto field = [&](const char* name, bool required) {
    const std::string p = std::string("/fields/") + name;
    if (!f.has(p)) {
      if (!required) return std::vector<double>();
      throw std::runtime_error(fmt::format(
          "'{}' holds no {}: probe needs u_x, u_y and pressure (output.fields left it out)", path, p));
    }
    std::vector<double> v = f.dataset(p);
    if (v.size() != n)
      throw std::runtime_error(
          fmt::format("'{}' is damaged: {} has {} values, not n_r·n_θ = {}", path, p, v.size(), n));
    return v;
  };
  const auto ux = field("u_x", true), uy = field("u_y", true), p = field("pressure", true),
             cp = field("cp", false);
  // The grid is the wind frame, the points and the stored u_x, u_y the world's (turned by flow.direction).
  const double beta = f.has_attr("/parameters", "direction") ? f.attr_double("/parameters", "direction") : 0.0;
  for (const auto& [x, y] : points) {
    const WorldForce w = rotate_deg(x, y, -beta);
    const ProbeStencil s = probe_stencil(g, w.x, w.y, t.points);
    ProbeSample q;
    q.x = x, q.y = y, q.r = s.r, q.theta = beta == 0.0 ? s.theta : std::atan2(y, x);
    if (q.theta < 0.0) q.theta += 2.0 * M_PI;
    q.u_x = probe_value(s, ux, g.n_theta);
    q.u_y = probe_value(s, uy, g.n_theta);
    q.pressure = probe_value(s, p, g.n_theta);
    if (!cp.empty()) q.cp = probe_value(s, cp, g.n_theta);
    t.samples.push_back(q);
  }
  return t;
}

namespace {

std::string interpolation_text(const ProbeTable& t) {
  return fmt::format("{}-point Lagrange in r and θ (error O(h^{})), fields of order {}", t.points, t.points,
                     t.field_order);
}

}  // namespace

std::string probe_text(const ProbeTable& t) {
  std::string s = fmt::format("magnus probe: {} ({}{})\n", t.file, t.model,
                              t.model == "potential" ? ", " + t.stencil + " stencil" : std::string());
  s += fmt::format("interpolation: {}\n\n", interpolation_text(t));
  s += fmt::format("{:>12} {:>12} {:>9} {:>9} {:>13} {:>13} {:>14} {:>12}\n", "x (m)", "y (m)", "r/a",
                   "θ (°)", "u_x (m/s)", "u_y (m/s)", "p (Pa)", "Cp");
  for (const auto& q : t.samples)
    s += fmt::format("{:>12} {:>12} {:>9} {:>9} {:>13} {:>13} {:>14} {:>12}\n", cell(q.x, "{:.6g}"),
                     cell(q.y, "{:.6g}"), cell(q.r / t.radius, "{:.5f}"),
                     cell(q.theta * 180.0 / M_PI, "{:.3f}"), cell(q.u_x, "{:.8g}"), cell(q.u_y, "{:.8g}"),
                     cell(q.pressure, "{:.10g}"), q.cp ? cell(*q.cp, "{:.6f}") : std::string("undefined"));
  return s;
}

std::string probe_csv(const ProbeTable& t) {
  std::string s = "x_m,y_m,r_m,theta_rad,u_x_m_s,u_y_m_s,pressure_Pa,cp\n";
  auto v = [](double x) { return fmt::format("{:.17g}", x + 0.0); };
  for (const auto& q : t.samples)
    s += fmt::format("{},{},{},{},{},{},{},{}\n", v(q.x), v(q.y), v(q.r), v(q.theta), v(q.u_x), v(q.u_y),
                     v(q.pressure), q.cp ? v(*q.cp) : std::string());
  return s;
}

Json probe_json(const ProbeTable& t) {
  Json j;
  j["file"] = t.file;
  j["model"] = t.model;
  if (t.model == "potential") j["stencil"] = t.stencil;
  j["field_order"] = count(t.field_order);
  j["interpolation_points"] = count(t.points);
  j["interpolation"] = interpolation_text(t);
  Json list = Json::array();
  for (const auto& q : t.samples) {
    Json o;
    o["x"] = quantity(q.x, "m");
    o["y"] = quantity(q.y, "m");
    o["r"] = quantity(q.r, "m");
    o["theta"] = quantity(q.theta, "rad");
    o["u_x"] = quantity(q.u_x, "m/s");
    o["u_y"] = quantity(q.u_y, "m/s");
    o["pressure"] = quantity(q.pressure, "Pa");
    o["cp"] = quantity(q.cp, "1");
    list.push_back(std::move(o));
  }
  j["points"] = std::move(list);
  return j;
}

}  // namespace magnus
