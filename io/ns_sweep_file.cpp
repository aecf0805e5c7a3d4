#include "io/ns_sweep_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "io/case_file.hpp"
#include "io/hdf5_io.hpp"
#include "io/json_output.hpp"
#include "io/report_viscous.hpp"
#include "io/text_format.hpp"

namespace magnus {

namespace {

constexpr double kFill = 9.969209968386869e36;  // the netCDF default fill value (as io/sweep_file)
const double kNaN = std::nan("");

double flag(const std::optional<bool>& b) { return b ? (*b ? 1.0 : 0.0) : kNaN; }

/// One column of the map: name, units, description, and its value at a point (NaN: undefined); set
/// stores a value read back.
struct Column {
  const char* name;
  const char* units;
  const char* what;
  std::function<double(const NsMapPoint&)> get;
  std::function<void(NsMapPoint&, double)> set;
};

#define NS_COL(NAME, UNITS, WHAT, FIELD)                                    \
  Column {                                                                  \
    NAME, UNITS, WHAT, [](const NsMapPoint& p) { return double(p.FIELD); }, \
        [](NsMapPoint& p, double v) { p.FIELD = decltype(p.FIELD)(v); }     \
  }

const std::vector<Column>& columns() {
  static const std::vector<Column> c = {
      NS_COL("reynolds", "1", "Reynolds number U·2a/ν", reynolds),
      NS_COL("alpha", "1", "spin ratio aω/U", alpha),
      NS_COL("row", "1", "index of Re in /axes/reynolds", row),
      NS_COL("column", "1", "index of α in /axes/alpha", column),
      NS_COL("cl", "1", "reported lift coefficient: steady, or time-averaged (see source)", cl),
      NS_COL("cd", "1", "reported drag coefficient: steady, or time-averaged (see source)", cd),
      NS_COL("cm", "1", "reported torque coefficient M/(½ρU²D²): steady or time-averaged", cm),
      NS_COL("cl_pressure", "1", "pressure part of the steady state's C_L", cl_pressure),
      NS_COL("cl_friction", "1", "friction part of the steady state's C_L", cl_friction),
      NS_COL("cd_pressure", "1", "pressure part of the steady state's C_D", cd_pressure),
      NS_COL("cd_friction", "1", "friction part of the steady state's C_D", cd_friction),
      NS_COL("cl_steady", "1", "C_L of the steady state (stable or not)", cl_steady),
      NS_COL("cd_steady", "1", "C_D of the steady state (stable or not)", cd_steady),
      NS_COL("cm_steady", "1", "C_M of the steady state (stable or not)", cm_steady),
      NS_COL("cl_ideal", "1", "potential flow (Kutta–Joukowski) −2πα", cl_ideal),
      NS_COL("ratio", "1", "C_L / C_L,ideal = S/(2πρa²)", ratio),
      NS_COL("strouhal", "1", "Strouhal number f·D/U of a time-averaged periodic point", strouhal),
      NS_COL("newton_steps", "1", "Newton steps (with arclength corrector steps)", newton_steps),
      NS_COL("arclength_steps", "1", "pseudo-arclength steps taken to reach this α", arclength_steps),
      NS_COL("converged", "1", "1: the steady branch reached this point", converged),
      NS_COL("fold", "1", "1: the branch turned back (a fold) before this α", fold),
      Column{"stable", "1", "1 stable, 0 unstable steady state; fill value: not decided",
             [](const NsMapPoint& p) { return flag(p.stable); },
             [](NsMapPoint& p, double v) {
               if (std::isfinite(v)) p.stable = v != 0.0;
             }},
      Column{"source", "1",
             "0 steady, 1 time-averaged (steady state unstable), 2 time-averaged (no steady state), 3 none, "
             "4 steady, reached by marching from rest (the continued state unstable or not found)",
             [](const NsMapPoint& p) { return double(int(p.source)); },
             [](NsMapPoint& p, double v) {
               p.source = v >= 0.0 && v <= 4.0 ? MapSource(int(v)) : MapSource::none;
             }},
      NS_COL("seconds", "s", "wall time of the point (measured under the run's load)", seconds),
  };
  return c;
}

/// How the map decided stability, in words.
std::string stability_text(const NsMap& m) {
  if (m.stability_method.empty()) return "stability method not recorded";
  if (m.stability_method == "none") return "no stability test (--steady-only)";
  return fmt::format("stability by {}{}", m.stability_method == "march" ? "the marching test" : "eigenvalues",
                     m.averaged ? ", unstable points marched from rest" : "");
}

std::string stable_text(const NsMapPoint& p) { return p.stable ? (*p.stable ? "yes" : "no") : "—"; }

std::string source_short(MapSource s) {
  switch (s) {
    case MapSource::steady:
      return "steady";
    case MapSource::averaged_unstable:
      return "mean (unstable)";
    case MapSource::averaged_no_steady:
      return "mean (no steady)";
    case MapSource::marched_steady:
      return "steady (march)";
    case MapSource::none:
      break;
  }
  return "—";
}

}  // namespace

std::string ns_map_table(const NsMap& m) {
  std::string t = fmt::format("{}\n", m.base.title);
  if (m.continued_in_re())
    t += fmt::format("{:<13}navier-stokes, steady branch continued in Re at α = {:g}\n", "model",
                     m.alphas.front());
  else
    t += fmt::format("{:<13}navier-stokes, steady branch continued in α per Re row\n", "model");
  t += fmt::format("{:<13}{}\n", "stability", stability_text(m));
  t += fmt::format("{:<13}n_theta = {}, n_r = {}, R/a = {:g}\n", "grid", m.n_theta, m.n_r, m.outer_over_a);
  t += fmt::format("{:<13}{} Re × {} α", "map", m.reynolds.size(), m.alphas.size());
  if (m.shards > 1) t += fmt::format(", shard {}/{} ({} points)", m.shard, m.shards, m.points.size());
  // How the points were shared out: only with more than one thread is anything parallel.
  const char* order = m.continued_in_re() ? " (one branch in Re: in order)"
                      : m.threads > 1     ? " (rows in parallel)"
                                          : "";
  t += fmt::format("\n{:<13}{:.2f} s on {} thread{}{}\n", "time", m.total_s, m.threads, m.threads == 1 ? "" : "s",
                   order);
  const double re_max = *std::max_element(m.reynolds.begin(), m.reynolds.end());
  if (above_laminar_range(re_max))
    t += fmt::format("{:<13}Re up to {:g} > {:g}: real flow is three-dimensional there; this 2D laminar map "
                     "is not what a real cylinder sees\n",
                     "note", re_max, kReynolds3D);
  t += "\n";
  t += fmt::format("{:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>8} {:>7} {:>6} {:>16} {:>6} {:>4} {:>7}\n", "Re",
                   "α", "C_L", "C_D", "C_M", "C_L,ideal", "S/2πρa²", "St", "stable", "source", "Newton",
                   "arc", "s");
  for (const auto& p : m.points)
    t += fmt::format("{:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>8} {:>7} {:>6} {:>16} {:>6} {:>4} {:>7}\n",
                     cell(p.reynolds, "{:.4g}"), cell(p.alpha, "{:.3f}"), cell(p.cl, "{:.4f}"),
                     cell(p.cd, "{:.4f}"), cell(p.cm, "{:.4f}"), cell(p.cl_ideal, "{:.4f}"),
                     cell(p.ratio, "{:.4f}"), cell(p.strouhal, "{:.4f}"), stable_text(p),
                     p.fold ? std::string("fold") : source_short(p.source), p.newton_steps, p.arclength_steps,
                     cell(p.seconds, "{:.2f}"));
  return t;
}

std::string ns_map_json(const NsMap& m, const std::vector<std::string>& written) {
  Json j;
  j["software_version"] = MAGNUS_VERSION;
  j["model"] = "navier-stokes";
  j["title"] = m.base.title;
  j["grid"] = {{"n_theta", count(m.n_theta)}, {"n_r", count(m.n_r)}, {"outer_radius", quantity(m.outer_over_a, "a")}};
  j["shard"] = {{"k", count(m.shard)}, {"n", count(m.shards)}};
  j["stability"] = {{"method", m.stability_method}, {"averaged", m.averaged}};
  j["axes"] = {{"alpha", quantity(m.alphas, "1")}, {"reynolds", quantity(m.reynolds, "1")}};
  j["timing"] = {{"total_s", quantity(m.total_s, "s")}, {"threads", count(m.threads)}};
  Json cols = Json::object();
  for (const auto& c : columns()) cols[c.name] = {{"units", c.units}, {"description", c.what}};
  j["columns"] = std::move(cols);
  Json points = Json::array();
  for (const auto& p : m.points) {
    Json q = Json::object();
    for (const auto& c : columns()) {
      const double v = c.get(p);
      q[c.name] = quantity(std::isfinite(v) ? std::optional<double>(v) : std::nullopt, c.units);
    }
    points.push_back(std::move(q));
  }
  j["points"] = std::move(points);
  j["output"] = written;
  return json_text(j);
}

std::string ns_map_csv(const NsMap& m) {
  std::string t;
  for (const auto& c : columns())
    t += (t.empty() ? "" : ",") + std::string(c.name) +
         (std::string(c.units) == "1" ? "" : std::string("_") + c.units);
  t += "\n";
  for (const auto& p : m.points) {
    std::string line;
    bool first = true;
    for (const auto& c : columns()) {
      const double v = c.get(p);
      line += (first ? "" : ",") + (std::isfinite(v) ? csv_number(v) : std::string());
      first = false;
    }
    t += line + "\n";
  }
  return t;
}

void write_ns_map_hdf5(const NsMap& m, const std::string& path) {
  write_hdf5_atomic(path, [&](H5Writer& w) {
    const H5Writer::id file = w.file();
    w.attr(file, "format", "magnus-sweep");
    w.attr(file, "format_version", 2L);
    w.attr(file, "format_version_units", "1");
    w.attr(file, "software_version", MAGNUS_VERSION);
    w.attr(file, "model", "navier-stokes");
    w.attr(file, "title", m.base.title);
    w.attr(file, "case", m.base.source_text);
    w.attr(file, "variable", "spin_ratio,reynolds");
    w.attr(file, "shard", long(m.shard));
    w.attr(file, "shards", long(m.shards));
    w.attr(file, "shard_units", "1");
    w.attr(file, "shards_units", "1");
    w.attr(file, "stability", m.stability_method);
    w.attr(file, "stability_units", "1");
    w.attr(file, "averaged", long(m.averaged));
    w.attr(file, "averaged_units", "1");
    {
      const H5Writer::id p = w.group("/parameters");
      w.attr_with_units(p, "radius", m.base.scene.radius, "m");
      w.attr_with_units(p, "speed", m.base.scene.speed, "m/s");
      w.attr_with_units(p, "density", m.base.scene.density, "kg/m^3");
      w.attr_with_units(p, "outer_radius", m.outer_over_a, "1");
      w.attr(p, "n_theta", long(m.n_theta));
      w.attr(p, "n_theta_units", "1");
      w.attr(p, "n_r", long(m.n_r));
      w.attr(p, "n_r_units", "1");
    }
    {
      const H5Writer::id t = w.group("/timing");
      w.attr_with_units(t, "total_s", m.total_s, "s");
      w.attr(t, "threads", long(m.threads));
      w.attr(t, "threads_units", "1");
    }
    const H5Writer::id A = w.group("/axes");
    w.dataset(A, "alpha", {m.alphas.size()}, m.alphas.data(), "1", "the map's spin ratios aω/U");
    w.dataset(A, "reynolds", {m.reynolds.size()}, m.reynolds.data(), "1", "the map's Reynolds numbers");
    const H5Writer::id G = w.group("/sweep");
    for (const auto& c : columns()) {
      std::vector<double> v;
      bool gaps = false;
      for (const auto& p : m.points) {
        const double x = c.get(p);
        gaps = gaps || !std::isfinite(x);
        v.push_back(std::isfinite(x) ? x : kFill);
      }
      w.dataset(G, c.name, {v.size()}, v.data(), c.units, c.what);
      if (gaps) w.attr(w.open(std::string("/sweep/") + c.name), "_FillValue", kFill);
    }
  });
}

NsMap read_ns_map_hdf5(const std::string& path) {
  const ResultFile f(path, {"magnus-sweep"});
  if (!f.has_attr("/", "model") || f.attr_string("/", "model") != "navier-stokes")
    throw std::runtime_error(path + ": not a navier-stokes sweep file (model is not \"navier-stokes\")");
  NsMap m;
  const std::string text = f.attr_string("/", "case");
  try {
    m.base = parse_case(text, path);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": its case does not parse: " + e.what());
  }
  m.base.source_text = text;
  m.shard = int(f.attr_int("/", "shard"));
  m.shards = int(f.attr_int("/", "shards"));
  // Files written before these attributes existed: unknown (merge then asks every shard to be alike).
  m.stability_method = f.has_attr("/", "stability") ? f.attr_string("/", "stability") : "";
  m.averaged = !f.has_attr("/", "averaged") || f.attr_int("/", "averaged") != 0;
  m.n_theta = int(f.attr_int("/parameters", "n_theta"));
  m.n_r = int(f.attr_int("/parameters", "n_r"));
  m.outer_over_a = f.attr_double("/parameters", "outer_radius");
  m.total_s = f.attr_double("/timing", "total_s");
  m.threads = int(f.attr_int("/timing", "threads"));
  m.alphas = f.dataset("/axes/alpha");
  m.reynolds = f.dataset("/axes/reynolds");
  std::vector<size_t> shape;
  const size_t n = f.dataset("/sweep/alpha", &shape).size();
  m.points.resize(n);
  for (auto& p : m.points) p.stable.reset();
  for (const auto& c : columns()) {
    const std::string name = std::string("/sweep/") + c.name;
    if (!f.has(name)) throw std::runtime_error(fmt::format("{}: no dataset {}", path, name));
    const std::vector<double> v = f.dataset(name);
    if (v.size() != n)
      throw std::runtime_error(fmt::format("{}: {} has {} values, not {}", path, name, v.size(), n));
    for (size_t i = 0; i < n; ++i) c.set(m.points[i], v[i] == kFill ? kNaN : v[i]);
  }
  return m;
}

