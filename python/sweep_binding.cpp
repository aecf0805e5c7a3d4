// _magnus._sweep: the potential-flow sweep (one factorization, two solves, every point by superposition)
// as columns named as in the sweep file's /sweep group (`magnus sweep -o`), with their units. An undefined
// value is NaN here only on its way to python/magnus/__init__.py, which masks it.
#include <pybind11/stl.h>

#include <cmath>
#include <fmt/core.h>

#include <functional>

#include "postproc/potential/sweep.hpp"
#include "bindings.hpp"

namespace magnus::python {

namespace {

/// One column: the name and unit of the sweep file's dataset, and its value from a table row.
struct Column {
  const char* name;
  const char* units;
  const char* description;
  std::function<double(const SweepRow&)> get;
};

double rad(double degrees) { return degrees * M_PI / 180.0; }

const std::vector<Column>& columns() {
  static const std::vector<Column> table = {
      {"alpha", "1", "spin ratio aω/U (circulation sweep: Γ/(2πaU))", [](const SweepRow& r) { return r.alpha; }},
      {"circulation", "m^2/s", "circulation Γ", [](const SweepRow& r) { return r.circulation; }},
      {"lift", "N/m", "lift per unit span (across the freestream), numeric", [](const SweepRow& r) { return r.lift; }},
      {"drag", "N/m", "drag per unit span (along the freestream), numeric", [](const SweepRow& r) { return r.drag; }},
      {"cl", "1", "lift coefficient, numeric", [](const SweepRow& r) { return r.cl; }},
      {"cl_kutta_joukowski", "1", "Kutta–Joukowski −Γ/(Ua)", [](const SweepRow& r) { return r.cl_kj; }},
      {"cl_seed_estimate", "1", "seed estimate −4aω/U", [](const SweepRow& r) { return r.cl_seed; }},
      {"cl_over_kj_minus_1", "1", "numeric / Kutta–Joukowski − 1", [](const SweepRow& r) { return r.cl_rel_kj; }},
      {"kj_over_seed", "1", "Kutta–Joukowski / seed estimate", [](const SweepRow& r) { return r.kj_over_seed; }},
      {"cd", "1", "drag coefficient, numeric", [](const SweepRow& r) { return r.cd; }},
      {"delta_p_top_bottom", "Pa", "p(a, π/2) − p(a, 3π/2), numeric", [](const SweepRow& r) { return r.delta_p; }},
      {"delta_p_seed_estimate", "Pa", "seed estimate 2ρUaω", [](const SweepRow& r) { return r.delta_p_seed; }},
      {"stagnation_theta1", "rad", "first stagnation point (smallest θ in [0, 2π))",
       [](const SweepRow& r) { return rad(r.stag_theta1_deg); }},
      {"stagnation_theta2", "rad", "second surface stagnation point (undefined for one free point)",
       [](const SweepRow& r) { return rad(r.stag_theta2_deg); }},
      {"stagnation_r_over_a", "1", "radius of the first stagnation point over a (1: on the surface)",
       [](const SweepRow& r) { return r.stag_r_over_a; }},
  };
  return table;
}

/// The sweep of a case over `values` (spin ratios, or circulations in m²/s): columns, units, descriptions,
/// and the grid, solver and timing it ran with.
py::dict sweep(const std::string& source, bool is_path, const std::string& variable,
               const std::vector<double>& values, const std::vector<std::string>& overrides, int threads) {
  const bool by_spin = variable == "spin_ratio";
  SweepResult s;
  {
    py::gil_scoped_release nogil;
    // As `magnus sweep`: the sweep sets the spin itself, so the case need not state one; the case's own
    // spin key and the overrides still replace it.
    std::vector<std::string> sets;
    if (by_spin) sets.push_back(fmt::format("cylinder.spin_ratio={}", values.front()));
    sets.insert(sets.end(), overrides.begin(), overrides.end());
    const Case c = case_of(source, is_path, sets);
    if (c.model == FlowModel::navier_stokes)
      throw std::runtime_error(
          (is_path ? source : std::string("<dict>")) +
          ": model.flow = \"navier-stokes\": magnus.sweep sweeps potential flow by superposition; the viscous "
          "continuation and S(Re, α) map run on the command line: magnus sweep CASE --spin-ratio A:B:STEP");
    s = by_spin ? sweep_spin_ratio(c, values, threads) : sweep_circulation(c, values, threads);
  }
  std::vector<SweepRow> rows;
  rows.reserve(s.points.size());
  for (const SweepPoint& p : s.points) rows.push_back(sweep_row(s, p));
  py::dict cols, units, descriptions;
  for (const Column& col : columns()) {
    std::vector<double> v(rows.size());
    for (size_t k = 0; k < rows.size(); ++k) v[k] = col.get(rows[k]);
    cols[col.name] = owned_array(std::move(v), {py::ssize_t(rows.size())});
    units[col.name] = col.units;
    descriptions[col.name] = col.description;
  }
  py::dict out;
  out["columns"] = cols;
  out["units"] = units;
  out["descriptions"] = descriptions;
  out["case"] = s.base.source_text;
  out["method"] = s.method;
  out["grid"] = py::dict(py::arg("n_r") = s.grid.n_r, py::arg("n_theta") = s.grid.n_theta,
                         py::arg("outer_radius") = s.grid.outer_radius() / s.grid.a);
  out["timing"] = py::dict(py::arg("linear_solves") = s.linear_solves, py::arg("assemble_s") = s.assemble_s,
                           py::arg("factor_s") = s.factor_s, py::arg("solve_s") = s.solve_s,
                           py::arg("evaluate_s") = s.evaluate_s, py::arg("total_s") = s.total_s);
  return out;
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("_sweep", &sweep, "lift against spin ratio or circulation by superposition", py::arg("source"),
        py::arg("is_path"), py::arg("variable"), py::arg("values"), py::arg("overrides"), py::arg("threads"));
}

}  // namespace magnus::python
