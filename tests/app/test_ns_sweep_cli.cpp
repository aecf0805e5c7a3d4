// magnus sweep on a navier-stokes case and magnus merge, through the binary: shards merged equal the
// unsharded map exactly; merge and --shard refuse bad input in one line and write nothing.
#include <catch2/catch.hpp>
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "io/hdf5_io.hpp"
#include "io/ns_sweep_file.hpp"
#include "io/stability_file.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {

void write_case(const std::string& path, int n_theta) {
  std::ofstream(path)
      << "title = \"coarse map\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\n"
         "spin_ratio = 0.0\n[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = 20.0\n[domain]\n"
         "outer_radius = 20.0\n[grid]\nn_theta = "
      << n_theta << "\n";
}


}  // namespace

TEST_CASE("navier-stokes sweep: shards merged equal the unsharded map exactly", "[app][sweep][merge]") {
  const std::string dir = temp_dir("ns-sweep-merge");
  write_case(dir + "/c.toml", 32);
  const std::vector<std::string> map = {
      "sweep", dir + "/c.toml", "--spin-ratio", "0:2:1", "--reynolds", "20:100:40", "-q"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = map;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  Outcome o = magnus_cmd(with({"-o", dir + "/all.h5"}), dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  REQUIRE(magnus_cmd(with({"-o", dir + "/threads.h5", "--threads", "2"}), dir).status == 0);
  REQUIRE(magnus_cmd(with({"-o", dir + "/s1.h5", "--shard", "1/2"}), dir).status == 0);
  REQUIRE(magnus_cmd(with({"-o", dir + "/s2.h5", "--shard", "2/2"}), dir).status == 0);
  o = magnus_cmd({"merge", dir + "/m.h5", dir + "/s2.h5", dir + "/s1.h5"}, dir);
  REQUIRE(o.status == 0);
  // magnus plot draws a merged map as S/(2πρa²) per Re.
  fs::create_directories(dir + "/png");
  REQUIRE(magnus_cmd({"plot", dir + "/m.h5", "-o", dir + "/png"}, dir).status == 0);
  CHECK(fs::file_size(dir + "/png/m_s_map.png") > 10000);
  // With computed 3D onsets (files of magnus stability --spanwise --critical-reynolds --output), the points
  // above the onset curve are marked; a file without an onset, or a map that is not one, is refused.
  // The same α 1…2 curve twice: above every point (Re_c 500: nothing framed), then at Re_c 50 and 70 (the
  // points Re 60 and 100 at α 1, Re 100 at α 2 framed). Same title, so the pictures differ by the frames.
  auto plot_with = [&](double re1, double re2) {
    for (auto [alpha, re] : {std::pair{1.0, re1}, {2.0, re2}})
      write_stability_hdf5(dir + fmt::format("/onset{:g}_{:g}.h5", alpha, re1),
                           Json{{"spin_ratio", alpha}, {"evaluations", Json::array()}, {"found", true},
                                {"critical_reynolds", re}},
                           "onset", "");
    const std::vector<std::string> onset = {"--onset3d", dir + fmt::format("/onset1_{:g}.h5", re1), "--onset3d",
                                            dir + fmt::format("/onset2_{:g}.h5", re1)};
    const Outcome p = magnus_cmd({"plot", dir + "/m.h5", "-o", dir + "/png", "--force"}, onset, dir);
    INFO(p.err);
    REQUIRE(p.status == 0);
    CHECK(fs::file_size(dir + "/png/m_s_map.png") > 10000);
    return slurp(dir + "/png/m_s_map.png");
  };
  const std::string unframed = plot_with(500.0, 500.0), framed = plot_with(50.0, 70.0);
  CHECK(framed != unframed);
  write_stability_hdf5(dir + "/scan.h5", Json{{"reynolds", 40.0}, {"spin_ratio", 1.0}}, "scan", "");
  CHECK(refused(magnus_cmd({"plot", dir + "/m.h5", "-o", dir + "/png", "--force", "--onset3d", dir + "/scan.h5"}, dir),
                "holds no 3D onset"));
  const NsMap all = read_ns_map_hdf5(dir + "/all.h5"), merged = read_ns_map_hdf5(dir + "/m.h5");
  CHECK(merged.shard == 1);
  CHECK(merged.shards == 1);
  REQUIRE(all.points.size() == 9);
  REQUIRE(merged.points.size() == 9);
  // Every column but the timing, bit for bit (NaN = NaN: both undefined).
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  for (size_t i = 0; i < 9; ++i) {
    const NsMapPoint &a = all.points[i], &b = merged.points[i];
    INFO("point " << i);
    CHECK(a.row == b.row);
    CHECK(a.column == b.column);
    for (auto [x, y] : {std::pair{a.cl, b.cl},
                        {a.cd, b.cd},
                        {a.cm, b.cm},
                        {a.cl_steady, b.cl_steady},
                        {a.cl_pressure, b.cl_pressure},
                        {a.cd_friction, b.cd_friction},
                        {a.ratio, b.ratio},
                        {a.strouhal, b.strouhal},
                        {a.reynolds, b.reynolds},
                        {a.alpha, b.alpha}})
      CHECK(same(x, y));
    CHECK(a.stable == b.stable);
    CHECK(a.source == b.source);
    CHECK(a.newton_steps == b.newton_steps);
  }
  // Two rows at once (threads): the same map to round-off (the LU's kernels round differently in a second
  // thread), the same decisions.
  const NsMap threaded = read_ns_map_hdf5(dir + "/threads.h5");
  REQUIRE(threaded.points.size() == 9);
  for (size_t i = 0; i < 9; ++i) {
    const NsMapPoint &a = all.points[i], &b = threaded.points[i];
    CHECK(std::fabs(a.cl - b.cl) < 1e-12);
    CHECK(std::fabs(a.cd - b.cd) < 1e-12);
    CHECK(a.stable == b.stable);
    CHECK(a.source == b.source);
  }
  // Re 20 is steady and stable at every α; Re 100 without spin sheds (time-averaged, with a Strouhal number).
  CHECK(all.points[0].source == MapSource::steady);
  CHECK(all.points[0].stable == std::optional<bool>(true));
  CHECK(all.points[6].source == MapSource::averaged_unstable);
  CHECK(all.points[6].strouhal > 0.1);

  SECTION("merge refuses overlapping, missing and mismatched shards in one line") {
    write_case(dir + "/d.toml", 36);
    REQUIRE(magnus_cmd({"sweep", dir + "/d.toml", "--spin-ratio", "0:2:1", "--reynolds", "20:100:40", "-q",
                        "--steady-only", "-o", dir + "/o2.h5", "--shard", "2/2"},
                       dir)
                .status == 0);
    for (auto [args, expect] :
         {std::pair{std::vector<std::string>{dir + "/s1.h5", dir + "/s1.h5"}, "are both shard 1/2"},
          {std::vector<std::string>{dir + "/s1.h5"}, "shard 2/2 is missing"},
          {std::vector<std::string>{dir + "/s1.h5", dir + "/o2.h5"}, "different cases"},
          {std::vector<std::string>{dir + "/s1.h5", dir + "/all.h5"}, "is shard 1/2 but"}}) {
      const Outcome b = magnus_cmd({"merge", dir + "/bad.h5"}, args, dir);
      INFO(b.err);
      CHECK(refused(b, expect));
      CHECK_FALSE(fs::exists(dir + "/bad.h5"));
    }
  }
}

TEST_CASE("navier-stokes sweep: bad --shard values are refused in one line before solving",
          "[app][sweep][merge]") {
  const std::string dir = temp_dir("ns-sweep-shard");
  write_case(dir + "/c.toml", 32);
  for (auto [shard, expect] : {std::pair{"0/2", "1 ≤ K ≤ N"},
                               {"3/2", "1 ≤ K ≤ N"},
                               {"a/b", "K/N"},
                               {"2", "K/N"},
                               {"-1/2", "K/N"},
                               {"1/4", "at most 3 shards"}}) {
    const Outcome o = magnus_cmd({"sweep", dir + "/c.toml", "--spin-ratio", "0:1:1", "--reynolds", "20:60:20",
                                  "--shard", shard, "-o", dir + "/x.h5"},
                                 dir);
    INFO(shard << ": " << o.err);
    CHECK(o.status != 0);
    CHECK(one_line(o.err));
    CHECK(o.err.find(expect) != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/x.h5"));
  }
}

TEST_CASE("navier-stokes sweep --json: every column of every point with its units, as in the file",
          "[app][sweep][json]") {
  const std::string dir = temp_dir("ns-sweep-json");
  write_case(dir + "/c.toml", 32);
  const Outcome o = magnus_cmd({"sweep", dir + "/c.toml", "--spin-ratio", "0:1:1", "--steady-only", "--json",
                                "-o", dir + "/m.h5"},
                               dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const auto j = nlohmann::json::parse(o.out);  // throws (fails) on anything but one JSON object
  const NsMap m = read_ns_map_hdf5(dir + "/m.h5");
  REQUIRE(j["points"].size() == m.points.size());
  REQUIRE(m.points.size() == 2);
  CHECK(j["model"] == "navier-stokes");
  CHECK(j["output"][0] == dir + "/m.h5");
  const std::string csv = magnus_cmd({"sweep", dir + "/c.toml", "--spin-ratio", "0:1:1", "--steady-only", "-q",
                                      "--csv", "-"},
                                     dir)
                              .out;
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const auto& [name, col] : j["columns"].items()) {
    INFO("column " << name);
    CHECK(header.find(name) != std::string::npos);  // the same columns as the CSV
    CHECK(col.contains("units"));
    for (const auto& p : j["points"]) CHECK((p[name].contains("value") && p[name]["units"] == col["units"]));
  }
  for (size_t k = 0; k < m.points.size(); ++k) {
    CHECK(j["points"][k]["cl"]["value"].get<double>() == m.points[k].cl);
    CHECK(j["points"][k]["stable"]["value"].is_null());  // --steady-only: stability not decided
  }
}
