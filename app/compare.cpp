#include "app/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "base/atomic_file.hpp"

namespace magnus {

namespace {

/// Two files hold the same parameter: both absent, the same text, or numbers within 1e-12 relative.
bool same(const CompareParam& a, const CompareParam& b) {
  if (a.present() != b.present()) return false;
  if (a.text || b.text) return a.text == b.text;
  if (!a.number) return true;
  const double x = *a.number, y = *b.number;
  return x == y || std::fabs(x - y) <= 1e-12 * std::max(std::fabs(x), std::fabs(y));
}

/// Only the rows of the files' models: potential results alone show no viscous rows, and the other way
/// round; in a mixed comparison each file shows "—" in the other model's rows.
void keep_rows_of_models(ComparedFiles& d) {
  std::vector<CompareQuantity> kept;
  std::vector<std::vector<std::optional<double>>> values(d.files.size());
  std::vector<std::vector<bool>> last(d.files.size());
  for (size_t q = 0; q < d.quantities.size(); ++q) {
    if (std::none_of(d.files.begin(), d.files.end(),
                     [&](const ComparedFile& f) { return f.has(d.quantities[q].models()); }))
      continue;
    kept.push_back(d.quantities[q]);
    for (size_t i = 0; i < d.files.size(); ++i)
      values[i].push_back(d.files[i].values[q]), last[i].push_back(d.files[i].last_step[q]);
  }
  d.quantities = std::move(kept);
  for (size_t i = 0; i < d.files.size(); ++i)
    d.files[i].values = std::move(values[i]), d.files[i].last_step = std::move(last[i]);
}

}  // namespace

Comparison compare_results(const std::vector<std::string>& paths) {
  if (paths.empty()) throw std::invalid_argument("compare: no result files given");
  ComparedFiles d;
  d.params = compare_parameters();
  d.quantities = compare_quantities();
  for (const auto& p : paths) d.files.push_back(read_compared(p, d.params, d.quantities));
  keep_rows_of_models(d);
  Comparison out;
  for (size_t k = 0; k < d.params.size(); ++k)
    for (size_t i = 1; i < d.files.size(); ++i)
      if (!same(d.files[0].params[k], d.files[i].params[k])) {
        d.differ.push_back(k);
        out.differing.push_back(d.params[k]->name);
        break;
      }
  out.table = comparison_table(d);
  out.csv = comparison_csv(d);
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
