// Floquet stability of shedding orbits to spanwise disturbances (solver/navier_stokes/floquet.hpp).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "postproc/navier_stokes/orbit.hpp"
#include "solver/navier_stokes/floquet.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/spanwise.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// The orbit of p (from rest, the symmetry broken as a run breaks it) and its Fourier series.
PeriodicBase shedding_orbit(const NsParams& p) {
  const OrbitRun run = test::shedding_orbit_run(p, 400.0, 1e-8);
  REQUIRE(run.orbit.converged);
  return orbit_series(p, run.orbit);
}

}  // namespace

TEST_CASE("[ns][floquet] Re 100: the orbit's Fourier series holds it to 1% in 8 harmonics", "[ns][floquet]") {
  // The base of a Floquet analysis: the Re 100 shedding orbit on n_θ 48, R = 30a, by its series. (Its
  // multipliers are checked in `ctest -L validation`: on this grid the Arnoldi estimates do not converge
  // in 30 periods, the slow far-field modes crowding the spectrum.)
  const NsParams p = test::cylinder_flow(100.0, 0.0, 48, 30.0);
  const PeriodicBase base = shedding_orbit(p);
  CHECK(base.truncation() < 1e-2);  // the 8th harmonic of the base is below 1% of the first
  CHECK(base.T == Approx(1.0 / 0.1644).epsilon(0.1));  // St within 10% of the consensus on this coarse grid
  CHECK_THROWS_AS(floquet_multipliers(p, base, -1.0), std::invalid_argument);
}

TEST_CASE("[ns][floquet] a steady base: the period map is e^{lambda T}, to second order in the step",
          "[ns][floquet]") {
  // A steady state written as a periodic base with no oscillation (one zero harmonic, T = 20 D/U): the period
  // map is then the stepper's e^{JT} on M, so its leading multiplier is e^{λT} of the rightmost eigenvalue
  // of the same spanwise problem found by shift-invert: the Re 60 wake's unstable pair on n_θ 32, β = 0.
  const NsParams p = test::cylinder_flow(60.0, 0.0, 32, 40.0);
  const NewtonResult s = solve_steady(p, potential_guess(p, ns_grid(p)));
  REQUIRE(s.converged);
  const double beta = 0.0;
  const StabilityResult eig = spanwise_eigenvalues(p, s.state, beta, 12, StabilityOptions{});
  REQUIRE(!eig.eigenvalues.empty());
  PeriodicBase base;
  base.mean = s.state, base.T = 20.0;
  NsState zero = s.state;
  std::fill(zero.psi.begin(), zero.psi.end(), 0.0), std::fill(zero.zeta.begin(), zero.zeta.end(), 0.0);
  base.cos_part = {zero}, base.sin_part = {zero};
  const std::complex<double> lead = eig.eigenvalues.front();  // rightmost, Im ≥ 0 first (D/U = 1 s)
  std::vector<double> err;
  FloquetResult cold;
  for (int steps : {100, 200, 400}) {
    FloquetOptions o;
    o.steps = steps;
    const FloquetResult r = floquet_multipliers(p, base, beta, o);
    if (steps == 400) cold = r;
    REQUIRE(!r.multipliers.empty());
    const std::complex<double> mu = r.multipliers[0], exact = std::exp(lead * base.T);
    const double e = std::min(std::abs(mu - exact), std::abs(mu - std::conj(exact)));
    INFO(steps << " steps: μ " << mu << " (residual " << r.residuals[0] << ") against e^{λT} " << exact << ", λ " << lead);
    CHECK(r.residuals[0] < 1e-5);
    err.push_back(e);
  }
  const double order = test::observed_order(err[1], err[2]);
  INFO("errors " << err[0] << ", " << err[1] << ", " << err[2] << ": observed order " << order);
  // Measured: 0.0260, 0.00652, 0.00163 (|μ| = 1.25), order 2.00.
  CHECK(err[2] < 2e-3);
  CHECK(std::fabs(order - 2.0) < 0.1);
  // Started from the mode found, Arnoldi stops at its tolerance as soon as it may (count + 2 vectors) on
  // the same multiplier: the warm start a neighbouring Reynolds number gets in the onset search.
  FloquetOptions warm;
  warm.steps = 400, warm.start = cold.mode, warm.tolerance = 1e-6;
  const FloquetResult w = floquet_multipliers(p, base, beta, warm);
  INFO("warm start: " << w.periods << " periods, μ " << w.multipliers[0] << " (cold: " << cold.periods << ")");
  CHECK(w.periods == warm.count + 3);  // the start's period and count + 2 vectors
  CHECK(cold.periods == FloquetOptions{}.krylov + 1);  // no tolerance: every vector
  CHECK(std::abs(std::abs(w.multipliers[0]) - std::abs(cold.multipliers[0])) < 1e-6);
}

