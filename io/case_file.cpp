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

namespace magnus {

using case_reader::apply_override;
using case_reader::Reader;
using case_reader::reject_unknown_keys;
using toml_safe::parse_toml;
using toml_safe::unshield;

Case parse_case(const std::string& toml_text, const std::string& origin,
                const std::vector<std::string>& overrides) {
  toml::table t;
  try {
    t = parse_toml(toml_text, origin);
  } catch (const toml::parse_error& e) {
    throw CaseError(fmt::format("{}:{}:{}: malformed TOML: {}", origin, e.source().begin.line,
                                e.source().begin.column, unshield(e.description())));
  }
  reject_unknown_keys(t, origin);
  std::vector<std::string> overridden;  // a bad value given with --set is blamed on --set
  for (const auto& o : overrides) {
    // A tolerance on the command line supersedes the file's grid and stencil.
    if (o.rfind("grid.tolerance=", 0) == 0) {
      if (auto* g = t.get_as<toml::table>("grid")) g->erase("n_theta"), g->erase("n_r");
      if (auto* s = t.get_as<toml::table>("solver")) s->erase("stencil");
    }
    overridden.push_back(apply_override(t, o));
  }

  const Reader r(t, origin, overridden);
  Case c;
  auto positive = [](double v) { return v > 0.0; };
  auto any = [](double) { return true; };
  c.title = r.word("", "title", c.title);
  const bool ns = r.word("model", "flow", "potential", {"potential", "navier-stokes"}) == "navier-stokes";
  c.model = ns ? FlowModel::navier_stokes : FlowModel::potential;
  // Each model's own keys. The viscous model computes the circulation, and has its own grid spacing, far
  // field and solver; potential flow is not marched in time.
  const std::string model = r.word("circulation", "model", "spin", {"spin", "given"});
  if (ns) {
    const char* circulation = "navier-stokes computes the circulation (an output of the viscous model)";
    if (model == "given")
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
        {"grid.tolerance", "takes the grid as given (grid.n_theta, grid.n_r)"},
        {"solver.method", "has its own solver"},
        {"solver.stencil", "has its own discretisation"}};
    for (const auto& [k, why] : potential_only)
      if (r.has(k.substr(0, k.find('.')), k.substr(k.find('.') + 1)))
        r.fail(k, fmt::format("is only used with model.flow = \"potential\": navier-stokes {}", why));
  } else {
    std::vector<std::string> ns_only;
    for (const auto& k : case_key_table().at("time")) ns_only.push_back("time." + k);
    ns_only.insert(ns_only.end(), {"output.snapshots", "output.snapshot_interval", "solver.advection_order",
                                   "solver.advection_order_xi"});
    for (const auto& k : ns_only)
      if (r.has(k.substr(0, k.find('.')), k.substr(k.find('.') + 1)))
        r.fail(k, "is only used with model.flow = \"navier-stokes\"");
  }
  // The scene's physical keys are required: a file that omits one is an error, not a demo.
  c.scene.circulation_given = model == "given";
  r.require("cylinder", "radius", "the cylinder radius a, m");
  r.require("flow", "speed", "the freestream speed U, m/s");
  const std::vector<std::string> spin_keys = {"spin", "spin_ratio", "rpm"};
  std::string spin_key;
  for (const auto& k : spin_keys) {
    if (!r.has("cylinder", k)) continue;
    if (!spin_key.empty())
      r.fail("cylinder." + k, fmt::format("conflicts with cylinder.{}: give exactly one of them", spin_key));
    spin_key = k;
  }
  if (spin_key.empty() && ns)
    r.fail("cylinder.spin",
           "required key is missing: give one of cylinder.spin (rad/s), cylinder.spin_ratio or cylinder.rpm");
  if (spin_key.empty() && !c.scene.circulation_given)
    r.fail("cylinder.spin",
           "required key is missing: give one of cylinder.spin (rad/s), cylinder.spin_ratio or "
           "cylinder.rpm, or circulation.model = \"given\" with circulation.value");
  c.scene.radius = r.number("cylinder", "radius", c.scene.radius, positive, "> 0 (m)");
  c.scene.speed = r.number(
      "flow", "speed", c.scene.speed, [](double v) { return v >= 0.0; }, ">= 0 (m/s)");
  c.scene.density = r.number("flow", "density", c.scene.density, positive, "> 0 (kg/m^3)");
  c.scene.pressure_inf = r.number("flow", "pressure", c.scene.pressure_inf, any, "finite (Pa)");
  // The viscosity: ν or Re = U·2a/ν, exactly one; required for navier-stokes, reported for potential flow.
  const bool has_nu = r.has("flow", "viscosity"), has_re = r.has("flow", "reynolds");
  if (has_nu && has_re) r.fail("flow.reynolds", "conflicts with flow.viscosity: give exactly one of them");
  if (ns && !has_nu && !has_re)
    r.fail("flow.viscosity",
           "required key is missing: model.flow = \"navier-stokes\" needs flow.viscosity (nu, m^2/s) or "
           "flow.reynolds (Re = U*2a/nu)");
  c.scene.viscosity = r.number("flow", "viscosity", 0.0, positive, "> 0 (m^2/s)");
  if (has_re) {
    c.scene.reynolds_given = true;
    c.scene.reynolds_value = r.number("flow", "reynolds", 0.0, positive, "> 0 (Re = U*2a/nu)");
    if (c.scene.speed == 0.0)
      r.fail("flow.reynolds", "needs flow.speed > 0 (Re = U*2a/nu); give flow.viscosity instead");
    c.scene.viscosity = c.scene.speed * 2.0 * c.scene.radius / c.scene.reynolds_value;
  }
  // Re has a floor for navier-stokes (kNsMinReynolds): named by the key that set it.
  if (ns && c.scene.speed > 0.0 && c.scene.viscosity > 0.0 && c.scene.reynolds() < kNsMinReynolds) {
    const std::string why = fmt::format(
        " out of range: must be >= {:g} for navier-stokes (below it the viscous length D/Re is over {:g} D: "
        "creeping flow whose forces depend on domain.outer_radius)",
        kNsMinReynolds, 1.0 / kNsMinReynolds);
    if (has_re) r.fail("flow.reynolds", fmt::format("{:g} is{}", c.scene.reynolds_value, why));
    r.fail("flow.viscosity",
           fmt::format("{:g} gives Re = U*2a/nu = {:g},{}", c.scene.viscosity, c.scene.reynolds(), why));
  }
  if (spin_key == "spin_ratio") {
    const double alpha = r.number("cylinder", "spin_ratio", 0.0, any, "finite");
    if (c.scene.speed == 0.0 && alpha != 0.0)
      r.fail("cylinder.spin_ratio", "needs flow.speed > 0 (alpha = a*omega/U); give cylinder.spin instead");
    c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  } else if (spin_key == "rpm") {
    c.scene.rpm_given = r.number("cylinder", "rpm", 0.0, any, "finite (rev/min)");
    c.scene.spin = *c.scene.rpm_given * (2.0 * M_PI / 60.0);
  } else {
    c.scene.spin = r.number("cylinder", "spin", 0.0, any, "finite (rad/s)");  // absent: ω = 0 (model "given")
  }
  if (r.has("circulation", "value") && !c.scene.circulation_given)
    r.fail("circulation.value", "is only used with circulation.model = \"given\"");
  if (c.scene.circulation_given && !r.has("circulation", "value"))
    r.fail("circulation.value", "is required with circulation.model = \"given\"");
  c.scene.circulation_value = r.number("circulation", "value", 0.0, any, "finite (m^2/s)");
  // Each value is finite, but what is derived from them must be too (1e300 * 1e300 is not).
  if (!std::isfinite(c.scene.spin))
    r.fail("cylinder.spin_ratio",
           fmt::format("gives a spin omega = alpha*U/a that is not finite (a = {}, U = {})", c.scene.radius,
                       c.scene.speed));
  // Navier-stokes allows still fluid around a spinning cylinder (the time unit is then D/(a|ω|)); with
  // neither U nor ω nothing moves.
  if (ns && c.scene.speed == 0.0 && c.scene.spin == 0.0)
    r.fail("flow.speed",
           "0 needs a spinning cylinder with model.flow = \"navier-stokes\" (cylinder.spin != 0): in still "
           "fluid nothing else moves");
  // The scene in the world: where the freestream flows, the ship's course, the span. Angles are taken as
  // given (not normalised) within one turn either way.
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
  c.grid.tolerance = r.number(
      "grid", "tolerance", 0.0, [](double v) { return v == 0.0 || (v >= 1e-14 && v <= 0.1); },
      "0 (grid as given) or 1e-14 ... 0.1");
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
  if (ns) {
    c.solver.advection_order = int(r.integer(
        "solver", "advection_order", c.solver.advection_order, [](long v) { return v == 2 || v == 4; },
        "2 (Arakawa's Jacobian) or 4 (fourth order in θ)"));
    c.solver.advection_order_xi = int(r.integer(
        "solver", "advection_order_xi", c.solver.advection_order_xi, [](long v) { return v == 2 || v == 4; },
        "2 (Arakawa's Jacobian) or 4 (fourth order in ξ)"));
    const std::string mode = r.word("time", "mode", "auto", {"auto", "steady", "unsteady"});
    c.time.mode = mode == "auto"     ? TimeMode::automatic
                  : mode == "steady" ? TimeMode::steady
                                     : TimeMode::unsteady;
    auto non_negative = [](double v) { return v >= 0.0; };
    c.time.end = r.number("time", "end", c.time.end, positive, "> 0 (D/U)");
    c.time.dt = r.number("time", "dt", c.time.dt, non_negative, ">= 0 (D/U; 0: from time.cfl)");
    if (c.time.dt > 0.0 && !(c.time.end / c.time.dt <= kNsMaxSteps))
      r.fail("time.dt", fmt::format("{:g} gives time.end/time.dt = {:.3g} steps, more than the {:g} a run may take",
                                    c.time.dt, c.time.end / c.time.dt, kNsMaxSteps));
    c.time.cfl = r.number(
        "time", "cfl", c.time.cfl, [](double v) { return v > 0.0 && v <= 0.8; }, "> 0 and <= 0.8");
    c.time.mean_tolerance = r.number(
        "time", "mean_tolerance", c.time.mean_tolerance, [](double v) { return v > 0.0 && v <= 0.1; },
        "> 0 and <= 0.1");
    c.time.checkpoint_interval = r.number("time", "checkpoint_interval", c.time.checkpoint_interval,
                                          non_negative, ">= 0 (D/U; 0: none)");
    c.output.snapshots = int(r.integer(
        "output", "snapshots", c.output.snapshots, [](long v) { return v >= 0 && v <= 10000; },
        "an integer from 0 (none) to 10000"));
    c.output.snapshot_interval =
        r.number("output", "snapshot_interval", c.output.snapshot_interval, positive, "> 0 (D/U)");
  }
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
  for (const char* key : {"grid.n_theta", "grid.n_r", "solver.stencil"}) {
    const std::string k(key);
    if (c.grid.tolerance > 0.0 && r.has(k.substr(0, k.find('.')), k.substr(k.find('.') + 1)))
      r.fail("grid.tolerance",
             fmt::format("conflicts with {}: the tolerance chooses the grid and stencil", k));
  }
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

std::string to_toml(const Case& c) {
  auto str = [](const std::string& v) {
    std::string q = "\"";
    for (char ch : v) {
      if (ch == '"' || ch == '\\') q += '\\';
      if (ch == '\n') {
        q += "\\n";
        continue;
      }
      // TOML basic strings may not hold control characters other than tab: escape them all.
      if ((unsigned char)ch < 0x20 || ch == 0x7F) {
        q += fmt::format("\\u{:04X}", (unsigned char)ch);
        continue;
      }
      q += ch;
    }
    return q + "\"";
  };
  auto num = [](double v) {
    std::string s = fmt::format("{}", v);
    return s.find_first_of(".eE") == std::string::npos ? s + ".0" : s;
  };
  // A navier-stokes case leaves out the keys of potential flow's circulation, far field and solver (they
  // would be errors), and adds its model, [time] and snapshots; a potential case writes none of these.
  const bool ns = c.model == FlowModel::navier_stokes;
  std::string t = fmt::format("title = {}\n", str(c.title));
  if (ns) t += fmt::format("\n[model]\nflow = {}\n", str(to_string(c.model)));
  // The spin as given when in rev/min (ω follows from it exactly as on reading), else ω.
  t += fmt::format("\n[cylinder]\nradius = {}\n", num(c.scene.radius));
  t += c.scene.rpm_given ? fmt::format("rpm = {}\n", num(*c.scene.rpm_given))
                         : fmt::format("spin = {}\n", num(c.scene.spin));
  if (c.scene.span > 0.0) t += fmt::format("span = {}\n", num(c.scene.span));
  // The world keys only when given (the default direction 0 leaves the text of a plain case as it was).
  t += fmt::format("\n[flow]\nspeed = {}\n", num(c.scene.speed));
  if (c.scene.direction_deg != 0.0) t += fmt::format("direction = {}\n", num(c.scene.direction_deg));
  if (c.scene.course_deg) t += fmt::format("course = {}\n", num(*c.scene.course_deg));
  t += fmt::format("density = {}\npressure = {}\n", num(c.scene.density), num(c.scene.pressure_inf));
  // The viscosity as given: a given Re stays the input (ν follows U and a), not the ν derived from it.
  if (c.scene.reynolds_given)
    t += fmt::format("reynolds = {}\n", num(c.scene.reynolds_value));
  else if (c.scene.viscosity > 0.0)
    t += fmt::format("viscosity = {}\n", num(c.scene.viscosity));
  if (!ns) {
    t += fmt::format("\n[circulation]\nmodel = {}\n", str(c.scene.circulation_given ? "given" : "spin"));
    if (c.scene.circulation_given) t += fmt::format("value = {}\n", num(c.scene.circulation_value));
  }
  t += fmt::format("\n[domain]\nouter_radius = {}\n", num(c.grid.outer_radius));
  if (!ns) t += fmt::format("far_field = {}\n", str(to_string(c.grid.far_field)));
  // With a tolerance the grid and stencil are chosen at run time (and stored in /parameters).
  // With a tolerance and no stated spacing the search chooses it too: the resolved case leaves it out.
  t += "\n[grid]\n";
  if (c.grid.tolerance == 0.0 || c.grid.spacing_given)
    t += fmt::format("spacing = {}\n", str(to_string(c.grid.spacing)));
  if (c.grid.tolerance > 0.0)
    t += fmt::format("tolerance = {}\n", num(c.grid.tolerance));
  else
    t += fmt::format("n_theta = {}\nn_r = {}\n", c.grid.n_theta, c.grid.n_r);
  if (!ns) {
    t += fmt::format("\n[solver]\nmethod = {}\n", str(to_string(c.solver.method)));
    if (c.grid.tolerance == 0.0) t += fmt::format("stencil = {}\n", str(to_string(c.solver.stencil)));
  } else {
    t += fmt::format("\n[solver]\nadvection_order = {}\nadvection_order_xi = {}\n", c.solver.advection_order,
                     c.solver.advection_order_xi);
    t += fmt::format(
        "\n[time]\nmode = {}\nend = {}\ndt = {}\ncfl = {}\nmean_tolerance = {}\ncheckpoint_interval = {}\n",
        str(to_string(c.time.mode)), num(c.time.end), num(c.time.dt), num(c.time.cfl),
        num(c.time.mean_tolerance), num(c.time.checkpoint_interval));
  }
  t += fmt::format("\n[output]\nfile = {}\n", str(c.output.file));
  if (c.output.fields) {
    std::string list;
    for (const auto& f : *c.output.fields) list += (list.empty() ? "" : ", ") + str(f);
    t += fmt::format("fields = [{}]\n", list);
  }
  if (c.output.compression > 0) t += fmt::format("compression = {}\n", c.output.compression);
  if (ns)
    t += fmt::format("snapshots = {}\nsnapshot_interval = {}\n", c.output.snapshots,
                     num(c.output.snapshot_interval));
  return t;
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
