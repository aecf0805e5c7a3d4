#pragma once
// The --json outputs of run, sweep, compare, inspect and probe: one JSON object each (nlohmann-json).
//
// Convention, the same everywhere: every number is an object {"value": V, "units": U} with U a UDUNITS
// string as in the result files ("1" for a dimensionless number); V is a number, an array of numbers, or
// null where the figure is undefined (never NaN). Text (names, choices, paths) is a plain string, a yes/no a
// plain boolean. Objects keep their keys in the order of the schema table (io/schema.hpp), from which the
// attributes are taken: no key is listed here that the table already lists.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/compare.hpp"
#include "io/schema_table.hpp"
#include "physics/reference_data.hpp"
#include "postproc/result.hpp"
#include "postproc/potential/sweep.hpp"

namespace magnus {

using Json = nlohmann::ordered_json;

/// {"value": v, "units": units}; null when v is empty or not finite.
Json quantity(std::optional<double> v, const std::string& units);
/// {"value": n, "units": "1"}: a count (an integer in the JSON).
Json count(long n);
/// {"value": [...], "units": units}; entries that are not finite are null.
Json quantity(const std::vector<double>& v, const std::string& units);

/// An attribute's value (io/schema_table.hpp): text as a string, an integer as a count, a number as a
/// quantity with its units (null where undefined).
Json value_json(const AttrValue& a);

/// Each value into j in order: a root one ("/") as j[name], another as j[GROUP][name] ("/forces" → "forces").
void put_values(Json& j, const std::vector<AttrValue>& values);

/// The text of a JSON output: indented by two, one trailing newline.
std::string json_text(const Json& j);

/// `magnus run --json`: the figures of the run summary (summary_text or viscous_summary_text), every
/// attribute of the schema that applies to r (parameters, forces, errors, timing), the stagnation (or
/// separation) points and the figures the summary derives (ratios, wall cells, steps/s …).
Json result_json(const FlowResult& r, const std::string& output_path);

/// `magnus sweep --json`: the case, grid, solver, timing and one object per point (the CSV's columns), the
/// viscous reference points in range (ref may be null) and the files written.
Json sweep_json(const SweepResult& s, const ViscousReference* ref, const std::vector<std::string>& written);

/// `magnus compare --json`: the parameters that differ (from c, compare_results(paths)) and, per file, its
/// schema groups as stored plus the ratios of the table. Throws one line naming an unreadable file.
Json compare_json(const std::vector<std::string>& paths, const Comparison& c);

/// `magnus inspect --json`: what a result or sweep file holds (attributes with units, stagnation points,
/// time series, datasets with shape and units; a sweep file's columns in full). Every value is read back,
/// as by the text. Throws one line.
Json inspect_json(const std::string& path);

}  // namespace magnus
