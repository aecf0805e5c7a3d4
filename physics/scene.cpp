#include "physics/scene.hpp"

#include <cfloat>
#include <cmath>
#include <tuple>

namespace magnus {

double Scene::Gamma() const {
  if (circulation_given) return circulation_value;
  return 2.0 * M_PI * radius * radius * spin;
}

double Scene::spin_ratio() const { return speed > 0.0 ? radius * spin / speed : 0.0; }

double Scene::reynolds() const {
  if (reynolds_given && speed > 0.0)
    return reynolds_value;  // as given: U·2a/ν of ν = U·2a/Re is off by an ulp
  return viscosity > 0.0 ? speed * 2.0 * radius / viscosity : 0.0;
}

double Scene::reference_speed() const { return speed > 0.0 ? speed : radius * std::fabs(spin); }

double Scene::time_unit() const { return 2.0 * radius / reference_speed(); }

double Scene::rpm() const { return spin * 60.0 / (2.0 * M_PI); }

namespace {

/// cos and sin of an angle in degrees, exact at multiples of 90° (cos 90° is 0, not 6e-17).
void cos_sin_deg(double deg, double& c, double& s) {
  const double q = std::fmod(deg, 360.0);
  const double k = q / 90.0;
  if (k == std::floor(k)) {
    const int n = (int(k) % 4 + 4) % 4;
    c = n == 0 ? 1.0 : n == 2 ? -1.0 : 0.0;
    s = n == 1 ? 1.0 : n == 3 ? -1.0 : 0.0;
    return;
  }
  const double rad = q * M_PI / 180.0;
  c = std::cos(rad), s = std::sin(rad);
}

}  // namespace

WorldForce rotate_deg(double x, double y, double deg) {
  double c, s;
  cos_sin_deg(deg, c, s);
  return {x * c - y * s, x * s + y * c};
}

WorldForce world_force(double drag, double lift, double direction_deg) {
  return rotate_deg(drag, lift, direction_deg);
}

CourseForce course_force(double drag, double lift, double direction_deg, double course_deg) {
  const WorldForce f = rotate_deg(drag, lift, direction_deg - course_deg);  // in the course's frame
  return {f.x, f.y};
}

std::optional<Overflow> find_overflow(const Scene& s, double outer_radius, const SceneKeys& k) {
  const double a = s.radius, U = s.speed, rho = s.density, w = s.spin, G = s.Gamma(), p = s.pressure_inf;
  struct Factor {
    const std::string* key;
    double value;
  };
  // Γ's own inputs: the given value, or a and ω (Γ = 2πa²ω).
  const std::vector<Factor> gamma = s.circulation_given
                                        ? std::vector<Factor>{{&k.circulation, s.circulation_value}}
                                        : std::vector<Factor>{{&k.radius, a}, {&k.spin, w}};
  auto with = [](std::vector<Factor> f, const std::vector<Factor>& more) {
    f.insert(f.end(), more.begin(), more.end());
    return f;
  };
  const Factor fa{&k.radius, a}, fU{&k.speed, U}, frho{&k.density, rho}, fw{&k.spin, w}, fp{&k.pressure, p};
  const double u_max = 2.0 * U + std::fabs(G) / (2.0 * M_PI * a), R = outer_radius * a;
  std::vector<std::tuple<const char*, double, std::vector<Factor>>> checks = {
      {"the circulation Γ", G, gamma},
      {"the spin ratio α = aω/U", s.spin_ratio(), {fa, fw, fU}},
      {"U²", U * U, {fU}},
      {"ρU²", rho * U * U, {frho, fU}},
      {"the force scale ½ρU²·2a", rho * U * U * a, {frho, fU, fa}},
      {"the lift ρUΓ", rho * U * G, with({frho, fU}, gamma)},
      {"the seed ΔP = 2ρUaω", 2.0 * rho * U * a * w, {frho, fU, fa, fw}},
      {"the exact ΔP = 4ρUΓ/(2πa)", 4.0 * rho * U * G / (2.0 * M_PI * a), with({frho, fU, fa}, gamma)},
      {"the seed force 4ρUa²ω", 4.0 * rho * U * a * a * w, {frho, fU, fa, fw}},
      {"the Magnus S = 2πρa²", 2.0 * M_PI * rho * a * a, {frho, fa}},
      {"the surface speed 2U + |Γ|/(2πa)", u_max, with({fU, fa}, gamma)},
      {"the surface pressure p∞ − ½ρ(2U + |Γ|/(2πa))²", p - 0.5 * rho * u_max * u_max,
       with({fp, frho, fU, fa}, gamma)},
      {"C_L = −Γ/(Ua)", U > 0.0 ? G / (U * a) : 0.0, with({fU, fa}, gamma)},
      {"the free stagnation radius |Γ|/(2πU)", U > 0.0 ? G / (2.0 * M_PI * U) : 0.0, with({fU}, gamma)},
      {"the streamfunction at the outer boundary U·R + |Γ|/(2π)·ln(R/a)",
       U * R + std::fabs(G) / (2.0 * M_PI) * std::log(outer_radius), with({fU, fa}, gamma)},
  };
  // The viscosity, when given: ν derived from a given Re, or Re derived from a given ν (U_ref: U, or the wall
  // speed a|ω| in still fluid).
  if (s.reynolds_given)
    checks.emplace_back("the viscosity ν = U·2a/Re", s.viscosity,
                        std::vector<Factor>{fU, fa, {&k.reynolds, s.reynolds_value}});
  else if (s.viscosity != 0.0)
    checks.emplace_back(U > 0.0 ? "the Reynolds number Re = U·2a/ν" : "the wall Reynolds number a|ω|·2a/ν",
                        s.reference_speed() * 2.0 * a / s.viscosity,
                        U > 0.0 ? std::vector<Factor>{fU, fa, {&k.viscosity, s.viscosity}}
                                : std::vector<Factor>{fa, fw, {&k.viscosity, s.viscosity}});
  if (s.span > 0.0)
    checks.emplace_back("the total lift ρUΓ·b", rho * U * G * s.span, with({frho, fU, {&k.span, s.span}}, gamma));
  for (const auto& [quantity, value, factors] : checks) {
    bool inputs_nonzero = true;
    for (const auto& f : factors) inputs_nonzero = inputs_nonzero && f.value != 0.0;
    // Not finite, or lost below the smallest normal double although every input is non-zero (a sum, like the
    // surface pressure, may be zero by cancellation: only products are checked for underflow).
    const bool underflow = inputs_nonzero && std::fabs(value) < DBL_MIN && value == value &&
                           std::string(quantity).find("pressure") == std::string::npos &&
                           std::string(quantity).find("speed") == std::string::npos;
    if (std::isfinite(value) && !underflow) continue;
    // The input furthest from 1 is blamed, each judged as given: a spin given as α = aω/U (or in rev/min)
    // by that value, since ω = αU/a is tiny only because a is huge.
    const Factor* worst = &factors.front();
    double worst_log = -1.0;
    for (const auto& f : factors) {
      const double given = f.key == &k.spin && k.spin_value != 0.0 ? k.spin_value : f.value;
      if (given != 0.0 && std::fabs(std::log10(std::fabs(given))) > worst_log)
        worst = &f, worst_log = std::fabs(std::log10(std::fabs(given)));
    }
    const bool spin_as_given = worst->key == &k.spin && k.spin_value != 0.0;
    return Overflow{quantity, *worst->key, spin_as_given ? k.spin_value : worst->value, underflow};
  }
  return std::nullopt;
}

const char* to_string(Spacing s) { return s == Spacing::geometric ? "geometric" : "uniform"; }
const char* to_string(FarField f) { return f == FarField::exact ? "exact" : "freestream"; }
const char* to_string(Method m) {
  return m == Method::automatic ? "auto" : m == Method::cholmod ? "cholmod" : "fft";
}
const char* to_string(StencilKind s) { return s == StencilKind::five_point ? "5-point" : "9-point"; }
const char* to_string(FlowModel m) { return m == FlowModel::potential ? "potential" : "navier-stokes"; }
const char* to_string(TimeMode m) {
  return m == TimeMode::automatic  ? "auto"
         : m == TimeMode::steady   ? "steady"
         : m == TimeMode::periodic ? "periodic"
                                   : "unsteady";
}

const std::vector<std::string>& field_names() {
  static const std::vector<std::string> names = {"psi", "u_r",       "u_theta",   "u_x",      "u_y",
                                                 "pressure", "cp", "psi_exact", "psi_error", "vorticity"};
  return names;
}

bool field_of_model(const std::string& name, FlowModel m) {
  if (name == "psi_exact" || name == "psi_error") return m == FlowModel::potential;
  if (name == "vorticity") return m == FlowModel::navier_stokes;
  return true;
}

const char* field_units(const std::string& name) {
  if (name == "psi" || name == "psi_exact" || name == "psi_error") return "m^2/s";
  if (name == "pressure") return "Pa";
  if (name == "cp") return "1";
  if (name == "vorticity") return "1/s";
  return "m/s";
}

}  // namespace magnus
