// The navier-stokes model's attributes of the schema table (Models::viscous): absent from potential results.
#include "io/schema_build.hpp"
#include "physics/checked_cast.hpp"

namespace magnus::schema_build {

namespace {

// The groups the rows name (P, F, T).
const char* const P = "/parameters";
const char* const F = "/forces";
const char* const T = "/timing";
const char* const E = "/errors";

/// A dimensionless number of the case's grid request in /parameters (read back into it).
AttrSpec grid_number(const char* name, const char* description, double GridRequest::*m) {
  return only(Models::viscous, num(
                                   P, name, "1", description, [m](const FlowResult& r) { return opt(r.c.grid.*m); },
                                   [m](FlowResult& r, double v) { r.c.grid.*m = v; }));
}

/// The viscous rows of /parameters: ν, Re, the time unit and the run's settings.
std::vector<AttrSpec> viscous_parameter_rows() {
  return {
      vnum(P, "viscosity", "m^2/s", "kinematic viscosity ν", &ViscousPart::viscosity),
      vnum(P, "reynolds", "1", "Reynolds number U·2a/ν (undefined when U = 0)", &ViscousPart::reynolds),
      vnum(P, "time_unit", "s", "convective time unit D/U (D/(a|ω|) when U = 0)", &ViscousPart::time_unit),
      only(Models::viscous, num(
                                P, "time_end", "1", "time.end asked for, in convective units",
                                [](const FlowResult& r) { return opt(r.c.time.end); },
                                [](FlowResult& r, double v) { r.c.time.end = v; })),
      only(Models::viscous,
           integer(
               P, "advection_order", "order of the advection term in θ: 2 (Arakawa's Jacobian) or 4",
               [](const FlowResult& r) { return opt(double(r.c.solver.advection_order)); },
               [](FlowResult& r, double v) { r.c.solver.advection_order = checked_cast<int>(v, "advection_order"); })),
      only(Models::viscous,
           integer(
               P, "advection_order_xi", "order of the advection term in ξ: 2 (Arakawa's Jacobian) or 4",
               [](const FlowResult& r) { return opt(double(r.c.solver.advection_order_xi)); },
               [](FlowResult& r, double v) { r.c.solver.advection_order_xi = checked_cast<int>(v, "advection_order_xi"); })),
      only(Models::viscous,
           text(
               P, "wall_closure", "the no-slip row for the wall vorticity: thom (first order) or jensen (second)",
               [](const FlowResult& r) { return r.c.solver.wall_closure; },
               [](FlowResult& r, const std::string& v) { r.c.solver.wall_closure = v; })),
      only(Models::viscous,
           integer(
               P, "implicit_rotation", "1: the wall's spin advected by Crank–Nicolson (solver.implicit_rotation), 0: by AB2",
               [](const FlowResult& r) { return opt(r.c.solver.implicit_rotation ? 1.0 : 0.0); },
               [](FlowResult& r, double v) { r.c.solver.implicit_rotation = v != 0.0; })),
      grid_number("wall_refinement", "grid.wall_refinement: Δξ_far/Δξ_wall (1: uniform ξ)",
                  &GridRequest::wall_refinement),
      grid_number("wall_layer", "grid.wall_layer: ξ-length of the rings' transition", &GridRequest::wall_layer),
      grid_number("absorbing_layer", "domain.absorbing_layer: r/a where the absorbing layer begins (0: none)",
                  &GridRequest::absorbing_layer),
      grid_number("absorbing_strength", "domain.absorbing_strength: the layer's sink λ at R, in U_ref/D",
                  &GridRequest::absorbing_strength),
  };
}

/// The viscous rows of /forces: mean and last-step forces, the ideal lift beside them, the leading eigenvalue.
std::vector<AttrSpec> viscous_force_rows() {
  return {
      row(vnum(F, "cl_mean", "1", "mean lift coefficient (over the last shedding period, or the last step)",
               &ViscousPart::cl_mean),
          "C_L mean (viscous)", "cl_mean", "{:.6g}"),
      row(vnum(F, "cd_mean", "1", "mean drag coefficient", &ViscousPart::cd_mean), "C_D mean (viscous)",
          "cd_mean", "{:.6g}"),
      vnum(F, "cm_mean", "1", "mean torque coefficient M/(½ρU²·D²)", &ViscousPart::cm_mean),
      row(vnum(F, "cl_amplitude", "1", "lift coefficient amplitude (max − min)/2 over the last period",
               &ViscousPart::cl_amplitude),
          "C_L amplitude", "cl_amplitude", "{:.4g}"),
      vnum(F, "cd_amplitude", "1", "drag coefficient amplitude (max − min)/2 over the last period",
           &ViscousPart::cd_amplitude),
      row(vnum(F, "strouhal", "1", "Strouhal number f·D/U of the lift signal (periodic flow only)",
               &ViscousPart::strouhal),
          "Strouhal number", "strouhal", "{:.5g}"),
      vnum(F, "period", "s", "shedding period (periodic flow only)", &ViscousPart::period),
      vnum(F, "lift_mean", "N/m", "mean lift per unit span", &ViscousPart::lift_mean),
      vnum(F, "drag_mean", "N/m", "mean drag per unit span", &ViscousPart::drag_mean),
      vnum(F, "torque_mean", "N*m/m", "mean torque on the body per unit span, CCW positive",
           &ViscousPart::torque_mean),
      vnum(F, "spin_power_mean", "W/m", "mean power to keep the spin, −M̄ω", &ViscousPart::spin_power_mean),
      vlast("cl_pressure", "1", "pressure part of C_L at the last step", &ViscousForces::C_L_pressure),
      vlast("cl_friction", "1", "friction part of C_L at the last step", &ViscousForces::C_L_friction),
      vlast("cd_pressure", "1", "pressure part of C_D at the last step", &ViscousForces::C_D_pressure),
      vlast("cd_friction", "1", "friction part of C_D at the last step", &ViscousForces::C_D_friction),
      vlast("cm", "1", "torque coefficient at the last step", &ViscousForces::C_M),
      vlast("torque", "N*m/m", "torque per unit span at the last step", &ViscousForces::M),
      vlast("spin_power", "W/m", "power to keep the spin at the last step, −Mω", &ViscousForces::P_spin),
      row(vnum(F, "cl_ideal", "1", "potential flow's lift coefficient for the same scene, −2πaω/U",
               &ViscousPart::cl_ideal),
          "C_L ideal (potential)", "cl_ideal", "{:.6g}"),
      row(vnum(F, "magnus_ratio", "1",
               "S(Re, α)/(2πρa²) = C_L,mean/C_L,ideal: the real share of the ideal lift (undefined at α = 0)",
               &ViscousPart::magnus_ratio),
          "S/(2πρa²)", "magnus_ratio", "{:.4f}"),
      vnum(F, "recirculation_length", "1", "recirculation length behind the body over D (steady flow)",
           &ViscousPart::recirculation_length),
      vnum(F, "eigenvalue_real", "1",
           "growth rate Re λ·D/U of the steady state's leading linear mode (time.mode = \"auto\")",
           &ViscousPart::eigenvalue_real),
      vnum(F, "eigenvalue_imag", "1",
           "frequency Im λ·D/U of the steady state's leading linear mode (time.mode = \"auto\"; St = Im/2π)",
           &ViscousPart::eigenvalue_imag),
      vnum(F, "eigenvalue_residual", "1",
           "relative residual ‖Jx − λMx‖/(‖Jx‖ + |λ|‖Mx‖) of the leading mode (time.mode = \"auto\")",
           &ViscousPart::eigenvalue_residual),
      vnum(F, "circulation_outer", "m^2/s", "circulation on the outer ring r = R", &ViscousPart::Gamma_R),
  };
}

/// The viscous rows of /timing: the phases of the run and where it stopped.
std::vector<AttrSpec> viscous_timing_rows() {
  return {
      vnum(T, "newton_s", "s", "wall clock, Newton's method (time.mode \"steady\" or \"auto\")",
           &ViscousPart::newton_seconds),
      vnum(T, "stability_s", "s", "wall clock, the eigenvalue test (time.mode \"auto\")",
           &ViscousPart::stability_seconds),
      vnum(T, "march_s", "s", "wall clock, the march in time", &ViscousPart::march_seconds),
      vnum(T, "t_reached", "s", "simulated time reached", &ViscousPart::t),
      vnum(T, "dt", "s", "last time step", &ViscousPart::dt),
      only(Models::viscous,
           integer(
               T, "steps", "time steps from rest (a resumed run: with those before --resume)",
               [](const FlowResult& r) { return r.viscous ? opt(double(r.viscous->steps)) : std::nullopt; },
               [](FlowResult& r, double v) { vis(r).steps = checked_cast<long>(v, "steps"); })),
  };
}

/// A viscous integer attribute (absent when 0).
AttrSpec vint(const char* group, const char* name, const char* description, int ViscousPart::*m) {
  return only(Models::viscous,
              integer(
                  group, name, description,
                  [m](const FlowResult& r) { return r.viscous && (*r.viscous).*m ? opt(double((*r.viscous).*m)) : std::nullopt; },
                  [m](FlowResult& r, double v) { vis(r).*m = checked_cast<int>(v, "companion grid"); }));
}

/// A viscous text attribute (absent when empty).
AttrSpec vtext(const char* group, const char* name, const char* description, std::string ViscousPart::*m) {
  return only(Models::viscous,
              Flow::when([m](const FlowResult& r) { return r.viscous && !((*r.viscous).*m).empty(); },
                         text(
                             group, name, description,
                             [m](const FlowResult& r) { return r.viscous ? (*r.viscous).*m : std::string(); },
                             [m](FlowResult& r, const std::string& v) { vis(r).*m = v; })));
}

/// The rows of the drift still to come in each estimate (means_drift, relative: d·q/(1 − q) for the last
/// differences d decaying by q a period, else 4 periods at the current rate).
std::vector<AttrSpec> drift_rows() {
  struct Drift {
    const char* name;
    const char* description;
    std::optional<double> ViscousPart::*m;
  };
  const Drift drifts[] = {
      {"cl_mean_drift_rel",
       "the drift still to come of the last periods' means of C_L, in cl_mean_rel_estimate, relative: d·q/(1 − q) "
       "for the last differences d decaying by q a period, else 4 periods at the current rate",
       &ViscousPart::cl_mean_drift_rel},
      {"cd_mean_drift_rel", "the drift still to come of C_D's means, in cd_mean_rel_estimate (as cl_mean_drift_rel)",
       &ViscousPart::cd_mean_drift_rel},
      {"strouhal_drift_rel",
       "the drift still to come of the periods' lengths, in strouhal_rel_estimate (as cl_mean_drift_rel)",
       &ViscousPart::strouhal_drift_rel}};
  std::vector<AttrSpec> rows;
  for (const Drift& d : drifts) rows.push_back(vnum(E, d.name, "1", d.description, d.m));
  return rows;
}

/// The rows of the computed 3D onset given to the run (magnus run --onset3d): absent when none was.
std::vector<AttrSpec> onset3d_rows() {
  return {
      vnum(P, "onset3d_reynolds", "1",
           "the computed 3D onset Re_c at this α (--onset3d files; linear in α between their points): the 2D "
           "flow is real below it (absent outside the α the files span)",
           &ViscousPart::onset3d_reynolds),
      vnum(P, "onset3d_alpha_min", "1", "the smallest spin ratio of the --onset3d files' points",
           &ViscousPart::onset3d_alpha_min),
      vnum(P, "onset3d_alpha_max", "1", "the largest spin ratio of the --onset3d files' points",
           &ViscousPart::onset3d_alpha_max),
      vtext(P, "onset3d_files", "the --onset3d files (magnus stability --spanwise --critical-reynolds --output)",
            &ViscousPart::onset3d_files),
  };
}

/// The viscous rows of /errors: the run's own estimate of its discretisation error.
std::vector<AttrSpec> viscous_error_rows() {
  std::vector<AttrSpec> rows = {
      vnum(E, "cl_mean_rel_estimate", "1",
           "estimated relative error of cl_mean: |f − f_coarse|/|f| against the grid twice as coarse (3× the "
           "Richardson estimate), plus the means' spread when they had not converged and their drift still to come",
           &ViscousPart::cl_mean_rel_estimate),
      vnum(E, "cd_mean_rel_estimate", "1", "estimated relative error of cd_mean (as cl_mean_rel_estimate)",
           &ViscousPart::cd_mean_rel_estimate),
      vnum(E, "strouhal_rel_estimate", "1", "estimated relative error of strouhal (as cl_mean_rel_estimate)",
           &ViscousPart::strouhal_rel_estimate),
      only(Models::viscous,
           integer(
               E, "means_converged", "1: the means (or steady values) had converged when the run stopped, 0: not",
               [](const FlowResult& r) { return r.viscous ? opt(r.viscous->means_converged ? 1.0 : 0.0) : std::nullopt; },
               [](FlowResult& r, double v) { vis(r).means_converged = v != 0.0; })),
      vnum(E, "means_spread_rel", "1",
           "the spread of the last periods' means (or the last window's drift) in the estimate, relative",
           &ViscousPart::means_spread_rel),
      vint(E, "companion_n_theta", "points in θ of the companion run's grid", &ViscousPart::companion_n_theta),
      vint(E, "companion_n_r", "rings of the companion run's grid", &ViscousPart::companion_n_r),
      vtext(E, "estimate_method", "how the error estimate was formed", &ViscousPart::error_method),
      vtext(E, "estimate_note", "why a part of the error estimate is undefined", &ViscousPart::error_note),
      only(Models::viscous,
           integer(
               E, "tolerance_met", "grid.tolerance: 1 when every defined estimate met it, 0 when not (absent: none)",
               [](const FlowResult& r) {
                 return r.viscous && r.viscous->tolerance_met ? opt(*r.viscous->tolerance_met ? 1.0 : 0.0)
                                                              : std::nullopt;
               },
               [](FlowResult& r, double v) { vis(r).tolerance_met = v != 0.0; })),
      vtext(E, "tolerance_note", "grid.tolerance: how the grid that met it was found, or why none did",
            &ViscousPart::tolerance_note),
      vnum(T, "companion_s", "s", "wall clock, the companion run of the error estimate (beside the run)",
           &ViscousPart::companion_seconds),
  };
  for (AttrSpec& a : drift_rows()) rows.push_back(std::move(a));
  return rows;
}

}  // namespace

std::vector<AttrSpec> viscous_attributes() {
  std::vector<AttrSpec> table;
  for (const auto& part :
       {viscous_parameter_rows(), viscous_force_rows(), viscous_timing_rows(), viscous_error_rows(),
        onset3d_rows()})
    table.insert(table.end(), part.begin(), part.end());
  return table;
}

}  // namespace magnus::schema_build
