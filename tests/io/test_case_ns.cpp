// The navier-stokes case keys: model.flow, flow.viscosity or flow.reynolds, [time] and the
// snapshot keys; what each model refuses of the other's keys; the defaults; and the resolved text, which
// must read back to itself and leave a potential case's text as it was.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "io/case_parse.hpp"
#include "postproc/navier_stokes/run.hpp"

using namespace magnus;
using Catch::Contains;
using test::error_of;
using test::parse;

namespace {

/// A potential scene: a = 0.1 m, ω = 100 rad/s, U = 10 m/s.
const std::string scene = "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n";
/// A navier-stokes scene: a = 5 mm, ω = 2 rad/s, U = 1 cm/s, ν = 1e-6 m²/s (water): Re = 100, α = 1.
const std::string ns_scene =
    "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.005\nspin = 2.0\n[flow]\nspeed = 0.01\n"
    "viscosity = 1e-6\n";
/// ns_scene with `flow_lines` in place of its flow.viscosity ("" for none), then `more`.
std::string ns_with(const std::string& flow_lines, const std::string& more = "") {
  return "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.005\nspin = 2.0\n[flow]\nspeed = 0.01\n" +
         flow_lines + more;
}
/// The resolved case reads back to itself.
void check_round_trip(const Case& c) {
  const Case d = parse_case(c.source_text, "resolved.toml");
  CHECK(d.source_text == c.source_text);
  CHECK(to_toml(d) == to_toml(c));
  CHECK(d.model == c.model);
  CHECK(d.scene.viscosity == c.scene.viscosity);
  CHECK(d.scene.reynolds_given == c.scene.reynolds_given);
  CHECK(d.scene.reynolds_value == c.scene.reynolds_value);
}

}  // namespace

TEST_CASE("model.flow: potential by default, navier-stokes with its own defaults", "[io][case]") {
  const Case p = parse(scene);
  CHECK(p.model == FlowModel::potential);
  CHECK(p.scene.viscosity == 0.0);
  CHECK_FALSE(p.scene.reynolds_given);
  CHECK(p.grid.outer_radius == 20.0);
  CHECK(p.grid.n_theta == 256);
  CHECK(parse("[model]\nflow = \"potential\"\n" + scene).source_text == p.source_text);

  const Case n = parse(ns_scene);
  CHECK(n.model == FlowModel::navier_stokes);
  CHECK(n.scene.viscosity == 1e-6);
  CHECK_FALSE(n.scene.reynolds_given);
  CHECK(n.scene.reynolds() == Approx(100.0));
  CHECK(n.scene.spin_ratio() == Approx(1.0));
  CHECK(n.grid.outer_radius == kNsDefaultOuterRadius);
  CHECK(n.grid.n_theta == kNsDefaultNTheta);
  CHECK(n.grid.n_r == 0);
  CHECK(n.grid.spacing == Spacing::geometric);
  CHECK(n.grid.tolerance == 0.0);
  // [time] and the snapshots keep the defaults of physics/scene.hpp.
  const TimeRequest t;
  CHECK(n.time.mode == TimeMode::automatic);
  CHECK(n.time.end == t.end);
  CHECK(n.time.dt == t.dt);
  CHECK(n.time.cfl == t.cfl);
  CHECK(n.time.mean_tolerance == t.mean_tolerance);
  CHECK(n.time.checkpoint_interval == t.checkpoint_interval);
  CHECK(n.output.snapshots == 0);
  CHECK(n.output.snapshot_interval == OutputRequest().snapshot_interval);
  // Keys that are given win over the model's defaults; grid.spacing = "geometric" may be stated.
  const Case g = parse(ns_scene +
                       "[domain]\nouter_radius = 40\n[grid]\nn_theta = 64\nn_r = 50\n"
                       "spacing = \"geometric\"\n");
  CHECK(g.grid.outer_radius == 40.0);
  CHECK(g.grid.n_theta == 64);
  CHECK(g.grid.n_r == 50);
  // model.flow by --set; a bare word is a string.
  const Case s = parse(scene, {"model.flow=navier-stokes", "flow.viscosity=1.5e-5"});
  CHECK(s.model == FlowModel::navier_stokes);
  CHECK(s.grid.n_theta == kNsDefaultNTheta);
  CHECK(s.scene.reynolds() == Approx(10.0 * 0.2 / 1.5e-5));
  CHECK(error_of(scene, {"model.flow=viscous"}) ==
        "--set model.flow: \"viscous\" is not one of \"potential\", \"navier-stokes\"");
  CHECK(error_of("[model]\nflow = 1\n" + scene) ==
        "test.toml: model.flow: expected a string, got an integer");
}

