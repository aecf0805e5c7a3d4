// What the navier-stokes summary says at the edges of its range: Re = 200 as given, a refused time step,
// a boundary layer with no cell across it, Re below the floor and a viscous length beyond R, and a cylinder
// spinning in still fluid (U = 0: the time unit D/(a|ω|), no Strouhal number). The Re 100, α 1 case on
// coarse grids: each run takes well under a second.
#include <fmt/core.h>
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>

#include "io/hdf5_io.hpp"
#include "io/stability_file.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

const std::string kCase = std::string(MAGNUS_SOURCE_DIR) + "/cases/re100_alpha1.toml";

/// magnus run on cases/re100_alpha1.toml (n_θ 32, R = 20a, t_end 2 D/U unless overridden) with --set sets.
test::Outcome run(const std::string& dir, const std::vector<std::string>& sets,
                  const std::string& out = "r.h5") {
  std::vector<std::string> args = {"run", kCase, "-o", dir + "/" + out};
  for (const char* s : {"grid.n_theta=32", "domain.outer_radius=20", "time.end=2"})
    args.push_back("--set"), args.push_back(s);
  for (const std::string& s : sets) args.push_back("--set"), args.push_back(s);
  return test::magnus_cmd(args, dir);
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

/// The longest run of digits in s.
size_t longest_digit_run(const std::string& s) {
  size_t best = 0, run = 0;
  for (char ch : s) best = std::max(best, run = (ch >= '0' && ch <= '9') ? run + 1 : 0);
  return best;
}

}  // namespace

TEST_CASE("navier-stokes summary: Re = 200 as given is stored as given", "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-re200");
  // flow.reynolds = 200: ν = U·2a/200 = 5e-7, and U·2a/ν of that ν is 200.00000000000003.
  const auto o = run(dir, {"flow.reynolds=200"});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(ResultFile(dir + "/r.h5").attr_double("/parameters", "reynolds") == 200.0);
  const auto c = run(dir, {}, "c.h5");  // the case's own Re = 100: 100 in the file, not 100.00000000000001
  REQUIRE(c.status == 0);
  CHECK(ResultFile(dir + "/c.h5").attr_double("/parameters", "reynolds") == 100.0);
}

/// A stability file holding a found 3D onset Re_c at spin ratio alpha (as magnus stability --spanwise
/// --critical-reynolds --output writes it; the search itself is tested with the command).
std::string onset_file(const std::string& dir, const std::string& name, double alpha, double Re_c) {
  const Json j = {{"spin_ratio", alpha},
                  {"evaluations", Json::array({Json{{"reynolds", Re_c - 10.0}, {"base", "periodic"},
                                                    {"growth_rate", -0.01}, {"beta_D", 1.6}, {"seconds", 1.0}},
                                               Json{{"reynolds", Re_c + 10.0}, {"base", "periodic"},
                                                    {"growth_rate", 0.01}, {"beta_D", 1.6}, {"seconds", 1.0}}})},
                  {"seconds", 2.0}, {"found", true}, {"critical_reynolds", Re_c}, {"change", 0.5},
                  {"bracket", {Re_c - 10.0, Re_c + 10.0}}, {"beta_D", 1.6}, {"wavelength_D", 3.93}};
  write_stability_hdf5(dir + "/" + name, j, "test", "title = \"test\"\n");
  return dir + "/" + name;
}

