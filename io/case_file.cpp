#include "io/case_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <toml++/toml.h>


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

// toml++ 3.3 (Debian 12) reaches __builtin_unreachable() — undefined behaviour — when its whitespace test meets
// some non-ASCII code points outside a string or comment ("title = Über", "[Ü]", "a = [ψ]", "\Ü" in a """
// string: https://github.com/marzer/tomlplusplus/issues/190, fixed upstream after 3.4). The parser never sees
// them: each is swapped for a private-use code point that toml++ treats the same way (a non-ASCII character
// that is neither whitespace nor allowed in a bare key), and swapped back in what the parse returns.
bool toml_ub_codepoint(char32_t c) {
  // The ranges where toml++'s is_non_ascii_horizontal_whitespace() has no case (blocks 0, 11, 63 of 0x3FA).
  return (c >= 0xA1 && c <= 0x499) || (c >= 0x2D1E && c <= 0x3117 && c != 0x3000) || (c >= 0xFAC6 && c <= 0xFEFE);
}
constexpr char32_t shield_offset = 0xF0000;  // plane 15, private use: 0xF00A1 ... 0xFFEFE

/// Decodes one well-formed UTF-8 sequence at s[i] (length in *len); returns 0 with *len = 1 if malformed.
char32_t decode_utf8(std::string_view s, size_t i, size_t* len) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const auto cont = [&](size_t k) { return i + k < s.size() && (b(k) & 0xC0) == 0x80; };
  *len = 1;
  const unsigned c0 = b(0);
  if (c0 >= 0xC2 && c0 <= 0xDF && cont(1)) {
    *len = 2;
    return char32_t(((c0 & 0x1F) << 6) | (b(1) & 0x3F));
  }
  if (c0 >= 0xE0 && c0 <= 0xEF && cont(1) && cont(2)) {
    const char32_t c = char32_t(((c0 & 0x0F) << 12) | ((b(1) & 0x3F) << 6) | (b(2) & 0x3F));
    if (c < 0x800 || (c >= 0xD800 && c <= 0xDFFF)) return 0;
    *len = 3;
    return c;
  }
  if (c0 >= 0xF0 && c0 <= 0xF4 && cont(1) && cont(2) && cont(3)) {
    const char32_t c = char32_t(((c0 & 0x07) << 18) | ((b(1) & 0x3F) << 12) | ((b(2) & 0x3F) << 6) | (b(3) & 0x3F));
    if (c < 0x10000 || c > 0x10FFFF) return 0;
    *len = 4;
    return c;
  }
  return 0;
}

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += char(c);
  } else if (c < 0x800) {
    out += char(0xC0 | (c >> 6));
    out += char(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += char(0xE0 | (c >> 12));
    out += char(0x80 | ((c >> 6) & 0x3F));
    out += char(0x80 | (c & 0x3F));
  } else {
    out += char(0xF0 | (c >> 18));
    out += char(0x80 | ((c >> 12) & 0x3F));
    out += char(0x80 | ((c >> 6) & 0x3F));
    out += char(0x80 | (c & 0x3F));
  }
}

/// Maps every code point c in s with from(c) to to(c); malformed bytes are left for toml++ to reject.
template <class From, class To>
std::string map_codepoints(std::string_view s, From from, To to, bool* changed = nullptr) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    size_t len;
    const char32_t c = decode_utf8(s, i, &len);
    if (len > 1 && from(c)) {
      append_utf8(out, to(c));
      if (changed) *changed = true;
    } else {
      out.append(s.substr(i, len));
    }
    i += len;
  }
  return out;
}

std::string unshield(std::string_view s) {
  return map_codepoints(s, [](char32_t c) { return c > shield_offset && toml_ub_codepoint(c - shield_offset); },
                        [](char32_t c) { return c - shield_offset; });
}

/// A copy of a parsed value with every string and key unshielded.
void unshield_into(const toml::node& n, toml::array& out);
toml::table unshield_table(const toml::table& t) {
  toml::table out;
  for (auto&& [k, v] : t) {
    const std::string key = unshield(k.str());
    if (const auto* sub = v.as_table()) out.insert(key, unshield_table(*sub));
    else if (const auto* arr = v.as_array()) {
      toml::array a;
      for (const auto& e : *arr) unshield_into(e, a);
      out.insert(key, std::move(a));
    } else if (const auto* str = v.as_string()) out.insert(key, unshield(str->get()));
    else v.visit([&](const auto& value) { out.insert(key, value); });
  }
  return out;
}
void unshield_into(const toml::node& n, toml::array& out) {
  if (const auto* sub = n.as_table()) out.push_back(unshield_table(*sub));
  else if (const auto* arr = n.as_array()) {
    toml::array a;
    for (const auto& e : *arr) unshield_into(e, a);
    out.push_back(std::move(a));
  } else if (const auto* str = n.as_string()) out.push_back(unshield(str->get()));
  else n.visit([&](const auto& value) { out.push_back(value); });
}

