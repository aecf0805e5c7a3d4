#include "io/inspect.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/schema.hpp"
#include "io/text_format.hpp"

namespace magnus {

namespace {

/// Bookkeeping attributes: shown through what they describe, not as values.
bool bookkeeping(const std::string& name) {
  return name == "units" || name == "undefined" || name == "note" || name == "description" || name == "long_name" ||
         (name.size() > 6 && name.compare(name.size() - 6, 6, "_units") == 0);
}

std::string value_text(const ResultFile& f, const std::string& obj, const std::string& name) {
  if (f.attr_is_text(obj, name)) {
    std::string v = f.attr_string(obj, name);
    const auto nl = v.find('\n');
    if (nl != std::string::npos)
      v = fmt::format("({} lines of text)", std::count(v.begin(), v.end(), '\n') + 1);
    return v;
  }
  return cell(f.attr_double(obj, name), "{:.10g}");  // no "-0"
}

/// The unit of obj@name: the companion NAME_units (version 2), else the schema's; "" for text.
std::string attr_units(const ResultFile& f, const std::string& obj, const std::string& name) {
  if (f.has_attr(obj, name + "_units") && f.attr_is_text(obj, name + "_units"))
    return f.attr_string(obj, name + "_units");
  if (const AttrSpec* a = find_attribute(obj, name)) return a->units;
  return "";
}

/// A name padded to `width` columns, and at least one space after it.
std::string padded(const std::string& name, size_t width) {
  return fmt::format("{:<{}} ", name, width - 1);
}

std::string line(const std::string& name, const std::string& value, const std::string& units) {
  return units.empty() ? fmt::format("  {}{}\n", padded(name, 26), value)
                       : fmt::format("  {}{}  [{}]\n", padded(name, 26), value, units);
}

/// Whether the file holds a navier-stokes result (its root attribute model).
bool is_viscous(const ResultFile& f) {
  return f.has_attr("/", "model") && f.attr_string("/", "model") == "navier-stokes";
}

/// Whether a schema entry for `m` belongs in the file (the model's own entries only).
bool belongs(Models m, const ResultFile& f) {
  switch (m) {
    case Models::all: return true;
    case Models::potential: return !is_viscous(f);
    case Models::viscous: return is_viscous(f);
    case Models::steady_study: return f.has("/steady_study");
  }
  return false;
}

/// Every attribute of a group: the schema's first (undefined ones marked), then any others the file holds.
std::string group_text(const ResultFile& f, const std::string& group, const char* heading, bool strict) {
  if (!f.has(group)) return "";
  std::string s = fmt::format("\n{}\n", heading);
  std::set<std::string> undefined;
  if (f.has_attr(group, "undefined")) {
    const std::string list = f.attr_string(group, "undefined");
    size_t at = 0;
    while (at <= list.size()) {
      const size_t comma = std::min(list.find(", ", at), list.size());
      undefined.insert(list.substr(at, comma - at));
      at = comma + 2;
    }
  }
  std::set<std::string> shown;
  for (const AttrSpec& a : result_attributes()) {
    if (group != a.group || group == "/" || !belongs(a.models, f)) continue;
    shown.insert(a.name);
    if (f.has_attr(group, a.name))
      s += line(a.name,
                value_text(f, group, a.name) +
                    (is_viscous(f) && viscous_last_step(group, a.name) ? " (last step)" : ""),
                a.units);
    else if (strict && !undefined.count(a.name))  // version 2 lists every value it omits
      throw std::runtime_error(
          fmt::format("'{}' is damaged or incomplete: {}@{} is missing", f.path(), group, a.name));
    else if (a.kind != AttrKind::text)
      s += line(a.name, "undefined", a.units);
  }
  for (const auto& name : f.attributes(group))
    if (!shown.count(name) && !bookkeeping(name))
      s += line(name, value_text(f, group, name), attr_units(f, group, name));
  return s;
}

std::string dims_text(const std::vector<size_t>& shape) {
  std::string dims;
  for (size_t d : shape) dims += (dims.empty() ? "" : " × ") + std::to_string(d);
  return dims;
}

/// The stagnation points, as coordinates: r in m and in units of a, θ in rad and degrees.
std::string stagnation_text(const ResultFile& f, double a) {
  std::string s;
  for (const bool exact : {false, true}) {
    std::vector<double> r, th;
    const std::string sfx = exact ? "_exact" : "";
    if (f.has("/stagnation/r" + sfx) && f.has("/stagnation/theta" + sfx)) {
      r = f.dataset("/stagnation/r" + sfx);
      th = f.dataset("/stagnation/theta" + sfx);
    } else if (f.has(exact ? "/stagnation/exact" : "/stagnation/numeric")) {  // version 1: (k, 2) of (r, θ)
      const auto v = f.dataset(exact ? "/stagnation/exact" : "/stagnation/numeric");
      for (size_t k = 0; k + 1 < v.size(); k += 2) r.push_back(v[k]), th.push_back(v[k + 1]);
    } else {
      continue;
    }
    s += fmt::format("  {}:{}\n", exact ? "exact" : "numeric", r.empty() ? " none" : "");
    for (size_t k = 0; k < std::min(r.size(), th.size()); ++k)
      s += fmt::format("    r = {} m ({} a), theta = {} rad ({}°)\n", figure(r[k], "{:.8g}"),
                       figure(a > 0 ? r[k] / a : 0.0, "{:.6g}"), figure(th[k], "{:.8g}"),
                       figure(th[k] * 180.0 / M_PI, "{:.4f}"));
  }
  return s.empty() ? s : "\nstagnation points\n" + s;
}

/// A navier-stokes file's time series: the force history (steps, time span in s and D/U) and the stored
/// states (how many, when).
std::string time_series_text(const ResultFile& f) {
  std::string s = "\ntime series\n";
  const double unit =
      f.has_attr("/parameters", "time_unit") ? f.attr_double("/parameters", "time_unit") : 0.0;
  // D/U, or D/(a|ω|) for a cylinder spinning in still fluid.
  const bool still = f.has_attr("/parameters", "speed") && !(f.attr_double("/parameters", "speed") > 0.0);
  const char* unit_name = still ? "D/(a|ω|)" : "D/U";
  auto span = [&](const std::vector<double>& t) {
    if (t.empty()) return std::string();
    std::string out = fmt::format(", t = {:.6g} … {:.6g} s", t.front(), t.back());
    if (unit > 0) out += fmt::format(" ({:.6g} … {:.6g} {})", t.front() / unit, t.back() / unit, unit_name);
    return out;
  };
  const std::vector<double> h = f.has("/history/t") ? f.dataset("/history/t") : std::vector<double>();
  s += fmt::format("  history: {} steps{}\n", h.size(), span(h));
  if (f.has("/snapshots/t")) {
    const std::vector<double> t = f.dataset("/snapshots/t");
    s += fmt::format("  snapshots: {} stored state{}{}\n", t.size(), t.size() == 1 ? "" : "s", span(t));
  } else {
    s += "  snapshots: none (output.snapshots = 0)\n";
  }
  return s;
}

/// read_views: also read the /mesh views (each a view of stored datasets, which are read and checked anyway;
/// reading them through HDF5's virtual-dataset mapping is most of the time on a large file).
std::string describe_flow(const ResultFile& f, bool read_views = true) {
  // A result has a version and its parameters: a file with only the format attribute is not one.
  const long version = f.attr_int("/", "format_version");
  if (!f.has("/parameters") || !f.has("/grid/r"))
    throw std::runtime_error(
        fmt::format("'{}' is not a complete magnus result: no /parameters or /grid", f.path()));
  // What every complete file holds (a damaged group can lose links silently): the grid, the surface but
  // what it lists as undefined, and (version 2) the stagnation points and a field behind every mesh view.
  std::vector<std::string> expected = {"/grid/r",        "/grid/theta",      "/grid/x",          "/grid/y",
                                       "/surface/theta", "/surface/u_theta", "/surface/pressure"};
  const std::string surface_undefined =
      f.has_attr("/surface", "undefined") ? f.attr_string("/surface", "undefined") : "";
  const bool viscous = is_viscous(f);
  if (surface_undefined.find("cp") == std::string::npos) {
    expected.push_back("/surface/cp");
    if (!viscous) expected.push_back("/surface/cp_exact");
  }
  if (version >= 2) {
    for (const char* p : {"/mesh/points", "/mesh/quads"}) expected.push_back(p);
    if (viscous)
      expected.insert(expected.end(), {"/surface/shear_stress", "/separation/theta", "/history/t"});
    else
      expected.insert(expected.end(), {"/stagnation/r", "/stagnation/theta", "/stagnation/r_exact",
                                       "/stagnation/theta_exact"});
    for (const DatasetSpec* d : field_datasets())
      if (f.has("/mesh/" + d->path.substr(8))) expected.push_back(d->path);
  }
  for (const auto& p : expected)
    if (!f.has(p))
      throw std::runtime_error(fmt::format("'{}' is damaged or incomplete: {} is missing", f.path(), p));
  std::string s;
  s += fmt::format("{}: magnus-flow version {} (written by magnus {})\n", f.path(), version,
                   f.attr_string("/", "software_version"));
  for (const char* k : {"model", "title"})
    if (f.has_attr("/", k)) s += fmt::format("{}: {}\n", k, f.attr_string("/", k));
  // Why a navier-stokes run stopped, and loudly whether it stopped before its end (Ctrl-C, an error).
  if (viscous && f.has_attr("/", "status")) {
    const bool partial = f.has_attr("/", "partial") && f.attr_int("/", "partial") != 0;
    s += fmt::format("status: {}{}\n", f.attr_string("/", "status"),
                     partial ? " — a PARTIAL result (stopped before its end: /@partial = 1)" : "");
  }
  s += group_text(f, "/parameters", "parameters", version >= 2);
  s += group_text(f, "/forces", "forces", version >= 2);
  s += group_text(f, "/errors", "errors", version >= 2);
  s += group_text(f, "/timing", "timing", version >= 2);
  s += group_text(f, "/steady_study", "steady grid study (values per grid: the /steady_study datasets)", true);
  for (const char* g : {"/fields", "/surface"})
    if (f.has_attr(g, "undefined"))
      s += fmt::format("\n{} undefined: {}\n", g, f.attr_string(g, "undefined"));
  s += stagnation_text(f, f.has_attr("/parameters", "radius") ? f.attr_double("/parameters", "radius") : 0.0);
  if (viscous) s += time_series_text(f);
  s += "\ndatasets\n";
  size_t values = 0, state_views = 0;
  const auto all = f.datasets();
  for (const auto& [name, shape] : all) {
    if (!read_views && name.rfind("/mesh/", 0) == 0 && name != "/mesh/quads") continue;
    if (name.rfind("/mesh/snapshots/", 0) == 0) {  // one view per stored state and field: summed up below
      ++state_views;
      values += f.dataset(name).size();
      continue;
    }
    std::string units = dataset_units(name);
    if (units.empty()) units = f.has_attr(name, "units") ? f.attr_string(name, "units") : "?";
    const DatasetSpec* d = find_dataset(name);
    s += fmt::format("  {}({})  [{}]{}\n", padded(name, 24), dims_text(shape), units,
                     d ? "  " + description_of(*d, viscous) : "");
    // Read every value back: HDF5 verifies the checksums (Fletcher-32) on the way, so a damaged file is
    // reported here rather than found later by whoever uses the numbers.
    values += f.dataset(name).size();
  }
  if (state_views > 0)
    s += fmt::format("  {:<24}{} views (FIELD/k: state k of /snapshots/FIELD, for the .xmf time series)\n",
                     "/mesh/snapshots/…", state_views);
  s += fmt::format("\nchecked: {} datasets, {} values read back intact\n", all.size(), values);
  return s;
}

std::string describe_sweep(const ResultFile& f) {
  std::string s;
  s += fmt::format("{}: magnus-sweep version {} (written by magnus {})\n", f.path(), f.version(),
                   f.has_attr("/", "software_version") ? f.attr_string("/", "software_version") : "?");
  for (const char* k : {"title", "model", "variable", "stability"})
    if (f.has_attr("/", k)) s += fmt::format("{}: {}\n", k, f.attr_string("/", k));
  if (f.has_attr("/", "averaged"))
    s += fmt::format("unstable points: {}\n", !f.attr_int("/", "averaged") ? "not marched"
                                                 : f.has_attr("/", "orbits") && f.attr_int("/", "orbits")
                                                     ? "shedding orbits (marched from rest where none was found)"
                                                     : "marched from rest");
  if (f.has_attr("/", "shards"))
    s += fmt::format("shard: {} of {}\n", f.attr_int("/", "shard"), f.attr_int("/", "shards"));
  if (f.has_attr("/", "case")) s += fmt::format("case (resolved):\n{}\n", f.attr_string("/", "case"));
  for (const auto& [g, heading] : {std::pair{"/parameters", "parameters"}, std::pair{"/timing", "timing"}}) {
    if (!f.has(g)) continue;
    s += fmt::format("\n{}\n", heading);
    for (const auto& name : f.attributes(g))
      if (!bookkeeping(name)) s += line(name, value_text(f, g, name), attr_units(f, g, name));
    if (f.has_attr(g, "units")) s += fmt::format("  (units: {})\n", f.attr_string(g, "units"));
  }
  s += "\ncolumns (/sweep)\n";
  size_t values = 0;
  const auto all = f.datasets();
  for (const auto& [name, shape] : all) {
    const std::vector<double> v = f.dataset(name);
    values += v.size();
    const bool fill = f.has_attr(name, "_FillValue");
    const double fv = fill ? f.attr_double(name, "_FillValue") : 0.0;
    double lo = INFINITY, hi = -INFINITY;
    size_t undefined = 0;
    for (double x : v) {
      if (!std::isfinite(x) || (fill && x == fv)) {
        ++undefined;
        continue;
      }
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    const std::string units = f.has_attr(name, "units") ? f.attr_string(name, "units") : "?";
    const std::string range =
        lo <= hi ? figure(lo, "{:.6g}") + " … " + figure(hi, "{:.6g}") : std::string("all undefined");
    s += fmt::format("  {:<32}({})  [{}]  {}{}\n", name, dims_text(shape), units, range,
                     undefined ? fmt::format(" ({} undefined)", undefined) : "");
  }
  if (f.has_attr("/sweep", "undefined"))
    s += fmt::format("  undefined (not stored): {}\n", f.attr_string("/sweep", "undefined"));
  s += fmt::format("\nchecked: {} datasets, {} values read back intact\n", all.size(), values);
  return s;
}

}  // namespace

std::string surface_csv(const std::string& path) {
  const ResultFile f(path, {"magnus-flow", "magnus-sweep"});
  if (f.format() != "magnus-flow")
    throw std::runtime_error(
        fmt::format("'{}' is a {} file: --surface-csv needs a result of magnus run", path, f.format()));
  const bool viscous = is_viscous(f);
  std::vector<std::vector<double>> cols;
  for (const char* p : {"/surface/theta", "/surface/u_theta", "/surface/pressure"}) {
    if (!f.has(p))
      throw std::runtime_error(fmt::format("'{}' is damaged or incomplete: {} is missing", path, p));
    cols.push_back(f.dataset(p));
  }
  const std::vector<double> cp = f.has("/surface/cp") ? f.dataset("/surface/cp") : std::vector<double>();
  std::vector<double> tau;
  if (viscous) {
    if (!f.has("/surface/shear_stress"))
      throw std::runtime_error(
          fmt::format("'{}' is damaged or incomplete: /surface/shear_stress is missing", path));
    tau = f.dataset("/surface/shear_stress");
  }
  const size_t n = cols[0].size();
  for (const std::vector<double>* c :
       std::initializer_list<const std::vector<double>*>{&cols[1], &cols[2], &cp, &tau})
    if (!c->empty() && c->size() != n)
      throw std::runtime_error(fmt::format("'{}' is damaged: the /surface datasets differ in length", path));
  auto v = [](double x) { return std::isfinite(x) ? fmt::format("{:.17g}", x + 0.0) : std::string(); };
  std::string s =
      std::string("theta_rad,theta_deg,u_theta_m_s,pressure_Pa,cp") + (viscous ? ",tau_w_Pa" : "") + "\n";
  for (size_t j = 0; j < n; ++j) {
    s += v(cols[0][j]) + "," + v(cols[0][j] * 180.0 / M_PI) + "," + v(cols[1][j]) + "," + v(cols[2][j]) +
         "," + (cp.empty() ? std::string() : v(cp[j]));
    if (viscous) s += "," + v(tau[j]);
    s += "\n";
  }
  return s;
}

std::string describe_result(const std::string& path) {
  const ResultFile f(path, {"magnus-flow", "magnus-sweep"});
  return f.format() == "magnus-sweep" ? describe_sweep(f) : describe_flow(f);
}

void check_result(const std::string& path) {
  const ResultFile f(path, {"magnus-flow", "magnus-sweep"});
  (void)(f.format() == "magnus-sweep" ? describe_sweep(f) : describe_flow(f, false));
}

}  // namespace magnus
