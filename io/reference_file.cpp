#include "io/reference_file.hpp"

#include <fmt/core.h>

#include <toml++/toml.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace magnus {

namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw std::runtime_error(fmt::format("{}: {}", origin, what));
}

std::string required_string(const toml::table& t, const char* key, const std::string& where) {
  const auto v = t[key].value<std::string>();
  if (!v || v->empty()) fail(where, fmt::format("missing or empty string '{}'", key));
  return *v;
}

std::vector<double> number_array(const toml::table& t, const char* key, const std::string& where,
                                 bool required) {
  const toml::array* a = t[key].as_array();
  if (!a) {
    if (required) fail(where, fmt::format("missing array '{}'", key));
    return {};
  }
  std::vector<double> out;
  for (size_t k = 0; k < a->size(); ++k) {
    const auto v = (*a)[k].value<double>();  // integers convert too
    if (!v || !std::isfinite(*v)) fail(where, fmt::format("{}[{}] is not a finite number", key, k));
    out.push_back(*v);
  }
  return out;
}

}  // namespace

ViscousReference parse_viscous_reference(const std::string& toml_text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    fail(origin, fmt::format("malformed TOML at line {}: {}", e.source().begin.line, e.description()));
  }
  ViscousReference ref;
  ref.title = required_string(root, "title", origin);
  ref.sign_convention = required_string(root, "sign_convention", origin);
  const toml::array* sets = root["dataset"].as_array();
  if (!sets || sets->empty()) fail(origin, "no [[dataset]] tables");
  for (size_t k = 0; k < sets->size(); ++k) {
    const toml::table* t = (*sets)[k].as_table();
    const std::string where = fmt::format("{}: dataset {}", origin, k + 1);
    if (!t) fail(where, "not a table");
    ViscousDataset d;
    d.id = required_string(*t, "id", where);
    d.label = required_string(*t, "label", where);
    d.citation = required_string(*t, "citation", where);
    d.source = required_string(*t, "source", where);
    d.method = required_string(*t, "method", where);
    d.cl_sign = required_string(*t, "cl_sign", where);
    if (d.cl_sign != "magnitude" && d.cl_sign != "magnus")
      fail(where, fmt::format("cl_sign must be \"magnitude\" or \"magnus\", got \"{}\"", d.cl_sign));
    const auto re = (*t)["reynolds"].value<double>();
    if (!re || !(*re > 0.0) || !std::isfinite(*re)) fail(where, "reynolds must be a positive number");
    d.reynolds = *re;
    const auto alpha = number_array(*t, "alpha", where, true);
    const auto cl = number_array(*t, "cl", where, true);
    const auto cd = number_array(*t, "cd", where, false);
    if (alpha.empty()) fail(where, "alpha is empty");
    if (cl.size() != alpha.size())
      fail(where, fmt::format("cl has {} values for {} alpha", cl.size(), alpha.size()));
    if (!cd.empty() && cd.size() != alpha.size())
      fail(where, fmt::format("cd has {} values for {} alpha", cd.size(), alpha.size()));
    for (size_t j = 0; j < alpha.size(); ++j) {
      ReferencePoint p;
      p.alpha = alpha[j];
      if (d.cl_sign == "magnitude") {
        if (cl[j] < 0.0)
          fail(where, fmt::format("cl[{}] = {} is negative but cl_sign = \"magnitude\"", j, cl[j]));
        // CCW spin (α > 0) lifts towards −y in magnus's convention; CW spin towards +y.
        p.cl = (alpha[j] >= 0.0 ? -cl[j] : cl[j]) + 0.0;  // + 0.0: no −0
      } else {
        p.cl = cl[j];
      }
      if (!cd.empty()) p.cd = cd[j];
      d.points.push_back(p);
    }
    ref.datasets.push_back(std::move(d));
  }
  return ref;
}

ViscousReference load_viscous_reference(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error(fmt::format(
        "cannot read the viscous reference data '{}' (set MAGNUS_DATA_DIR to the directory holding it)",
        path));
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_viscous_reference(ss.str(), path);
}

std::string data_dir() {
  const char* env = std::getenv("MAGNUS_DATA_DIR");
  if (env && *env) return env;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  // A binary in the build tree reads the source's data/; any other (an installed one) the data installed
  // beside it, <prefix>/share/magnus/data — never the source tree, which an installed copy may outlive.
  if (!ec && fs::equivalent(exe.parent_path(), fs::path(MAGNUS_BUILD_DIR), ec)) return MAGNUS_DATA_DIR;
  return ec ? std::string(MAGNUS_DATA_DIR)
            : (exe.parent_path().parent_path() / MAGNUS_INSTALL_DATA_DIR).string();
}

std::string viscous_reference_path() { return data_dir() + "/viscous_lift_reference.toml"; }

}  // namespace magnus
