// The navier-stokes S(Re, α) map's table (io/schema_files.hpp): root (shard, stability), /parameters,
// /timing, the axes and the /sweep columns.
#include <cmath>

#include "io/schema_files.hpp"

namespace magnus {

namespace {

using R = Rows<NsMap>;


const double kNaN = std::nan("");

double flag(const std::optional<bool>& b) { return b ? (*b ? 1.0 : 0.0) : kNaN; }

#define NS_COL(NAME, UNITS, WHAT, FIELD)                                    \
  Column<NsMapPoint> {                                                                  \
    NAME, UNITS, WHAT, [](const NsMapPoint& p) { return double(p.FIELD); }, \
        [](NsMapPoint& p, double v) { p.FIELD = decltype(p.FIELD)(v); }     \
  }

}  // namespace

const std::vector<Column<NsMapPoint>>& ns_map_columns() {
  static const std::vector<Column<NsMapPoint>> c = {
      NS_COL("reynolds", "1", "Reynolds number U·2a/ν", reynolds),
      NS_COL("alpha", "1", "spin ratio aω/U", alpha),
      NS_COL("row", "1", "index of Re in /axes/reynolds", row),
      NS_COL("column", "1", "index of α in /axes/alpha", column),
      NS_COL("cl", "1", "reported lift coefficient: steady, or time-averaged (see source)", cl),
      NS_COL("cd", "1", "reported drag coefficient: steady, or time-averaged (see source)", cd),
      NS_COL("cm", "1", "reported torque coefficient M/(½ρU²D²): steady or time-averaged", cm),
      NS_COL("cl_pressure", "1", "pressure part of the steady state's C_L", cl_pressure),
      NS_COL("cl_friction", "1", "friction part of the steady state's C_L", cl_friction),
      NS_COL("cd_pressure", "1", "pressure part of the steady state's C_D", cd_pressure),
      NS_COL("cd_friction", "1", "friction part of the steady state's C_D", cd_friction),
      NS_COL("cl_steady", "1", "C_L of the steady state (stable or not)", cl_steady),
      NS_COL("cd_steady", "1", "C_D of the steady state (stable or not)", cd_steady),
      NS_COL("cm_steady", "1", "C_M of the steady state (stable or not)", cm_steady),
      NS_COL("cl_ideal", "1", "potential flow (Kutta–Joukowski) −2πα", cl_ideal),
      NS_COL("ratio", "1", "C_L / C_L,ideal = S/(2πρa²)", ratio),
      NS_COL("strouhal", "1", "Strouhal number f·D/U of a time-averaged periodic point", strouhal),
      NS_COL("newton_steps", "1", "Newton steps (with arclength corrector steps)", newton_steps),
      NS_COL("arclength_steps", "1", "pseudo-arclength steps taken to reach this α", arclength_steps),
      NS_COL("converged", "1", "1: the steady branch reached this point", converged),
      NS_COL("fold", "1", "1: the branch turned back (a fold) before this α", fold),
      Column<NsMapPoint>{"stable", "1", "1 stable, 0 unstable steady state; fill value: not decided",
             [](const NsMapPoint& p) { return flag(p.stable); },
             [](NsMapPoint& p, double v) {
               if (std::isfinite(v)) p.stable = v != 0.0;
             }},
      Column<NsMapPoint>{"source", "1",
             "0 steady, 1 time-averaged (steady state unstable), 2 time-averaged (no steady state), 3 none, "
             "4 steady, reached by marching from rest (the continued state unstable or not found), "
             "5 time-averaged over the shedding orbit found by shooting (--orbits)",
             [](const NsMapPoint& p) { return double(int(p.source)); },
             [](NsMapPoint& p, double v) {
               p.source = v >= 0.0 && v <= 5.0 ? MapSource(int(v)) : MapSource::none;
             }},
      NS_COL("regime", "1",
             "what the flow does: 0 steady, 1 shedding, 2 the second (one-sided) shedding window (shedding again "
             "after a steady stretch, at under half the first window's St), 3 bistable (a stable steady state and "
             "a shedding orbit coexist, --orbits); fill value: not classified",
             regime),
      NS_COL("cl_rel_estimate", "1",
             "relative error bar of cl: |f − f_c|/|f| against the grid twice as coarse (fill value: undefined)",
             cl_rel_estimate),
      NS_COL("cd_rel_estimate", "1", "relative error bar of cd, as cl's", cd_rel_estimate),
      NS_COL("strouhal_rel_estimate", "1", "relative error bar of the Strouhal number, as cl's",
             strouhal_rel_estimate),
      NS_COL("meets_tolerance", "1",
             "1: the bars are within the default grid's tolerances (C_L, St 1%, C_D 2%), 0: not; fill value: "
             "no C_D bar",
             meets_tolerance),
      NS_COL("seconds", "s", "wall time of the point (measured under the run's load)", seconds),
  };
  return c;
}


namespace {

std::vector<Attr<NsMap>> make_ns_map_attributes() {
  const char* P = "/parameters";
  const char* T = "/timing";
  const auto file = Shown::file_only;
  // The root's shard, stability and the groups are the file's: --json lays them out as grid, shard, axes.
  auto count = [file](const char* group, const char* name, const char* description, int NsMap::*m) {
    return R::shown(file, R::required(R::integer(
                              group, name, description, [m](const NsMap& x) { return opt(x.*m); },
                              [m](NsMap& x, double v) { x.*m = int(v); })));
  };
  std::vector<Attr<NsMap>> t = R::header("magnus-sweep", 2, "navier-stokes");
  t.insert(t.end(), {
      R::text("/", "title", "the case's title", [](const NsMap& m) { return m.base.title; }),
      R::shown(file, R::text("/", "case", "the resolved case as TOML (read back by parsing it)",
                             [](const NsMap& m) { return m.base.source_text; })),
      R::shown(file, R::text("/", "variable", "what is swept: spin_ratio,reynolds",
                             [](const NsMap&) { return std::string("spin_ratio,reynolds"); })),
      count("/", "shard", "K of the shard K/N this file holds (1 when whole)", &NsMap::shard),
      count("/", "shards", "N of the shard K/N (1 when whole)", &NsMap::shards),
      R::shown(file, R::text(
                         "/", "stability", "how stability was decided: eigenvalues, march or none",
                         [](const NsMap& m) { return m.stability_method; },
                         [](NsMap& m, const std::string& v) { m.stability_method = v; }, "1")),
      R::shown(file, R::integer(
                         "/", "averaged", "1: unstable points were marched from rest (not --steady-only)",
                         [](const NsMap& m) { return opt(m.averaged); }, [](NsMap& m, double v) { m.averaged = v != 0.0; })),
      R::shown(file, R::integer(
                         "/", "orbits", "1: shedding points as periodic orbits by shooting (--orbits), marched where none was found",
                         [](const NsMap& m) { return opt(m.orbits); }, [](NsMap& m, double v) { m.orbits = v != 0.0; })),
      R::shown(file, R::num(P, "radius", "m", "cylinder radius a", [](const NsMap& m) { return opt(m.base.scene.radius); })),
      R::shown(file, R::num(P, "speed", "m/s", "freestream speed U", [](const NsMap& m) { return opt(m.base.scene.speed); })),
      R::shown(file, R::num(P, "density", "kg/m^3", "fluid density ρ", [](const NsMap& m) { return opt(m.base.scene.density); })),
      R::shown(file, R::required(R::num(
                         P, "outer_radius", "1", "outer radius of the grid over a, R/a",
                         [](const NsMap& m) { return opt(m.outer_over_a); }, [](NsMap& m, double v) { m.outer_over_a = v; }))),
      count(P, "n_theta", "angular grid points", &NsMap::n_theta),
      count(P, "n_r", "radial grid points", &NsMap::n_r),
      R::shown(file, R::required(R::num(
                         T, "total_s", "s", "wall clock of the map (summed over the shards when merged)",
                         [](const NsMap& m) { return opt(m.total_s); }, [](NsMap& m, double v) { m.total_s = v; }))),
      count(T, "threads", "threads the rows ran on (summed over the shards when merged)", &NsMap::threads),
  });
  return t;
}

}  // namespace

const std::vector<Attr<NsMap>>& ns_map_attributes() {
  static const std::vector<Attr<NsMap>> table = make_ns_map_attributes();
  return table;
}

namespace {

/// One of the map's axes: the NsMap member it holds.
Dataset<NsMap> axis(const char* name, const char* description, std::vector<double> NsMap::*m) {
  Dataset<NsMap> d{std::string("/axes/") + name, "1", description, DataShape::flat, {}, {}};
  d.values = [m](const NsMap& x) { return x.*m; };
  d.set = [m](NsMap& x, std::vector<double> v) { x.*m = std::move(v); };
  return d;
}

}  // namespace

const std::vector<Dataset<NsMap>>& ns_map_axes() {
  static const std::vector<Dataset<NsMap>> table = {
      axis("alpha", "the map's spin ratios aω/U", &NsMap::alphas),
      axis("reynolds", "the map's Reynolds numbers", &NsMap::reynolds),
  };
  return table;
}

}  // namespace magnus
