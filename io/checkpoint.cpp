#include "io/checkpoint.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "io/hdf5_io.hpp"

namespace magnus {

namespace {

constexpr const char* kFormat = "magnus-checkpoint";

/// The history's columns: name and member.
const std::vector<std::pair<const char*, double ForceSample::*>>& history_columns() {
  static const std::vector<std::pair<const char*, double ForceSample::*>> c = {
      {"t", &ForceSample::t},     {"cl", &ForceSample::C_L},  {"cd", &ForceSample::C_D},
      {"cm", &ForceSample::C_M},  {"fx", &ForceSample::F_x},  {"fy", &ForceSample::F_y},
      {"torque", &ForceSample::M}};
  return c;
}

}  // namespace

std::string checkpoint_path(const std::string& result_path) {
  const size_t slash = result_path.rfind('/');
  const size_t dot = result_path.rfind('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? result_path.substr(0, dot) : result_path) + ".checkpoint.h5";
}

std::string checkpoint_key(const Case& c) {
  const NsParams p = ns_params(c);
  const PolarGrid g = ns_grid(p);  // the grid as built: n_r = 0 asks for square cells
  return fmt::format("a={:.17g} U={:.17g} omega={:.17g} nu={:.17g} rho={:.17g} R/a={:.17g} n_theta={} n_r={}",
                     p.a, p.U, p.omega, p.nu, c.scene.density, g.outer_radius() / p.a, g.n_theta, g.n_r);
}

void write_checkpoint(const std::string& path, const Case& c, const Checkpoint& cp) {
  write_hdf5_atomic(path, [&](H5Writer& w) {
    const H5Writer::id root = w.file();
    w.attr(root, "format", kFormat);
    w.attr(root, "format_version", 1L);
    w.attr(root, "key", checkpoint_key(c));
    w.attr(root, "case", c.source_text);
    const NsState& s = cp.state;
    const H5Writer::id st = w.group("/state");
    w.attr_with_units(st, "t", s.t, "s");
    w.attr_with_units(st, "Gamma_R", s.Gamma_R, "m^2/s");
    w.attr_with_units(st, "Gamma_flux_prev", s.Gamma_flux_prev, "m^2/s^2");
    w.attr_with_units(st, "dt_prev", s.dt_prev, "s");
    w.dataset(st, "psi", {s.psi.size()}, s.psi.data(), "m^2/s", "stream function ψ");
    w.dataset(st, "zeta", {s.zeta.size()}, s.zeta.data(), "1/s", "vorticity ζ");
    w.dataset(st, "N_prev", {s.N_prev.size()}, s.N_prev.data(), "m^2/s^2", "advection of the previous step");
    const H5Writer::id h = w.group("/history");
    std::vector<double> col(cp.history.size());
    for (const auto& [name, m] : history_columns()) {
      for (size_t q = 0; q < col.size(); ++q) col[q] = cp.history[q].*m;
      w.dataset(h, name, {col.size()}, col.data(), "", name);
    }
    const H5Writer::id sn = w.group("/snapshots");
    std::vector<double> t, psi, zeta;
    for (const Snapshot& x : cp.snapshots) {
      t.push_back(x.t);
      psi.insert(psi.end(), x.psi.begin(), x.psi.end());
      zeta.insert(zeta.end(), x.vorticity.begin(), x.vorticity.end());
    }
    w.dataset(sn, "t", {t.size()}, t.data(), "s");
    w.dataset(sn, "psi", {psi.size()}, psi.data(), "m^2/s");
    w.dataset(sn, "vorticity", {zeta.size()}, zeta.data(), "1/s");
  });
}

Checkpoint read_checkpoint(const std::string& path, const Case& c) {
  std::unique_ptr<ResultFile> f;
  try {
    f = std::make_unique<ResultFile>(path, std::vector<std::string>{kFormat});
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("--resume: {}", e.what()));
  }
  const std::string key = f->attr_string("/", "key"), want = checkpoint_key(c);
  if (key != want)
    throw std::runtime_error(fmt::format(
        "--resume: '{}' belongs to another scene or grid ({}; this case: {})", path, key, want));
  Checkpoint cp;
  NsState& s = cp.state;
  s.t = f->attr_double("/state", "t");
  s.Gamma_R = f->attr_double("/state", "Gamma_R");
  s.Gamma_flux_prev = f->attr_double("/state", "Gamma_flux_prev");
  s.dt_prev = f->attr_double("/state", "dt_prev");
  s.psi = f->dataset("/state/psi");
  s.zeta = f->dataset("/state/zeta");
  s.N_prev = f->dataset("/state/N_prev");
  const auto& cols = history_columns();
  std::vector<std::vector<double>> v;
  for (const auto& col : cols) v.push_back(f->dataset(std::string("/history/") + col.first));
  cp.history.resize(v[0].size());
  for (size_t k = 0; k < cols.size(); ++k) {
    if (v[k].size() != cp.history.size())
      throw std::runtime_error(fmt::format("--resume: '{}' is damaged: /history columns differ in length", path));
    for (size_t q = 0; q < v[k].size(); ++q) cp.history[q].*cols[k].second = v[k][q];
  }
  for (ForceSample& h : cp.history) h.has_coefficients = c.scene.speed > 0.0;
  const std::vector<double> t = f->dataset("/snapshots/t"), psi = f->dataset("/snapshots/psi"),
                            zeta = f->dataset("/snapshots/vorticity");
  const size_t n = s.psi.size();
  if (s.zeta.size() != n || psi.size() != t.size() * n || zeta.size() != t.size() * n)
    throw std::runtime_error(fmt::format("--resume: '{}' is damaged: its arrays do not match", path));
  for (size_t k = 0; k < t.size(); ++k)
    cp.snapshots.push_back({t[k], {psi.begin() + long(k * n), psi.begin() + long((k + 1) * n)},
                            {zeta.begin() + long(k * n), zeta.begin() + long((k + 1) * n)}});
  for (double x : s.psi)
    if (!std::isfinite(x)) throw std::runtime_error(fmt::format("--resume: '{}' holds a non-finite ψ", path));
  return cp;
}

}  // namespace magnus