TEST_CASE("time keys and the snapshots: every value, and every range named", "[io][case]") {
  const Case c = parse(ns_scene +
                       "[time]\nmode = \"unsteady\"\nend = 50\ndt = 0.01\ncfl = 0.8\nmean_tolerance = 0.1\n"
                       "checkpoint_interval = 0\n[output]\nsnapshots = 40\nsnapshot_interval = 0.5\n");
  CHECK(c.time.mode == TimeMode::unsteady);
  CHECK(c.time.end == 50.0);
  CHECK(c.time.dt == 0.01);
  CHECK(c.time.cfl == 0.8);
  CHECK(c.time.mean_tolerance == 0.1);
  CHECK(c.time.checkpoint_interval == 0.0);
  CHECK(c.output.snapshots == 40);
  CHECK(c.output.snapshot_interval == 0.5);
  CHECK(parse(ns_scene + "[time]\nmode = \"steady\"\n").time.mode == TimeMode::steady);
  CHECK(parse(ns_scene + "[time]\nmode = \"auto\"\n").time.mode == TimeMode::automatic);
  CHECK(parse(ns_scene + "[time]\nmode = \"periodic\"\n").time.mode == TimeMode::periodic);
  CHECK(parse(ns_scene + "[output]\nsnapshots = 10000\n").output.snapshots == 10000);
  // The scene's grid comes with its scheme: Jensen's closure, fourth order in θ where the wake sheds
  // (ns_scene: Re 100, α 1); a stated grid: 2, Thom.
  CHECK(parse(ns_scene).solver.advection_order == 4);
  CHECK(parse(ns_scene + "[grid]\nn_theta = 64\n").solver.advection_order == 2);
  CHECK(parse(ns_scene + "[solver]\nadvection_order = 2\n").solver.advection_order == 2);
  CHECK(parse(ns_scene + "[solver]\nadvection_order = 4\n").solver.advection_order == 4);
  CHECK(parse(ns_scene, {"solver.advection_order=4"}).solver.advection_order == 4);
  CHECK(parse(ns_scene).solver.advection_order_xi == 2);
  CHECK(parse(ns_scene + "[solver]\nadvection_order_xi = 4\n").solver.advection_order_xi == 4);
  CHECK(parse(ns_scene, {"solver.advection_order_xi=4"}).solver.advection_order_xi == 4);
  CHECK(parse(ns_scene).solver.wall_closure == "jensen");
  CHECK(parse(ns_scene + "[grid]\nn_theta = 64\n").solver.wall_closure == "thom");
  CHECK(parse(ns_scene, {"solver.wall_closure=thom"}).solver.wall_closure == "thom");
  CHECK(parse(ns_scene + "[solver]\nwall_closure = \"jensen\"\n").solver.wall_closure == "jensen");
  CHECK(parse(ns_scene, {"solver.wall_closure=jensen"}).solver.wall_closure == "jensen");
  CHECK(ns_params(parse(ns_scene)).wall_closure == NsWallClosure::jensen);
  CHECK(ns_params(parse(ns_scene, {"solver.wall_closure=thom"})).wall_closure == NsWallClosure::thom);
  CHECK(ns_params(parse(ns_scene, {"solver.wall_closure=jensen"})).wall_closure == NsWallClosure::jensen);
  CHECK(parse(ns_scene).solver.implicit_rotation);
  CHECK(!parse(ns_scene + "[solver]\nimplicit_rotation = false\n").solver.implicit_rotation);
  CHECK(!parse(ns_scene, {"solver.implicit_rotation=false"}).solver.implicit_rotation);
  CHECK(ns_params(parse(ns_scene)).implicit_rotation);
  CHECK(!ns_params(parse(ns_scene, {"solver.implicit_rotation=false"})).implicit_rotation);

  const std::vector<std::pair<std::string, std::string>> bad = {
      {"[time]\nmode = \"fast\"\n",
       "test.toml: time.mode: \"fast\" is not one of \"auto\", \"steady\", \"unsteady\", \"periodic\""},
      {"[time]\nend = 0\n", "test.toml: time.end: 0 is out of range: must be > 0 (D/U)"},
      {"[time]\nend = -3.0\n", "test.toml: time.end: -3 is out of range: must be > 0 (D/U)"},
      {"[time]\nend = inf\n", "test.toml: time.end: must be finite, got inf"},
      {"[time]\ndt = -0.1\n",
       "test.toml: time.dt: -0.1 is out of range: must be >= 0 (D/U; 0: from time.cfl)"},
      {"[time]\ncfl = 0\n", "test.toml: time.cfl: 0 is out of range: must be > 0 and <= 0.8"},
      {"[time]\ncfl = 0.81\n", "test.toml: time.cfl: 0.81 is out of range: must be > 0 and <= 0.8"},
      {"[time]\nmean_tolerance = 0\n",
       "test.toml: time.mean_tolerance: 0 is out of range: must be > 0 and <= 0.1"},
      {"[time]\nmean_tolerance = 0.2\n",
       "test.toml: time.mean_tolerance: 0.2 is out of range: must be > 0 and <= 0.1"},
      {"[time]\ncheckpoint_interval = -1\n",
       "test.toml: time.checkpoint_interval: -1 is out of range: must be >= 0 (D/U; 0: none)"},
      {"[output]\nsnapshots = -1\n",
       "test.toml: output.snapshots: -1 is out of range: must be an integer from 0 (none) to 10000"},
      {"[output]\nsnapshots = 10001\n",
       "test.toml: output.snapshots: 10001 is out of range: must be an integer from 0 (none) to 10000"},
      {"[output]\nsnapshots = 2.5\n", "test.toml: output.snapshots: expected an integer, got a float"},
      {"[output]\nsnapshot_interval = 0\n",
       "test.toml: output.snapshot_interval: 0 is out of range: must be > 0 (D/U)"},
      {"[time]\nend = \"long\"\n", "test.toml: time.end: expected a number, got a string"},
      {"[solver]\nadvection_order = 3\n",
       "test.toml: solver.advection_order: 3 is out of range: must be 2 (Arakawa's Jacobian) or 4 (fourth "
       "order in θ)"},
      {"[solver]\nadvection_order = 4.0\n",
       "test.toml: solver.advection_order: expected an integer, got a float"},
      {"[solver]\nadvection_order_xi = 6\n",
       "test.toml: solver.advection_order_xi: 6 is out of range: must be 2 (Arakawa's Jacobian) or 4 (fourth "
       "order in ξ)"},
      {"[solver]\nwall_closure = \"briley\"\n",
       "test.toml: solver.wall_closure: \"briley\" is not one of \"thom\", \"jensen\""},
      {"[solver]\nimplicit_rotation = 0\n",
       "test.toml: solver.implicit_rotation: expected true or false, got an integer"},
      {"[solver]\nimplicit_rotation = \"no\"\n",
       "test.toml: solver.implicit_rotation: expected true or false, got a string"},
  };
  for (const auto& [text, message] : bad) {
    CAPTURE(text);
    CHECK(error_of(ns_scene + text) == message);
  }
}

