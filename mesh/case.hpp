#pragma once
// Resolved parameters of one flow case, SI units. Plain data: parsing lives in app/.
#include <optional>
#include <string>
#include <vector>

namespace magnus {

enum class Spacing { geometric, uniform };
enum class FarField { exact, freestream };
enum class Method { automatic, cholmod, fft };
enum class StencilKind { five_point, nine_point };

/// All parameters of a scene after defaults, overrides and range checks.
struct Case {
  std::string title = "Spinning cylinder";
  double radius = 0.1;          ///< a, m
  double spin = 100.0;          ///< ω, rad/s, CCW positive
  double speed = 10.0;          ///< U, m/s, towards +x
  double density = 1.225;       ///< ρ, kg/m^3
  double pressure_inf = 0.0;    ///< p∞, Pa
  bool circulation_given = false;  ///< model "given" (else "spin": Γ = 2πa²ω)
  double circulation_value = 0.0;  ///< Γ for model "given", m^2/s
  double outer_radius = 20.0;   ///< R/a, dimensionless
  FarField far_field = FarField::exact;
  int n_theta = 256;
  int n_r = 0;                  ///< 0: chosen from the spacing (square cells)
  Spacing spacing = Spacing::geometric;
  double tolerance = 0.0;       ///< target relative lift error; 0: grid as given
  Method method = Method::automatic;
  StencilKind stencil = StencilKind::five_point;
  std::string output_file = "magnus.h5";
  std::optional<std::vector<std::string>> output_fields;  ///< absent: all fields; [] none
  std::string source_text;      ///< resolved case as TOML, stored in results

  /// Γ = 2πa²ω (spin model) or the given value, m^2/s.
  double circulation() const;
  /// α = aω/U; 0 when U = 0.
  double spin_ratio() const;
};

const char* to_string(Spacing);
const char* to_string(FarField);
const char* to_string(Method);
const char* to_string(StencilKind);

}  // namespace magnus
