// write_result: a FlowResult as a magnus-flow file, format version 2, from the schema table.
#include <fmt/core.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/finite.hpp"
#include "io/hdf5_io.hpp"
#include "io/schema.hpp"
#include "io/xdmf.hpp"

namespace magnus {

namespace {

std::string group_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

void write_file(const FlowResult& r, H5Writer& w) {
  std::map<std::string, H5Writer::id> groups{{"/", w.file()}};
  std::map<std::string, std::vector<std::string>> undefined;
  auto group = [&](const std::string& name) {
    auto it = groups.find(name);
    return it != groups.end() ? it->second : (groups[name] = w.group(name));
  };

  for (const AttrSpec& a : result_attributes()) {
    if (!applies(a.models, r)) continue;
    const H5Writer::id g = group(a.group);
    if (a.kind == AttrKind::text) {
      w.attr(g, a.name, a.text(r));
      continue;
    }
    const std::optional<double> v = a.number(r);
    if (!v || !std::isfinite(*v)) {  // never NaN in a file: omitted and listed
      undefined[a.group].push_back(a.name);
      continue;
    }
    if (a.kind == AttrKind::integer)
      w.attr(g, a.name, long(*v));
    else
      w.attr(g, a.name, *v);
    w.attr(g, units_attribute(a.name).c_str(), a.units);
  }

  const size_t nr = r.grid.n_r, nt = r.grid.n_theta;
  const FieldSelection selected = select_fields(r.c.output.fields, r.c.model);
  std::vector<std::string> on_grid, on_theta;
  for (const DatasetSpec& d : result_datasets()) {
    if (!applies(d.models, r)) continue;
    const std::vector<double> v = d.values(r);
    const std::string name = d.path.substr(d.path.rfind('/') + 1);
    const bool is_field = d.path.rfind("/fields/", 0) == 0;
    if (v.empty() && d.shape != DataShape::points) {
      // A field not asked for is simply absent; one asked for (or a surface value) that is empty is
      // undefined.
      if (!is_field || selected.has(name)) undefined[group_of(d.path)].push_back(name);
      continue;
    }
    for (double x : v)
      if (!std::isfinite(x))
        throw std::runtime_error(fmt::format("{} holds a non-finite value: not written", d.path));
    std::vector<size_t> shape = {v.size()};
    if (d.shape == DataShape::grid) shape = {nr, nt};
    if (shape[0] * (shape.size() > 1 ? shape[1] : 1) != v.size())
      throw std::runtime_error(fmt::format("{} has {} values, not {} × {}", d.path, v.size(), nr, nt));
    w.dataset(group(group_of(d.path)), name, shape, v.data(), d.units, d.description);
    if (d.shape == DataShape::grid) on_grid.push_back(d.path);
    if (d.shape == DataShape::n_theta && d.path != "/grid/theta") on_theta.push_back(d.path);
  }
  for (const auto& [g, names] : undefined) w.attr(group(g), "undefined", join(names));

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
