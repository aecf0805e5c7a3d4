// The rotor-sail data file: every dataset cited with its Re and aspect ratio, the values as published,
// bad files refused in one line naming the file and the dataset, the Re rule for drawing them.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "io/rotor_data.hpp"

using namespace magnus;

namespace {

const std::string kPath = std::string(MAGNUS_SOURCE_DIR) + "/data/rotor_data.toml";

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const RotorDataset& by_id(const RotorData& d, const std::string& id) {
  for (const auto& s : d.datasets)
    if (s.id == id) return s;
  FAIL("no dataset " << id);
  throw 0;
}

/// The shipped text with the first line starting with `key` inside the dataset `id` replaced by `line`.
std::string edited(const std::string& id, const std::string& key, const std::string& line) {
  std::istringstream in(slurp(kPath));
  std::string out, l;
  bool inside = false, done = false;
  while (std::getline(in, l)) {
    if (l.rfind("id = ", 0) == 0) inside = l == "id = \"" + id + "\"";
    if (inside && !done && l.rfind(key + " ", 0) == 0) {
      out += line + "\n";
      done = true;
      continue;
    }
    out += l + "\n";
  }
  REQUIRE(done);
  return out;
}

}  // namespace

TEST_CASE("rotor data: every shipped dataset is cited, with its Re, geometry and aspect ratio", "[io]") {
  const RotorData r = load_rotor_data(kPath);
  REQUIRE(r.datasets.size() == 5);
  for (const auto& d : r.datasets) {
    INFO(d.id);
    CHECK(!d.citation.empty());
    CHECK(d.source.find("NTNU-IMT/stormbird") != std::string::npos);  // where the numbers were read
    CHECK(!d.accuracy.empty());
    CHECK(!d.reynolds_note.empty());
    CHECK(!d.end_plates.empty());
    CHECK(d.alpha_max > d.alpha_min);
    if (!d.three_d) CHECK(!d.aspect_ratio);  // 2D: infinite span
    // Every value inside the stated α range, and real rotors stay below the ideal |C_L| = 2πα.
    for (double a = d.alpha_min; a <= d.alpha_max; a += 0.05) {
      const auto v = rotor_value(d, a);
      if (!v) continue;  // a table starting above alpha_min
      CHECK(v->cl <= 0.0);
      CHECK(std::fabs(v->cl) <= 2.0 * M_PI * a + 1e-12);
      if (v->cd) CHECK(*v->cd > 0.0);
    }
    CHECK(!rotor_value(d, d.alpha_max + 0.1));
  }
  // Values as read in the source files (magnitudes turned into magnus's sign).
  const RotorDataset& o = by_id(r, "ostman2023_2d");
  CHECK(o.method == "CFD");
  REQUIRE(o.points.size() == 9);
  CHECK(o.points[4].alpha == 3.0);
  CHECK(o.points[4].cl == -9.10);
  CHECK(*o.points[4].cd == 0.066);
  const RotorDataset& b = by_id(r, "bordogna2019");
  CHECK(b.reynolds_known);
  CHECK(b.reynolds_min == 3.6e5);
  CHECK(!b.three_d);
  CHECK(!b.points.front().cd);  // lift only
  CHECK(!by_id(r, "prandtl1926").reynolds_known);
}

