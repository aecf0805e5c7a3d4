// The viscous model against the consensus of published values (physics/viscous_consensus.hpp), run as a
// user runs it: a case's text → parse_case → run_viscous, on the scene's default grid (grid.refine = 1)
// and on grid.refine = 2. Marched scenes: the converged value is the Richardson extrapolation at order 2
// from the two, f₂ + (f₂ − f₁)/3. Steady scenes: time.mode = "steady", the grid study's Richardson value.
// Label `validation` (tens of minutes): ctest -L validation -R consensus. D = 1 m, U = 1 m/s, ρ = 1 kg/m³.
#include <fmt/core.h>
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "physics/viscous_consensus.hpp"
#include "postproc/navier_stokes/run.hpp"

using namespace magnus;

namespace {

/// A navier-stokes case at Re, α (a = 0.5 m, U = 1 m/s: D/U = 1 s) with extra keys `more` (TOML lines).
std::string consensus_case(double Re, double alpha, const std::string& mode, double t_end,
                           const std::string& more = "") {
  return fmt::format(
      "title = \"consensus Re {0} alpha {1}\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\n"
      "spin_ratio = {1}\n[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = {0}\n[time]\nmode = \"{2}\"\n"
      "end = {3}\n{4}",
      Re, alpha, mode, t_end, more);
}

/// One run of a case's text (cached: the checks of a scene share its runs); prints its grid and wall time.
const FlowResult& run_text(const std::string& text, const std::string& overrides) {
  static std::map<std::string, FlowResult> cache;
  const std::string key = text + "|" + overrides;
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  std::vector<std::string> sets;
  if (!overrides.empty()) sets.push_back(overrides);
  const Case c = parse_case(text, "consensus", sets);
  FlowResult r = run_viscous(c);
  const ViscousPart& v = *r.viscous;
  const double wall = v.newton_seconds.value_or(0.0) + v.stability_seconds.value_or(0.0) +
                      v.march_seconds.value_or(0.0);
  std::printf("  %s [%s]: grid %d x %d, R/a %.0f; %s; wall %.1f s\n", c.title.c_str(), overrides.c_str(),
              r.grid.n_theta, r.grid.n_r, r.grid.outer_radius() / c.scene.radius, v.status.c_str(), wall);
  std::fflush(stdout);
  return cache.emplace(key, std::move(r)).first->second;
}

/// Prints ours against the table's entry and checks the entry's tolerance.
void check_consensus(const char* id, double ours, const std::string& how) {
  const ConsensusValue& ref = consensus(id);
  const double diff = (ours - ref.value) / std::fabs(ref.value);
  std::printf("  %-14s ours %9.4f  published %9.4f (%s)  difference %+6.2f%%  tolerance %.1f%%  (%s)\n",
              ref.quantity, ours, ref.value, ref.sources, 100.0 * diff, 100.0 * ref.tolerance, how.c_str());
  std::fflush(stdout);
  INFO(ref.id << ": ours " << ours << " against " << ref.value);
  CHECK(std::fabs(diff) <= ref.tolerance);
}

/// A marched scene on grid.refine 1 and 2: the two results.
struct Marched {
  const FlowResult& r1;
  const FlowResult& r2;
  /// f₂ + (f₂ − f₁)/3 of a ViscousPart figure (Richardson at order 2, grid ratio 2).
  template <class F>
  double richardson(F f) const {
    const double f1 = f(*r1.viscous), f2 = f(*r2.viscous);
    std::printf("    refine 1: %.5f  refine 2: %.5f\n", f1, f2);
    return f2 + (f2 - f1) / 3.0;
  }
};

Marched marched(double Re, double alpha, double t_end, const std::string& more = "") {
  const std::string text = consensus_case(Re, alpha, "unsteady", t_end, more);
  const FlowResult& r1 = run_text(text, "");
  const FlowResult& r2 = run_text(text, "grid.refine=2");
  REQUIRE((r1.viscous->periodic && r2.viscous->periodic));
  return {r1, r2};
}

/// A steady scene by the grid study (time.mode = "steady") at grid.refine 2, domain R = R_over_a·a
/// (domain.outer_radius is R/a).
const FlowResult& steady(double Re, double alpha, double R_over_a = 100.0) {
  const FlowResult& r = run_text(
      consensus_case(Re, alpha, "steady", 100, fmt::format("[domain]\nouter_radius = {}\n", R_over_a)),
      "grid.refine=2");
  REQUIRE(r.viscous->steady_study);
  REQUIRE(r.viscous->steady_study->converged);
  return r;
}

/// The separation angle (deg) from the rear stagnation point (θ = 0) on the upper side, α = 0.
double separation_deg(const FlowResult& r) {
  for (double t : r.viscous->separation)
    if (t > 0.05 && t < M_PI) return 180.0 / M_PI * t;
  return 0.0;
}

const char* kRich = "Richardson of refine 1 and 2";
const char* kStudy = "steady grid study, Richardson";

}  // namespace

