// The magnus command as a user runs it: exit codes, one-line errors, no partial or clobbered files,
// and every shipped case against its expected figures.
#include <toml++/toml.h>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/hdf5_io.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {

/// The scene keys a case file requires, for cases about other keys.
const std::string scene = "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n";

/// Files in dir other than the ones the harness itself writes.
std::vector<std::string> stray_files(const std::string& dir, const std::vector<std::string>& expected) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name == "stdout.txt" || name == "stderr.txt") continue;
    if (std::find(expected.begin(), expected.end(), name) == expected.end()) out.push_back(name);
  }
  return out;
}

}  // namespace

TEST_CASE("bad input: non-zero exit, one line naming the key or file, no output, old output intact",
          "[app][cli]") {
  struct Bad {
    const char* what;
    std::string toml;
    std::string needle;
  };
  const std::vector<Bad> bad = {
      {"malformed TOML", "[grid\nn_theta = 64\n", "malformed TOML"},
      {"unknown key", scene + "[grid]\nn_thetta = 64\n", "grid.n_theta"},
      {"wrong type", "[cylinder]\nradius = 0.1\nspin = 1.0\n[flow]\nspeed = \"fast\"\n", "flow.speed"},
      {"out of range", scene + "density = -1.0\n", "flow.density"},
      {"NaN", "[cylinder]\nradius = 0.1\nspin = 1.0\n[flow]\nspeed = nan\n", "flow.speed"},
      {"inf", "[cylinder]\nradius = 0.1\nspin = inf\n[flow]\nspeed = 1.0\n", "cylinder.spin"},
      {"spin and spin_ratio", "[cylinder]\nradius = 0.1\nspin = 1.0\nspin_ratio = 2.0\n[flow]\nspeed = 1.0\n",
       "cylinder.spin_ratio"},
      {"n_theta odd", scene + "[grid]\nn_theta = 63\n", "grid.n_theta"},
      {"n_theta < 8", scene + "[grid]\nn_theta = 4\n", "grid.n_theta"},
      {"R/a <= 1", scene + "[domain]\nouter_radius = 0.5\n", "domain.outer_radius"},
      {"empty case: radius required", "", "cylinder.radius: required key is missing"},
      {"no speed", "[cylinder]\nradius = 0.1\nspin = 1.0\n", "flow.speed: required key is missing"},
      {"no spin", "[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n",
       "cylinder.spin: required key is missing"},
  };
  for (const auto& b : bad) {
    SECTION(b.what) {
      const std::string dir = test::temp_dir("cli-bad");
      const std::string case_path = dir + "/case.toml";
      std::ofstream(case_path) << b.toml;
      // An earlier result that must survive byte for byte, and a fresh name that must not appear.
      std::ofstream(dir + "/old.h5") << "ORIGINAL BYTES";
      for (const char* target : {"old.h5", "new.h5"}) {
        const Outcome o = magnus_cmd({"run", case_path, "-o", dir + "/" + target}, dir);
        CAPTURE(b.what, o.err);
        REQUIRE(o.status != 0);
        REQUIRE(lines(o.err) == 1);
        REQUIRE(o.err.find(b.needle) != std::string::npos);
        REQUIRE(o.err.find("case.toml") != std::string::npos);
      }
      REQUIRE(slurp(dir + "/old.h5") == "ORIGINAL BYTES");
      REQUIRE(stray_files(dir, {"case.toml", "old.h5"}).empty());
    }
  }
  SECTION("missing case file") {
    const std::string dir = test::temp_dir("cli-missing");
    const Outcome o = magnus_cmd({"run", dir + "/nope.toml", "-o", dir + "/x.h5"}, dir);
    REQUIRE(o.status != 0);
    REQUIRE(lines(o.err) == 1);
    REQUIRE(o.err.find("nope.toml") != std::string::npos);
    REQUIRE(stray_files(dir, {}).empty());
  }
  SECTION("unwritable output path") {
    const std::string dir = test::temp_dir("cli-unwritable");
    std::ofstream(dir + "/case.toml") << scene + "[grid]\nn_theta = 16\n";
    std::ofstream(dir + "/plainfile") << "x";
    for (const std::string& out : {dir + "/no/such/dir/r.h5", dir + "/plainfile/r.h5"}) {
      const Outcome o = magnus_cmd({"run", dir + "/case.toml", "-o", out}, dir);
      CAPTURE(o.err);
      REQUIRE(o.status != 0);
      REQUIRE(lines(o.err) == 1);
      REQUIRE(o.err.find(out) != std::string::npos);
    }
    REQUIRE(stray_files(dir, {"case.toml", "plainfile"}).empty());
  }
  SECTION("bad --set and unknown options") {
    const std::string dir = test::temp_dir("cli-set");
    std::ofstream(dir + "/case.toml") << "";
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"run", dir + "/case.toml", "--set", "grid.ntheta=64", "-o", dir + "/r.h5"},
          std::vector<std::string>{"run", dir + "/case.toml", "--bogus"},
          std::vector<std::string>{"frobnicate"}}) {
      const Outcome o = magnus_cmd(args, dir);
      CAPTURE(o.err);
      REQUIRE(o.status != 0);
      REQUIRE(lines(o.err) == 1);
    }
    REQUIRE(stray_files(dir, {"case.toml"}).empty());
  }
}