NsMap merge_ns_maps(const std::vector<NsMap>& shards, const std::vector<std::string>& paths) {
  if (shards.empty()) throw std::runtime_error("merge: no shards given");
  const NsMap& a = shards.front();
  std::map<int, size_t> seen;
  for (size_t i = 0; i < shards.size(); ++i) {
    const NsMap& s = shards[i];
    const std::string& name = paths[i];
    if (s.base.source_text != a.base.source_text)
      throw std::runtime_error(fmt::format("merge: {} and {} come from different cases", paths[0], name));
    if (s.n_theta != a.n_theta || s.n_r != a.n_r || s.outer_over_a != a.outer_over_a)
      throw std::runtime_error(
          fmt::format("merge: {} ({} × {}, R/a {:g}) and {} ({} × {}, R/a {:g}) have different grids",
                      paths[0], a.n_theta, a.n_r, a.outer_over_a, name, s.n_theta, s.n_r, s.outer_over_a));
    if (s.stability_method != a.stability_method || s.averaged != a.averaged)
      throw std::runtime_error(fmt::format(
          "merge: {} ({}) and {} ({}) decided stability differently: compute every shard with the same "
          "--stability and --steady-only",
          paths[0], stability_text(a), name, stability_text(s)));
    if (s.alphas != a.alphas || s.reynolds != a.reynolds)
      throw std::runtime_error(fmt::format("merge: {} and {} map different α or Re values", paths[0], name));
    if (s.shards != a.shards)
      throw std::runtime_error(fmt::format("merge: {} is shard {}/{} but {} is shard {}/{}", paths[0],
                                           a.shard, a.shards, name, s.shard, s.shards));
    if (auto it = seen.find(s.shard); it != seen.end())
      throw std::runtime_error(fmt::format("merge: {} and {} are both shard {}/{} (overlapping)",
                                           paths[it->second], name, s.shard, s.shards));
    seen[s.shard] = i;
    // Complete within itself: exactly its rows, every α.
    std::vector<int> rows = shard_rows(int(s.reynolds.size()), s.shard, s.shards);
    if (s.points.size() != rows.size() * s.alphas.size())
      throw std::runtime_error(fmt::format("merge: {} (shard {}/{}) holds {} points, not {}: incomplete",
                                           name, s.shard, s.shards, s.points.size(),
                                           rows.size() * s.alphas.size()));
    for (size_t q = 0; q < s.points.size(); ++q)
      if (s.points[q].row != rows[q / s.alphas.size()] || s.points[q].column != int(q % s.alphas.size()))
        throw std::runtime_error(
            fmt::format("merge: {} (shard {}/{}) holds points of other rows", name, s.shard, s.shards));
  }
  for (int k = 1; k <= a.shards; ++k)
    if (!seen.count(k))
      throw std::runtime_error(fmt::format("merge: shard {}/{} is missing (given: {} file{})", k, a.shards,
                                           shards.size(), shards.size() == 1 ? "" : "s"));
  NsMap m = a;
  m.shard = m.shards = 1;
  m.points.clear();
  m.total_s = 0.0;
  m.threads = 0;
  for (const auto& s : shards) {
    m.points.insert(m.points.end(), s.points.begin(), s.points.end());
    m.total_s += s.total_s;
    m.threads += s.threads;
  }
  std::stable_sort(m.points.begin(), m.points.end(), [](const NsMapPoint& x, const NsMapPoint& y) {
    return x.row != y.row ? x.row < y.row : x.column < y.column;
  });
  return m;
}

}  // namespace magnus
