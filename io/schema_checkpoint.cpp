// The checkpoint's table (io/schema_files.hpp): root (format, identity key, case), /state, the history and
// the kept snapshots.
#include <algorithm>

#include "io/checkpoint.hpp"
#include "io/schema_files.hpp"

namespace magnus {

namespace {

using R = Rows<CheckpointOut, Checkpoint>;
using Out = CheckpointOut;
using Data = Dataset<CheckpointOut, Checkpoint>;


/// A number of the stepper's state: read back (it must be there), checked finite by the reader.
R::Row state(const char* name, const char* units, const char* description, double NsState::*m) {
  return R::required(R::num(
      "/state", name, units, description, [m](const Out& o) { return opt(o.cp.state.*m); },
      [m](Checkpoint& cp, double v) { cp.state.*m = v; }));
}

/// An array of the stepper's state, read back as it is.
Data state_array(const char* name, const char* units, const char* description, std::vector<double> NsState::*m) {
  return {std::string("/state/") + name, units, description, DataShape::flat,
          [m](const Out& o) { return o.cp.state.*m; },
          [m](Checkpoint& cp, std::vector<double> v) { cp.state.*m = std::move(v); }};
}

/// The kept snapshots' times (field nullptr) or one field, each state after the other (the reader splits).
Data snapshots(const char* name, const char* units, std::vector<double> Snapshot::*field) {
  return {std::string("/snapshots/") + name, units, "", DataShape::flat, [field](const Out& o) {
            std::vector<double> v;
            for (const Snapshot& x : o.cp.snapshots)
              if (field)
                v.insert(v.end(), (x.*field).begin(), (x.*field).end());
              else
                v.push_back(x.t);
            return v;
          }, {}};
}

}  // namespace

const std::vector<std::pair<const char*, double ForceSample::*>>& checkpoint_history_members() {
  static const std::vector<std::pair<const char*, double ForceSample::*>> c = {
      {"t", &ForceSample::t},     {"cl", &ForceSample::C_L}, {"cd", &ForceSample::C_D},
      {"cm", &ForceSample::C_M},  {"fx", &ForceSample::F_x}, {"fy", &ForceSample::F_y},
      {"torque", &ForceSample::M}};
  return c;
}

const std::vector<Attr<CheckpointOut, Checkpoint>>& checkpoint_attributes() {
  static const std::vector<R::Row> table = {
      R::text("/", "format", "\"magnus-checkpoint\"", [](const Out&) { return std::string("magnus-checkpoint"); }),
      R::integer("/", "format_version", "version of this layout", [](const Out&) { return opt(1); }, {}, ""),
      R::text("/", "key", "the identity the case must share: \"key=value key=value …\"",
              [](const Out& o) { return checkpoint_key(o.c); }),
      R::text("/", "case", "the case as TOML", [](const Out& o) { return o.c.source_text; }),
      state("t", "s", "time t of the state", &NsState::t),
      state("Gamma_R", "m^2/s", "circulation Γ_R at the outer boundary", &NsState::Gamma_R),
      state("Gamma_flux_prev", "m^2/s^2", "the previous step's circulation flux", &NsState::Gamma_flux_prev),
      state("dt_prev", "s", "the previous time step", &NsState::dt_prev),
      R::integer(
          "/state", "steps", "time steps from rest to the state, over every run before",
          [](const Out& o) { return opt(double(o.cp.steps)); },
          [](Checkpoint& cp, double v) { cp.steps = std::max(0L, long(v)); }, ""),
  };
  return table;
}

const std::vector<Dataset<CheckpointOut, Checkpoint>>& checkpoint_datasets() {
  static const std::vector<Data> table = [] {
    std::vector<Data> t = {state_array("psi", "m^2/s", "stream function ψ", &NsState::psi),
                           state_array("zeta", "1/s", "vorticity ζ", &NsState::zeta),
                           state_array("N_prev", "m^2/s^2", "advection of the previous step", &NsState::N_prev)};
    for (const auto& [name, m] : checkpoint_history_members())
      t.push_back({std::string("/history/") + name, "", name, DataShape::flat, [m = m](const Out& o) {
                     std::vector<double> v;
                     for (const ForceSample& h : o.cp.history) v.push_back(h.*m);
                     return v;
                   }, {}});
    for (const Data& d : {snapshots("t", "s", nullptr), snapshots("psi", "m^2/s", &Snapshot::psi),
                          snapshots("vorticity", "1/s", &Snapshot::vorticity)})
      t.push_back(d);
    return t;
  }();
  return table;
}

}  // namespace magnus
