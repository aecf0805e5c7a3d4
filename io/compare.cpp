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
#include "io/inspect.hpp"
#include "io/schema.hpp"

namespace magnus {

namespace {

/// The parameters compared: the root title, the model and every /parameters attribute of the schema.
std::vector<const AttrSpec*> params() {
  std::vector<const AttrSpec*> out = {find_attribute("/", "title"), find_attribute("/", "model")};
  for (const AttrSpec& a : result_attributes())
    if (std::string(a.group) == "/parameters") out.push_back(&a);
  return out;
}

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
  if (p.number) return figure(*p.number, "{:.10g}");
  return "—";
}

/// One row of the comparison: a schema attribute with a compare label, or a ratio of two of them.
struct Quantity {
  std::string label, csv, spec;
  const AttrSpec* attr = nullptr;  ///< the value, or
  const AttrSpec* num = nullptr;   ///< num / den (− 1 when minus_one)
  const AttrSpec* den = nullptr;
  bool minus_one = false;
  /// The results the row belongs to: a file of the other model shows "—" there (not "undefined").
  Models models() const { return (attr ? attr : num)->models; }
};

/// The marker of a row that does not apply to a file's model.
constexpr const char* kNotApplicable = "—";

std::vector<Quantity> quantities() {
  std::vector<Quantity> out;
  for (const AttrSpec& a : result_attributes()) {
    if (!a.compare_label) continue;
    out.push_back({a.compare_label, a.compare_csv, a.compare_format, &a});
    if (std::string(a.name) == "cl_seed_estimate") {
      const AttrSpec* cl = find_attribute("/forces", "cl");
      const AttrSpec* kj = find_attribute("/forces", "cl_kutta_joukowski");
      out.push_back({"C_L numeric/K–J − 1", "cl_over_kj_minus_1", "{:.3e}", nullptr, cl, kj, true});
      out.push_back({"C_L K–J/seed", "kj_over_seed", "{:.6f}", nullptr, kj, &a, false});
    }
  }
  return out;
}

struct FileData {
  std::string path;
  bool viscous = false;  // a navier-stokes result
  bool partial = false;  // a navier-stokes run stopped before its end (/@partial = 1)
  std::string status;    // why it stopped (navier-stokes)
  bool has(Models m) const { return m == Models::all || (m == Models::viscous) == viscous; }
  std::vector<Param> params;                  // as params()
  std::vector<std::optional<double>> values;  // as quantities()
  std::vector<bool> last_step;                // as quantities(): a navier-stokes value of the last step
};

FileData read(const std::string& path, const std::vector<const AttrSpec*>& ps,
              const std::vector<Quantity>& qs) {
  check_result(path);  // a file inspect refuses is refused here too, not shown with "—" or "undefined"
  const ResultFile f(path);
  FileData d;
  d.path = path;
  d.viscous = f.has_attr("/", "model") && f.attr_string("/", "model") == "navier-stokes";
  d.partial = d.viscous && f.has_attr("/", "partial") && f.attr_int("/", "partial") != 0;
  if (d.viscous && f.has_attr("/", "status")) d.status = f.attr_string("/", "status");
  for (const AttrSpec* p : ps) {
    Param v;
    if (std::string(p->group) == "/" && std::string(p->name) == "model") {
      v.text = d.viscous ? "navier-stokes" : "potential";  // version 1 files hold potential flow only
    } else if (f.has_attr(p->group, p->name)) {
      if (p->kind == AttrKind::text)
        v.text = f.attr_string(p->group, p->name);
      else
        v.number = f.attr_double(p->group, p->name);
    }
    d.params.push_back(v);
  }
  // A navier-stokes file's lift, drag, C_L, C_D are compared by their time means (means with means): the
  // last step's values are one instant of a shedding wake.
  auto attr = [&](const AttrSpec* a) -> std::optional<double> {
    if (const AttrSpec* mean = d.viscous ? viscous_mean_of(a->group, a->name) : nullptr) a = mean;
    if (!f.has_attr(a->group, a->name)) return std::nullopt;
    return f.attr_double(a->group, a->name);
  };
  auto last = [&](const AttrSpec* a) {
    return a && d.viscous && viscous_last_step(a->group, a->name) && !viscous_mean_of(a->group, a->name);
  };
  for (const Quantity& q : qs) {
    d.last_step.push_back(last(q.attr) || last(q.num) || last(q.den));
    if (q.attr) {
      d.values.push_back(attr(q.attr));
      continue;
    }
    const auto n = attr(q.num), m = attr(q.den);
    d.values.push_back(n && m && *m != 0.0 ? std::optional<double>(*n / *m - (q.minus_one ? 1.0 : 0.0))
                                           : std::nullopt);
  }
  return d;
}

}  // namespace

