#include "io/result_reader.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "io/hdf5_io.hpp"

namespace magnus {

namespace {

std::vector<StagnationPoint> read_points(const ResultFile& f, const char* name, double a) {
  std::vector<StagnationPoint> out;
  if (!f.has(name)) return out;
  std::vector<size_t> shape;
  const auto v = f.dataset(name, &shape);
  if (v.empty()) return out;
  if (shape.size() != 2 || shape[1] != 2)
    throw std::runtime_error(fmt::format("'{}': {} is not a (k, 2) table of (r, theta)", f.path(), name));
  for (size_t k = 0; k < shape[0]; ++k) {
    const double r = v[2 * k], th = v[2 * k + 1];
    out.push_back({r, th, std::fabs(r - a) <= 1e-9 * a});
  }
  return out;
}

}  // namespace

FlowResult read_result(const std::string& path) {
  const ResultFile f(path);
  FlowResult r;
  Case& c = r.c;
  c.title = f.has_attr("/", "title") ? f.attr_string("/", "title") : std::string("Spinning cylinder");
  c.scene.radius = f.attr_double("/parameters", "radius");
  c.scene.speed = f.attr_double("/parameters", "speed");
  c.scene.spin = f.attr_double("/parameters", "spin");
  c.scene.density = f.attr_double("/parameters", "density");
  c.scene.pressure_inf = f.attr_double("/parameters", "pressure_inf");
  c.scene.circulation_given =
      f.has_attr("/parameters", "circulation_model") && f.attr_string("/parameters", "circulation_model") == "given";
  c.scene.circulation_value = f.attr_double("/parameters", "circulation");
  if (f.has_attr("/parameters", "spacing"))
    c.grid.spacing = f.attr_string("/parameters", "spacing") == "uniform" ? Spacing::uniform : Spacing::geometric;
  if (f.has_attr("/parameters", "stencil"))
    c.solver.stencil = f.attr_string("/parameters", "stencil") == "9-point" ? StencilKind::nine_point : StencilKind::five_point;
  if (!(c.scene.radius > 0.0)) throw std::runtime_error(fmt::format("'{}': /parameters radius is not positive", path));

  PolarGrid& g = r.grid;
  g.a = c.scene.radius;
  g.spacing = c.grid.spacing;
  g.r = f.dataset("/grid/r");
  g.theta = f.dataset("/grid/theta");
  g.n_r = int(g.r.size());
  g.n_theta = int(g.theta.size());
  if (g.n_r < 2 || g.n_theta < 4) throw std::runtime_error(fmt::format("'{}': the grid is too small to plot", path));
  g.d_theta = 2.0 * M_PI / g.n_theta;
  for (double ri : g.r) g.xi.push_back(std::log(ri / g.a));
  c.grid.n_theta = g.n_theta;
  c.grid.n_r = g.n_r;
  c.grid.outer_radius = g.outer_radius() / g.a;

  auto field = [&](const char* name, std::vector<double>& into) {
    const std::string obj = std::string("/fields/") + name;
    if (!f.has(obj)) return;
    std::vector<size_t> shape;
    into = f.dataset(obj, &shape);
    if (shape.size() != 2 || shape[0] != size_t(g.n_r) || shape[1] != size_t(g.n_theta))
      throw std::runtime_error(fmt::format("'{}': {} does not match the grid ({} × {})", path, obj, g.n_r, g.n_theta));
  };
  field("psi", r.fields.psi);
  field("cp", r.fields.cp);

  auto surface = [&](const char* name, std::vector<double>& into) {
    const std::string obj = std::string("/surface/") + name;
    if (!f.has(obj)) return;
    into = f.dataset(obj);
    if (into.size() != size_t(g.n_theta))
      throw std::runtime_error(fmt::format("'{}': {} has {} values for n_theta = {}", path, obj, into.size(), g.n_theta));
  };
  surface("theta", r.surface.theta);
  surface("u_theta", r.surface.u_theta);
  surface("pressure", r.surface.pressure);
  surface("cp", r.surface.cp);
  surface("cp_exact", r.surface.cp_exact);
  if (r.surface.cp.empty() != r.surface.cp_exact.empty()) r.surface.cp.clear(), r.surface.cp_exact.clear();

  r.stagnation = read_points(f, "/stagnation/numeric", c.scene.radius);
  r.stagnation_exact = read_points(f, "/stagnation/exact", c.scene.radius);
  return r;
}

}  // namespace magnus
