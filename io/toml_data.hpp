#pragma once
// Reading the published-data files in data/ (TOML with [[dataset]] tables): the checks both readers
// (reference_file: viscous reference lift; rotor_data: rotor sails) share, each failing in one line.
#include <toml++/toml.h>

#include <string>
#include <vector>

namespace magnus {

/// Throw std::runtime_error("WHERE: WHAT"): one line naming the file (and dataset) and the problem.
[[noreturn]] void data_fail(const std::string& where, const std::string& what);

/// The key's non-empty string; data_fail when it is missing, empty or not a string.
std::string required_string(const toml::table& t, const char* key, const std::string& where);

/// The key's array of finite numbers (integers convert); empty when absent and not required.
std::vector<double> number_array(const toml::table& t, const char* key, const std::string& where,
                                 bool required = false);

/// The parsed file, its title and sign_convention (both required strings, set here) and a non-empty
/// [[dataset]] array checked; data_fail names the file and what is wrong.
toml::table parse_data_file(const std::string& toml_text, const std::string& origin, std::string& title,
                            std::string& sign_convention);

/// The root's [[dataset]] array (parse_data_file has checked it is there and non-empty).
const toml::array& datasets_of(const toml::table& root);

}  // namespace magnus
