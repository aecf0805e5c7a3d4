// The error estimate of a viscous run (postproc/navier_stokes/error_estimate.hpp): the companion grid, the
// formula, the undefined cases, and its honesty against a Richardson reference of finer grids, on a steady
// case and on a shedding orbit (time.mode = "periodic").
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>

#include "io/case_file.hpp"
#include "postproc/navier_stokes/error_estimate.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/run_case.hpp"
#include "solver/navier_stokes/newton.hpp"

using namespace magnus;

TEST_CASE("companion_params: n_θ/2 and (n_r − 1)/2 + 1 rings, every other field kept", "[estimate]") {
  NsParams p;
  p.n_theta = 192, p.n_r = 0, p.nu = 0.02, p.cfl = 0.5, p.advection_order = 4, p.advection_order_xi = 4;
  p.outer_over_a = 40.0, p.threads = 2, p.dt = 0.01, p.radial_refinement = 2.0;
  const PolarGrid g = ns_grid(p);
  const NsParams c = companion_params(p, g);
  CHECK(c.n_theta == 96);
  CHECK(c.n_r == (g.n_r - 1) / 2 + 1);
  CHECK(c.nu == p.nu);
  CHECK(c.cfl == p.cfl);
  CHECK(c.advection_order == 4);
  CHECK(c.advection_order_xi == 4);
  CHECK(c.threads == 2);
  CHECK(c.dt == p.dt);
  CHECK(c.radial_refinement == p.radial_refinement);
  // The same outer radius, half the spacing each way.
  const PolarGrid gc = ns_grid(c);
  CHECK(gc.outer_radius() == Approx(g.outer_radius()).epsilon(1e-12));
  CHECK(gc.d_theta == Approx(2.0 * g.d_theta).epsilon(1e-12));
  CHECK(gc.xi[1] - gc.xi[0] == Approx(2.0 * (g.xi[1] - g.xi[0])).epsilon(1e-9));
  // n_θ/2 odd: up to the next even count.
  p.n_theta = 20;
  CHECK(companion_params(p, ns_grid(p)).n_theta == 10);
  p.n_theta = 12;
  CHECK(companion_params(p, ns_grid(p)).n_theta == 6);
  CHECK(companion_refusal(p, ns_grid(p), false).find("below 8") != std::string::npos);
}

TEST_CASE("same_orbit: a companion orbit within 30% in St and a factor 2 in amplitude is the run's", "[estimate]") {
  UnsteadyResult run, c;
  run.St = 0.02, run.C_L_amplitude = 1.3;
  c = run;
  CHECK(same_orbit(run, c));
  c.St = 0.0259, c.C_L_amplitude = 0.66;
  CHECK(same_orbit(run, c));
  c.St = 0.0261;  // the two-sided mode near α = 5 sheds at St ≈ 0.1: another branch
  CHECK_FALSE(same_orbit(run, c));
  c.St = 0.02, c.C_L_amplitude = 2.7;
  CHECK_FALSE(same_orbit(run, c));
  c.C_L_amplitude = 1.3, c.St = 0.0;  // no period
  CHECK_FALSE(same_orbit(run, c));
}

TEST_CASE("relative_estimate: |f_h − f_2h|/|f_h| + spread, undefined at f_h ≈ 0 and for non-finite input",
          "[estimate]") {
  CHECK(*relative_estimate(2.0, 1.9, 0.0) == Approx(0.05).epsilon(1e-12));
  CHECK(*relative_estimate(-2.0, -2.1, 0.01) == Approx(0.06).epsilon(1e-12));
  CHECK_FALSE(relative_estimate(0.0, 0.1, 0.0));
  CHECK_FALSE(relative_estimate(1e-4, 0.1, 0.0));
  CHECK_FALSE(relative_estimate(1.0, std::nan(""), 0.0));
  CHECK_FALSE(relative_estimate(1.0, INFINITY, 0.0));
}

