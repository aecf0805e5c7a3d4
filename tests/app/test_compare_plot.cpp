// magnus compare and magnus plot, run as a user runs them: compare reads back what run wrote, plot
// draws every shipped case from its result file alone.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <hdf5.h>

#include "app/compare.hpp"
#include "app/plot_files.hpp"
#include "io/compare.hpp"
#include "io/hdf5_io.hpp"
#include "plot/png_image.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char ch : s) {
    if (ch == '"')
      quoted = !quoted;
    else if (ch == sep && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

TEST_CASE("magnus compare reads back exactly what magnus run wrote", "[app][compare]") {
  const std::string dir = test::temp_dir("compare");
  std::ofstream(dir + "/a.toml") << "title = \"A\"\n[cylinder]\nradius = 0.1\nspin_ratio = "
                                    "1.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 32\n";
  std::ofstream(dir + "/b.toml") << "title = \"B\"\n[cylinder]\nradius = 0.1\nspin_ratio = "
                                    "1.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 64\n";
  std::ofstream(dir + "/c.toml") << "title = \"C, no wind\"\n[cylinder]\nradius = 0.1\nspin = "
                                    "100.0\n[flow]\nspeed = 0.0\n[grid]\nn_theta = 32\n";
  for (const char* n : {"a", "b", "c"})
    REQUIRE(magnus_cmd({"run", dir + "/" + n + ".toml", "-o", dir + "/" + n + ".h5", "-q"}, dir).status == 0);
  const std::vector<std::string> files = {dir + "/a.h5", dir + "/b.h5", dir + "/c.h5"};

  const Comparison cmp = compare_results(files);
  // Only the parameters that differ: the grid (and the wind and spin for c), never the radius.
  auto differs = [&](const char* name) {
    return std::find(cmp.differing.begin(), cmp.differing.end(), name) != cmp.differing.end();
  };
  CHECK(differs("n_theta"));
  CHECK(differs("n_r"));
  CHECK(differs("speed"));
  CHECK(differs("title"));
  CHECK_FALSE(differs("radius"));
  CHECK_FALSE(differs("density"));
  CHECK_FALSE(differs("stencil"));
  CHECK(cmp.table.find("parameters that differ") != std::string::npos);
  CHECK(cmp.table.find("\n  radius") == std::string::npos);
  CHECK(cmp.table.find("\n  n_theta") != std::string::npos);

  // The CSV holds every value at full precision: equal to the attributes, bit for bit.
  std::istringstream csv(cmp.csv);
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> head = split(line, ',');
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(split(line, ','));
  REQUIRE(rows.size() == 3);
  auto column = [&](const std::string& name) {
    const auto it = std::find(head.begin(), head.end(), name);
    REQUIRE(it != head.end());
    return size_t(it - head.begin());
  };
  const std::vector<std::pair<std::string, std::string>> attrs = {
      {"lift_N_m", "lift"},
      {"drag_N_m", "drag"},
      {"cl", "cl"},
      {"cl_kutta_joukowski", "cl_kutta_joukowski"},
      {"cl_seed_estimate", "cl_seed_estimate"},
      {"cd", "cd"},
      {"delta_p_top_bottom_Pa", "delta_p_top_bottom"},
      {"delta_p_seed_estimate_Pa", "delta_p_seed_estimate"}};
  for (size_t i = 0; i < files.size(); ++i) {
    const ResultFile f(files[i]);
    CHECK(rows[i][0] == files[i]);
    for (const auto& [col, attr] : attrs) {
      CAPTURE(files[i], col);
      const std::string cell = rows[i][column(col)];
      if (f.has_attr("/forces", attr)) {
        REQUIRE_FALSE(cell.empty());
        CHECK(std::strtod(cell.c_str(), nullptr) == f.attr_double("/forces", attr));
      } else {
        CHECK(cell.empty());  // undefined (U = 0)
      }
    }
    if (f.has_attr("/errors", "cl_rel"))
      CHECK(std::strtod(rows[i][column("cl_rel")].c_str(), nullptr) == f.attr_double("/errors", "cl_rel"));
    else
      CHECK(rows[i][column("cl_rel")].empty());  // undefined (U = 0)
  }
  CHECK(rows[2][column("cl")].empty());
  CHECK(rows[0][column("kj_over_seed")].rfind("1.57079632679489", 0) == 0);

  // Through the command line: the table on stdout, the CSV file, one line for a foreign file.
  const Outcome o = magnus_cmd({"compare", files[0], files[1], "--csv", dir + "/cmp.csv"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  for (const char* s :
       {"lift (N/m)", "C_L Kutta–Joukowski", "C_L seed estimate", "C_D", "error C_L rel", "n_theta"})
    CHECK(o.out.find(s) != std::string::npos);
  CHECK(slurp(dir + "/cmp.csv") == compare_results({files[0], files[1]}).csv);
  std::ofstream(dir + "/foreign.h5") << "not HDF5";
  for (const std::string& bad : {dir + "/a.toml", dir + "/foreign.h5", dir + "/missing.h5"}) {
    const Outcome b = magnus_cmd({"compare", files[0], bad}, dir);
    CAPTURE(b.err);
    CHECK(b.status != 0);
    CHECK(lines(b.err) == 1);
    CHECK(b.err.find(bad) != std::string::npos);
  }
  // A sweep file is HDF5 but not a flow result.
  REQUIRE(magnus_cmd({"sweep", dir + "/a.toml", "--spin-ratio", "0:1:1", "-o", dir + "/sw.h5", "-q"}, dir)
              .status == 0);
  const Outcome sw = magnus_cmd({"compare", files[0], dir + "/sw.h5"}, dir);
  CHECK(sw.status != 0);
  CHECK(lines(sw.err) == 1);
  CHECK(sw.err.find("magnus-sweep") != std::string::npos);
}

TEST_CASE("magnus plot writes complete PNGs of the stated size for every shipped case", "[app][plot]") {
  std::vector<std::string> cases;
  for (const auto& e : fs::directory_iterator(std::string(MAGNUS_SOURCE_DIR) + "/cases"))
    if (e.path().extension() == ".toml") cases.push_back(e.path().string());
  std::sort(cases.begin(), cases.end());
  REQUIRE(cases.size() >= 6);
  const std::string dir = test::temp_dir("plot-cases");
  const std::string pics = dir + "/pictures";
  for (const auto& path : cases) {
    const std::string stem = fs::path(path).stem().string();
    CAPTURE(stem);
    const std::string h5 = dir + "/" + stem + ".h5";
    REQUIRE(magnus_cmd({"run", path, "--set", "grid.n_theta=64", "-o", h5, "-q"}, dir).status == 0);
    const Outcome o = magnus_cmd({"plot", h5, "-o", pics, "--size", "320x240"}, dir);
    CAPTURE(o.err);
    REQUIRE(o.status == 0);
    const bool still = ResultFile(h5).attr_double("/parameters", "speed") == 0.0;
    std::vector<std::string> expected = {"_streamlines.png"};
    if (!still) expected.insert(expected.end(), {"_cp.png", "_surface_cp.png"});
    for (const auto& suffix : expected) {
      const std::string png = pics + "/" + stem + suffix;
      CHECK(o.out.find(png) != std::string::npos);
      CHECK(test::png_size(png) == std::pair<unsigned long, unsigned long>(320, 240));
    }
    // U = 0: Cp is undefined, the two Cp pictures are skipped with a note each.
    CHECK(lines(o.err) == (still ? 2u : 0u));
    CHECK(fs::exists(pics + "/" + stem + "_cp.png") == !still);
  }
  for (const auto& e : fs::directory_iterator(pics))
    CHECK(e.path().filename().string().find(".tmp-") == std::string::npos);
}

TEST_CASE("magnus plot skips what the file lacks and fails in one line when nothing can be drawn",
          "[app][plot]") {
  const std::string dir = test::temp_dir("plot-partial");
  std::ofstream(dir + "/case.toml") << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = "
                                       "10.0\n[grid]\nn_theta = 32\n[output]\nfields = [\"psi\"]\n";
  std::ofstream(dir + "/still.toml") << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = "
                                        "0.0\n[grid]\nn_theta = 32\n[output]\nfields = []\n";
  REQUIRE(magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5", "-q"}, dir).status == 0);
  REQUIRE(magnus_cmd({"run", dir + "/still.toml", "-o", dir + "/s.h5", "-q"}, dir).status == 0);

  // psi only: streamlines and surface Cp (always stored), the Cp field skipped with a note. Default
  // directory: beside the result; default size 1000x800.
  const Outcome o = magnus_cmd({"plot", dir + "/r.h5"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  CHECK(lines(o.err) == 1);
  CHECK(o.err.find("/fields/cp") != std::string::npos);
  CHECK(test::png_size(dir + "/r_streamlines.png") == std::pair<unsigned long, unsigned long>(1000, 800));
  CHECK(test::png_size(dir + "/r_surface_cp.png") == std::pair<unsigned long, unsigned long>(1000, 800));
  CHECK_FALSE(fs::exists(dir + "/r_cp.png"));

  // The library call reports the same.
  const PlotOutcome p = plot_result_file(dir + "/r.h5", dir + "/lib", {200, 160});
  CHECK(p.written.size() == 2);
  CHECK(p.skipped.size() == 1);

  // No fields and no wind: nothing to draw.
  const Outcome none = magnus_cmd({"plot", dir + "/s.h5", "-o", dir + "/none"}, dir);
  CHECK(none.status != 0);
  CHECK(lines(none.err) == 1);
  CHECK(none.err.find("nothing to plot") != std::string::npos);
  CHECK((!fs::exists(dir + "/none") || fs::is_empty(dir + "/none")));

  // Bad input: a foreign file, a bad size, an output "directory" that is a file.
  std::ofstream(dir + "/plain") << "x";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"plot", dir + "/case.toml"},
        std::vector<std::string>{"plot", dir + "/r.h5", "--size", "100"},
        std::vector<std::string>{"plot", dir + "/r.h5", "--size", "0x100"},
        std::vector<std::string>{"plot", dir + "/r.h5", "-o", dir + "/plain"}}) {
    const Outcome b = magnus_cmd(args, dir);
    CAPTURE(args, b.err);
    CHECK(b.status != 0);
    CHECK(lines(b.err) == 1);
  }
  CHECK(parse_plot_size("900x700").width == 900);
  CHECK(parse_plot_size("900x700").height == 700);
  REQUIRE_THROWS_AS(parse_plot_size("900x"), std::invalid_argument);
  REQUIRE_THROWS_AS(parse_plot_size("-9x700"), std::invalid_argument);
}

TEST_CASE("magnus plot draws a sweep file as C_L against α, or against Γ for a circulation sweep",
          "[app][plot]") {
  const std::string dir = test::temp_dir("plot-sweep");
  const std::string cases = std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml";
  REQUIRE(magnus_cmd({"sweep", cases, "--spin-ratio", "0:3:0.5", "--set", "grid.n_theta=32", "-o",
                      dir + "/s.h5", "-q"},
                     dir)
              .status == 0);
  const Outcome o = magnus_cmd({"plot", dir + "/s.h5", "--size", "640x480"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find(dir + "/s_cl.png") != std::string::npos);
  CHECK(test::png_size(dir + "/s_cl.png") == std::pair<unsigned long, unsigned long>(640, 480));
  // The numeric points are drawn where C_L = −2πα puts them.
  const LiftSweep s = read_lift_sweep(dir + "/s.h5");
  REQUIRE(s.x.size() == 7);
  CHECK(s.cl[2] == Approx(-2 * M_PI).epsilon(0.01));
  const CurveFigure f = lift_figure(s, nullptr);
  const PlotFrame frame = plot_curves(f.page, f.lines, f.points, dir + "/again.png", {640, 480});
  const Image img = read_png(dir + "/again.png");
  auto red_near = [&](const Image& im, double x, double y) {
    return im.near(frame.px(x), frame.py(y), 4, [&](int u, int v) { return im.red(u, v); });
  };
  CHECK(red_near(img, 1.0, -2 * M_PI));
  CHECK(red_near(img, 3.0, -6 * M_PI));
  CHECK_FALSE(red_near(img.blank(), 3.0, -6 * M_PI));

  // A circulation sweep: x is Γ in m²/s.
  REQUIRE(magnus_cmd({"sweep", cases, "--set", "circulation.model=given", "--set", "circulation.value=0",
                      "--circulation", "-5:5:2.5", "--set", "grid.n_theta=32", "-o", dir + "/c.h5", "-q"},
                     dir)
              .status == 0);
  const LiftSweep c = read_lift_sweep(dir + "/c.h5");
  CHECK(c.by_circulation);
  CHECK(c.x.front() == Approx(-5.0));
  CHECK(lift_figure(c, nullptr).page.xlabel.find("Γ (m^2/s)") != std::string::npos);
  CHECK(magnus_cmd({"plot", dir + "/c.h5"}, dir).status == 0);
  CHECK(test::png_size(dir + "/c_cl.png").first == 1000);
}

TEST_CASE("magnus plot --window: the field pictures show it, bad values refused in one line, no files",
          "[app][plot]") {
  const std::string dir = test::temp_dir("plot-window");
  std::ofstream(dir + "/case.toml") << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = "
                                       "10.0\n[grid]\nn_theta = 32\n";
  REQUIRE(magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5", "-q"}, dir).status == 0);
  const Outcome o =
      magnus_cmd({"plot", dir + "/r.h5", "-o", dir + "/w", "--window", "-2:10,-3:3", "--size", "900x600"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  // The box is 12 by 6 radii with equal scales: twice as wide as high.
  const test::Image img = test::read_png(dir + "/w/r_cp.png");
  // The field's box: the longest run of coloured (not grey) pixels across and down.
  auto coloured = [&](int x, int y) {
    const int r = img.at(x, y, 0), g = img.at(x, y, 1), b = img.at(x, y, 2);
    return std::max({r, g, b}) - std::min({r, g, b}) > 40;
  };
  auto longest = [&](bool across) {
    int best = 0;
    for (int k = 0; k < (across ? img.height : img.width); ++k)
      for (int m = 0, run = 0; m < (across ? img.width : img.height); ++m) {
        run = (across ? coloured(m, k) : coloured(k, m)) ? run + 1 : 0;
        best = std::max(best, run);
      }
    return best;
  };
  const int w = longest(true), h = longest(false);
  REQUIRE(h > 100);
  CHECK(double(w) / double(h) == Approx(2.0).epsilon(0.05));
  for (const char* bad : {"-2:10", "10:-2,-3:3", "x:1,2:3", "-2:10,-3:3,4", "30:40,-3:3"}) {
    const Outcome b = magnus_cmd({"plot", dir + "/r.h5", "-o", dir + "/bad", "--window", bad}, dir);
    CAPTURE(bad, b.err);
    CHECK(b.status != 0);
    CHECK(lines(b.err) == 1);
    CHECK(b.err.find("--window") != std::string::npos);
    CHECK(!fs::exists(dir + "/bad"));
  }
}

TEST_CASE("compare, compare --csv, plot and probe refuse a damaged file that inspect refuses", "[app][compare]") {
  const std::string dir = test::temp_dir("compare-damaged");
  std::ofstream(dir + "/a.toml") << "[cylinder]\nradius = 0.1\nspin_ratio = 1.0\n[flow]\nspeed = 10.0\n[grid]\n"
                                    "n_theta = 32\n";
  REQUIRE(magnus_cmd({"run", dir + "/a.toml", "-o", dir + "/a.h5", "-q"}, dir).status == 0);
  // Damage that leaves a readable HDF5 file: an attribute gone (as when its object header is lost).
  for (const auto& [group, attr] : {std::pair{"/parameters", "spin"}, std::pair{"/forces", "cl"}}) {
    CAPTURE(group, attr);
    const std::string bad = dir + "/bad.h5";
    fs::copy_file(dir + "/a.h5", bad, fs::copy_options::overwrite_existing);
    const hid_t f = H5Fopen(bad.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(f >= 0);
    REQUIRE(H5Adelete_by_name(f, group, attr, H5P_DEFAULT) >= 0);
    H5Fclose(f);
    const std::string missing = std::string(group) + "@" + attr + " is missing";
    const Outcome inspected = magnus_cmd({"inspect", bad}, dir);
    REQUIRE(inspected.status == 1);
    REQUIRE(inspected.err.find(missing) != std::string::npos);
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"compare", dir + "/a.h5", bad},
          std::vector<std::string>{"compare", dir + "/a.h5", bad, "--csv", dir + "/c.csv"},
          std::vector<std::string>{"compare", bad, "--json"}, std::vector<std::string>{"plot", bad, "-q"},
          std::vector<std::string>{"probe", bad, "0.2,0"}}) {
      CAPTURE(args[0], args.size());
      const Outcome o = magnus_cmd(args, dir);
      CHECK(o.status == 1);
      CHECK(one_line(o.err));
      CHECK(o.err.find(missing) != std::string::npos);
      CHECK(o.out.empty());
    }
    CHECK(!fs::exists(dir + "/c.csv"));
    CHECK(!fs::exists(dir + "/bad_streamlines.png"));
  }
}

TEST_CASE("no value prints as -0: compare's table and CSV, the sweep CSV", "[app][compare]") {
  const std::string dir = test::temp_dir("compare-minus-zero");
  std::ofstream(dir + "/z.toml") << "[cylinder]\nradius = 0.1\nspin = 0.0\n[flow]\nspeed = 10.0\n[grid]\n"
                                    "n_theta = 32\n";
  REQUIRE(magnus_cmd({"run", dir + "/z.toml", "-o", dir + "/z.h5", "-q"}, dir).status == 0);
  const Outcome table = magnus_cmd({"compare", dir + "/z.h5"}, dir);
  REQUIRE(table.status == 0);
  const std::string kj = line_of(table.out, "  C_L Kutta–Joukowski");
  REQUIRE(kj.size() > 2);
  CHECK(kj.compare(kj.size() - 2, 2, " 0") == 0);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"compare", dir + "/z.h5", "--csv", "-"},
        std::vector<std::string>{"sweep", dir + "/z.toml", "--spin-ratio", "0:1:1", "-q", "--csv", "-"}}) {
    const Outcome o = magnus_cmd(args, dir);
    REQUIRE(o.status == 0);
    const std::vector<std::string> rows = [&] {
      std::vector<std::string> r;
      std::istringstream in(o.out);
      for (std::string l; std::getline(in, l);) r.push_back(l);
      return r;
    }();
    REQUIRE(rows.size() >= 2);
    const std::vector<std::string> head = split(rows[0], ','), zero = split(rows[1], ',');
    REQUIRE(head.size() == zero.size());
    const size_t k = size_t(std::find(head.begin(), head.end(), "cl_kutta_joukowski") - head.begin());
    REQUIRE(k < head.size());
    CHECK(zero[k] == "0");
    for (const auto& cell : zero) CHECK(cell != "-0");
  }
}
