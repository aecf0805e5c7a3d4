// The computed 3D onset curve read as a verdict per map point (postproc/navier_stokes/spanwise_critical.hpp)
// and its file (io/stability_file.hpp).
#include <catch2/catch.hpp>

#include "io/stability_file.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("[ns][onset3d] the 2D flow is real below the computed onset, linear in α between its points",
          "[ns][onset3d]") {
  const std::vector<Onset3d> curve = {{2.0, 70.0}, {1.0, 50.0}};  // unsorted on purpose
  CHECK(two_d_is_real(49.0, 1.0, curve) == std::optional<bool>(true));
  CHECK(two_d_is_real(50.0, 1.0, curve) == std::optional<bool>(false));  // at the onset: not below it
  CHECK(two_d_is_real(59.0, 1.5, curve) == std::optional<bool>(true));   // Re_c(1.5) = 60
  CHECK(two_d_is_real(61.0, 1.5, curve) == std::optional<bool>(false));
  CHECK(two_d_is_real(69.0, 2.0, curve) == std::optional<bool>(true));
  CHECK(!two_d_is_real(40.0, 0.5, curve));  // outside the α the curve spans: undefined
  CHECK(!two_d_is_real(40.0, 2.5, curve));
  CHECK(onset_alpha_range(curve) == std::pair<double, double>(1.0, 2.0));
  const std::vector<Onset3d> one = {{0.0, 188.5}};
  CHECK(two_d_is_real(100.0, 0.0, one) == std::optional<bool>(true));
  CHECK(!two_d_is_real(100.0, 0.1, one));
}

TEST_CASE("[ns][onset3d] a stability file's 3D onset reads back, one without is refused", "[ns][onset3d]") {
  const std::string dir = test::temp_dir("onset3d-file");
  const Json found = {{"spin_ratio", 1.5},
                      {"evaluations", Json::array({Json{{"reynolds", 40.0}, {"base", "steady"}, {"growth_rate", -0.01},
                                                        {"beta_D", 1.0}, {"seconds", 1.0}},
                                                   Json{{"reynolds", 80.0}, {"base", "periodic"}, {"growth_rate", 0.02},
                                                        {"beta_D", 1.2}, {"seconds", 2.0}}})},
                      {"seconds", 3.0},
                      {"found", true},
                      {"critical_reynolds", 55.25},
                      {"change", 0.5},
                      {"bracket", {50.0, 60.0}},
                      {"beta_D", 1.1},
                      {"wavelength_D", 5.71}};
  write_stability_hdf5(dir + "/onset.h5", found, "test", "title = \"test\"\n");
  const Onset3d o = read_onset3d(dir + "/onset.h5");
  CHECK(o.alpha == 1.5);
  CHECK(o.Re_c == 55.25);

  Json none = found;
  none.erase("critical_reynolds"), none.erase("change"), none.erase("bracket"), none.erase("beta_D");
  none.erase("wavelength_D");
  none["found"] = false, none["undefined"] = "the most unstable growth rate does not cross zero";
  write_stability_hdf5(dir + "/none.h5", none, "test", "title = \"test\"\n");
  CHECK_THROWS_WITH(read_onset3d(dir + "/none.h5"), Catch::Contains("found no crossing"));
  const Json scan = {{"reynolds", 40.0}, {"spin_ratio", 0.0}, {"stable", true}, {"eigenvalues", Json::array()}};
  write_stability_hdf5(dir + "/scan.h5", scan, "test", "title = \"test\"\n");
  CHECK_THROWS_WITH(read_onset3d(dir + "/scan.h5"), Catch::Contains("holds no 3D onset"));
}
