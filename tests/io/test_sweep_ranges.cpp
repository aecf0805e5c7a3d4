// The A:B:STEP ranges of magnus sweep, and the viscous reference data file.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "io/reference_file.hpp"
#include "io/sweep_file.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;
namespace fs = std::filesystem;

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
  for (const char* bad : {"4:0:1", "0:1:0", "0:1:-0.5", "0:1", "1", "", "a:b:c", "0:1:0.1:2", "0:1e9:1e-3",
                          "nan:1:1", "0:inf:1", "0:1:1e-300", "0:1x:0.1", "0:1:0.1 "}) {
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
  if (old)
    ::setenv("MAGNUS_DATA_DIR", saved.c_str(), 1);
  else
    ::unsetenv("MAGNUS_DATA_DIR");
  if (!old) CHECK(fs::equivalent(viscous_reference_path(), path));
}