TEST_CASE("a case without its scene keys is refused in one exact line, nothing written", "[app][cli]") {
  const std::string dir = test::temp_dir("cli-required");
  std::ofstream(dir + "/case.toml") << "[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n";
  const Outcome o = magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5"}, dir);
  CHECK(o.status == 1);
  CHECK(
      o.err ==
      "magnus: error: " + dir +
          "/case.toml: cylinder.spin: required key is missing: give one of "
          "cylinder.spin (rad/s), cylinder.spin_ratio or cylinder.rpm, or circulation.model = \"given\" with "
          "circulation.value\n");
  const Outcome e = magnus_cmd({"run", dir + "/case.toml", "--set", "cylinder.radius=1", "--set",
                                "flow.speed=0", "--set", "circulation.model=given", "-o", dir + "/r.h5"},
                               dir);
  CHECK(e.err == "magnus: error: " + dir +
                     "/case.toml: circulation.value: is required with circulation.model = "
                     "\"given\"\n");
  CHECK(stray_files(dir, {"case.toml"}).empty());
}

TEST_CASE("finite inputs whose derived quantities overflow are refused in one line naming the key",
          "[app][cli]") {
  const std::string dir = test::temp_dir("cli-overflow");
  const std::string demo = std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml";
  struct Bad {
    std::vector<std::string> sets;
    std::string message;
  };
  const std::vector<Bad> bad = {
      {{"flow.speed=1e160"}, "flow.speed: 1e+160 is too large: U² is not finite"},
      {{"flow.density=1e300", "flow.speed=1e5"}, "flow.density: 1e+300 is too large: ρU² is not finite"},
      {{"cylinder.radius=1e3", "cylinder.spin=1e306"},
       "cylinder.spin: 1e+306 is too large: the circulation Γ is not finite"},
      {{"cylinder.radius=1e150", "flow.speed=1e-150"},
       "flow.speed: 1e-150 is too small: the free stagnation radius |Γ|/(2πU) is not finite"},
      {{"cylinder.radius=1e-160"},
       "cylinder.radius: 1e-160 is too small: the circulation Γ underflows double precision"},
  };
  for (const auto& b : bad) {
    std::vector<std::string> args = {"run", demo, "-o", dir + "/r.h5"};
    for (const auto& s : b.sets) args.insert(args.end(), {"--set", s});
    const Outcome o = magnus_cmd(args, dir);
    CHECK(o.status == 1);
    CHECK(o.err == "magnus: error: --set " + b.message + "\n");  // each value came from --set
    CHECK(o.out.empty());
  }
  CHECK(stray_files(dir, {}).empty());
  // A large density alone keeps every figure finite: it runs, and nothing prints inf or nan.
  const Outcome ok = magnus_cmd(
      {"run", demo, "-o", dir + "/r.h5", "--set", "flow.density=1e300", "--set", "grid.n_theta=32"}, dir);
  CHECK(ok.status == 0);
  CHECK(ok.out.find("inf") == std::string::npos);
  CHECK(ok.out.find("nan") == std::string::npos);
}

