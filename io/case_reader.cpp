#include "io/case_reader.hpp"

#include "io/toml_safe.hpp"

namespace magnus::case_reader {

using toml_safe::decode_utf8;
using toml_safe::parse_toml;

namespace {

/// s without the spaces and tabs at either end.
std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

}  // namespace

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
        throw CaseError(fmt::format("{}: unknown section [{}]{}", origin, cut_input(key),
                                    near.empty() ? "" : fmt::format(" (did you mean [{}]?)", near)));
      }
      for (auto&& [k2, v2] : *v.as_table()) {
        const std::string key2(k2.str());
        const auto& keys = sec->second;
        if (std::find(keys.begin(), keys.end(), key2) == keys.end()) {
          throw CaseError(
              fmt::format("{}: unknown key {}{}", origin, cut_input(key + "." + key2),
                          unknown_key_hint(key + "." + key2)));
        }
        (void)v2;
      }
    } else if (key != "title") {
      throw CaseError(fmt::format("{}: unknown key {}{}", origin, cut_input(key), unknown_key_hint(key)));
    }
  }
}

std::string apply_override(toml::table& t, const std::string& spec) {
  const auto eq = spec.find('=');
  const std::string path = eq == std::string::npos ? "" : trim(spec.substr(0, eq));
  if (path.empty()) throw CaseError(fmt::format("--set {}: expected section.key=value", cut_input(spec)));
  const std::string text = trim(spec.substr(eq + 1));  // spaces around '=' and the key are allowed
  if (text.empty()) throw CaseError(fmt::format("--set {}: no value", cut_input(spec)));
  const auto dot = path.find('.');
  const std::string section = dot == std::string::npos ? "" : path.substr(0, dot);
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  const auto& keys = case_keys();
  if (std::find(keys.begin(), keys.end(), path) == keys.end()) {
    throw CaseError(fmt::format("--set {}: unknown key {}{}", cut_input(spec), cut_input(path),
                                unknown_key_hint(path)));
  }
  toml::table* target = &t;
  if (!section.empty()) {
    if (!t.contains(section)) t.insert(section, toml::table{});
    target = t.get_as<toml::table>(section);
    if (!target) throw CaseError(fmt::format("--set {}: {} is not a table in the case", cut_input(spec), section));
  }
  // An override of one of a mutually exclusive group replaces the others of its group.
  if (section == "cylinder" && (key == "spin" || key == "spin_ratio" || key == "rpm"))
    for (const char* k : {"spin", "spin_ratio", "rpm"}) target->erase(k);
  if (section == "flow" && (key == "viscosity" || key == "reynolds"))
    for (const char* k : {"viscosity", "reynolds"}) target->erase(k);
  try {
    toml::table parsed = parse_toml("v = " + text, "--set " + cut_input(spec));
    target->insert_or_assign(key, parsed["v"]);
  } catch (const toml::parse_error&) {
    // A bare word is a string; like every TOML string it must be UTF-8.
    for (size_t i = 0, len = 0; i < text.size(); i += len)
      if (decode_utf8(text, i, &len) == 0 && static_cast<unsigned char>(text[i]) >= 0x80)
        throw CaseError(fmt::format("--set {}: the value is not valid UTF-8", cut_input(spec)));
    target->insert_or_assign(key, text);
  }
  return path;
}


}  // namespace magnus::case_reader
