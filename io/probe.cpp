#include "io/probe.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/text_format.hpp"

namespace magnus {

ProbeFields read_probe_fields(const std::string& path) {
  check_result(path);  // what inspect refuses is refused here too
  const ResultFile f(path);
  ProbeFields d;
  d.model = f.has_attr("/", "model") ? f.attr_string("/", "model") : "potential";
  d.stencil = f.has_attr("/parameters", "stencil") ? f.attr_string("/parameters", "stencil") : "5-point";
  for (const char* p : {"/grid/r", "/grid/theta"})
    if (!f.has(p))
      throw std::runtime_error(fmt::format("'{}' is not a complete magnus result: no {}", path, p));
  PolarGrid& g = d.grid;
  g.r = f.dataset("/grid/r");
  g.theta = f.dataset("/grid/theta");
  g.n_r = int(g.r.size());
  g.n_theta = int(g.theta.size());
  if (g.r.empty()) throw std::runtime_error(fmt::format("'{}': /grid/r is empty", path));
  g.a = g.r.front();
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
  d.u_x = field("u_x", true), d.u_y = field("u_y", true), d.pressure = field("pressure", true);
  d.cp = field("cp", false);
  // The grid is the wind frame, the points and the stored u_x, u_y the world's (turned by flow.direction).
  d.direction_deg = f.has_attr("/parameters", "direction") ? f.attr_double("/parameters", "direction") : 0.0;
  return d;
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
