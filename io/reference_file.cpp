#include "io/reference_file.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/toml_data.hpp"

namespace magnus {

ViscousReference parse_viscous_reference(const std::string& toml_text, const std::string& origin) {
  ViscousReference ref;
  const toml::table root = parse_data_file(toml_text, origin, ref.title, ref.sign_convention);
  const toml::array* sets = &datasets_of(root);
  for (size_t k = 0; k < sets->size(); ++k) {
    const toml::table* t = (*sets)[k].as_table();
    const std::string where = fmt::format("{}: dataset {}", origin, k + 1);
    if (!t) data_fail(where, "not a table");
    ViscousDataset d;
    d.id = required_string(*t, "id", where);
    d.label = required_string(*t, "label", where);
    d.citation = required_string(*t, "citation", where);
    d.source = required_string(*t, "source", where);
    d.method = required_string(*t, "method", where);
    d.cl_sign = required_string(*t, "cl_sign", where);
    if (d.cl_sign != "magnitude" && d.cl_sign != "magnus")
      data_fail(where, fmt::format("cl_sign must be \"magnitude\" or \"magnus\", got \"{}\"", d.cl_sign));
    const auto re = (*t)["reynolds"].value<double>();
    if (!re || !(*re > 0.0) || !std::isfinite(*re)) data_fail(where, "reynolds must be a positive number");
    d.reynolds = *re;
    const auto alpha = number_array(*t, "alpha", where, true);
    const auto cl = number_array(*t, "cl", where, true);
    const auto cd = number_array(*t, "cd", where, false);
    if (alpha.empty()) data_fail(where, "alpha is empty");
    if (cl.size() != alpha.size())
      data_fail(where, fmt::format("cl has {} values for {} alpha", cl.size(), alpha.size()));
    if (!cd.empty() && cd.size() != alpha.size())
      data_fail(where, fmt::format("cd has {} values for {} alpha", cd.size(), alpha.size()));
    for (size_t j = 0; j < alpha.size(); ++j) {
      ReferencePoint p;
      p.alpha = alpha[j];
      if (d.cl_sign == "magnitude") {
        if (cl[j] < 0.0)
          data_fail(where, fmt::format("cl[{}] = {} is negative but cl_sign = \"magnitude\"", j, cl[j]));
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
