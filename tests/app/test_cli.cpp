// The magnus command as a user runs it: exit codes, one-line errors, no partial or clobbered files,
// and every shipped case against its expected figures.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "io/hdf5_io.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {


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

TEST_CASE("bad input: non-zero exit, one line naming the key or file, no output, old output intact", "[app][cli]") {
  struct Bad {
    const char* what;
    std::string toml;
    std::string needle;
  };
  const std::vector<Bad> bad = {
      {"malformed TOML", "[grid\nn_theta = 64\n", "malformed TOML"},
      {"unknown key", "[grid]\nn_thetta = 64\n", "grid.n_theta"},
      {"wrong type", "[flow]\nspeed = \"fast\"\n", "flow.speed"},
      {"out of range", "[flow]\ndensity = -1.0\n", "flow.density"},
      {"NaN", "[flow]\nspeed = nan\n", "flow.speed"},
      {"inf", "[cylinder]\nspin = inf\n", "cylinder.spin"},
      {"spin and spin_ratio", "[cylinder]\nspin = 1.0\nspin_ratio = 2.0\n", "cylinder.spin_ratio"},
      {"n_theta odd", "[grid]\nn_theta = 63\n", "grid.n_theta"},
      {"n_theta < 8", "[grid]\nn_theta = 4\n", "grid.n_theta"},
      {"R/a <= 1", "[domain]\nouter_radius = 0.5\n", "domain.outer_radius"},
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
    std::ofstream(dir + "/case.toml") << "[grid]\nn_theta = 16\n";
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
          std::vector<std::string>{"run", dir + "/case.toml", "--bogus"}, std::vector<std::string>{"frobnicate"}}) {
      const Outcome o = magnus_cmd(args, dir);
      CAPTURE(o.err);
      REQUIRE(o.status != 0);
      REQUIRE(lines(o.err) == 1);
    }
    REQUIRE(stray_files(dir, {"case.toml"}).empty());
  }
}

TEST_CASE("a successful run replaces the old result and prints the summary", "[app][cli]") {
  const std::string dir = test::temp_dir("cli-ok");
  std::ofstream(dir + "/case.toml") << "[grid]\nn_theta = 32\n";
  std::ofstream(dir + "/r.h5") << "OLD";
  const Outcome o = magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5"}, dir);
  REQUIRE(o.status == 0);
  REQUIRE(o.err.empty());
  for (const char* s : {"C_L", "Kutta–Joukowski", "seed estimate", "C_D", "ΔP top−bottom", "Magnus S", "stagnation",
                        "errors", "timing"})
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
      const std::string dir = test::temp_dir("case");
      std::vector<std::string> args = {"run", path, "-o", dir + "/r.h5", "-q"};
      if (auto sets = ex["set"].as_array())
        for (const auto& s : *sets) args.insert(args.end(), {"--set", *s.value<std::string>()});
      const Outcome o = magnus_cmd(args, dir);
      CAPTURE(o.err);
      REQUIRE(o.status == 0);
      const ResultFile f(dir + "/r.h5");
      if (ex["cl"].is_string()) {
        REQUIRE_FALSE(f.has_attr("/forces", "cl"));
      } else {
        const double cl = *ex["cl"].value<double>(), got = f.attr_double("/forces", "cl");
        if (auto rel = ex["cl_rel_max"].value<double>()) REQUIRE(std::fabs(got / cl - 1) <= *rel);
        if (auto abs = ex["cl_abs_max"].value<double>()) REQUIRE(std::fabs(got - cl) <= *abs);
      }
      if (auto cd = ex["cd_abs_max"].value<double>()) REQUIRE(std::fabs(f.attr_double("/forces", "cd")) <= *cd);
      if (auto lift = ex["lift_abs_max"].value<double>()) REQUIRE(std::fabs(f.attr_double("/forces", "lift")) <= *lift);
      if (auto g = ex["circulation"].value<double>())
        REQUIRE(std::fabs(f.attr_double("/forces", "circulation_measured") / *g - 1) <= *ex["circulation_rel_max"].value<double>());
      if (auto deg = ex["stagnation_deg"].as_array()) {
        std::vector<size_t> shape;
        const auto pts = f.dataset("/stagnation/numeric", &shape);
        const double tol = *ex["stagnation_tol_deg"].value<double>();
        REQUIRE(shape[0] >= 1);
        // Every expected angle has a computed point near it, and every computed point an expected angle.
        auto near = [&](double a, double b) { return std::fabs(std::remainder(a - b, 360.0)) <= tol; };
        for (size_t k = 0; k < shape[0]; ++k) {
          bool found = false;
          for (const auto& d : *deg) found = found || near(pts[2 * k + 1] * 180 / M_PI, *d.value<double>());
          REQUIRE(found);
        }
        for (const auto& d : *deg) {
          bool found = false;
          for (size_t k = 0; k < shape[0]; ++k) found = found || near(pts[2 * k + 1] * 180 / M_PI, *d.value<double>());
          REQUIRE(found);
        }
        if (auto rs = ex["stagnation_free_r_over_a"].value<double>()) {
          REQUIRE(shape[0] == 1);
          const double a = f.attr_double("/parameters", "radius");
          REQUIRE(std::fabs(pts[0] / a / *rs - 1) <= *ex["stagnation_r_rel_tol"].value<double>());
        }
      }
    }
  }
}

TEST_CASE("outputs never overwrite inputs, each other or a directory; a directory is not a case file", "[app][cli]") {
  const std::string dir = test::temp_dir("cli-clobber");
  std::ofstream(dir + "/case.toml") << "[grid]\nn_theta = 16\n";
  std::ofstream(dir + "/keep.xmf") << "KEEP";
  fs::create_directory(dir + "/r.xmf");
  struct Bad {
    std::vector<std::string> args;
    const char* needle;
  };
  const std::vector<Bad> bad = {
      {{"run", dir + "/case.toml", "-o", dir + "/keep.xmf"}, "same name"},         // result = its own sidecar
      {{"run", dir + "/case.toml", "-o", dir + "/r.h5"}, "is a directory"},        // sidecar r.xmf is a directory
      {{"run", dir + "/case.toml", "-o", dir + "/case.toml"}, "overwrite the input"},
      {{"run", dir}, "not a regular file"},
      {{"sweep", dir + "/case.toml", "--spin-ratio", "0:1:0.5", "--csv", dir + "/case.toml"}, "overwrite the input"},
      {{"sweep", dir + "/case.toml", "--spin-ratio", "0:1:0.5", "--csv", dir + "/s.out", "-o", dir + "/s.out"},
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
  REQUIRE(slurp(dir + "/case.toml") == "[grid]\nn_theta = 16\n");
  REQUIRE(stray_files(dir, {"case.toml", "keep.xmf", "r.xmf"}).empty());
  // compare --csv onto one of its inputs
  REQUIRE(magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/a.h5", "-q"}, dir).status == 0);
  const std::string before = slurp(dir + "/a.h5");
  const Outcome o = magnus_cmd({"compare", dir + "/a.h5", "--csv", dir + "/a.h5"}, dir);
  REQUIRE(o.status != 0);
  REQUIRE(o.err.find("overwrite the input") != std::string::npos);
  REQUIRE(slurp(dir + "/a.h5") == before);
}
