#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "postproc/pipeline.hpp"
#include "plot/plot.hpp"

using namespace magnus;

namespace {

/// A fresh empty directory under $TMPDIR (or /tmp).
std::string plot_temp_dir(const std::string& name) {
  const char* base = std::getenv("TMPDIR");
  std::string tmpl = std::string(base && *base ? base : "/tmp") + "/magnus-" + name + "-XXXXXX";
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  if (!::mkdtemp(buf.data())) throw std::runtime_error("mkdtemp failed for " + tmpl);
  return buf.data();
}

/// Entries of a directory other than . and .. (hidden ones included).
std::vector<std::string> dir_entries(const std::string& dir) {
  std::vector<std::string> out;
  const std::string cmd = "ls -A '" + dir + "'";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return out;
  char line[4096];
  while (std::fgets(line, sizeof line, p)) {
    std::string s(line);
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    if (!s.empty()) out.push_back(s);
  }
  ::pclose(p);
  return out;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

unsigned long be32(const std::string& b, size_t at) {
  const auto* u = reinterpret_cast<const unsigned char*>(b.data()) + at;
  return (unsigned long)u[0] << 24 | (unsigned long)u[1] << 16 | (unsigned long)u[2] << 8 | u[3];
}

/// The file exists, is a PNG (signature, IHDR first) of the given size, and ends with IEND.
void require_png(const std::string& path, PlotSize size) {
  INFO(path);
  const std::string b = read_bytes(path);
  REQUIRE(b.size() > 100);
  const std::string sig("\x89PNG\r\n\x1a\n", 8);
  REQUIRE(b.compare(0, 8, sig) == 0);
  REQUIRE(b.compare(12, 4, "IHDR") == 0);
  CHECK(be32(b, 16) == (unsigned long)size.width);
  CHECK(be32(b, 20) == (unsigned long)size.height);
  CHECK(b.compare(b.size() - 8, 4, "IEND") == 0);
}

/// The spin-ratio-α case (a = 0.1 m, U = 10 m/s) on a small grid, all fields.
FlowResult small_result(double alpha) {
  Case c;
  c.title = "Plot test";
  c.scene.radius = 0.1;
  c.scene.speed = 10.0;
  c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  c.grid.n_theta = 64;
  return run_case(c);
}

}  // namespace

TEST_CASE("plots of a flow result are complete PNGs of the requested size", "[plot]") {
  const std::string dir = plot_temp_dir("plot");
  for (double alpha : {1.0, 3.0}) {
    const FlowResult r = small_result(alpha);
    REQUIRE(!r.fields.psi.empty());
    REQUIRE(!r.fields.cp.empty());
    const std::string tag = dir + "/alpha" + std::to_string(int(alpha));
    const PlotSize def{};
    plot_streamlines(r, tag + "_stream.png");
    require_png(tag + "_stream.png", def);
    const PlotSize odd{640, 480};
    plot_cp_field(r, tag + "_cp.png", odd);
    require_png(tag + "_cp.png", odd);
    const PlotSize tall{500, 700};
    plot_surface_cp(r, tag + "_surface.png", tall);
    require_png(tag + "_surface.png", tall);
  }
  // No temporary files are left behind.
  for (const auto& e : dir_entries(dir)) CHECK(e.find(".tmp-") == std::string::npos);
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("sweep and log-log plots are PNGs; an existing file is replaced", "[plot]") {
  const std::string dir = plot_temp_dir("plot");
  std::vector<CurvePoint> numeric;
  for (int k = 0; k <= 12; ++k) numeric.push_back({0.25 * k, -2 * M_PI * 0.25 * k});
  const std::vector<ReferenceSet> refs = {{"viscous reference", {{1.0, -2.5}, {2.0, -5.5}, {3.0, -8.5}}}};
  const std::string sweep = dir + "/sweep.png";
  { std::ofstream(sweep) << "old contents"; }
  plot_sweep("Lift against spin ratio", numeric, refs, sweep, {800, 600});
  require_png(sweep, {800, 600});

  const std::vector<Series> series = {{"fft 5-point", {{1e-4, 1e-2}, {4e-4, 2.5e-3}, {1.6e-3, 6e-4}}},
                                      {"cholmod 9-point", {{1e-3, 1e-5}, {4e-3, 2e-7}, {1e-2, 0.0}}}};
  plot_loglog("Speed against error", "time (s)", "relative lift error", series, dir + "/pareto.png");
  require_png(dir + "/pareto.png", PlotSize{});

  // Nothing positive to draw on log axes: an error, and no file.
  REQUIRE_THROWS_AS(plot_loglog("t", "x", "y", {{"zero", {{0.0, 1.0}}}}, dir + "/empty.png"), std::runtime_error);
  CHECK(dir_entries(dir).size() == 2);
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("an unwritable plot path throws one line naming the file and leaves nothing", "[plot]") {
  const FlowResult r = small_result(1.0);
  const std::string dir = plot_temp_dir("plot");

  // A directory that does not exist.
  const std::string missing = dir + "/no/such/dir/stream.png";
  try {
    plot_streamlines(r, missing);
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK(what.find(missing) != std::string::npos);
    CHECK(what.find('\n') == std::string::npos);
  }

  // An unwritable place even for root (CI runs as root): a path beneath a regular file.
  const std::string ro = dir + "/ro";
  { std::ofstream(ro) << "a plain file"; }
  REQUIRE_THROWS_AS(plot_streamlines(r, ro + "/stream.png"), std::runtime_error);
  // The target is a directory: the rename fails, the temporary is removed.
  const std::string as_dir = dir + "/taken.png";
  REQUIRE(::mkdir(as_dir.c_str(), 0755) == 0);
  REQUIRE_THROWS_AS(plot_surface_cp(r, as_dir), std::runtime_error);
  const auto left = dir_entries(dir);
  CHECK(left.size() == 2);  // ro and taken.png, no temporaries
  for (const auto& e : left) CHECK(e.find(".tmp-") == std::string::npos);

  // A result without a Cp field, and an impossible size.
  FlowResult no_cp = r;
  no_cp.fields.cp.clear();
  REQUIRE_THROWS_WITH(plot_cp_field(no_cp, dir + "/cp.png"), "plot: the result has no cp field");
  REQUIRE_THROWS_AS(plot_streamlines(r, dir + "/tiny.png", {4, 4}), std::runtime_error);
  CHECK(dir_entries(dir).size() == 2);
  std::system(("rm -rf '" + dir + "'").c_str());
}
