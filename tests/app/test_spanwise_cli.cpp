// magnus stability --spanwise: the 3D scan per wavenumber, its verdict in the JSON, refusals before solving.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/hdf5_io.hpp"
#include "io/schema_io.hpp"
#include "support.hpp"

using namespace magnus::test;

namespace {
const std::string s_map = std::string(MAGNUS_SOURCE_DIR) + "/cases/s_map.toml";
}

TEST_CASE("magnus stability --spanwise: the growth rate per wavenumber and the verdict", "[app][stability]") {
  const std::string dir = temp_dir("ns-spanwise-cli");
  // Re 40 without spin on the map's grid: the steady wake, β·D = 0 and 1.
  const std::string h5 = dir + "/spectra.h5";
  Outcome o = magnus_cmd(
      {"stability", s_map, "--set", "flow.reynolds=40", "--spanwise", "--beta", "0:1:1", "--output", h5, "--json"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const auto j = nlohmann::json::parse(o.out);
  const auto& sp = j["spanwise"];
  REQUIRE(sp["points"].size() == 2);
  // β = 0 is a second discretisation of the 2D problem: the same verdict (stable), though the slow far-field
  // modes that lead a stable wake differ (−0.044 U/D here against the 2D problem's −0.0076).
  CHECK(sp["points"][0]["beta_D"].get<double>() == 0.0);
  CHECK(sp["points"][0]["wavelength_D"].is_null());
  CHECK(j["eigenvalues"][0]["growth_rate"].get<double>() < 0.0);
  CHECK(sp["points"][0]["growth_rate"].get<double>() < 0.0);
  CHECK(sp["points"][1]["wavelength_D"].get<double>() == Approx(2.0 * M_PI));
  // Spanwise variation damps this wake: β·D = 1 decays faster than the 2D far-field modes.
  CHECK(sp["points"][1]["growth_rate"].get<double>() < sp["points"][0]["growth_rate"].get<double>());
  CHECK(sp["stable"].get<bool>() == (sp["points"][0]["growth_rate"].get<double>() < 0.0));
  CHECK(sp["verdict"].get<std::string>().find("spanwise-uniform flow is stable") != std::string::npos);
  CHECK(sp["base"] == "steady");
  // The operator's measured bias travels with every verdict, in the JSON and in the text.
  CHECK(sp["accuracy_note"].get<std::string>().find("independent") != std::string::npos);
  const Outcome text = magnus_cmd({"stability", s_map, "--set", "flow.reynolds=40", "--spanwise", "--beta", "1:1:1"}, dir);
  REQUIRE(text.status == 0);
  CHECK(line_of(text.out, "accuracy").find("accuracy       steady bases (BiGlobal): within 1%") == 0);
  {
    // The HDF5 file carries the JSON's numbers: the 2D eigenvalues and the scan (β = 0 has no wavelength:
    // the fill value, named by _FillValue).
    const magnus::ResultFile f(h5, {"magnus-stability"});
    CHECK(f.attr_string("/", "model") == "navier-stokes");
    CHECK(f.attr_double("/", "reynolds") == 40.0);
    const std::vector<double> eig = f.dataset("/eigenvalues/growth_rate");
    REQUIRE(eig.size() == j["eigenvalues"].size());
    CHECK(eig[0] == j["eigenvalues"][0]["growth_rate"].get<double>());
    const std::vector<double> beta = f.dataset("/spanwise/beta_D"), g = f.dataset("/spanwise/growth_rate");
    const std::vector<double> lz = f.dataset("/spanwise/wavelength_D");
    REQUIRE(beta.size() == 2);
    for (size_t k = 0; k < 2; ++k) {
      CHECK(beta[k] == sp["points"][k]["beta_D"].get<double>());
      CHECK(g[k] == sp["points"][k]["growth_rate"].get<double>());
    }
    CHECK(lz[0] == magnus::kFillValue);
    CHECK(lz[1] == Approx(2.0 * M_PI));
    CHECK(f.attr_string("/spanwise", "verdict") == sp["verdict"].get<std::string>());
    CHECK(f.attr_string("/spanwise", "accuracy_note") == sp["accuracy_note"].get<std::string>());
    CHECK(f.attr_int("/spanwise", "stable") == (sp["stable"].get<bool>() ? 1 : 0));
  }

  // Re 100 sheds: the scan is of its orbit (Floquet). n_θ 32, R = 20a: the exponent is ln(μ)/T in U/D.
  o = magnus_cmd({"stability", s_map, "--set", "flow.reynolds=100", "--set", "grid.n_theta=32", "--spanwise",
                  "--beta", "1.6:1.6:1", "--json"},
                 dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const auto k = nlohmann::json::parse(o.out);
  CHECK(k["stable"] == false);
  const auto& fl = k["spanwise"];
  CHECK(fl["base"] == "periodic");
  const double T = fl["period_D_over_U"];
  CHECK(T > 5.0);  // St = 1/T between 0.12 and 0.2
  CHECK(T < 8.5);
  REQUIRE(fl["points"].size() == 1);
  const auto& pt = fl["points"][0];
  const double mu = std::hypot(pt["multiplier_real"].get<double>(), pt["multiplier_imag"].get<double>());
  CHECK(pt["growth_rate"].get<double>() == Approx(std::log(mu) / T).margin(1e-12));

  for (auto [args, expect] :
       {std::pair{std::vector<std::string>{"--beta", "0:1:1"}, "only used with --spanwise"},
        {std::vector<std::string>{"--spanwise", "--beta", "-1:1:1"}, "must be ≥ 0"},
        {std::vector<std::string>{"--spanwise", "--critical-spin", "1:2"},
         "not --critical-spin or an onset curve"},
        {std::vector<std::string>{"--spanwise", "--critical-reynolds", "40:60", "--spin-ratio", "0:1:1"},
         "not --critical-spin or an onset curve"},
        {std::vector<std::string>{"--critical-spin", "1:2", "--output", dir + "/x.h5"},
         "not the 2D onset search"},
        {std::vector<std::string>{"--output", dir}, "it is a directory"},
        {std::vector<std::string>{"--spanwise", "--fine-grid", "96:30"},
         "only used with --spanwise --critical-reynolds"},
        {std::vector<std::string>{"--spanwise", "--critical-reynolds", "40:60", "--fine-grid", "96"},
         "expected N:R"},
        {std::vector<std::string>{"--spanwise", "--critical-reynolds", "40:60", "--fine-grid", "97:30"},
         "n_θ must be an even whole number"},
        {std::vector<std::string>{"--spanwise", "--critical-reynolds", "40:60", "--fine-grid", "96:1"},
         "R/a must be in (1, 10000]"},
        {std::vector<std::string>{"--spanwise", "--critical-reynolds", "40:60", "--fine-grid", "32:30"},
         "must be finer than the case's grid (n_θ 48, R = 20a)"},
        {std::vector<std::string>{"--spanwise", "--critical-reynolds", "40:60", "--fine-grid", "48:20"},
         "not both the same"}}) {
    const Outcome b = magnus_cmd({"stability", s_map}, args, dir);
    INFO(b.err);
    CHECK(refused(b, expect));
  }
}

TEST_CASE("magnus stability --spanwise --critical-reynolds: a range with no 3D onset is undefined",
          "[app][stability]") {
  const std::string dir = temp_dir("ns-spanwise-critical");
  // α 3 on n_θ 32, R = 20a: the steady state is stable to every wavenumber at both ends of Re 30…60, so the
  // search has no crossing to find and says so; each end is one scan.
  // With --fine-grid the refinement is not run, and says why.
  const Outcome o =
      magnus_cmd({"stability", s_map, "--set", "grid.n_theta=32", "--set", "cylinder.spin_ratio=3",
                  "--spanwise", "--beta", "1:2:1", "--critical-reynolds", "30:60", "--output",
                  dir + "/onset.h5", "--fine-grid", "48:30", "--json"},
                 dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const auto j = nlohmann::json::parse(o.out);
  CHECK(j["found"] == false);
  CHECK(j["undefined"].get<std::string>().find("does not cross zero in [30, 60]") != std::string::npos);
  CHECK(j["accuracy_note"].get<std::string>().find("mode A's onset comes out at Re 187.5") != std::string::npos);
  CHECK(!j.contains("critical_reynolds"));
  REQUIRE(j["evaluations"].size() == 2);
  for (const auto& e : j["evaluations"]) {
    CHECK(e["base"] == "steady");
    CHECK(e["growth_rate"].get<double>() < 0.0);
  }
  CHECK(j["evaluations"][0]["reynolds"].get<double>() == 30.0);
  CHECK(j["evaluations"][1]["reynolds"].get<double>() == 60.0);
  // The file: a row per scan, the search's outcome in /onset3d's attributes.
  const magnus::ResultFile f(dir + "/onset.h5", {"magnus-stability"});
  CHECK(f.dataset("/onset3d/reynolds") == std::vector<double>{30.0, 60.0});
  CHECK(f.dataset("/onset3d/periodic") == std::vector<double>{0.0, 0.0});
  CHECK(f.attr_int("/onset3d", "found") == 0);
  CHECK(f.attr_string("/onset3d", "message") == j["undefined"].get<std::string>());
  CHECK(f.attr_string("/onset3d", "accuracy_note") == j["accuracy_note"].get<std::string>());
  CHECK(!f.has_attr("/onset3d", "critical_reynolds"));
  CHECK(j["fine_grid"]["undefined"] == "the search on the case's grid found no onset");
  CHECK(j["fine_grid"]["n_theta"] == 48);
  CHECK(j["fine_grid"]["outer_radius_over_a"] == 30.0);
  CHECK(f.attr_string("/onset3d/fine_grid", "message") == "the search on the case's grid found no onset");
  CHECK(!f.has_attr("/onset3d/fine_grid", "critical_reynolds"));
}
