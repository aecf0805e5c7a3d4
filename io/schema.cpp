#include "io/schema.hpp"

#include <cmath>

#include "io/schema_build.hpp"

namespace magnus {

namespace {

using namespace schema_build;

std::vector<AttrSpec> make_attributes() {
  const char* P = "/parameters";
  const char* F = "/forces";
  const char* E = "/errors";
  const char* T = "/timing";
  std::vector<AttrSpec> table = {
      text("/", "format", "\"magnus-flow\"", [](const FlowResult&) { return std::string("magnus-flow"); }),
      integer("/", "format_version", "version of this layout; readers accept 1 and 2",
              [](const FlowResult&) { return opt(double(kFlowFormatVersion)); }),
      text("/", "software_version", "magnus version that wrote the file",
           [](const FlowResult&) { return std::string(MAGNUS_VERSION); }),
      text(
          "/", "model", "flow model: potential or navier-stokes",
          [](const FlowResult& r) { return std::string(to_string(r.c.model)); },
          [](FlowResult& r, const std::string& v) {
            r.c.model = v == "navier-stokes" ? FlowModel::navier_stokes : FlowModel::potential;
          }),
      only(Models::viscous,
           text(
               "/", "status", "why the navier-stokes run stopped",
               [](const FlowResult& r) { return r.viscous ? r.viscous->status : std::string(); },
               [](FlowResult& r, const std::string& v) { vis(r).status = v; })),
      only(Models::viscous,
           integer(
               "/", "partial", "1: interrupted or stopped on an error before its end (a partial result)",
               [](const FlowResult& r) { return opt(r.viscous && r.viscous->partial ? 1.0 : 0.0); },
               [](FlowResult& r, double v) { vis(r).partial = v != 0.0; })),
      text(
          "/", "case", "the resolved case as TOML", [](const FlowResult& r) { return r.c.source_text; },
          [](FlowResult& r, const std::string& v) { r.c.source_text = v; }),
      text(
          "/", "title", "the case's title", [](const FlowResult& r) { return r.c.title; },
          [](FlowResult& r, const std::string& v) { r.c.title = v; }),

      num(
          P, "radius", "m", "cylinder radius a", [](const FlowResult& r) { return opt(r.c.scene.radius); },
          [](FlowResult& r, double v) { r.c.scene.radius = v; }),
      num(
          P, "spin", "rad/s", "spin ω, counter-clockwise positive",
          [](const FlowResult& r) { return opt(r.c.scene.spin); },
          [](FlowResult& r, double v) { r.c.scene.spin = v; }),
      num(P, "spin_ratio", "1", "spin ratio α = aω/U (undefined when U = 0)",
          [](const FlowResult& r) {
            return r.c.scene.speed > 0.0 ? opt(r.c.scene.spin_ratio()) : std::nullopt;
          }),
      num(
          P, "speed", "m/s", "freestream speed U (towards the direction)",
          [](const FlowResult& r) { return opt(r.c.scene.speed); },
          [](FlowResult& r, double v) { r.c.scene.speed = v; }),
      num(
          P, "density", "kg/m^3", "fluid density ρ",
          [](const FlowResult& r) { return opt(r.c.scene.density); },
          [](FlowResult& r, double v) { r.c.scene.density = v; }),
      num(
          P, "pressure_inf", "Pa", "freestream pressure p∞",
          [](const FlowResult& r) { return opt(r.c.scene.pressure_inf); },
          [](FlowResult& r, double v) { r.c.scene.pressure_inf = v; }),
      num(
          P, "circulation", "m^2/s", "circulation Γ (2πa²ω for the spin model)",
          [](const FlowResult& r) { return opt(r.c.scene.Gamma()); },
          [](FlowResult& r, double v) { r.c.scene.circulation_value = v; }),
      text(
          P, "circulation_model", "\"spin\" (Γ = 2πa²ω) or \"given\"",
          [](const FlowResult& r) { return std::string(r.c.scene.circulation_given ? "given" : "spin"); },
          [](FlowResult& r, const std::string& v) { r.c.scene.circulation_given = v == "given"; }),
      num(P, "outer_radius", "1", "outer radius of the grid over a, R/a (as built)",
          [](const FlowResult& r) { return opt(r.grid.outer_radius() / r.grid.a); }),
      num(
          P, "outer_radius_requested", "1", "outer radius over a asked for by the case",
          [](const FlowResult& r) { return opt(r.c.grid.outer_radius); },
          [](FlowResult& r, double v) { r.c.grid.outer_radius = v; }),
      text(
          P, "far_field", "far-field condition: exact or freestream",
          [](const FlowResult& r) { return std::string(to_string(r.c.grid.far_field)); },
          [](FlowResult& r, const std::string& v) {
            r.c.grid.far_field = v == "freestream" ? FarField::freestream : FarField::exact;
          }),
      text(
          P, "spacing", "radial spacing: geometric or uniform",
          [](const FlowResult& r) { return std::string(to_string(r.c.grid.spacing)); },
          [](FlowResult& r, const std::string& v) {
            r.c.grid.spacing = v == "uniform" ? Spacing::uniform : Spacing::geometric;
          }),
      integer(P, "n_r", "radial grid points", [](const FlowResult& r) { return opt(double(r.grid.n_r)); }),
      integer(P, "n_theta", "angular grid points",
              [](const FlowResult& r) { return opt(double(r.grid.n_theta)); }),
      text(
          P, "method", "linear solver that ran: fft or cholmod",
          [](const FlowResult& r) { return r.info.method; },
          [](FlowResult& r, const std::string& v) { r.info.method = v; }),
      text(
          P, "stencil", "finite-difference stencil: 5-point or 9-point",
          [](const FlowResult& r) { return std::string(to_string(r.c.solver.stencil)); },
          [](FlowResult& r, const std::string& v) {
            r.c.solver.stencil = v == "9-point" ? StencilKind::nine_point : StencilKind::five_point;
          }),

      row(num(
              F, "lift", "N/m", "lift F_y per unit span, numeric",
              [](const FlowResult& r) { return opt(r.forces.lift); },
              [](FlowResult& r, double v) { r.forces.lift = v; }),
          "lift F_y (N/m)", "lift_N_m", "{:.10g}"),
      row(num(
              F, "drag", "N/m", "drag F_x per unit span, numeric",
              [](const FlowResult& r) { return opt(r.forces.drag); },
              [](FlowResult& r, double v) { r.forces.drag = v; }),
          "drag F_x (N/m)", "drag_N_m", "{:.3g}"),
      row(num(
              F, "cl", "1", "lift coefficient F_y/(½ρU²·2a) (undefined when U = 0)",
              [](const FlowResult& r) { return r.forces.cl; },
              [](FlowResult& r, double v) { r.forces.cl = v; }),
          "C_L numeric", "cl", "{:.10g}"),
      row(num(
              F, "cd", "1", "drag coefficient F_x/(½ρU²·2a) (undefined when U = 0)",
              [](const FlowResult& r) { return r.forces.cd; },
              [](FlowResult& r, double v) { r.forces.cd = v; }),
          "C_D", "cd", "{:.3e}"),
      row(num(
              F, "cl_kutta_joukowski", "1", "Kutta–Joukowski lift coefficient −Γ/(Ua)",
              [](const FlowResult& r) { return r.forces.cl_kutta_joukowski; },
              [](FlowResult& r, double v) { r.forces.cl_kutta_joukowski = v; }),
          "C_L Kutta–Joukowski", "cl_kutta_joukowski", "{:.10g}"),
      row(num(
              F, "cl_seed_estimate", "1", "seed estimate of the lift coefficient −4aω/U",
              [](const FlowResult& r) { return r.forces.cl_seed_estimate; },
              [](FlowResult& r, double v) { r.forces.cl_seed_estimate = v; }),
          "C_L seed estimate", "cl_seed_estimate", "{:.10g}"),
      num(
          F, "lift_kutta_joukowski", "N/m", "Kutta–Joukowski lift −ρUΓ",
          [](const FlowResult& r) { return opt(r.forces.lift_kutta_joukowski); },
          [](FlowResult& r, double v) { r.forces.lift_kutta_joukowski = v; }),
      row(num(
              F, "delta_p_top_bottom", "Pa", "p(a, 90°) − p(a, 270°), numeric",
              [](const FlowResult& r) { return opt(r.forces.delta_p_top_bottom); },
              [](FlowResult& r, double v) { r.forces.delta_p_top_bottom = v; }),
          "ΔP top−bottom (Pa)", "delta_p_top_bottom_Pa", "{:.8g}"),
      num(
          F, "delta_p_top_bottom_exact", "Pa", "exact top − bottom pressure difference 4ρUΓ/(2πa)",
          [](const FlowResult& r) { return opt(r.forces.delta_p_top_bottom_exact); },
          [](FlowResult& r, double v) { r.forces.delta_p_top_bottom_exact = v; }),
      row(num(
              F, "delta_p_seed_estimate", "Pa", "seed estimate of the pressure difference 2ρUaω",
              [](const FlowResult& r) { return opt(r.forces.delta_p_seed_estimate); },
              [](FlowResult& r, double v) { r.forces.delta_p_seed_estimate = v; }),
          "ΔP seed 2ρUaω (Pa)", "delta_p_seed_estimate_Pa", "{:.8g}"),
      num(
          F, "circulation_measured", "m^2/s", "∮ u_θ a dθ on the body, numeric",
          [](const FlowResult& r) { return opt(r.forces.circulation_measured); },
          [](FlowResult& r, double v) { r.forces.circulation_measured = v; }),
      num(
          F, "magnus_S", "kg/m", "Magnus coefficient S = −F_y/(Uω) (undefined when U = 0 or ω = 0)",
          [](const FlowResult& r) { return r.forces.magnus_S; },
          [](FlowResult& r, double v) { r.forces.magnus_S = v; }),
      num(
          F, "magnus_S_exact", "kg/m",
          "exact Magnus coefficient: 2πρa² (spin model), ρΓ/ω (given Γ; undefined when ω = 0)",
          [](const FlowResult& r) { return r.forces.magnus_S_exact; },
          [](FlowResult& r, double v) { r.forces.magnus_S_exact = v; }),

      row(num(
              E, "psi_max_rel", "1", "max|ψ − ψ_exact| / max|ψ_exact|",
              [](const FlowResult& r) { return opt(r.errors.psi_max_rel); },
              [](FlowResult& r, double v) { r.errors.psi_max_rel = v; }),
          "error ψ max rel", "psi_max_rel", "{:.3e}"),
      row(num(
              E, "cp_surface_max_abs", "1", "max|Cp − Cp_exact| on r = a (undefined when U = 0)",
              [](const FlowResult& r) { return r.errors.cp_surface_max_abs; },
              [](FlowResult& r, double v) { r.errors.cp_surface_max_abs = v; }),
          "error Cp surface max abs", "cp_surface_max_abs", "{:.3e}"),
      row(num(
              E, "cl_rel", "1", "|F_y − F_y,KJ| / |F_y,KJ|; when Γ = 0, |F_y|/(ρU²a) (undefined when U = 0)",
              [](const FlowResult& r) { return r.errors.cl_rel; },
              [](FlowResult& r, double v) { r.errors.cl_rel = v; }),
          "error C_L rel", "cl_rel", "{:.3e}"),
      num(
          E, "circulation_rel", "1", "|Γ_measured − Γ| / |Γ| (over 2πaU when Γ = 0)",
          [](const FlowResult& r) { return opt(r.errors.circulation_rel); },
          [](FlowResult& r, double v) { r.errors.circulation_rel = v; }),
      num(
          E, "cl_rel_estimated", "1", "a-posteriori estimate of cl_rel (tolerance mode only)",
          [](const FlowResult& r) {
            return r.info.estimated_cl_rel >= 0.0 ? opt(r.info.estimated_cl_rel) : std::nullopt;
          },
          [](FlowResult& r, double v) { r.info.estimated_cl_rel = v; }),

      row(num(
              T, "total_s", "s", "wall clock, whole run",
              [](const FlowResult& r) { return opt(r.timing.total_s); },
              [](FlowResult& r, double v) { r.timing.total_s = v; }),
          "time total (s)", "total_s", "{:.3g}"),
      num(
          T, "assemble_s", "s", "wall clock, assembling",
          [](const FlowResult& r) { return opt(r.timing.assemble_s); },
          [](FlowResult& r, double v) { r.timing.assemble_s = v; }),
      num(
          T, "factor_s", "s", "wall clock, factorization",
          [](const FlowResult& r) { return opt(r.timing.factor_s); },
          [](FlowResult& r, double v) { r.timing.factor_s = v; }),
      num(
          T, "solve_s", "s", "wall clock, solving", [](const FlowResult& r) { return opt(r.timing.solve_s); },
          [](FlowResult& r, double v) { r.timing.solve_s = v; }),
      num(
          T, "postproc_s", "s", "wall clock, post-processing",
          [](const FlowResult& r) { return opt(r.timing.postproc_s); },
          [](FlowResult& r, double v) { r.timing.postproc_s = v; }),
  };
  // Potential flow's own entries: its solvers and the errors against its exact solution.
  for (AttrSpec& a : table) {
    const std::string g = a.group, n = a.name;
    if (g == E || (g == P && (n == "far_field" || n == "method" || n == "stencil" || n == "circulation_model")))
      a.models = Models::potential;
  }
  // The scene's world placement and engineering forces, each after the last entry of its group.
  for (const AttrSpec& a : scene_attributes()) {
    auto at = table.end();
    for (auto it = table.begin(); it != table.end(); ++it)
      if (std::string(it->group) == a.group) at = it + 1;
    table.insert(at, a);
  }
  const std::vector<AttrSpec> viscous = viscous_attributes();
  table.insert(table.end(), viscous.begin(), viscous.end());
  return table;
}

using Member = std::vector<double> Fields::*;

DatasetSpec field(const char* name, const char* units, const char* description, Member m) {
  return {std::string("/fields/") + name,
          units,
          description,
          DataShape::grid,
          [m](const FlowResult& r) { return r.fields.*m; },
          [m](FlowResult& r, std::vector<double> v) { r.fields.*m = std::move(v); }};
}

using SurfaceMember = std::vector<double> Surface::*;

DatasetSpec surface(const char* name, const char* units, const char* description, SurfaceMember m) {
  return {std::string("/surface/") + name,
          units,
          description,
          DataShape::n_theta,
          [m](const FlowResult& r) { return r.surface.*m; },
          [m](FlowResult& r, std::vector<double> v) { r.surface.*m = std::move(v); }};
}

/// The world x or y of each node, row-major (n_r, n_θ): (r cos θ, r sin θ) of the wind frame turned by the
/// direction β (exactly r cos θ, r sin θ when β = 0).
std::vector<double> coordinate(const PolarGrid& g, bool y, double direction_deg) {
  std::vector<double> v(size_t(g.n_r) * size_t(g.n_theta));
  for (size_t i = 0; i < size_t(g.n_r); ++i)
    for (size_t j = 0; j < size_t(g.n_theta); ++j) {
      const WorldForce p = rotate_deg(g.r[i] * std::cos(g.theta[j]), g.r[i] * std::sin(g.theta[j]), direction_deg);
      v[i * size_t(g.n_theta) + j] = y ? p.y : p.x;
    }
  return v;
}

/// u_x (y false) or u_y of the world frame: the wind-frame components turned by the direction β. Read back,
/// the pair is turned back (when u_y arrives after u_x), so that a result in memory is in the wind frame.
DatasetSpec world_velocity(const char* name, const char* description, bool y) {
  return {std::string("/fields/") + name,
          "m/s",
          description,
          DataShape::grid,
          [y](const FlowResult& r) {
            const double beta = r.c.scene.direction_deg;
            const auto &ux = r.fields.u_x, &uy = r.fields.u_y;
            if (beta == 0.0 || ux.size() != uy.size()) return y ? uy : ux;
            std::vector<double> v(ux.size());
            for (size_t q = 0; q < v.size(); ++q) {
              const WorldForce w = rotate_deg(ux[q], uy[q], beta);
              v[q] = y ? w.y : w.x;
            }
            return v;
          },
          [y](FlowResult& r, std::vector<double> v) {
            (y ? r.fields.u_y : r.fields.u_x) = std::move(v);
            auto &ux = r.fields.u_x, &uy = r.fields.u_y;
            const double beta = r.c.scene.direction_deg;
            if (!y || beta == 0.0 || ux.size() != uy.size()) return;
            for (size_t q = 0; q < ux.size(); ++q) {
              const WorldForce w = rotate_deg(ux[q], uy[q], -beta);
              ux[q] = w.x, uy[q] = w.y;
            }
          }};
}

DatasetSpec stagnation(const char* name, const char* units, const char* description, bool exact, bool theta) {
  return {std::string("/stagnation/") + name,
          units,
          description,
          DataShape::points,
          [exact, theta](const FlowResult& r) {
            std::vector<double> v;
            for (const auto& p : exact ? r.stagnation_exact : r.stagnation)
              v.push_back(theta ? p.theta : p.r);
            return v;
          },
          {}};
}

/// One column of the force history (one value per step).
DatasetSpec history(const char* name, const char* units, const char* description, double ForceSample::*m) {
  return {std::string("/history/") + name, units, description, DataShape::steps,
          [m](const FlowResult& r) {
            std::vector<double> v;
            if (r.viscous)
              for (const ForceSample& f : r.viscous->history) v.push_back(f.*m);
            return v;
          },
          [m](FlowResult& r, std::vector<double> v) {
            auto& h = vis(r).history;
            h.resize(v.size());
            for (size_t q = 0; q < v.size(); ++q) h[q].*m = v[q];
          },
          Models::viscous};
}

/// One dataset of the stored states (output.snapshots): their times (member null) or one field of each,
/// flattened (N·n_r·n_θ). Written and read by the writer and reader themselves (shape (N, n_r, n_θ)).
DatasetSpec snapshot(const char* name, const char* units, const char* description,
                     std::vector<double> Snapshot::*m) {
  return {std::string("/snapshots/") + name,
          units,
          description,
          DataShape::points,
          [m](const FlowResult& r) {
            std::vector<double> v;
            if (r.viscous)
              for (const Snapshot& s : r.viscous->snapshots) {
                if (m)
                  v.insert(v.end(), (s.*m).begin(), (s.*m).end());
                else
                  v.push_back(s.t);
              }
            return v;
          },
          {},
          Models::viscous};
}

std::vector<DatasetSpec> make_datasets() {
  return {
      {"/grid/r", "m", "radius r_i of grid row i (dimension scale of every field's first axis)",
       DataShape::n_r, [](const FlowResult& r) { return r.grid.r; },
       [](FlowResult& r, std::vector<double> v) { r.grid.r = std::move(v); }},
      {"/grid/theta", "rad",
       "angle θ_j of grid column j from the freestream direction, counter-clockwise (wind frame; dimension scale)",
       DataShape::n_theta, [](const FlowResult& r) { return r.grid.theta; },
       [](FlowResult& r, std::vector<double> v) { r.grid.theta = std::move(v); }},
      {"/grid/x",
       "m",
       "world x of each node: r cos(θ + direction)",
       DataShape::grid,
       [](const FlowResult& r) { return coordinate(r.grid, false, r.c.scene.direction_deg); },
       {}},
      {"/grid/y",
       "m",
       "world y of each node: r sin(θ + direction)",
       DataShape::grid,
       [](const FlowResult& r) { return coordinate(r.grid, true, r.c.scene.direction_deg); },
       {}},
      field("psi", "m^2/s", "stream function ψ", &Fields::psi),
      field("u_r", "m/s", "radial velocity u_r = (1/r) ∂ψ/∂θ", &Fields::u_r),
      field("u_theta", "m/s", "angular velocity u_θ = −∂ψ/∂r", &Fields::u_theta),
      world_velocity("u_x", "velocity component along the world +x", false),
      world_velocity("u_y", "velocity component along the world +y", true),
      field("pressure", "Pa", "pressure p = p∞ + ½ρ(U² − |u|²)", &Fields::pressure),
      field("cp", "1", "pressure coefficient (p − p∞)/(½ρU²) (undefined when U = 0)", &Fields::cp),
      only(Models::potential,
           field("psi_exact", "m^2/s", "exact stream function on the same grid", &Fields::psi_exact)),
      only(Models::potential, field("psi_error", "m^2/s", "ψ − ψ_exact", &Fields::psi_error)),
      only(Models::viscous, field("vorticity", "1/s", "vorticity ζ = −∇²ψ", &Fields::vorticity)),
      surface("theta", "rad", "angle of the body points (= /grid/theta)", &Surface::theta),
      surface("u_theta", "m/s", "velocity on the body r = a", &Surface::u_theta),
      surface("pressure", "Pa", "pressure on the body", &Surface::pressure),
      surface("cp", "1", "pressure coefficient on the body (undefined when U = 0)", &Surface::cp),
      only(Models::potential,
           surface("cp_exact", "1", "exact pressure coefficient on the body (undefined when U = 0)",
                   &Surface::cp_exact)),
      only(Models::viscous,
           surface("shear_stress", "Pa", "wall shear stress τ_w = μ(ζ_w − 2ω)", &Surface::shear_stress)),
      only(Models::potential,
           stagnation("r", "m", "radius of each stagnation point, numeric (sorted by θ)", false, false)),
      only(Models::potential,
           stagnation("theta", "rad", "angle of each stagnation point from the freestream direction, numeric, in [0, 2π)", false, true)),
      only(Models::potential,
           stagnation("r_exact", "m", "radius of each stagnation point, exact", true, false)),
      only(Models::potential,
           stagnation("theta_exact", "rad", "angle of each stagnation point from the freestream direction, exact, in [0, 2π)", true, true)),
      only(Models::viscous, {"/separation/theta",
                             "rad",
                             "angles where the wall shear stress changes sign (separation, reattachment)",
                             DataShape::points,
                             [](const FlowResult& r) {
                               return r.viscous ? r.viscous->separation : std::vector<double>();
                             },
                             [](FlowResult& r, std::vector<double> v) { vis(r).separation = std::move(v); }}),
      history("t", "s", "time of each step", &ForceSample::t),
      {"/history/t_convective", "1", "time of each step in convective units D/U", DataShape::steps,
       [](const FlowResult& r) {
         std::vector<double> v;
         if (r.viscous)
           for (const ForceSample& f : r.viscous->history) v.push_back(f.t / r.viscous->time_unit);
         return v;
       },
       {}, Models::viscous},
      history("cl", "1", "lift coefficient", &ForceSample::C_L),
      history("cd", "1", "drag coefficient", &ForceSample::C_D),
      history("cm", "1", "torque coefficient", &ForceSample::C_M),
      history("lift", "N/m", "lift per unit span", &ForceSample::F_y),
      history("drag", "N/m", "drag per unit span", &ForceSample::F_x),
      history("torque", "N*m/m", "torque per unit span", &ForceSample::M),
      snapshot("t", "s", "time of each stored state (output.snapshots), oldest first", nullptr),
      snapshot("psi", "m^2/s", "stream function ψ of each stored state, (N, n_r, n_theta)", &Snapshot::psi),
      snapshot("vorticity", "1/s", "vorticity ζ of each stored state, (N, n_r, n_theta)",
               &Snapshot::vorticity),
  };
}

}  // namespace

bool applies(Models m, const FlowResult& r) {
  return m == Models::all || (m == Models::viscous) == r.viscous.has_value();
}

const std::vector<AttrSpec>& result_attributes() {
  static const std::vector<AttrSpec> table = make_attributes();
  return table;
}

const std::vector<DatasetSpec>& result_datasets() {
  static const std::vector<DatasetSpec> table = make_datasets();
  return table;
}

std::vector<const DatasetSpec*> field_datasets() {
  std::vector<const DatasetSpec*> out;
  for (const auto& d : result_datasets())
    if (d.path.rfind("/fields/", 0) == 0) out.push_back(&d);
  return out;
}

const AttrSpec* find_attribute(const std::string& group, const std::string& name) {
  for (const auto& a : result_attributes())
    if (group == a.group && name == a.name) return &a;
  return nullptr;
}

const DatasetSpec* find_dataset(const std::string& path) {
  for (const auto& d : result_datasets())
    if (d.path == path) return &d;
  return nullptr;
}

std::string dataset_units(const std::string& path) {
  if (const DatasetSpec* d = find_dataset(path)) return d->units;
  if (path == "/mesh/points") return "m";
  if (path == "/mesh/quads") return "1";
  if (path == "/mesh/velocity") return "m/s";
  // The views of one stored state: /mesh/snapshots/FIELD/K is state K of /snapshots/FIELD.
  if (path.rfind("/mesh/snapshots/", 0) == 0) {
    const std::string rest = path.substr(5);
    return dataset_units(rest.substr(0, rest.rfind('/')));
  }
  if (path.rfind("/mesh/", 0) == 0)
    if (const DatasetSpec* d = find_dataset("/fields/" + path.substr(6))) return d->units;
  return "";
}

std::string units_attribute(const std::string& name) { return name + "_units"; }

}  // namespace magnus