TEST_CASE("estimate_from_companion: a failed, stopped or interrupted pair gives no estimate, says why",
          "[estimate]") {
  UnsteadyResult fine, coarse;
  fine.C_L_mean = -2.5, fine.C_D_mean = 1.1, fine.St = 0.165, fine.converged = true, fine.periodic = true;
  coarse.C_L_mean = -2.4, coarse.C_D_mean = 1.2, coarse.St = 0.16;
  {
    ViscousPart v;
    estimate_from_companion(v, fine, coarse, {});
    CHECK(*v.cl_mean_rel_estimate == Approx(0.04));
    CHECK(*v.cd_mean_rel_estimate == Approx(0.1 / 1.1));
    CHECK(*v.strouhal_rel_estimate == Approx(0.005 / 0.165));
    CHECK(v.error_note.empty());
    CHECK_FALSE(v.means_spread_rel);
  }
  {  // not converged: the spread is added, the largest kept
    ViscousPart v;
    fine.converged = false;
    estimate_from_companion(v, fine, coarse, MeansSpread{0.01, 0.02, 0.03});
    CHECK(*v.cl_mean_rel_estimate == Approx(0.05));
    CHECK(*v.strouhal_rel_estimate == Approx(0.005 / 0.165 + 0.03));
    CHECK_FALSE(v.means_converged);
    CHECK(*v.means_spread_rel == Approx(0.03));
    fine.converged = true;
  }
  auto none = [&](const UnsteadyResult& f, const UnsteadyResult& c, const char* why) {
    ViscousPart v;
    estimate_from_companion(v, f, c, {});
    CHECK_FALSE(v.cl_mean_rel_estimate);
    CHECK_FALSE(v.cd_mean_rel_estimate);
    CHECK_FALSE(v.strouhal_rel_estimate);
    CHECK(v.error_note.find(why) != std::string::npos);
  };
  UnsteadyResult failed = coarse;
  failed.ok = false, failed.message = "CFL above the limit at t = 3 s";
  none(fine, failed, "the companion run failed: CFL above");
  // A companion stopped short of the run's time has no means of the same flow; one stopped at it has.
  fine.state.t = 50.0;
  UnsteadyResult stopped = coarse;
  stopped.interrupted = true;
  stopped.state.t = 20.0;
  none(fine, stopped, "the companion was stopped before it reached the run's time");
  stopped.state.t = 50.0;
  ViscousPart caught_up;
  estimate_from_companion(caught_up, fine, stopped, {});
  CHECK(caught_up.cl_mean_rel_estimate);
  UnsteadyResult interrupted = fine;
  interrupted.interrupted = true;
  none(interrupted, coarse, "the run was interrupted");
  // α = 0: C_L ≈ 0 has no relative error, C_D still has one.
  UnsteadyResult zero = fine;
  zero.C_L_mean = 2e-5;
  ViscousPart v;
  estimate_from_companion(v, zero, coarse, {});
  CHECK_FALSE(v.cl_mean_rel_estimate);
  CHECK(v.cd_mean_rel_estimate);
  CHECK(v.error_note.find("C_L ≈ 0") != std::string::npos);
}

namespace {

/// Steady C_L, C_D at Re 20, α 0.5, R = 20a on n_θ × n_r by Newton from the potential flow.
std::pair<double, double> steady_forces(const Case& c, int n_theta, int n_r) {
  NsParams p = ns_params(c);
  p.n_theta = n_theta, p.n_r = n_r;
  const NewtonResult nr = solve_steady(p, potential_guess(p, ns_grid(p)));
  REQUIRE(nr.converged);
  const ViscousForces f = viscous_forces(ns_grid(p), p, c.scene.density, nr.state);
  return {*f.C_L, *f.C_D};
}

}  // namespace

TEST_CASE("the estimate is honest: at Re 20, α 0.5 (steady, Newton, n_θ 96) it brackets the error against "
          "a Richardson reference of two finer grids",
          "[estimate][ns]") {
  const Case c = parse_case(
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 0.5\n[flow]\nspeed = 1.0\n"
      "reynolds = 20\n[domain]\nouter_radius = 20.0\n[grid]\nn_theta = 96\nn_r = 77\n",
      "test");
  const FlowResult r = run_case(c);
  const ViscousPart& v = *r.viscous;
  REQUIRE(v.newton);
  REQUIRE(v.cl_mean_rel_estimate);
  REQUIRE(v.cd_mean_rel_estimate);
  // The reference: Richardson (order 2) from 144 × 115 and 192 × 153, the spacing 2/3 and 1/2 of the run's.
  // (On 48 × 39 against its companion 24 × 20 the C_D estimate, 0.24%, falls short of the error, 0.50%:
  // there C_D is not yet in the asymptotic range, its differences 0.0046, 0.0063, 0.0025 from 24 to 192.)
  const auto [cl3, cd3] = steady_forces(c, 144, 115);
  const auto [cl4, cd4] = steady_forces(c, 192, 153);
  const double q = (192.0 / 144.0) * (192.0 / 144.0) - 1.0;
  const double cl_ref = cl4 + (cl4 - cl3) / q, cd_ref = cd4 + (cd4 - cd3) / q;
  const double cl_err = std::fabs(*v.cl_mean - cl_ref) / std::fabs(cl_ref);
  const double cd_err = std::fabs(*v.cd_mean - cd_ref) / std::fabs(cd_ref);
  INFO("C_L " << *v.cl_mean << " ref " << cl_ref << " error " << cl_err << " estimate " << *v.cl_mean_rel_estimate);
  INFO("C_D " << *v.cd_mean << " ref " << cd_ref << " error " << cd_err << " estimate " << *v.cd_mean_rel_estimate);
  CHECK(*v.cl_mean_rel_estimate >= cl_err);
  CHECK(*v.cd_mean_rel_estimate >= cd_err);
  // …and not by orders of magnitude: the safety factor 3 over an order-2 Richardson estimate.
  CHECK(*v.cl_mean_rel_estimate <= 10.0 * cl_err);
  CHECK(*v.cd_mean_rel_estimate <= 10.0 * cd_err);
}

