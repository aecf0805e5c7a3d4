#include "io/json_output.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "io/compare.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/report_viscous.hpp"
#include "io/schema.hpp"
#include "postproc/forces.hpp"

namespace magnus {

Json quantity(std::optional<double> v, const std::string& units) {
  Json q;
  if (v && std::isfinite(*v))
    q["value"] = *v + 0.0;  // + 0.0: never -0
  else
    q["value"] = nullptr;
  q["units"] = units;
  return q;
}

Json count(long n) {
  Json q;
  q["value"] = n;
  q["units"] = "1";
  return q;
}

Json quantity(const std::vector<double>& v, const std::string& units) {
  Json a = Json::array();
  for (double x : v) a.push_back(std::isfinite(x) ? Json(x + 0.0) : Json(nullptr));
  Json q;
  q["value"] = std::move(a);
  q["units"] = units;
  return q;
}

std::string json_text(const Json& j) {
  return j.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

namespace {

/// "/forces" → "forces"; "/" → "" (the top level).
std::string key_of(const std::string& group) { return group.size() > 1 ? group.substr(1) : std::string(); }

/// A stagnation point: r in m and over a, θ in rad and degrees, on the surface or free.
Json point_json(const StagnationPoint& p, double a) {
  Json q;
  q["r"] = quantity(p.r, "m");
  q["r_over_a"] = quantity(a > 0.0 ? std::optional<double>(p.r / a) : std::nullopt, "1");
  q["theta"] = quantity(p.theta, "rad");
  q["theta_deg"] = quantity(p.theta * 180.0 / M_PI, "degree");
  q["on_surface"] = p.on_surface;
  return q;
}

Json points_json(const std::vector<StagnationPoint>& unsorted, double a) {
  Json list = Json::array();
  for (const auto& p : sorted_stagnation_points(unsorted)) list.push_back(point_json(p, a));
  return list;
}

/// The figures the potential summary derives from the stored ones.
Json potential_derived(const FlowResult& r, Json& j) {
  const Scene& sc = r.c.scene;
  const Forces& f = r.forces;
  const bool given = sc.circulation_given, moving = sc.speed > 0.0, spinning = sc.spin != 0.0;
  // The seed estimates lift from ω: with a given Γ and no spin it says nothing (the summary: undefined).
  if (given && !spinning)
    for (const char* k : {"cl_seed_estimate", "delta_p_seed_estimate"})
      if (j["forces"].contains(k)) j["forces"][k]["value"] = nullptr;
  Json d;
  d["nodes"] = count(r.grid.nodes());
  d["threads"] = count(r.info.threads);
  if (!r.info.grid_choice.empty()) d["grid_choice"] = r.info.grid_choice;
  if (given)
    d["alpha_circulation"] = quantity(
        moving ? std::optional<double>(sc.Gamma() / (2.0 * M_PI * sc.radius * sc.speed)) : std::nullopt, "1");
  const auto& kj = f.cl_kutta_joukowski;
  d["cl_over_kj_minus_1"] =
      quantity(f.cl && kj && *kj != 0.0 ? std::optional<double>(*f.cl / *kj - 1.0) : std::nullopt, "1");
  d["kj_over_seed"] = quantity(kj && spinning && f.cl_seed_estimate && *f.cl_seed_estimate != 0.0
                                   ? std::optional<double>(*kj / *f.cl_seed_estimate)
                                   : std::nullopt,
                               "1");
  d["delta_p_over_seed"] = quantity(
      f.delta_p_seed_estimate != 0.0 ? std::optional<double>(f.delta_p_top_bottom / f.delta_p_seed_estimate)
                                     : std::nullopt,
      "1");
  d["magnus_S_seed"] = quantity(4.0 * sc.density * sc.radius * sc.radius, "kg/m");
  return d;
}

/// The figures the navier-stokes summary derives from the stored ones.
Json viscous_derived(const FlowResult& r) {
  const Scene& sc = r.c.scene;
  const ViscousPart& v = *r.viscous;
  const PolarGrid& g = r.grid;
  Json d;
  d["nodes"] = count(g.nodes());
  if (v.reynolds && *v.reynolds > 0.0 && g.r.size() > 1) {
    const double alpha = sc.speed > 0.0 ? sc.spin_ratio() : 0.0;
    const double cells = (2.0 * g.a / std::sqrt(*v.reynolds * (1.0 + alpha * alpha))) / (g.r[1] - g.r[0]);
    d["wall_cells"] = quantity(cells, "1");
    d["wall_cells_coarse"] = cells < kWallCellsForPercent;
  }
  const bool unit = v.time_unit > 0.0;
  d["t_convective"] = quantity(unit ? std::optional<double>(v.t / v.time_unit) : std::nullopt, "1");
  d["dt_convective"] = quantity(unit ? std::optional<double>(v.dt / v.time_unit) : std::nullopt, "1");
  d["steps_per_second"] = quantity(
      r.timing.solve_s > 0.0 ? std::optional<double>(double(v.steps) / r.timing.solve_s) : std::nullopt,
      "1/s");
  d["three_dimensional"] = v.reynolds && *v.reynolds > kReynolds3D;
  if (sc.speed <= 0.0) {  // still fluid: the potential vortex u_θ = a²ω/r is an exact viscous solution
    const double nu = v.viscosity > 0.0 ? v.viscosity : sc.viscosity;
    const double exact = -4.0 * M_PI * sc.density * nu * sc.radius * sc.radius * sc.spin;
    d["torque_potential_vortex"] = quantity(exact, "N*m/m");
    d["torque_over_potential_vortex_minus_1"] =
        quantity(exact != 0.0 ? std::optional<double>(v.torque_mean / exact - 1.0) : std::nullopt, "1");
  }
  return d;
}

}  // namespace

Json result_json(const FlowResult& r, const std::string& output_path) {
  Json j;
  for (const AttrSpec& a : result_attributes()) {
    if (!applies(a.models, r)) continue;
    const std::string g = key_of(a.group), name = a.name;
    if (g.empty() && (name == "format" || name == "format_version")) continue;  // of the file, not the run
    Json value;
    if (a.kind == AttrKind::text)
      value = a.text(r);
    else if (const auto v = a.number(r); v && a.kind == AttrKind::integer)
      value = count(long(*v));
    else
      value = quantity(v, a.units);
    if (g.empty())
      j[name] = std::move(value);
    else
      j[g][name] = std::move(value);
  }
  if (r.viscous) {
    j["partial"] = r.viscous->partial;  // a yes/no, not a number
    j["derived"] = viscous_derived(r);
    j["separation"] = quantity(r.viscous->separation, "rad");
  } else {
    j["derived"] = potential_derived(r, j);
    Json st;
    st["numeric"] = points_json(r.stagnation, r.c.scene.radius);
    st["exact"] = points_json(r.stagnation_exact, r.c.scene.radius);
    bool outside = false;
    if (r.stagnation.empty())
      for (const auto& p : r.stagnation_exact)
        outside = outside || (!p.on_surface && p.r > r.grid.outer_radius());
    st["numeric_outside_grid"] = outside;
    j["stagnation"] = std::move(st);
  }
  if (!output_path.empty()) {
    j["output"]["file"] = output_path;
    j["output"]["xdmf"] = xdmf_path(output_path);
  }
  return j;
}

// ---------------------------------------------------------------------------------------------
// sweep

namespace {

/// The columns of a sweep point, named as the magnus-sweep file's datasets.
struct SweepColumn {
  const char* name;
  const char* units;
  double SweepRow::*member;
};

constexpr SweepColumn kSweepColumns[] = {
    {"alpha", "1", &SweepRow::alpha},
    {"circulation", "m^2/s", &SweepRow::circulation},
    {"lift", "N/m", &SweepRow::lift},
    {"drag", "N/m", &SweepRow::drag},
    {"cl", "1", &SweepRow::cl},
    {"cl_kutta_joukowski", "1", &SweepRow::cl_kj},
    {"cl_seed_estimate", "1", &SweepRow::cl_seed},
    {"cl_over_kj_minus_1", "1", &SweepRow::cl_rel_kj},
    {"kj_over_seed", "1", &SweepRow::kj_over_seed},
    {"cd", "1", &SweepRow::cd},
    {"delta_p_top_bottom", "Pa", &SweepRow::delta_p},
    {"delta_p_seed_estimate", "Pa", &SweepRow::delta_p_seed},
};

}  // namespace

Json sweep_json(const SweepResult& s, const ViscousReference* ref, const std::vector<std::string>& written) {
  const Case& c = s.base;
  const PolarGrid& g = s.grid;
  const bool by_spin = s.variable == SweepVariable::spin_ratio;
  Json j;
  j["software_version"] = MAGNUS_VERSION;
  j["model"] = "potential";
  j["title"] = c.title;
  j["variable"] = by_spin ? "spin_ratio" : "circulation";
  Json& p = j["parameters"];
  p["radius"] = quantity(c.scene.radius, "m");
  p["speed"] = quantity(c.scene.speed, "m/s");
  p["density"] = quantity(c.scene.density, "kg/m^3");
  p["pressure_inf"] = quantity(c.scene.pressure_inf, "Pa");
  p["circulation_model"] = c.scene.circulation_given ? "given" : "spin";
  if (!by_spin) {
    p["spin"] = quantity(c.scene.spin, "rad/s");
    p["spin_ratio"] =
        quantity(c.scene.speed > 0.0 ? std::optional<double>(c.scene.spin_ratio()) : std::nullopt, "1");
  }
  p["outer_radius"] = quantity(g.outer_radius() / g.a, "1");
  p["far_field"] = to_string(c.grid.far_field);
  p["spacing"] = to_string(g.spacing);
  p["n_r"] = count(g.n_r);
  p["n_theta"] = count(g.n_theta);
  p["method"] = s.method;
  p["stencil"] = to_string(c.solver.stencil);
  if (!s.grid_choice.empty()) j["grid_choice"] = s.grid_choice;
  Json& t = j["timing"];
  t["linear_solves"] = count(s.linear_solves);
  t["points"] = count(long(s.points.size()));
  t["assemble_s"] = quantity(s.assemble_s, "s");
  t["factor_s"] = quantity(s.factor_s, "s");
  t["solve_s"] = quantity(s.solve_s, "s");
  t["evaluate_s"] = quantity(s.evaluate_s, "s");
  t["total_s"] = quantity(s.total_s, "s");
  Json points = Json::array();
  for (const SweepPoint& pt : s.points) {
    const SweepRow w = sweep_row(s, pt);
    Json q;
    for (const SweepColumn& col : kSweepColumns) q[col.name] = quantity(w.*col.member, col.units);
    q["stagnation"] = points_json(pt.stagnation, pt.scene.radius);
    points.push_back(std::move(q));
  }
  j["points"] = std::move(points);
  if (ref && !s.points.empty()) {
    const double lo = sweep_row(s, s.points.front()).alpha, hi = sweep_row(s, s.points.back()).alpha;
    Json rows = Json::array();
    for (const auto& d : ref->datasets)
      for (const auto& pt : d.points) {
        if (pt.alpha < lo - 1e-9 || pt.alpha > hi + 1e-9) continue;
        Json q;
        q["alpha"] = quantity(pt.alpha, "1");
        q["reynolds"] = quantity(d.reynolds, "1");
        q["cl"] = quantity(pt.cl, "1");
        q["cd"] = quantity(pt.cd, "1");
        q["cl_ideal"] = quantity(-2.0 * M_PI * pt.alpha, "1");
        q["label"] = d.label;
        q["source"] = d.source;
        rows.push_back(std::move(q));
      }
    if (!rows.empty()) j["reference"] = std::move(rows);
  }
  j["output"] = written;
  return j;
}

// ---------------------------------------------------------------------------------------------
// files: compare and inspect

namespace {

bool bookkeeping(const std::string& name) {
  return name == "units" || name == "undefined" || name == "note" || name == "description" ||
         name == "_FillValue" || (name.size() > 6 && name.compare(name.size() - 6, 6, "_units") == 0);
}

bool is_viscous(const ResultFile& f) {
  return f.has_attr("/", "model") && f.attr_string("/", "model") == "navier-stokes";
}

bool belongs(Models m, const ResultFile& f) {
  return m == Models::all || (m == Models::viscous) == is_viscous(f);
}

/// An attribute as stored: text, or a number with its unit (the companion NAME_units, else the schema's).
Json stored_value(const ResultFile& f, const std::string& obj, const std::string& name) {
  if (f.attr_is_text(obj, name)) return f.attr_string(obj, name);
  std::string units;
  if (f.has_attr(obj, name + "_units") && f.attr_is_text(obj, name + "_units"))
    units = f.attr_string(obj, name + "_units");
  else if (const AttrSpec* a = find_attribute(obj, name))
    units = a->units;
  const AttrSpec* a = find_attribute(obj, name);
  if (a && a->kind == AttrKind::integer) return count(f.attr_int(obj, name));
  return quantity(f.attr_double(obj, name), units);
}

/// A group of a magnus-flow file: the schema's attributes of the file's model (null where undefined), then
/// any other attribute the file holds.
Json group_json(const ResultFile& f, const std::string& group) {
  Json j = Json::object();
  if (!f.has(group)) return j;
  std::set<std::string> shown;
  for (const AttrSpec& a : result_attributes()) {
    if (group != a.group || !belongs(a.models, f)) continue;
    shown.insert(a.name);
    if (f.has_attr(group, a.name))
      j[a.name] = stored_value(f, group, a.name);
    else if (a.kind != AttrKind::text)
      j[a.name] = quantity(std::nullopt, a.units);
  }
  for (const auto& name : f.attributes(group))
    if (!shown.count(name) && !bookkeeping(name)) j[name] = stored_value(f, group, name);
  if (group == "/" && j.contains("partial") && j["partial"].is_object())
    j["partial"] = j["partial"]["value"] == 1.0;
  return j;
}

/// The root attributes, the schema groups and (potential flow) the ratios the compare table shows.
Json flow_groups(const ResultFile& f) {
  Json j;
  j["file"] = f.path();
  const Json root = group_json(f, "/");
  for (auto it = root.begin(); it != root.end(); ++it) j[it.key()] = it.value();
  if (!j.contains("model")) j["model"] = "potential";  // version 1 files hold potential flow only
  for (const char* g : {"/parameters", "/forces", "/errors", "/timing"})
    if (f.has(g)) j[key_of(g)] = group_json(f, g);
  if (!is_viscous(f) && j.contains("forces")) {
    auto value = [&](const char* k) -> std::optional<double> {
      const Json& q = j["forces"].contains(k) ? j["forces"][k]["value"] : Json(nullptr);
      return q.is_number() ? std::optional<double>(q.get<double>()) : std::nullopt;
    };
    const auto cl = value("cl"), kj = value("cl_kutta_joukowski"), seed = value("cl_seed_estimate");
    j["derived"]["cl_over_kj_minus_1"] =
        quantity(cl && kj && *kj != 0.0 ? std::optional<double>(*cl / *kj - 1.0) : std::nullopt, "1");
    j["derived"]["kj_over_seed"] =
        quantity(kj && seed && *seed != 0.0 ? std::optional<double>(*kj / *seed) : std::nullopt, "1");
  }
  return j;
}

Json undefined_list(const ResultFile& f, const std::string& obj) {
  Json list = Json::array();
  if (!f.has_attr(obj, "undefined")) return list;
  const std::string s = f.attr_string(obj, "undefined");
  size_t at = 0;
  while (at < s.size()) {
    const size_t comma = std::min(s.find(", ", at), s.size());
    list.push_back(s.substr(at, comma - at));
    at = comma + 2;
  }
  return list;
}

Json shape_json(const std::vector<size_t>& shape) {
  std::vector<double> v(shape.begin(), shape.end());
  return quantity(v, "1");
}

Json inspect_flow(const ResultFile& f) {
  Json j = flow_groups(f);
  j["format"] = f.format();
  j["format_version"] = count(f.version());
  for (const char* g : {"/fields", "/surface"}) j["undefined"][key_of(g)] = undefined_list(f, g);
  const double a = f.has_attr("/parameters", "radius") ? f.attr_double("/parameters", "radius") : 0.0;
  if (!is_viscous(f)) {
    Json st;
    for (const bool exact : {false, true}) {
      const std::string sfx = exact ? "_exact" : "";
      std::vector<double> r, th;
      if (f.has("/stagnation/r" + sfx) && f.has("/stagnation/theta" + sfx)) {
        r = f.dataset("/stagnation/r" + sfx);
        th = f.dataset("/stagnation/theta" + sfx);
      } else if (f.has(exact ? "/stagnation/exact" : "/stagnation/numeric")) {  // version 1: (k, 2)
        const auto v = f.dataset(exact ? "/stagnation/exact" : "/stagnation/numeric");
        for (size_t k = 0; k + 1 < v.size(); k += 2) r.push_back(v[k]), th.push_back(v[k + 1]);
      }
      Json list = Json::array();
      for (size_t k = 0; k < std::min(r.size(), th.size()); ++k)
        list.push_back(point_json({r[k], th[k], a > 0.0 && std::fabs(r[k] / a - 1.0) < 1e-9}, a));
      st[exact ? "exact" : "numeric"] = std::move(list);
    }
    j["stagnation"] = std::move(st);
  } else {
    if (f.has("/separation/theta")) j["separation"] = quantity(f.dataset("/separation/theta"), "rad");
    Json ts;
    const double unit =
        f.has_attr("/parameters", "time_unit") ? f.attr_double("/parameters", "time_unit") : 0.0;
    auto span = [&](const std::string& path, const char* key) {
      const std::vector<double> t = f.has(path) ? f.dataset(path) : std::vector<double>();
      Json q;
      q["count"] = count(long(t.size()));
      if (!t.empty()) {
        q["t"] = quantity(std::vector<double>{t.front(), t.back()}, "s");
        if (unit > 0.0)
          q["t_convective"] = quantity(std::vector<double>{t.front() / unit, t.back() / unit}, "1");
      }
      ts[key] = std::move(q);
    };
    span("/history/t", "history");
    span("/snapshots/t", "snapshots");
    j["time_series"] = std::move(ts);
  }
  Json ds = Json::array();
  size_t values = 0, n_datasets = 0;
  for (const auto& [name, shape] : f.datasets()) {
    size_t n = 1;
    for (size_t d : shape) n *= d;
    values += n;
    ++n_datasets;
    if (name.rfind("/mesh/snapshots/", 0) == 0) continue;  // one view per state and field: counted only
    Json q;
    q["path"] = name;
    q["shape"] = shape_json(shape);
    std::string units = dataset_units(name);
    if (units.empty() && f.has_attr(name, "units")) units = f.attr_string(name, "units");
    q["units"] = units;
    if (const DatasetSpec* d = find_dataset(name)) q["description"] = d->description;
    ds.push_back(std::move(q));
  }
  j["datasets"] = std::move(ds);
  j["checked"]["datasets"] = count(long(n_datasets));
  j["checked"]["values"] = count(long(values));
  return j;
}

Json inspect_sweep(const ResultFile& f) {
  Json j;
  j["file"] = f.path();
  j["format"] = f.format();
  j["format_version"] = count(f.version());
  for (const auto& name : f.attributes("/"))
    if (!bookkeeping(name) && name != "format" && name != "format_version")
      j[name] = stored_value(f, "/", name);
  for (const char* g : {"/parameters", "/timing"}) {
    if (!f.has(g)) continue;
    Json q = Json::object();
    for (const auto& name : f.attributes(g))
      if (!bookkeeping(name)) q[name] = stored_value(f, g, name);
    j[key_of(g)] = std::move(q);
  }
  Json cols = Json::object();
  size_t values = 0, n_datasets = 0;
  for (const auto& [name, shape] : f.datasets()) {
    std::vector<double> v = f.dataset(name);
    values += v.size();
    ++n_datasets;
    if (f.has_attr(name, "_FillValue")) {
      const double fv = f.attr_double(name, "_FillValue");
      for (double& x : v)
        if (x == fv) x = NAN;  // undefined: null
    }
    Json q = quantity(v, f.has_attr(name, "units") ? f.attr_string(name, "units") : "");
    if (f.has_attr(name, "description")) q["description"] = f.attr_string(name, "description");
    cols[name.rfind("/sweep/", 0) == 0 ? name.substr(7) : name] = std::move(q);
  }
  j["columns"] = std::move(cols);
  j["undefined"] = undefined_list(f, "/sweep");
  j["checked"]["datasets"] = count(long(n_datasets));
  j["checked"]["values"] = count(long(values));
  return j;
}

}  // namespace

Json compare_json(const std::vector<std::string>& paths, const Comparison& c) {
  Json j;
  j["software_version"] = MAGNUS_VERSION;
  j["differing"] = c.differing;
  Json files = Json::array();
  for (const auto& p : paths) {
    const ResultFile f(p);
    files.push_back(flow_groups(f));
  }
  j["files"] = std::move(files);
  return j;
}

Json inspect_json(const std::string& path) {
  describe_result(
      path);  // the checks of the text: a damaged or incomplete file is one line, every value read
  const ResultFile f(path, {"magnus-flow", "magnus-sweep"});
  return f.format() == "magnus-sweep" ? inspect_sweep(f) : inspect_flow(f);
}

}  // namespace magnus
