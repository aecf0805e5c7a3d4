// The absorbing layer (operator.hpp): a vortex inside it fades as the sink −λ(r)ζ says, and the circulation
// it takes leaves Γ_R too; outside it nothing changes. Newton's rows with the layer: test_newton.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <utility>

#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/stages.hpp"

using namespace magnus;

namespace {

/// Still fluid, no spin, R = 20a; the layer from r_s = 10a with λ_R = 1/s (or none).
NsParams still_fluid(double absorbing_start) {
  NsParams p;
  p.a = 0.1, p.U = 0.0, p.omega = 0.0, p.nu = 1e-6;
  p.outer_over_a = 20.0, p.n_theta = 128, p.n_r = 160, p.threads = 1;
  p.absorbing_start = absorbing_start, p.absorbing_rate = 1.0;
  return p;
}

/// ∫∫ ζ w dA over rings 1…n_r−2 (the absorbed_circulation quadrature), w = weight(r), m²/s.
template <class W>
double weighted_circulation(const PolarGrid& g, const std::vector<double>& zeta, W weight) {
  double sum = 0.0;
  for (int i = 1; i + 1 < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j)
      sum += weight(g.r[i]) * zeta[size_t(i) * g.n_theta + j] * g.r[i] * g.r[i] * g.ring_width(i) * g.d_theta;
  return sum;
}

struct Faded {
  double Gamma0, Gamma, expected, Gamma_R;
};

/// A Gaussian vortex of radius a at r = 15a stepped for t_end = 4 s: its circulation inside R, the pure
/// sink's ∫∫ ζ_0 e^{−λ(r) t} dA (the exact answer without transport, which the blob's own rotation about
/// its centre leaves nearly unchanged), and Γ_R.
Faded fade(double absorbing_start) {
  const NsParams p = still_fluid(absorbing_start);
  const PolarGrid g = ns_grid(p);
  NsState s = impulsive_start(p, g);
  add_vortex_blob(g, s, 15.0 * p.a, 0.0, p.a, 1e-3);
  const double Gamma0 = weighted_circulation(g, s.zeta, [](double) { return 1.0; });
  s.Gamma_R = Gamma0;
  const double t_end = 4.0, dt = 0.01;
  const std::vector<double> zeta0 = s.zeta;
  const NsOperator op(p, dt);
  NsState next;
  for (int q = 0; q < int(std::lround(t_end / dt)); ++q) advance(op, s, next), std::swap(s, next);
  const double expected =
      weighted_circulation(g, zeta0, [&](double r) { return std::exp(-absorbing_rate_at(p, r) * t_end); });
  return {Gamma0, weighted_circulation(g, s.zeta, [](double) { return 1.0; }), expected, s.Gamma_R};
}

}  // namespace

TEST_CASE("[ns] absorbing layer: a vortex in it fades at the rate lambda(r), Gamma_R keeps the budget", "[ns]") {
  const Faded with = fade(10.0), without = fade(0.0);
  INFO("Γ_0 " << with.Gamma0 << ", with the layer " << with.Gamma << " (pure sink " << with.expected << ", Γ_R "
              << with.Gamma_R << "), without " << without.Gamma << " (Γ_R " << without.Gamma_R << ")");
  // Without the layer the vortex keeps its circulation (still fluid, far from both boundaries).
  CHECK(std::fabs(without.Gamma - without.Gamma0) < 1e-6 * without.Gamma0);
  CHECK(std::fabs(without.Gamma_R - without.Gamma0) < 1e-6 * without.Gamma0);
  // With it, ⟨λ⟩t ≈ 1: the circulation falls to e^{−1} of itself, as the sink alone would take it.
  CHECK(with.Gamma < 0.45 * with.Gamma0);
  CHECK(std::fabs(with.Gamma - with.expected) < 2e-5 * (with.Gamma0 - with.expected));
  // What the layer removed left Γ_R too: Γ_R is still the circulation inside R (no wall circulation here).
  CHECK(std::fabs(with.Gamma_R - with.Gamma) < 1e-6 * (with.Gamma0 - with.Gamma));
}

TEST_CASE("[ns] absorbing layer: its parameters are checked by the operator", "[ns]") {
  for (const double start : {0.5, 1.0, 20.0, 30.0}) {
    INFO("absorbing_start " << start);
    CHECK_THROWS_AS(NsOperator(still_fluid(start), 0.01), std::invalid_argument);
  }
  NsParams p = still_fluid(10.0);
  p.absorbing_rate = -1.0;
  CHECK_THROWS_AS(NsOperator(p, 0.01), std::invalid_argument);
  p.absorbing_rate = std::nan("");
  CHECK_THROWS_AS(NsOperator(p, 0.01), std::invalid_argument);
}
