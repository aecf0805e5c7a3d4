// The last line of defence: every number the schema stores is checked before anything is printed or written.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <limits>

#include "io/finite.hpp"
#include "io/hdf5_io.hpp"
#include "io/report.hpp"
#include "io/text_format.hpp"
#include "physics/checked_cast.hpp"
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

TEST_CASE("double to integer conversions are defined for every double", "[io][finite]") {
  CHECK(saturate_cast<long>(1e300) == std::numeric_limits<long>::max());
  CHECK(saturate_cast<long>(-1e300) == std::numeric_limits<long>::min());
  CHECK(saturate_cast<int>(std::nan("")) == 0);
  CHECK(saturate_cast<int>(2147483647.9) == 2147483647);
  CHECK(saturate_cast<int>(2147483648.0) == 2147483647);
  CHECK(saturate_cast<int>(-2147483648.9) == -2147483647 - 1);
  CHECK(saturate_cast<size_t>(-0.5) == 0);
  CHECK(saturate_cast<size_t>(-1.0) == 0);
  CHECK(checked_cast<long>(-12.7, "x") == -12);
  CHECK(checked_cast<long>(9223372036854774784.0, "x") == 9223372036854774784L);  // 2^63 - 1024
  CHECK_THROWS_WITH(checked_cast<long>(9.2233720368547758e18, "steps"), "steps: 9.22337e+18 is out of range for an integer");
  CHECK_THROWS_WITH(checked_cast<int>(INFINITY, "n"), "n: inf is out of range for an integer");
  CHECK_THROWS_WITH(checked_cast<int>(std::nan(""), "n"), "n: nan is out of range for an integer");
}

TEST_CASE("a figure that rounds to zero has no minus sign, and keeps an asked-for plus", "[io][finite][report]") {
  CHECK(figure(-0.0, "{:.6g}") == "0");
  CHECK(figure(-1e-9, "{:.2f}") == "0.00");
  CHECK(figure(-0.0, "{:.3e}") == "0.000e+00");
  CHECK(figure(-0.0, "{:+.5f}") == "+0.00000");     // an eigenvalue's imaginary part, λ = −0.01 − 0i
  CHECK(figure(-4e-7, "{:+.5f}") == "+0.00000");
  CHECK(figure(-0.01, "{:+.5f}") == "-0.01000");
  CHECK(csv_number(-0.0) == "0");
  CHECK(csv_number(-1e-300) == "-1e-300");  // a tiny value keeps its sign
}
