#pragma once
// `magnus compare`'s formats: what a result file holds of the compared parameters and figures (read through
// the schema table), and the side-by-side table and CSV of several files. The comparison itself (which rows,
// which parameters differ) is app/compare.hpp's.
#include <optional>
#include <string>
#include <vector>

#include "io/schema.hpp"

namespace magnus {

/// The comparison of result files: a text table (for stdout) and the same as CSV (one row per file).
struct Comparison {
  std::string table, csv;
  std::vector<std::string> differing;  ///< names of the parameters that differ between the files
};

/// A parameter as one file holds it: a number, a text, or absent.
struct CompareParam {
  std::optional<double> number;
  std::optional<std::string> text;
  bool present() const { return number || text; }
};

/// One row of the comparison: a schema attribute with a compare label, or a ratio of two of them.
struct CompareQuantity {
  std::string label, csv, spec;
  const AttrSpec* attr = nullptr;  ///< the value, or
  const AttrSpec* num = nullptr;   ///< num / den (− 1 when minus_one)
  const AttrSpec* den = nullptr;
  bool minus_one = false;
  /// The results the row belongs to: a file of the other model shows "—" there (not "undefined").
  Models models() const { return (attr ? attr : num)->models; }
};

/// What one file holds of the compared parameters and quantities.
struct ComparedFile {
  std::string path;
  bool viscous = false;  ///< a navier-stokes result
  bool partial = false;  ///< a navier-stokes run stopped before its end (/@partial = 1)
  std::string status;    ///< why it stopped (navier-stokes)
  bool has(Models m) const { return m == Models::all || (m == Models::viscous) == viscous; }
  std::vector<CompareParam> params;           ///< as compare_parameters()
  std::vector<std::optional<double>> values;  ///< as the quantities
  std::vector<bool> last_step;                ///< as the quantities: a navier-stokes value of the last step
};

/// The files side by side: the parameters, the rows shown, and which parameters differ (indices into params).
struct ComparedFiles {
  std::vector<const AttrSpec*> params;
  std::vector<CompareQuantity> quantities;
  std::vector<ComparedFile> files;
  std::vector<size_t> differ;
};

/// The parameters compared: the root title, the model and every /parameters attribute of the schema.
std::vector<const AttrSpec*> compare_parameters();
/// The rows compared: every schema attribute with a compare label, and the two lift ratios after C_L seed.
std::vector<CompareQuantity> compare_quantities();

/// Read one result file's parameters and quantities (a navier-stokes file's lift, drag, C_L, C_D: its time
/// means). Refuses, in one line, a file inspect refuses.
ComparedFile read_compared(const std::string& path, const std::vector<const AttrSpec*>& ps,
                           const std::vector<CompareQuantity>& qs);

/// The table printed on stdout: the files, the parameters that differ, then one row per quantity.
std::string comparison_table(const ComparedFiles& d);
/// The CSV: one row per file (with navier-stokes files, the columns partial and last_step).
std::string comparison_csv(const ComparedFiles& d);

}  // namespace magnus
