// magnus sweep through the binary: the table, CSV, HDF5 and PNG outputs, and the one-line refusals.
#include <hdf5.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/plot_files.hpp"
#include "io/hdf5_io.hpp"
#include "io/reference_file.hpp"
#include "io/rotor_data.hpp"
#include "io/sweep_file.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {}  // namespace

TEST_CASE("magnus sweep: table, CSV, HDF5 and plot, bad ranges give one line and no files",
          "[app][sweep][cli]") {
  const std::string dir = test::temp_dir("sweep-cli");
  const std::string case_path = dir + "/case.toml";
  std::ofstream(case_path)
      << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 32\n";
  const Outcome o = magnus_cmd({"sweep", case_path, "--spin-ratio", "0:4:0.5", "--csv", dir + "/s.csv", "-o",
                                dir + "/s.h5", "--plot", dir + "/s.png", "--size", "400x300"},
                               dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  REQUIRE(o.err.empty());
  for (const char* s : {"C_L numeric", "C_L K–J", "C_L seed", "num/K–J − 1", "K–J/seed", "C_D", "ΔP (Pa)",
                        "seed ΔP (Pa)", "Γ (m²/s)", "stagnation points", "2 linear solves", "Stojković"})
    CHECK(o.out.find(s) != std::string::npos);
  CHECK(o.out.find("(free)") != std::string::npos);
  CHECK(o.out.find("(surface)") != std::string::npos);

  // CSV: a header and one line per point, 15 columns; α = 1 has C_L seed = −4 and K–J/seed = π/2.
  std::istringstream csv(slurp(dir + "/s.csv"));
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(csv, line)) rows.push_back(line);
  REQUIRE(rows.size() == 10);
  CHECK(rows[0].rfind("alpha,circulation_m2_s,", 0) == 0);
  for (const auto& row : rows) CHECK(std::count(row.begin(), row.end(), ',') == 14);
  std::vector<std::string> fields;
  {
    std::istringstream r3(rows[3]);
    std::string f;
    while (std::getline(r3, f, ',')) fields.push_back(f);
  }
  REQUIRE(fields.size() >= 9);
  CHECK(fields[0] == "1");
  CHECK(fields[6] == "-4");
  CHECK(fields[8].rfind("1.5707963267948", 0) == 0);

  // HDF5: format attribute, one dataset per column with units.
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const hid_t f = H5Fopen((dir + "/s.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const hid_t a = H5Aopen(f, "format", H5P_DEFAULT);
    REQUIRE(a >= 0);
    const hid_t t = H5Aget_type(a);  // fixed-length UTF-8, as every magnus string attribute
    REQUIRE(H5Tis_variable_str(t) == 0);
    std::string s(H5Tget_size(t), '\0');
    REQUIRE(H5Aread(a, t, s.data()) >= 0);
    CHECK(std::string(s.c_str()) == "magnus-sweep");
    H5Tclose(t);
    H5Aclose(a);
    for (const char* name :
         {"alpha", "circulation", "cl", "cl_kutta_joukowski", "cl_seed_estimate", "cl_over_kj_minus_1",
          "kj_over_seed", "cd", "delta_p_top_bottom", "delta_p_seed_estimate", "stagnation_theta1",
          "stagnation_theta2", "stagnation_r_over_a"}) {
      const std::string path = std::string("/sweep/") + name;
      CAPTURE(path);
      const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
      REQUIRE(d >= 0);
      const hid_t sp = H5Dget_space(d);
      CHECK(H5Sget_simple_extent_npoints(sp) == 9);
      CHECK(H5Aexists(d, "units") > 0);
      if (std::string(name) == "cl_seed_estimate") {
        std::vector<double> v(9);
        REQUIRE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
        CHECK(v[8] == Approx(-16.0));
      }
      H5Sclose(sp);
      H5Dclose(d);
    }
    H5Fclose(f);
  }
  CHECK(test::png_size(dir + "/s.png") == std::pair<unsigned long, unsigned long>(400, 300));
  for (const auto& e : fs::directory_iterator(dir))
    CHECK(e.path().filename().string().find(".tmp-") == std::string::npos);

  // Bad input: one line on stderr, non-zero exit, nothing written.
  const std::string bad_dir = test::temp_dir("sweep-cli-bad");
  std::ofstream(bad_dir + "/case.toml")
      << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 16\n";
  std::ofstream(bad_dir + "/still.toml")
      << "[cylinder]\nradius = 0.1\nspin = 100.0\n[grid]\nn_theta = 16\n[flow]\nspeed = 0.0\n";
  const std::string c = bad_dir + "/case.toml", out = bad_dir + "/o.csv";
  const std::vector<std::vector<std::string>> bad = {
      {"sweep", c, "--spin-ratio", "4:0:0.5", "--csv", out},
      {"sweep", c, "--spin-ratio", "0:4:0", "--csv", out},
      {"sweep", c, "--spin-ratio", "0:4:-1", "--csv", out},
      {"sweep", c, "--spin-ratio", "0:4", "--csv", out},
      {"sweep", c, "--spin-ratio", "0:1e12:1", "--csv", out},
      {"sweep", c, "--spin-ratio", "x:1:1", "--csv", out},
      {"sweep", c, "--csv", out},
      {"sweep", c, "--spin-ratio", "0:1:1", "--circulation", "0:1:1", "--csv", out},
      {"sweep", c, "--circulation", "0:1:1", "--csv", out},
      {"sweep", bad_dir + "/still.toml", "--spin-ratio", "0:1:1", "--csv", out},
      {"sweep", c, "--spin-ratio", "0:1:1", "--size", "12x9000", "--plot", bad_dir + "/p.png"},
      {"sweep", c, "--spin-ratio", "0:1:1", "--csv", bad_dir + "/no/such/dir/o.csv"},
  };
  for (const auto& args : bad) {
    const Outcome b = magnus_cmd(args, bad_dir);
    CAPTURE(args, b.err);
    CHECK(b.status != 0);
    CHECK(lines(b.err) == 1);
    CHECK(b.out.empty());
  }
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(bad_dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"case.toml", "stderr.txt", "stdout.txt", "still.toml"});
}

