#include "io/schema.hpp"

#include <cmath>

#include "io/schema_build.hpp"

namespace magnus {

namespace {

using namespace schema_build;

// The groups of the flow result, as the file holds them (P, F, E, T name them in the rows).
const char* const P = "/parameters";
const char* const F = "/forces";
const char* const E = "/errors";
const char* const T = "/timing";

/// The rows of the file's root: format, version, model, run status, the case.
std::vector<AttrSpec> root_rows() {
  return {
    Flow::shown(Shown::file_only, text("/", "format", "\"magnus-flow\"",
                                        [](const FlowResult&) { return std::string("magnus-flow"); })),
    Flow::shown(Shown::file_only, integer("/", "format_version", "version of this layout; readers accept 1 and 2",
                                           [](const FlowResult&) { return opt(double(kFlowFormatVersion)); })),
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
  };
}

/// The rows of /parameters: the scene, the grid and the solver.
std::vector<AttrSpec> parameter_rows() {
  return {
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
  };
}

/// The rows of /forces: numeric, exact and estimated forces.
std::vector<AttrSpec> force_rows() {
  return {
    row(num(
            F, "lift", "N/m", "lift per unit span (across the freestream), numeric",
            [](const FlowResult& r) { return opt(r.forces.lift); },
            [](FlowResult& r, double v) { r.forces.lift = v; }),
        "lift (N/m)", "lift_N_m", "{:.10g}"),
    row(num(
            F, "drag", "N/m", "drag per unit span (along the freestream), numeric",
            [](const FlowResult& r) { return opt(r.forces.drag); },
            [](FlowResult& r, double v) { r.forces.drag = v; }),
        "drag (N/m)", "drag_N_m", "{:.3g}"),
    row(num(
            F, "cl", "1", "lift coefficient L/(½ρU²·2a), L across the freestream (undefined when U = 0)",
            [](const FlowResult& r) { return r.forces.cl; },
            [](FlowResult& r, double v) { r.forces.cl = v; }),
        "C_L numeric", "cl", "{:.10g}"),
    row(num(
            F, "cd", "1", "drag coefficient D/(½ρU²·2a), D along the freestream (undefined when U = 0)",
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
        F, "magnus_S", "kg/m", "Magnus coefficient S = −L/(Uω), L the lift (undefined when U = 0 or ω = 0)",
        [](const FlowResult& r) { return r.forces.magnus_S; },
        [](FlowResult& r, double v) { r.forces.magnus_S = v; }),
    num(
        F, "magnus_S_exact", "kg/m",
        "exact Magnus coefficient: 2πρa² (spin model), ρΓ/ω (given Γ; undefined when ω = 0)",
        [](const FlowResult& r) { return r.forces.magnus_S_exact; },
        [](FlowResult& r, double v) { r.forces.magnus_S_exact = v; }),
  };
}

/// The rows of /errors: against the exact solution.
std::vector<AttrSpec> error_rows() {
  return {
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
            E, "cl_rel", "1", "|L − L_KJ| / |L_KJ| (L the lift); when Γ = 0, |L|/(ρU²a) (undefined when U = 0)",
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
  };
}

/// The rows of /timing: wall clock of each phase.
std::vector<AttrSpec> timing_rows() {
  return {
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
}

std::vector<AttrSpec> make_attributes() {
  std::vector<AttrSpec> table;
  for (const auto& part : {root_rows(), parameter_rows(), force_rows(), error_rows(), timing_rows()})
    table.insert(table.end(), part.begin(), part.end());
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
  for (const auto& part : {viscous_attributes(), study_attributes()}) table.insert(table.end(), part.begin(), part.end());
  return table;
}

}  // namespace

bool applies(Models m, const FlowResult& r) {
  switch (m) {
    case Models::all: return true;
    case Models::potential: return !r.viscous;
    case Models::viscous: return r.viscous.has_value();
    case Models::steady_study: return r.viscous && r.viscous->steady_study;
  }
  return false;
}

const std::vector<AttrSpec>& result_attributes() {
  static const std::vector<AttrSpec> table = make_attributes();
  return table;
}

const AttrSpec* find_attribute(const std::string& group, const std::string& name) {
  for (const auto& a : result_attributes())
    if (group == a.group && name == a.name) return &a;
  return nullptr;
}

bool viscous_last_step(const std::string& group, const std::string& name) {
  static const char* const kLast[] = {"lift",        "drag",        "cl",          "cd",         "delta_p_top_bottom",
                                      "cl_pressure", "cl_friction", "cd_pressure", "cd_friction", "cm",
                                      "torque",      "spin_power"};
  if (group != "/forces") return false;
  for (const char* k : kLast)
    if (name == k) return true;
  return false;
}

const AttrSpec* viscous_mean_of(const std::string& group, const std::string& name) {
  if (group != "/forces") return nullptr;
  for (const char* k : {"cl", "cd", "lift", "drag"})
    if (name == k) return find_attribute(group, name + "_mean");
  return nullptr;
}

std::string units_attribute(const std::string& name) { return name + "_units"; }

}  // namespace magnus