TEST_CASE("a successful run replaces the old result and prints the summary", "[app][cli]") {
  const std::string dir = test::temp_dir("cli-ok");
  std::ofstream(dir + "/case.toml") << scene + "[grid]\nn_theta = 32\n";
  // The old result (a coarser grid) is magnus's own: replaced.
  REQUIRE(magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5", "-q", "--set", "grid.n_theta=16"}, dir)
              .status == 0);
  const Outcome o = magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5"}, dir);
  REQUIRE(o.status == 0);
  REQUIRE(o.err.empty());
  for (const char* s : {"C_L", "Kutta–Joukowski", "seed estimate", "C_D", "ΔP top−bottom", "Magnus S",
                        "stagnation", "errors", "timing"})
    REQUIRE(o.out.find(s) != std::string::npos);
  REQUIRE(ResultFile(dir + "/r.h5").attr_string("/", "format") == "magnus-flow");
  REQUIRE(stray_files(dir, {"case.toml", "r.h5", "r.xmf"}).empty());
  const Outcome i = magnus_cmd({"inspect", dir + "/r.h5"}, dir);
  REQUIRE(i.status == 0);
  REQUIRE(i.out.find("/fields/psi") != std::string::npos);
  REQUIRE(i.out.find("cl_kutta_joukowski") != std::string::npos);
  const Outcome bad = magnus_cmd({"inspect", dir + "/case.toml"}, dir);
  REQUIRE(bad.status != 0);
  REQUIRE(lines(bad.err) == 1);
  REQUIRE(magnus_cmd({"--version"}, dir).out.find("magnus") != std::string::npos);
}

/// What is wrong with an .expect file ("" if nothing). Every key is known; keys that go together are given
/// together; every figure a case has is stated: C_L (a number with cl_rel_max or cl_abs_max, or "undefined"
/// with lift_abs_max when U = 0), C_D (cd_abs_max, U > 0), the circulation (with circulation_rel_max or
/// circulation_abs_max), the stagnation points (stagnation_deg, [] for none, with stagnation_tol_deg) and a
/// free point's radius (stagnation_free_r_over_a with stagnation_r_rel_tol).
/// A navier-stokes case's expectations: its means and St against published values, each with a tolerance.
std::string expect_problem_viscous(const toml::table& ex) {
  static const std::vector<std::string> known = {"model",        "set",         "cl_mean",
                                                 "cl_mean_rel_max", "cd_mean",  "cd_mean_rel_max",
                                                 "strouhal",     "strouhal_rel_max"};
  for (auto&& [k, v] : ex) {
    (void)v;
    if (std::find(known.begin(), known.end(), std::string(k.str())) == known.end())
      return "unknown key " + std::string(k.str()) + " for a navier-stokes case";
  }
  // C_D always; C_L and St with their tolerances, or neither (a steady case: no shedding, C_L 0 at α = 0).
  for (const std::string k : {"cd_mean", "cd_mean_rel_max"})
    if (!ex[k].value<double>()) return "missing number " + k;
  for (const std::string k : {"cl_mean", "strouhal"}) {
    if (ex.contains(k) != ex.contains(k + "_rel_max")) return k + " and " + k + "_rel_max go together";
    for (const std::string& key : {k, k + "_rel_max"})
      if (ex.contains(key) && !ex[key].value<double>()) return "missing number " + key;
  }
  return "";
}