TEST_CASE("a periodic run's bar is its orbit on the grid twice as coarse, and it brackets the error against a "
          "Richardson reference (Re 100, α 1, n_θ 64 uniform rings, R 30a)",
          "[estimate][periodic_orbit]") {
  const std::string text =
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 1.0\n[flow]\nspeed = 1.0\n"
      "reynolds = 100\n[domain]\nouter_radius = 30.0\n[time]\nmode = \"periodic\"\nend = 300\n";
  const FlowResult r = run_case(parse_case(text, "test", {"grid.n_theta=64"}));
  const ViscousPart& v = *r.viscous;
  REQUIRE(v.converged);
  REQUIRE(v.error_note.empty());
  CHECK(v.error_method.find("companion orbit on 32 × ") != std::string::npos);
  REQUIRE((v.cl_mean_rel_estimate && v.cd_mean_rel_estimate && v.strouhal_rel_estimate));
  CHECK(v.means_converged);  // an orbit: no spread between periods is added to its bars

  // The grid twice as fine, whose own companion is the first run's grid, from rest: the first run's orbit
  // itself, so its bar is |f − f_first|/|f|.
  const FlowResult f = run_case(parse_case(
      text, "test", {"grid.n_theta=128", "grid.n_r=" + std::to_string(2 * (r.grid.n_r - 1) + 1)}));
  const ViscousPart& w = *f.viscous;
  REQUIRE(w.converged);
  REQUIRE(w.companion_n_theta == 64);
  REQUIRE(w.companion_n_r == r.grid.n_r);
  using Get = double (*)(const ViscousPart&);
  const std::tuple<const char*, Get, std::optional<double> ViscousPart::*> figures[] = {
      {"C_L", [](const ViscousPart& x) { return *x.cl_mean; }, &ViscousPart::cl_mean_rel_estimate},
      {"C_D", [](const ViscousPart& x) { return *x.cd_mean; }, &ViscousPart::cd_mean_rel_estimate},
      {"St", [](const ViscousPart& x) { return *x.strouhal; }, &ViscousPart::strouhal_rel_estimate}};
  for (const auto& [name, get, bar] : figures) {
    const double f1 = get(v), f2 = get(w);
    CHECK(*(w.*bar) == Approx(std::fabs(f2 - f1) / std::fabs(f2)).epsilon(1e-9));
    const double ref = f2 + (f2 - f1) / 3.0;  // Richardson at order 2
    const double err = std::fabs(f1 - ref) / std::fabs(ref);
    WARN(name << ": n_θ 64 " << f1 << ", 128 " << f2 << ", Richardson " << ref << "; error of the first "
              << err << ", its bar " << *(v.*bar));
    CHECK(*(v.*bar) >= err);
    CHECK(*(v.*bar) <= 20.0 * err);  // loose, not useless: the 32-point companion is far from asymptotic
  }
}

TEST_CASE("a periodic run whose coarse companion does not shed has no bar, and says why (Re 60, n_θ 48)",
          "[estimate][periodic_orbit]") {
  // Near the onset the grid twice as coarse (24 points) is steady: from rest, and again from the run's orbit
  // interpolated onto it, it finds no shedding orbit.
  const FlowResult r = run_case(parse_case(
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 0.0\n[flow]\nspeed = 1.0\n"
      "reynolds = 60\n[domain]\nouter_radius = 30.0\n[grid]\nn_theta = 48\n[time]\nmode = \"periodic\"\n"
      "end = 300\n",
      "test"));
  const ViscousPart& v = *r.viscous;
  REQUIRE(v.converged);
  REQUIRE(v.strouhal);  // the run's own orbit sheds
  CHECK_FALSE(v.cl_mean_rel_estimate);
  CHECK_FALSE(v.cd_mean_rel_estimate);
  CHECK_FALSE(v.strouhal_rel_estimate);
  INFO(v.error_note);
  CHECK(v.error_note.find("the companion run failed: ") != std::string::npos);
  CHECK(v.companion_n_theta == 24);
}

TEST_CASE("a run interrupted while its companion runs keeps its result and drops the bar",
          "[estimate][periodic_orbit]") {
  // keep_going is what a Ctrl-C turns false: polled once the run's own march or orbit is done, it stops the
  // companion instead of waiting for it. Here it says stop at once, while the run's steps go on.
  const std::string mode = GENERATE(std::string("periodic"), std::string("unsteady"));
  INFO("time.mode = " << mode);
  const Case c = parse_case(
      "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 1.0\n[flow]\nspeed = 1.0\n"
      "reynolds = 100\n[domain]\nouter_radius = 30.0\n[grid]\nn_theta = 48\n[time]\nmode = \"" +
          mode + "\"\nend = " + (mode == "periodic" ? "300" : "60") + "\n",
      "test");
  ViscousHooks hooks;
  hooks.keep_going = [] { return false; };
  const FlowResult r = run_viscous(c, hooks);
  const ViscousPart& v = *r.viscous;
  if (mode == "periodic") REQUIRE(v.converged);
  CHECK_FALSE(v.partial);
  CHECK(v.strouhal);
  CHECK(v.companion_n_theta == 24);  // the companion was started, then stopped
  CHECK_FALSE(v.cl_mean_rel_estimate);
  CHECK_FALSE(v.cd_mean_rel_estimate);
  CHECK(v.error_note.find("stopped by an interrupt") != std::string::npos);
}
