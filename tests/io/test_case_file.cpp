#include <catch2/catch.hpp>
#include <cmath>

#include "io/case_file.hpp"

using namespace magnus;

namespace {
Case parse(const std::string& text, const std::vector<std::string>& sets = {}) {
  return parse_case(text, "test.toml", sets);
}
}  // namespace

TEST_CASE("defaults: an empty case is the spin-ratio-1 demo", "[app][case]") {
  const Case c = parse("");
  REQUIRE(c.scene.radius == 0.1);
  REQUIRE(c.scene.spin == 100.0);
  REQUIRE(c.scene.speed == 10.0);
  REQUIRE(c.scene.spin_ratio() == Approx(1.0));
  REQUIRE(c.grid.n_theta == 256);
  REQUIRE(c.grid.far_field == FarField::exact);
  REQUIRE(c.grid.spacing == Spacing::geometric);
  REQUIRE(c.solver.method == Method::automatic);
  REQUIRE(c.output.file == "magnus.h5");
  REQUIRE(c.scene.Gamma() == Approx(2 * M_PI * 0.01 * 100));
}

TEST_CASE("spin_ratio sets ω = αU/a; the model 'given' sets Γ", "[app][case]") {
  const Case c = parse("[cylinder]\nradius = 0.5\nspin_ratio = 2\n[flow]\nspeed = 4.0\n");
  REQUIRE(c.scene.spin == Approx(16.0));
  const Case g = parse("[circulation]\nmodel = \"given\"\nvalue = -3.5\n");
  REQUIRE(g.scene.Gamma() == -3.5);
}

TEST_CASE("overrides (--set): TOML values, bare words are strings", "[app][case]") {
  const Case c = parse("[grid]\nn_theta = 64\n", {"grid.n_theta=128", "solver.method=cholmod",
                                                  "output.fields=[\"psi\", \"cp\"]", "title=hello"});
  REQUIRE(c.grid.n_theta == 128);
  REQUIRE(c.solver.method == Method::cholmod);
  REQUIRE(*c.output.fields == std::vector<std::string>{"psi", "cp"});
  REQUIRE_FALSE(parse("").output.fields.has_value());
  REQUIRE(parse("[output]\nfields = []\n").output.fields->empty());
  REQUIRE(c.title == "hello");
}

TEST_CASE("the resolved case round-trips through TOML", "[app][case]") {
  const Case c = parse("[cylinder]\nspin_ratio = 3\n[grid]\nn_theta = 64\nspacing = \"uniform\"\n");
  const Case d = parse(to_toml(c));
  REQUIRE(d.scene.spin == c.scene.spin);
  REQUIRE(d.grid.n_theta == 64);
  REQUIRE(d.grid.spacing == Spacing::uniform);
  REQUIRE(to_toml(d) == to_toml(c));
}

TEST_CASE("bad input names the key and the problem", "[app][case]") {
  using Catch::Contains;
  REQUIRE_THROWS_WITH(parse("[grid\nn_theta = 3"), Contains("test.toml:1") && Contains("malformed TOML"));
  REQUIRE_THROWS_WITH(parse("[grid]\nn_thetaa = 64\n"), Contains("grid.n_thetaa") && Contains("did you mean grid.n_theta"));
  REQUIRE_THROWS_WITH(parse("[gird]\nn_theta = 64\n"), Contains("[gird]") && Contains("[grid]"));
  REQUIRE_THROWS_WITH(parse("[grid]\nn_theta = \"many\"\n"), Contains("grid.n_theta") && Contains("expected an integer"));
  REQUIRE_THROWS_WITH(parse("[flow]\nspeed = -1.0\n"), Contains("flow.speed") && Contains("out of range"));
  REQUIRE_THROWS_WITH(parse("[flow]\ndensity = nan\n"), Contains("flow.density") && Contains("finite"));
  REQUIRE_THROWS_WITH(parse("[cylinder]\nradius = inf\n"), Contains("cylinder.radius") && Contains("finite"));
  REQUIRE_THROWS_WITH(parse("[cylinder]\nspin = 1.0\nspin_ratio = 1.0\n"), Contains("spin_ratio") && Contains("exactly one"));
  REQUIRE_THROWS_WITH(parse("[grid]\nn_theta = 255\n"), Contains("grid.n_theta") && Contains("even"));
  REQUIRE_THROWS_WITH(parse("[grid]\nn_theta = 6\n"), Contains("grid.n_theta") && Contains(">= 8"));
  REQUIRE_THROWS_WITH(parse("[domain]\nouter_radius = 1.0\n"), Contains("domain.outer_radius") && Contains("> 1"));
  REQUIRE_THROWS_WITH(parse("[domain]\nfar_field = \"far\"\n"), Contains("domain.far_field") && Contains("\"exact\""));
  REQUIRE_THROWS_WITH(parse("[circulation]\nmodel = \"given\"\n"), Contains("circulation.value") && Contains("required"));
  REQUIRE_THROWS_WITH(parse("[circulation]\nvalue = 2.0\n"), Contains("circulation.value"));
  REQUIRE_THROWS_WITH(parse("[grid]\nspacing = \"uniform\"\n[solver]\nstencil = \"9-point\"\n"), Contains("solver.stencil"));
  REQUIRE_THROWS_WITH(parse("[output]\nfields = [\"psi\", \"vorticity\"]\n"), Contains("output.fields") && Contains("vorticity"));
  REQUIRE_THROWS_WITH(parse("", {"grid.n_thetaa=64"}), Contains("--set") && Contains("grid.n_theta"));
  REQUIRE_THROWS_WITH(parse("", {"grid.n_theta"}), Contains("--set") && Contains("section.key=value"));
  REQUIRE_THROWS_WITH(parse("[flow]\nspeed = 0.0\n[cylinder]\nspin_ratio = 1.0\n"), Contains("cylinder.spin_ratio"));
  REQUIRE_THROWS_WITH(load_case("/nonexistent/case.toml"), Contains("/nonexistent/case.toml"));
}

TEST_CASE("nearest key suggestions", "[app][case]") {
  REQUIRE(nearest_key("grid.ntheta") == "grid.n_theta");
  REQUIRE(nearest_key("flow.sped") == "flow.speed");
  REQUIRE(nearest_key("cylinder.spinratio") == "cylinder.spin_ratio");
  REQUIRE(nearest_key("completely.unrelated_thing_here") == "");
}