std::string expect_problem(const toml::table& ex) {
  if (ex["model"].value<std::string>() == std::optional<std::string>("navier-stokes"))
    return expect_problem_viscous(ex);
  static const std::vector<std::string> known = {"set",
                                                 "cl",
                                                 "cl_rel_max",
                                                 "cl_abs_max",
                                                 "cd_abs_max",
                                                 "lift_abs_max",
                                                 "circulation",
                                                 "circulation_rel_max",
                                                 "circulation_abs_max",
                                                 "stagnation_deg",
                                                 "stagnation_tol_deg",
                                                 "stagnation_free_r_over_a",
                                                 "stagnation_r_rel_tol",
                                                 "thrust_total",
                                                 "thrust_total_rel_max",
                                                 "side_force_total_abs_max"};
  for (auto&& [k, v] : ex) {
    (void)v;
    if (std::find(known.begin(), known.end(), std::string(k.str())) == known.end())
      return "unknown key " + std::string(k.str());
  }
  auto has = [&](const char* k) { return ex.contains(k); };
  auto number = [&](const char* k) { return ex[k].value<double>().has_value(); };
  for (const char* k : {"cl", "circulation", "stagnation_deg", "stagnation_tol_deg"})
    if (!has(k)) return std::string("missing key ") + k;
  for (const char* k :
       {"cl_rel_max", "cl_abs_max", "cd_abs_max", "lift_abs_max", "circulation", "circulation_rel_max",
        "circulation_abs_max", "stagnation_tol_deg", "stagnation_free_r_over_a", "stagnation_r_rel_tol"})
    if (has(k) && !number(k)) return std::string(k) + " must be a number";
  if (!ex["stagnation_deg"].is_array()) return "stagnation_deg must be an array of angles (deg)";
  if (ex["cl"].is_string()) {
    if (*ex["cl"].value<std::string>() != "undefined") return "cl must be a number or \"undefined\"";
    if (!has("lift_abs_max")) return "cl = \"undefined\" needs lift_abs_max";
    for (const char* k : {"cl_rel_max", "cl_abs_max", "cd_abs_max"})
      if (has(k)) return std::string(k) + " does not go with cl = \"undefined\"";
  } else {
    if (!number("cl")) return "cl must be a number or \"undefined\"";
    if (has("cl_rel_max") == has("cl_abs_max")) return "cl needs exactly one of cl_rel_max, cl_abs_max";
    if (!has("cd_abs_max")) return "cl needs cd_abs_max";
  }
  if (has("circulation_rel_max") == has("circulation_abs_max"))
    return "circulation needs exactly one of circulation_rel_max, circulation_abs_max";
  if (has("stagnation_free_r_over_a") != has("stagnation_r_rel_tol"))
    return "stagnation_free_r_over_a and stagnation_r_rel_tol go together";
  // A rotor sail (cylinder.span and flow.course): its thrust over the span, N.
  if (has("thrust_total") != has("thrust_total_rel_max") || has("thrust_total") != has("side_force_total_abs_max"))
    return "thrust_total, thrust_total_rel_max and side_force_total_abs_max go together";
  for (const char* k : {"thrust_total", "thrust_total_rel_max", "side_force_total_abs_max"})
    if (has(k) && !number(k)) return std::string(k) + " must be a number";
  return "";
}

TEST_CASE(".expect files: an unknown, missing or unpaired key is refused by name", "[app][cases]") {
  const std::string ok =
      "cl = -6.0\ncl_rel_max = 1e-3\ncd_abs_max = 1e-12\ncirculation = 6.0\n"
      "circulation_rel_max = 1e-10\nstagnation_deg = [30.0, 150.0]\nstagnation_tol_deg = 0.5\n";
  CHECK(expect_problem(toml::parse(ok)) == "");
  CHECK(expect_problem(toml::parse(ok + "cl_rel_mx = 1e-3\n")) == "unknown key cl_rel_mx");
  CHECK(expect_problem(toml::parse(ok + "stagnation_free_r_over_a = 3.7\n")) ==
        "stagnation_free_r_over_a and stagnation_r_rel_tol go together");
  CHECK(expect_problem(toml::parse(ok + "cl_abs_max = 1e-3\n")) ==
        "cl needs exactly one of cl_rel_max, cl_abs_max");
  toml::table no_tol = toml::parse(ok);
  no_tol.erase("stagnation_tol_deg");
  CHECK(expect_problem(no_tol) == "missing key stagnation_tol_deg");
  toml::table undefined = toml::parse(ok);
  undefined.insert_or_assign("cl", "undefined");
  CHECK(expect_problem(undefined) == "cl = \"undefined\" needs lift_abs_max");
}

