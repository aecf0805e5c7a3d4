#include "io/result_reader.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/schema.hpp"
#include "io/schema_io.hpp"

namespace magnus {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

/// Stagnation points: version 2 stores /stagnation/r and /stagnation/theta (and *_exact); version 1 a
/// (k, 2) table /stagnation/numeric (or exact) of (r, θ).
std::vector<StagnationPoint> read_points(const ResultFile& f, bool exact, double a) {
  std::vector<double> r, th;
  const std::string suffix = exact ? "_exact" : "";
  if (f.has("/stagnation/r" + suffix) && f.has("/stagnation/theta" + suffix)) {
    r = f.dataset("/stagnation/r" + suffix);
    th = f.dataset("/stagnation/theta" + suffix);
    if (r.size() != th.size())
      fail(fmt::format("'{}': /stagnation/r{} and theta{} differ in length", f.path(), suffix, suffix));
  } else {
    const std::string name = exact ? "/stagnation/exact" : "/stagnation/numeric";
    if (!f.has(name)) return {};
    std::vector<size_t> shape;
    const auto v = f.dataset(name, &shape);
    if (v.empty()) return {};
    if (shape.size() != 2 || shape[1] != 2)
      fail(fmt::format("'{}': {} is not a (k, 2) table of (r, theta)", f.path(), name));
    for (size_t k = 0; k < shape[0]; ++k) r.push_back(v[2 * k]), th.push_back(v[2 * k + 1]);
  }
  std::vector<StagnationPoint> out;
  for (size_t k = 0; k < r.size(); ++k) out.push_back({r[k], th[k], std::fabs(r[k] - a) <= 1e-9 * a});
  return out;
}

/// The stored states of a navier-stokes run (/snapshots/t, psi, vorticity), each checked against the grid.
void read_snapshots(const ResultFile& f, FlowResult& r) {
  if (!f.has("/snapshots/t")) return;
  const std::vector<double> t = f.dataset("/snapshots/t");
  const size_t n = t.size(), nr = size_t(r.grid.n_r), nt = size_t(r.grid.n_theta), per = nr * nt;
  std::vector<Snapshot> states(n);
  for (size_t k = 0; k < n; ++k) states[k].t = t[k];
  for (const auto& [name, member] :
       {std::pair{"psi", &Snapshot::psi}, std::pair{"vorticity", &Snapshot::vorticity}}) {
    const std::string path = std::string("/snapshots/") + name;
    if (!f.has(path)) fail(fmt::format("'{}': /snapshots/t is there but {} is missing", f.path(), path));
    std::vector<size_t> shape;
    const std::vector<double> v = f.dataset(path, &shape);
    if (shape.size() != 3 || shape[0] != n || shape[1] != nr || shape[2] != nt)
      fail(fmt::format("'{}': {} is not ({} × {} × {}): one state per time on the grid", f.path(), path, n,
                       nr, nt));
    for (size_t k = 0; k < n; ++k)
      (states[k].*member).assign(v.begin() + long(k * per), v.begin() + long((k + 1) * per));
  }
  if (!r.viscous) r.viscous.emplace();
  r.viscous->snapshots = std::move(states);
}

}  // namespace

FlowResult read_result(const std::string& path) {
  check_result(path);  // what inspect refuses (a missing attribute, a bad checksum) is refused here too
  const ResultFile f(path);
  FlowResult r;
  Case& c = r.c;
  // Every attribute of the schema the file holds (versions 1 and 2 share the names).
  read_attrs(result_attributes(), f, r, true);
  for (const char* required : {"radius", "speed", "spin", "density", "pressure_inf", "circulation"})
    if (!f.has_attr("/parameters", required))
      fail(fmt::format("'{}': /parameters has no attribute '{}'", path, required));
  if (!(c.scene.radius > 0.0)) fail(fmt::format("'{}': /parameters radius is not positive", path));

  PolarGrid& g = r.grid;
  g.a = c.scene.radius;
  g.spacing = c.grid.spacing;
  g.r = f.dataset("/grid/r");
  g.theta = f.dataset("/grid/theta");
  g.n_r = int(g.r.size());
  g.n_theta = int(g.theta.size());
  if (g.n_r < 2 || g.n_theta < 4) fail(fmt::format("'{}': the grid is too small to plot", path));
  g.d_theta = 2.0 * M_PI / g.n_theta;
  for (double ri : g.r) g.xi.push_back(std::log(ri / g.a));
  c.grid.n_theta = g.n_theta;
  c.grid.n_r = g.n_r;
  if (!f.has_attr("/parameters", "outer_radius_requested")) c.grid.outer_radius = g.outer_radius() / g.a;

  // The fields and the surface that are present, each checked against the grid.
  for (const DatasetSpec& d : result_datasets()) {
    if (!d.set || d.path.rfind("/grid/", 0) == 0 || !f.has(d.path)) continue;
    std::vector<size_t> shape;
    std::vector<double> v = f.dataset(d.path, &shape);
    if (d.shape == DataShape::grid &&
        (shape.size() != 2 || shape[0] != size_t(g.n_r) || shape[1] != size_t(g.n_theta)))
      fail(fmt::format("'{}': {} does not match the grid ({} × {})", path, d.path, g.n_r, g.n_theta));
    if (d.shape == DataShape::n_theta && v.size() != size_t(g.n_theta))
      fail(fmt::format("'{}': {} has {} values for n_theta = {}", path, d.path, v.size(), g.n_theta));
    d.set(r, std::move(v));
  }
  // Potential flow's Cp comes with its exact curve (a navier-stokes result has none).
  if (!r.viscous && r.surface.cp.empty() != r.surface.cp_exact.empty())
    r.surface.cp.clear(), r.surface.cp_exact.clear();

  read_snapshots(f, r);
  r.stagnation = read_points(f, false, c.scene.radius);
  r.stagnation_exact = read_points(f, true, c.scene.radius);
  return r;
}

}  // namespace magnus