Comparison compare_results(const std::vector<std::string>& paths) {
  if (paths.empty()) throw std::invalid_argument("compare: no result files given");
  const std::vector<const AttrSpec*> kParams = params();
  std::vector<Quantity> kQuantities = quantities();
  std::vector<FileData> files;
  for (const auto& p : paths) files.push_back(read(p, kParams, kQuantities));
  // Only the rows of the files' models: potential results alone show no viscous rows, and the other way
  // round; in a mixed comparison each file shows "—" in the other model's rows.
  {
    std::vector<Quantity> kept;
    std::vector<std::vector<std::optional<double>>> values(files.size());
    std::vector<std::vector<bool>> last(files.size());
    for (size_t q = 0; q < kQuantities.size(); ++q) {
      if (std::none_of(files.begin(), files.end(),
                       [&](const FileData& f) { return f.has(kQuantities[q].models()); }))
        continue;
      kept.push_back(kQuantities[q]);
      for (size_t i = 0; i < files.size(); ++i)
        values[i].push_back(files[i].values[q]), last[i].push_back(files[i].last_step[q]);
    }
    kQuantities = std::move(kept);
    for (size_t i = 0; i < files.size(); ++i)
      files[i].values = std::move(values[i]), files[i].last_step = std::move(last[i]);
  }

  Comparison out;
  std::vector<size_t> differ;
  for (size_t k = 0; k < std::size(kParams); ++k)
    for (size_t i = 1; i < files.size(); ++i)
      if (!same(files[0].params[k], files[i].params[k])) {
        differ.push_back(k);
        out.differing.push_back(kParams[k]->name);
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
    const std::string units = kParams[k]->kind == AttrKind::number ? kParams[k]->units : "";
    param_rows.push_back(
        {units.empty() ? kParams[k]->name : fmt::format("{} ({})", kParams[k]->name, units), cells});
  }
  for (size_t q = 0; q < std::size(kQuantities); ++q) {
    std::vector<std::string> cells;
    for (const auto& f : files)
      cells.push_back(!f.has(kQuantities[q].models()) ? kNotApplicable
                      : f.values[q] ? figure(*f.values[q], kQuantities[q].spec.c_str()) +
                                          (f.last_step[q] ? " (last step)" : "")
                                    : "undefined");
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
    t += fmt::format("  {} {}{}{}\n", head[i], files[i].path,
                     title.text ? "  — " + *title.text : std::string(),
                     files[i].partial ? "  (PARTIAL: " + files[i].status + ")" : std::string());
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
  const bool any_viscous =
      std::any_of(files.begin(), files.end(), [](const FileData& f) { return f.viscous; });
  t += any_viscous ? "lift, drag, errors; viscous beside ideal (— : not of that file's model); navier-stokes "
                     "lift, drag, C_L, C_D: time means\n"
                   : "lift, drag, errors\n";
  for (const auto& [label, cells] : value_rows) row(label, cells);

  // CSV: one row per file; with navier-stokes files, a column partial: 1, 0, or "" for a potential file.
  std::string& c = out.csv;
  c += any_viscous ? "file,title,partial" : "file,title";
  for (size_t k : differ)
    if (k != 0) c += std::string(",") + kParams[k]->name;
  for (const auto& q : kQuantities) c += std::string(",") + q.csv;
  // With navier-stokes files: the columns that hold a file's last-step values (space-separated; the rest of
  // its lift, drag, C_L, C_D columns are time means).
  if (any_viscous) c += ",last_step";
  c += "\n";
  for (const auto& f : files) {
    c += csv_field(f.path) + "," + csv_field(f.params[0].text.value_or(""));
    if (any_viscous) c += f.viscous ? (f.partial ? ",1" : ",0") : ",";
    for (size_t k : differ)
      if (k != 0)
        c += "," + csv_field(f.params[k].text     ? *f.params[k].text
                             : f.params[k].number ? csv_number(*f.params[k].number)
                                                  : "");
    for (const auto& v : f.values) c += "," + (v ? csv_number(*v) : std::string());
    if (any_viscous) {
      std::string names;
      for (size_t q = 0; q < kQuantities.size(); ++q)
        if (f.last_step[q] && f.values[q]) names += (names.empty() ? "" : " ") + kQuantities[q].csv;
      c += "," + csv_field(names);
    }
    c += "\n";
  }
  return out;
}

void command_compare(const std::vector<std::string>& paths, const std::string& csv) {
  check_distinct_paths(paths, {csv});
  if (!csv.empty()) check_writable(csv);
  const Comparison c = compare_results(paths);
  if (!csv.empty()) write_text_output(csv, c.csv);
  // With --csv -, standard output carries the CSV alone (for a pipe); the table, which says the same, is
  // not printed.
  if (!is_stdout(csv)) std::fputs(c.table.c_str(), stdout);
}

}  // namespace magnus
