// The sweep file, format version 2: units beside every attribute, angles in rad, never NaN.
#include <catch2/catch.hpp>

#include <cmath>

#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/schema_files.hpp"
#include "io/sweep_file.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("sweep file 2: no NaN, a _FillValue where a column is partly undefined, angles in rad",
          "[io][sweep]") {
  const std::string dir = test::temp_dir("sweep-v2");
  Case c = test::make_case(1.0, 32);
  // α = 0: Γ = 0 (cl/K–J − 1 undefined); α = 3 > 2: one free stagnation point (θ2 undefined).
  const SweepResult s = sweep_spin_ratio(c, {0.0, 1.0, 3.0});
  write_sweep_hdf5(s, dir + "/s.h5");
  const ResultFile f(dir + "/s.h5", {"magnus-sweep"});
  REQUIRE(f.version() == 2);
  for (const auto& [path, shape] : f.datasets()) {
    CAPTURE(path);
    REQUIRE(f.has_attr(path, "units"));
    for (double v : f.dataset(path)) REQUIRE(std::isfinite(v));
  }
  for (const char* p : {"/sweep/stagnation_theta1", "/sweep/stagnation_theta2"})
    REQUIRE(f.attr_string(p, "units") == "rad");
  const auto t1 = f.dataset("/sweep/stagnation_theta1");
  for (double v : t1) REQUIRE((v >= 0.0 && v < 2 * M_PI));
  const auto t2 = f.dataset("/sweep/stagnation_theta2");
  REQUIRE(f.has_attr("/sweep/stagnation_theta2", "_FillValue"));
  const double fill = f.attr_double("/sweep/stagnation_theta2", "_FillValue");
  REQUIRE(t2[2] == fill);
  REQUIRE(t2[1] != fill);
  REQUIRE(f.dataset("/sweep/cl_over_kj_minus_1")[0] ==
          f.attr_double("/sweep/cl_over_kj_minus_1", "_FillValue"));
  REQUIRE_FALSE(f.has_attr("/sweep/cl", "_FillValue"));
  for (const char* a : {"radius", "speed", "density", "pressure_inf", "outer_radius", "n_r"})
    REQUIRE(f.has_attr("/parameters", std::string(a) + "_units"));
  REQUIRE(f.attr_string("/parameters", "radius_units") == "m");
  REQUIRE(f.attr_string("/timing", "total_s_units") == "s");

  // inspect lists the parameters and the columns with units and ranges.
  const std::string text = describe_result(dir + "/s.h5");
  CHECK(text.find("magnus-sweep version 2") != std::string::npos);
  CHECK(text.find("radius") != std::string::npos);
  CHECK(text.find("[m]") != std::string::npos);
  CHECK(text.find("/sweep/alpha") != std::string::npos);
  CHECK(text.find("0 … 3") != std::string::npos);
  CHECK(text.find("(1 undefined)") != std::string::npos);
}

TEST_CASE("sweep file: the file holds the declared table, each column with its unit and description",
          "[io][sweep]") {
  const std::string dir = test::temp_dir("sweep-table");
  const SweepResult s = sweep_spin_ratio(test::make_case(1.0, 32), {0.0, 1.0});
  write_sweep_hdf5(s, dir + "/s.h5");
  const ResultFile f(dir + "/s.h5", {"magnus-sweep"});
  for (const AttrValue& a : attr_values(sweep_attributes(), s, Shown::file_only)) {
    CAPTURE(a.group, a.name);
    REQUIRE(f.has_attr(a.group, a.name));
    if (a.kind != AttrKind::text) CHECK(f.attr_string(a.group, std::string(a.name) + "_units") == a.units);
  }
  CHECK_FALSE(f.has_attr("/parameters", "spin_ratio"));  // --json's only
  const auto columns = sweep_columns(s.variable);
  CHECK(f.datasets().size() == columns.size());
  for (const Column<SweepRow>& c : columns) {
    const std::string path = std::string("/sweep/") + c.name;
    CAPTURE(path);
    CHECK(f.attr_string(path, "units") == c.units);
    CHECK(f.attr_string(path, "description") == c.description);
  }
}