TEST_CASE("rotor data: the Tillig & Ringsberg fit evaluates its printed polynomials", "[io]") {
  const RotorData r = load_rotor_data(kPath);
  const RotorDataset& t = by_id(r, "tillig2020");
  CHECK(t.method == "fit");
  CHECK(t.points.empty());
  // |C_L| = −0.1039α + 3.1309α² − 0.9817α³ + 0.1145α⁴ − 0.0046α⁵ and
  // C_D = 0.6375 − 1.641α + 1.7243α² − 0.4424α³ + 0.0464α⁴ − 0.0017α⁵, evaluated by hand at α = 3:
  const double cl3 = -0.1039 * 3 + 3.1309 * 9 - 0.9817 * 27 + 0.1145 * 81 - 0.0046 * 243;
  const double cd3 = 0.6375 - 1.641 * 3 + 1.7243 * 9 - 0.4424 * 27 + 0.0464 * 81 - 0.0017 * 243;
  const auto v = rotor_value(t, 3.0);
  REQUIRE(v);
  CHECK(v->cl == Approx(-cl3).epsilon(1e-12));
  CHECK(*v->cd == Approx(cd3).epsilon(1e-12));
  CHECK(v->cl == Approx(-9.5172).margin(5e-5));
  CHECK(*v->cd == Approx(2.6337).margin(5e-5));
  CHECK(rotor_value(t, 0.0)->cl == 0.0);
  CHECK(*rotor_value(t, 0.0)->cd == 0.6375);  // a stationary cylinder's drag at the fit's Re
  CHECK(polynomial_value({1.0, 2.0, 3.0}, 2.0) == 17.0);
  CHECK(polynomial_value({}, 2.0) == 0.0);
  // The full-scale fit gives about half the ideal lift at α = 3 (viscous, 3D losses).
  CHECK(std::fabs(v->cl) / (2 * M_PI * 3) == Approx(0.505).margin(0.005));
}

TEST_CASE("rotor data: a bad file is refused in one line naming the file and the dataset", "[io]") {
  auto refused = [](const std::string& text, const std::string& what) {
    INFO(what);
    try {
      parse_rotor_data(text, "rotor.toml");
      FAIL("accepted");
    } catch (const std::runtime_error& e) {
      const std::string m = e.what();
      CHECK(m.find('\n') == std::string::npos);
      CHECK(m.rfind("rotor.toml", 0) == 0);
      CHECK(m.find(what) != std::string::npos);
    }
  };
  refused(edited("tillig2020", "citation", "citation = \"\""),
          "dataset 5 (\"tillig2020\"): missing or empty string 'citation'");
  refused(edited("bordogna2019", "reynolds", "reynolds = -3"),
          "\"bordogna2019\"): reynolds must be positive");
  refused(edited("bordogna2019", "reynolds", "reynolds = \"high\""), "reynolds must be a number");
  refused(edited("prandtl1926", "aspect_ratio", "aspect_ratio = \"infinite\""),
          "does not fit geometry \"3D\"");
  refused(edited("ostman2023_2d", "aspect_ratio", "aspect_ratio = 5.0"), "needs geometry \"3D\"");
  refused(edited("ostman2023_2d", "alpha_range", "alpha_range = [0.0, 6.0]"),
          "alpha[8] = 8 is outside alpha_range");
  refused(edited("ostman2023_2d", "cl =", "cl = [0.0, 1.22]"), "cl has 2 values for 9 alpha");
  refused(edited("ostman2023_3d", "cd =", "cd = [0.6459, -0.47, 2.416, 3.381]"), "cd[1] = -0.47 is negative");
  refused(edited("ostman2023_3d", "method", "method = \"guess\""), "method must be");
  refused(edited("tillig2020", "cl_poly", "cl_poly = [0.0, 0.1039, -3.1309, 0.9817, -0.1145, 0.0046]"),
          "negative |C_L| or C_D");
  refused(edited("tillig2020", "method", "method = \"experiment\""), "a polynomial needs method = \"fit\"");
  refused(edited("tillig2020", "cl_sign", "cl_sign = \"magnus\""), "cl_sign must be \"magnitude\"");
  refused(edited("ostman2023_3d", "id", "id = \"ostman2023_2d\""), "the id is used twice");
  refused("title = [\n", "malformed TOML");
  try {
    load_rotor_data("/nowhere/rotor_data.toml");
    FAIL("accepted");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("MAGNUS_DATA_DIR") != std::string::npos);
  }
}