TEST_CASE("potential flow: the keys of [time] and the snapshots are refused by name", "[io][case]") {
  for (const char* key : {"mode = \"auto\"", "end = 300.0", "dt = 0.0", "cfl = 0.5", "mean_tolerance = 1e-3",
                          "checkpoint_interval = 10.0"}) {
    const std::string k(key);
    CAPTURE(k);
    CHECK(error_of(scene + "[time]\n" + k + "\n") ==
          "test.toml: time." + k.substr(0, k.find(' ')) +
              ": is only used with model.flow = \"navier-stokes\"");
  }
  CHECK(error_of(scene + "[solver]\nadvection_order = 4\n") ==
        "test.toml: solver.advection_order: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of(scene + "[solver]\nadvection_order_xi = 4\n") ==
        "test.toml: solver.advection_order_xi: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of(scene + "[solver]\nwall_closure = \"jensen\"\n") ==
        "test.toml: solver.wall_closure: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of(scene + "[solver]\nimplicit_rotation = false\n") ==
        "test.toml: solver.implicit_rotation: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of(scene + "[output]\nsnapshots = 10\n") ==
        "test.toml: output.snapshots: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of(scene + "[output]\nsnapshot_interval = 1.0\n") ==
        "test.toml: output.snapshot_interval: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of(scene, {"time.end=20"}) ==
        "--set time.end: is only used with model.flow = \"navier-stokes\"");
  CHECK(error_of("[model]\nflow = \"potential\"\n" + scene + "[time]\nend = 20\n") ==
        "test.toml: time.end: is only used with model.flow = \"navier-stokes\"");
  // An empty [time] holds no key: nothing to refuse.
  CHECK(error_of(scene + "[time]\n") == "");
}