TEST_CASE("navier-stokes summary: whether the 2D flow is real, from a computed 3D onset or said not computed",
          "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-3d");
  // n_θ 48: the boundary layer has a cell across it up to Re 170 at α 1, so the S line gives its verdict.
  auto with = [&](const std::string& re, const std::string& out, const std::vector<std::string>& files,
                  bool json) {
    std::vector<std::string> args = {"run", kCase, "-o", dir + "/" + out};
    if (json) args.push_back("--json");
    for (const char* s : {"grid.n_theta=48", "domain.outer_radius=20", "time.end=2"})
      args.push_back("--set"), args.push_back(s);
    args.push_back("--set"), args.push_back("flow.reynolds=" + re);
    for (const std::string& f : files) args.push_back("--onset3d"), args.push_back(f);
    return test::magnus_cmd(args, dir);
  };
  // Without an onset: no fixed rule; the summary says it was not computed and how to compute it.
  const auto none = with("170", "none.h5", {}, false);
  INFO(none.err);
  REQUIRE(none.status == 0);
  CHECK(test::line_of(none.out, "3D") ==
        "3D             whether this 2D flow is real is not computed for this run: magnus stability CASE "
        "--spanwise --critical-reynolds A:B --output F.h5 finds the 3D onset, magnus run CASE --onset3d F.h5 "
        "applies it");
  CHECK(test::line_of(none.out, "S/(2πρa²)").find("(a real cylinder's where its flow stays 2D: see 3D)") !=
        std::string::npos);
  CHECK_FALSE(ResultFile(dir + "/none.h5").has_attr("/parameters", "onset3d_alpha_min"));

  // An onset curve through α 0 (Re_c 180) and α 2 (Re_c 140): at the case's α = 1, Re_c = 160.
  const std::string f0 = onset_file(dir, "a0.h5", 0.0, 180.0), f2 = onset_file(dir, "a2.h5", 2.0, 140.0);
  const auto below = with("150", "below.h5", {f0, f2}, false);
  INFO(below.err);
  REQUIRE(below.status == 0);
  CHECK(test::line_of(below.out, "3D") == "3D             2D flow is real here: Re = 150 is below the computed 3D "
                                            "onset Re_c = 160 at α = 1 (" + f0 + ", " + f2 + ")");
  CHECK(test::line_of(below.out, "S/(2πρa²)").find("the share of the ideal lift a real cylinder gets") !=
        std::string::npos);
  const ResultFile fb(dir + "/below.h5");
  CHECK(fb.attr_double("/parameters", "onset3d_reynolds") == Approx(160.0).epsilon(1e-12));
  CHECK(fb.attr_double("/parameters", "onset3d_alpha_min") == 0.0);
  CHECK(fb.attr_double("/parameters", "onset3d_alpha_max") == 2.0);
  CHECK(fb.attr_string("/parameters", "onset3d_files") == f0 + ", " + f2);
  CHECK(Json::parse(with("150", "below.h5", {f0, f2}, true).out)["derived"]["three_dimensional"] == false);

  const auto above = with("170", "above.h5", {f0, f2}, false);
  REQUIRE(above.status == 0);
  CHECK(test::line_of(above.out, "3D") ==
        "3D             Re = 170 is not below the computed 3D onset Re_c = 160 at α = 1 (" + f0 + ", " + f2 +
            "): real flow is three-dimensional here; this is the 2D laminar answer, not the real one");
  CHECK(test::line_of(above.out, "S/(2πρa²)").find("not a real cylinder's: its flow is three-dimensional there") !=
        std::string::npos);
  CHECK(Json::parse(with("170", "above.h5", {f0, f2}, true).out)["derived"]["three_dimensional"] == true);

  // One point at α 0 does not answer at α 1: undefined, and said so.
  const auto outside = with("150", "outside.h5", {f0}, false);
  REQUIRE(outside.status == 0);
  CHECK(test::line_of(outside.out, "3D") ==
        "3D             undefined at α = 1: the computed 3D onset given covers α = 0 only (" + f0 + ")");
  CHECK(Json::parse(with("150", "outside.h5", {f0}, true).out)["derived"]["three_dimensional"].is_null());
  CHECK_FALSE(ResultFile(dir + "/outside.h5").has_attr("/parameters", "onset3d_reynolds"));

  // Refused before solving, in one line: a file without an onset, and a potential-flow case.
  const Json scan = {{"reynolds", 40.0}, {"spin_ratio", 0.0}, {"stable", true}, {"eigenvalues", Json::array()}};
  write_stability_hdf5(dir + "/scan.h5", scan, "test", "title = \"test\"\n");
  const auto bad = with("150", "bad.h5", {dir + "/scan.h5"}, false);
  CHECK(bad.status != 0);
  CHECK(test::lines(bad.err) == 1);
  CHECK(bad.err.find("holds no 3D onset") != std::string::npos);
  CHECK_FALSE(exists(dir + "/bad.h5"));
  const auto pot = test::magnus_cmd({"run", std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml", "-o",
                                     dir + "/pot.h5", "--onset3d", f0},
                                    dir);
  CHECK(pot.status != 0);
  CHECK(pot.err == "magnus: error: --onset3d: only for a navier-stokes case (potential flow is not 3D-unstable)\n");
}

TEST_CASE("navier-stokes run: a refused time step names the limit as the impulsive start's",
          "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-dt");
  const auto o = run(dir, {"time.dt=0.5"});
  REQUIRE(o.status != 0);
  REQUIRE(test::lines(o.err) == 1);
  INFO(o.err);
  CHECK(std::regex_search(
      o.err,
      std::regex("^magnus: error: time\\.dt = 0\\.5 \\(D/U\\) is above 0\\.0[0-9]+ D/U, the stability limit "
                 "at the start \\(from rest, where the flow is fastest; the Δt that time\\.cfl picks grows "
                 "as the flow settles\\) on this grid \\(CFL 0\\.72\\): leave it out or lower it\n$")));
  CHECK_FALSE(exists(dir + "/r.h5"));
}

