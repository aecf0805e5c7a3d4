#include "io/toml_data.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

namespace magnus {

void data_fail(const std::string& where, const std::string& what) {
  throw std::runtime_error(fmt::format("{}: {}", where, what));
}

std::string required_string(const toml::table& t, const char* key, const std::string& where) {
  const auto v = t[key].value<std::string>();
  if (!v || v->empty()) data_fail(where, fmt::format("missing or empty string '{}'", key));
  return *v;
}

std::vector<double> number_array(const toml::table& t, const char* key, const std::string& where,
                                 bool required) {
  const toml::array* a = t[key].as_array();
  if (!a) {
    if (required) data_fail(where, fmt::format("missing array '{}'", key));
    return {};
  }
  std::vector<double> out;
  for (size_t k = 0; k < a->size(); ++k) {
    const auto v = (*a)[k].value<double>();  // integers convert too
    if (!v || !std::isfinite(*v)) data_fail(where, fmt::format("{}[{}] is not a finite number", key, k));
    out.push_back(*v);
  }
  return out;
}

toml::table parse_data_file(const std::string& toml_text, const std::string& origin, std::string& title,
                            std::string& sign_convention) {
  toml::table root;
  try {
    root = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    data_fail(origin, fmt::format("malformed TOML at line {}: {}", e.source().begin.line, e.description()));
  }
  title = required_string(root, "title", origin);
  sign_convention = required_string(root, "sign_convention", origin);
  const toml::array* sets = root["dataset"].as_array();
  if (!sets || sets->empty()) data_fail(origin, "no [[dataset]] tables");
  return root;
}

const toml::array& datasets_of(const toml::table& root) { return *root["dataset"].as_array(); }

}  // namespace magnus