/// toml::parse without toml++'s undefined behaviour (above). Throws toml::parse_error (description shielded:
/// pass it through unshield()) or CaseError.
toml::table parse_toml(const std::string& text, const std::string& origin) {
  bool changed = false;
  // Private-use code points of the swap range cannot be told apart from swapped ones: refuse them.
  map_codepoints(text, [](char32_t c) { return c > shield_offset && toml_ub_codepoint(c - shield_offset); },
                 [&](char32_t c) -> char32_t {
                   throw CaseError(fmt::format("{}: unsupported character U+{:X} (private use)", origin, uint32_t(c)));
                 });
  const std::string safe = map_codepoints(text, toml_ub_codepoint, [](char32_t c) { return c + shield_offset; },
                                          &changed);
  toml::table t = toml::parse(safe, origin);
  return changed ? unshield_table(t) : t;
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
  // The edit distance is at least the difference in length, and no valid key is longer than 20 characters:
  // a key this long is never within max(2, size/3) of one (and a megabyte key would cost seconds).
  if (key.size() > 64) return "";
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
  c.scene.radius = r.number("cylinder", "radius", c.scene.radius, positive, "> 0 (m)");
  if (r.has("cylinder", "spin") && r.has("cylinder", "spin_ratio"))
    r.fail("cylinder.spin_ratio", "conflicts with cylinder.spin: give exactly one of them");
  c.scene.speed = r.number("flow", "speed", c.scene.speed, [](double v) { return v >= 0.0; }, ">= 0 (m/s)");
  c.scene.density = r.number("flow", "density", c.scene.density, positive, "> 0 (kg/m^3)");
  c.scene.pressure_inf = r.number("flow", "pressure", c.scene.pressure_inf, any, "finite (Pa)");
  if (r.has("cylinder", "spin_ratio")) {
    const double alpha = r.number("cylinder", "spin_ratio", 0.0, any, "finite");
    if (c.scene.speed == 0.0 && alpha != 0.0)
      r.fail("cylinder.spin_ratio", "needs flow.speed > 0 (alpha = a*omega/U); give cylinder.spin instead");
    c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  } else {
    c.scene.spin = r.number("cylinder", "spin", c.scene.spin, any, "finite (rad/s)");
  }
  const std::string model = r.word("circulation", "model", "spin", {"spin", "given"});
  c.scene.circulation_given = model == "given";
  if (r.has("circulation", "value") && !c.scene.circulation_given)
    r.fail("circulation.value", "is only used with circulation.model = \"given\"");
  if (c.scene.circulation_given && !r.has("circulation", "value"))
    r.fail("circulation.value", "is required with circulation.model = \"given\"");
  c.scene.circulation_value = r.number("circulation", "value", 0.0, any, "finite (m^2/s)");
  // Each value is finite, but what is derived from them must be too (1e300 * 1e300 is not).
  if (!std::isfinite(c.scene.spin))
    r.fail("cylinder.spin_ratio", fmt::format("gives a spin omega = alpha*U/a that is not finite (a = {}, U = {})",
                                              c.scene.radius, c.scene.speed));
  if (!std::isfinite(c.scene.Gamma()))
    r.fail("cylinder.radius", fmt::format("gives a circulation 2*pi*a^2*omega that is not finite (a = {}, omega = {})", c.scene.radius, c.scene.spin));
  if (!std::isfinite(c.scene.spin_ratio()))
    r.fail("flow.speed", fmt::format("{} is too small: the spin ratio a*omega/U is not finite", c.scene.speed));
  c.grid.outer_radius = r.number("domain", "outer_radius", c.grid.outer_radius,
                            [](double v) { return v > 1.0 && v <= 1e12; }, "> 1 and <= 1e12 (R/a)");
  c.grid.far_field = r.word("domain", "far_field", "exact", {"exact", "freestream"}) == "exact"
                    ? FarField::exact : FarField::freestream;
  c.grid.n_theta = int(r.integer("grid", "n_theta", c.grid.n_theta,
                            [](long v) { return v >= 8 && v <= (1 << 20) && v % 2 == 0; },
                            "even, >= 8 and <= 1048576"));
  c.grid.n_r = int(r.integer("grid", "n_r", c.grid.n_r, [](long v) { return v == 0 || (v >= 3 && v <= (1 << 22)); },
                        "0 (square cells) or 3 ... 4194304"));
  c.grid.spacing = r.word("grid", "spacing", "geometric", {"geometric", "uniform"}) == "geometric"
                  ? Spacing::geometric : Spacing::uniform;
  c.grid.tolerance = r.number("grid", "tolerance", 0.0, [](double v) { return v == 0.0 || (v >= 1e-14 && v <= 0.1); },
                         "0 (grid as given) or 1e-14 ... 0.1");
  const std::string method = r.word("solver", "method", "auto", {"auto", "cholmod", "fft"});
  c.solver.method = method == "auto" ? Method::automatic : method == "cholmod" ? Method::cholmod : Method::fft;
  c.solver.stencil = r.word("solver", "stencil", "5-point", {"5-point", "9-point"}) == "5-point"
                  ? StencilKind::five_point : StencilKind::nine_point;
  c.output.file = r.word("output", "file", c.output.file);
  if (c.output.file.empty()) r.fail("output.file", "must not be empty");
  if (r.has("output", "fields")) c.output.fields = r.words("output", "fields");
  for (const auto& f : c.output.fields.value_or(std::vector<std::string>{})) {
    const auto& names = field_names();
    if (std::find(names.begin(), names.end(), f) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      r.fail("output.fields", fmt::format("unknown field \"{}\" (fields: {})", f, list));
    }
  }
  if (c.solver.stencil == StencilKind::nine_point && c.grid.spacing == Spacing::uniform)
    r.fail("solver.stencil", "\"9-point\" needs grid.spacing = \"geometric\" (uniform in ln r)");
  for (const char* key : {"grid.n_theta", "grid.n_r", "solver.stencil"}) {
    const std::string k(key);
    if (c.grid.tolerance > 0.0 && r.has(k.substr(0, k.find('.')), k.substr(k.find('.') + 1)))
      r.fail("grid.tolerance", fmt::format("conflicts with {}: the tolerance chooses the grid and stencil", k));
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
  return parse_case(ss.str(), path, overrides);
}

std::string to_toml(const Case& c) {
  auto str = [](const std::string& v) {
    std::string q = "\"";
    for (char ch : v) {
      if (ch == '"' || ch == '\\') q += '\\';
      if (ch == '\n') { q += "\\n"; continue; }
      // TOML basic strings may not hold control characters other than tab: escape them all.
      if ((unsigned char)ch < 0x20 || ch == 0x7F) { q += fmt::format("\\u{:04X}", (unsigned char)ch); continue; }
      q += ch;
    }
    return q + "\"";
  };
  auto num = [](double v) {
    std::string s = fmt::format("{}", v);
    return s.find_first_of(".eE") == std::string::npos ? s + ".0" : s;
  };
  std::string t = fmt::format("title = {}\n", str(c.title));
  t += fmt::format("\n[cylinder]\nradius = {}\nspin = {}\n", num(c.scene.radius), num(c.scene.spin));
  t += fmt::format("\n[flow]\nspeed = {}\ndensity = {}\npressure = {}\n", num(c.scene.speed), num(c.scene.density),
                   num(c.scene.pressure_inf));
  t += fmt::format("\n[circulation]\nmodel = {}\n", str(c.scene.circulation_given ? "given" : "spin"));
  if (c.scene.circulation_given) t += fmt::format("value = {}\n", num(c.scene.circulation_value));
  t += fmt::format("\n[domain]\nouter_radius = {}\nfar_field = {}\n", num(c.grid.outer_radius), str(to_string(c.grid.far_field)));
  // With a tolerance the grid and stencil are chosen at run time (and stored in /parameters).
  t += fmt::format("\n[grid]\nspacing = {}\n", str(to_string(c.grid.spacing)));
  if (c.grid.tolerance > 0.0) t += fmt::format("tolerance = {}\n", num(c.grid.tolerance));
  else t += fmt::format("n_theta = {}\nn_r = {}\n", c.grid.n_theta, c.grid.n_r);
  t += fmt::format("\n[solver]\nmethod = {}\n", str(to_string(c.solver.method)));
  if (c.grid.tolerance == 0.0) t += fmt::format("stencil = {}\n", str(to_string(c.solver.stencil)));
  t += fmt::format("\n[output]\nfile = {}\n", str(c.output.file));
  if (c.output.fields) {
    std::string list;
    for (const auto& f : *c.output.fields) list += (list.empty() ? "" : ", ") + str(f);
    t += fmt::format("fields = [{}]\n", list);
  }
  return t;
}

}  // namespace magnus