TEST_CASE("navier-stokes summary: below one wall cell the boundary layer is not resolved",
          "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-coarse");
  // n_θ = 8 at Re 200, α 6: 0.044 cells across D/√(Re(1 + α²)); C_L came out with the wrong sign.
  const auto o =
      run(dir, {"grid.n_theta=8", "flow.reynolds=200", "cylinder.spin_ratio=6", "time.mode=unsteady"});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CAPTURE(o.out);
  CHECK(test::line_of(o.out, "               boundary layer") ==
        "               boundary layer: 0.044 wall cells across D/√(Re(1 + α²)) — not resolved: below 1 cell "
        "the forces are not meaningful (grid.n_theta ≥ 166 with grid.n_r = 0, or grid.n_r ≥ 132)");
  // The verdict comes first, before any figure.
  CHECK(o.out.find("verdict        NOT RESOLVED: 0.044 wall cells") < o.out.find("\ncase "));
  CHECK(o.out.find("several %") == std::string::npos);
  // Between one and five cells: coarse, C_D can be off by more than 10% (measured: +14% with 4.5 cells).
  const auto c = run(dir, {"grid.n_theta=96"}, "c.h5");
  REQUIRE(c.status == 0);
  CHECK(
      test::line_of(c.out, "               boundary layer") ==
      "               boundary layer: 3.6 wall cells across D/√(Re(1 + α²)) — coarse: below 5 cells C_D can "
      "be off by more than 10% (+14% with 4.5 cells at Re 100, α 2; raise grid.refine, or leave grid.n_theta "
      "and grid.n_r to magnus)");
  // Between five and six: a few % (measured: +4.6% with 5.6 cells at α 1.5).
  const auto d = run(dir, {"grid.n_theta=144"}, "d.h5");
  REQUIRE(d.status == 0);
  CHECK(test::line_of(d.out, "               boundary layer")
            .find("— coarse: below 6 cells expect C_D errors of a few % (+4.6% with 5.6 cells at Re 100, α "
                  "1.5; raise grid.refine, or leave grid.n_theta and grid.n_r to magnus)") != std::string::npos);
}

TEST_CASE("navier-stokes case: Re below 0.01 is refused, a viscous length beyond R is noted",
          "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-low-re");
  for (const char* re : {"1e-300", "0.001"}) {
    const auto o = run(dir, {fmt::format("flow.reynolds={}", re)});
    REQUIRE(o.status != 0);
    REQUIRE(test::lines(o.err) == 1);
    CHECK(o.err == fmt::format("magnus: error: --set flow.reynolds: {} is out of range: must be >= 0.01 for "
                               "navier-stokes (below it the viscous length D/Re is over 100 D: creeping flow "
                               "whose forces depend on domain.outer_radius)\n",
                               re == std::string("0.001") ? "0.001" : "1e-300"));
    CHECK_FALSE(exists(dir + "/r.h5"));
  }
  // The same through flow.viscosity: U·2a/ν = 1e-4/1 = 1e-4.
  const auto v = run(dir, {"flow.viscosity=1"});
  REQUIRE(v.status != 0);
  CHECK(v.err ==
        std::string("magnus: error: --set") +
            " flow.viscosity: 1 gives Re = U*2a/nu = 0.0001, out of range: must be >= 0.01 for "
            "navier-stokes (below it the viscous length D/Re is over 100 D: creeping flow whose forces "
            "depend on domain.outer_radius)\n");
  // Re = 0.05 on R = 20a: D/Re = 20 D = 40a lies beyond R.
  const auto o = run(dir, {"flow.reynolds=0.05"});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find(
            "note           the viscous length D/Re = 20 D reaches beyond the grid (R = 10 D): the forces "
            "depend on R (raise domain.outer_radius)\n") != std::string::npos);
  CHECK(longest_digit_run(o.out) < 20);
  const auto f = run(dir, {"flow.reynolds=1"}, "f.h5");  // D/Re = D, well inside R
  REQUIRE(f.status == 0);
  CHECK(f.out.find("viscous length") == std::string::npos);
}