TEST_CASE("[validation] consensus: steady Re 20, alpha 0: C_D and the wake length", "[validation]") {
  const SteadyStudy& st = *steady(20, 0).viscous->steady_study;
  REQUIRE((st.C_D && st.recirculation));
  check_consensus("re20_cd", st.C_D->value, kStudy);
  check_consensus("re20_lw", st.recirculation->value, kStudy);
}

TEST_CASE("[validation] consensus: steady Re 40, alpha 0: C_D at R = 60a, 80a, 100a, wake, separation",
          "[validation]") {
  for (const auto& [R, id] : {std::pair{60.0, "re40_cd_60"}, {80.0, "re40_cd_80"}, {100.0, "re40_cd_100"}}) {
    const SteadyStudy& st = *steady(40, 0, R).viscous->steady_study;
    REQUIRE(st.C_D);
    check_consensus(id, st.C_D->value, kStudy);
  }
  const FlowResult& r = steady(40, 0, 100.0);
  REQUIRE(r.viscous->steady_study->recirculation);
  check_consensus("re40_lw", r.viscous->steady_study->recirculation->value, kStudy);
  check_consensus("re40_sep", separation_deg(r), "finest grid of the study");
}

TEST_CASE("[validation] consensus: Re 100, alpha 0: mean C_D and St", "[validation]") {
  const Marched m = marched(100, 0, 300);
  check_consensus("re100_a0_cd", m.richardson([](const ViscousPart& v) { return *v.cd_mean; }), kRich);
  check_consensus("re100_a0_st", m.richardson([](const ViscousPart& v) { return *v.strouhal; }), kRich);
}

TEST_CASE("[validation] consensus: Re 100, alpha 1: mean |C_L|, C_D, St, C_L amplitude", "[validation]") {
  const Marched m = marched(100, 1, 300);
  check_consensus("re100_a1_cl", m.richardson([](const ViscousPart& v) { return -*v.cl_mean; }), kRich);
  check_consensus("re100_a1_cd", m.richardson([](const ViscousPart& v) { return *v.cd_mean; }), kRich);
  check_consensus("re100_a1_st", m.richardson([](const ViscousPart& v) { return *v.strouhal; }), kRich);
  check_consensus("re100_a1_amp", m.richardson([](const ViscousPart& v) { return *v.cl_amplitude; }), kRich);
}

TEST_CASE("[validation] consensus: Re 100, alpha 1.5: mean C_D", "[validation]") {
  const Marched m = marched(100, 1.5, 300);
  check_consensus("re100_a15_cd", m.richardson([](const ViscousPart& v) { return *v.cd_mean; }), kRich);
}

TEST_CASE("[validation] consensus: steady Re 100, alpha 2: |C_L| and C_D", "[validation]") {
  const SteadyStudy& st = *steady(100, 2).viscous->steady_study;
  REQUIRE((st.C_D && st.C_L));
  check_consensus("re100_a2_cl", -st.C_L->value, kStudy);
  check_consensus("re100_a2_cd", st.C_D->value, kStudy);
}

TEST_CASE("[validation] consensus: steady Re 100, alpha 4 and 6: |C_L| (digitised)", "[validation]") {
  for (const auto& [alpha, id] : {std::pair{4.0, "re100_a4_cl"}, {6.0, "re100_a6_cl"}}) {
    const SteadyStudy& st = *steady(100, alpha).viscous->steady_study;
    REQUIRE(st.C_L);
    check_consensus(id, -st.C_L->value, kStudy);
  }
}

