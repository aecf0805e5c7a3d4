#include "io/json_output.hpp"
#include "physics/checked_cast.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "io/compare.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/json_parts.hpp"
#include "io/report_scene.hpp"
#include "io/report_viscous.hpp"
#include "io/rotor_data.hpp"
#include "postproc/scene_forces.hpp"
#include "io/schema.hpp"
#include "io/schema_files.hpp"
#include "postproc/potential/forces.hpp"

namespace magnus {

Json quantity(std::optional<double> v, const std::string& units) {
  Json q;
  if (v && std::isfinite(*v))
    q["value"] = *v + 0.0;  // + 0.0: never -0
  else
    q["value"] = nullptr;
  q["units"] = units;
  return q;
}

Json count(long n) {
  Json q;
  q["value"] = n;
  q["units"] = "1";
  return q;
}

Json quantity(const std::vector<double>& v, const std::string& units) {
  Json a = Json::array();
  for (double x : v) a.push_back(std::isfinite(x) ? Json(x + 0.0) : Json(nullptr));
  Json q;
  q["value"] = std::move(a);
  q["units"] = units;
  return q;
}

std::string json_text(const Json& j) {
  return j.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

Json value_json(const AttrValue& a) {
  if (a.kind == AttrKind::text) return a.text;
  if (a.kind == AttrKind::integer && a.number && std::isfinite(*a.number)) return count(saturate_cast<long>(*a.number));
  return quantity(a.number, a.units);
}

void put_values(Json& j, const std::vector<AttrValue>& values) {
  for (const AttrValue& a : values) {
    const std::string g = json_parts::key_of(a.group);
    if (g.empty())
      j[a.name] = value_json(a);
    else
      j[g][a.name] = value_json(a);
  }
}

namespace json_parts {

std::string key_of(const std::string& group) { return group.size() > 1 ? group.substr(1) : std::string(); }

Json kj_ratios(std::optional<double> minus_1, std::optional<double> over_seed) {
  Json d;
  d["cl_over_kj_minus_1"] = quantity(minus_1, "1");
  d["kj_over_seed"] = quantity(over_seed, "1");
  return d;
}

Json point_json(const StagnationPoint& p, double a) {
  Json q;
  q["r"] = quantity(p.r, "m");
  q["r_over_a"] = quantity(a > 0.0 ? std::optional<double>(p.r / a) : std::nullopt, "1");
  q["theta"] = quantity(p.theta, "rad");
  q["theta_deg"] = quantity(p.theta * 180.0 / M_PI, "degree");
  q["on_surface"] = p.on_surface;
  return q;
}

}  // namespace json_parts

namespace {

using json_parts::key_of;
using json_parts::point_json;

Json points_json(const std::vector<StagnationPoint>& sorted, double a) {
  Json list = Json::array();
  for (const auto& p : sorted) list.push_back(point_json(p, a));
  return list;
}

/// The figures the potential summary derives from the stored ones.
/// A rotor's published data at the scene's α (the summary's "rotor data" block): each dataset's |C_L| and C_D
/// (null outside its α range or without drag), its Re and whether it fits the scene's (null: no viscosity).
Json rotor_data_json(const Scene& sc) {
  const RotorData* data = shipped_rotor_data();
  if (!data) return nullptr;
  const double re = sc.viscosity > 0.0 ? sc.reynolds() : 0.0;
  Json rows = Json::array();
  for (const auto& d : data->datasets) {
    const auto v = rotor_value(d, std::fabs(sc.spin_ratio()));
    Json q;
    q["id"] = d.id;
    q["label"] = d.label;
    q["citation"] = d.citation;
    q["method"] = d.method;
    q["reynolds"] = rotor_reynolds_text(d);
    q["fits_reynolds"] = re > 0.0 ? Json(rotor_fits_reynolds(d, re)) : Json(nullptr);
    q["cl_magnitude"] = quantity(v ? std::optional<double>(std::fabs(v->cl)) : std::nullopt, "1");
    q["cd"] = quantity(v ? v->cd : std::nullopt, "1");
    rows.push_back(std::move(q));
  }
  return rows;
}

Json potential_derived(const FlowResult& r, Json& j) {
  const Scene& sc = r.c.scene;
  const Forces& f = r.forces;
  const bool given = sc.circulation_given, moving = sc.speed > 0.0, spinning = sc.spin != 0.0;
  // The seed estimates lift from ω: with a given Γ and no spin it says nothing (the summary: undefined).
  if (given && !spinning)
    for (const char* k : {"cl_seed_estimate", "delta_p_seed_estimate"})
      if (j["forces"].contains(k)) j["forces"][k]["value"] = nullptr;
  Json d;
  d["nodes"] = count(r.grid.nodes());
  d["threads"] = count(r.info.threads);
  if (!r.info.grid_choice.empty()) d["grid_choice"] = r.info.grid_choice;
  const DerivedRatios ratios = derived_ratios(r);
  if (given) d["alpha_circulation"] = quantity(ratios.alpha_Gamma, "1");
  // The seed's ratio is undefined without spin (the summary: "undefined (ω = 0)").
  d.update(json_parts::kj_ratios(ratios.cl_over_kj_minus_1, ratios.kj_over_seed));
  d["delta_p_over_seed"] = quantity(ratios.delta_p_over_seed, "1");
  d["magnus_S_seed"] = quantity(ratios.magnus_S_seed, "kg/m");
  // Real flow: the Reynolds number when a viscosity is given, and the nearest published viscous figure.
  if (sc.viscosity > 0.0) {
    d["viscosity"] = quantity(sc.viscosity, "m^2/s");
    d["reynolds"] = quantity(moving ? std::optional<double>(sc.reynolds()) : std::nullopt, "1");
  }
  if (moving && f.cl) {
    d["inviscid_upper_bound"] = true;
    const ViscousReference* ref = shipped_reference();
    const auto n = ref ? nearest_reference(sc, *ref) : std::nullopt;
    Json q = nullptr;
    if (n) {
      q = Json::object();
      q["reynolds"] = quantity(n->reynolds, "1");
      q["alpha"] = quantity(n->alpha, "1");
      q["cl"] = quantity(n->cl, "1");
      q["cl_over_ideal"] = quantity(share_of_ideal_lift(n->cl, n->alpha), "1");
      q["label"] = n->label;
      q["source"] = n->source;
    }
    d["reference"] = std::move(q);
  }
  if (moving && sc.span > 0.0) d["rotor_data"] = rotor_data_json(sc);
  return d;
}

/// The figures the navier-stokes summary derives from the stored ones.
Json viscous_derived(const FlowResult& r) {
  const ViscousPart& v = *r.viscous;
  const PolarGrid& g = r.grid;
  Json d;
  d["nodes"] = count(g.nodes());
  const ViscousRatios ratios = viscous_ratios(r);
  if (ratios.wall_cells) {
    const double cells = *ratios.wall_cells;
    d["wall_cells"] = quantity(cells, "1");
    d["wall_cells_coarse"] = cells < kWallCellsForPercent;
    d["wall_cells_unresolved"] = cells < kWallCellsResolved;  // the forces are not meaningful
  }
  d["t_convective"] = quantity(ratios.t_convective, "1");
  d["dt_convective"] = quantity(ratios.dt_convective, "1");
  d["steps_per_second"] = quantity(ratios.steps_per_second, "1/s");
  // By the computed 3D onset the run was given (--onset3d): null without one, or outside the α it spans.
  const std::optional<bool> real = two_d_is_real(v);
  d["three_dimensional"] = real ? Json(!*real) : Json();
  if (v.reynolds) d["onset3d_verdict"] = three_d_text(v, r.c.scene.spin_ratio());  // the summary's "3D" line
  d["viscous_length_beyond_grid"] = v.reynolds && viscous_length_beyond_grid(g, *v.reynolds);
  if (v.steady_study) d["steady_study"] = json_parts::steady_study_json(*v.steady_study);
  if (ratios.torque_potential_vortex) {  // still fluid: the potential vortex u_θ = a²ω/r is exact
    d["torque_potential_vortex"] = quantity(*ratios.torque_potential_vortex, "N*m/m");
    d["torque_over_potential_vortex_minus_1"] = quantity(ratios.torque_over_potential_vortex_minus_1, "1");
  }
  return d;
}

}  // namespace

Json result_json(const FlowResult& r, const std::string& output_path) {
  Json j;
  std::vector<AttrValue> values;
  for (const AttrSpec& a : result_attributes())  // format and format_version are the file's, not the run's
    if (applies(a.models, r) && a.shown != Shown::file_only) values.push_back(value_of(a, r));
  put_values(j, values);
  if (r.viscous) {
    for (auto it = j["forces"].begin(); it != j["forces"].end(); ++it)  // one instant, not a time mean
      if (viscous_last_step("/forces", it.key())) it.value()["at"] = "last step";
    j["partial"] = r.viscous->partial;  // a yes/no, not a number
    j["derived"] = viscous_derived(r);
    j["separation"] = quantity(r.viscous->separation, "rad");
  } else {
    j["derived"] = potential_derived(r, j);
  }
  if (r.c.scene.direction_deg != 0.0) {  // lift and drag are in the flow's frame; the world's F_x, F_y beside
    const SceneForces f = scene_forces(r);
    const WorldForce w = f.world;
    j["derived"]["force_world_x"] = quantity(w.x, "N/m");
    j["derived"]["force_world_y"] = quantity(w.y, "N/m");
  }
  if (!r.viscous) {
    Json st;
    st["numeric"] = points_json(r.stagnation, r.c.scene.radius);
    st["exact"] = points_json(r.stagnation_exact, r.c.scene.radius);
    st["numeric_outside_grid"] = stagnation_outside_grid(r).has_value();
    j["stagnation"] = std::move(st);
  }
  if (!output_path.empty()) {
    j["output"]["file"] = output_path;
    j["output"]["xdmf"] = xdmf_path(output_path);
  }
  return j;
}

// ---------------------------------------------------------------------------------------------
// sweep

Json sweep_json(const SweepResult& s, const ViscousReference* ref, const std::vector<std::string>& written) {
  Json j;
  put_values(j, attr_values(sweep_attributes(), s, Shown::json_only));
  const std::vector<Column<SweepRow>> columns = sweep_columns(s.variable);
  Json points = Json::array();
  for (const SweepPoint& pt : s.points) {
    const SweepRow w = sweep_row(s, pt);
    Json q;
    for (const Column<SweepRow>& col : columns)  // the stagnation points: as points, not columns
      if (std::string(col.name).rfind("stagnation_", 0) != 0) q[col.name] = quantity(col.get(w), col.units);
    q["stagnation"] = points_json(pt.stagnation, pt.scene.radius);
    points.push_back(std::move(q));
  }
  j["points"] = std::move(points);
  if (ref && !s.points.empty()) {
    const double lo = sweep_row(s, s.points.front()).alpha, hi = sweep_row(s, s.points.back()).alpha;
    Json rows = Json::array();
    for (const auto& d : ref->datasets)
      for (const auto& pt : d.points) {
        if (pt.alpha < lo - 1e-9 || pt.alpha > hi + 1e-9) continue;
        Json q;
        q["alpha"] = quantity(pt.alpha, "1");
        q["reynolds"] = quantity(d.reynolds, "1");
        q["cl"] = quantity(pt.cl, "1");
        q["cd"] = quantity(pt.cd, "1");
        q["cl_ideal"] = quantity(cl_ideal(pt.alpha), "1");
        q["label"] = d.label;
        q["source"] = d.source;
        rows.push_back(std::move(q));
      }
    if (!rows.empty()) j["reference"] = std::move(rows);
  }
  j["output"] = written;
  return j;
}

}  // namespace magnus