TEST_CASE("navier-stokes: potential flow's circulation, far field, solver and tolerance are refused",
          "[io][case]") {
  const std::string circulation = ": navier-stokes computes the circulation (an output of the viscous model)";
  CHECK(error_of(ns_scene + "[circulation]\nmodel = \"given\"\nvalue = 1.0\n") ==
        "test.toml: circulation.model: \"given\" is only used with model.flow = \"potential\"" + circulation);
  CHECK(error_of(ns_scene + "[circulation]\nvalue = 1.0\n") ==
        "test.toml: circulation.value: is only used with model.flow = \"potential\"" + circulation);
  CHECK(
      error_of(ns_scene + "[grid]\nspacing = \"uniform\"\n") ==
      "test.toml: grid.spacing: \"uniform\" is only used with model.flow = \"potential\": the navier-stokes "
      "grid is geometric");
  CHECK(
      error_of(ns_scene + "[domain]\nfar_field = \"exact\"\n") ==
      "test.toml: domain.far_field: is only used with model.flow = \"potential\": navier-stokes sets its own "
      "far-field conditions");
  // navier-stokes takes grid.tolerance from 1e-4 (its own error estimate's floor) to 0.1.
  CHECK(error_of(ns_scene + "[grid]\ntolerance = 1e-6\n") ==
        "test.toml: grid.tolerance: 1e-06 is out of range: must be 0 (the scene's grid) or 1e-4 ... 0.1 "
        "(navier-stokes: relative, on mean C_L, C_D and St; below 1e-4 the run's own error estimate is not "
        "reliable)");
  CHECK_NOTHROW(parse_case(ns_scene + "[grid]\ntolerance = 1e-3\n", "test.toml"));
  CHECK_THAT(error_of(ns_scene + "[grid]\ntolerance = 1e-3\nrefine = 2\n"),
             Contains("grid.tolerance: conflicts with grid.refine"));
  CHECK_THAT(error_of(ns_scene + "[grid]\nrefine = 0.1\n"), Contains("grid.refine: 0.1 is out of range"));
  CHECK_THAT(error_of(scene + "[grid]\nrefine = 2\n"),
             Contains("grid.refine: is only used with model.flow = \"navier-stokes\""));
  CHECK(error_of(ns_scene + "[solver]\nmethod = \"auto\"\n") ==
        "test.toml: solver.method: is only used with model.flow = \"potential\": navier-stokes has its own "
        "solver");
  CHECK(error_of(ns_scene + "[solver]\nstencil = \"5-point\"\n") ==
        "test.toml: solver.stencil: is only used with model.flow = \"potential\": navier-stokes has its own "
        "discretisation");
  // The same by --set, and a potential case file switched to navier-stokes keeps its potential-only keys.
  CHECK_THAT(error_of(ns_scene, {"grid.tolerance=1e-6"}), Contains("--set grid.tolerance: 1e-06 is out of range"));
  CHECK_THAT(error_of(ns_scene, {"solver.method=fft"}), Contains("--set solver.method: is only used"));
  CHECK_THAT(error_of(scene + "[domain]\nfar_field = \"freestream\"\n",
                      {"model.flow=navier-stokes", "flow.viscosity=1e-5"}),
             Contains("test.toml: domain.far_field: is only used with model.flow = \"potential\""));
  // circulation.model = "spin" says nothing the viscous model contradicts: accepted, not echoed.
  CHECK(parse(ns_scene + "[circulation]\nmodel = \"spin\"\n").source_text == parse(ns_scene).source_text);
  // The spin is required, and "given" is no way out of it.
  CHECK(error_of("[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.005\n[flow]\nspeed = 0.01\n"
                 "viscosity = 1e-6\n") ==
        "test.toml: cylinder.spin: required key is missing: give one of cylinder.spin (rad/s), "
        "cylinder.spin_ratio or cylinder.rpm");
  // n_theta is checked as for potential flow.
  CHECK_THAT(error_of(ns_scene + "[grid]\nn_theta = 63\n"), Contains("grid.n_theta") && Contains("even"));
  CHECK_THAT(error_of(ns_scene + "[grid]\nn_theta = 6\n"), Contains("grid.n_theta") && Contains(">= 8"));
  CHECK(parse(ns_scene + "[grid]\nn_theta = 8\n").grid.n_theta == 8);
}

