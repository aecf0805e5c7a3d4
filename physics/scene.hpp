#pragma once
// A case's parameters after defaults, overrides and range checks, SI units, split by concern the way
// the case file is: the physical scene ([cylinder], [flow], [circulation]), the grid it is solved on
// ([domain], [grid]), the solver ([solver]) and what is written ([output]). Plain data: parsing lives
// in io/, and each layer takes only the part it needs.
#include <optional>
#include <string>
#include <vector>

namespace magnus {

enum class Spacing { geometric, uniform };
enum class FarField { exact, freestream };
enum class Method { automatic, cholmod, fft };
enum class StencilKind { five_point, nine_point };

/// The physical scene: a cylinder of radius a spinning at ω in a freestream U towards +x.
struct Scene {
  double radius = 0.1;             ///< a, m
  double spin = 100.0;             ///< ω, rad/s, CCW positive
  double speed = 10.0;             ///< U, m/s, towards +x
  double density = 1.225;          ///< ρ, kg/m^3
  double pressure_inf = 0.0;       ///< p∞, Pa
  bool circulation_given = false;  ///< circulation model "given" (else "spin": Γ = 2πa²ω)
  double circulation_value = 0.0;  ///< Γ for the model "given", m^2/s

  /// Γ = 2πa²ω (spin model) or the given value, m^2/s.
  double Gamma() const;
  /// α = aω/U; 0 when U = 0 (undefined: callers that report it check U first).
  double spin_ratio() const;
};

/// The grid asked for: the domain, the spacing and the resolution (or a tolerance that picks it).
struct GridRequest {
  double outer_radius = 20.0;  ///< R/a, dimensionless
  FarField far_field = FarField::exact;
  int n_theta = 256;
  int n_r = 0;                 ///< 0: chosen from the spacing (square cells)
  Spacing spacing = Spacing::geometric;
  double tolerance = 0.0;      ///< target relative lift error; 0: the grid as given
};

/// The linear solver and the stencil.
struct SolverChoice {
  Method method = Method::automatic;
  StencilKind stencil = StencilKind::five_point;
};

/// What a run writes.
struct OutputRequest {
  std::string file = "magnus.h5";
  std::optional<std::vector<std::string>> fields;  ///< absent: all fields; [] none
};

/// One case: the four parts, its title and its resolved TOML text (stored in results).
struct Case {
  std::string title = "Spinning cylinder";
  Scene scene;
  GridRequest grid;
  SolverChoice solver;
  OutputRequest output;
  std::string source_text;  ///< resolved case as TOML
};

const char* to_string(Spacing);
const char* to_string(FarField);
const char* to_string(Method);
const char* to_string(StencilKind);

/// The (n_r, n_θ) fields a result can hold (output.fields), in file order.
const std::vector<std::string>& field_names();
/// Units of a field of that name ("m^2/s", "m/s", "Pa", "1").
const char* field_units(const std::string& name);

}  // namespace magnus
