#pragma once
// Writing and reading the rows of a declared table (io/schema_table.hpp): the one way every magnus file
// stores its attributes and columns. Numbers carry their unit in NAME_units (format version 2); an undefined
// number is never stored (no NaN) but listed in its group's `undefined` attribute; a column undefined at
// some rows holds the netCDF fill value there, named by its `_FillValue` attribute.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "io/hdf5_io.hpp"
#include "io/schema_table.hpp"

namespace magnus {

/// The value stored where a column with some defined rows is undefined (netCDF's default fill for doubles;
/// the dataset's `_FillValue` attribute says so, and xarray/netCDF readers mask it).
constexpr double kFillValue = 9.969209968386869e36;

/// The groups of a file being written, each created on first use, and per group the names of the values
/// left undefined (written by write_undefined).
struct FileGroups {
  H5Writer& w;
  std::map<std::string, H5Writer::id> ids = {};
  std::map<std::string, std::vector<std::string>> undefined = {};
  /// The group ("/": the file), created when first asked for.
  H5Writer::id operator()(const std::string& group);
};

/// How an undefined value is stored: as it is (NaN; a checkpoint, whose reader refuses it naming it), as
/// kFillValue in a column (named by `_FillValue`), or so and, when no row is defined (and there are rows),
/// not at all (the name listed in `undefined`). An undefined attribute is listed unless as_is.
enum class Gaps { as_is, fill, fill_or_omit };

/// Store each value: text as is; a number (or an integer, as a long) with NAME_units when its units are not
/// "" — or, when empty or (but with Gaps::as_is) not finite, only its name in the group's undefined list.
void write_attrs(const std::vector<AttrValue>& values, FileGroups& g, Gaps gaps = Gaps::fill_or_omit);

/// Each group's `undefined` attribute: its undefined names, comma-separated.
void write_undefined(FileGroups& g);

/// The dataset group/NAME of a column's values v, with its units and description.
void write_column(FileGroups& g, const std::string& group, const char* name, const char* units,
                  const std::string& description, std::vector<double> v, Gaps gaps);

/// Every column of `columns` at `rows`, as write_column.
template <class Row>
void write_columns(FileGroups& g, const std::string& group, const std::vector<Column<Row>>& columns,
                   const std::vector<Row>& rows, Gaps gaps) {
  for (const Column<Row>& c : columns) {
    std::vector<double> v;
    for (const Row& r : rows) v.push_back(c.get(r));
    write_column(g, group, c.name, c.units, c.description, std::move(v), gaps);
  }
}

/// Every dataset of the table (1-D: a flat array) as write_column with `gaps`.
template <class From, class Into>
void write_datasets(FileGroups& g, const std::vector<Dataset<From, Into>>& table, const From& x, Gaps gaps) {
  for (const Dataset<From, Into>& d : table) {
    const size_t slash = d.path.rfind('/');
    write_column(g, d.path.substr(0, slash), d.path.substr(slash + 1).c_str(), d.units.c_str(), d.description,
                 d.values(x), gaps);
  }
}

/// Every dataset of the table read back in order, each passed to check (which may throw) and then put back
/// by its set; those without a set are returned by path, for the caller to assemble.
template <class From, class Into>
std::map<std::string, std::vector<double>> read_datasets(
    const std::vector<Dataset<From, Into>>& table, const ResultFile& f, Into& x,
    const std::function<void(const std::string&, const std::vector<double>&)>& check = {}) {
  std::map<std::string, std::vector<double>> rest;
  for (const Dataset<From, Into>& d : table) {
    std::vector<double> v = f.dataset(d.path);
    if (check) check(d.path, v);
    if (d.set)
      d.set(x, std::move(v));
    else
      rest[d.path] = std::move(v);
  }
  return rest;
}

/// The values of column group/NAME read back, kFillValue as NaN. Throws one line naming the file when it is
/// missing or does not hold n values.
std::vector<double> read_column(const ResultFile& f, const std::string& group, const char* name, size_t n);

/// Put every attribute of the table the file holds back into x (a `required` one missing: one line naming
/// it). Integers are read as integers unless lenient (a magnus-flow file reads them as numbers).
template <class From, class Into>
void read_attrs(const std::vector<Attr<From, Into>>& table, const ResultFile& f, Into& x, bool lenient = false) {
  for (const Attr<From, Into>& a : table) {
    if (!a.required && !f.has_attr(a.group, a.name)) continue;
    if (a.kind == AttrKind::text && a.set_text)
      a.set_text(x, f.attr_string(a.group, a.name));
    else if (a.kind == AttrKind::integer && a.set_number && !lenient)
      a.set_number(x, double(f.attr_int(a.group, a.name)));
    else if (a.kind != AttrKind::text && a.set_number)
      a.set_number(x, f.attr_double(a.group, a.name));
  }
}

}  // namespace magnus
