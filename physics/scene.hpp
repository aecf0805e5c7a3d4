#pragma once
// A case's parameters after defaults, overrides and range checks, SI units, split by concern the way
// the case file is: the physical scene ([cylinder], [flow], [circulation]), the grid it is solved on
// ([domain], [grid]), the solver ([solver]) and what is written ([output]). Plain data: parsing lives
// in io/, and each layer takes only the part it needs.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace magnus {

enum class Spacing { geometric, uniform };
enum class FarField { exact, freestream };
enum class Method { automatic, cholmod, fft };
enum class StencilKind { five_point, nine_point };
/// The fluid model: ideal (inviscid, irrotational) or 2D laminar Navier–Stokes.
enum class FlowModel { potential, navier_stokes };
/// How a navier-stokes case is run: "auto" (march in time; stop when steady or periodic), "steady"
/// (Newton's method on the discrete steady equations), "unsteady" (march to time.end or converged
/// periodic means), "periodic" (a short march, then the shedding orbit by Newton–GMRES shooting).
enum class TimeMode { automatic, steady, unsteady, periodic };

/// The physical scene: a cylinder of radius a spinning at ω in a freestream U. The solve is done in the wind
/// frame (freestream towards +x'); the world frame is the wind frame turned CCW by the direction β.
struct Scene {
  double radius = 0.1;             ///< a, m
  double spin = 100.0;             ///< ω, rad/s, CCW positive
  double speed = 10.0;             ///< U, m/s, towards +x
  double density = 1.225;          ///< ρ, kg/m^3
  double pressure_inf = 0.0;       ///< p∞, Pa
  bool circulation_given = false;  ///< circulation model "given" (else "spin": Γ = 2πa²ω)
  double circulation_value = 0.0;  ///< Γ for the model "given", m^2/s
  double viscosity = 0.0;          ///< ν, m^2/s (kinematic); 0: not given (potential flow only)
  bool reynolds_given = false;  ///< flow.reynolds was given: ν = U·2a/Re (else flow.viscosity or neither)
  double reynolds_value = 0.0;  ///< Re as given in flow.reynolds (echoed as given), else 0
  double direction_deg = 0.0;   ///< β, deg CCW from +x: the world direction the freestream flows towards
  std::optional<double>
      course_deg;                   ///< c, deg CCW from +x: the way the ship moves (rotor sail); absent: none
  double span = 0.0;                ///< b, m: the cylinder's length for total forces; 0: not given
  std::optional<double> rpm_given;  ///< cylinder.rpm as given, rev/min (echoed as given); absent: not rpm

  /// Γ = 2πa²ω (spin model) or the given value, m^2/s.
  double Gamma() const;
  /// α = aω/U; 0 when U = 0 (undefined: callers that report it check U first).
  double spin_ratio() const;
  /// Re = U·2a/ν, or flow.reynolds exactly as given (U·2a/ν of the ν it sets reads 200.00000000000003 for
  /// 200); 0 when ν or U is 0 (undefined: callers check viscosity and speed first).
  double reynolds() const;
  /// The reference speed of the time unit and the coefficients' dynamic pressure: U, or the wall speed
  /// a|ω| when U = 0 (a spinning cylinder in still fluid), m/s.
  double reference_speed() const;
  /// The convective time unit D/U_ref = 2a/U_ref (U_ref = reference_speed()), s.
  double time_unit() const;
  /// The spin in revolutions per minute, ω·60/(2π), 1/min.
  double rpm() const;
};

/// A force per unit span (drag D along the freestream, lift L across it, CCW of it) in the world frame:
/// F_x = D cos β − L sin β, F_y = D sin β + L cos β (β = direction), N/m.
struct WorldForce {
  double x = 0.0, y = 0.0;  ///< N/m
};
WorldForce world_force(double drag, double lift, double direction_deg);

/// A rotor sail's forces per unit span along its course c: thrust T = F·ĉ = D cos φ − L sin φ (positive
/// ahead) and side force S = F·(ẑ × ĉ) = D sin φ + L cos φ (positive to port, i.e. CCW of the course),
/// φ = β − c the freestream's angle from the course, N/m.
struct CourseForce {
  double thrust = 0.0, side = 0.0;  ///< N/m
};
CourseForce course_force(double drag, double lift, double direction_deg, double course_deg);

