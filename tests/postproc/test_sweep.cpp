// magnus sweep: superposition equals one run per point, two solves per sweep, range parsing, the
// table/CSV/HDF5/PNG outputs, and the viscous reference data file.
#include <catch2/catch.hpp>
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/reference_file.hpp"
#include "io/sweep_file.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

namespace {


/// |a − b| relative to max(|a|, |b|, floor): the floor keeps values near zero (α = 0) meaningful.
double rel_diff(double a, double b, double floor) {
  return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), floor});
}

/// PNG width and height from the IHDR chunk (0, 0 if not a PNG).
std::pair<unsigned long, unsigned long> png_size(const std::string& path) {
  const std::string b = slurp(path);
  if (b.size() < 24 || b.compare(1, 3, "PNG") != 0 || b.compare(12, 4, "IHDR") != 0) return {0, 0};
  auto be32 = [&](size_t at) {
    const auto* u = reinterpret_cast<const unsigned char*>(b.data()) + at;
    return (unsigned long)u[0] << 24 | (unsigned long)u[1] << 16 | (unsigned long)u[2] << 8 | u[3];
  };
  return {be32(16), be32(20)};
}

}  // namespace

TEST_CASE("a sweep equals one run per point to 1e-12, with two linear solves in all", "[app][sweep]") {
  struct Setup {
    const char* what;
    Case c;
  };
  std::vector<Setup> setups = {
      {"fft, 5-point, exact far field", test::make_case(1.0, 64)},
      {"cholmod, 9-point, freestream far field",
       test::make_case(1.0, 64, Spacing::geometric, FarField::freestream, StencilKind::nine_point, Method::cholmod)},
      {"uniform spacing", test::make_case(1.0, 48, Spacing::uniform, FarField::exact, StencilKind::five_point,
                                          Method::cholmod, 8.0)},
  };
  const std::vector<double> alphas = {0.0, 0.5, 1.0, 1.9, 2.0, 2.5, 4.0, -1.5};
  for (const auto& s : setups) {
    SECTION(s.what) {
      const SweepResult sw = sweep_spin_ratio(s.c, alphas);
      REQUIRE(sw.linear_solves == 2);
      REQUIRE(sw.points.size() == alphas.size());
      for (size_t k = 0; k < alphas.size(); ++k) {
        Case c = s.c;
        c.scene.spin = alphas[k] * c.scene.speed / c.scene.radius;
        const FlowResult r = run_case(c);
        const SweepPoint& p = sw.points[k];
        CAPTURE(alphas[k]);
        REQUIRE(p.scene.spin_ratio() == Approx(alphas[k]).epsilon(1e-15));
        const double q = 0.5 * c.scene.density * c.scene.speed * c.scene.speed;  // dynamic pressure, the scale of ΔP
        CHECK(rel_diff(*p.forces.cl, *r.forces.cl, 1.0) <= 1e-12);
        CHECK(rel_diff(p.forces.lift, r.forces.lift, q * 2 * c.scene.radius) <= 1e-12);
        CHECK(rel_diff(p.forces.delta_p_top_bottom, r.forces.delta_p_top_bottom, q) <= 1e-12);
        CHECK(*p.forces.cl_kutta_joukowski == Approx(-2 * M_PI * alphas[k]).margin(1e-14));
        CHECK(*p.forces.cl_seed_estimate == Approx(-4 * alphas[k]).margin(1e-14));
        REQUIRE(p.stagnation.size() == r.stagnation.size());
        for (size_t j = 0; j < p.stagnation.size(); ++j) {
          CHECK(p.stagnation[j].on_surface == r.stagnation[j].on_surface);
          CHECK(p.stagnation[j].theta == Approx(r.stagnation[j].theta).margin(1e-10));
          CHECK(p.stagnation[j].r == Approx(r.stagnation[j].r).epsilon(1e-10));
        }
      }
    }
  }
  SECTION("circulation sweep (model \"given\")") {
    Case c = test::make_case(1.0, 64);
    c.scene.circulation_given = true;
    const std::vector<double> gammas = {-2.0, 0.0, 1.5, 20.0};
    const SweepResult sw = sweep_circulation(c, gammas);
    REQUIRE(sw.linear_solves == 2);
    for (size_t k = 0; k < gammas.size(); ++k) {
      Case ck = c;
      ck.scene.circulation_value = gammas[k];
      const FlowResult r = run_case(ck);
      CAPTURE(gammas[k]);
      CHECK(sw.points[k].scene.Gamma() == gammas[k]);
      CHECK(rel_diff(*sw.points[k].forces.cl, *r.forces.cl, 1.0) <= 1e-12);
      CHECK(rel_diff(sw.points[k].forces.delta_p_top_bottom, r.forces.delta_p_top_bottom, 61.25) <= 1e-12);
      // The α column of a circulation sweep is the equivalent spin ratio Γ/(2πaU).
      CHECK(sweep_row(sw, sw.points[k]).alpha == Approx(gammas[k] / (2 * M_PI * c.scene.radius * c.scene.speed)));
    }
  }
}