TEST_CASE("[validation] consensus: Re 100, alpha 5: the one-sided second shedding mode", "[validation]") {
  // The second mode's period is ~45 D/U and it grows slowly from rest: its orbit by shooting (a march to
  // where two periods agree, then Newton), on the default grid only.
  const FlowResult& r = run_text(consensus_case(100, 5, "periodic", 1500), "");
  const ViscousPart& v = *r.viscous;
  REQUIRE(v.periodic);
  REQUIRE(v.converged);
  check_consensus("re100_a5_cl", -*v.cl_mean, "default grid, the orbit");
  check_consensus("re100_a5_cd", *v.cd_mean, "default grid, the orbit");
  check_consensus("re100_a5_st", *v.strouhal, "default grid, the orbit");
}

TEST_CASE("[validation] Re 100, alpha 5: the steady drag does not depend on the outer radius (25a to 200a)",
          "[validation]") {
  // The drag at high spin is a small difference of large parts (pressure −1.28, friction +1.13), and the
  // published values sit 0.3 above magnus's: a tilt of the force by 0.8°. magnus's far field carries the
  // circulation, so its drag should not move with R. Measured: C_D −0.1548, −0.1509, −0.1494, −0.1486 at
  // R = 25a, 50a, 100a, 200a (spread 0.006), |C_L| within 0.1%.
  std::vector<double> cd, cl;
  for (const double R : {25.0, 50.0, 100.0, 200.0}) {
    const FlowResult& r =
        run_text(consensus_case(100, 5, "steady", 100, fmt::format("[domain]\nouter_radius = {}\n", R)), "");
    const SteadyStudy& st = *r.viscous->steady_study;
    REQUIRE((st.converged && st.C_D && st.C_L));
    std::printf("  R = %3.0fa: C_D %.5f ± %.5f, C_L %.4f ± %.4f\n", R, st.C_D->value, st.C_D->error,
                st.C_L->value, st.C_L->error);
    cd.push_back(st.C_D->value), cl.push_back(st.C_L->value);
  }
  const auto [cd_lo, cd_hi] = std::minmax_element(cd.begin(), cd.end());
  const auto [cl_lo, cl_hi] = std::minmax_element(cl.begin(), cl.end());
  CHECK(*cd_hi - *cd_lo <= 0.01);                          // 3% of the published 0.33
  CHECK(*cl_hi - *cl_lo <= 2e-3 * std::fabs(cl.back()));  // C_L < 0: lo, hi by value
  CHECK(*cd_hi < 0.0);                                     // a thrust, at every R
}

TEST_CASE("[validation] Re 100, alpha 1 with the absorbing layer: refine 1, 2, 4 converge at order 2",
          "[validation]") {
  // The default case's family (the scene's grid refined 1, 2 and 4 times, its layer from 50a): without the
  // layer the vortex street crossing R made it irregular at the 0.5% level. Measured: C_L −2.50276,
  // −2.50114, −2.50077 (order 2.1), C_D 1.09317, 1.09413, 1.09441 (order 1.8), St 0.16493, 0.16497,
  // 0.16498; refine 2 within 0.03% of refine 4 in all three (about 15 min in all).
  const std::string text = consensus_case(100, 1, "unsteady", 300);
  const FlowResult& r1 = run_text(text, "");
  const FlowResult& r2 = run_text(text, "grid.refine=2");
  const FlowResult& r4 = run_text(text, "grid.refine=4");
  for (const FlowResult* r : {&r1, &r2, &r4}) {
    REQUIRE(r->viscous->periodic);
    CHECK(r->c.grid.absorbing_layer == 50.0);
  }
  using Get = double (*)(const ViscousPart&);
  const std::pair<const char*, Get> figures[] = {
      {"C_L", [](const ViscousPart& v) { return *v.cl_mean; }},
      {"C_D", [](const ViscousPart& v) { return *v.cd_mean; }},
      {"St", [](const ViscousPart& v) { return *v.strouhal; }}};
  for (const auto& [name, get] : figures) {
    const double f1 = get(*r1.viscous), f2 = get(*r2.viscous), f4 = get(*r4.viscous);
    const double order = std::log2(std::fabs((f1 - f2) / (f2 - f4)));
    std::printf("  %s: %.5f %.5f %.5f, observed order %.2f, refine 2 to 4 %.3f%%\n", name, f1, f2, f4, order,
                100.0 * std::fabs(f2 / f4 - 1.0));
    INFO(name << ": " << f1 << ", " << f2 << ", " << f4 << "; observed order " << order);
    CHECK(std::fabs(f2 - f4) <= 5e-4 * std::fabs(f4));  // four digits on refine 2
    if (std::string(name) != "St") CHECK(std::fabs(order - 2.0) < 0.5);  // St moves by 1e-5: order is noise
  }
}