TEST_CASE("flow.viscosity or flow.reynolds: exactly one, in range, with a speed for Re", "[io][case]") {
  // Re = U·2a/ν sets ν from U and a.
  const Case r = parse(ns_with("reynolds = 100\n"));
  CHECK(r.scene.reynolds_given);
  CHECK(r.scene.reynolds_value == 100.0);
  CHECK(r.scene.viscosity == 0.01 * 2.0 * 0.005 / 100.0);
  CHECK(r.scene.reynolds() == Approx(100.0));

  CHECK(error_of(ns_with("")) ==
        "test.toml: flow.viscosity: required key is missing: model.flow = \"navier-stokes\" needs "
        "flow.viscosity (nu, m^2/s) or flow.reynolds (Re = U*2a/nu)");
  CHECK(error_of(ns_with("viscosity = 1e-6\nreynolds = 100\n")) ==
        "test.toml: flow.reynolds: conflicts with flow.viscosity: give exactly one of them");
  CHECK(error_of(scene + "viscosity = 1e-6\nreynolds = 100\n") ==
        "test.toml: flow.reynolds: conflicts with flow.viscosity: give exactly one of them");
  CHECK(error_of(ns_with("viscosity = 0\n")) ==
        "test.toml: flow.viscosity: 0 is out of range: must be > 0 (m^2/s)");
  CHECK(error_of(ns_with("viscosity = -1e-6\n")) ==
        "test.toml: flow.viscosity: -1e-06 is out of range: must be > 0 (m^2/s)");
  CHECK(error_of(ns_with("viscosity = nan\n")) == "test.toml: flow.viscosity: must be finite, got nan");
  CHECK(error_of(ns_with("reynolds = 0\n")) ==
        "test.toml: flow.reynolds: 0 is out of range: must be > 0 (Re = U*2a/nu)");
  CHECK(error_of(ns_with("reynolds = inf\n")) == "test.toml: flow.reynolds: must be finite, got inf");
  CHECK(error_of(ns_with("reynolds = \"100\"\n")) ==
        "test.toml: flow.reynolds: expected a number, got a string");
  // Re cannot define ν without a speed, in either model.
  const std::string no_speed =
      "test.toml: flow.reynolds: needs flow.speed > 0 (Re = U*2a/nu); give flow.viscosity instead";
  CHECK(error_of(ns_with("reynolds = 100\n"), {"flow.speed=0"}) == no_speed);
  CHECK(error_of(scene + "reynolds = 100\n", {"flow.speed=0"}) == no_speed);
  // Re and ν must be finite and normal: a tiny ν with a large U·2a, a huge Re with a tiny U·2a.
  CHECK(error_of("[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 1e10\nspin = 1.0\n[flow]\n"
                 "speed = 1e10\nviscosity = 1e-300\n") ==
        "test.toml: flow.viscosity: 1e-300 is too small: the Reynolds number Re = U·2a/ν is not finite");
  CHECK(
      error_of("[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 1e-10\nspin = 100.0\n[flow]\n"
               "speed = 1e-10\nreynolds = 1e300\n") ==
      "test.toml: flow.reynolds: 1e+300 is too large: the viscosity ν = U·2a/Re underflows double precision");
  CHECK(error_of("[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 1e10\nspin = 1e10\n[flow]\n"
                 "speed = 0\nviscosity = 1e-300\n") ==
        "test.toml: flow.viscosity: 1e-300 is too small: the wall Reynolds number a|ω|·2a/ν is not finite");
  // The same checks for a potential case that reports its viscosity.
  CHECK_THAT(error_of("[cylinder]\nradius = 1e10\nspin = 1.0\n[flow]\nspeed = 1e10\nviscosity = 1e-300\n"),
             Contains("flow.viscosity") && Contains("Re = U·2a/ν is not finite"));
}

TEST_CASE("an override of flow.viscosity or flow.reynolds replaces the other", "[io][case]") {
  const Case r = parse(ns_scene, {"flow.reynolds=200"});
  CHECK(r.scene.reynolds_given);
  CHECK(r.scene.reynolds() == Approx(200.0));
  const Case v = parse(ns_with("reynolds = 100\n"), {"flow.viscosity=2e-6"});
  CHECK_FALSE(v.scene.reynolds_given);
  CHECK(v.scene.viscosity == 2e-6);
  CHECK(v.scene.reynolds() == Approx(50.0));
  // Re stays the input when U changes: ν follows.
  const Case u = parse(ns_with("reynolds = 100\n"), {"flow.speed=0.02"});
  CHECK(u.scene.reynolds() == Approx(100.0));
  CHECK(u.scene.viscosity == Approx(2e-6));
}

TEST_CASE("navier-stokes speed: still fluid only around a spinning cylinder", "[io][case]") {
  const Case still = parse(ns_scene, {"flow.speed=0"});
  CHECK(still.scene.speed == 0.0);
  CHECK(still.scene.reference_speed() == Approx(0.005 * 2.0));
  check_round_trip(still);
  CHECK(parse(ns_scene, {"flow.speed=0", "cylinder.rpm=-30"}).scene.spin == Approx(-M_PI));
  const std::string nothing =
      "--set flow.speed: 0 needs a spinning cylinder with model.flow = \"navier-stokes\" (cylinder.spin "
      "!= "
      "0): in still fluid nothing else moves";
  CHECK(error_of(ns_scene, {"flow.speed=0", "cylinder.spin=0"}) == nothing);
  CHECK(error_of(ns_scene, {"flow.speed=0", "cylinder.spin_ratio=0"}) == nothing);
  CHECK(
      error_of(ns_scene, {"flow.speed=0", "cylinder.spin_ratio=1"}) ==
      "--set cylinder.spin_ratio: needs flow.speed > 0 (alpha = a*omega/U); give cylinder.spin instead");
  // A non-spinning cylinder in a stream is fine; potential flow keeps U = 0 with ω = 0.
  CHECK(parse(ns_scene, {"cylinder.spin=0"}).scene.spin == 0.0);
  CHECK(error_of(scene, {"flow.speed=0", "cylinder.spin=0"}) == "");
  // spin_ratio works as for potential flow: ω = αU/a.
  CHECK(parse(ns_scene, {"cylinder.spin_ratio=1.5"}).scene.spin == Approx(1.5 * 0.01 / 0.005));
}

