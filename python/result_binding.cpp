// _magnus.Result: a FlowResult seen from Python through the schema table (io/schema.hpp), so the names,
// values and units are those of the result file: forces, parameters, errors, timing (dicts; None where
// undefined), fields, grid, surface, history, stagnation (dicts of numpy arrays) and units.
#include <pybind11/stl.h>

#include <cmath>

#include "io/hdf5_io.hpp"
#include "io/schema.hpp"
#include "bindings.hpp"

namespace magnus::python {

namespace {

using Ptr = std::shared_ptr<const FlowResult>;

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

/// The attributes of one group ("/forces", "/parameters", "/errors", "/timing", "/") that apply to r:
/// numbers as float, integers as int, text as str; an undefined value is None.
py::dict attributes(const FlowResult& r, const std::string& group) {
  py::dict d;
  for (const AttrSpec& a : result_attributes()) {
    if (group != a.group || !applies(a.models, r)) continue;
    if (a.kind == AttrKind::text) {
      d[a.name] = a.text ? py::cast(a.text(r)) : py::none();
      continue;
    }
    const std::optional<double> v = a.number ? a.number(r) : std::nullopt;
    if (!v || !std::isfinite(*v))
      d[a.name] = py::none();
    else if (a.kind == AttrKind::integer)
      d[a.name] = py::int_(long(*v));
    else
      d[a.name] = py::float_(*v);
  }
  return d;
}

/// What is listed about a group's entries (attributes or datasets): their values, units or descriptions.
enum class Listing { values, units, descriptions };

/// The units (or one-line descriptions) of a group's numeric attributes.
py::dict attribute_units(const FlowResult& r, const std::string& group, Listing what = Listing::units) {
  py::dict d;
  for (const AttrSpec& a : result_attributes())
    if (group == a.group && applies(a.models, r) && a.kind != AttrKind::text)
      d[a.name] = what == Listing::units ? a.units : a.description;
  return d;
}

/// The datasets under `prefix` ("/surface/", "/history/", "/stagnation/") that apply to r and hold values
/// (or the units or descriptions of all that apply).
py::dict datasets(const Ptr& r, const std::string& prefix, Listing what) {
  py::dict d;
  for (const DatasetSpec& s : result_datasets()) {
    if (!starts_with(s.path, prefix) || !applies(s.models, *r)) continue;
    const std::string name = s.path.substr(prefix.size());
    if (what != Listing::values) {
      d[name.c_str()] = what == Listing::units ? s.units : description_of(s, r->viscous.has_value());
      continue;
    }
    std::vector<double> v = s.values(*r);
    if (v.empty()) continue;
    const auto n = py::ssize_t(v.size());
    d[name.c_str()] = owned_array(std::move(v), {n});
  }
  return d;
}

/// The (n_r, n_θ) fields present, as views of the result's own vectors.
py::dict fields(const Ptr& r) {
  py::dict d;
  for (const DatasetSpec* s : field_datasets()) {
    if (!applies(s->models, *r)) continue;
    const std::string name = s->path.substr(std::string("/fields/").size());
    const std::vector<double>& v = r->fields.get(name);
    if (v.empty()) continue;
    d[name.c_str()] = view_of(r, v, {py::ssize_t(r->grid.n_r), py::ssize_t(r->grid.n_theta)});
  }
  return d;
}

/// The units (or descriptions) of the fields present.
py::dict field_units(const FlowResult& r, Listing what = Listing::units) {
  py::dict d;
  for (const DatasetSpec* s : field_datasets())
    if (applies(s->models, r) && !r.fields.get(s->path.substr(8)).empty())
      d[s->path.substr(8).c_str()] = what == Listing::units ? s->units : description_of(*s, r.viscous.has_value());
  return d;
}

/// r (n_r) and θ (n_θ) as views, x = r cos θ and y = r sin θ (n_r, n_θ) computed.
py::dict grid(const Ptr& r) {
  py::dict d;
  d["r"] = view_of(r, r->grid.r, {py::ssize_t(r->grid.r.size())});
  d["theta"] = view_of(r, r->grid.theta, {py::ssize_t(r->grid.theta.size())});
  for (const char* name : {"x", "y"}) {
    const DatasetSpec* s = find_dataset(std::string("/grid/") + name);
    d[name] = owned_array(s->values(*r), {py::ssize_t(r->grid.n_r), py::ssize_t(r->grid.n_theta)});
  }
  return d;
}

/// navier-stokes: the stored states (output.snapshots) as t (N) and psi, vorticity (N, n_r, n_θ) views.
py::object snapshots(const Ptr& r) {
  if (!r->viscous) return py::none();
  const auto& states = r->viscous->snapshots;
  std::vector<double> t;
  for (const Snapshot& s : states) t.push_back(s.t);
  py::dict d;
  d["t"] = owned_array(std::move(t), {py::ssize_t(states.size())});
  for (const auto& [name, member] :
       {std::pair{"psi", &Snapshot::psi}, std::pair{"vorticity", &Snapshot::vorticity}}) {
    py::list each;
    for (const Snapshot& s : states)
      each.append(view_of(r, s.*member, {py::ssize_t(r->grid.n_r), py::ssize_t(r->grid.n_theta)}));
    // One (N, n_r, n_θ) array: the states are separate vectors, so this is the one copy made.
    d[name] = states.empty() ? owned_array({}, {0, py::ssize_t(r->grid.n_r), py::ssize_t(r->grid.n_theta)})
                             : py::module_::import("numpy").attr("stack")(each);
  }
  return d;
}

/// The unit (or the one-line description) of every value, by group, as the result file stores them.
py::dict units(const Ptr& r, Listing what) {
  py::dict d;
  for (const char* group : {"parameters", "forces", "errors", "timing"})
    d[group] = attribute_units(*r, std::string("/") + group, what);
  d["fields"] = field_units(*r, what);
  for (const char* group : {"grid", "surface", "stagnation", "history", "snapshots"})
    if (r->viscous || (group != std::string("history") && group != std::string("snapshots")))
      d[group] = datasets(r, std::string("/") + group + "/", what);
  return d;
}

}  // namespace

void bind_result(py::module_& m) {
  py::class_<PyResult>(m, "Result",
                       "One solved (or read) flow: the contents of a magnus-flow result file. Arrays are "
                       "read-only views of the result (copy with numpy.array to modify).")
      .def_property_readonly(
          "forces", [](const PyResult& p) { return attributes(*p.r, "/forces"); },
          "dict: the /forces attributes (lift, drag in N/m, cl, cd, …); None where undefined")
      .def_property_readonly(
          "parameters", [](const PyResult& p) { return attributes(*p.r, "/parameters"); },
          "dict: every resolved parameter (radius, spin, speed, …)")
      .def_property_readonly(
          "errors", [](const PyResult& p) { return attributes(*p.r, "/errors"); },
          "dict: errors against the exact solution (potential flow)")
      .def_property_readonly(
          "timing", [](const PyResult& p) { return attributes(*p.r, "/timing"); }, "dict: wall seconds per phase")
      .def_property_readonly(
          "attributes", [](const PyResult& p) { return attributes(*p.r, "/"); },
          "dict: the file's root attributes (model, title, case as TOML, …)")
      .def_property_readonly(
          "model", [](const PyResult& p) { return std::string(to_string(p.r->c.model)); },
          "'potential' or 'navier-stokes'")
      .def_property_readonly(
          "case", [](const PyResult& p) { return p.r->c.source_text; }, "the resolved case as TOML text")
      .def_property_readonly(
          "fields", [](const PyResult& p) { return fields(p.r); },
          "dict of (n_r, n_theta) arrays: psi, u_r, u_theta, u_x, u_y, pressure, cp, …")
      .def_property_readonly(
          "grid", [](const PyResult& p) { return grid(p.r); }, "dict: r (n_r), theta (n_theta), x, y (n_r, n_theta)")
      .def_property_readonly(
          "surface", [](const PyResult& p) { return datasets(p.r, "/surface/", Listing::values); },
          "dict of (n_theta) arrays on the body r = a: theta, u_theta, pressure, cp, …")
      .def_property_readonly(
          "stagnation", [](const PyResult& p) { return datasets(p.r, "/stagnation/", Listing::values); },
          "dict: r, theta (numeric) and r_exact, theta_exact of the stagnation points")
      .def_property_readonly(
          "history",
          [](const PyResult& p) -> py::object {
            if (!p.r->viscous) return py::none();
            return datasets(p.r, "/history/", Listing::values);
          },
          "navier-stokes: dict of (n_steps) arrays t, t_convective, cl, cd, cm, lift, drag, torque; "
          "None for potential flow")
      .def_property_readonly(
          "snapshots", [](const PyResult& p) { return snapshots(p.r); },
          "navier-stokes: dict of the stored states (output.snapshots): t (N), psi and vorticity "
          "(N, n_r, n_theta); None for potential flow")
      .def_property_readonly(
          "units", [](const PyResult& p) { return units(p.r, Listing::units); },
          "dict of dicts: the unit of every value, by group (forces, parameters, fields, …)")
      .def_property_readonly(
          "descriptions", [](const PyResult& p) { return units(p.r, Listing::descriptions); },
          "dict of dicts shaped like units: the one-line description of every value, as the file stores it")
      .def(
          "write",
          [](const PyResult& p, const py::object& where, int compression) {
            if (compression < 0 || compression > 9)
              throw std::invalid_argument("compression: must be a gzip level from 0 to 9");
            const auto path = py::module_::import("os").attr("fspath")(where).cast<std::string>();
            py::gil_scoped_release nogil;
            write_result(*p.r, path, compression);
          },
          "write the result as a magnus-flow HDF5 file (+ .xmf), atomically", py::arg("path"),
          py::arg("compression") = 0)
      .def("__repr__", [](const PyResult& p) {
        const FlowResult& r = *p.r;
        return "<magnus.Result " + std::string(to_string(r.c.model)) + " '" + r.c.title + "' " +
               std::to_string(r.grid.n_r) + "x" + std::to_string(r.grid.n_theta) + ">";
      });
}

}  // namespace magnus::python
