// The potential sweep's table (io/schema_files.hpp): root, /parameters, /timing and the /sweep columns.
#include <cmath>

#include "io/schema_files.hpp"

namespace magnus {

namespace {

using R = Rows<SweepResult>;
using S = SweepResult;

/// Whether α = aω/U is swept (else Γ, m²/s).
bool by_spin(const S& s) { return s.variable == SweepVariable::spin_ratio; }
/// Degrees to rad.
double rad(double degrees) { return degrees * M_PI / 180.0; }

/// A column of the sweep: the SweepRow member it shows.
Column<SweepRow> col(const char* name, const char* units, const char* description, double SweepRow::*m) {
  return {name, units, description, [m](const SweepRow& r) { return r.*m; }};
}

std::vector<Attr<S>> make_sweep_attributes() {
  const char* P = "/parameters";
  const char* T = "/timing";
  const auto file = Shown::file_only;
  const auto json = Shown::json_only;
  std::vector<Attr<S>> t = R::header("magnus-sweep", 2, "potential");
  t.insert(t.end(), {
      R::text("/", "title", "the case's title", [](const S& s) { return s.base.title; }),
      R::shown(file, R::text("/", "case", "the resolved case as TOML", [](const S& s) { return s.base.source_text; })),
      R::text("/", "variable", "what is swept: spin_ratio or circulation",
              [](const S& s) { return std::string(by_spin(s) ? "spin_ratio" : "circulation"); }),
      R::num(P, "radius", "m", "cylinder radius a", [](const S& s) { return opt(s.base.scene.radius); }),
      R::num(P, "speed", "m/s", "freestream speed U", [](const S& s) { return opt(s.base.scene.speed); }),
      R::num(P, "density", "kg/m^3", "fluid density ρ", [](const S& s) { return opt(s.base.scene.density); }),
      R::num(P, "pressure_inf", "Pa", "freestream pressure p∞", [](const S& s) { return opt(s.base.scene.pressure_inf); }),
      // The scene's Re for the overlays of `magnus plot` (potential flow itself does not use ν).
      R::shown(file, R::when([](const S& s) { return s.base.scene.viscosity > 0.0; },
                             R::num(P, "viscosity", "m^2/s", "kinematic viscosity ν (when given)",
                                    [](const S& s) { return opt(s.base.scene.viscosity); }))),
      R::text(P, "circulation_model", "\"spin\" (Γ = 2πa²ω) or \"given\"",
              [](const S& s) { return std::string(s.base.scene.circulation_given ? "given" : "spin"); }),
      R::when([](const S& s) { return !by_spin(s); },
              R::num(P, "spin", "rad/s", "the case's spin ω (circulation sweep: for the seed estimate)",
                     [](const S& s) { return opt(s.base.scene.spin); })),
      R::shown(json, R::when([](const S& s) { return !by_spin(s); },
                             R::num(P, "spin_ratio", "1", "the case's aω/U (undefined when U = 0)", [](const S& s) {
                               return s.base.scene.speed > 0.0 ? opt(s.base.scene.spin_ratio()) : std::nullopt;
                             }))),
      R::num(P, "outer_radius", "1", "outer radius of the grid over a, R/a (as built)",
             [](const S& s) { return opt(s.grid.outer_radius() / s.grid.a); }),
      R::text(P, "far_field", "far-field condition: exact or freestream",
              [](const S& s) { return std::string(to_string(s.base.grid.far_field)); }),
      R::text(P, "spacing", "radial spacing: geometric or uniform",
              [](const S& s) { return std::string(to_string(s.base.grid.spacing)); }),
      R::integer(P, "n_r", "radial grid points", [](const S& s) { return opt(s.grid.n_r); }),
      R::integer(P, "n_theta", "angular grid points", [](const S& s) { return opt(s.grid.n_theta); }),
      R::text(P, "method", "linear solver that ran: fft or cholmod", [](const S& s) { return s.method; }),
      R::text(P, "stencil", "finite-difference stencil: 5-point or 9-point",
              [](const S& s) { return std::string(to_string(s.base.solver.stencil)); }),
      R::shown(json, R::when([](const S& s) { return !s.grid_choice.empty(); },
                             R::text("/", "grid_choice", "how grid.tolerance chose the grid",
                                     [](const S& s) { return s.grid_choice; }))),
      R::integer(T, "linear_solves", "right-hand sides solved with the one factorization",
                 [](const S& s) { return opt(s.linear_solves); }),
      R::shown(json, R::integer(T, "points", "points swept", [](const S& s) { return opt(double(s.points.size())); })),
      R::num(T, "assemble_s", "s", "wall clock, assembling", [](const S& s) { return opt(s.assemble_s); }),
      R::num(T, "factor_s", "s", "wall clock, factorization", [](const S& s) { return opt(s.factor_s); }),
      R::num(T, "solve_s", "s", "wall clock, solving", [](const S& s) { return opt(s.solve_s); }),
      R::num(T, "evaluate_s", "s", "wall clock, evaluating the points", [](const S& s) { return opt(s.evaluate_s); }),
      R::num(T, "total_s", "s", "wall clock, whole sweep", [](const S& s) { return opt(s.total_s); }),
  });
  return t;
}

}  // namespace

const std::vector<Attr<SweepResult>>& sweep_attributes() {
  static const std::vector<Attr<SweepResult>> table = make_sweep_attributes();
  return table;
}

std::vector<Column<SweepRow>> sweep_columns(SweepVariable v) {
  return {
      col("alpha", "1", v == SweepVariable::spin_ratio ? "spin ratio aω/U" : "equivalent spin ratio Γ/(2πaU)",
          &SweepRow::alpha),
      col("circulation", "m^2/s", "circulation Γ", &SweepRow::circulation),
      col("lift", "N/m", "lift per unit span (across the freestream), numeric", &SweepRow::lift),
      col("drag", "N/m", "drag per unit span (along the freestream), numeric", &SweepRow::drag),
      col("cl", "1", "lift coefficient, numeric", &SweepRow::cl),
      col("cl_kutta_joukowski", "1", "Kutta–Joukowski −Γ/(Ua)", &SweepRow::cl_kj),
      col("cl_seed_estimate", "1", "seed estimate −4aω/U", &SweepRow::cl_seed),
      col("cl_over_kj_minus_1", "1", "numeric / Kutta–Joukowski − 1", &SweepRow::cl_rel_kj),
      col("kj_over_seed", "1", "Kutta–Joukowski / seed estimate", &SweepRow::kj_over_seed),
      col("cd", "1", "drag coefficient, numeric", &SweepRow::cd),
      col("delta_p_top_bottom", "Pa", "p(a, π/2) − p(a, 3π/2), numeric", &SweepRow::delta_p),
      col("delta_p_seed_estimate", "Pa", "seed estimate 2ρUaω", &SweepRow::delta_p_seed),
      {"stagnation_theta1", "rad", "first stagnation point (smallest θ in [0, 2π)), counter-clockwise from +x",
       [](const SweepRow& r) { return rad(r.stag_theta1_deg); }},
      {"stagnation_theta2", "rad", "second surface stagnation point; undefined (fill value) when there is one (free) point",
       [](const SweepRow& r) { return rad(r.stag_theta2_deg); }},
      col("stagnation_r_over_a", "1", "radius of the first stagnation point over a: 1 on the surface, > 1 for a free point",
          &SweepRow::stag_r_over_a),
  };
}

}  // namespace magnus