TEST_CASE("potential flow: a viscosity is optional, reported and echoed as given", "[io][case]") {
  const Case v = parse(scene + "viscosity = 1.5e-5\n");
  CHECK(v.model == FlowModel::potential);
  CHECK(v.scene.viscosity == 1.5e-5);
  CHECK(v.scene.reynolds() == Approx(10.0 * 0.2 / 1.5e-5));
  CHECK_THAT(v.source_text,
             Contains("[flow]\nspeed = 10.0\ndensity = 1.225\npressure = 0.0\nviscosity = 1.5e-05\n"));
  check_round_trip(v);
  const Case r = parse(scene + "reynolds = 1e5\n");
  CHECK(r.scene.reynolds_given);
  CHECK(r.scene.viscosity == 10.0 * 0.2 / 1e5);
  CHECK_THAT(r.source_text, Contains("pressure = 0.0\nreynolds = 100000.0\n\n[circulation]"));
  check_round_trip(r);
}

TEST_CASE("the resolved case: potential text unchanged, navier-stokes text reads back to itself",
          "[io][case]") {
  // Byte for byte the resolved text of a potential case before the navier-stokes keys existed.
  CHECK(
      parse(scene).source_text ==
      "title = \"Spinning cylinder\"\n\n[cylinder]\nradius = 0.1\nspin = 100.0\n\n[flow]\nspeed = 10.0\n"
      "density = 1.225\npressure = 0.0\n\n[circulation]\nmodel = \"spin\"\n\n[domain]\nouter_radius = 20.0\n"
      "far_field = \"exact\"\n\n[grid]\nspacing = \"geometric\"\nn_theta = 256\nn_r = 0\n\n[solver]\n"
      "method = \"auto\"\nstencil = \"5-point\"\n\n[output]\nfile = \"magnus.h5\"\n");

  // Without a stated grid the navier-stokes text says grid.refine: the scene's rule chooses the grid again
  // from the same keys (n_θ, the rings' clustering); stated keys are kept as stated.
  const Case n = parse(ns_scene);
  CHECK(n.source_text ==
        "title = \"Spinning cylinder\"\n\n[model]\nflow = \"navier-stokes\"\n\n[cylinder]\nradius = 0.005\n"
        "spin = 2.0\n\n[flow]\nspeed = 0.01\ndensity = 1.225\npressure = 0.0\nviscosity = 1e-06\n\n[domain]\n"
        "outer_radius = 100.0\nabsorbing_layer = 50.0\nabsorbing_strength = 2.0\n\n[grid]\nspacing = \"geometric\"\nrefine = 1.0\n\n[solver]\n"
        "advection_order = 4\nadvection_order_xi = 2\nwall_closure = \"jensen\"\n\n[time]\n"
        "mode = \"auto\"\nend = 300.0\ndt = 0.0\ncfl = 0.7\nmean_tolerance = 0.001\ncheckpoint_interval = "
        "10.0\n"
        "\n[output]\nfile = \"magnus.h5\"\nsnapshots = 0\nsnapshot_interval = 0.25\n");
  check_round_trip(n);
  // A stated grid and clustering read back as stated.
  const Case g = parse(ns_scene + "[grid]\nn_theta = 64\nwall_refinement = 3\n");
  CHECK_THAT(g.source_text, Contains("n_theta = 64\nn_r = 0\nwall_refinement = 3.0\n\n[solver]"));
  // Jensen's wall closure reads back; Thom's (the default) is left out, as in texts before the key.
  const Case j = parse(ns_scene, {"solver.wall_closure=jensen"});
  CHECK_THAT(j.source_text, Contains("advection_order_xi = 2\nwall_closure = \"jensen\"\n\n[time]"));
  check_round_trip(j);
  // The explicit rotation reads back; the implicit one (the default) is left out, as in texts before the key.
  const Case e = parse(ns_scene, {"solver.implicit_rotation=false"});
  CHECK_THAT(e.source_text, Contains("advection_order_xi = 2\nwall_closure = \"jensen\"\nimplicit_rotation = false\n\n[time]"));
  check_round_trip(e);
  CHECK(g.grid.n_theta_given);
  CHECK(g.grid.wall_refinement_given);
  CHECK(!g.grid.wall_layer_given);
  check_round_trip(g);

  // Re as given (not the ν derived from it), spin_ratio resolved to ω, every [time] key and the snapshots.
  const Case r = parse(
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.005\nspin_ratio = 1\n[flow]\nspeed = 0.15\n"
      "reynolds = 100\n[time]\nmode = \"steady\"\nend = 80\ndt = 0.005\ncfl = 0.3\nmean_tolerance = 1e-4\n"
      "checkpoint_interval = 0\n[output]\nfields = [\"psi\"]\ncompression = 4\nsnapshots = 12\n"
      "snapshot_interval = 0.125\n");
  CHECK_THAT(r.source_text, Contains("\nreynolds = 100.0\n"));
  CHECK_THAT(r.source_text, !Contains("viscosity"));
  CHECK_THAT(r.source_text, Contains("\n[time]\nmode = \"steady\"\nend = 80.0\ndt = 0.005\ncfl = 0.3\n"
                                     "mean_tolerance = 0.0001\ncheckpoint_interval = 0.0\n"));
  CHECK_THAT(r.source_text, Contains("compression = 4\nsnapshots = 12\nsnapshot_interval = 0.125\n"));
  check_round_trip(r);
  const Case d = parse_case(r.source_text, "resolved.toml");
  CHECK(d.time.mode == TimeMode::steady);
  CHECK(d.time.end == 80.0);
  CHECK(d.time.dt == 0.005);
  CHECK(d.time.cfl == 0.3);
  CHECK(d.time.mean_tolerance == 1e-4);
  CHECK(d.time.checkpoint_interval == 0.0);
  CHECK(d.output.snapshots == 12);
  CHECK(d.output.snapshot_interval == 0.125);
  CHECK(d.scene.spin == r.scene.spin);
  // No key of potential flow's circulation, far field or solver in the navier-stokes text.
  for (const char* absent : {"[circulation]", "far_field", "method =", "stencil =", "\ntolerance ="})
    CHECK_THAT(n.source_text, !Contains(absent));
}

