#pragma once
// Reading a case's TOML table: typed values with range checks that name the key, the unknown-key check and
// the --set overrides. Used by io/case_file only.
#include <fmt/core.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "io/case_keys.hpp"

namespace magnus::case_reader {

/// Reads typed values from the parsed table, naming origin and key in every error.
class Reader {
 public:
  /// overridden: the "section.key"s whose values came from --set (a bad one is blamed on --set, not the file).
  Reader(const toml::table& t, std::string origin, std::vector<std::string> overridden = {})
      : t_(t), origin_(std::move(origin)), overridden_(std::move(overridden)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    if (std::find(overridden_.begin(), overridden_.end(), key) != overridden_.end())
      throw CaseError(fmt::format("--set {}: {}", key, what));
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
    if (!ok(v)) fail(key_name(section, key), fmt::format("{} is out of range: must be {}", refused(v, ok), range));
    return v;
  }

  /// A refused value as quoted: 6 significant digits, or as many as it takes to show that it is out of
  /// range (100.00000000000001 against "<= 100"; 1e-300 stays 1e-300).
  static std::string refused(double v, const std::function<bool(double)>& ok) {
    const std::string short_text = fmt::format("{:.6g}", v);
    return ok(std::strtod(short_text.c_str(), nullptr)) ? fmt::format("{}", v) : short_text;
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
      fail(key_name(section, key), fmt::format("\"{}\" is not one of {}", cut_input(v), list));
    }
    return v;
  }

  bool boolean(const std::string& section, const std::string& key, bool fallback) const {
    const toml::node* n = find(section, key);
    if (!n) return fallback;
    const auto b = n->as_boolean();
    if (!b) fail(key_name(section, key), fmt::format("expected true or false, got {}", type_name(*n)));
    return b->get();
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
  std::vector<std::string> overridden_;
};

/// Throws CaseError naming the first key or section of t that is not in case_key_table() (with a hint).
void reject_unknown_keys(const toml::table& t, const std::string& origin);

/// Apply one "section.key=value" override to t (a bare word is a string); an override of one of a mutually
/// exclusive group replaces the others of its group. Returns the "section.key" it set. Throws CaseError.
std::string apply_override(toml::table& t, const std::string& spec);

}  // namespace magnus::case_reader