TEST_CASE("magnus sweep --spin-ratio: the case needs no spin key of its own", "[app][sweep][cli]") {
  const std::string dir = test::temp_dir("sweep-nospin");
  const std::string case_path = dir + "/case.toml";
  std::ofstream(case_path) << "[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 64\n";
  const Outcome o = magnus_cmd({"sweep", case_path, "--spin-ratio", "0:2:1", "-o", dir + "/s.h5"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  const ResultFile f(dir + "/s.h5", {"magnus-sweep"});
  const auto alpha = f.dataset("/sweep/alpha"), cl = f.dataset("/sweep/cl");
  REQUIRE(alpha == std::vector<double>{0.0, 1.0, 2.0});
  for (size_t k = 0; k < cl.size(); ++k)
    REQUIRE(cl[k] == Approx(-2 * M_PI * alpha[k]).epsilon(3e-3).margin(1e-12));
  // A run of the same file still needs it: only the sweep supplies the spin.
  REQUIRE(magnus_cmd({"run", case_path, "-o", dir + "/r.h5"}, dir).status != 0);
}

TEST_CASE("a sweep file keeps the case's viscosity: plotted again, overlays only of its Re", "[app][sweep][cli]") {
  const std::string dir = test::temp_dir("sweep-viscosity");
  const std::string rotor = std::string(MAGNUS_SOURCE_DIR) + "/cases/rotor_sail.toml";
  const Outcome o = magnus_cmd(
      {"sweep", rotor, "--spin-ratio", "0:2:1", "-o", dir + "/s.h5", "--set", "grid.n_theta=32"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  const LiftSweep s = read_lift_sweep(dir + "/s.h5");
  CHECK(s.base.viscosity == 1.5e-5);
  CHECK(s.base.reynolds() == Approx(4e6));
  const ViscousReference ref = load_viscous_reference(viscous_reference_path());
  const CurveFigure f = lift_figure(s, &ref, shipped_rotor_data());
  for (const auto& p : f.points) CHECK(p.label.find("Re = 100") == std::string::npos);
  // A case without a viscosity stores none (no Re): every table is drawn.
  const std::string plain = dir + "/plain.toml";
  std::ofstream(plain) << "[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 32\n";
  REQUIRE(magnus_cmd({"sweep", plain, "--spin-ratio", "0:2:1", "-o", dir + "/p.h5"}, dir).status == 0);
  const ResultFile pf(dir + "/p.h5", {"magnus-sweep"});
  CHECK(!pf.has_attr("/parameters", "viscosity"));
  int drawn = 0;
  for (const auto& p : lift_figure(read_lift_sweep(dir + "/p.h5"), &ref, nullptr).points)
    drawn += p.label.find("Re = 100") != std::string::npos;
  CHECK(drawn == int(ref.datasets.size()));
}