TEST_CASE("rotor data: a dataset fits a scene whose Re is within a factor 3 of its own", "[io]") {
  RotorDataset d;
  d.reynolds_known = true;
  d.reynolds_min = d.reynolds_max = 3.6e5;
  CHECK(rotor_fits_reynolds(d, 3.6e5));
  CHECK(rotor_fits_reynolds(d, 1.3e5));  // 3.6e5 / 3 = 1.2e5 ≤ 1.3e5
  CHECK(!rotor_fits_reynolds(d, 1.1e5));
  CHECK(rotor_fits_reynolds(d, 1.07e6));  // ≤ 3 · 3.6e5 = 1.08e6
  CHECK(!rotor_fits_reynolds(d, 1.1e6));
  CHECK(!rotor_fits_reynolds(d, 100.0));  // the 2D laminar model's range
  CHECK(rotor_fits_reynolds(d, 0.0));     // no viscosity, no Re: drawn, labelled with its own Re
  d.reynolds_min = 1e6;
  d.reynolds_max = 7e6;
  CHECK(rotor_fits_reynolds(d, 2.1e7));
  CHECK(!rotor_fits_reynolds(d, 2.2e7));
  CHECK(rotor_fits_reynolds(d, 3.4e5));
  CHECK(rotor_reynolds_text(d) == "Re = 1·10^6 … 7·10^6");
  d.reynolds_known = false;
  CHECK(!rotor_fits_reynolds(d, 3.6e5));
  CHECK(rotor_fits_reynolds(d, 0.0));
  CHECK(rotor_reynolds_text(d) == "Re not stated");

  // The rotor-sail scene (a = 2.5 m, U = 12 m/s, ν = 1.5e-5 m²/s): Re = 4·10^6 picks the full-scale fit only.
  const RotorData r = load_rotor_data(kPath);
  const double re = 12.0 * 5.0 / 1.5e-5;
  std::string fitting;
  for (const auto& s : r.datasets)
    if (rotor_fits_reynolds(s, re)) fitting += s.id + " ";
  CHECK(fitting == "tillig2020 ");
}

TEST_CASE("rotor data: the comparison text sets ideal, 2D model and rotor data side by side", "[io]") {
  const RotorData r = load_rotor_data(kPath);
  const std::string t = rotor_comparison_text(r, 4.0e6, 3.27, 6.0);
  CHECK(t.find("Re = 4·10^6") != std::string::npos);
  CHECK(t.find("h/D = 6") != std::string::npos);
  CHECK(t.find("|C_L| = 2πα = 20.5") != std::string::npos);  // 2π · 3.27 = 20.55
  CHECK(t.find("inviscid upper bound") != std::string::npos);
  CHECK(t.find("Re ≲ 200 only (this scene's Re is above it") != std::string::npos);
  for (const auto& d : r.datasets) CHECK(t.find(d.id) != std::string::npos);
  CHECK(t.find("✓ tillig2020") != std::string::npos);
  CHECK(t.find("  ostman2023_2d") != std::string::npos);  // Re unknown: not marked as fitting
  // The fit at α = 3.27 (10.2) and the 2D CFD interpolated between α = 3 and 4 (9.10 → 10.77: 9.55).
  const RotorDataset& o = by_id(r, "ostman2023_2d");
  CHECK(rotor_value(o, 3.27)->cl == Approx(-(9.10 + 0.27 * (10.77 - 9.10))));
  CHECK(t.find("|C_L| = 9.55, C_D = 0.0595") != std::string::npos);
  const std::string none = rotor_comparison_text(r, 0.0, 1.0, 0.0);
  CHECK(none.find("no viscosity given: no Re") != std::string::npos);
  CHECK(none.find("2D, per unit span") != std::string::npos);
  CHECK(none.find("- prandtl1926") != std::string::npos);
  CHECK(none.find("nan") == std::string::npos);
  CHECK(rotor_comparison_text(r, 100.0, 1.0, 0.0).find("this scene's Re is in range") != std::string::npos);
}
