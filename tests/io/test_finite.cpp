// The last line of defence: every number the schema stores is checked before anything is printed or written.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "io/finite.hpp"
#include "io/hdf5_io.hpp"
#include "io/report.hpp"
#include "io/text_format.hpp"
#include "support.hpp"

using namespace magnus;

TEST_CASE("the last line of defence names the first stored number that is not finite", "[io][finite]") {
  const FlowResult r = run_case(test::make_case(1.0, 16));
  REQUIRE(first_non_finite(r) == "");
  REQUIRE_NOTHROW(check_finite(r));
  FlowResult f = r;
  f.fields.psi[1 * 16 + 2] = INFINITY;
  CHECK(first_non_finite(f) == "/fields/psi at (i, j) = (1, 2)");
  f.forces.cl = NAN;
  CHECK(first_non_finite(f).find("(/forces@cl)") != std::string::npos);
  CHECK_THROWS_WITH(check_finite(f),
                    Catch::Contains("(/forces@cl) is not finite (NaN or infinite: the inputs are "
                                    "beyond double precision); nothing was written"));
  // Neither the summary nor the file is made from it.
  CHECK_THROWS(summary_text(f, "x.h5"));
  const std::string dir = test::temp_dir("finite");
  CHECK_THROWS(write_result(f, dir + "/x.h5"));
  CHECK_FALSE(std::ifstream(dir + "/x.h5").good());
  FlowResult s = r;
  s.surface.pressure[3] = -INFINITY;
  CHECK(first_non_finite(s) == "/surface/pressure at 3");
  FlowResult p = r;
  p.stagnation.at(0).theta = NAN;
  CHECK(first_non_finite(p) == "/stagnation/theta at 0");
}

TEST_CASE("a fixed-point figure of a huge value is printed in exponent form, never hundreds of digits",
          "[io][finite][report]") {
  CHECK(fmt_opt(1e290, "{:.5f}") == "1e+290");
  CHECK(fmt_opt(-2.5e12, "{:.4f}") == "-2.5e+12");
  CHECK(fmt_opt(-123456.789, "{:.5f}") == "-123456.78900");
  CHECK(fmt_opt(std::nullopt, "{:.5f}") == "undefined");
  CHECK(cell(1e290, "{:.3f}") == "1e+290");
  CHECK(cell(12.5, "{:.3f}") == "12.500");
}
