// The navier-stokes command line beyond runs and shards: the S(Re, α) map's --reynolds alone (one branch
// continued in Re), what an unstable point reports, --orbits (shedding points as orbits), merge refusing
// shards that decided stability differently, the plot refused before solving when nothing would be
// drawable, `magnus stability` with its refusals, the bench's options, "auto" marching an unstable state,
// Ctrl-C before the march, and the progress line on a terminal.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "io/ns_sweep_file.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {

const std::string s_map = std::string(MAGNUS_SOURCE_DIR) + "/cases/s_map.toml";

void write_case(const std::string& path, int n_theta, double alpha) {
  std::ofstream(path)
      << "title = \"coarse map\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\n"
         "spin_ratio = "
      << alpha
      << "\n[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = 20.0\n[domain]\n"
         "outer_radius = 20.0\n[grid]\nn_theta = "
      << n_theta << "\n";
}


}  // namespace

TEST_CASE("navier-stokes sweep --reynolds alone: the case's α continued in Re, the states of separate solves",
          "[app][sweep]") {
  const std::string dir = temp_dir("ns-sweep-re");
  write_case(dir + "/c.toml", 32, 1.0);
  const Outcome o = magnus_cmd({"sweep", dir + "/c.toml", "--reynolds", "20:60:20", "--steady-only", "-o",
                                dir + "/re.h5", "--plot", dir + "/re.png"},
                               dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("continued in Re at α = 1") != std::string::npos);
  // No fixed Re rule: where the map is real is computed (magnus plot --onset3d), and the summary says so.
  CHECK(o.out.find("3D           where this 2D map is real is not computed here: magnus plot MAP.h5 --onset3d") !=
        std::string::npos);
  CHECK(fs::file_size(dir + "/re.png") > 10000);  // S against Re, one curve
  // The same points as rows of a map, each row started from the potential flow.
  REQUIRE(magnus_cmd({"sweep", dir + "/c.toml", "--spin-ratio", "1:1:1", "--reynolds", "20:60:20",
                      "--steady-only", "-q", "-o", dir + "/map.h5"},
                     dir)
              .status == 0);
  const NsMap re = read_ns_map_hdf5(dir + "/re.h5"), map = read_ns_map_hdf5(dir + "/map.h5");
  CHECK(re.continued_in_re());
  REQUIRE(re.points.size() == 3);
  REQUIRE(map.points.size() == 3);
  for (size_t i = 0; i < 3; ++i) {
    INFO("Re " << re.points[i].reynolds);
    CHECK(re.points[i].alpha == 1.0);
    CHECK(re.points[i].reynolds == 20.0 * double(i + 1));
    REQUIRE(re.points[i].converged);
    // One steady state, reached from two starts: equal to Newton's tolerance.
    CHECK(re.points[i].cl_steady == Approx(map.points[i].cl_steady).epsilon(1e-8));
    CHECK(re.points[i].cd_steady == Approx(map.points[i].cd_steady).epsilon(1e-8));
  }
  // A potential case has no Reynolds number to sweep.
  const Outcome p = magnus_cmd({"sweep", std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml",
                                "--reynolds", "20:60:20", "-o", dir + "/p.h5"},
                               dir);
  CHECK(p.status != 0);
  CHECK(one_line(p.err));
  CHECK(p.err.find("--reynolds alone sweeps a navier-stokes case") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/p.h5"));
}

TEST_CASE("navier-stokes map: an unstable point is marched from rest and says what the march found",
          "[app][sweep]") {
  // Re 100 on the map's grid: at α = 5.1 the continued steady state is unstable and the march sheds; at
  // α = 5.4 the continued state is unstable too, but the march from rest settles on another, stable steady
  // state (the one magnus run finds from the potential flow), and the point says so.
  const std::string dir = temp_dir("ns-map-march");
  const Outcome o = magnus_cmd({"sweep", s_map, "--spin-ratio", "4.8:5.4:0.3", "--reynolds", "100:100:1", "-q",
                                "-o", dir + "/m.h5"},
                               dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const NsMap m = read_ns_map_hdf5(dir + "/m.h5");
  REQUIRE(m.points.size() == 3);
  CHECK(m.stability_method == "eigenvalues");
  const NsMapPoint &a = m.points[0], &b = m.points[1], &c = m.points[2];
  CHECK(a.source == MapSource::steady);
  CHECK(a.stable == std::optional<bool>(true));
  CHECK(b.stable == std::optional<bool>(false));
  CHECK(b.source == MapSource::averaged_unstable);
  // The slow shedding of high spin: St 0.0230 from the crossings, 0.0231 from the spectrum of the march's
  // lift (successive maxima of its faster ripple gave 0.120).
  CHECK(b.strouhal == Approx(0.0231).epsilon(0.03));
  CHECK(c.stable == std::optional<bool>(false));
  REQUIRE(c.source == MapSource::marched_steady);
  CHECK(std::isnan(c.strouhal));
  CHECK(std::fabs(c.cl - c.cl_steady) > 0.005 * std::fabs(c.cl_steady));  // not the continued state (1% apart)
  const Outcome r = magnus_cmd({"run", s_map, "--set", "cylinder.spin_ratio=5.4", "-o", dir + "/r.h5", "--json"},
                               dir);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(c.cl == Approx(j["forces"]["cl"]["value"].get<double>()).epsilon(1e-4));
}

TEST_CASE("navier-stokes map --orbits: shedding points as orbits in the file, inspect and JSON, and its refusals",
          "[app][sweep]") {
  const std::string dir = temp_dir("ns-map-orbits");
  const Outcome o = magnus_cmd({"sweep", s_map, "--spin-ratio", "0:0.25:0.25", "--reynolds", "100:100:1", "--orbits",
                                "-o", dir + "/m.h5", "--json"},
                               dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  // The progress lines say how each orbit started: the first on the growing mode, the next continued.
  CHECK(o.err.find("α 0: steady, the shedding orbit (from hopf mode") != std::string::npos);
  CHECK(o.err.find("α 0.25: steady, the shedding orbit (from continued") != std::string::npos);
  const auto j = nlohmann::json::parse(o.out);
  CHECK(j["stability"]["orbits"].get<bool>());
  const NsMap m = read_ns_map_hdf5(dir + "/m.h5");
  CHECK(m.orbits);
  REQUIRE(m.points.size() == 2);
  for (const NsMapPoint& p : m.points) {
    CHECK(p.source == MapSource::orbit);
    CHECK(p.regime == double(MapRegime::shedding));
    CHECK(p.strouhal == Approx(0.155).epsilon(0.01));  // the map grid's shedding at Re 100
  }
  CHECK(j["columns"].contains("regime"));
  const Outcome i = magnus_cmd({"inspect", dir + "/m.h5"}, dir);
  CHECK(i.out.find("unstable points: shedding orbits (marched from rest where none was found)") != std::string::npos);
  // --orbits computes what --steady-only leaves out; a potential case has no shedding.
  const Outcome both = magnus_cmd({"sweep", s_map, "--spin-ratio", "0:1:1", "--reynolds", "100:100:1", "--orbits",
                                   "--steady-only", "-o", dir + "/b.h5"},
                                  dir);
  CHECK(both.status != 0);
  CHECK(one_line(both.err));
  CHECK(both.err.find("--orbits and --steady-only") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/b.h5"));
  const Outcome pot = magnus_cmd(
      {"sweep", std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml", "--spin-ratio", "0:1:1", "--orbits"}, dir);
  CHECK(pot.status != 0);
  CHECK(one_line(pot.err));
  CHECK(pot.err.find("--orbits need a navier-stokes case") != std::string::npos);
}

TEST_CASE("navier-stokes merge: shards that decided stability differently are refused", "[app][merge]") {
  const std::string dir = temp_dir("ns-merge-stability");
  write_case(dir + "/c.toml", 32, 0.0);
  const std::vector<std::string> map = {"sweep", dir + "/c.toml", "--spin-ratio", "1:2:1", "--reynolds",
                                        "20:40:20", "-q"};
  auto shard = [&](const std::string& k, const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> a = map;
    a.insert(a.end(), {"--shard", k, "-o", dir + "/" + out});
    a.insert(a.end(), extra.begin(), extra.end());
    return magnus_cmd(a, dir).status;
  };
  REQUIRE(shard("1/2", "s1.h5", {}) == 0);
  REQUIRE(shard("2/2", "steady.h5", {"--steady-only"}) == 0);
  REQUIRE(shard("2/2", "march.h5", {"--stability", "march"}) == 0);
  REQUIRE(shard("2/2", "orbits.h5", {"--orbits"}) == 0);
  REQUIRE(shard("2/2", "s2.h5", {}) == 0);
  for (const std::string other : {"steady.h5", "march.h5", "orbits.h5"}) {
    const Outcome b = magnus_cmd({"merge", dir + "/bad.h5", dir + "/s1.h5", dir + "/" + other}, dir);
    INFO(other << ": " << b.err);
    CHECK(b.status != 0);
    CHECK(one_line(b.err));
    CHECK(b.err.find("decided stability differently") != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/bad.h5"));
  }
  CHECK(magnus_cmd({"merge", dir + "/good.h5", dir + "/s1.h5", dir + "/s2.h5"}, dir).status == 0);
}

TEST_CASE("navier-stokes sweep: nothing drawable or '-' for a binary output is refused before solving",
          "[app][sweep]") {
  const std::string dir = temp_dir("ns-sweep-refuse");
  write_case(dir + "/c.toml", 32, 0.0);
  struct Bad {
    std::vector<std::string> args;
    const char* expect;
  };
  const std::string c = dir + "/c.toml";
  for (const Bad& b : {Bad{{"sweep", c, "--spin-ratio", "0:0:1", "--reynolds", "20:40:20", "--csv", dir + "/o.csv",
                            "-o", dir + "/o.h5", "--plot", dir + "/o.png"},
                           "undefined at α = 0"},
                       Bad{{"sweep", c, "--spin-ratio", "0:1:1", "--reynolds", "0.001:0.002:0.001", "-o",
                            dir + "/o.h5"},
                           "below 0.01, the floor"},
                       Bad{{"sweep", c, "--spin-ratio", "0:1:1", "-o", "-"}, "cannot go to standard output"},
                       Bad{{"sweep", c, "--spin-ratio", "0:1:1", "--plot", "-"}, "cannot go to standard output"},
                       Bad{{"run", c, "-o", "-"}, "cannot go to standard output"},
                       Bad{{"merge", "-", dir + "/x.h5"}, "cannot go to standard output"}}) {
    const Outcome o = magnus_cmd(b.args, dir);
    INFO(b.args[0] << " " << b.args.back() << ": " << o.err);
    CHECK(o.status != 0);
    CHECK(one_line(o.err));
    CHECK(o.err.find(b.expect) != std::string::npos);
    CHECK(o.err.find("magnus: Re") == std::string::npos);  // refused before any point was solved
  }
  for (const char* f : {"o.csv", "o.h5", "o.png", "-", "-.xmf"}) CHECK_FALSE(fs::exists(dir + "/" + f));
}

TEST_CASE("magnus stability: the eigenvalues, the critical spin ratio, and refusals before solving",
          "[app][stability]") {
  const std::string dir = temp_dir("ns-stability-cli");
  // `magnus stability <the map's case> ARGS --json`, required to succeed, its output parsed.
  const auto stability_json = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"stability", s_map});
    args.push_back("--json");
    const Outcome r = magnus_cmd(args, dir);
    INFO(r.err);
    REQUIRE(r.status == 0);
    return nlohmann::json::parse(r.out);
  };
  // Re 60, α 1.5 on the map's grid: the wake's pair grows (unstable); bisection brackets the critical α.
  auto j = stability_json({"--set", "flow.reynolds=60", "--set", "cylinder.spin_ratio=1.5"});
  CHECK(j["stable"] == false);
  const auto& lead = j["eigenvalues"][0];
  CHECK(lead["growth_rate"].get<double>() > 0.0);
  CHECK(lead["strouhal"].get<double>() == Approx(std::fabs(lead["frequency"].get<double>()) / (2.0 * M_PI)));
  // Eigenvalues rightmost first.
  for (size_t k = 1; k < j["eigenvalues"].size(); ++k)
    CHECK(j["eigenvalues"][k]["growth_rate"].get<double>() <= j["eigenvalues"][k - 1]["growth_rate"].get<double>());
  // The evidence: each eigenvalue's residual, the shifts searched (the five defaults first) and their disks.
  for (const auto& e : j["eigenvalues"]) CHECK(e["residual"].get<double>() <= 1e-5);
  REQUIRE(j["search"]["shifts"].size() >= 5);
  CHECK(j["search"]["shifts"][0]["shift_real"].get<double>() == 0.1);
  CHECK(j["search"]["shifts"][4]["shift_imag"].get<double>() == 1.4);
  CHECK(j["search"]["covered"].is_boolean());
  for (const auto& sh : j["search"]["shifts"]) CHECK(sh["radius"].get<double>() >= 0.0);

  j = stability_json({"--set", "flow.reynolds=60", "--critical-spin", "1.4:1.9", "--tolerance", "0.05"});
  const double lo = j["bracket"][0], hi = j["bracket"][1], ac = j["critical_spin_ratio"];
  // The secant search stops when its root moves by at most half the tolerance (or the bracket is that narrow).
  CHECK((j["change"].get<double>() <= 0.025 || hi - lo <= 0.05));
  CHECK((lo <= ac && ac <= hi));
  CHECK((1.4 <= lo && hi <= 1.9));
  CHECK(j["at_a"]["stable"] == false);  // sheds below the threshold
  CHECK(j["at_b"]["stable"] == true);   // steady above it
  CHECK(j["evaluations"].get<int>() < 8);  // bisection to 0.05 from a width of 0.5 took 6 points and 2 more ends
  REQUIRE(j["points"].size() == j["evaluations"].get<size_t>());
  CHECK(j["points"][0]["value"].get<double>() == 1.4);  // the ends first
  CHECK(j["points"][1]["value"].get<double>() == 1.9);
  for (const auto& pt : j["points"]) CHECK(pt["newton_seconds"].get<double>() >= 0.0);

  // The onset in Re at α = 0 on the same coarse grid, and the curve α_L(Re) over three Reynolds numbers.
  j = stability_json({"--critical-reynolds", "40:60", "--tolerance", "0.1"});
  const double re_c = j["critical_reynolds"];
  CHECK((j["bracket"][0].get<double>() <= re_c && re_c <= j["bracket"][1].get<double>()));
  CHECK(j["at_a"]["stable"] == true);   // steady below the onset
  CHECK(j["at_b"]["stable"] == false);  // sheds above it
  CHECK(j["onset_strouhal"].get<double>() > 0.08);
  CHECK(j["onset_strouhal"].get<double>() < 0.16);
  j = stability_json({"--critical-spin", "1.0:2.2", "--reynolds", "60:80:10", "--tolerance", "0.02"});
  REQUIRE(j["curve"].size() == 3);
  for (size_t k = 0; k < 3; ++k) REQUIRE(j["curve"][k].contains("critical_spin_ratio"));
  // Shedding persists to higher spin as Re rises (Kang, Choi & Lee 1999: α_L 1.4, 1.75, 1.9 at Re 60, 100, 160).
  CHECK(j["curve"][1]["critical_spin_ratio"].get<double>() > j["curve"][0]["critical_spin_ratio"].get<double>());
  CHECK(j["curve"][2]["critical_spin_ratio"].get<double>() > j["curve"][1]["critical_spin_ratio"].get<double>());

  // Re 90 on this grid: the step from Re 80's crossing follows another pair (it decays at 0.13 U/D where the
  // wake's pair grows) and finds no sign change, so the point is searched over the whole range instead: the
  // crossing the point's own search gives.
  j = stability_json({"--critical-spin", "0.05:2.6", "--reynolds", "80:90:10", "--tolerance", "0.002"});
  REQUIRE(j["curve"].size() == 2);
  REQUIRE(j["curve"][1].contains("critical_spin_ratio"));
  CHECK(j["curve"][0]["restarted"].is_null());
  CHECK(j["curve"][1]["restarted"].is_string());
  const double alone =
      stability_json({"--set", "flow.reynolds=90", "--critical-spin", "0.05:2.6", "--tolerance", "0.002"})["critical_spin_ratio"];
  CHECK(std::fabs(j["curve"][1]["critical_spin_ratio"].get<double>() - alone) < 1e-9);  // the same search

  for (auto [args, expect] :
       {std::pair{std::vector<std::string>{"--critical-spin", "0:inf"}, "two finite spin ratios"},
        {std::vector<std::string>{"--critical-spin", "2:1"}, "needs A < B"},
        {std::vector<std::string>{"--critical-spin", "1:2", "--tolerance", "0"}, "must be > 0"},
        {std::vector<std::string>{"--critical-spin", "1:2", "--tolerance", "5"}, "below B − A"},
        {std::vector<std::string>{"--tolerance", "0.1"}, "only used with --critical-spin"},
        {std::vector<std::string>{"--critical-spin", "1:2", "--critical-reynolds", "40:60"}, "give one of them"},
        {std::vector<std::string>{"--critical-reynolds", "0:60"}, "Reynolds numbers > 0"},
        {std::vector<std::string>{"--reynolds", "60:80:10"}, "an onset curve needs --critical-spin"},
        {std::vector<std::string>{"--critical-spin", "1:2", "--spin-ratio", "0:1:0.5"}, "use --reynolds"},
        {std::vector<std::string>{"--critical-spin", "1:2", "--reynolds", "-10:80:10"}, "must be > 0"}}) {
    const Outcome b = magnus_cmd({"stability", s_map}, args, dir);
    INFO(b.err);
    CHECK(refused(b, expect));
  }
}

TEST_CASE("navier-stokes bench: --csv - is the CSV alone, potential-only options are refused", "[app][bench]") {
  const std::string dir = temp_dir("ns-bench-cli");
  const Outcome o = magnus_cmd({"bench", s_map, "--ladder", "16", "--steps", "5", "--csv", "-"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.rfind("n_theta,", 0) == 0);                 // the CSV's header first
  CHECK(o.out.find("magnus bench") == std::string::npos);  // the table went to standard error
  CHECK(o.err.find("magnus bench") != std::string::npos);
  for (const char* opt : {"--method=fft", "--stencil=9-point", "--repeats=3"}) {
    const Outcome b = magnus_cmd({"bench", s_map, "--ladder", "16", opt}, dir);
    INFO(opt << ": " << b.err);
    CHECK(b.status != 0);
    CHECK(one_line(b.err));
    CHECK(b.err.find("only used by a potential-flow bench") != std::string::npos);
  }
}

TEST_CASE("navier-stokes auto run: an unstable steady state is marched and the result says why",
          "[app][ns]") {
  // Re 50, α 0.5 on the map's grid: Newton finds the steady state, its leading pair grows, so "auto"
  // marches from rest to the shedding wake (periodic means, St), and keeps the eigenvalue it decided by.
  const std::string dir = temp_dir("ns-auto-unstable");
  const Outcome o = magnus_cmd({"run", s_map, "--set", "flow.reynolds=50", "--set", "cylinder.spin_ratio=0.5",
                                "-o", dir + "/r.h5", "--json"},
                               dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const auto j = nlohmann::json::parse(o.out);
  const std::string status = j["status"];
  CHECK(status.find("auto: marched in time (the steady state is unstable") != std::string::npos);
  CHECK(status.find("periodic means converged") != std::string::npos);
  CHECK(j["forces"]["eigenvalue_real"]["value"].get<double>() > 0.0);
  CHECK(j["forces"]["strouhal"]["value"].get<double>() > 0.08);
  CHECK(j["forces"]["cl_amplitude"]["value"].get<double>() > 0.01);
}

TEST_CASE("navier-stokes run: Ctrl-C or SIGTERM during the steady solve ends the program at once, writes "
          "nothing",
          "[app][ns]") {
  // The Re 40 grid study takes about 2 s of Newton solves; a signal after 0.3 s must not be held until
  // they end (there is no partial state to keep before the march): the run ends, and no file appears.
  // The shell reports 128 + the signal, as it does for the march's 130 and 143.
  for (const int sig : {SIGINT, SIGTERM}) {
    CAPTURE(sig);
    const std::string dir = temp_dir("ns-int-newton-" + std::to_string(sig));
    const std::string cmd = "'" + std::string(MAGNUS_EXE) + "' run '" + std::string(MAGNUS_SOURCE_DIR) +
                            "/cases/re40_steady.toml' -o '" + dir + "/r.h5' >'" + dir + "/out.txt' 2>'" + dir +
                            "/err.txt' & pid=$!; sleep 0.3; kill -" + std::to_string(sig) + " $pid; wait $pid";
    const int raw = std::system(cmd.c_str());
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 128 + sig);
    CHECK_FALSE(fs::exists(dir + "/r.h5"));
    CHECK_FALSE(fs::exists(dir + "/r.xmf"));
    CHECK(slurp(dir + "/out.txt").empty());
  }
}

TEST_CASE("navier-stokes run: on a terminal a progress line shows t, C_L, C_D, steps/s and the ETA",
          "[app][ns]") {
  // script(1) (util-linux, in every Debian) gives the run a terminal; without one no progress is printed.
  const std::string dir = temp_dir("ns-progress");
  const std::string run = "'" + std::string(MAGNUS_EXE) + "' run '" + std::string(MAGNUS_SOURCE_DIR) +
                          "/cases/re100_alpha1.toml' --set grid.n_theta=96 --set time.mode=unsteady --set "
                          "time.end=40 -o '" + dir + "/r.h5'";
  const int raw = std::system(("script -qec \"" + run + "\" /dev/null >'" + dir + "/tty.txt' 2>&1").c_str());
  REQUIRE(WIFEXITED(raw));
  REQUIRE(WEXITSTATUS(raw) == 0);
  const std::string tty = slurp(dir + "/tty.txt");
  const std::regex line(R"(t = [0-9.]+ D/U of 40  C_L = [-+][0-9.]+  C_D = [0-9.]+  [0-9]+ steps/s  ETA ≤ [0-9]+:[0-9]{2})");
  CHECK(std::regex_search(tty, line));
  const Outcome piped = magnus_cmd({"run", std::string(MAGNUS_SOURCE_DIR) + "/cases/re100_alpha1.toml", "--set",
                                    "grid.n_theta=96", "--set", "time.mode=unsteady", "--set", "time.end=40",
                                    "-o", dir + "/p.h5"},
                                   dir);
  REQUIRE(piped.status == 0);
  CHECK(piped.err.find("ETA") == std::string::npos);  // not a terminal: no progress line
}

TEST_CASE("navier-stokes hard cases on a coarse grid: each a finite result with its error stated",
          "[app][ns]") {
  // α up to 6, Re from 1 to 200, U = 0 (still fluid), on n_θ = 32: every run ends with finite figures (a
  // JSON document holds no NaN or inf), and the summary's wall-cell count says how far to trust them.
  const std::string dir = temp_dir("ns-hard");
  const std::string c = std::string(MAGNUS_SOURCE_DIR) + "/cases/re100_alpha1.toml";
  struct Hard {
    std::vector<std::string> sets;
    bool coarse, unresolved, coefficients;
  };
  for (const Hard& h : {Hard{{"flow.reynolds=1", "cylinder.spin_ratio=6"}, true, false, true},
                        Hard{{"flow.reynolds=200", "cylinder.spin_ratio=0"}, true, false, true},
                        Hard{{"flow.reynolds=200", "cylinder.spin_ratio=6"}, true, true, true},
                        Hard{{"flow.speed=0", "flow.viscosity=0.01", "cylinder.spin=2"}, false, false, false}}) {
    std::vector<std::string> a = {"run", c, "-o", dir + "/h.h5", "--json", "--set", "grid.n_theta=32", "--set",
                                  "time.mode=unsteady", "--set", "time.end=5"};
    for (const auto& s : h.sets) a.insert(a.end(), {"--set", s});
    const Outcome o = magnus_cmd(a, dir);
    INFO(h.sets[0] << " " << h.sets[1] << ": " << o.err);
    REQUIRE(o.status == 0);
    const auto j = nlohmann::json::parse(o.out);
    CHECK(j["forces"]["lift"]["value"].is_number());
    CHECK(j["forces"]["torque"]["value"].is_number());
    CHECK(j["forces"]["cl"]["value"].is_number() == h.coefficients);  // U = 0: undefined, null
    if (h.coefficients) {
      CHECK(j["derived"]["wall_cells_coarse"] == h.coarse);
      CHECK(j["derived"]["wall_cells_unresolved"] == h.unresolved);
    }
  }
}

TEST_CASE("navier-stokes summary of a steady run: values marked steady, no signed zero", "[app][ns]") {
  // Re 20 without spin on the map's grid: auto finds the stable steady state; its C_L is round-off.
  const std::string dir = temp_dir("ns-steady-summary");
  const Outcome o = magnus_cmd({"run", s_map, "--set", "flow.reynolds=20", "--set", "cylinder.spin_ratio=0", "-o",
                                dir + "/r.h5"},
                               dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const std::string cl = line_of(o.out, "C_L  "), cd = line_of(o.out, "C_D  ");
  CHECK(cl.rfind("C_L            0.00000 (steady)", 0) == 0);
  CHECK(cd.find(" (steady)") != std::string::npos);
  CHECK(o.out.find("(mean)") == std::string::npos);
  CHECK(o.out.find("-0.0000") == std::string::npos);
}

TEST_CASE("map error bars: in the CSV and the file, the same values either way, none with --no-error-bars",
          "[app][sweep]") {
  const std::string dir = temp_dir("ns-map-bars");
  write_case(dir + "/c.toml", 32, 0.0);
  const auto map = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"sweep", dir + "/c.toml", "--spin-ratio", "0.5:1:0.5", "--reynolds",
                                     "20:20:1", "--steady-only", "-q", "-o", dir + "/" + out};
    args.insert(args.end(), extra.begin(), extra.end());
    REQUIRE(magnus_cmd(args, dir).status == 0);
    return read_ns_map_hdf5(dir + "/" + out);
  };
  const NsMap with = map("with.h5", {"--csv", dir + "/with.csv"}), without = map("without.h5", {"--no-error-bars"});
  REQUIRE(with.points.size() == 2);
  const std::string csv = slurp(dir + "/with.csv"), header = csv.substr(0, csv.find('\n'));
  for (const char* col : {"cl_rel_estimate", "cd_rel_estimate", "strouhal_rel_estimate", "meets_tolerance"})
    CHECK(header.find(col) != std::string::npos);
  for (size_t i = 0; i < 2; ++i) {
    // The bars do not change what is reported; they are defined with, undefined without.
    CHECK(with.points[i].cl == without.points[i].cl);
    CHECK(with.points[i].cd_rel_estimate > 0.0);
    CHECK(std::isfinite(with.points[i].meets_tolerance));
    CHECK(std::isnan(without.points[i].cd_rel_estimate));
    CHECK(std::isnan(without.points[i].meets_tolerance));
  }
  // A potential case has no map to put bars on.
  const Outcome p = magnus_cmd(
      {"sweep", std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml", "--spin-ratio", "0:1:1", "--no-error-bars"},
      dir);
  CHECK(p.status != 0);
  CHECK(one_line(p.err));
  CHECK(p.err.find("--no-error-bars and --orbits need a navier-stokes case") != std::string::npos);
}
