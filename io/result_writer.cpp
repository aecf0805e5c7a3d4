// write_result: a FlowResult as a magnus-flow file, format version 2, from the schema table.
#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "physics/checked_cast.hpp"
#include "io/finite.hpp"
#include "io/hdf5_io.hpp"
#include "io/schema.hpp"
#include "io/schema_io.hpp"
#include "io/xdmf.hpp"

namespace magnus {

namespace {

std::string group_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == 0 ? "/" : path.substr(0, slash);
}

bool is_snapshot(const DatasetSpec& d) { return d.path.rfind("/snapshots/", 0) == 0; }

/// The stored states of a navier-stokes run: /snapshots/t (N) and each field (N, n_r, n_θ), each state
/// stored once (the .xmf's time series views them); t, r and θ are their dimension scales. Nothing when
/// there are none.
void write_snapshots(const FlowResult& r, H5Writer& w) {
  if (!r.viscous || r.viscous->snapshots.empty()) return;
  const size_t n = r.viscous->snapshots.size(), nr = r.grid.n_r, nt = r.grid.n_theta;
  for (const Snapshot& s : r.viscous->snapshots)
    if (s.psi.size() != nr * nt || s.vorticity.size() != nr * nt)
      throw std::runtime_error(
          fmt::format("the snapshot at t = {} s does not match the grid ({} × {})", s.t, nr, nt));
  const H5Writer::id g = w.group("/snapshots");
  for (const DatasetSpec& d : result_datasets()) {
    if (!is_snapshot(d)) continue;
    const std::vector<double> v = d.values(r);
    const std::string name = d.path.substr(d.path.rfind('/') + 1);
    const std::vector<size_t> shape = name == "t" ? std::vector<size_t>{n} : std::vector<size_t>{n, nr, nt};
    w.dataset(g, name, shape, v.data(), d.units, description_of(d, true));
  }
  w.make_scale("/snapshots/t", "t");
  for (const DatasetSpec& d : result_datasets())
    if (is_snapshot(d) && d.path != "/snapshots/t") {
      w.attach_scale(d.path, "/snapshots/t", 0);
      w.attach_scale(d.path, "/grid/r", 1);
      w.attach_scale(d.path, "/grid/theta", 2);
    }
}

void write_file(const FlowResult& r, H5Writer& w) {
  FileGroups group{w};
  std::vector<AttrValue> values;
  for (const AttrSpec& a : result_attributes())
    if (applies(a.models, r)) values.push_back(value_of(a, r));
  write_attrs(values, group);

  const size_t nr = r.grid.n_r, nt = r.grid.n_theta;
  const FieldSelection selected = select_fields(r.c.output.fields, r.c.model);
  std::vector<std::string> on_grid, on_theta;
  for (const DatasetSpec& d : result_datasets()) {
    if (!applies(d.models, r) || is_snapshot(d)) continue;
    const std::vector<double> v = d.values(r);
    const std::string name = d.path.substr(d.path.rfind('/') + 1);
    const bool is_field = d.path.rfind("/fields/", 0) == 0;
    if (v.empty() && d.shape == DataShape::levels) continue;  // a study with no grid (it failed on all)
    if (v.empty() && d.shape != DataShape::points) {
      // A field not asked for is simply absent; one asked for (or a surface value) that is empty is
      // undefined.
      if (!is_field || selected.has(name)) group.undefined[group_of(d.path)].push_back(name);
      continue;
    }
    for (double x : v)
      if (!std::isfinite(x))
        throw std::runtime_error(fmt::format("{} holds a non-finite value: not written", d.path));
    std::vector<size_t> shape = {v.size()};
    if (d.shape == DataShape::grid) shape = {nr, nt};
    if (shape[0] * (shape.size() > 1 ? shape[1] : 1) != v.size())
      throw std::runtime_error(fmt::format("{} has {} values, not {} × {}", d.path, v.size(), nr, nt));
    w.dataset(group(group_of(d.path)), name, shape, v.data(), d.units,
              description_of(d, r.viscous.has_value()));
    if (d.shape == DataShape::grid) on_grid.push_back(d.path);
    if (d.shape == DataShape::n_theta && d.path != "/grid/theta") on_theta.push_back(d.path);
  }
  write_undefined(group);

  // r and θ are the dimension scales of every (n_r, n_θ) dataset and θ of the surface (xarray and
  // h5netcdf then see named coordinates).
  w.make_scale("/grid/r", "r");
  w.make_scale("/grid/theta", "theta");
  for (const auto& p : on_grid) {
    w.attach_scale(p, "/grid/r", 0);
    w.attach_scale(p, "/grid/theta", 1);
  }
  for (const auto& p : on_theta) w.attach_scale(p, "/grid/theta", 0);
  // A netCDF reader (h5netcdf, so xarray) resolves a dimension in the variable's group or a parent group,
  // not in a sibling like /grid: the scales are named in the root group too (hard links, no copy).
  w.link("/grid/r", "/r");
  w.link("/grid/theta", "/theta");

  write_snapshots(r, w);

  write_mesh(r, w);
}

}  // namespace

void write_result(const FlowResult& r, const std::string& path, int compression) {
  check_finite(r);  // nothing that is not finite is written
  write_hdf5_atomic(
      path, [&](H5Writer& w) { write_file(r, w); }, {{xdmf_path(path), xdmf_text(r, base_of(path))}},
      compression);
}

}  // namespace magnus
