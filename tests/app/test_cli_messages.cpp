// What `magnus` says, line for line: the run summary of the given-circulation model, stagnation points, U =
// 0, and the one-line messages for bad command lines (each with its exit status).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <thread>

#include "io/hdf5_io.hpp"
#include "io/output_size.hpp"
#include "solver/memory.hpp"
#include "support.hpp"

using namespace magnus;
using namespace magnus::test;

namespace {

const std::string demo = std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml";


/// The line after the one that starts with label.
std::string line_after(const std::string& text, const std::string& label) {
  const size_t at = text.find("\n" + label);
  if (at == std::string::npos) return "";
  const size_t b = text.find('\n', at + 1) + 1, e = text.find('\n', b);
  return text.substr(b, e - b);
}

bool has_negative_zero(const std::string& s) { return std::regex_search(s, std::regex("-0(?![0-9.e])")); }

}  // namespace

TEST_CASE("summary: the given-circulation model labels each figure by its model", "[app][cli][report]") {
  const std::string dir = temp_dir("cli-given");
  std::ofstream(dir + "/g.toml") << "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n"
                                    "[circulation]\nmodel = \"given\"\nvalue = -3.0\n[grid]\nn_theta = 32\n";
  const Outcome o = magnus_cmd({"run", dir + "/g.toml", "-o", dir + "/g.h5"}, dir);
  REQUIRE(o.status == 0);
  CHECK(test::line_of(o.out, "case") ==
        "case           a = 0.1 m, ω = 100 rad/s, U = 10 m/s, α = aω/U = 1, α_Γ = Γ/(2πaU) = "
        "-0.477465 (the given Γ sets the flow), ρ = 1.225 kg/m³");
  CHECK(test::line_of(o.out, "circulation") == "circulation    Γ = -3 m²/s (given, not from the spin)");
  CHECK(test::line_of(o.out, "C_L  ").find("seed estimate -4 (−4α: from ω, not from the given Γ)") !=
        std::string::npos);
  CHECK(line_after(o.out, "C_L  ").find("KJ/seed = -0.750000 (= α_Γ·π/(2α): π/2 only when Γ = 2πa²ω)") !=
        std::string::npos);
  CHECK(line_after(o.out, "ΔP top−bottom").find(": the given Γ, not the spin, sets ΔP (exact 2α_Γ/α)") !=
        std::string::npos);
  CHECK(
      test::line_of(o.out, "Magnus S").find("exact ρΓ/ω = -0.03675 kg/m (the given Γ)   seed 4ρa² = 0.049 kg/m") !=
      std::string::npos);
  CHECK(o.out.find("potential flow doubles") == std::string::npos);
  CHECK(o.out.find("2πρa²") == std::string::npos);

  const Outcome z =
      magnus_cmd({"run", dir + "/g.toml", "-o", dir + "/g.h5", "--set", "cylinder.spin=0"}, dir);
  REQUIRE(z.status == 0);
  CHECK(test::line_of(z.out, "case").find("α = aω/U = 0, α_Γ = Γ/(2πaU) = -0.477465 (the given Γ sets the flow)") !=
        std::string::npos);
  CHECK(test::line_of(z.out, "C_L  ") ==
        "C_L            numeric 2.987288752   Kutta–Joukowski 3   seed estimate undefined (ω = 0)");
  CHECK(line_after(z.out, "C_L  ").find("KJ/seed = undefined (ω = 0)") != std::string::npos);
  CHECK(test::line_of(z.out, "ΔP top−bottom").find("seed 2ρUaω = undefined (ω = 0)") != std::string::npos);
  CHECK(test::line_of(z.out, "Magnus S") ==
        "Magnus S       numeric undefined (ω = 0)   exact ρΓ/ω = undefined (ω = 0)   seed 4ρa² = 0.049 kg/m");
  CHECK_FALSE(has_negative_zero(z.out));
  CAPTURE(z.out);
  // The spin model without spin: the seed's estimate is a plain 0, never "-0".
  const Outcome n = magnus_cmd({"run", std::string(MAGNUS_SOURCE_DIR) + "/cases/no_spin.toml", "-o",
                                dir + "/n.h5", "--set", "grid.n_theta=32"},
                               dir);
  REQUIRE(n.status == 0);
  CHECK(test::line_of(n.out, "C_L  ").find("seed estimate 0") != std::string::npos);
  CHECK_FALSE(has_negative_zero(n.out));
}