TEST_CASE("every shipped case runs and meets the expected figures beside it", "[app][cases]") {
  std::vector<std::string> cases;
  for (const auto& e : fs::directory_iterator(std::string(MAGNUS_SOURCE_DIR) + "/cases"))
    if (e.path().extension() == ".toml") cases.push_back(e.path().string());
  std::sort(cases.begin(), cases.end());
  REQUIRE(cases.size() >= 6);
  for (const auto& path : cases) {
    DYNAMIC_SECTION(fs::path(path).filename().string()) {
      const std::string expect_path = fs::path(path).replace_extension(".expect").string();
      REQUIRE(fs::exists(expect_path));
      const toml::table ex = toml::parse_file(expect_path);
      REQUIRE(expect_problem(ex) == "");
      auto num = [&](const char* k) { return *ex[k].value<double>(); };
      const std::string dir = test::temp_dir("case");
      std::vector<std::string> args = {"run", path, "-o", dir + "/r.h5", "-q"};
      if (auto sets = ex["set"].as_array())
        for (const auto& s : *sets) args.insert(args.end(), {"--set", *s.value<std::string>()});
      const Outcome o = magnus_cmd(args, dir);
      CAPTURE(o.err);
      REQUIRE(o.status == 0);
      const ResultFile f(dir + "/r.h5");
      if (ex.contains("model")) {  // navier-stokes: the means and St against published values
        for (const char* k : {"cl_mean", "cd_mean", "strouhal"}) {
          if (!ex.contains(k)) continue;
          CAPTURE(k, f.attr_double("/forces", k));
          REQUIRE(std::fabs(f.attr_double("/forces", k) / num(k) - 1) <= num((std::string(k) + "_rel_max").c_str()));
        }
        continue;
      }
      if (ex["cl"].is_string()) {
        REQUIRE_FALSE(f.has_attr("/forces", "cl"));
        REQUIRE_FALSE(f.has_attr("/forces", "cd"));
        REQUIRE(std::fabs(f.attr_double("/forces", "lift")) <= num("lift_abs_max"));
      } else {
        const double cl = num("cl"), got = f.attr_double("/forces", "cl");
        if (ex.contains("cl_rel_max"))
          REQUIRE(std::fabs(got / cl - 1) <= num("cl_rel_max"));
        else
          REQUIRE(std::fabs(got - cl) <= num("cl_abs_max"));
        REQUIRE(std::fabs(f.attr_double("/forces", "cd")) <= num("cd_abs_max"));
      }
      const double g = num("circulation"), g_got = f.attr_double("/forces", "circulation_measured");
      if (ex.contains("circulation_rel_max"))
        REQUIRE(std::fabs(g_got / g - 1) <= num("circulation_rel_max"));
      else
        REQUIRE(std::fabs(g_got - g) <= num("circulation_abs_max"));
      const toml::array& deg = *ex["stagnation_deg"].as_array();
      const auto st_r = f.dataset("/stagnation/r"), st_theta = f.dataset("/stagnation/theta");
      REQUIRE(st_r.size() == st_theta.size());
      const size_t n_points = st_r.size();
      const double tol = num("stagnation_tol_deg");
      REQUIRE(n_points >= std::min<size_t>(1, deg.size()));
      // Every expected angle has a computed point near it, and every computed point an expected angle.
      auto near = [&](double a, double b) { return std::fabs(std::remainder(a - b, 360.0)) <= tol; };
      for (size_t k = 0; k < n_points; ++k) {
        bool found = false;
        for (const auto& d : deg) found = found || near(st_theta[k] * 180 / M_PI, *d.value<double>());
        REQUIRE(found);
      }
      for (const auto& d : deg) {
        bool found = false;
        for (size_t k = 0; k < n_points; ++k)
          found = found || near(st_theta[k] * 180 / M_PI, *d.value<double>());
        REQUIRE(found);
      }
      if (ex.contains("thrust_total")) {
        CAPTURE(f.attr_double("/forces", "thrust_total"));
        REQUIRE(std::fabs(f.attr_double("/forces", "thrust_total") / num("thrust_total") - 1) <=
                num("thrust_total_rel_max"));
        REQUIRE(std::fabs(f.attr_double("/forces", "side_force_total")) <= num("side_force_total_abs_max"));
      }
      if (ex.contains("stagnation_free_r_over_a")) {
        REQUIRE(n_points == 1);
        const double a = f.attr_double("/parameters", "radius");
        REQUIRE(std::fabs(st_r[0] / a / num("stagnation_free_r_over_a") - 1) <= num("stagnation_r_rel_tol"));
      }
    }
  }
}

