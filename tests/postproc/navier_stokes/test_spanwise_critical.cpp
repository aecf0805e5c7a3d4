// The computed 3D onset curve read as a verdict per map point (postproc/navier_stokes/spanwise_critical.hpp)
// and its file (io/stability_file.hpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "io/hdf5_io.hpp"
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

  // Refined on a finer grid (--fine-grid): its onset, when found, is the one a run applies.
  Json refined = found;
  refined["fine_grid"] = {
      {"n_theta", 96},
      {"n_r", 88},
      {"outer_radius_over_a", 40.0},
      {"found", true},
      {"critical_reynolds", 57.5},
      {"error_estimate", 0.4},
      {"beta_D", 1.1},
      {"seconds", 9.0},
      {"evaluations", Json::array({Json{{"reynolds", 55.25}, {"growth_rate", -0.004}},
                                   Json{{"reynolds", 56.355}, {"growth_rate", -0.002}}})}};
  write_stability_hdf5(dir + "/refined.h5", refined, "test", "title = \"test\"\n");
  CHECK(read_onset3d(dir + "/refined.h5").Re_c == 57.5);
  const ResultFile rf(dir + "/refined.h5", {"magnus-stability"});
  CHECK(rf.dataset("/onset3d/fine_grid/reynolds") == std::vector<double>{55.25, 56.355});
  CHECK(rf.attr_int("/onset3d/fine_grid", "n_theta") == 96);
  CHECK(rf.attr_double("/onset3d/fine_grid", "error_estimate") == 0.4);
  refined["fine_grid"].erase("critical_reynolds"), refined["fine_grid"].erase("error_estimate");
  refined["fine_grid"]["found"] = false, refined["fine_grid"]["undefined"] = "no growth rate converged";
  write_stability_hdf5(dir + "/unrefined.h5", refined, "test", "title = \"test\"\n");
  CHECK(read_onset3d(dir + "/unrefined.h5").Re_c == 55.25);  // not found there: the search's own onset
  CHECK(
      ResultFile(dir + "/unrefined.h5", {"magnus-stability"}).attr_string("/onset3d/fine_grid", "message") ==
      "no growth rate converged");

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

TEST_CASE("[ns][onset3d] refined on a finer grid: the onset is the finer grid's own within its bar",
          "[ns][onset3d]") {
  // The stationary 3D mode of fast spin (α 5.25, steady 2D-stable bases: BiGlobal, converged eigenvalues),
  // searched on n_θ 32 and refined on n_θ 40 (R = 20a both), against the n_θ 40 grid's own search at the
  // same wavenumber. Measured: 37.19 on n_θ 32; 38.672 ± 0.020 refined, 38.670 by the fine grid's search.
  const NsParams coarse = test::cylinder_flow(40.0, 5.25, 32, 20.0),
                 fine = test::cylinder_flow(40.0, 5.25, 40, 20.0);
  const SpanwiseCritical c = spanwise_critical(coarse, {1.0, 1.5, 2.0}, 30.0, 50.0, 1.0, "arnoldi");
  REQUIRE(c.found);
  const SpanwiseFine f = spanwise_critical_fine(coarse, c, fine, "arnoldi");
  INFO("coarse " << c.Re_c << ", refined " << f.Re_c << " ± " << f.bar << ": " << f.message);
  REQUIRE(f.found);
  REQUIRE(f.evaluations.size() == 2);
  CHECK(f.evaluations[0].Re == c.Re_c);
  CHECK(f.evaluations[1].Re == Approx(1.02 * c.Re_c).epsilon(1e-12));
  const SpanwiseCritical direct = spanwise_critical(fine, {f.beta_D}, 37.0, 40.0, 1e-3, "arnoldi");
  REQUIRE(direct.found);
  INFO("the fine grid's own search: " << direct.Re_c << " ± " << direct.change);
  CHECK(std::fabs(f.Re_c - direct.Re_c) <= f.bar + direct.change);
  CHECK(std::fabs(f.Re_c - direct.Re_c) < std::fabs(f.line_Re_c - direct.Re_c));  // the curvature helps
  CHECK(f.extrapolated);  // 38.67 lies a whole spacing above the scans at 37.19 and 37.93, and says so
  CHECK(f.bar < 0.1 * std::fabs(f.Re_c - c.Re_c));  // the refinement moves the onset by far more than its bar
  CHECK_THROWS_AS(spanwise_critical_fine(coarse, SpanwiseCritical{}, fine, "arnoldi"), std::invalid_argument);
}

TEST_CASE("[ns][onset3d] fine_onset: the parabola's zero with a given curvature or else the straight line's",
          "[ns][onset3d]") {
  // g(x) = g_1 + s(x − 10) + ½g''(x − 10)(x − 12) with g_1 = −0.05, s = 0.04, g'' = −0.01: g_2 = 0.03, and
  // its zero solves u² − 10u + 10 = 0 (u = x − 10): x = 15 − √15. The line's zero is 11.25.
  const FineRoot r = fine_onset(10.0, -0.05, 12.0, 0.03, -0.01);
  REQUIRE(r.found);
  CHECK(r.parabola);
  CHECK(r.line == Approx(11.25).epsilon(1e-14));
  CHECK(r.Re_c == Approx(15.0 - std::sqrt(15.0)).epsilon(1e-13));
  CHECK(r.correction == Approx(std::fabs(r.Re_c - 11.25)).epsilon(1e-13));
  const FineRoot flat = fine_onset(10.0, -0.05, 12.0, 0.03, 0.0);  // g'' = 0: the line, no correction
  CHECK(flat.Re_c == Approx(11.25).epsilon(1e-14));
  CHECK(flat.correction == 0.0);
  // Both below zero, bending down: the parabola never reaches zero; the line's zero (14) stands, with the
  // line's own error there, ½|g''|·|(14 − 10)(14 − 12)|/s = ½·0.5·8/0.25 = 8.
  const FineRoot none = fine_onset(10.0, -1.0, 12.0, -0.5, -0.5);
  REQUIRE(none.found);
  CHECK(!none.parabola);
  CHECK(none.Re_c == Approx(14.0).epsilon(1e-14));
  CHECK(none.correction == Approx(8.0).epsilon(1e-13));
  CHECK(!fine_onset(10.0, 0.03, 12.0, -0.05, 0.0).found);  // falling with Re: no onset
  CHECK(!fine_onset(12.0, -0.05, 10.0, 0.03, 0.0).found);  // Re_2 < Re_1
}
