#include <catch2/catch.hpp>
#include <cmath>

#include "io/case_file.hpp"
#include "io/case_parse.hpp"

using namespace magnus;
using test::error_of;
using test::parse;

namespace {
/// The scene keys a case file requires, as the sections [cylinder] and [flow], for tests about other keys.
const std::string scene = "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n";
}  // namespace

TEST_CASE("the scene's physical keys are required: no silent demo", "[app][case]") {
  const std::string spin_missing =
      "test.toml: cylinder.spin: required key is missing: give one of cylinder.spin (rad/s), "
      "cylinder.spin_ratio or "
      "cylinder.rpm, or circulation.model = \"given\" with circulation.value";
  CHECK(error_of("") == "test.toml: cylinder.radius: required key is missing (the cylinder radius a, m)");
  CHECK(error_of("[cylinder]\nradius = 0.1\nspin = 1.0\n") ==
        "test.toml: flow.speed: required key is missing (the freestream speed U, m/s)");
  CHECK(error_of("[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n") == spin_missing);
  CHECK(error_of("[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n[circulation]\nmodel = \"given\"\n") ==
        "test.toml: circulation.value: is required with circulation.model = \"given\"");
  CHECK(error_of("[cylinder]\nradius = 0.1\nrpm = 60\nspin = 1.0\n[flow]\nspeed = 10.0\n") ==
        "test.toml: cylinder.rpm: conflicts with cylinder.spin: give exactly one of them");
  // The given model needs no spin (ω = 0); rpm is 2π/60 rad/s per rev/min; --set supplies keys too.
  const Case g = parse(
      "[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n[circulation]\nmodel = \"given\"\nvalue = 2.0\n");
  CHECK(g.scene.spin == 0.0);
  CHECK(g.scene.Gamma() == 2.0);
  CHECK(parse("[cylinder]\nradius = 0.1\nrpm = 60\n[flow]\nspeed = 10.0\n").scene.spin ==
        2.0 * M_PI / 60.0 * 60.0);
  CHECK(parse("", {"cylinder.radius=0.5", "flow.speed=2", "cylinder.spin=4"}).scene.spin_ratio() == 1.0);
  // An override of one of {spin, spin_ratio, rpm} replaces the others of the group.
  CHECK(parse(scene, {"cylinder.spin_ratio=2"}).scene.spin == 200.0);
  CHECK(parse(scene, {"cylinder.rpm=0"}).scene.spin == 0.0);
}

TEST_CASE("numerical keys keep their defaults", "[app][case]") {
  const Case c = parse(scene);
  REQUIRE(c.scene.radius == 0.1);
  REQUIRE(c.scene.spin == 100.0);
  REQUIRE(c.scene.speed == 10.0);
  REQUIRE(c.scene.density == 1.225);
  REQUIRE(c.scene.spin_ratio() == Approx(1.0));
  REQUIRE(c.grid.n_theta == 256);
  REQUIRE(c.grid.far_field == FarField::exact);
  REQUIRE(c.grid.spacing == Spacing::geometric);
  REQUIRE(c.solver.method == Method::automatic);
  REQUIRE(c.output.file == "magnus.h5");
  REQUIRE(c.scene.Gamma() == Approx(2 * M_PI * 0.01 * 100));
}

TEST_CASE("spin_ratio sets ω = αU/a, the model 'given' sets Γ", "[app][case]") {
  const Case c = parse("[cylinder]\nradius = 0.5\nspin_ratio = 2\n[flow]\nspeed = 4.0\n");
  REQUIRE(c.scene.spin == Approx(16.0));
  const Case g = parse(scene + "[circulation]\nmodel = \"given\"\nvalue = -3.5\n");
  REQUIRE(g.scene.Gamma() == -3.5);
}

TEST_CASE("overrides (--set): TOML values, bare words are strings", "[app][case]") {
  const Case c = parse(scene + "[grid]\nn_theta = 64\n", {"grid.n_theta=128", "solver.method=cholmod",
                                                          "output.fields=[\"psi\", \"cp\"]", "title=hello"});
  REQUIRE(c.grid.n_theta == 128);
  REQUIRE(c.solver.method == Method::cholmod);
  REQUIRE(*c.output.fields == std::vector<std::string>{"psi", "cp"});
  REQUIRE_FALSE(parse(scene).output.fields.has_value());
  REQUIRE(parse(scene + "[output]\nfields = []\n").output.fields->empty());
  REQUIRE(c.title == "hello");
}

