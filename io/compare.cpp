#include "io/compare.hpp"

#include "io/text_format.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "io/hdf5_io.hpp"

namespace magnus {

namespace {

/// A parameter as stored in /parameters (or the root title): number or text.
struct ParamSpec {
  const char* object;
  const char* name;
  bool text;
  const char* units;
};
const ParamSpec kParams[] = {
    {"/", "title", true, ""},
    {"/parameters", "radius", false, "m"},
    {"/parameters", "speed", false, "m/s"},
    {"/parameters", "spin", false, "rad/s"},
    {"/parameters", "spin_ratio", false, "1"},
    {"/parameters", "circulation_model", true, ""},
    {"/parameters", "circulation", false, "m²/s"},
    {"/parameters", "density", false, "kg/m³"},
    {"/parameters", "pressure_inf", false, "Pa"},
    {"/parameters", "outer_radius", false, "R/a"},
    {"/parameters", "far_field", true, ""},
    {"/parameters", "spacing", true, ""},
    {"/parameters", "n_theta", false, ""},
    {"/parameters", "n_r", false, ""},
    {"/parameters", "method", true, ""},
    {"/parameters", "stencil", true, ""},
};

struct Param {
  std::optional<double> number;
  std::optional<std::string> text;
  bool present() const { return number || text; }
};

bool same(const Param& a, const Param& b) {
  if (a.present() != b.present()) return false;
  if (a.text || b.text) return a.text == b.text;
  if (!a.number) return true;
  const double x = *a.number, y = *b.number;
  return x == y || std::fabs(x - y) <= 1e-12 * std::max(std::fabs(x), std::fabs(y));
}

std::string show(const Param& p) {
  if (p.text) return *p.text;
  if (p.number) return fmt::format("{:.10g}", *p.number);
  return "—";
}

/// One row of the comparison: a label with units, how to get the value, and its format.
struct Quantity {
  const char* label;
  const char* csv;
  const char* spec;
};
const Quantity kQuantities[] = {
    {"lift F_y (N/m)", "lift_N_m", "{:.10g}"},
    {"drag F_x (N/m)", "drag_N_m", "{:.3g}"},
    {"C_L numeric", "cl", "{:.10g}"},
    {"C_L Kutta–Joukowski", "cl_kutta_joukowski", "{:.10g}"},
    {"C_L seed estimate", "cl_seed_estimate", "{:.10g}"},
    {"C_L numeric/K–J − 1", "cl_over_kj_minus_1", "{:.3e}"},
    {"C_L K–J/seed", "kj_over_seed", "{:.6f}"},
    {"C_D", "cd", "{:.3e}"},
    {"ΔP top−bottom (Pa)", "delta_p_top_bottom_Pa", "{:.8g}"},
    {"ΔP seed 2ρUaω (Pa)", "delta_p_seed_estimate_Pa", "{:.8g}"},
    {"error ψ max rel", "psi_max_rel", "{:.3e}"},
    {"error Cp surface max abs", "cp_surface_max_abs", "{:.3e}"},
    {"error C_L rel", "cl_rel", "{:.3e}"},
    {"time total (s)", "total_s", "{:.3g}"},
};

struct FileData {
  std::string path;
  std::vector<Param> params;                   // as kParams
  std::vector<std::optional<double>> values;  // as kQuantities
};

FileData read(const std::string& path) {
  const ResultFile f(path);
  FileData d;
  d.path = path;
  for (const auto& p : kParams) {
    Param v;
    if (f.has_attr(p.object, p.name)) {
      if (p.text) v.text = f.attr_string(p.object, p.name);
      else v.number = f.attr_double(p.object, p.name);
    }
    d.params.push_back(v);
  }
  auto attr = [&](const char* obj, const char* name) -> std::optional<double> {
    if (!f.has_attr(obj, name)) return std::nullopt;
    return f.attr_double(obj, name);
  };
  const auto cl = attr("/forces", "cl"), kj = attr("/forces", "cl_kutta_joukowski"),
             seed = attr("/forces", "cl_seed_estimate");
  d.values = {attr("/forces", "lift"),
              attr("/forces", "drag"),
              cl,
              kj,
              seed,
              cl && kj && *kj != 0.0 ? std::optional<double>(*cl / *kj - 1.0) : std::nullopt,
              kj && seed && *seed != 0.0 ? std::optional<double>(*kj / *seed) : std::nullopt,
              attr("/forces", "cd"),
              attr("/forces", "delta_p_top_bottom"),
              attr("/forces", "delta_p_seed_estimate"),
              attr("/errors", "psi_max_rel"),
              attr("/errors", "cp_surface_max_abs"),
              attr("/errors", "cl_rel"),
              attr("/timing", "total_s")};
  return d;
}


}  // namespace

Comparison compare_results(const std::vector<std::string>& paths) {
  if (paths.empty()) throw std::invalid_argument("compare: no result files given");
  std::vector<FileData> files;
  for (const auto& p : paths) files.push_back(read(p));

  Comparison out;
  std::vector<size_t> differ;
  for (size_t k = 0; k < std::size(kParams); ++k)
    for (size_t i = 1; i < files.size(); ++i)
      if (!same(files[0].params[k], files[i].params[k])) {
        differ.push_back(k);
        out.differing.push_back(kParams[k].name);
        break;
      }

  // Cells, then widths.
  const size_t n = files.size();
  std::vector<std::string> head(n);
  for (size_t i = 0; i < n; ++i) head[i] = fmt::format("[{}]", i + 1);
  std::vector<std::pair<std::string, std::vector<std::string>>> param_rows, value_rows;
  for (size_t k : differ) {
    if (k == 0) continue;  // the titles head the table already
    std::vector<std::string> cells;
    for (const auto& f : files) cells.push_back(show(f.params[k]));
    const std::string units = kParams[k].units;
    param_rows.push_back({units.empty() ? kParams[k].name : fmt::format("{} ({})", kParams[k].name, units), cells});
  }
  for (size_t q = 0; q < std::size(kQuantities); ++q) {
    std::vector<std::string> cells;
    for (const auto& f : files)
      cells.push_back(f.values[q] ? fmt::format(fmt::runtime(kQuantities[q].spec), *f.values[q]) : "undefined");
    value_rows.push_back({kQuantities[q].label, cells});
  }
  size_t label_w = 24;
  std::vector<size_t> col_w(n, 12);
  for (const auto* rows : {&param_rows, &value_rows})
    for (const auto& [label, cells] : *rows) {
      label_w = std::max(label_w, display_width(label) + 2);
      for (size_t i = 0; i < n; ++i) col_w[i] = std::max(col_w[i], display_width(cells[i]));
    }

  std::string& t = out.table;
  t += fmt::format("magnus compare: {} result file{}\n", n, n == 1 ? "" : "s");
  for (size_t i = 0; i < n; ++i) {
    const Param& title = files[i].params[0];
    t += fmt::format("  {} {}{}\n", head[i], files[i].path, title.text ? "  — " + *title.text : std::string());
  }
  auto row = [&](const std::string& label, const std::vector<std::string>& cells) {
    std::string s = pad_right("  " + label, label_w + 2);
    for (size_t i = 0; i < n; ++i) s += "  " + pad_left(cells[i], col_w[i]);
    t += s + "\n";
  };
  t += "\n";
  row("", head);
  if (n == 1) {
    t += "parameters: one file, nothing to compare\n";
  } else if (param_rows.empty()) {
    t += differ.empty() ? "parameters: all the same\n" : "parameters: all the same but the title\n";
  } else {
    t += "parameters that differ\n";
    for (const auto& [label, cells] : param_rows) row(label, cells);
  }
  t += "lift, drag, errors\n";
  for (const auto& [label, cells] : value_rows) row(label, cells);

  // CSV: one row per file.
  std::string& c = out.csv;
  c += "file,title";
  for (size_t k : differ)
    if (k != 0) c += std::string(",") + kParams[k].name;
  for (const auto& q : kQuantities) c += std::string(",") + q.csv;
  c += "\n";
  for (const auto& f : files) {
    c += csv_field(f.path) + "," + csv_field(f.params[0].text.value_or(""));
    for (size_t k : differ)
      if (k != 0) c += "," + csv_field(f.params[k].text ? *f.params[k].text
                                       : f.params[k].number ? fmt::format("{:.17g}", *f.params[k].number) : "");
    for (const auto& v : f.values) c += "," + (v ? fmt::format("{:.17g}", *v) : std::string());
    c += "\n";
  }
  return out;
}

void command_compare(const std::vector<std::string>& paths, const std::string& csv) {
  check_distinct_paths(paths, {csv});
  if (!csv.empty()) check_writable(csv);
  const Comparison c = compare_results(paths);
  if (!csv.empty()) write_text_output(csv, c.csv);
  std::fputs(c.table.c_str(), stdout);
}

}  // namespace magnus
