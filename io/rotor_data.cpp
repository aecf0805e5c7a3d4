#include "io/rotor_data.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/reference_file.hpp"
#include "io/toml_data.hpp"

namespace magnus {

namespace {

/// reynolds = number | [low, high] | "unknown".
void read_reynolds(const toml::table& t, const std::string& where, RotorDataset& d) {
  const toml::node* n = t.get("reynolds");
  if (!n) data_fail(where, "missing 'reynolds' (a number, [low, high] or \"unknown\")");
  if (const auto s = n->value<std::string>()) {
    if (*s != "unknown")
      data_fail(where, fmt::format("reynolds must be a number, [low, high] or \"unknown\", got \"{}\"", *s));
    d.reynolds_known = false;
    return;
  }
  std::vector<double> r;
  if (n->is_array()) {
    r = number_array(t, "reynolds", where);
    if (r.size() != 2) data_fail(where, "reynolds as a range must be [low, high]");
  } else if (const auto v = n->value<double>()) {
    r = {*v, *v};
  } else {
    data_fail(where, "reynolds must be a number, [low, high] or \"unknown\"");
  }
  if (!(r[0] > 0.0) || !std::isfinite(r[1]) || r[1] < r[0])
    data_fail(where, fmt::format("reynolds must be positive with low <= high, got [{}, {}]", r[0], r[1]));
  d.reynolds_known = true;
  d.reynolds_min = r[0];
  d.reynolds_max = r[1];
}

/// aspect_ratio = number (h/D > 0) | "unknown" (3D) | "infinite" (2D).
void read_geometry(const toml::table& t, const std::string& where, RotorDataset& d) {
  const std::string g = required_string(t, "geometry", where);
  if (g != "2D" && g != "3D") data_fail(where, fmt::format("geometry must be \"2D\" or \"3D\", got \"{}\"", g));
  d.three_d = g == "3D";
  const toml::node* n = t.get("aspect_ratio");
  if (!n) data_fail(where, "missing 'aspect_ratio' (h/D, \"unknown\" or \"infinite\")");
  if (const auto s = n->value<std::string>()) {
    if (*s == "infinite" ? d.three_d : *s == "unknown" ? !d.three_d : true)
      data_fail(where, fmt::format("aspect_ratio \"{}\" does not fit geometry \"{}\" (2D: \"infinite\"; 3D: h/D "
                              "or \"unknown\")",
                              *s, g));
  } else if (const auto v = n->value<double>()) {
    if (!d.three_d || !(*v > 0.0) || !std::isfinite(*v))
      data_fail(where, fmt::format("aspect_ratio = {} needs geometry \"3D\" and a positive h/D", *v));
    d.aspect_ratio = *v;
  } else {
    data_fail(where, "aspect_ratio must be h/D, \"unknown\" or \"infinite\"");
  }
  d.end_plates = required_string(t, "end_plates", where);
}

void read_values(const toml::table& t, const std::string& where, RotorDataset& d) {
  const auto range = number_array(t, "alpha_range", where);
  if (range.size() != 2 || !(range[0] >= 0.0) || !(range[1] > range[0]))
    data_fail(where, "alpha_range must be [low, high] with 0 <= low < high");
  d.alpha_min = range[0];
  d.alpha_max = range[1];
  const auto alpha = number_array(t, "alpha", where), cl = number_array(t, "cl", where),
             cd = number_array(t, "cd", where);
  d.cl_poly = number_array(t, "cl_poly", where);
  d.cd_poly = number_array(t, "cd_poly", where);
  const bool table = !alpha.empty() || !cl.empty() || !cd.empty();
  const bool fit = !d.cl_poly.empty() || !d.cd_poly.empty();
  if (table == fit) data_fail(where, "give either alpha/cl(/cd) arrays or cl_poly(/cd_poly), not both or neither");
  if (fit) {
    if (d.cl_poly.empty()) data_fail(where, "cl_poly is missing or empty");
    if (d.method != "fit")
      data_fail(where, fmt::format("a polynomial needs method = \"fit\", got \"{}\"", d.method));
    // The fit must give a non-negative |C_L| and C_D across its range (a sign slip in a coefficient shows).
    for (int k = 0; k <= 50; ++k) {
      const double a = d.alpha_min + (d.alpha_max - d.alpha_min) * k / 50.0;
      if (polynomial_value(d.cl_poly, a) < -1e-9 ||
          (!d.cd_poly.empty() && !(polynomial_value(d.cd_poly, a) > 0.0)))
        data_fail(where,
             fmt::format("the polynomial gives a negative |C_L| or C_D at α = {:.3g} inside alpha_range", a));
    }
    return;
  }
  if (alpha.empty()) data_fail(where, "alpha is missing or empty");
  if (cl.size() != alpha.size())
    data_fail(where, fmt::format("cl has {} values for {} alpha", cl.size(), alpha.size()));
  if (!cd.empty() && cd.size() != alpha.size())
    data_fail(where, fmt::format("cd has {} values for {} alpha", cd.size(), alpha.size()));
  for (size_t j = 0; j < alpha.size(); ++j) {
    if (alpha[j] < d.alpha_min - 1e-9 || alpha[j] > d.alpha_max + 1e-9)
      data_fail(where, fmt::format("alpha[{}] = {} is outside alpha_range [{}, {}]", j, alpha[j], d.alpha_min,
                              d.alpha_max));
    if (j > 0 && !(alpha[j] > alpha[j - 1]))
      data_fail(where, fmt::format("alpha[{}] = {} does not increase", j, alpha[j]));
    if (cl[j] < 0.0)
      data_fail(where, fmt::format("cl[{}] = {} is negative but cl_sign = \"magnitude\"", j, cl[j]));
    if (!cd.empty() && cd[j] < 0.0) data_fail(where, fmt::format("cd[{}] = {} is negative", j, cd[j]));
    RotorPoint p;
    p.alpha = alpha[j];
    p.cl = -cl[j] + 0.0;  // CCW spin lifts towards −y in magnus's convention; + 0.0: no −0
    if (!cd.empty()) p.cd = cd[j];
    d.points.push_back(p);
  }
}

}  // namespace

RotorData parse_rotor_data(const std::string& toml_text, const std::string& origin) {
  RotorData data;
  const toml::table root = parse_data_file(toml_text, origin, data.title, data.sign_convention);
  const toml::array* sets = &datasets_of(root);
  for (size_t k = 0; k < sets->size(); ++k) {
    const toml::table* t = (*sets)[k].as_table();
    std::string where = fmt::format("{}: dataset {}", origin, k + 1);
    if (!t) data_fail(where, "not a table");
    RotorDataset d;
    d.id = required_string(*t, "id", where);
    where = fmt::format("{}: dataset {} (\"{}\")", origin, k + 1, d.id);
    for (const auto& e : data.datasets)
      if (e.id == d.id) data_fail(where, "the id is used twice");
    d.label = required_string(*t, "label", where);
    d.citation = required_string(*t, "citation", where);
    d.source = required_string(*t, "source", where);
    d.method = required_string(*t, "method", where);
    if (d.method != "experiment" && d.method != "CFD" && d.method != "fit")
      data_fail(where, fmt::format("method must be \"experiment\", \"CFD\" or \"fit\", got \"{}\"", d.method));
    d.accuracy = required_string(*t, "accuracy", where);
    read_reynolds(*t, where, d);
    d.reynolds_note = required_string(*t, "reynolds_note", where);
    read_geometry(*t, where, d);
    const std::string sign = required_string(*t, "cl_sign", where);
    if (sign != "magnitude") data_fail(where, fmt::format("cl_sign must be \"magnitude\", got \"{}\"", sign));
    read_values(*t, where, d);
    data.datasets.push_back(std::move(d));
  }
  return data;
}

RotorData load_rotor_data(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error(fmt::format(
        "cannot read the rotor data '{}' (set MAGNUS_DATA_DIR to the directory holding it)", path));
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_rotor_data(ss.str(), path);
}

std::string rotor_data_path() { return data_dir() + "/rotor_data.toml"; }

namespace {
struct Shipped {
  std::optional<RotorData> data;
  std::string error;
};
const Shipped& shipped() {
  static const Shipped s = [] {
    Shipped r;
    try {
      r.data = load_rotor_data(rotor_data_path());
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    return r;
  }();
  return s;
}
}  // namespace

const RotorData* shipped_rotor_data() { return shipped().data ? &*shipped().data : nullptr; }
std::string rotor_data_error() { return shipped().error; }

}  // namespace magnus