TEST_CASE("the resolved case round-trips through TOML", "[app][case]") {
  const Case c = parse(
      "[cylinder]\nradius = 0.1\nspin_ratio = 3\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 64\nspacing = "
      "\"uniform\"\n");
  const Case d = parse(to_toml(c));
  REQUIRE(d.scene.spin == c.scene.spin);
  REQUIRE(d.grid.n_theta == 64);
  REQUIRE(d.grid.spacing == Spacing::uniform);
  REQUIRE(to_toml(d) == to_toml(c));
}

TEST_CASE("bad input names the key and the problem", "[app][case]") {
  using Catch::Contains;
  REQUIRE_THROWS_WITH(parse("[grid\nn_theta = 3"), Contains("test.toml:1") && Contains("malformed TOML"));
  REQUIRE_THROWS_WITH(parse(scene + "[grid]\nn_thetaa = 64\n"),
                      Contains("grid.n_thetaa") && Contains("did you mean grid.n_theta"));
  REQUIRE_THROWS_WITH(parse(scene + "[gird]\nn_theta = 64\n"), Contains("[gird]") && Contains("[grid]"));
  REQUIRE_THROWS_WITH(parse(scene + "[grid]\nn_theta = \"many\"\n"),
                      Contains("grid.n_theta") && Contains("expected an integer"));
  REQUIRE_THROWS_WITH(parse("[cylinder]\nradius = 0.1\nspin = 1.0\n[flow]\nspeed = -1.0\n"),
                      Contains("flow.speed") && Contains("out of range"));
  REQUIRE_THROWS_WITH(parse("[cylinder]\nradius = 0.1\nspin = 1.0\n[flow]\nspeed = 1.0\ndensity = nan\n"),
                      Contains("flow.density") && Contains("finite"));
  REQUIRE_THROWS_WITH(parse("[cylinder]\nradius = inf\nspin = 1.0\n[flow]\nspeed = 1.0\n"),
                      Contains("cylinder.radius") && Contains("finite"));
  REQUIRE_THROWS_WITH(parse("[cylinder]\nradius = 0.1\nspin = 1.0\nspin_ratio = 1.0\n[flow]\nspeed = 1.0\n"),
                      Contains("spin_ratio") && Contains("exactly one"));
  REQUIRE_THROWS_WITH(parse(scene + "[grid]\nn_theta = 255\n"), Contains("grid.n_theta") && Contains("even"));
  REQUIRE_THROWS_WITH(parse(scene + "[grid]\nn_theta = 6\n"), Contains("grid.n_theta") && Contains(">= 8"));
  REQUIRE_THROWS_WITH(parse(scene + "[domain]\nouter_radius = 1.0\n"),
                      Contains("domain.outer_radius") && Contains("> 1"));
  REQUIRE_THROWS_WITH(parse(scene + "[domain]\nfar_field = \"far\"\n"),
                      Contains("domain.far_field") && Contains("\"exact\""));
  REQUIRE_THROWS_WITH(parse(scene + "[circulation]\nmodel = \"given\"\n"),
                      Contains("circulation.value") && Contains("required"));
  REQUIRE_THROWS_WITH(parse(scene + "[circulation]\nvalue = 2.0\n"), Contains("circulation.value"));
  REQUIRE_THROWS_WITH(parse(scene + "[grid]\nspacing = \"uniform\"\n[solver]\nstencil = \"9-point\"\n"),
                      Contains("solver.stencil"));
  REQUIRE_THROWS_WITH(parse(scene + "[output]\nfields = [\"psi\", \"vorticity\"]\n"),
                      Contains("output.fields") && Contains("vorticity"));
  REQUIRE_THROWS_WITH(parse(scene, {"grid.n_thetaa=64"}), Contains("--set") && Contains("grid.n_theta"));
  REQUIRE_THROWS_WITH(parse(scene, {"grid.n_theta"}), Contains("--set") && Contains("section.key=value"));
  REQUIRE_THROWS_WITH(parse("[flow]\nspeed = 0.0\n[cylinder]\nradius = 0.1\nspin_ratio = 1.0\n"),
                      Contains("cylinder.spin_ratio"));
  REQUIRE_THROWS_WITH(load_case("/nonexistent/case.toml"), Contains("/nonexistent/case.toml"));
}

TEST_CASE("nearest key suggestions", "[app][case]") {
  REQUIRE(nearest_key("grid.ntheta") == "grid.n_theta");
  REQUIRE(nearest_key("flow.sped") == "flow.speed");
  REQUIRE(nearest_key("cylinder.spinratio") == "cylinder.spin_ratio");
  REQUIRE(nearest_key("completely.unrelated_thing_here") == "");
}

