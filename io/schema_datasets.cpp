// The datasets of the schema table (io/schema.hpp): grid, fields (u_x, u_y and x, y in the world frame turned
// by flow.direction), surface, stagnation points, history and snapshots.
#include <cmath>

#include "io/schema_build.hpp"

namespace magnus {

namespace {

using namespace schema_build;

using Member = std::vector<double> Fields::*;

/// d, described otherwise in a navier-stokes result.
DatasetSpec described_viscous(DatasetSpec d, const char* viscous_description) {
  d.viscous_description = viscous_description;
  return d;
}

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

/// The rows of /grid: the radii, angles and Cartesian coordinates of the nodes.
std::vector<DatasetSpec> grid_rows() {
  return {
    {"/grid/r", "m", "radius r_i of grid row i (dimension scale of every field's first axis)",
     DataShape::n_r, [](const FlowResult& r) { return r.grid.r; },
     [](FlowResult& r, std::vector<double> v) { r.grid.r = std::move(v); }},
    {"/grid/theta", "rad",
     "angle θ_j of grid column j from the freestream direction, counter-clockwise (wind frame; dimension "
     "scale)",
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
  };
}

/// The rows of /fields: the selected fields on the grid.
std::vector<DatasetSpec> field_rows() {
  return {
    field("psi", "m^2/s", "stream function ψ", &Fields::psi),
    field("u_r", "m/s", "radial velocity u_r = (1/r) ∂ψ/∂θ", &Fields::u_r),
    field("u_theta", "m/s", "angular velocity u_θ = −∂ψ/∂r", &Fields::u_theta),
    world_velocity("u_x", "velocity component along the world +x", false),
    world_velocity("u_y", "velocity component along the world +y", true),
    described_viscous(field("pressure", "Pa", "pressure p = p∞ + ½ρ(U² − |u|²)", &Fields::pressure),
                      "pressure from the pressure Poisson equation ∇²p = 2ρ(∂u_x/∂x ∂u_y/∂y − ∂u_x/∂y "
                      "∂u_y/∂x), fixed to p∞ far upstream"),
    field("cp", "1", "pressure coefficient (p − p∞)/(½ρU²) (undefined when U = 0)", &Fields::cp),
    only(Models::potential,
         field("psi_exact", "m^2/s", "exact stream function on the same grid", &Fields::psi_exact)),
    only(Models::potential, field("psi_error", "m^2/s", "ψ − ψ_exact", &Fields::psi_error)),
    only(Models::viscous, field("vorticity", "1/s", "vorticity ζ = −∇²ψ", &Fields::vorticity)),
  };
}

/// The rows of /surface and /stagnation: values on the body and its stagnation points.
std::vector<DatasetSpec> surface_rows() {
  return {
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
         stagnation("theta", "rad",
                    "angle of each stagnation point from the freestream direction, numeric, in [0, 2π)",
                    false, true)),
    only(Models::potential,
         stagnation("r_exact", "m", "radius of each stagnation point, exact", true, false)),
    only(Models::potential,
         stagnation("theta_exact", "rad",
                    "angle of each stagnation point from the freestream direction, exact, in [0, 2π)", true,
                    true)),
    only(Models::viscous,
         {"/separation/theta", "rad",
          "separation points: angles where the wall shear stress changes sign from + to − (the wall flow "
           "leaves the wall); stagnation, reattachment and symmetry points are not listed", DataShape::points,
          [](const FlowResult& r) { return r.viscous ? r.viscous->separation : std::vector<double>(); },
          [](FlowResult& r, std::vector<double> v) { vis(r).separation = std::move(v); }}),
  };
}

/// The rows of /history and /snapshots: the force history and the stored states of a march.
std::vector<DatasetSpec> history_rows() {
  return {
    history("t", "s", "time of each step", &ForceSample::t),
    {"/history/t_convective",
     "1",
     "time of each step in convective units D/U (D/(a|ω|) when U = 0)",
     DataShape::steps,
     [](const FlowResult& r) {
       std::vector<double> v;
       if (r.viscous)
         for (const ForceSample& f : r.viscous->history) v.push_back(f.t / r.viscous->time_unit);
       return v;
     },
     {},
     Models::viscous},
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

std::vector<DatasetSpec> make_datasets() {
  std::vector<DatasetSpec> table;
  for (const auto& part : {grid_rows(), field_rows(), surface_rows(), history_rows(), study_datasets()})
    table.insert(table.end(), part.begin(), part.end());
  return table;
}


}  // namespace

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

const std::string& description_of(const DatasetSpec& d, bool viscous) {
  return viscous && !d.viscous_description.empty() ? d.viscous_description : d.description;
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

}  // namespace magnus
