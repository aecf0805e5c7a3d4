// Inputs that broke the case-file or --set parser under libFuzzer (scripts/fuzz.sh), kept as regression
// tests. The contract: parse_case either returns a case whose resolved TOML reads back to itself, or throws
// CaseError (one line naming the file or the --set). Nothing else: no other exception, no crash, no undefined
// behaviour.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "io/case_file.hpp"

using namespace magnus;

namespace {

/// The text with the scene keys a case file requires appended, unless it has a [cylinder] or [flow] of its
/// own (these tests are about the parser, not the scene).
std::string scened(const std::string& text) {
  if (text.find("[cylinder]") != std::string::npos || text.find("[flow]") != std::string::npos) return text;
  return text + "\n[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n";
}

/// Parses; on success checks the resolved TOML round trip and returns true; on CaseError returns false.
bool parses(const std::string& text, const std::vector<std::string>& sets = {},
            std::string* error = nullptr) {
  try {
    const Case c = parse_case(scened(text), "fuzz.toml", sets);
    REQUIRE(std::isfinite(c.scene.spin));
    REQUIRE(std::isfinite(c.scene.Gamma()));
    REQUIRE(std::isfinite(c.scene.spin_ratio()));
    const Case again = parse_case(c.source_text, "resolved.toml");
    REQUIRE(again.source_text == c.source_text);
    return true;
  } catch (const CaseError& e) {
    const std::string what = e.what();
    REQUIRE(what.find('\n') == std::string::npos);
    if (error) *error = what;
    return false;
  }
}

/// Each line of an input as a --set override on an empty case (how the fuzz target uses it).
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
    out.push_back(text.substr(start, nl - start));
  out.push_back(text.substr(start));
  return out;
}

}  // namespace

TEST_CASE("fuzz: non-ASCII characters where toml++ 3.3 hits __builtin_unreachable", "[app][case][fuzz]") {
  // toml++ 3.3's whitespace test has no case for U+00A1..U+0499, U+2D1E..U+3117 and U+FAC6..U+FEFE
  // (marzer/tomlplusplus#190): first found by the fuzzer as a mutated shipped case with 'ψ' in a key.
  std::string err;
  for (const char* bad :
       {"title = Über\n", "Ü = 1\n", "[Ü]\n", "a = [ ψ ]\n", "a = { Ü = 1 }\n", "[grid]\nn_theta = 64Ü\n",
        "title = \"\"\"\\Ü\"\"\"\n", "title = ﬀ\n", "# ψ = U (r − a²/r) sinθ\nψ = 1\n"}) {
    CAPTURE(bad);
    REQUIRE_FALSE(parses(bad, {}, &err));
    REQUIRE(err.find("fuzz.toml") == 0);
  }
  // The same characters where TOML allows them: strings, quoted keys (named in the message), comments.
  REQUIRE(parses("# Γ = 2πa²ω, ψ, α, Ü\ntitle = \"Über ψ ⴀ ﬀ\" # ψ\n"));
  REQUIRE(parse_case(scened("title = \"Über ψ ⴀ ﬀ\"\n"), "x").title == "Über ψ ⴀ ﬀ");
  REQUIRE(parse_case(scened("title = '''Über\nψ'''\n"), "x").title == "Über\nψ");
  REQUIRE(parse_case(scened("title = \"\"\"\\\n   Über\"\"\"\n"), "x").title ==
          "Über");  // line-ending backslash
  REQUIRE(parse_case(scened("title = \"\"\"\\\n  ⴀ\"\"\"\n"), "x").title == "ⴀ");
  REQUIRE_FALSE(parses("[cylinder]\n\"Ü\" = 1\n", {}, &err));
  REQUIRE(err.find("unknown key cylinder.Ü") != std::string::npos);
  REQUIRE_FALSE(parses("title = Über\n", {}, &err));
  REQUIRE(err.find("malformed TOML") != std::string::npos);
  // Through --set: "v = Über" is not TOML, so it is a bare word.
  REQUIRE(parse_case(scened(""), "x", {"title=Über ψ"}).title == "Über ψ");
  REQUIRE(parse_case(scened(""), "x", {"title=\"ⴀ\""}).title == "ⴀ");
  // The private-use code points the parser swaps them for are refused, not confused with them.
  REQUIRE_FALSE(parses("title = \"\xF3\xB0\x82\xA1\"\n", {}, &err));  // U+F00A1
  REQUIRE(err.find("U+F00A1") != std::string::npos);
}

TEST_CASE("fuzz: a --set bare word that is not UTF-8 is refused", "[app][case][fuzz]") {
  // crash-4433ab72: the resolved TOML of the accepted case held the raw bytes and did not parse.
  const std::string input =
      "grid.n_theta=64\nsolver.method=fft\noutput.fields=[\"psi\", \"cp\"]\ntitle=ault"
      "\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff# The default demo";
  std::string err;
  REQUIRE_FALSE(parses("", lines_of(input), &err));
  REQUIRE(err.find("not valid UTF-8") != std::string::npos);
  REQUIRE_FALSE(parses("", {"output.file=r\xc3.h5"}));
  REQUIRE_FALSE(parses("", {"title=\xed\xa0\x80"}));  // a UTF-16 surrogate
  REQUIRE(parses("", {"output.file=r\xc3\xa9sultat.h5"}));
}

TEST_CASE("fuzz: control characters in strings survive the resolved TOML", "[app][case][fuzz]") {
  REQUIRE(parses("title = \"a\\u0001b\\u007fc\\td\\re\"\n"));
  REQUIRE(parse_case(scened("title = \"a\\u0001b\\u007f\"\n"), "x").title ==
          "a\x01"
          "b\x7f");
  REQUIRE(parses("", {"title=a\rb"}));
  REQUIRE(parses("[output]\nfile = \"\\u001b[31m.h5\"\n"));
}

TEST_CASE("fuzz: finite values whose products overflow are refused", "[app][case][fuzz]") {
  std::string err;
  REQUIRE_FALSE(parses("[cylinder]\nradius = 0.1\nspin_ratio = 1e300\n[flow]\nspeed = 1e300\n", {}, &err));
  REQUIRE(err.find("cylinder.spin_ratio") != std::string::npos);
  REQUIRE_FALSE(parses("[cylinder]\nradius = 1e200\nspin = 1e200\n[flow]\nspeed = 1.0\n", {}, &err));
  REQUIRE(err.find("cylinder.radius") != std::string::npos);
  REQUIRE_FALSE(parses("[cylinder]\nradius = 1\nspin = 1\n[flow]\nspeed = 5e-324\n", {}, &err));
  REQUIRE(err.find("flow.speed") != std::string::npos);
  REQUIRE_FALSE(parses("", {"cylinder.radius=1e200", "cylinder.spin=1e200"}));
  REQUIRE(parses("[cylinder]\nradius = 1e-6\nspin_ratio = 1e4\n[flow]\nspeed = 1e-12\n"));
}

TEST_CASE("fuzz: a very long unknown key is refused without a suggestion (the search is bounded by length)",
          "[app][case][fuzz]") {
  // The nearest-key suggestion was O(length) per valid key and per key part: seconds for a megabyte key.
  const std::string key(1 << 20, 'k');
  std::string err;
  REQUIRE_FALSE(parses("", {"grid." + key + "=1"}, &err));
  REQUIRE(err.find("did you mean") == std::string::npos);
  REQUIRE_FALSE(parses("[grid]\n" + key + " = 1\n"));
  REQUIRE_FALSE(parses("", {"grid.n_thetaa=1"}, &err));
  REQUIRE(err.find("did you mean grid.n_theta") != std::string::npos);
}