TEST_CASE("summary: stagnation points on the surface at α = 2, in one order, and outside the grid",
          "[app][cli][report]") {
  const std::string dir = temp_dir("cli-stagnation");
  auto run = [&](const std::string& alpha, const std::vector<std::string>& more = {}) {
    std::vector<std::string> args = {"run",   demo,
                                     "-o",    dir + "/r.h5",
                                     "--set", "cylinder.spin_ratio=" + alpha,
                                     "--set", "grid.n_theta=64"};
    for (const auto& m : more) args.insert(args.end(), {"--set", m});
    const Outcome o = magnus_cmd(args, dir);
    REQUIRE(o.status == 0);
    return o.out;
  };
  const std::string two = run("2");
  CHECK(line_after(two, "stagnation") == "               exact   θ = 90.000° on the surface");
  const std::string back = run("-1");
  CHECK(test::line_of(back, "stagnation") ==
        "stagnation     numeric θ = 210.075° on the surface, θ = 329.925° on the surface");
  CHECK(line_after(back, "stagnation") ==
        "               exact   θ = 210.000° on the surface, θ = 330.000° on the surface");
  const std::string far = run("100");
  CHECK(test::line_of(far, "stagnation") ==
        "stagnation     numeric none: the free point lies outside the grid (exact r_s/a = "
        "99.99, grid R/a = 20.9768)");
}

TEST_CASE("U = 0: the C_L error is undefined, in the summary, the file and bench", "[app][cli][report]") {
  const std::string dir = temp_dir("cli-still");
  const std::string still = std::string(MAGNUS_SOURCE_DIR) + "/cases/pure_rotation.toml";
  const Outcome o = magnus_cmd({"run", still, "-o", dir + "/r.h5", "--set", "grid.n_theta=32"}, dir);
  REQUIRE(o.status == 0);
  CHECK(test::line_of(o.out, "errors").find("C_L rel undefined") != std::string::npos);
  CHECK_FALSE(ResultFile(dir + "/r.h5").has_attr("/errors", "cl_rel"));
  const Outcome b = magnus_cmd({"bench", still, "--ladder", "16"}, dir);
  CHECK(b.status == 1);
  CHECK(b.err ==
        "magnus: error: bench: flow.speed = 0: C_L and its error are undefined without a freestream; "
        "bench needs flow.speed > 0\n");
  CHECK(b.out.empty());
}

TEST_CASE("command-line messages: one exact line each, with the exit status", "[app][cli]") {
  const std::string dir = temp_dir("cli-messages");
  struct Case_ {
    std::vector<std::string> args;
    int status;
    std::string err;
  };
  const std::vector<Case_> cases = {
      {{"run", demo, "--set", "cylinder.radius=", "-o", dir + "/r.h5"},
       1,
       "magnus: error: --set cylinder.radius=: no value\n"},
      {{"run", demo, "--set", "flow.velocity=2", "-o", dir + "/r.h5"},
       1,
       "magnus: error: --set flow.velocity=2: unknown key flow.velocity (did you mean flow.speed?)\n"},
      {{"run", demo, "--set", "cylinder.spen=2", "-o", dir + "/r.h5"},
       1,
       "magnus: error: --set cylinder.spen=2: unknown key cylinder.spen (keys of [cylinder]: radius, spin, "
       "spin_ratio, rpm, span)\n"},
      {{"run", demo, "--set", "flow.sped=2", "-o", dir + "/r.h5"},
       1,
       "magnus: error: --set flow.sped=2: unknown key flow.sped (did you mean flow.speed?)\n"},
      {{"run", demo, "--tolerance", "1e-15", "-o", dir + "/r.h5"},
       1,
       "magnus: error: --tolerance 1e-15: must be between 1e-14 and 0.1\n"},
      {{"frobnicate"},
       2,
       "magnus: unknown command 'frobnicate' (commands: run, inspect, sweep, compare, plot, bench, probe, merge, stability; "
       "see "
       "magnus --help)\n"},
      {{"run", demo, "--tolerance", "1e-6", "--set", "grid.spacing=uniform", "-o", dir + "/r.h5"},
       1,
       "magnus: error: grid.tolerance = 1e-06 with grid.spacing = \"uniform\" needs about n_θ × n_r = 3136 × "
       "9484 "
       "(2.97e+07 nodes, 226.9 MiB per field), more than the limit of 4194304 nodes; grid.spacing = "
       "\"geometric\" "
       "(9-point stencil, order 6) meets it with 32 × 17\n"},
  };
  for (const auto& c : cases) {
    const Outcome o = magnus_cmd(c.args, dir);
    CAPTURE(c.args);
    CHECK(o.status == c.status);
    CHECK(o.err == c.err);
    CHECK(o.out.empty());
  }
  // Spaces around '=' and the key are allowed.
  const Outcome sp = magnus_cmd(
      {"run", demo, "--set", " cylinder.radius = 2 ", "--set", "grid.n_theta=16", "-o", dir + "/r.h5", "-q"},
      dir);
  CHECK(sp.status == 0);
  CHECK(sp.err.empty());
  CHECK(ResultFile(dir + "/r.h5").attr_double("/parameters", "radius") == 2.0);
  // An HDF5 result is not a case.
  const Outcome h5 = magnus_cmd({"run", dir + "/r.h5", "-o", dir + "/s.h5"}, dir);
  CHECK(h5.status == 1);
  CHECK(h5.err == "magnus: error: " + dir +
                      "/r.h5: an HDF5 result file, not a case file (TOML); to see what it "
                      "holds: magnus inspect " +
                      dir + "/r.h5\n");
  // More threads than cores: a note, and the run uses the cores there are.
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores > 0 && cores < 64) {
    const Outcome t = magnus_cmd(
        {"run", demo, "--threads", "64", "--set", "grid.n_theta=16", "-o", dir + "/r.h5", "-q"}, dir);
    CHECK(t.status == 0);
    CHECK(t.err == "magnus: note: --threads 64 is more than the " + std::to_string(cores) +
                       " cores of this machine: using " + std::to_string(cores) + "\n");
  }
}

