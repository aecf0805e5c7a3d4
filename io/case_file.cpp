#include "io/case_file.hpp"

#include <fmt/core.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/case_keys.hpp"
#include "io/case_reader.hpp"
#include "io/toml_safe.hpp"
#include "postproc/navier_stokes/grid_rule.hpp"

namespace magnus {

using case_reader::apply_override;
using case_reader::Reader;
using case_reader::reject_unknown_keys;
using toml_safe::parse_toml;
using toml_safe::unshield;

namespace {

bool positive(double v) { return v > 0.0; }
bool any(double) { return true; }

/// Whether the case gives "section.key".
bool has_key(const Reader& r, const std::string& k) {
  return r.has(k.substr(0, k.find('.')), k.substr(k.find('.') + 1));
}

/// The case's TOML table with the --set overrides applied; `overridden` gets the keys they set (a bad value
/// given with --set is blamed on --set). Throws CaseError.
toml::table case_table(const std::string& toml_text, const std::string& origin,
                       const std::vector<std::string>& overrides, std::vector<std::string>& overridden) {
  toml::table t;
  try {
    t = parse_toml(toml_text, origin);
  } catch (const toml::parse_error& e) {
    throw CaseError(fmt::format("{}:{}:{}: malformed TOML: {}", origin, e.source().begin.line,
                                e.source().begin.column, unshield(e.description())));
  }
  reject_unknown_keys(t, origin);
  for (const auto& o : overrides) {
    // A tolerance on the command line supersedes the file's grid (its rings' map too) and stencil.
    if (o.rfind("grid.tolerance=", 0) == 0) {
      if (auto* g = t.get_as<toml::table>("grid"))
        for (const char* k : {"n_theta", "n_r", "wall_refinement", "wall_layer"}) g->erase(k);
      if (auto* s = t.get_as<toml::table>("solver")) s->erase("stencil");
    }
    overridden.push_back(apply_override(t, o));
  }
  return t;
}

/// Each model's own keys: the viscous model computes the circulation, and has its own grid spacing, far
/// field and solver; potential flow is not marched in time. `circulation` is circulation.model.
void check_model_keys(const Reader& r, bool ns, const std::string& circulation_model) {
  if (ns) {
    const char* circulation = "navier-stokes computes the circulation (an output of the viscous model)";
    if (circulation_model == "given")
      r.fail("circulation.model",
             fmt::format("\"given\" is only used with model.flow = \"potential\": {}", circulation));
    if (r.has("circulation", "value"))
      r.fail("circulation.value",
             fmt::format("is only used with model.flow = \"potential\": {}", circulation));
    if (r.word("grid", "spacing", "geometric", {"geometric", "uniform"}) == "uniform")
      r.fail("grid.spacing",
             "\"uniform\" is only used with model.flow = \"potential\": the navier-stokes grid is geometric");
    const std::vector<std::pair<std::string, const char*>> potential_only = {
        {"domain.far_field", "sets its own far-field conditions"},
        {"solver.method", "has its own solver"},
        {"solver.stencil", "has its own discretisation"}};
    for (const auto& [k, why] : potential_only)
      if (has_key(r, k))
        r.fail(k, fmt::format("is only used with model.flow = \"potential\": navier-stokes {}", why));
  } else {
    std::vector<std::string> ns_only;
    for (const auto& k : case_key_table().at("time")) ns_only.push_back("time." + k);
    ns_only.insert(ns_only.end(), {"output.snapshots", "output.snapshot_interval", "solver.advection_order",
                                   "solver.advection_order_xi", "solver.wall_closure", "solver.implicit_rotation", "grid.wall_refinement", "grid.wall_layer",
                                   "grid.refine", "domain.absorbing_layer", "domain.absorbing_strength"});
    for (const auto& k : ns_only)
      if (has_key(r, k)) r.fail(k, "is only used with model.flow = \"navier-stokes\"");
  }
}

/// The scene's required keys (a file that omits one is an error, not a demo) and the one spin key given:
/// "spin", "spin_ratio", "rpm", or "" (none: a given circulation without spin).
std::string required_keys(const Reader& r, bool ns, bool circulation_given) {
  r.require("cylinder", "radius", "the cylinder radius a, m");
  r.require("flow", "speed", "the freestream speed U, m/s");
  std::string spin_key;
  for (const std::string k : {"spin", "spin_ratio", "rpm"}) {
    if (!r.has("cylinder", k)) continue;
    if (!spin_key.empty())
      r.fail("cylinder." + k, fmt::format("conflicts with cylinder.{}: give exactly one of them", spin_key));
    spin_key = k;
  }
  if (spin_key.empty() && ns)
    r.fail("cylinder.spin",
           "required key is missing: give one of cylinder.spin (rad/s), cylinder.spin_ratio or cylinder.rpm");
  if (spin_key.empty() && !circulation_given)
    r.fail("cylinder.spin",
           "required key is missing: give one of cylinder.spin (rad/s), cylinder.spin_ratio or "
           "cylinder.rpm, or circulation.model = \"given\" with circulation.value");
  return spin_key;
}

/// The viscosity: ν or Re = U·2a/ν, exactly one; required for navier-stokes, reported for potential flow.
/// Re has a floor for navier-stokes (kNsMinReynolds), named by the key that set it.
void read_viscosity(const Reader& r, bool ns, Scene& sc) {
  const bool has_nu = r.has("flow", "viscosity"), has_re = r.has("flow", "reynolds");
  if (has_nu && has_re) r.fail("flow.reynolds", "conflicts with flow.viscosity: give exactly one of them");
  if (ns && !has_nu && !has_re)
    r.fail("flow.viscosity",
           "required key is missing: model.flow = \"navier-stokes\" needs flow.viscosity (nu, m^2/s) or "
           "flow.reynolds (Re = U*2a/nu)");
  sc.viscosity = r.number("flow", "viscosity", 0.0, positive, "> 0 (m^2/s)");
  if (has_re) {
    sc.reynolds_given = true;
    sc.reynolds_value = r.number("flow", "reynolds", 0.0, positive, "> 0 (Re = U*2a/nu)");
    if (sc.speed == 0.0)
      r.fail("flow.reynolds", "needs flow.speed > 0 (Re = U*2a/nu); give flow.viscosity instead");
    sc.viscosity = sc.speed * 2.0 * sc.radius / sc.reynolds_value;
  }
  if (ns && sc.speed > 0.0 && sc.viscosity > 0.0 && sc.reynolds() < kNsMinReynolds) {
    const std::string why = fmt::format(
        " out of range: must be >= {:g} for navier-stokes (below it the viscous length D/Re is over {:g} D: "
        "creeping flow whose forces depend on domain.outer_radius)",
        kNsMinReynolds, 1.0 / kNsMinReynolds);
    if (has_re) r.fail("flow.reynolds", fmt::format("{:g} is{}", sc.reynolds_value, why));
    r.fail("flow.viscosity",
           fmt::format("{:g} gives Re = U*2a/nu = {:g},{}", sc.viscosity, sc.reynolds(), why));
  }
}

/// ω from the spin key given (ω, α = aω/U or rev/min) and the given circulation's value.
void read_spin(const Reader& r, bool ns, const std::string& spin_key, Scene& sc) {
  if (spin_key == "spin_ratio") {
    const double alpha = r.number("cylinder", "spin_ratio", 0.0, any, "finite");
    if (sc.speed == 0.0 && alpha != 0.0)
      r.fail("cylinder.spin_ratio", "needs flow.speed > 0 (alpha = a*omega/U); give cylinder.spin instead");
    sc.spin = alpha * sc.speed / sc.radius;
  } else if (spin_key == "rpm") {
    sc.rpm_given = r.number("cylinder", "rpm", 0.0, any, "finite (rev/min)");
    sc.spin = *sc.rpm_given * (2.0 * M_PI / 60.0);
  } else {
    sc.spin = r.number("cylinder", "spin", 0.0, any, "finite (rad/s)");  // absent: ω = 0 (model "given")
  }
  if (r.has("circulation", "value") && !sc.circulation_given)
    r.fail("circulation.value", "is only used with circulation.model = \"given\"");
  if (sc.circulation_given && !r.has("circulation", "value"))
    r.fail("circulation.value", "is required with circulation.model = \"given\"");
  sc.circulation_value = r.number("circulation", "value", 0.0, any, "finite (m^2/s)");
  // Each value is finite, but what is derived from them must be too (1e300 * 1e300 is not).
  if (!std::isfinite(sc.spin))
    r.fail("cylinder.spin_ratio",
           fmt::format("gives a spin omega = alpha*U/a that is not finite (a = {}, U = {})", sc.radius,
                       sc.speed));
  // Navier-stokes allows still fluid around a spinning cylinder (the time unit is then D/(a|ω|)); with
  // neither U nor ω nothing moves.
  if (ns && sc.speed == 0.0 && sc.spin == 0.0)
    r.fail("flow.speed",
           "0 needs a spinning cylinder with model.flow = \"navier-stokes\" (cylinder.spin != 0): in still "
           "fluid nothing else moves");
}

/// The scene in the world (where the freestream flows, the ship's course, the span; angles taken as given,
/// not normalised, within one turn either way), the outer radius, and what they derive that overflows.
void read_world(const Reader& r, bool ns, const std::string& spin_key, Case& c) {
  auto angle = [](double v) { return v >= -360.0 && v <= 360.0; };
  c.scene.direction_deg = r.number("flow", "direction", 0.0, angle, "in [-360, 360] (deg, CCW from +x)");
  if (r.has("flow", "course"))
    c.scene.course_deg = r.number("flow", "course", 0.0, angle, "in [-360, 360] (deg, CCW from +x)");
  c.scene.span = r.number(
      "cylinder", "span", 0.0, [](double v) { return v > 0.0 && v <= 1e6; }, "> 0 and <= 1e6 (m)");
  c.grid.outer_radius = r.number(
      "domain", "outer_radius", ns ? kNsDefaultOuterRadius : c.grid.outer_radius,
      [](double v) { return v > 1.0 && v <= 1e12; }, "> 1 and <= 1e12 (R/a)");
  SceneKeys keys;
  if (!spin_key.empty()) keys.spin = "cylinder." + spin_key;
  if (spin_key == "spin_ratio" || spin_key == "rpm")
    keys.spin_value = r.number("cylinder", spin_key, 0.0, any, "");
  if (const auto o = find_overflow(c.scene, c.grid.outer_radius, keys))
    r.fail(o->key,
           fmt::format("{:g} is too {}: {} {}", o->value, std::fabs(o->value) >= 1.0 ? "large" : "small",
                       o->quantity, o->underflow ? "underflows double precision" : "is not finite"));
}

/// [scene]: the physical keys, in the order their errors are reported.
void read_scene(const Reader& r, bool ns, const std::string& circulation_model, Case& c) {
  Scene& sc = c.scene;
  sc.circulation_given = circulation_model == "given";
  const std::string spin_key = required_keys(r, ns, sc.circulation_given);
  sc.radius = r.number("cylinder", "radius", sc.radius, positive, "> 0 (m)");
  sc.speed = r.number(
      "flow", "speed", sc.speed, [](double v) { return v >= 0.0; }, ">= 0 (m/s)");
  sc.density = r.number("flow", "density", sc.density, positive, "> 0 (kg/m^3)");
  sc.pressure_inf = r.number("flow", "pressure", sc.pressure_inf, any, "finite (Pa)");
  read_viscosity(r, ns, sc);
  read_spin(r, ns, spin_key, sc);
  read_world(r, ns, spin_key, c);
}

/// [domain] far field, [grid], [solver] method and stencil, and [output] of both models.
void read_grid_solver_output(const Reader& r, bool ns, Case& c) {
  c.grid.far_field = r.word("domain", "far_field", "exact", {"exact", "freestream"}) == "exact"
                         ? FarField::exact
                         : FarField::freestream;
  c.grid.n_theta = int(r.integer(
      "grid", "n_theta", ns ? kNsDefaultNTheta : c.grid.n_theta,
      [](long v) { return v >= 8 && v <= (1 << 20) && v % 2 == 0; }, "even, >= 8 and <= 1048576"));
  c.grid.n_r = int(r.integer(
      "grid", "n_r", c.grid.n_r, [](long v) { return v == 0 || (v >= 3 && v <= (1 << 22)); },
      "0 (square cells) or 3 ... 4194304"));
  c.grid.spacing = r.word("grid", "spacing", "geometric", {"geometric", "uniform"}) == "geometric"
                       ? Spacing::geometric
                       : Spacing::uniform;
  c.grid.spacing_given = r.has("grid", "spacing");
  c.grid.n_theta_given = r.has("grid", "n_theta");
  if (ns)
    c.grid.tolerance = r.number(
        "grid", "tolerance", 0.0, [](double v) { return v == 0.0 || (v >= kNsMinTolerance && v <= 0.1); },
        "0 (the scene's grid) or 1e-4 ... 0.1 (navier-stokes: relative, on mean C_L, C_D and St; below 1e-4 "
        "the run's own error estimate is not reliable)");
  else
    c.grid.tolerance = r.number(
        "grid", "tolerance", 0.0, [](double v) { return v == 0.0 || (v >= 1e-14 && v <= 0.1); },
        "0 (grid as given) or 1e-14 ... 0.1");
  c.grid.refine = r.number(
      "grid", "refine", 1.0, [](double v) { return v >= 0.25 && v <= 16.0; },
      "0.25 ... 16 (the scene's grid: n_θ times it, every spacing divided by it)");
  const std::string method = r.word("solver", "method", "auto", {"auto", "cholmod", "fft"});
  c.solver.method = method == "auto"      ? Method::automatic
                    : method == "cholmod" ? Method::cholmod
                                          : Method::fft;
  c.solver.stencil = r.word("solver", "stencil", "5-point", {"5-point", "9-point"}) == "5-point"
                         ? StencilKind::five_point
                         : StencilKind::nine_point;
  c.output.file = r.word("output", "file", c.output.file);
  if (c.output.file.empty()) r.fail("output.file", "must not be empty");
  if (r.has("output", "fields")) c.output.fields = r.words("output", "fields");
  c.output.compression = int(r.integer(
      "output", "compression", c.output.compression, [](long v) { return v >= 0 && v <= 9; },
      "an integer from 0 (none) to 9"));
}

/// navier-stokes: the rings' clustering at the wall, the advection's orders, [time] and the snapshots.
void read_navier_stokes(const Reader& r, Case& c) {
  c.grid.wall_refinement = r.number(
      "grid", "wall_refinement", c.grid.wall_refinement, [](double v) { return v >= 1.0 && v <= 100.0; },
      "1 (uniform in ξ) ... 100 (Δξ_far/Δξ_wall)");
  const double span = std::log(c.grid.outer_radius);
  c.grid.wall_layer = r.number(
      "grid", "wall_layer", c.grid.wall_layer, [span](double v) { return v > 0.0 && v <= span; },
      "> 0 and <= ln(R/a), R/a = domain.outer_radius (the ξ-length of the spacing's transition)");
  c.grid.wall_refinement_given = r.has("grid", "wall_refinement");
  c.grid.wall_layer_given = r.has("grid", "wall_layer");
  // The scene's scheme goes with the scene's grid (grid_rule.hpp): Jensen's wall closure, and fourth order
  // in θ where the wake sheds.
  const bool rule = rule_grid(c);
  c.solver.advection_order = int(r.integer(
      "solver", "advection_order", rule ? rule_advection_order(scene_sheds(c)) : c.solver.advection_order,
      [](long v) { return v == 2 || v == 4; },
      "2 (Arakawa's Jacobian) or 4 (fourth order in θ)"));
  c.solver.advection_order_xi = int(r.integer(
      "solver", "advection_order_xi", c.solver.advection_order_xi, [](long v) { return v == 2 || v == 4; },
      "2 (Arakawa's Jacobian) or 4 (fourth order in ξ)"));
  c.solver.wall_closure =
      r.word("solver", "wall_closure", rule ? kRuleWallClosure : c.solver.wall_closure, {"thom", "jensen"});
  c.solver.implicit_rotation = r.boolean("solver", "implicit_rotation", c.solver.implicit_rotation);
  const std::string mode = r.word("time", "mode", "auto", {"auto", "steady", "unsteady", "periodic"});
  c.time.mode = mode == "auto"       ? TimeMode::automatic
                : mode == "steady"   ? TimeMode::steady
                : mode == "periodic" ? TimeMode::periodic
                                     : TimeMode::unsteady;
  const double R = c.grid.outer_radius;
  const std::string layer_range = fmt::format("0 (none) or > 1 and < {:g} = domain.outer_radius (r/a where the layer begins)", R);
  const bool marched = scene_sheds(c) && c.time.mode != TimeMode::steady;  // the rule's layer: not for steady
  c.grid.absorbing_layer = r.number("domain", "absorbing_layer", rule_absorbing_layer(marched, R),
                                     [R](double v) { return v == 0.0 || (v > 1.0 && v < R); }, layer_range.c_str());
  c.grid.absorbing_strength = r.number(
      "domain", "absorbing_strength", c.grid.absorbing_strength, [](double v) { return v > 0.0 && v <= 100.0; },
      "> 0 and <= 100 (the sink λ at R, in U/D; a|ω|/D in still fluid)");
  auto non_negative = [](double v) { return v >= 0.0; };
  c.time.end = r.number("time", "end", c.time.end, positive, "> 0 (D/U)");
  c.time.dt = r.number("time", "dt", c.time.dt, non_negative, ">= 0 (D/U; 0: from time.cfl)");
  if (c.time.dt > 0.0 && !(c.time.end / c.time.dt <= kNsMaxSteps))
    r.fail("time.dt",
           fmt::format("{:g} gives time.end/time.dt = {:.3g} steps, more than the {:g} a run may take",
                       c.time.dt, c.time.end / c.time.dt, kNsMaxSteps));
  c.time.cfl = r.number(
      "time", "cfl", c.time.cfl, [](double v) { return v > 0.0 && v <= 0.8; }, "> 0 and <= 0.8");
  c.time.mean_tolerance = r.number(
      "time", "mean_tolerance", c.time.mean_tolerance, [](double v) { return v > 0.0 && v <= 0.1; },
      "> 0 and <= 0.1");
  c.time.stop_on_drift = r.boolean("time", "stop_on_drift", c.time.stop_on_drift);
  c.time.checkpoint_interval = r.number("time", "checkpoint_interval", c.time.checkpoint_interval,
                                        non_negative, ">= 0 (D/U; 0: none)");
  c.output.snapshots = int(r.integer(
      "output", "snapshots", c.output.snapshots, [](long v) { return v >= 0 && v <= 10000; },
      "an integer from 0 (none) to 10000"));
  c.output.snapshot_interval =
      r.number("output", "snapshot_interval", c.output.snapshot_interval, positive, "> 0 (D/U)");
}

/// What no single key decides: the fields of the model (u_x with u_y in a turned world), the 9-point
/// stencil's geometric spacing, a tolerance beside the grid it would choose.
void check_combinations(const Reader& r, const Case& c) {
  for (const auto& f : c.output.fields.value_or(std::vector<std::string>{})) {
    const auto& names = field_names();
    if (std::find(names.begin(), names.end(), f) == names.end() || !field_of_model(f, c.model)) {
      std::string list;
      for (const auto& n : names)
        if (field_of_model(n, c.model)) list += (list.empty() ? "" : ", ") + n;
      r.fail("output.fields",
             fmt::format("{} field \"{}\" (fields of {} flow: {})",
                         std::find(names.begin(), names.end(), f) == names.end() ? "unknown" : "no such", cut_input(f),
                         to_string(c.model), list));
    }
  }
  // In a turned world each of u_x, u_y mixes both wind-frame components: they are stored together.
  if (c.scene.direction_deg != 0.0 && c.output.fields) {
    const auto& f = *c.output.fields;
    const bool ux = std::find(f.begin(), f.end(), "u_x") != f.end(),
               uy = std::find(f.begin(), f.end(), "u_y") != f.end();
    if (ux != uy)
      r.fail("output.fields", fmt::format("\"{}\" needs \"{}\" too when flow.direction is not 0 (each mixes "
                                          "both components of the wind frame)",
                                          ux ? "u_x" : "u_y", ux ? "u_y" : "u_x"));
  }
  if (c.solver.stencil == StencilKind::nine_point && c.grid.spacing == Spacing::uniform)
    r.fail("solver.stencil", "\"9-point\" needs grid.spacing = \"geometric\" (uniform in ln r)");
  for (const char* key : {"grid.n_theta", "grid.n_r", "solver.stencil", "grid.refine"})
    if (c.grid.tolerance > 0.0 && has_key(r, key))
      r.fail("grid.tolerance",
             fmt::format("conflicts with {}: the tolerance chooses the grid and stencil", key));
}

}  // namespace

Case parse_case(const std::string& toml_text, const std::string& origin,
                const std::vector<std::string>& overrides) {
  std::vector<std::string> overridden;
  const toml::table t = case_table(toml_text, origin, overrides, overridden);
  const Reader r(t, origin, overridden);
  Case c;
  c.title = r.word("", "title", c.title);
  const bool ns = r.word("model", "flow", "potential", {"potential", "navier-stokes"}) == "navier-stokes";
  c.model = ns ? FlowModel::navier_stokes : FlowModel::potential;
  const std::string circulation_model = r.word("circulation", "model", "spin", {"spin", "given"});
  check_model_keys(r, ns, circulation_model);
  read_scene(r, ns, circulation_model, c);
  read_grid_solver_output(r, ns, c);
  if (ns) read_navier_stokes(r, c);
  check_combinations(r, c);
  c.source_text = to_toml(c);
  return c;
}

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw CaseError(fmt::format("cannot read case file '{}': not a regular file", path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(fmt::format("cannot read case file '{}': {}", path, std::strerror(errno)));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw CaseError(fmt::format("cannot read case file '{}': read error", path));
  if (ss.str().rfind("\x89HDF\r\n\x1a\n", 0) == 0)  // the HDF5 signature at offset 0
    throw CaseError(fmt::format(
        "{}: an HDF5 result file, not a case file (TOML); to see what it holds: magnus inspect {}", path,
        path));
  return parse_case(ss.str(), path, overrides);
}

void retitle_for_overrides(Case& c, const std::string& case_path, const std::vector<std::string>& sets) {
  std::string changed;
  for (const auto& s : sets) {
    std::string key = s.substr(0, s.find('='));
    key.erase(0, key.find_first_not_of(' '));
    key.erase(key.find_last_not_of(' ') + 1);
    if (key == "title") return;
    const std::string section = key.substr(0, key.find('.'));
    if (section == "model" || section == "cylinder" || section == "flow" || section == "circulation")
      changed += (changed.empty() ? "" : " ") + s;
  }
  if (changed.empty()) return;
  const std::string name = case_path.substr(case_path.find_last_of('/') + 1);
  c.title = fmt::format("{} flow, {} with --set {}",
                        c.model == FlowModel::navier_stokes ? "Navier–Stokes" : "Potential", name, changed);
  c.source_text = to_toml(c);
}

}  // namespace magnus