TEST_CASE("navier-stokes summary at U = 0: times in D/(a|ω|), no Strouhal number", "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-still");
  const std::vector<std::string> still = {"flow.speed=0", "flow.viscosity=1e-6", "cylinder.spin=2"};
  const auto o = run(dir, still);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CAPTURE(o.out);
  CHECK(o.out.find("D/U") == std::string::npos);
  CHECK(o.out.find("U/D") == std::string::npos);
  CHECK(std::regex_search(o.out,
                          std::regex("stopped: auto: stable \\(leading eigenvalue -0\\.[0-9]+ \\+0(\\.[0-9]+)?i "
                                     "a\\|ω\\|/D, St undefined \\(U = 0\\)(; not verified: the search left a "
                                     "gap right of it; by the time stepper, a weak vortex added to it decays "
                                     "at -0\\.[0-9]+ a\\|ω\\|/D over 30–60 D/\\(a\\|ω\\|\\))?\\)")));
  CHECK(std::regex_search(
      o.out, std::regex("\nstability      steady state's leading eigenvalue λ·D/\\(a\\|ω\\|\\) = "
                        "-0\\.[0-9]+ \\+0\\.[0-9]+i \\(stable; St undefined \\(U = 0\\)\\)\n")));
  std::vector<std::string> marched = still;
  marched.push_back("time.mode=unsteady");
  const auto m = run(dir, marched, "m.h5");
  REQUIRE(m.status == 0);
  CHECK(std::regex_search(m.out,
                          std::regex("\nrun            t = 2 s = 2 D/\\(a\\|ω\\|\\), [0-9]+ steps of Δt = "
                                     "[0-9.e-]+ s \\([0-9.e-]+ D/\\(a\\|ω\\|\\)\\)")));
  CHECK(m.out.find("D/U") == std::string::npos);
  const auto i = test::magnus_cmd({"inspect", dir + "/m.h5"}, dir);
  REQUIRE(i.status == 0);
  CHECK(i.out.find("D/U)") == std::string::npos);
  CHECK(i.out.find(" D/(a|ω|))\n") != std::string::npos);
}

TEST_CASE("navier-stokes summary: an attached steady flow has no separation and no bubble",
          "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-attached");
  // Re 4, α = 0: τ_w = 0 only at the front stagnation point and, by symmetry, at the rear point.
  const auto o = run(dir, {"flow.reynolds=4", "cylinder.spin_ratio=0", "time.mode=steady"});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(test::line_of(o.out, "separation") ==
        "separation     none (no point where the wall flow leaves the wall)");
  CHECK(test::line_of(o.out, "recirculation") == "recirculation  none (no bubble behind the body; steady)");
  // Re 40: a bubble; its separation points are listed, not the front and rear points.
  const auto b = run(dir, {"flow.reynolds=40", "cylinder.spin_ratio=0", "time.mode=steady"}, "b.h5");
  REQUIRE(b.status == 0);
  const std::string sep = test::line_of(b.out, "separation");
  CAPTURE(sep);
  CHECK(std::regex_match(
      sep, std::regex("separation     θ = 5\\d\\.\\d\\d°, 30\\d\\.\\d\\d° \\(steady; τ_w .*")));
  // No spin: S is undefined (no unit after it), and a long value keeps a space before the ideal column.
  CHECK(test::line_of(b.out, "Magnus S").rfind("Magnus S       undefined  ", 0) == 0);
  const std::string lift = test::line_of(b.out, "lift");
  CAPTURE(lift);
  CHECK(lift.find("across the flow ") != std::string::npos);
  const std::string parts = test::line_of(b.out, "               last step");  // no second column: no space
  CAPTURE(parts);
  REQUIRE_FALSE(parts.empty());
  CHECK(parts.back() != ' ');
  CHECK(test::line_of(b.out, "recirculation").find("L/D = ") != std::string::npos);
}

TEST_CASE("navier-stokes summary: an outer boundary close for a wake is noted with its measured effect",
          "[app][ns][report]") {
  const std::string dir = test::temp_dir("ns-report-small-r");
  // R = 2a gave a steady flow with C_D 0.805 at Re 100, α 1, where the shedding wake has 1.10: noted.
  const auto o = run(dir, {"domain.outer_radius=2"});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("note           the outer boundary R = 1 D is close for a wake: at Re 100, α = 1, against "
                   "R = 50 D, St moved by −0.7% at R = 25 D") != std::string::npos);
  CHECK(o.out.find("flow came out steady (C_D 0.80 against 1.10)") != std::string::npos);
  // From R = 50a (25 D) on, no note.
  const auto b = run(dir, {"domain.outer_radius=50"}, "b.h5");
  REQUIRE(b.status == 0);
  CHECK(b.out.find("the outer boundary R") == std::string::npos);
}