TEST_CASE("two solves however many points; U = 0 and the wrong circulation model are refused", "[app][sweep]") {
  const Case c = test::make_case(1.0, 32);
  std::vector<double> many;
  for (int k = 0; k <= 2000; ++k) many.push_back(-5.0 + 0.005 * k);
  for (int threads : {1, 3}) {
    const SweepResult s = sweep_spin_ratio(c, many, threads);
    REQUIRE(s.linear_solves == 2);
    REQUIRE(s.points.size() == many.size());
    CHECK(s.points[1000].scene.spin_ratio() == Approx(0.0).margin(1e-12));
    CHECK(*s.points.back().forces.cl == Approx(-2 * M_PI * 5.0).epsilon(1e-2));
  }
  Case still = c;
  still.scene.speed = 0.0;
  REQUIRE_THROWS_AS(sweep_spin_ratio(still, {1.0}), std::invalid_argument);
  Case given = c;
  given.scene.circulation_given = true;
  REQUIRE_THROWS_AS(sweep_spin_ratio(given, {1.0}), std::invalid_argument);
  REQUIRE_THROWS_AS(sweep_circulation(c, {1.0}), std::invalid_argument);
  given.scene.speed = 0.0;
  REQUIRE_THROWS_AS(sweep_circulation(given, {1.0}), std::invalid_argument);
}

