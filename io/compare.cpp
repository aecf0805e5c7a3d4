#include "io/compare.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/text_format.hpp"

namespace magnus {

namespace {

/// The marker of a row that does not apply to a file's model.
constexpr const char* kNotApplicable = "—";

std::string show(const CompareParam& p) {
  if (p.text) return *p.text;
  if (p.number) return figure(*p.number, "{:.10g}");
  return "—";
}

/// A row of the table: its label and one cell per file.
using TableRow = std::pair<std::string, std::vector<std::string>>;

/// The parameters that differ (but the title, which heads the table), one row each.
std::vector<TableRow> param_rows(const ComparedFiles& d) {
  std::vector<TableRow> rows;
  for (size_t k : d.differ) {
    if (k == 0) continue;  // the titles head the table already
    std::vector<std::string> cells;
    for (const auto& f : d.files) cells.push_back(show(f.params[k]));
    const AttrSpec& p = *d.params[k];
    const std::string units = p.kind == AttrKind::number ? p.units : "";
    rows.push_back({units.empty() ? p.name : fmt::format("{} ({})", p.name, units), cells});
  }
  return rows;
}

/// One row per quantity: the figure, "(last step)" after a navier-stokes value of the last step, "undefined",
/// or "—" where the row is not of the file's model.
std::vector<TableRow> value_rows(const ComparedFiles& d) {
  std::vector<TableRow> rows;
  for (size_t q = 0; q < d.quantities.size(); ++q) {
    std::vector<std::string> cells;
    for (const auto& f : d.files)
      cells.push_back(!f.has(d.quantities[q].models()) ? kNotApplicable
                      : f.values[q]                    ? figure(*f.values[q], d.quantities[q].spec.c_str()) +
                                          (f.last_step[q] ? " (last step)" : "")
                                    : "undefined");
    rows.push_back({d.quantities[q].label, cells});
  }
  return rows;
}

bool any_viscous(const ComparedFiles& d) {
  return std::any_of(d.files.begin(), d.files.end(), [](const ComparedFile& f) { return f.viscous; });
}

}  // namespace

std::vector<const AttrSpec*> compare_parameters() {
  std::vector<const AttrSpec*> out = {find_attribute("/", "title"), find_attribute("/", "model")};
  for (const AttrSpec& a : result_attributes())
    if (std::string(a.group) == "/parameters") out.push_back(&a);
  return out;
}

std::vector<CompareQuantity> compare_quantities() {
  std::vector<CompareQuantity> out;
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

ComparedFile read_compared(const std::string& path, const std::vector<const AttrSpec*>& ps,
                           const std::vector<CompareQuantity>& qs) {
  check_result(path);  // a file inspect refuses is refused here too, not shown with "—" or "undefined"
  const ResultFile f(path);
  ComparedFile d;
  d.path = path;
  d.viscous = f.has_attr("/", "model") && f.attr_string("/", "model") == "navier-stokes";
  d.partial = d.viscous && f.has_attr("/", "partial") && f.attr_int("/", "partial") != 0;
  if (d.viscous && f.has_attr("/", "status")) d.status = f.attr_string("/", "status");
  for (const AttrSpec* p : ps) {
    CompareParam v;
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
  for (const CompareQuantity& q : qs) {
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

std::string comparison_table(const ComparedFiles& d) {
  const size_t n = d.files.size();
  std::vector<std::string> head(n);
  for (size_t i = 0; i < n; ++i) head[i] = fmt::format("[{}]", i + 1);
  const std::vector<TableRow> params = param_rows(d), values = value_rows(d);
  size_t label_w = 24;
  std::vector<size_t> col_w(n, 12);
  for (const auto* rows : {&params, &values})
    for (const auto& [label, cells] : *rows) {
      label_w = std::max(label_w, display_width(label) + 2);
      for (size_t i = 0; i < n; ++i) col_w[i] = std::max(col_w[i], display_width(cells[i]));
    }

  std::string t = fmt::format("magnus compare: {} result file{}\n", n, n == 1 ? "" : "s");
  for (size_t i = 0; i < n; ++i) {
    const ComparedFile& f = d.files[i];
    const CompareParam& title = f.params[0];
    t += fmt::format("  {} {}{}{}\n", head[i], f.path, title.text ? "  — " + *title.text : std::string(),
                     f.partial ? "  (PARTIAL: " + f.status + ")" : std::string());
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
  } else if (params.empty()) {
    t += d.differ.empty() ? "parameters: all the same\n" : "parameters: all the same but the title\n";
  } else {
    t += "parameters that differ\n";
    for (const auto& [label, cells] : params) row(label, cells);
  }
  t += any_viscous(d)
           ? "lift, drag, errors; viscous beside ideal (— : not of that file's model); navier-stokes "
             "lift, drag, C_L, C_D: time means\n"
           : "lift, drag, errors\n";
  for (const auto& [label, cells] : values) row(label, cells);
  return t;
}

std::string comparison_csv(const ComparedFiles& d) {
  // One row per file; with navier-stokes files, a column partial: 1, 0, or "" for a potential file.
  const bool viscous = any_viscous(d);
  std::string c = viscous ? "file,title,partial" : "file,title";
  for (size_t k : d.differ)
    if (k != 0) c += std::string(",") + d.params[k]->name;
  for (const auto& q : d.quantities) c += std::string(",") + q.csv;
  // With navier-stokes files: the columns that hold a file's last-step values (space-separated; the rest of
  // its lift, drag, C_L, C_D columns are time means).
  if (viscous) c += ",last_step";
  c += "\n";
  for (const auto& f : d.files) {
    c += csv_field(f.path) + "," + csv_field(f.params[0].text.value_or(""));
    if (viscous) c += f.viscous ? (f.partial ? ",1" : ",0") : ",";
    for (size_t k : d.differ)
      if (k != 0)
        c += "," + csv_field(f.params[k].text     ? *f.params[k].text
                             : f.params[k].number ? csv_number(*f.params[k].number)
                                                  : "");
    for (const auto& v : f.values) c += "," + (v ? csv_number(*v) : std::string());
    if (viscous) {
      std::string names;
      for (size_t q = 0; q < d.quantities.size(); ++q)
        if (f.last_step[q] && f.values[q]) names += (names.empty() ? "" : " ") + d.quantities[q].csv;
      c += "," + csv_field(names);
    }
    c += "\n";
  }
  return c;
}

}  // namespace magnus
