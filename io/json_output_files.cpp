// The --json outputs that read files: magnus compare and magnus inspect (io/json_output.hpp).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "io/compare.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/json_output.hpp"
#include "io/json_parts.hpp"
#include "io/schema.hpp"

namespace magnus {

using json_parts::key_of;
using json_parts::point_json;

namespace {

bool bookkeeping(const std::string& name) {
  return name == "units" || name == "undefined" || name == "note" || name == "description" || name == "long_name" ||
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
  for (const char* g : {"/parameters", "/forces", "/errors", "/timing", "/steady_study"})
    if (f.has(g)) j[key_of(g)] = group_json(f, g);
  if (f.has("/steady_study")) {  // its grids, coarse to fine: one array per dataset
    Json levels = Json::object();
    for (const auto& [name, shape] : f.datasets())
      if (name.rfind("/steady_study/", 0) == 0) levels[name.substr(14)] = quantity(f.dataset(name), dataset_units(name));
    j["steady_study"]["levels"] = std::move(levels);
  }
  if (is_viscous(f) && j.contains("forces"))  // one instant of the run, not a time mean
    for (auto it = j["forces"].begin(); it != j["forces"].end(); ++it)
      if (viscous_last_step("/forces", it.key()) && it.value().is_object()) it.value()["at"] = "last step";
  if (!is_viscous(f) && j.contains("forces")) {
    auto value = [&](const char* k) -> std::optional<double> {
      const Json& q = j["forces"].contains(k) ? j["forces"][k]["value"] : Json(nullptr);
      return q.is_number() ? std::optional<double>(q.get<double>()) : std::nullopt;
    };
    j["derived"] =
        json_parts::kj_ratios(cl_over_kj_minus_1(value("cl"), value("cl_kutta_joukowski")),
                              kj_over_seed(value("cl_kutta_joukowski"), value("cl_seed_estimate")));
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
    if (const DatasetSpec* d = find_dataset(name)) q["description"] = description_of(*d, is_viscous(f));
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

namespace json_parts {

Json steady_study_json(const SteadyStudy& st) {
  Json levels = Json::array();
  for (const SteadyLevel& lv : st.levels) {
    Json l;
    l["n_theta"] = count(lv.n_theta);
    l["n_r"] = count(lv.n_r);
    l["cd"] = quantity(lv.C_D, "1");
    l["cl"] = quantity(lv.C_L, "1");
    l["recirculation_length"] = quantity(lv.recirculation, "1");
    l["residuals"] = quantity(lv.newton.residuals, "1");
    l["factorisations"] = count(lv.newton.factorisations);
    l["seconds"] = quantity(lv.newton.wall_seconds, "s");
    levels.push_back(std::move(l));
  }
  const auto extrapolated = [](const std::optional<Richardson>& r) -> Json {
    if (!r) return nullptr;
    Json q = quantity(r->value, "1");
    q["error"] = quantity(r->error, "1");
    q["finest"] = quantity(r->finest, "1");
    q["order"] = quantity(r->order, "1");
    q["order_observed"] = r->observed;
    return q;
  };
  Json j;
  j["levels"] = std::move(levels);
  j["cd"] = extrapolated(st.C_D);
  j["cl"] = extrapolated(st.C_L);
  j["recirculation_length"] = extrapolated(st.recirculation);
  return j;
}

}  // namespace json_parts

}  // namespace magnus
