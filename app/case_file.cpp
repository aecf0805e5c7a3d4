#include "app/case_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <toml++/toml.h>

#include "postproc/fields.hpp"

namespace magnus {

namespace {

const std::map<std::string, std::vector<std::string>>& schema() {
  static const std::map<std::string, std::vector<std::string>> s = {
      {"", {"title"}},
      {"cylinder", {"radius", "spin", "spin_ratio"}},
      {"flow", {"speed", "density", "pressure"}},
      {"circulation", {"model", "value"}},
      {"domain", {"outer_radius", "far_field"}},
      {"grid", {"n_theta", "n_r", "spacing", "tolerance"}},
      {"solver", {"method", "stencil"}},
      {"output", {"file", "fields"}},
  };
  return s;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string key_name(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

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

  double number(const std::string& section, const std::string& key, double fallback,
                const std::function<bool(double)>& ok, const char* range) const {
    const toml::node* n = find(section, key);
    if (!n) return fallback;
    double v;
    if (auto i = n->as_integer()) v = double(i->get());
    else if (auto f = n->as_floating_point()) v = f->get();
    else fail(key_name(section, key), fmt::format("expected a number, got {}", type_name(*n)));
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
    if (!arr) fail(key_name(section, key), fmt::format("expected an array of strings, got {}", type_name(*n)));
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
      case toml::node_type::string: return "a string";
      case toml::node_type::integer: return "an integer";
      case toml::node_type::floating_point: return "a float";
      case toml::node_type::boolean: return "a boolean";
      case toml::node_type::array: return "an array";
      case toml::node_type::table: return "a table";
      default: return "a date/time";
    }
  }

 private:
  const toml::table& t_;
  std::string origin_;
};

void reject_unknown_keys(const toml::table& t, const std::string& origin) {
  const auto& s = schema();
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
          const std::string near = nearest_key(key + "." + key2);
          throw CaseError(fmt::format("{}: unknown key {}.{}{}", origin, key, key2,
                                      near.empty() ? "" : fmt::format(" (did you mean {}?)", near)));
        }
        (void)v2;
      }
    } else if (key != "title") {
      const std::string near = nearest_key(key);
      throw CaseError(fmt::format("{}: unknown key {}{}", origin, key,
                                  near.empty() ? "" : fmt::format(" (did you mean {}?)", near)));
    }
  }
}

void apply_override(toml::table& t, const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0)
    throw CaseError(fmt::format("--set {}: expected section.key=value", spec));
  const std::string path = spec.substr(0, eq), text = spec.substr(eq + 1);
  const auto dot = path.find('.');
  const std::string section = dot == std::string::npos ? "" : path.substr(0, dot);
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  const auto& keys = case_keys();
  if (std::find(keys.begin(), keys.end(), path) == keys.end()) {
    const std::string near = nearest_key(path);
    throw CaseError(fmt::format("--set {}: unknown key {}{}", spec, path,
                                near.empty() ? "" : fmt::format(" (did you mean {}?)", near)));
  }
  toml::table* target = &t;
  if (!section.empty()) {
    if (!t.contains(section)) t.insert(section, toml::table{});
    target = t.get_as<toml::table>(section);
    if (!target) throw CaseError(fmt::format("--set {}: {} is not a table in the case", spec, section));
  }
  try {
    toml::table parsed = toml::parse("v = " + text);
    target->insert_or_assign(key, parsed["v"]);
  } catch (const toml::parse_error&) {
    target->insert_or_assign(key, text);  // a bare word is a string
  }
}

}  // namespace

const std::vector<std::string>& case_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& [sec, names] : schema())
      for (const auto& n : names) k.push_back(key_name(sec, n));
    return k;
  }();
  return keys;
}