TEST_CASE("the result file must fit on the disk: estimate against the free space", "[app][cli]") {
  CHECK(estimated_output_bytes(10, 16, 9) == 8 * 160 * 11 + 8 * (10 + 6 * 16));
  CHECK_THROWS_WITH(check_disk_space("x.h5", 2048, 1024),
                    "x.h5: the result needs about 2 KiB, but only 1 KiB is free there");
  CHECK_NOTHROW(check_disk_space("x.h5", 1024, 1024));
  // End to end (no free space is injected: the program reads no test switch): tests/app/test_ns_signals.cpp.
}

TEST_CASE("magnus --help names both models", "[app][cli]") {
  const std::string dir = temp_dir("cli-help");
  const Outcome o = magnus_cmd({"--help"}, dir);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("Navier–Stokes") != std::string::npos);
  CHECK(o.out.find("potential flow") != std::string::npos);
}

TEST_CASE("a navier-stokes run longer than kNsMaxSteps steps at its CFL step is refused before it starts",
          "[app][cli]") {
  const std::string dir = temp_dir("cli-max-steps");
  std::ofstream(dir + "/n.toml") << "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = "
                                    "1.0\n[flow]\nspeed = 1.0\nreynolds = 100.0\n[grid]\nn_theta = 32\nn_r = 24\n"
                                    "[time]\nmode = \"unsteady\"\nend = 1e12\n";
  const Outcome o = magnus_cmd({"run", dir + "/n.toml", "-o", dir + "/n.h5", "-q"}, dir);
  CHECK(o.status == 1);
  CHECK(one_line(o.err));
  CHECK(o.err.find("time.end = 1e+12 D/U takes about") != std::string::npos);
  CHECK(o.err.find("more than the 1e+07 a run may take") != std::string::npos);
  CHECK(!std::ifstream(dir + "/n.h5"));
}

TEST_CASE("a long command-line value is quoted cut to 60 characters", "[app][cli]") {
  const std::string dir = temp_dir("cli-long-input");
  const std::string junk(100000, '9');
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"sweep", demo, "--spin-ratio", junk + ":1:0.5", "-q"},
        std::vector<std::string>{"run", demo, "-q", "--tolerance", junk},
        std::vector<std::string>{"run", demo, "-q", "--max-memory", junk + "X"}}) {
    const Outcome o = magnus_cmd(args, dir);
    CAPTURE(o.err.substr(0, 300));
    CHECK(o.status != 0);
    CHECK(one_line(o.err));
    CHECK(o.err.size() < 400);
    CHECK(o.err.find("9…") != std::string::npos);
  }
}