TEST_CASE("the navier-stokes keys are valid keys, with suggestions for near spellings", "[io][case]") {
  const auto& keys = case_keys();
  for (const char* k : {"model.flow", "flow.viscosity", "flow.reynolds", "time.mode", "time.end", "time.dt",
                        "time.cfl", "time.mean_tolerance", "time.checkpoint_interval", "output.snapshots",
                        "output.snapshot_interval", "solver.advection_order"})
    CHECK(std::find(keys.begin(), keys.end(), std::string(k)) != keys.end());
  CHECK(nearest_key("flow.viscosty") == "flow.viscosity");
  CHECK(nearest_key("flow.reynolds_number") == "");
  CHECK(nearest_key("flow.reynold") == "flow.reynolds");
  CHECK(nearest_key("flow.nu") == "flow.viscosity");
  CHECK(nearest_key("flow.re") == "flow.reynolds");
  CHECK(nearest_key("model") == "model.flow");
  CHECK(nearest_key("flow.model") == "model.flow");
  CHECK(nearest_key("output.snapshot") == "output.snapshots");
  CHECK(nearest_key("time.cfl_number") == "");
  CHECK(nearest_key("solver.advection_ordr") == "solver.advection_order");
  CHECK(nearest_key("time.checkpoint_intervall") == "time.checkpoint_interval");
  CHECK(error_of(ns_scene + "[time]\nends = 20\n") ==
        "test.toml: unknown key time.ends (did you mean time.end?)");
  CHECK(error_of(scene + "mu = 1e-3\n")
            .find("keys of [flow]: speed, direction, course, density, pressure, viscosity, "
                  "reynolds") != std::string::npos);
  CHECK(error_of("model = \"navier-stokes\"\n" + scene) ==
        "test.toml: unknown key model (did you mean model.flow?)");
  CHECK(error_of(scene + "[tme]\nend = 1\n") == "test.toml: unknown section [tme] (did you mean [time]?)");
}

