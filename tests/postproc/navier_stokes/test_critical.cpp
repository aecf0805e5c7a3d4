// The onset search's ends (critical.hpp): the growing pair found by Arnoldi on the linearised march and
// one tracked shift is the pair the full shift-invert search finds, so the crossing is the same, whichever
// end grows.
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/critical.hpp"
#include "postproc/navier_stokes/regula_falsi.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

HopfPoint search(const NsParams& p, double A, double B, bool seed) {
  HopfOptions o;
  o.tol = 0.002;
  o.seed_ends = seed;
  o.full.threads = 1;
  return hopf_point(p, HopfParameter::spin_ratio, A, B, o);
}

}  // namespace

TEST_CASE("[ns][critical] Re 100: the ends seeded by the march's Arnoldi give the full search's crossing",
          "[ns][critical]") {
  const NsParams p = test::cylinder_flow(100.0, 1.8, 32, 20.0);  // a coarse grid: the search, not the physics
  const HopfPoint full = search(p, 1.4, 2.4, false);
  const HopfPoint seeded = search(p, 1.4, 2.4, true);
  INFO("full search: α_L " << full.x_c << " ± " << full.change << ", pair at A " << full.at_a.mode
                           << "; seeded: α_L " << seeded.x_c << " ± " << seeded.change << ", pair at A "
                           << seeded.at_a.mode);
  CHECK(!full.at_a.seeded);
  CHECK(seeded.at_a.seeded);
  CHECK(seeded.at_a.growth() > 0.0);
  // The same eigenvalue of J at A (the seeded one is tracked at the march's estimate), and the same crossing
  // to well within the tolerance.
  CHECK(std::abs(seeded.at_a.mode - full.at_a.mode) < 1e-6);
  CHECK(std::fabs(seeded.x_c - full.x_c) < 0.1 * 0.002);
}

TEST_CASE("[ns][critical] Re_c without spin: a stable first end hands the search to the other end's march",
          "[ns][critical]") {
  const NsParams p = test::cylinder_flow(50.0, 0.0, 32, 20.0);
  HopfOptions o;
  o.tol = 0.02;
  o.full.threads = 1;
  const HopfPoint seeded = hopf_point(p, HopfParameter::reynolds, 40.0, 60.0, o);
  o.seed_ends = false;
  const HopfPoint full = hopf_point(p, HopfParameter::reynolds, 40.0, 60.0, o);
  INFO("seeded: Re_c " << seeded.x_c << ", full search: " << full.x_c);
  CHECK(seeded.at_a.growth() < 0.0);
  CHECK(!seeded.at_a.seeded);  // stable: tracked at B's pair
  CHECK(seeded.at_b.seeded);
  CHECK(std::abs(seeded.at_b.mode - full.at_b.mode) < 1e-6);
  CHECK(std::fabs(seeded.x_c - full.x_c) < 0.1 * 0.02);
}

TEST_CASE("[ns][critical] a neighbouring crossing's pair, followed to the ends: the crossing the ends' own "
          "searches give",
          "[ns][critical]") {
  // The curve α_L(Re) starts each point from the last one's crossing: its steady state for Newton, its pair
  // and eigenvector for both ends (one shift each, the pair most nearly parallel kept), no search of their own.
  const NsParams p = test::cylinder_flow(100.0, 1.8, 32, 20.0);
  const HopfPoint at_100 = search(p, 1.4, 2.4, true);
  REQUIRE(!at_100.next.vector.empty());
  CHECK(std::fabs(at_100.next.lambda.real()) < 0.01);  // the pair at the crossing
  const NsParams q = with_parameter(p, HopfParameter::reynolds, 110.0);
  HopfOptions o;
  o.tol = 0.002;
  o.full.threads = 1;
  const double A = at_100.x_c, B = at_100.x_c + 0.15;  // Re 110's crossing lies above Re 100's
  const HopfPoint own = hopf_point(q, HopfParameter::spin_ratio, A, B, o);
  const HopfPoint followed = hopf_point(q, HopfParameter::spin_ratio, A, B, o, {}, &at_100.next);
  INFO("own searches: α_L " << own.x_c << ", pair at A " << own.at_a.mode << "; followed: α_L " << followed.x_c
                            << ", pair at A " << followed.at_a.mode << " (overlap " << followed.at_a.overlap
                            << "), at B " << followed.at_b.mode << " (overlap " << followed.at_b.overlap << ")");
  CHECK(own.at_a.seeded);
  CHECK(!followed.at_a.seeded);
  CHECK(followed.at_a.overlap >= 0.5);  // followed, not the nearest pair
  CHECK(followed.at_b.overlap >= 0.5);
  CHECK(std::abs(followed.at_a.mode - own.at_a.mode) < 1e-6);  // the same eigenvalue of J
  CHECK(std::fabs(followed.x_c - own.x_c) < 0.1 * 0.002);
  for (const HopfEvaluation& e : followed.evaluations) CHECK(e.vector.empty());  // states and vectors dropped

  // Stepped from Re 100's crossing instead (the curve's way): its pair followed there, then secant steps with
  // Re 100's slope until the growth rate changes sign; the same crossing, from fewer steady states.
  REQUIRE(at_100.next.slope < 0.0);  // shedding stops above α_L: Re λ falls with α
  const HopfPoint stepped = hopf_point_from(q, HopfParameter::spin_ratio, at_100.x_c, 1.4, 2.4, o, at_100.next);
  INFO("stepped from " << at_100.x_c << ": α_L " << stepped.x_c << " in " << stepped.evaluations.size()
                       << " steady states (the ends' own bracket: " << own.evaluations.size() << ")");
  REQUIRE(!stepped.evaluations.empty());
  CHECK(stepped.evaluations.front().x == at_100.x_c);
  CHECK(stepped.evaluations.front().overlap >= 0.5);
  CHECK(std::fabs(stepped.x_c - own.x_c) < 0.1 * 0.002);
  CHECK(stepped.evaluations.size() < own.evaluations.size());
}

TEST_CASE("[ns][critical] the search variable: alpha squared for a spin range reaching down to 0, else the parameter",
          "[ns][critical]") {
  // Re λ is even in α (the flow at −α mirrors the one at α): a line in α² through two points of
  // σ = σ0 − c·α² finds its root exactly, a line in α does not.
  const SearchVariable v = search_variable(HopfParameter::spin_ratio, 0.05, 2.6);
  CHECK(v.squared);
  CHECK(!search_variable(HopfParameter::spin_ratio, -1.0, 1.0).squared);  // both signs of α
  CHECK(!search_variable(HopfParameter::spin_ratio, 1.6, 2.2).squared);  // far from α = 0
  CHECK(!search_variable(HopfParameter::reynolds, 40.0, 200.0).squared);
  const auto sigma = [](double a) { return 0.015 - 0.02 * a * a; };  // root √0.75 = 0.8660
  const double a0 = 0.05, a1 = 2.6;
  const double in_u = v.x(secant_zero(v.u(a0), sigma(a0), v.u(a1), sigma(a1)));
  const double in_x = secant_zero(a0, sigma(a0), a1, sigma(a1));
  CHECK(in_u == Approx(std::sqrt(0.75)).epsilon(1e-12));
  CHECK(std::fabs(in_x - std::sqrt(0.75)) > 0.5);
  CHECK(v.x(v.u(1.7)) == Approx(1.7).epsilon(1e-15));
}
