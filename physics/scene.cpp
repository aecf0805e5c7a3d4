#include "physics/scene.hpp"

#include <cmath>

namespace magnus {

double Scene::Gamma() const {
  if (circulation_given) return circulation_value;
  return 2.0 * M_PI * radius * radius * spin;
}

double Scene::spin_ratio() const { return speed > 0.0 ? radius * spin / speed : 0.0; }

const char* to_string(Spacing s) { return s == Spacing::geometric ? "geometric" : "uniform"; }
const char* to_string(FarField f) { return f == FarField::exact ? "exact" : "freestream"; }
const char* to_string(Method m) {
  return m == Method::automatic ? "auto" : m == Method::cholmod ? "cholmod" : "fft";
}
const char* to_string(StencilKind s) { return s == StencilKind::five_point ? "5-point" : "9-point"; }

const std::vector<std::string>& field_names() {
  static const std::vector<std::string> names = {"psi", "u_r", "u_theta", "u_x", "u_y",
                                                 "pressure", "cp", "psi_exact", "psi_error"};
  return names;
}

const char* field_units(const std::string& name) {
  if (name == "psi" || name == "psi_exact" || name == "psi_error") return "m^2/s";
  if (name == "pressure") return "Pa";
  if (name == "cp") return "1";
  return "m/s";
}

}  // namespace magnus