TEST_CASE("output.compression: a gzip level 0 to 9, kept in the resolved case", "[io][case]") {
  REQUIRE(parse(scene).output.compression == 0);
  const Case c = parse(scene + "[output]\ncompression = 6\n");
  REQUIRE(c.output.compression == 6);
  REQUIRE(parse(to_toml(c)).output.compression == 6);
  REQUIRE(error_of(scene + "[output]\ncompression = 10\n").find("output.compression") != std::string::npos);
  REQUIRE(error_of(scene + "[output]\ncompression = 1.5\n").find("expected an integer") != std::string::npos);
}

TEST_CASE("a bad value given with --set is blamed on --set, not on the case file", "[app][case]") {
  CHECK(error_of(scene, {"model.flow=navier-stoke"}) ==
        "--set model.flow: \"navier-stoke\" is not one of \"potential\", \"navier-stokes\"");
  CHECK(error_of(scene, {"solver.method=ftt"}) ==
        "--set solver.method: \"ftt\" is not one of \"auto\", \"cholmod\", \"fft\"");
  CHECK(error_of(scene, {"grid.n_theta=7"}).rfind("--set grid.n_theta: 7 is out of range", 0) == 0);
  CHECK(error_of(scene, {"flow.viscosity=-1e-6"}).rfind("--set flow.viscosity: -1e-06 is out of range", 0) == 0);
  // The same value in the file is the file's.
  CHECK(error_of(scene + "[grid]\nn_theta = 7\n").rfind("test.toml: grid.n_theta: 7 is out of range", 0) == 0);
  // A key the override did not touch is still the file's, overrides or not.
  CHECK(error_of(scene + "[solver]\nmethod = \"ftt\"\n", {"grid.n_theta=64"})
            .rfind("test.toml: solver.method:", 0) == 0);
}

TEST_CASE("quoted input is cut to 60 characters, refused values show 6 digits unless more are needed",
          "[app][case]") {
  const std::string huge(1000000, 'x');
  for (const std::string& msg :
       {error_of(scene, {"flow." + huge + "=1"}), error_of(scene + "[domain]\n" + huge + " = 1\n"),
        error_of(scene, {"model.flow=" + huge}), error_of(scene + "[" + huge + "]\n")}) {
    CAPTURE(msg.substr(0, 200));
    CHECK(!msg.empty());
    CHECK(msg.size() < 400);
    CHECK(msg.find("xxxxxxxxxx…") != std::string::npos);
    CHECK(msg.find(std::string(61, 'x')) == std::string::npos);
  }
  // 400.5 needs no more than 6 digits to be out of [-360, 360]; 360.00000000000006 does (360 is in range).
  CHECK(error_of(scene, {"flow.direction=400.50000000000006"}) ==
        "--set flow.direction: 400.5 is out of range: must be in [-360, 360] (deg, CCW from +x)");
  CHECK(error_of(scene, {"flow.direction=360.00000000000006"}) ==
        "--set flow.direction: 360.00000000000006 is out of range: must be in [-360, 360] (deg, CCW from "
        "+x)");
}

TEST_CASE("an overflow is blamed on the key whose value causes it", "[app][case]") {
  // ω = αU/a is tiny only because a is huge: the radius is named, not cylinder.spin_ratio.
  const std::string e =
      error_of("[cylinder]\nradius = 1e308\nspin_ratio = 0.5\n[flow]\nspeed = 1.0\n");
  CHECK(e.rfind("test.toml: cylinder.radius: 1e+308 is too large", 0) == 0);
  // A spin ratio that is itself extreme is still named.
  CHECK(error_of("[cylinder]\nradius = 1.0\nspin_ratio = 1e300\n[flow]\nspeed = 1e10\n")
            .rfind("test.toml: cylinder.spin_ratio:", 0) == 0);
}

TEST_CASE("a navier-stokes run of more than kNsMaxSteps time steps is refused", "[app][case]") {
  const std::string ns = "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 1.0\n"
                         "[flow]\nspeed = 1.0\nreynolds = 100.0\n[time]\nend = 100.0\n";
  CHECK(error_of(ns, {"time.dt=1e-300"}) ==
        "--set time.dt: 1e-300 gives time.end/time.dt = 1e+302 steps, more than the 1e+07 a run may take");
  CHECK(error_of(ns + "dt = 8e-6\n") ==
        "test.toml: time.dt: 8e-06 gives time.end/time.dt = 1.25e+07 steps, more than the 1e+07 a run may take");
  CHECK(error_of(ns + "dt = 2e-5\n").empty());  // five million steps: accepted
}
