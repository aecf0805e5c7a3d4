#pragma once
// The one table of what a magnus-flow file holds: every attribute of /, /parameters,
// /forces, /errors and /timing and every dataset, with its unit, a one-line description and how to get
// it from (and put it back into) a FlowResult. The writer, the reader, inspect and compare use it; no
// other place lists the keys.
//
// Units convention (format version 2): a dataset carries a `units` attribute; a numeric group attribute
// NAME carries a companion attribute `NAME_units`. Text attributes (names, choices) carry none. Units are
// UDUNITS strings ("m^2/s", "kg/m^3", "rad"; "1" for a dimensionless number). An undefined value is never
// stored (no NaN): its name is listed in the group's `undefined` attribute (comma-separated).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "postproc/result.hpp"

namespace magnus {

/// The format version written; readers accept 1 and 2.
constexpr long kFlowFormatVersion = 2;

/// How an attribute is stored.
enum class AttrKind { number, integer, text };

/// Which results an entry belongs to: every result, potential flow's only (errors against the exact
/// solution), the navier-stokes model's only (means, history) or a steady grid study's only (its grids and
/// Richardson values, time.mode = "steady"). An entry that does not apply is absent.
enum class Models { all, potential, viscous, steady_study };

/// Whether an entry for `m` belongs in result r.
bool applies(Models m, const FlowResult& r);

/// One attribute of a magnus-flow file.
struct AttrSpec {
  const char* group;  ///< "/", "/parameters", "/forces", "/errors", "/timing"
  const char* name;   ///< attribute name
  AttrKind kind;
  const char* units;        ///< UDUNITS string; "" for text
  const char* description;  ///< one line
  /// The value of a number or integer from a result; empty when undefined (then not stored).
  std::function<std::optional<double>(const FlowResult&)> number;
  /// The value of a text attribute.
  std::function<std::string(const FlowResult&)> text;
  /// Put a value read from a file back into a result (read_result); may be empty.
  std::function<void(FlowResult&, double)> set_number;
  std::function<void(FlowResult&, const std::string&)> set_text;
  const char* compare_label = nullptr;   ///< row label in `magnus compare` (nullptr: not a row)
  const char* compare_csv = nullptr;     ///< its CSV column name
  const char* compare_format = nullptr;  ///< its fmt spec in the table
  Models models = Models::all;
};

/// What a dataset's shape follows.
/// (n_r), (n_θ), (n_r, n_θ), (k) stagnation points, (n_steps) history, (k) separation points, (n_grids)
/// the grids of a steady study.
enum class DataShape { n_r, n_theta, grid, points, steps, levels };

/// One stored dataset of a magnus-flow file.
struct DatasetSpec {
  std::string path;         ///< "/fields/psi"
  std::string units;        ///< UDUNITS string
  std::string description;  ///< one line
  DataShape shape;
  /// The values from a result (row-major); empty: not written (a field not selected, Cp at U = 0).
  std::function<std::vector<double>(const FlowResult&)> values;
  /// Put values read from a file back into a result; may be empty.
  std::function<void(FlowResult&, std::vector<double>)> set;
  Models models = Models::all;
  /// The description in a navier-stokes result where the model computes it otherwise (the pressure: the
  /// pressure Poisson equation, not Bernoulli); empty: `description` for both models.
  std::string viscous_description = {};
};

/// The one-line description of d as a result of the given model (viscous: navier-stokes).
const std::string& description_of(const DatasetSpec& d, bool viscous);

/// Every attribute, in file order.
const std::vector<AttrSpec>& result_attributes();
/// Every stored dataset (fields in field_names() order), in file order.
const std::vector<DatasetSpec>& result_datasets();
/// The fields of result_datasets() (paths /fields/NAME).
std::vector<const DatasetSpec*> field_datasets();
/// The attribute group/name, or nullptr.
const AttrSpec* find_attribute(const std::string& group, const std::string& name);
/// True for the /forces attributes a navier-stokes result holds at its last time step, not as a time mean
/// (lift, drag, cl, cd, delta_p_top_bottom and the pressure/friction parts, cm, torque, spin_power).
bool viscous_last_step(const std::string& group, const std::string& name);
/// The time-mean attribute that stands for a last-step one in a navier-stokes comparison (cl → cl_mean,
/// cd → cd_mean, lift → lift_mean, drag → drag_mean), or nullptr.
const AttrSpec* viscous_mean_of(const std::string& group, const std::string& name);
/// The dataset at path, or nullptr. Knows the mesh views (/mesh/...) too.
const DatasetSpec* find_dataset(const std::string& path);
/// The units of any dataset magnus writes (stored, or the /mesh views of the .xmf); "" if unknown.
std::string dataset_units(const std::string& path);
/// The companion attribute holding an attribute's unit: NAME_units.
std::string units_attribute(const std::string& name);

}  // namespace magnus
