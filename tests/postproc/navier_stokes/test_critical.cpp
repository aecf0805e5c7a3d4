// The onset search's ends (critical.hpp): the growing pair found by Arnoldi on the linearised march and
// one tracked shift is the pair the full shift-invert search finds, so the crossing is the same, whichever
// end grows.
#include <catch2/catch.hpp>
#include <cmath>

#include "postproc/navier_stokes/critical.hpp"
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
}