TEST_CASE("[ns][floquet] the harmonics summed on their union pattern give the sum of their products",
          "[ns][floquet]") {
  // Three sparse matrices with patterns that overlap in part (and an empty column): the stepper's one-pass
  // sum Σ c_h B_h x against the matrices applied one by one, and the union pattern holds each row once.
  const long n = 40;
  std::vector<EigenProblem> B(3);
  unsigned seed = 12345;
  auto next = [&seed] { return (seed = seed * 1103515245u + 12345u) / 65536u % 32768u; };
  for (size_t h = 0; h < B.size(); ++h) {
    B[h].n = n;
    B[h].Ap.assign(size_t(n) + 1, 0);
    for (long c = 0; c < n; ++c) {
      for (long r = 0; r < n && c != 7; ++r)
        if ((r + c + long(h)) % 5 == 0 || next() % 11 == 0)
          B[h].Ai.push_back(r), B[h].Ax.push_back(double(next()) / 16384.0 - 1.0);
      B[h].Ap[size_t(c) + 1] = long(B[h].Ai.size());
    }
  }
  const HarmonicSum sum(B);
  REQUIRE(sum.H == 3);
  for (long c = 0; c < n; ++c) {
    std::vector<long> rows(sum.Ai.begin() + sum.Ap[size_t(c)], sum.Ai.begin() + sum.Ap[size_t(c) + 1]);
    std::sort(rows.begin(), rows.end());
    CHECK(std::adjacent_find(rows.begin(), rows.end()) == rows.end());
  }
  const size_t nn = static_cast<size_t>(n);
  std::vector<double> x(nn), y(nn), ref(nn, 0.0);
  for (double& v : x) v = double(next()) / 16384.0 - 1.0;
  const double c[3] = {0.7, -1.3, 0.25};
  for (size_t h = 0; h < B.size(); ++h) B[h].multiply_add(x, c[h], ref);
  sum.apply(c, x, y);
  double err = 0.0, scale = 0.0;
  for (size_t q = 0; q < nn; ++q)
    err = std::max(err, std::fabs(y[q] - ref[q])), scale = std::max(scale, std::fabs(ref[q]));
  CHECK(scale > 1.0);
  CHECK(err < 1e-14 * scale);
}

TEST_CASE("[ns][floquet] canonical_phase: every shift of an orbit lands on one phase", "[ns][floquet]") {
  // A synthetic orbit with two harmonics, ζ(t) = A cos(ωt + 0.3) + B sin(2ωt − 1.1), sampled by the
  // Fourier accumulator from two different starting times: the two series describe one orbit, and
  // canonical_phase must take both to the same phase, where the first harmonic of Σζ is a pure cosine.
  const size_t nodes = 50;
  const int N = 32;
  const double T = 4.0, w = 2.0 * M_PI / T;
  std::vector<double> A(nodes), B(nodes);
  for (size_t q = 0; q < nodes; ++q) A[q] = std::sin(0.7 * double(q) + 0.2), B[q] = std::cos(1.3 * double(q));
  auto series = [&](double t0) {
    FourierAccumulator acc(nodes, N, 3, T);
    for (int n = 0; n < N; ++n) {
      const double t = t0 + n * T / N;
      NsState s;
      s.psi.assign(nodes, 0.0), s.zeta.assign(nodes, 0.0);
      for (size_t q = 0; q < nodes; ++q)
        s.zeta[q] = A[q] * std::cos(w * t + 0.3) + B[q] * std::sin(2.0 * w * t - 1.1), s.psi[q] = 0.5 * s.zeta[q];
      acc.add(n, s);
    }
    return canonical_phase(acc.base());
  };
  const PeriodicBase a = series(0.0), b = series(1.37);
  double C = 0.0, S = 0.0, gap = 0.0;
  for (size_t q = 0; q < nodes; ++q) {
    C += a.cos_part[0].zeta[q], S += a.sin_part[0].zeta[q];
    for (size_t k = 0; k < 2; ++k)
      gap = std::max({gap, std::fabs(a.cos_part[k].zeta[q] - b.cos_part[k].zeta[q]),
                      std::fabs(a.sin_part[k].zeta[q] - b.sin_part[k].zeta[q]),
                      std::fabs(a.cos_part[k].psi[q] - b.cos_part[k].psi[q])});
  }
  CHECK(gap < 1e-12);
  CHECK(std::fabs(S) < 1e-12);
  CHECK(C > 0.0);
}

TEST_CASE("[ns][floquet] FloquetOptions::met: the absolute tolerance near neutral, the relative one far from it",
          "[ns][floquet]") {
  FloquetOptions o;
  o.tolerance = 1e-3, o.relative = 0.1;
  CHECK(o.met(1.0, 9e-4));
  CHECK(!o.met(1.0, 2e-3));  // |μ| = 1: only the absolute tolerance
  CHECK(o.met(std::complex<double>(0.3, 0.4), 0.04));  // |μ| = 0.5: a tenth of 0.5
  CHECK(!o.met(std::complex<double>(0.3, 0.4), 0.06));
  CHECK(!FloquetOptions{}.met(1.0, 1e-9));  // no tolerance: never met
}
