#include "io/case_file.hpp"

#include "io/case_keys.hpp"

#include <fmt/core.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "io/toml_safe.hpp"

namespace magnus {

using toml_safe::decode_utf8;
using toml_safe::parse_toml;
using toml_safe::unshield;

namespace {

/// Reads typed values from the parsed table, naming origin and key in every error.
class Reader {
 public:
  Reader(const toml::table& t, std::string origin) : t_(t), origin_(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw CaseError(fmt::format("{}: {}: {}", origin_, key, what));
  }

  const toml::node* find(const std::string& section, const std::string& key) const {
    if (section.empty()) return t_.get(key);
    const toml::table* s = t_.get_as<toml::table>(section);
    return s ? s->get(key) : nullptr;
  }
  bool has(const std::string& section, const std::string& key) const { return find(section, key); }
  /// Fails with "KEY: required key is missing (what)" unless the key is present.
  void require(const std::string& section, const std::string& key, const char* what) const {
    if (!has(section, key)) fail(key_name(section, key), fmt::format("required key is missing ({})", what));
  }

  double number(const std::string& section, const std::string& key, double fallback,
                const std::function<bool(double)>& ok, const char* range) const {
    const toml::node* n = find(section, key);
    if (!n) return fallback;
    double v;
    if (auto i = n->as_integer())
      v = double(i->get());
    else if (auto f = n->as_floating_point())
      v = f->get();
    else
      fail(key_name(section, key), fmt::format("expected a number, got {}", type_name(*n)));
    if (!std::isfinite(v)) fail(key_name(section, key), fmt::format("must be finite, got {}", v));
    if (!ok(v)) fail(key_name(section, key), fmt::format("{} is out of range: must be {}", v, range));
    return v;
  }

  long integer(const std::string& section, const std::string& key, long fallback,
               const std::function<bool(long)>& ok, const char* range) const {
    const toml::node* n = find(section, key);
    if (!n) return fallback;
    const auto i = n->as_integer();
    if (!i) fail(key_name(section, key), fmt::format("expected an integer, got {}", type_name(*n)));
    const long v = long(i->get());
    if (!ok(v)) fail(key_name(section, key), fmt::format("{} is out of range: must be {}", v, range));
    return v;
  }

  std::string word(const std::string& section, const std::string& key, const std::string& fallback,
                   const std::vector<std::string>& allowed = {}) const {
    const toml::node* n = find(section, key);
    if (!n) return fallback;
    const auto s = n->as_string();
    if (!s) fail(key_name(section, key), fmt::format("expected a string, got {}", type_name(*n)));
    const std::string v = s->get();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
      fail(key_name(section, key), fmt::format("\"{}\" is not one of {}", v, list));
    }
    return v;
  }

  std::vector<std::string> words(const std::string& section, const std::string& key) const {
    const toml::node* n = find(section, key);
    if (!n) return {};
    const auto arr = n->as_array();
    if (!arr)
      fail(key_name(section, key), fmt::format("expected an array of strings, got {}", type_name(*n)));
    std::vector<std::string> out;
    for (const auto& e : *arr) {
      const auto s = e.as_string();
      if (!s) fail(key_name(section, key), fmt::format("expected strings, got {}", type_name(e)));
      out.push_back(s->get());
    }
    return out;
  }

  static const char* type_name(const toml::node& n) {
    switch (n.type()) {
      case toml::node_type::string:
        return "a string";
      case toml::node_type::integer:
        return "an integer";
      case toml::node_type::floating_point:
        return "a float";
      case toml::node_type::boolean:
        return "a boolean";
      case toml::node_type::array:
        return "an array";
      case toml::node_type::table:
        return "a table";
      default:
        return "a date/time";
    }
  }