TEST_CASE("outputs never overwrite inputs, each other or a directory, a directory is not a case file",
          "[app][cli]") {
  const std::string dir = test::temp_dir("cli-clobber");
  std::ofstream(dir + "/case.toml") << scene + "[grid]\nn_theta = 16\n";
  std::ofstream(dir + "/keep.xmf") << "KEEP";
  fs::create_directory(dir + "/r.xmf");
  struct Bad {
    std::vector<std::string> args;
    const char* needle;
  };
  const std::vector<Bad> bad = {
      {{"run", dir + "/case.toml", "-o", dir + "/keep.xmf"}, "same name"},   // result = its own sidecar
      {{"run", dir + "/case.toml", "-o", dir + "/r.h5"}, "is a directory"},  // sidecar r.xmf is a directory
      {{"run", dir + "/case.toml", "-o", dir + "/case.toml"}, "overwrite the input"},
      {{"run", dir}, "not a regular file"},
      {{"sweep", dir + "/case.toml", "--spin-ratio", "0:1:0.5", "--csv", dir + "/case.toml"},
       "overwrite the input"},
      {{"sweep", dir + "/case.toml", "--spin-ratio", "0:1:0.5", "--csv", dir + "/s.out", "-o",
        dir + "/s.out"},
       "same name"},
      {{"bench", dir + "/case.toml", "--ladder", "16", "--csv", dir + "/case.toml"}, "overwrite the input"},
  };
  for (const auto& b : bad) {
    const Outcome o = magnus_cmd(b.args, dir);
    CAPTURE(b.args, o.err);
    REQUIRE(o.status != 0);
    REQUIRE(lines(o.err) == 1);
    REQUIRE(o.err.find(b.needle) != std::string::npos);
  }
  REQUIRE(slurp(dir + "/keep.xmf") == "KEEP");
  REQUIRE(slurp(dir + "/case.toml") == scene + "[grid]\nn_theta = 16\n");
  REQUIRE(stray_files(dir, {"case.toml", "keep.xmf", "r.xmf"}).empty());
  // compare --csv onto one of its inputs
  REQUIRE(magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/a.h5", "-q"}, dir).status == 0);
  const std::string before = slurp(dir + "/a.h5");
  const Outcome o = magnus_cmd({"compare", dir + "/a.h5", "--csv", dir + "/a.h5"}, dir);
  REQUIRE(o.status != 0);
  REQUIRE(o.err.find("overwrite the input") != std::string::npos);
  REQUIRE(slurp(dir + "/a.h5") == before);
}

TEST_CASE("run: output.compression writes a smaller file with the same figures", "[app][cli]") {
  const std::string dir = test::temp_dir("cli-compression");
  const std::string cs = std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml";
  const auto plain = test::magnus_cmd({"run", cs, "-o", dir + "/plain.h5", "--set", "grid.n_theta=128"}, dir);
  const auto packed = test::magnus_cmd(
      {"run", cs, "-o", dir + "/packed.h5", "--set", "grid.n_theta=128", "--set", "output.compression=6"},
      dir);
  REQUIRE(plain.status == 0);
  REQUIRE(packed.status == 0);
  REQUIRE(test::slurp(dir + "/packed.h5").size() < 0.9 * test::slurp(dir + "/plain.h5").size());
  const ResultFile a(dir + "/plain.h5"), b(dir + "/packed.h5");
  REQUIRE(a.dataset("/fields/psi") == b.dataset("/fields/psi"));
  REQUIRE(a.attr_double("/forces", "cl") == b.attr_double("/forces", "cl"));
}
