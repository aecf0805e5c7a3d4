#pragma once
// Building blocks of the schema table (io/schema.cpp, io/schema_viscous.cpp): one attribute or dataset entry
// from its group, name, unit, description and the member of FlowResult it reads and writes. Internal to io/.
#include <functional>
#include <optional>
#include <string>

#include "io/schema.hpp"

namespace magnus::schema_build {

using Flow = Rows<FlowResult>;
using Get = Flow::Get;
using Set = Flow::Set;

inline AttrSpec num(const char* group, const char* name, const char* units, const char* description, Get get,
                    Set set = {}) {
  return Flow::num(group, name, units, description, std::move(get), std::move(set));
}

inline AttrSpec integer(const char* group, const char* name, const char* description, Get get, Set set = {}) {
  return Flow::integer(group, name, description, std::move(get), std::move(set));
}

inline AttrSpec text(const char* group, const char* name, const char* description, Flow::GetText get,
                     Flow::SetText set = {}) {
  return Flow::text(group, name, description, std::move(get), std::move(set));
}

inline AttrSpec row(AttrSpec a, const char* label, const char* csv, const char* spec) {
  a.compare_label = label;
  a.compare_csv = csv;
  a.compare_format = spec;
  return a;
}

inline AttrSpec only(Models m, AttrSpec a) {
  a.models = m;
  return a;
}

inline DatasetSpec only(Models m, DatasetSpec d) {
  d.models = m;
  return d;
}

/// The viscous part of a result being read back (created on first use).
inline ViscousPart& vis(FlowResult& r) {
  if (!r.viscous) r.viscous.emplace();
  return *r.viscous;
}

/// A viscous number attribute: group, name, units, description, the member it reads and writes.
inline AttrSpec vnum(const char* group, const char* name, const char* units, const char* description,
                     std::optional<double> ViscousPart::*m) {
  return only(Models::viscous,
              num(
                  group, name, units, description,
                  [m](const FlowResult& r) { return r.viscous ? (*r.viscous).*m : std::nullopt; },
                  [m](FlowResult& r, double v) { vis(r).*m = v; }));
}

inline AttrSpec vnum(const char* group, const char* name, const char* units, const char* description,
                     double ViscousPart::*m) {
  return only(Models::viscous,
              num(
                  group, name, units, description,
                  [m](const FlowResult& r) { return r.viscous ? opt((*r.viscous).*m) : std::nullopt; },
                  [m](FlowResult& r, double v) { vis(r).*m = v; }));
}

/// A viscous force attribute of the last step (ViscousForces member; set_number fills it back).
template <class T>
inline AttrSpec vlast(const char* name, const char* units, const char* description, T ViscousForces::*m) {
  return only(Models::viscous, num(
                                   "/forces", name, units, description,
                                   [m](const FlowResult& r) -> std::optional<double> {
                                     if (!r.viscous) return std::nullopt;
                                     return r.viscous->last.*m;
                                   },
                                   [m](FlowResult& r, double v) { vis(r).last.*m = v; }));
}

/// The navier-stokes model's attributes (parameters, means and parts of the forces, run facts).
std::vector<AttrSpec> viscous_attributes();
/// A steady grid study's attributes of /steady_study (io/schema_study.cpp): converged, mirror, seconds,
/// message and the Richardson values of C_D, C_L and L/D with their error bars and orders.
std::vector<AttrSpec> study_attributes();
/// A steady grid study's datasets /steady_study/* (one value per grid, coarse to fine).
std::vector<DatasetSpec> study_datasets();
/// The scene's world placement and engineering forces (io/schema_scene.cpp): rpm, direction, course, span,
/// thrust, side force and the totals over the span.
std::vector<AttrSpec> scene_attributes();

}  // namespace magnus::schema_build
