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
#include <string>
#include <vector>

#include "io/schema_table.hpp"
#include "postproc/result.hpp"

namespace magnus {

/// The format version written; readers accept 1 and 2.
constexpr long kFlowFormatVersion = 2;

/// Whether an entry for `m` belongs in result r.
bool applies(Models m, const FlowResult& r);

/// One attribute of a magnus-flow file (io/schema_table.hpp).
using AttrSpec = Attr<FlowResult>;

/// One stored dataset of a magnus-flow file.
using DatasetSpec = Dataset<FlowResult>;

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
