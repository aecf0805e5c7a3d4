#include "io/ns_sweep_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "io/case_file.hpp"
#include "io/hdf5_io.hpp"
#include "io/schema_files.hpp"
#include "io/schema_io.hpp"
#include "io/json_output.hpp"
#include "io/report_viscous.hpp"
#include "io/text_format.hpp"

namespace magnus {

namespace {

/// How the map decided stability, in words.
std::string stability_text(const NsMap& m) {
  if (m.stability_method.empty()) return "stability method not recorded";
  if (m.stability_method == "none") return "no stability test (--steady-only)";
  return fmt::format("stability by {}{}", m.stability_method == "march" ? "the marching test" : "eigenvalues",
                     !m.averaged ? ""
                     : m.orbits  ? ", unstable points as shedding orbits (marched from rest where none was found)"
                                 : ", unstable points marched from rest");
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
    case MapSource::orbit:
      return "mean (orbit)";
    case MapSource::none:
      break;
  }
  return "—";
}

/// The regimes in one line: how many points of each, and where the second window and the bistable points
/// lie (at most eight named of each). Empty when no point is classified.
std::string regime_summary(const NsMap& m) {
  int n[4] = {0, 0, 0, 0}, unclassified = 0;
  std::string where[4];
  for (const auto& p : m.points) {
    if (!std::isfinite(p.regime)) {
      ++unclassified;
      continue;
    }
    const int r = int(p.regime);
    if (r < 0 || r > 3) continue;
    if (r >= 2 && n[r] < 8) where[r] += fmt::format("{}Re {:g} α {:g}", n[r] ? ", " : "", p.reynolds, p.alpha);
    ++n[r];
  }
  if (n[0] + n[1] + n[2] + n[3] == 0) return "";
  auto named = [&](int r) { return n[r] ? fmt::format(" ({}{})", where[r], n[r] > 8 ? ", …" : "") : ""; };
  return fmt::format("{:<13}{} steady, {} shedding, {} in the second (one-sided) shedding window{}, {} bistable "
                     "(a stable steady state and a shedding orbit){}{}\n",
                     "regimes", n[0], n[1], n[2], named(2), n[3], named(3),
                     unclassified ? fmt::format(", {} not classified", unclassified) : "");
}

/// A relative bar in per cent, "—" when undefined.
std::string bar_cell(double rel) {
  if (!std::isfinite(rel)) return "—";
  return 100.0 * rel >= 10.0 ? fmt::format("{:.0f}", 100.0 * rel) : fmt::format("{:.2g}", 100.0 * rel);
}

/// How many points meet the default tolerances, and the largest C_D bar, in one line (empty: no bars).
std::string error_summary(const NsMap& m) {
  int meet = 0, short_of = 0, undecided = 0;
  const NsMapPoint* worst = nullptr;
  for (const auto& p : m.points) {
    const double v = p.meets_tolerance;
    (std::isfinite(v) ? (v == 1.0 ? meet : short_of) : undecided) += 1;
    if (std::isfinite(p.cd_rel_estimate) && (!worst || p.cd_rel_estimate > worst->cd_rel_estimate)) worst = &p;
  }
  if (!worst) return "";
  return fmt::format("{:<13}{} of {} points within the default tolerances (C_L, St 1%, C_D 2%), {} short of "
                     "them, {} without a bar; largest C_D bar {}% at Re {:g}, α {:g}{}\n",
                     "error bars", meet, m.points.size(), short_of, undecided, bar_cell(worst->cd_rel_estimate),
                     worst->reynolds, worst->alpha,
                     short_of > 0 ? " (a finer grid: --set grid.n_theta=… or domain.outer_radius)" : "");
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
  t += fmt::format("{:<13}where this 2D map is real is not computed here: magnus plot MAP.h5 --onset3d F.h5 frames "
                   "the points above a computed 3D onset (magnus stability CASE --spanwise --critical-reynolds "
                   "A:B --output F.h5)\n",
                   "3D");
  t += error_summary(m);
  t += regime_summary(m);
  t += "\n";
  t += fmt::format("{:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>8} {:>7} {:>6} {:>6} {:>6} {:>6} {:>16} {:>6} {:>4} "
                   "{:>7}\n",
                   "Re", "α", "C_L", "C_D", "C_M", "C_L,ideal", "S/2πρa²", "St", "±C_L%", "±C_D%", "±St%",
                   "stable", "source", "Newton", "arc", "s");
  for (const auto& p : m.points)
    t += fmt::format("{:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>8} {:>7} {:>6} {:>6} {:>6} {:>6} {:>16} {:>6} {:>4} "
                     "{:>7}\n",
                     cell(p.reynolds, "{:.4g}"), cell(p.alpha, "{:.3f}"), cell(p.cl, "{:.4f}"),
                     cell(p.cd, "{:.4f}"), cell(p.cm, "{:.4f}"), cell(p.cl_ideal, "{:.4f}"),
                     cell(p.ratio, "{:.4f}"), cell(p.strouhal, "{:.4f}"), bar_cell(p.cl_rel_estimate),
                     bar_cell(p.cd_rel_estimate), bar_cell(p.strouhal_rel_estimate), stable_text(p),
                     p.fold ? std::string("fold") : source_short(p.source), p.newton_steps, p.arclength_steps,
                     cell(p.seconds, "{:.2f}"));
  return t;
}

std::string ns_map_json(const NsMap& m, const std::vector<std::string>& written) {
  Json j;
  put_values(j, attr_values(ns_map_attributes(), m, Shown::json_only));
  j["grid"] = {{"n_theta", count(m.n_theta)}, {"n_r", count(m.n_r)}, {"outer_radius", quantity(m.outer_over_a, "a")}};
  j["shard"] = {{"k", count(m.shard)}, {"n", count(m.shards)}};
  j["stability"] = {{"method", m.stability_method}, {"averaged", m.averaged}, {"orbits", m.orbits}};
  j["axes"] = {{"alpha", quantity(m.alphas, "1")}, {"reynolds", quantity(m.reynolds, "1")}};
  j["timing"] = {{"total_s", quantity(m.total_s, "s")}, {"threads", count(m.threads)}};
  Json cols = Json::object();
  for (const auto& c : ns_map_columns()) cols[c.name] = {{"units", c.units}, {"description", c.description}};
  j["columns"] = std::move(cols);
  Json points = Json::array();
  for (const auto& p : m.points) {
    Json q = Json::object();
    for (const auto& c : ns_map_columns()) {
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
  for (const auto& c : ns_map_columns())
    t += (t.empty() ? "" : ",") + std::string(c.name) +
         (std::string(c.units) == "1" ? "" : std::string("_") + c.units);
  t += "\n";
  for (const auto& p : m.points) {
    std::string line;
    bool first = true;
    for (const auto& c : ns_map_columns()) {
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
    FileGroups g{w};
    write_attrs(attr_values(ns_map_attributes(), m, Shown::file_only), g);
    write_datasets(g, ns_map_axes(), m, Gaps::as_is);
    write_columns(g, "/sweep", ns_map_columns(), m.points, Gaps::fill);
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
  // Files written before stability and averaged existed: unknown (merge then asks every shard to be alike).
  m.stability_method = "";
  read_attrs(ns_map_attributes(), f, m);
  read_datasets(ns_map_axes(), f, m);
  const size_t n = f.dataset("/sweep/alpha").size();
  m.points.resize(n);
  for (auto& p : m.points) p.stable.reset();
  // The error bars came later: a map file without them reads as undefined there.
  const auto later = [](const std::string& name) {
    return name == "cl_rel_estimate" || name == "cd_rel_estimate" || name == "strouhal_rel_estimate" ||
           name == "meets_tolerance" || name == "regime";
  };
  for (const auto& c : ns_map_columns()) {
    const bool absent = later(c.name) && !f.has(std::string("/sweep/") + c.name);
    const std::vector<double> v = absent ? std::vector<double>(n, std::nan("")) : read_column(f, "/sweep", c.name, n);
    for (size_t i = 0; i < n; ++i) c.set(m.points[i], v[i]);
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
    if (s.stability_method != a.stability_method || s.averaged != a.averaged || s.orbits != a.orbits)
      throw std::runtime_error(fmt::format(
          "merge: {} ({}) and {} ({}) decided stability differently: compute every shard with the same "
          "--stability, --steady-only and --orbits",
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
