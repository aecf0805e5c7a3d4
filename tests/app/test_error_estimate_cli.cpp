// Every navier-stokes run states an estimate of its discretisation error (a companion run on the grid twice
// as coarse): in the HDF5 file, the --json output and the summary; a run stopped before its means converged
// adds their spread and says so; where no estimate can be formed it is undefined, never NaN.
#include <fmt/core.h>
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/result_reader.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// A navier-stokes case at Re, α on a coarse grid (a = 0.5 m, U = 1 m/s: D/U = 1 s), R = 20a.
std::string write_ns_case(const std::string& dir, double Re, double alpha, double t_end, int n_theta) {
  const std::string path = dir + "/case.toml";
  std::ofstream(path) << fmt::format(
      "title = \"estimate\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = {}\n"
      "[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = {}\n[domain]\nouter_radius = 20.0\n[grid]\n"
      "n_theta = {}\n[time]\nend = {}\n[output]\nsnapshots = 0\n",
      alpha, Re, n_theta, t_end);
  return path;
}

}  // namespace

TEST_CASE("navier-stokes run: the error estimate in the file and the summary, unconverged means add their "
          "spread",
          "[app][ns][estimate]") {
  const std::string dir = test::temp_dir("ns-estimate");
  // Re 100, α 1 to t = 30 D/U: shedding has begun but the means are far from converged.
  const auto o = test::magnus_cmd({"run", write_ns_case(dir, 100, 1, 30, 48), "-o", dir + "/r.h5"}, dir);
  INFO(o.out << o.err);
  REQUIRE(o.status == 0);
  const FlowResult r = read_result(dir + "/r.h5");
  REQUIRE(r.viscous);
  const ViscousPart& v = *r.viscous;
  REQUIRE(v.cl_mean_rel_estimate);
  REQUIRE(v.cd_mean_rel_estimate);
  for (double e : {*v.cl_mean_rel_estimate, *v.cd_mean_rel_estimate}) {
    CHECK(std::isfinite(e));
    CHECK(e > 0.0);
  }
  CHECK(v.companion_n_theta == 24);
  CHECK(v.companion_n_r == (r.grid.n_r - 1) / 2 + 1);
  // Not converged at time.end: means_converged = 0, and the spread is part of each estimate.
  CHECK_FALSE(v.means_converged);
  REQUIRE(v.means_spread_rel);
  CHECK(*v.means_spread_rel > 0.0);
  // Shedding has begun: the spread is between periods (each estimate is at least the spread).
  CHECK(o.out.find("the means had not converged when the run stopped at time.end: the spread between periods, ") !=
        std::string::npos);
  CHECK(o.out.find("is part of the estimate") != std::string::npos);
  const double largest =
      std::max({*v.cl_mean_rel_estimate, *v.cd_mean_rel_estimate, v.strouhal_rel_estimate.value_or(0.0)});
  CHECK(largest >= *v.means_spread_rel);
  CHECK(o.out.find("error (est.)   C_L ±") != std::string::npos);
  CHECK(o.out.find("from a companion run on 24 × ") != std::string::npos);
  CHECK(o.out.find("nan") == std::string::npos);
  // magnus inspect shows them (schema-driven).
  const auto i = test::magnus_cmd({"inspect", dir + "/r.h5"}, dir);
  REQUIRE(i.status == 0);
  CHECK(i.out.find("cl_mean_rel_estimate") != std::string::npos);
  CHECK(i.out.find("means_converged") != std::string::npos);
}

TEST_CASE("navier-stokes run: a steady Re 20 run (Newton) has estimates of C_L and C_D, none of St",
          "[app][ns][estimate]") {
  const std::string dir = test::temp_dir("ns-estimate-steady");
  const auto o = test::magnus_cmd({"run", write_ns_case(dir, 20, 0.5, 40, 48), "-o", dir + "/r.h5"}, dir);
  INFO(o.out << o.err);
  REQUIRE(o.status == 0);
  const FlowResult r = read_result(dir + "/r.h5");
  const ViscousPart& v = *r.viscous;
  CHECK(o.out.find("steady state by Newton's method") != std::string::npos);
  REQUIRE(v.cl_mean_rel_estimate);
  REQUIRE(v.cd_mean_rel_estimate);
  CHECK(*v.cl_mean_rel_estimate > 0.0);
  CHECK(*v.cd_mean_rel_estimate > 0.0);
  CHECK_FALSE(v.strouhal_rel_estimate);
  CHECK(v.means_converged);
  CHECK(o.out.find("from a companion Newton solve on 24 × ") != std::string::npos);
}

TEST_CASE("navier-stokes run: no companion possible (n_θ 12: the coarse grid has 6): the estimate is "
          "undefined, marked so, nothing NaN",
          "[app][ns][estimate]") {
  const std::string dir = test::temp_dir("ns-estimate-none");
  const auto o = test::magnus_cmd({"run", write_ns_case(dir, 40, 0.5, 2, 12), "-o", dir + "/r.h5",
                                   "--set", "time.mode=unsteady"}, dir);
  INFO(o.out << o.err);
  REQUIRE(o.status == 0);
  const FlowResult r = read_result(dir + "/r.h5");
  const ViscousPart& v = *r.viscous;
  CHECK_FALSE(v.cl_mean_rel_estimate);
  CHECK_FALSE(v.cd_mean_rel_estimate);
  CHECK_FALSE(v.strouhal_rel_estimate);
  CHECK(v.companion_n_theta == 0);
  CHECK(o.out.find("error (est.)   undefined (the grid twice as coarse, n_θ 6, is below 8 points)") !=
        std::string::npos);
  const auto j = test::magnus_cmd({"inspect", dir + "/r.h5", "--json"}, dir);
  REQUIRE(j.status == 0);
  // Undefined is marked undefined: no value in the file, null in the JSON.
  const nlohmann::json f = nlohmann::json::parse(j.out);
  for (const char* k : {"cl_mean_rel_estimate", "cd_mean_rel_estimate", "strouhal_rel_estimate"})
    CHECK(f["errors"][k]["value"].is_null());
  CHECK(j.out.find("NaN") == std::string::npos);
  CHECK(j.out.find("nan") == std::string::npos);
}