TEST_CASE("sweep ranges A:B:STEP: inclusive, rounded, and bad ones refused in one line", "[app][sweep]") {
  SweepRange r = parse_sweep_range("0:4:0.5", "--spin-ratio");
  REQUIRE(r.values.size() == 9);
  CHECK(r.values.back() == 4.0);
  r = parse_sweep_range("0:1:0.1", "--spin-ratio");
  REQUIRE(r.values.size() == 11);
  CHECK(r.values[3] == 0.3);
  CHECK(r.values.back() == 1.0);
  CHECK(parse_sweep_range("-1:1:1", "x").values == std::vector<double>{-1.0, 0.0, 1.0});
  CHECK(parse_sweep_range("2:2:1", "x").values == std::vector<double>{2.0});
  CHECK(parse_sweep_range("0:1:0.3", "x").values.size() == 4);  // 0, 0.3, 0.6, 0.9
  CHECK(parse_sweep_range("1e-3:2e-3:1e-3", "x").values.size() == 2);
  for (const char* bad : {"4:0:1", "0:1:0", "0:1:-0.5", "0:1", "1", "", "a:b:c", "0:1:0.1:2", "0:1e9:1e-3", "nan:1:1",
                          "0:inf:1", "0:1:1e-300", "0:1x:0.1", "0:1:0.1 "}) {
    CAPTURE(bad);
    try {
      parse_sweep_range(bad, "--spin-ratio");
      FAIL("no exception");
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      CHECK(what.find("--spin-ratio") != std::string::npos);
      CHECK(what.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("magnus sweep: table, CSV, HDF5 and plot; bad ranges give one line and no files", "[app][sweep][cli]") {
  const std::string dir = test::temp_dir("sweep-cli");
  const std::string case_path = dir + "/case.toml";
  std::ofstream(case_path) << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 32\n";
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
    for (const char* name : {"alpha", "circulation", "cl", "cl_kutta_joukowski", "cl_seed_estimate",
                             "cl_over_kj_minus_1", "kj_over_seed", "cd", "delta_p_top_bottom",
                             "delta_p_seed_estimate", "stagnation_theta1", "stagnation_theta2", "stagnation_r_over_a"}) {
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
  CHECK(png_size(dir + "/s.png") == std::pair<unsigned long, unsigned long>(400, 300));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().find(".tmp-") == std::string::npos);

  // Bad input: one line on stderr, non-zero exit, nothing written.
  const std::string bad_dir = test::temp_dir("sweep-cli-bad");
  std::ofstream(bad_dir + "/case.toml") << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 16\n";
  std::ofstream(bad_dir + "/still.toml") << "[cylinder]\nradius = 0.1\nspin = 100.0\n[grid]\nn_theta = 16\n[flow]\nspeed = 0.0\n";
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

TEST_CASE("the viscous reference data file parses and carries its citations", "[app][reference]") {
  const std::string path = std::string(MAGNUS_SOURCE_DIR) + "/data/viscous_lift_reference.toml";
  const ViscousReference ref = load_viscous_reference(path);
  CHECK(ref.sign_convention.find("C_L = −|C_L|") != std::string::npos);
  REQUIRE(ref.datasets.size() == 2);
  const ViscousDataset& s = ref.datasets[0];
  CHECK(s.id == "stojkovic2002");
  CHECK(s.citation.find("Stojković") != std::string::npos);
  CHECK(s.citation.find("Physics of Fluids 14, 3160 (2002)") != std::string::npos);
  CHECK(s.source == "Table II");
  CHECK(s.reynolds == 100.0);
  CHECK(s.label.find("Re = 100") != std::string::npos);
  REQUIRE(s.points.size() == 5);
  const double alpha[] = {0.0, 0.5, 1.0, 1.5, 2.0}, cl[] = {0.0, -1.220, -2.504, -3.900, -5.48},
               cd[] = {1.3371, 1.2770, 1.1080, 0.8180, 0.46};
  for (size_t k = 0; k < 5; ++k) {
    CHECK(s.points[k].alpha == alpha[k]);
    CHECK(s.points[k].cl == cl[k]);  // magnitudes turned into magnus's sign
    CHECK(*s.points[k].cd == cd[k]);
  }
  const ViscousDataset& k = ref.datasets[1];
  CHECK(k.citation.find("Kang") != std::string::npos);
  CHECK(k.citation.find("Physics of Fluids 11, 3312 (1999)") != std::string::npos);
  CHECK(k.cl_sign == "magnus");
  REQUIRE(k.points.size() == 1);
  CHECK(k.points[0].alpha == 1.0);
  CHECK(k.points[0].cl == -2.4881);
  CHECK(*k.points[0].cd == 1.1040);
  // Viscous lift is below potential flow's |C_L| = 2πα at every tabulated α > 0.
  for (const auto& d : ref.datasets)
    for (const auto& p : d.points)
      if (p.alpha > 0) CHECK(std::fabs(p.cl) < 2 * M_PI * p.alpha);

  // A dataset without its citation is refused, naming the key.
  const std::string text = slurp(path);
  std::string uncited;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l))
    if (l.rfind("citation", 0) != 0) uncited += l + "\n";
  REQUIRE_THROWS_WITH(parse_viscous_reference(uncited, "x.toml"), Catch::Contains("citation"));
  REQUIRE_THROWS_AS(parse_viscous_reference("title = 1\n", "x.toml"), std::runtime_error);

  // The data directory: the source tree's data/, or $MAGNUS_DATA_DIR.
  const char* old = std::getenv("MAGNUS_DATA_DIR");
  const std::string saved = old ? old : "";
  ::setenv("MAGNUS_DATA_DIR", "/nowhere", 1);
  CHECK(viscous_reference_path() == "/nowhere/viscous_lift_reference.toml");
  REQUIRE_THROWS_WITH(load_viscous_reference(viscous_reference_path()), Catch::Contains("MAGNUS_DATA_DIR"));
  if (old) ::setenv("MAGNUS_DATA_DIR", saved.c_str(), 1);
  else ::unsetenv("MAGNUS_DATA_DIR");
  if (!old) CHECK(fs::equivalent(viscous_reference_path(), path));
}