/// (x, y) turned CCW by `deg` degrees: (x cos − y sin, x sin + y cos); exact for multiples of 90°.
WorldForce rotate_deg(double x, double y, double deg);

/// The navier-stokes rings' clustering at the wall (grid.wall_refinement = Δξ_far/Δξ_wall, 1: uniform ξ)
/// and the ξ-length over which the spacing relaxes to the far one (grid.wall_layer).
constexpr double kNsDefaultWallRefinement = 1.0;
constexpr double kNsDefaultWallLayer = 0.1;

/// The grid asked for: the domain, the spacing and the resolution (or a tolerance that picks it).
struct GridRequest {
  double outer_radius = 20.0;  ///< R/a, dimensionless
  FarField far_field = FarField::exact;
  int n_theta = 256;
  int n_r = 0;  ///< 0: chosen from the spacing (square cells)
  Spacing spacing = Spacing::geometric;
  bool spacing_given = false;  ///< grid.spacing was stated (file or --set): a tolerance search keeps it
  double tolerance = 0.0;      ///< target relative lift error; 0: the grid as given
  double wall_refinement = kNsDefaultWallRefinement;  ///< Δξ_far/Δξ_wall ≥ 1 (navier-stokes only)
  double wall_layer = kNsDefaultWallLayer;  ///< ξ-length of the spacing's transition (navier-stokes only)
  bool n_theta_given = false;  ///< grid.n_theta was stated: navier-stokes then takes it instead of its rule
  double refine = 1.0;         ///< navier-stokes: the scene's grid refined by this factor (n_θ·f, Δξ/f)
  /// navier-stokes with grid.tolerance: the refine factor the tolerance search solved on (not a key); 0:
  /// the design grid, refine·√(2·0.01/τ)
  double refine_solved = 0.0;
  bool wall_refinement_given = false;  ///< grid.wall_refinement was stated (navier-stokes)
  bool wall_layer_given = false;       ///< grid.wall_layer was stated (navier-stokes)
  /// navier-stokes: where the absorbing layer begins, r_s/a (domain.absorbing_layer; 0: none), and its
  /// sink at R, λ_R in U_ref/D (domain.absorbing_strength): λ(r) = λ_R·((r − r_s)/(R − r_s))² beyond r_s.
  double absorbing_layer = 0.0;
  double absorbing_strength = 2.0;
};

/// The linear solver and the stencil (potential flow); the advection's order in θ (navier-stokes).
struct SolverChoice {
  Method method = Method::automatic;
  StencilKind stencil = StencilKind::five_point;
  int advection_order = 2;     ///< 2 (Arakawa's Jacobian) or 4 (fourth order in θ), navier-stokes only
  int advection_order_xi = 2;  ///< 2 or 4 (fourth order in ξ, the wake's streamwise direction), likewise
  std::string wall_closure = "thom";  ///< the no-slip row for ζ_w: "thom" (first order) or "jensen" (second)
  bool implicit_rotation = true;  ///< the wall's spin by Crank–Nicolson (false: all advection by AB2), likewise
};

/// The navier-stokes model's defaults where they differ from potential flow's: the wake needs a far
/// outer boundary (R/a) and the boundary layer fewer θ points than potential flow's round-off accuracy.
constexpr double kNsDefaultOuterRadius = 100.0;
constexpr int kNsDefaultNTheta = 192;
/// The finest grid.tolerance navier-stokes takes: four digits (the companion run's estimate, and the
/// converged periodic means, are not reliable below it).
constexpr double kNsMinTolerance = 1e-4;

/// Time marching of a navier-stokes case ([time]). Times are in convective units D/U_ref, D = 2a,
/// U_ref = Scene::reference_speed().
/// The most time steps a navier-stokes run may take: ten million (usual runs take a few thousand to a hundred
/// thousand; each step keeps a sample of the force history, 64 bytes). time.end/time.dt above it is refused.
constexpr double kNsMaxSteps = 1e7;

struct TimeRequest {
  TimeMode mode = TimeMode::automatic;
  double end = 300.0;                 ///< t_end, D/U_ref, > 0
  double dt = 0.0;                    ///< Δt, D/U_ref; 0: from the CFL number
  double cfl = 0.7;                   ///< target CFL number, (0, 0.8]
  double mean_tolerance = 1e-3;       ///< stop when the last periods' means of C_L, C_D agree to this (relative above 1)
  /// …and the drift still to come of those means (the trend of the last four) is below it too; false: stop on
  /// agreement alone, as before the drift rule (cheaper, but a slow monotone drift passes as converged).
  bool stop_on_drift = true;
  double checkpoint_interval = 10.0;  ///< checkpoint every this many D/U_ref; 0: none
};