 private:
  const toml::table& t_;
  std::string origin_;
};

void reject_unknown_keys(const toml::table& t, const std::string& origin) {
  const auto& s = case_key_table();
  for (auto&& [k, v] : t) {
    const std::string key(k.str());
    if (v.is_table()) {
      const auto sec = s.find(key);
      if (sec == s.end() || key.empty()) {
        std::string near;
        for (const auto& [name, keys] : s)
          if (!name.empty() && edit_distance(name, key) <= 2) near = name;
        throw CaseError(fmt::format("{}: unknown section [{}]{}", origin, key,
                                    near.empty() ? "" : fmt::format(" (did you mean [{}]?)", near)));
      }
      for (auto&& [k2, v2] : *v.as_table()) {
        const std::string key2(k2.str());
        const auto& keys = sec->second;
        if (std::find(keys.begin(), keys.end(), key2) == keys.end()) {
          throw CaseError(
              fmt::format("{}: unknown key {}.{}{}", origin, key, key2, unknown_key_hint(key + "." + key2)));
        }
        (void)v2;
      }
    } else if (key != "title") {
      throw CaseError(fmt::format("{}: unknown key {}{}", origin, key, unknown_key_hint(key)));
    }
  }
}

/// s without the spaces and tabs at either end.
std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

void apply_override(toml::table& t, const std::string& spec) {
  const auto eq = spec.find('=');
  const std::string path = eq == std::string::npos ? "" : trim(spec.substr(0, eq));
  if (path.empty()) throw CaseError(fmt::format("--set {}: expected section.key=value", spec));
  const std::string text = trim(spec.substr(eq + 1));  // spaces around '=' and the key are allowed
  if (text.empty()) throw CaseError(fmt::format("--set {}: no value", spec));
  const auto dot = path.find('.');
  const std::string section = dot == std::string::npos ? "" : path.substr(0, dot);
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  const auto& keys = case_keys();
  if (std::find(keys.begin(), keys.end(), path) == keys.end()) {
    throw CaseError(fmt::format("--set {}: unknown key {}{}", spec, path, unknown_key_hint(path)));
  }
  toml::table* target = &t;
  if (!section.empty()) {
    if (!t.contains(section)) t.insert(section, toml::table{});
    target = t.get_as<toml::table>(section);
    if (!target) throw CaseError(fmt::format("--set {}: {} is not a table in the case", spec, section));
  }
  // An override of one of a mutually exclusive group replaces the others of its group.
  if (section == "cylinder" && (key == "spin" || key == "spin_ratio" || key == "rpm"))
    for (const char* k : {"spin", "spin_ratio", "rpm"}) target->erase(k);
  if (section == "flow" && (key == "viscosity" || key == "reynolds"))
    for (const char* k : {"viscosity", "reynolds"}) target->erase(k);
  try {
    toml::table parsed = parse_toml("v = " + text, "--set " + spec);
    target->insert_or_assign(key, parsed["v"]);
  } catch (const toml::parse_error&) {
    // A bare word is a string; like every TOML string it must be UTF-8.
    for (size_t i = 0, len = 0; i < text.size(); i += len)
      if (decode_utf8(text, i, &len) == 0 && static_cast<unsigned char>(text[i]) >= 0x80)
        throw CaseError(fmt::format("--set {}: the value is not valid UTF-8", spec));
    target->insert_or_assign(key, text);
  }
}

}  // namespace

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
  for (const auto& o : overrides) {
    // A tolerance on the command line supersedes the file's grid and stencil.
    if (o.rfind("grid.tolerance=", 0) == 0) {
      if (auto* g = t.get_as<toml::table>("grid")) g->erase("n_theta"), g->erase("n_r");
      if (auto* s = t.get_as<toml::table>("solver")) s->erase("stencil");
    }
    apply_override(t, o);
  }

  const Reader r(t, origin);
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
    ns_only.insert(ns_only.end(), {"output.snapshots", "output.snapshot_interval"});
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
  if (spin_key == "spin_ratio") {
    const double alpha = r.number("cylinder", "spin_ratio", 0.0, any, "finite");
    if (c.scene.speed == 0.0 && alpha != 0.0)
      r.fail("cylinder.spin_ratio", "needs flow.speed > 0 (alpha = a*omega/U); give cylinder.spin instead");
    c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  } else if (spin_key == "rpm") {
    c.scene.spin = r.number("cylinder", "rpm", 0.0, any, "finite (rev/min)") * (2.0 * M_PI / 60.0);
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
    const std::string mode = r.word("time", "mode", "auto", {"auto", "steady", "unsteady"});
    c.time.mode = mode == "auto"     ? TimeMode::automatic
                  : mode == "steady" ? TimeMode::steady
                                     : TimeMode::unsteady;
    auto non_negative = [](double v) { return v >= 0.0; };
    c.time.end = r.number("time", "end", c.time.end, positive, "> 0 (D/U)");
    c.time.dt = r.number("time", "dt", c.time.dt, non_negative, ">= 0 (D/U; 0: from time.cfl)");
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
      r.fail("output.fields", fmt::format("{} field \"{}\" (fields of {} flow: {})",
                                          std::find(names.begin(), names.end(), f) == names.end()
                                              ? "unknown"
                                              : "no such",
                                          f, to_string(c.model), list));
    }
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
  t += fmt::format("\n[cylinder]\nradius = {}\nspin = {}\n", num(c.scene.radius), num(c.scene.spin));
  t += fmt::format("\n[flow]\nspeed = {}\ndensity = {}\npressure = {}\n", num(c.scene.speed),
                   num(c.scene.density), num(c.scene.pressure_inf));
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

}  // namespace magnus