std::string nearest_key(const std::string& key) {
  std::string best;
  size_t best_d = std::string::npos;
  for (const auto& k : case_keys()) {
    // Compare with the full key and with its last part, so "n_thetaa" finds "grid.n_theta".
    const std::string tail = k.substr(k.find('.') + 1);
    const std::string ktail = key.substr(key.find('.') + 1);
    const size_t d = std::min(edit_distance(key, k), edit_distance(ktail, tail) + (key.find('.') == std::string::npos ? 0 : edit_distance(key.substr(0, key.find('.')), k.substr(0, k.find('.')))));
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best_d <= std::max<size_t>(2, key.size() / 3) ? best : "";
}

Case parse_case(const std::string& toml_text, const std::string& origin,
                const std::vector<std::string>& overrides) {
  toml::table t;
  try {
    t = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    throw CaseError(fmt::format("{}:{}:{}: malformed TOML: {}", origin, e.source().begin.line,
                                e.source().begin.column, e.description()));
  }
  reject_unknown_keys(t, origin);
  for (const auto& o : overrides) apply_override(t, o);

  const Reader r(t, origin);
  Case c;
  auto positive = [](double v) { return v > 0.0; };
  auto any = [](double) { return true; };
  c.title = r.word("", "title", c.title);
  c.radius = r.number("cylinder", "radius", c.radius, positive, "> 0 (m)");
  if (r.has("cylinder", "spin") && r.has("cylinder", "spin_ratio"))
    r.fail("cylinder.spin_ratio", "conflicts with cylinder.spin: give exactly one of them");
  c.speed = r.number("flow", "speed", c.speed, [](double v) { return v >= 0.0; }, ">= 0 (m/s)");
  c.density = r.number("flow", "density", c.density, positive, "> 0 (kg/m^3)");
  c.pressure_inf = r.number("flow", "pressure", c.pressure_inf, any, "finite (Pa)");
  if (r.has("cylinder", "spin_ratio")) {
    const double alpha = r.number("cylinder", "spin_ratio", 0.0, any, "finite");
    if (c.speed == 0.0 && alpha != 0.0)
      r.fail("cylinder.spin_ratio", "needs flow.speed > 0 (alpha = a*omega/U); give cylinder.spin instead");
    c.spin = alpha * c.speed / c.radius;
    c.spin_given_as_ratio = true;
  } else {
    c.spin = r.number("cylinder", "spin", c.spin, any, "finite (rad/s)");
  }
  const std::string model = r.word("circulation", "model", "spin", {"spin", "given"});
  c.circulation_given = model == "given";
  if (r.has("circulation", "value") && !c.circulation_given)
    r.fail("circulation.value", "is only used with circulation.model = \"given\"");
  if (c.circulation_given && !r.has("circulation", "value"))
    r.fail("circulation.value", "is required with circulation.model = \"given\"");
  c.circulation_value = r.number("circulation", "value", 0.0, any, "finite (m^2/s)");
  c.outer_radius = r.number("domain", "outer_radius", c.outer_radius,
                            [](double v) { return v > 1.0 && v <= 1e12; }, "> 1 and <= 1e12 (R/a)");
  c.far_field = r.word("domain", "far_field", "exact", {"exact", "freestream"}) == "exact"
                    ? FarField::exact : FarField::freestream;
  c.n_theta = int(r.integer("grid", "n_theta", c.n_theta,
                            [](long v) { return v >= 8 && v <= (1 << 20) && v % 2 == 0; },
                            "even, >= 8 and <= 1048576"));
  c.n_r = int(r.integer("grid", "n_r", c.n_r, [](long v) { return v == 0 || (v >= 3 && v <= (1 << 22)); },
                        "0 (square cells) or 3 ... 4194304"));
  c.spacing = r.word("grid", "spacing", "geometric", {"geometric", "uniform"}) == "geometric"
                  ? Spacing::geometric : Spacing::uniform;
  c.tolerance = r.number("grid", "tolerance", 0.0, [](double v) { return v == 0.0 || (v >= 1e-14 && v <= 0.1); },
                         "0 (grid as given) or 1e-14 ... 0.1");
  const std::string method = r.word("solver", "method", "auto", {"auto", "cholmod", "fft"});
  c.method = method == "auto" ? Method::automatic : method == "cholmod" ? Method::cholmod : Method::fft;
  c.stencil = r.word("solver", "stencil", "5-point", {"5-point", "9-point"}) == "5-point"
                  ? StencilKind::five_point : StencilKind::nine_point;
  c.output_file = r.word("output", "file", c.output_file);
  if (c.output_file.empty()) r.fail("output.file", "must not be empty");
  if (r.has("output", "fields")) c.output_fields = r.words("output", "fields");
  for (const auto& f : c.output_fields.value_or(std::vector<std::string>{})) {
    const auto& names = field_names();
    if (std::find(names.begin(), names.end(), f) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      r.fail("output.fields", fmt::format("unknown field \"{}\" (fields: {})", f, list));
    }
  }
  if (c.stencil == StencilKind::nine_point && c.spacing == Spacing::uniform)
    r.fail("solver.stencil", "\"9-point\" needs grid.spacing = \"geometric\" (uniform in ln r)");
  if (c.tolerance > 0.0 && r.has("grid", "n_r"))
    r.fail("grid.tolerance", "conflicts with grid.n_r: the tolerance chooses the grid");
  c.source_text = to_toml(c);
  return c;
}

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(fmt::format("cannot read case file '{}': {}", path, std::strerror(errno)));
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_case(ss.str(), path, overrides);
}

std::string to_toml(const Case& c) {
  auto str = [](const std::string& v) {
    std::string q = "\"";
    for (char ch : v) {
      if (ch == '"' || ch == '\\') q += '\\';
      if (ch == '\n') { q += "\\n"; continue; }
      q += ch;
    }
    return q + "\"";
  };
  auto num = [](double v) {
    std::string s = fmt::format("{}", v);
    return s.find_first_of(".eE") == std::string::npos ? s + ".0" : s;
  };
  std::string t = fmt::format("title = {}\n", str(c.title));
  t += fmt::format("\n[cylinder]\nradius = {}\nspin = {}\n", num(c.radius), num(c.spin));
  t += fmt::format("\n[flow]\nspeed = {}\ndensity = {}\npressure = {}\n", num(c.speed), num(c.density),
                   num(c.pressure_inf));
  t += fmt::format("\n[circulation]\nmodel = {}\n", str(c.circulation_given ? "given" : "spin"));
  if (c.circulation_given) t += fmt::format("value = {}\n", num(c.circulation_value));
  t += fmt::format("\n[domain]\nouter_radius = {}\nfar_field = {}\n", num(c.outer_radius), str(to_string(c.far_field)));
  t += fmt::format("\n[grid]\nn_theta = {}\nspacing = {}\n", c.n_theta, str(to_string(c.spacing)));
  if (c.tolerance > 0.0) t += fmt::format("tolerance = {}\n", num(c.tolerance));
  else t += fmt::format("n_r = {}\n", c.n_r);
  t += fmt::format("\n[solver]\nmethod = {}\nstencil = {}\n", str(to_string(c.method)), str(to_string(c.stencil)));
  t += fmt::format("\n[output]\nfile = {}\n", str(c.output_file));
  if (c.output_fields) {
    std::string list;
    for (const auto& f : *c.output_fields) list += (list.empty() ? "" : ", ") + str(f);
    t += fmt::format("fields = [{}]\n", list);
  }
  return t;
}

}  // namespace magnus