/// What a run writes.
struct OutputRequest {
  std::string file = "magnus.h5";
  std::optional<std::vector<std::string>> fields;  ///< absent: all fields; [] none
  int compression = 0;                             ///< gzip level of the large datasets, 0 (none) … 9
  int snapshots = 0;                ///< navier-stokes: keep the last N states for an XDMF time series
  double snapshot_interval = 0.25;  ///< between snapshots, D/U_ref, > 0
};

/// One case: the parts, its title and its resolved TOML text (stored in results).
struct Case {
  std::string title = "Spinning cylinder";
  FlowModel model = FlowModel::potential;
  Scene scene;
  TimeRequest time;  ///< navier-stokes only
  GridRequest grid;
  SolverChoice solver;
  OutputRequest output;
  std::string source_text;  ///< resolved case as TOML
};

/// A derived quantity of a scene that is not finite in double precision, and the input to blame for it.
struct Overflow {
  std::string quantity;  ///< e.g. "U²", "ρU²", "the seed ΔP = 2ρUaω"
  std::string key;       ///< the case key of the input with the largest |log10| among the quantity's factors
  double value = 0.0;    ///< that input's value (SI)
  bool underflow = false;  ///< the quantity is below the smallest normal double (else it is not finite)
};

/// The case-file keys the scene's inputs came from (spin: "cylinder.spin", ".spin_ratio" or ".rpm").
struct SceneKeys {
  std::string radius = "cylinder.radius", spin = "cylinder.spin", speed = "flow.speed",
              density = "flow.density", pressure = "flow.pressure", circulation = "circulation.value",
              viscosity = "flow.viscosity", reynolds = "flow.reynolds", span = "cylinder.span";
  double spin_value = 0.0;  ///< the value given for `spin` in its own units (α, rev/min); 0: ω itself
};

/// The first of Γ, α = aω/U, U², ρU², ½ρU²·2a, Γ, ρUΓ, the seed ΔP = 2ρUaω, 4ρUΓ/(2πa), F_seed = 4ρUa²ω, S =
/// 2πρa², the surface speed 2U + |Γ|/(2πa) and pressure p∞ ± ½ρ(2U + |Γ|/(2πa))², and ψ(R) ≈ U·R +
/// |Γ|/(2π)·ln(R/a) (R = outer_radius·a), C_L = −Γ/(Ua), the free stagnation radius |Γ|/(2πU) and, when a
/// viscosity is given, ν = U·2a/Re (from flow.reynolds) or the Reynolds number U_ref·2a/ν (from
/// flow.viscosity, U_ref = reference_speed()), and with a span b the total lift ρUΓ·b, that is not finite, or
/// that a product of non-zero inputs underflows below the smallest normal double; empty if none.
std::optional<Overflow> find_overflow(const Scene& s, double outer_radius, const SceneKeys& keys = {});

const char* to_string(Spacing);
const char* to_string(FarField);
const char* to_string(Method);
const char* to_string(StencilKind);
const char* to_string(FlowModel);  ///< "potential" | "navier-stokes"
const char* to_string(TimeMode);   ///< "auto" | "steady" | "unsteady" | "periodic"

/// The (n_r, n_θ) fields a result can hold (output.fields), in file order; psi_exact and psi_error are
/// potential flow's, vorticity the navier-stokes model's.
const std::vector<std::string>& field_names();
/// Whether a model computes the field: psi_exact, psi_error are potential flow's, vorticity is
/// navier-stokes's, the others both's.
bool field_of_model(const std::string& name, FlowModel m);
/// Units of a field of that name ("m^2/s", "m/s", "Pa", "1", "1/s").
const char* field_units(const std::string& name);

/// The boundary layer's thickness over the radius, δ/a = 2/√(Re(1 + α²)) (δ = D/√(Re(1 + α²)): spin thins it
/// where the wall moves against the stream), dimensionless; Re = U·2a/ν (or a|ω|·2a/ν in still fluid, α = 0).
inline double boundary_layer_over_a(double reynolds, double alpha) {
  return 2.0 / std::sqrt(reynolds * (1.0 + alpha * alpha));
}

}  // namespace magnus
