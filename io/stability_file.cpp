#include "io/stability_file.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "io/hdf5_io.hpp"
#include "io/schema_io.hpp"

namespace magnus {

namespace {

/// The number at key of each row (NaN where absent or null: stored as the fill value); booleans, and text
/// compared with one_when (given for a text key), as 0/1.
std::vector<double> column(const Json& rows, const char* key, const char* one_when) {
  std::vector<double> v;
  for (const Json& r : rows) {
    const auto it = r.find(key);
    if (it == r.end() || it->is_null())
      v.push_back(std::nan(""));
    else if (it->is_boolean())
      v.push_back(it->get<bool>() ? 1.0 : 0.0);
    else if (it->is_string() && one_when)
      v.push_back(*it == one_when ? 1.0 : 0.0);
    else
      v.push_back(it->get<double>());
  }
  return v;
}

/// One attribute from key of j under the file's name (undefined when absent, null or not finite).
AttrValue number(const char* group, const char* name, const Json& j, const char* key, const char* units,
                 AttrKind kind = AttrKind::number) {
  std::optional<double> v;
  const auto it = j.find(key);
  if (it != j.end() && !it->is_null()) v = it->is_boolean() ? (it->get<bool>() ? 1.0 : 0.0) : it->get<double>();
  return {group, name, kind, units, v, {}};
}

AttrValue text(const char* group, const char* name, std::string v) {
  return {group, name, AttrKind::text, "", std::nullopt, std::move(v)};
}

struct ColumnSpec {
  const char *key, *name, *units, *description;
  const char* one_when = nullptr;  ///< a text key: stored as 1 where it reads this, else 0
};

void write_rows(FileGroups& g, const std::string& group, const Json& rows, const std::vector<ColumnSpec>& specs) {
  for (const ColumnSpec& c : specs) write_column(g, group, c.name, c.units, c.description, column(rows, c.key, c.one_when), Gaps::fill_or_omit);
}

void write_spanwise(FileGroups& g, const Json& s) {
  const bool orbit = s.value("base", "") == "periodic";
  std::vector<ColumnSpec> specs = {
      {"beta_D", "beta_D", "1", "spanwise wavenumber β·D"},
      {"wavelength_D", "wavelength_D", "1", "spanwise wavelength λ_z/D = 2π/(β·D) (undefined at β = 0)"},
      {"growth_rate", "growth_rate", "1",
       orbit ? "Floquet exponent ln|μ|·D/(U T) of the leading multiplier" : "leading eigenvalue's real part, λ·D/U"},
      {"frequency", "frequency", "1", orbit ? "arg(μ)·D/(U T)" : "leading eigenvalue's imaginary part, λ·D/U"},
      {"covered", "covered", "1",
       orbit ? "1: the leading multiplier converged (Ritz estimate < 1e-3)" : "1: the shifts covered the strip"},
      {"solves", "solves", "1", orbit ? "time steps of the linear stepper" : "shifted solves"},
      {"seconds", "seconds", "s", "wall time of the wavenumber"}};
  if (orbit) {
    specs.push_back({"multiplier_real", "multiplier_real", "1", "leading Floquet multiplier μ, real part"});
    specs.push_back({"multiplier_imag", "multiplier_imag", "1", "leading Floquet multiplier μ, imaginary part"});
  }
  write_rows(g, "/spanwise", s["points"], specs);
  if (s.contains("accuracy_note")) write_attrs({text("/spanwise", "accuracy_note", s["accuracy_note"].get<std::string>())}, g);
  write_attrs({text("/spanwise", "base", s.value("base", "")), text("/spanwise", "verdict", s.value("verdict", "")),
               number("/spanwise", "stable", s, "stable", "", AttrKind::integer),
               number("/spanwise", "period", s, "period_D_over_U", "D/U"),
               number("/spanwise", "most_unstable_beta_D", s, "most_unstable_beta_D", "1"),
               number("/spanwise", "most_unstable_wavelength_D", s, "most_unstable_wavelength_D", "1"),
               number("/spanwise", "most_unstable_growth_rate", s, "most_unstable_growth_rate", "1")},
              g);
}

/// The onset refined on a finer grid (--fine-grid) in /onset3d/fine_grid: its two scans and its onset.
void write_onset_fine(FileGroups& g, const Json& f) {
  const char* G = "/onset3d/fine_grid";
  if (f.contains("evaluations"))
    write_rows(g, G, f["evaluations"],
               {{"reynolds", "reynolds", "1", "Reynolds number of the fine grid's scan"},
                {"growth_rate", "growth_rate", "1", "its growth rate at beta_D, U/D"},
                {"seconds", "seconds", "s", "wall time of the scan (the two ran at once)"}});
  std::vector<AttrValue> a = {number(G, "n_theta", f, "n_theta", "", AttrKind::integer),
                              number(G, "n_r", f, "n_r", "", AttrKind::integer),
                              number(G, "outer_radius_over_a", f, "outer_radius_over_a", "1"),
                              number(G, "found", f, "found", "", AttrKind::integer),
                              number(G, "critical_reynolds", f, "critical_reynolds", "1"),
                              number(G, "error_estimate", f, "error_estimate", "1"),
                              number(G, "beta_D", f, "beta_D", "1")};
  if (f.contains("undefined")) a.push_back(text(G, "message", f["undefined"].get<std::string>()));
  write_attrs(a, g);
}

void write_onset(FileGroups& g, const Json& j) {
  write_rows(g, "/onset3d", j["evaluations"],
             {{"reynolds", "reynolds", "1", "Reynolds number of the scan"},
              {"base", "periodic", "1", "1: the base was the shedding orbit (Floquet), 0: the steady state", "periodic"},
              {"growth_rate", "growth_rate", "1", "largest growth rate over the wavenumbers, U/D"},
              {"beta_D", "beta_D", "1", "its wavenumber β·D"},
              {"seconds", "seconds", "s", "wall time of the scan"}});
  std::vector<AttrValue> a = {number("/onset3d", "found", j, "found", "", AttrKind::integer),
                              number("/onset3d", "critical_reynolds", j, "critical_reynolds", "1"),
                              number("/onset3d", "change", j, "change", "1"),
                              number("/onset3d", "beta_D", j, "beta_D", "1"),
                              number("/onset3d", "wavelength_D", j, "wavelength_D", "1")};
  if (j.contains("bracket")) {
    a.push_back({"/onset3d", "bracket_lo", AttrKind::number, "1", j["bracket"][0].get<double>(), {}});
    a.push_back({"/onset3d", "bracket_hi", AttrKind::number, "1", j["bracket"][1].get<double>(), {}});
  }
  if (j.contains("undefined")) a.push_back(text("/onset3d", "message", j["undefined"].get<std::string>()));
  if (j.contains("accuracy_note")) a.push_back(text("/onset3d", "accuracy_note", j["accuracy_note"].get<std::string>()));
  write_attrs(a, g);
  if (j.contains("fine_grid")) write_onset_fine(g, j["fine_grid"]);
}

}  // namespace

void write_stability_hdf5(const std::string& path, const Json& j, const std::string& title,
                          const std::string& case_text) {
  write_hdf5_atomic(path, [&](H5Writer& w) {
    FileGroups g{w};
    std::vector<AttrValue> root = {text("/", "format", "magnus-stability"),
                                   {"/", "format_version", AttrKind::integer, "", 1.0, {}},
                                   text("/", "software_version", MAGNUS_VERSION),
                                   text("/", "model", "navier-stokes"),
                                   text("/", "title", title),
                                   text("/", "case", case_text),
                                   number("/", "reynolds", j, "reynolds", "1"),
                                   number("/", "spin_ratio", j, "spin_ratio", "1"),
                                   number("/", "stable", j, "stable", "", AttrKind::integer)};
    if (j.contains("eigensolver")) root.push_back(text("/", "eigensolver", j["eigensolver"].get<std::string>()));
    write_attrs(root, g);
    if (j.contains("eigenvalues"))
      write_rows(g, "/eigenvalues", j["eigenvalues"],
                 {{"growth_rate", "growth_rate", "1", "eigenvalue's real part, λ·D/U"},
                  {"frequency", "frequency", "1", "eigenvalue's imaginary part, λ·D/U"},
                  {"strouhal", "strouhal", "1", "St = Im λ·D/(2πU)"},
                  {"residual", "residual", "1", "‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖)"}});
    if (j.contains("spanwise")) write_spanwise(g, j["spanwise"]);
    if (j.contains("evaluations")) write_onset(g, j);
    write_undefined(g);
  });
}

Onset3d read_onset3d(const std::string& path) {
  const ResultFile f(path, {"magnus-stability"});
  if (!f.has("/onset3d"))
    throw std::runtime_error(path + ": holds no 3D onset (write one with magnus stability --spanwise --critical-reynolds A:B --output)");
  if (f.attr_int("/onset3d", "found") != 1 || !f.has_attr("/onset3d", "critical_reynolds"))
    throw std::runtime_error(path + ": its 3D onset search found no crossing");
  const char* fine = "/onset3d/fine_grid";
  const bool refined = f.has(fine) && f.has_attr(fine, "found") && f.attr_int(fine, "found") == 1 &&
                       f.has_attr(fine, "critical_reynolds");
  return {f.attr_double("/", "spin_ratio"), f.attr_double(refined ? fine : "/onset3d", "critical_reynolds")};
}

void give_onset3d(RunHooks& hooks, const Case& c, const std::vector<std::string>& files, const std::string& option) {
  if (!files.empty() && c.model != FlowModel::navier_stokes)
    throw std::invalid_argument(option + ": only for a navier-stokes case (potential flow is not 3D-unstable)");
  for (const std::string& f : files) hooks.onset3d.push_back(read_onset3d(f));
  hooks.onset3d_files = files;
}

}  // namespace magnus
