#pragma once
// The declared-table machinery every magnus file shares (a flow result, a sweep, an S(Re, α) map, a
// checkpoint): one row per attribute, dataset or column with its name, unit, description and how to get it
// from (and put it back into) the C++ struct it stores. The writers, readers, inspect and --json walk these
// rows (io/schema_io.hpp); no other place lists a file's keys.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace magnus {

/// How an attribute is stored.
enum class AttrKind { number, integer, text };

/// Which results an entry belongs to: every result, potential flow's only (errors against the exact
/// solution), the navier-stokes model's only (means, history) or a steady grid study's only (its grids and
/// Richardson values, time.mode = "steady"). An entry that does not apply is absent.
enum class Models { all, potential, viscous, steady_study };

/// Where an entry appears: in the file and in the --json output, or in one of them only.
enum class Shown { everywhere, file_only, json_only };

/// What a dataset's shape follows.
/// (n_r), (n_θ), (n_r, n_θ), (k) stagnation points, (n_steps) history, (k) separation points, (n_grids)
/// the grids of a steady study, (n) a flat array (a checkpoint's state, a sweep's column).
enum class DataShape { n_r, n_theta, grid, points, steps, levels, flat };

/// One attribute of a file written from a From and read back into an Into (the same struct but for a
/// checkpoint, written from its case and state and read into its state).
template <class From, class Into = From>
struct Attr {
  const char* group;  ///< "/", "/parameters", "/forces", …
  const char* name;   ///< attribute name
  AttrKind kind;
  const char* units;        ///< UDUNITS string ("" for text, and for an integer stored without NAME_units)
  const char* description;  ///< one line
  /// The value of a number or integer; empty when undefined (then not stored, listed in `undefined`).
  std::function<std::optional<double>(const From&)> number;
  /// The value of a text attribute.
  std::function<std::string(const From&)> text;
  /// Put a value read from a file back (the readers); may be empty.
  std::function<void(Into&, double)> set_number;
  std::function<void(Into&, const std::string&)> set_text;
  const char* compare_label = nullptr;   ///< row label in `magnus compare` (nullptr: not a row)
  const char* compare_csv = nullptr;     ///< its CSV column name
  const char* compare_format = nullptr;  ///< its fmt spec in the table
  Models models = Models::all;           ///< (a flow result) the model it belongs to
  std::function<bool(const From&)> when = {};  ///< empty: always there; else absent where false
  Shown shown = Shown::everywhere;
  bool required = false;  ///< a reader refuses a file without it (one line naming it)
};

/// One dataset of a file (see Attr for From and Into).
template <class From, class Into = From>
struct Dataset {
  std::string path;         ///< "/fields/psi"
  std::string units;        ///< UDUNITS string
  std::string description;  ///< one line ("": none stored)
  DataShape shape;
  /// The values (row-major); empty: not written (a field not selected, Cp at U = 0).
  std::function<std::vector<double>(const From&)> values;
  /// Put values read from a file back; may be empty.
  std::function<void(Into&, std::vector<double>)> set;
  Models models = Models::all;
  /// The description in a navier-stokes result where the model computes it otherwise (the pressure: the
  /// pressure Poisson equation, not Bernoulli); empty: `description` for both models.
  std::string viscous_description = {};
};

/// One column of a table stored as one dataset per column (a sweep's /sweep/NAME, a history): its value at
/// a row (NaN: undefined) and how to put a value read back into a row.
template <class Row>
struct Column {
  const char* name;
  const char* units;
  std::string description;
  std::function<double(const Row&)> get;
  std::function<void(Row&, double)> set = {};
};

/// A defined number (a row's getter).
inline std::optional<double> opt(double v) { return v; }

/// An attribute's value for one struct: what the writers store and the --json outputs print.
struct AttrValue {
  const char* group;
  const char* name;
  AttrKind kind;
  const char* units;
  std::optional<double> number;  ///< number and integer
  std::string text;              ///< text
};

/// The value of row a for x.
template <class From, class Into>
AttrValue value_of(const Attr<From, Into>& a, const From& x) {
  return {a.group, a.name, a.kind, a.units,
          a.kind != AttrKind::text && a.number ? a.number(x) : std::nullopt,
          a.kind == AttrKind::text && a.text ? a.text(x) : std::string()};
}

/// The values of the rows there for x (`when`) and shown in `where` (file_only: the file, json_only: --json).
template <class From, class Into>
std::vector<AttrValue> attr_values(const std::vector<Attr<From, Into>>& table, const From& x, Shown where) {
  std::vector<AttrValue> out;
  for (const Attr<From, Into>& a : table)
    if ((a.shown == Shown::everywhere || a.shown == where) && (!a.when || a.when(x))) out.push_back(value_of(a, x));
  return out;
}

/// Rows of a table of From (read into Into): a number with its unit, an integer (unit "1", or none with
/// units ""), a text; `when` and `shown` narrow where a row appears.
template <class From, class Into = From>
struct Rows {
  using Row = Attr<From, Into>;
  using Get = std::function<std::optional<double>(const From&)>;
  using Set = std::function<void(Into&, double)>;
  using GetText = std::function<std::string(const From&)>;
  using SetText = std::function<void(Into&, const std::string&)>;

  /// A number with its unit (NAME_units).
  static Row num(const char* group, const char* name, const char* units, const char* description, Get get,
                 Set set = {}) {
    return Row{group, name, AttrKind::number, units, description, std::move(get), {}, std::move(set), {}};
  }
  /// An integer, stored as a long; unit "1" (or units "": no NAME_units).
  static Row integer(const char* group, const char* name, const char* description, Get get, Set set = {},
                     const char* units = "1") {
    return Row{group, name, AttrKind::integer, units, description, std::move(get), {}, std::move(set), {}};
  }
  /// A text (a name, a choice): no unit unless given.
  static Row text(const char* group, const char* name, const char* description, GetText get,
                  SetText set = {}, const char* units = "") {
    return Row{group, name, AttrKind::text, units, description, {}, std::move(get), {}, std::move(set)};
  }
  /// a, there only where `there` holds.
  static Row when(std::function<bool(const From&)> there, Row a) {
    a.when = std::move(there);
    return a;
  }
  /// a, in the file or the --json output only.
  static Row shown(Shown where, Row a) {
    a.shown = where;
    return a;
  }
  /// a, which a reader cannot do without.
  static Row required(Row a) {
    a.required = true;
    return a;
  }
  /// The root rows a sweep file opens with: format and format_version (the file's only), software_version
  /// and model.
  static std::vector<Row> header(const char* format, long version, const char* model) {
    return {shown(Shown::file_only, text("/", "format", "the file's kind", [format](const From&) { return std::string(format); })),
            shown(Shown::file_only, integer("/", "format_version", "version of this layout",
                                            [version](const From&) { return opt(double(version)); })),
            text("/", "software_version", "magnus version that wrote the file",
                 [](const From&) { return std::string(MAGNUS_VERSION); }),
            text("/", "model", "flow model", [model](const From&) { return std::string(model); })};
  }
};

}  // namespace magnus
