// magnus replaces its own outputs only: an existing file it did not write (reached directly or through a
// symlink) is refused unless --force is given; its own results, sweeps, CSV tables, PNGs and sidecars are
// replaced as before.
#include <unistd.h>
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/output_owner.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {

const char* kCase = "[cylinder]\nradius = 0.1\nspin_ratio = 1.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 32\n";
const std::string kForeign = "root:x:0:0:root:/root:/bin/bash\n";

}  // namespace

TEST_CASE("an output symlink to a file magnus did not write is refused, its target untouched", "[app][safety]") {
  const std::string dir = temp_dir("owner-link");
  std::ofstream(dir + "/c.toml") << kCase;
  std::ofstream(dir + "/passwd") << kForeign;
  fs::create_symlink(dir + "/passwd", dir + "/link.h5");
  const Outcome o = magnus_cmd({"run", dir + "/c.toml", "-o", dir + "/link.h5", "-q"}, dir);
  CHECK(o.status == 1);
  CHECK(one_line(o.err));
  CHECK(o.err.find("passwd") != std::string::npos);
  CHECK(o.err.find("--force") != std::string::npos);
  CHECK(slurp(dir + "/passwd") == kForeign);
  CHECK(fs::is_symlink(dir + "/link.h5"));
  // With --force the link's target is replaced (the link stays), as the user asked.
  REQUIRE(magnus_cmd({"run", dir + "/c.toml", "-o", dir + "/link.h5", "-q", "--force"}, dir).status == 0);
  CHECK(slurp(dir + "/passwd").rfind("\x89HDF\r\n\x1a\n", 0) == 0);
  CHECK(fs::is_symlink(dir + "/link.h5"));
  // Now it is magnus's own result: replaced through the link without --force.
  CHECK(magnus_cmd({"run", dir + "/c.toml", "-o", dir + "/link.h5", "-q"}, dir).status == 0);
}

TEST_CASE("every command refuses to replace a file it did not write, and replaces its own", "[app][safety]") {
  const std::string dir = temp_dir("owner-commands");
  std::ofstream(dir + "/c.toml") << kCase;
  REQUIRE(magnus_cmd({"run", dir + "/c.toml", "-o", dir + "/r.h5", "-q"}, dir).status == 0);
  const std::string r = dir + "/r.h5";
  // Each writer: its arguments with OUT for the file it writes.
  const std::vector<std::pair<std::string, std::vector<std::string>>> writers = {
      {"r2.h5", {"run", dir + "/c.toml", "-q", "-o", "OUT"}},
      {"s.csv", {"sweep", dir + "/c.toml", "--spin-ratio", "0:1:1", "-q", "--csv", "OUT"}},
      {"s.h5", {"sweep", dir + "/c.toml", "--spin-ratio", "0:1:1", "-q", "-o", "OUT"}},
      {"s.png", {"sweep", dir + "/c.toml", "--spin-ratio", "1:2:1", "-q", "--plot", "OUT"}},
      {"c.csv", {"compare", r, r, "--csv", "OUT"}},
      {"p.csv", {"probe", r, "0.2,0", "--csv", "OUT"}},
      {"f.csv", {"inspect", r, "--surface-csv", "OUT"}},
      {"b.csv", {"bench", dir + "/c.toml", "--ladder", "16,32", "--repeats", "1", "--method", "fft", "--csv", "OUT"}},
      {"st.h5",
       {"stability", std::string(MAGNUS_SOURCE_DIR) + "/cases/s_map.toml", "--set", "grid.n_theta=24", "--set",
        "flow.reynolds=20", "--output", "OUT"}},
  };
  for (const auto& [name, args] : writers) {
    const std::string out = dir + "/" + name;
    std::vector<std::string> a = args;
    std::replace(a.begin(), a.end(), std::string("OUT"), out);
    CAPTURE(name);
    // A file of the user's: refused in one line, left as it was.
    std::ofstream(out) << kForeign;
    Outcome o = magnus_cmd(a, dir);
    CHECK(o.status == 1);
    CHECK(one_line(o.err));
    CHECK(o.err.find("magnus replaces only its own outputs") != std::string::npos);
    CHECK(slurp(out) == kForeign);
    // An empty file: replaced.
    std::ofstream(out, std::ios::trunc).close();
    CHECK(magnus_cmd(a, dir).status == 0);
    const std::string first = slurp(out);
    CHECK(!first.empty());
    // Its own output: replaced again (not refused).
    CHECK(magnus_cmd(a, dir).status == 0);
    CHECK(not_a_magnus_output(out).empty());
  }
  // plot writes beside the result: a foreign PNG of the same name is refused, magnus's own is replaced.
  std::ofstream(dir + "/r_streamlines.png") << "\x89PNG\r\n\x1a\nnot magnus";
  CHECK(magnus_cmd({"plot", r, "-q"}, dir).status == 1);
  fs::remove(dir + "/r_streamlines.png");
  CHECK(magnus_cmd({"plot", r, "-q"}, dir).status == 0);
  CHECK(not_a_magnus_output(dir + "/r_streamlines.png").empty());
  CHECK(magnus_cmd({"plot", r, "-q"}, dir).status == 0);
  // The .xmf sidecar of a result is magnus's own too.
  CHECK(not_a_magnus_output(dir + "/r.xmf").empty());
}

TEST_CASE("what counts as magnus's own output", "[app][safety]") {
  const std::string dir = temp_dir("owner-rules");
  auto verdict = [&](const std::string& bytes) {
    std::ofstream(dir + "/f", std::ios::binary | std::ios::trunc) << bytes;
    return not_a_magnus_output(dir + "/f");
  };
  CHECK(not_a_magnus_output(dir + "/absent").empty());
  CHECK(verdict("").empty());
  CHECK(!verdict(kForeign).empty());
  CHECK(verdict("alpha,circulation_m2_s,lift_N_m,drag_N_m\n0,0,0,0\n").empty());
  CHECK(!verdict("alpha,beta\n1,2\n").empty());
  CHECK(!verdict("\x89HDF\r\n\x1a\n and not really").empty());
  // A PNG is magnus's when it carries the Software text chunk mark_png adds.
  std::string png("\x89PNG\r\n\x1a\n", 8);
  png += std::string("\0\0\0\x0dIHDR", 8) + std::string(13, '\1') + std::string(4, '\2');
  png += std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  CHECK(!verdict(png).empty());
  const std::string marked = mark_png(png);
  CHECK(marked.size() == png.size() + 12 + std::string("Software").size() + 1 + std::string("magnus ").size() +
                             std::string(MAGNUS_VERSION).size());
  CHECK(verdict(marked).empty());
}

TEST_CASE("an empty output name is refused in one line, not taken as the default", "[app][cli]") {
  const std::string dir = temp_dir("owner-empty-name");
  std::ofstream(dir + "/c.toml") << kCase << "[output]\nfile = \"" << dir << "/default.h5\"\n";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", dir + "/c.toml", "-o", ""},
        std::vector<std::string>{"sweep", dir + "/c.toml", "--spin-ratio", "0:1:1", "--csv", ""}}) {
    const Outcome o = magnus_cmd(args, dir);
    CHECK(o.status == 2);
    CHECK(one_line(o.err));
    CHECK(o.err.find("empty file name") != std::string::npos);
  }
  CHECK(!fs::exists(dir + "/default.h5"));
}