TEST_CASE("navier-stokes: Re below 0.01 is refused by the key that sets it, potential flow only reports it",
          "[io][case]") {
  const std::string why =
      " out of range: must be >= 0.01 for navier-stokes (below it the viscous length D/Re is "
      "over 100 D: creeping flow whose forces depend on domain.outer_radius)";
  CHECK(error_of(ns_with("reynolds = 1e-3\n")) == "test.toml: flow.reynolds: 0.001 is" + why);
  CHECK(error_of(ns_with("viscosity = 1.0\n")) ==
        "test.toml: flow.viscosity: 1 gives Re = U*2a/nu = 0.0001," + why);
  CHECK(parse(ns_with("reynolds = 0.01\n")).scene.reynolds() == 0.01);
  CHECK(parse(ns_with("viscosity = 1.0\n"), {"flow.speed=0"}).scene.viscosity == 1.0);  // still fluid: no Re
  CHECK(parse(scene + "reynolds = 1e-3\n").scene.reynolds() == 1e-3);
}

TEST_CASE("domain.absorbing_layer: the scene's rule, as given, and refused out of range", "[io][case]") {
  // The rule: a layer from R/2 where the wake sheds (Re ≥ 60, α ≤ 1) and R ≥ 50a; none elsewhere.
  const Case shed = parse(ns_scene);
  CHECK(shed.grid.absorbing_layer == 50.0);
  CHECK(shed.grid.absorbing_strength == 2.0);
  CHECK(ns_params(shed).absorbing_start == 50.0);
  CHECK(ns_params(shed).absorbing_rate == Approx(2.0 * 0.01 / 0.01));  // 2 U/D in 1/s (D = 1 cm, U = 1 cm/s)
  CHECK(parse(ns_scene, {"cylinder.spin=3.6"}).grid.absorbing_layer == 0.0);  // α 1.8: steady, no layer
  CHECK(parse(ns_scene, {"domain.outer_radius=40"}).grid.absorbing_layer == 0.0);
  CHECK(parse(ns_scene, {"flow.viscosity=4e-6"}).grid.absorbing_layer == 0.0);  // Re 25
  // As given, on any scene; 0 turns the rule's layer off; both keys read back.
  const Case given = parse(ns_scene, {"domain.absorbing_layer=30", "domain.absorbing_strength=1.5"});
  CHECK(given.grid.absorbing_layer == 30.0);
  CHECK(ns_params(given).absorbing_rate == Approx(1.5));
  CHECK_THAT(given.source_text, Contains("outer_radius = 100.0\nabsorbing_layer = 30.0\nabsorbing_strength = 1.5\n"));
  check_round_trip(given);
  CHECK(parse(ns_scene, {"domain.absorbing_layer=0"}).grid.absorbing_layer == 0.0);
  CHECK(parse(ns_scene, {"cylinder.spin=3.6", "domain.absorbing_layer=40"}).grid.absorbing_layer == 40.0);
  const std::string range = " is out of range: must be 0 (none) or > 1 and < 100 = domain.outer_radius (r/a "
                            "where the layer begins)";
  CHECK(error_of(ns_scene + "[domain]\nabsorbing_layer = 100\n") == "test.toml: domain.absorbing_layer: 100" + range);
  CHECK(error_of(ns_scene + "[domain]\nabsorbing_layer = 0.5\n") == "test.toml: domain.absorbing_layer: 0.5" + range);
  CHECK(error_of(ns_scene + "[domain]\nabsorbing_strength = 0\n") ==
        "test.toml: domain.absorbing_strength: 0 is out of range: must be > 0 and <= 100 (the sink λ at R, in U/D; "
        "a|ω|/D in still fluid)");
  // A steady solve of a shedding scene gets no layer from the rule: it would only add the layer's bias.
  CHECK(parse(ns_scene, {"time.mode=steady"}).grid.absorbing_layer == 0.0);
  CHECK(parse(ns_scene, {"time.mode=periodic"}).grid.absorbing_layer == 50.0);
  CHECK(error_of(scene + "[domain]\nabsorbing_layer = 10\n") ==
        "test.toml: domain.absorbing_layer: is only used with model.flow = \"navier-stokes\"");
}

TEST_CASE("grid.tolerance on the command line supersedes the file's whole grid, its rings' map too",
          "[io][case]") {
  const std::string file = ns_scene + "[grid]\nn_theta = 288\nn_r = 240\nwall_refinement = 3.0\nwall_layer = 0.5\n";
  const Case given = parse(file);
  CHECK(given.grid.wall_refinement_given);
  CHECK(given.grid.wall_refinement == 3.0);
  const Case t = parse(file, {"grid.tolerance=0.001"});
  CHECK_FALSE(t.grid.n_theta_given);
  CHECK(t.grid.n_r == 0);
  CHECK_FALSE(t.grid.wall_refinement_given);
  CHECK_FALSE(t.grid.wall_layer_given);
  CHECK(t.grid.wall_refinement == kNsDefaultWallRefinement);
}
