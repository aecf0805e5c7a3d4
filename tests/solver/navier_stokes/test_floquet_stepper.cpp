// The Floquet stepper's period map on a base that does vary in time (solver/navier_stokes/floquet.hpp),
// against an independent integration of the same linear equations.
#include <catch2/catch.hpp>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "solver/navier_stokes/floquet.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/spanwise.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// A base with two harmonics of unlike shapes in its cos and sin parts (ψ in m²/s, ζ unused by the spanwise
/// problem): the potential flow of p, and ψ_k = c·U a (1 − a/r)² f(θ) vanishing on the wall.
PeriodicBase two_harmonic_base(const NsParams& p, double T) {
  const PolarGrid g = ns_grid(p);
  PeriodicBase b;
  b.mean = potential_guess(p, g), b.T = T;
  NsState zero = b.mean;
  std::fill(zero.psi.begin(), zero.psi.end(), 0.0), std::fill(zero.zeta.begin(), zero.zeta.end(), 0.0);
  b.cos_part.assign(2, zero), b.sin_part.assign(2, zero);
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j) {
      const size_t q = size_t(i) * size_t(g.n_theta) + size_t(j);
      const double th = g.theta[size_t(j)], s = p.U * p.a * std::pow(1.0 - p.a / g.r[size_t(i)], 2);
      b.cos_part[0].psi[q] = 0.8 * s * std::cos(2.0 * th);
      b.sin_part[0].psi[q] = 0.6 * s * std::sin(3.0 * th + 0.3);
      b.cos_part[1].psi[q] = 0.4 * s * std::sin(th);
      b.sin_part[1].psi[q] = 0.5 * s * std::cos(th - 0.7);
    }
  return b;
}

/// b(t) = b_0 + Σ_k (b_k^c cos kωt + b_k^s sin kωt), ψ only.
NsState base_at(const PeriodicBase& b, double t) {
  NsState s = b.mean;
  for (size_t k = 0; k < b.cos_part.size(); ++k) {
    const double w = 2.0 * M_PI * double(k + 1) / b.T, c = std::cos(w * t), d = std::sin(w * t);
    for (size_t q = 0; q < s.psi.size(); ++q) s.psi[q] += c * b.cos_part[k].psi[q] + d * b.sin_part[k].psi[q];
  }
  return s;
}

/// The same period by Crank–Nicolson on the whole of J(t), assembled afresh from b(t) at every step (no
/// harmonic matrices, no Adams–Bashforth), the pressure at the half step and the constraints at t_{n+1}:
///     M(u^{n+1} − u^n)/Δt = ½ A(t_{n+1}) u^{n+1} + ½ A(t_n) u^n + G p^{n+½},   0 = C(t_{n+1}) u^{n+1}.
std::vector<double> crank_nicolson_period(const NsParams& p, const PeriodicBase& b, double beta, int steps,
                                          std::vector<double> x) {
  const SpanwiseOutflow out = spanwise_outflow(p, b.mean);
  const double dt = b.T / steps;
  EigenProblem Jn = spanwise_problem(p, base_at(b, 0.0), beta, out);
  const long n = Jn.n;
  for (int s = 0; s < steps; ++s) {
    const EigenProblem J1 = spanwise_problem(p, base_at(b, (s + 1) * dt), beta, out);
    for (long r = kSpanwisePressure; r < n; r += kSpanwiseFields) x[size_t(r)] = 0.0;  // p^{n−½} not carried
    std::vector<double> rhs = Jn.multiply(x);
    std::vector<Eigen::Triplet<double>> K;
    for (long c = 0; c < n; ++c)
      for (long t = J1.Ap[size_t(c)]; t < J1.Ap[size_t(c) + 1]; ++t) {
        const long r = J1.Ai[size_t(t)];
        const bool half = J1.m[size_t(r)] != 0.0 && c % kSpanwiseFields != kSpanwisePressure;
        K.emplace_back(r, c, half ? 0.5 * J1.Ax[size_t(t)] : J1.Ax[size_t(t)]);
      }
    for (long r = 0; r < n; ++r) {
      const double m = J1.m[size_t(r)];
      if (m != 0.0) K.emplace_back(r, r, -m / dt);
      rhs[size_t(r)] = m != 0.0 ? -m / dt * x[size_t(r)] - 0.5 * rhs[size_t(r)] : 0.0;
    }
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(K.begin(), K.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
    REQUIRE(lu.info() == Eigen::Success);
    const Eigen::VectorXd next = lu.solve(Eigen::Map<const Eigen::VectorXd>(rhs.data(), n));
    x.assign(next.data(), next.data() + n);
    Jn = J1;
  }
  return x;
}

/// max |a − b| over the rows with mass (the velocities inside; the pressure and the ghosts are the
/// constraints' multipliers and boundary values).
double velocity_gap(const EigenProblem& J, const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0.0;
  for (size_t r = 0; r < a.size(); ++r)
    if (J.m[r] != 0.0) e = std::max(e, std::fabs(a[r] - b[r]));
  return e;
}

}  // namespace

TEST_CASE("[ns][floquet] a base with harmonics: the period map against Crank-Nicolson on the whole of J(t)",
          "[ns][floquet]") {
  // The stepper takes J(t) apart (J_0 by Crank–Nicolson, the harmonics' B(t) by Adams–Bashforth 2, summed on
  // their union pattern). Here J(t) is assembled whole from b(t) at every step and stepped by Crank–Nicolson:
  // a second scheme for the same equations. Both are second order, so their Richardson limits must agree
  // far closer than either differs from its own limit, and far closer than the map of a base with its cos
  // and sin parts swapped: the harmonics' phases, frequencies and weights are what is checked.
  const NsParams p = test::cylinder_flow(40.0, 0.5, 24, 10.0);
  const PeriodicBase base = two_harmonic_base(p, 4.0);
  const double beta = 1.5 / (2.0 * p.a);
  const EigenProblem J = spanwise_problem(p, base.mean, beta);
  std::vector<double> x(size_t(J.n), 0.0);
  unsigned seed = 2024;
  for (size_t r = 0; r < x.size(); ++r)
    if (J.m[r] != 0.0) x[r] = double((seed = seed * 1103515245u + 12345u) / 65536u % 32768u) / 16384.0 - 1.0;
  x = floquet_period_map(p, base, beta, 20, x);  // one that meets the constraints (their rows hold no base)

  std::vector<std::vector<double>> P, C;
  for (int steps : {50, 100, 200}) P.push_back(floquet_period_map(p, base, beta, steps, x));
  for (int steps : {100, 200}) C.push_back(crank_nicolson_period(p, base, beta, steps, x));
  auto richardson = [](const std::vector<double>& coarse, const std::vector<double>& fine) {
    std::vector<double> l(fine.size());
    for (size_t r = 0; r < l.size(); ++r) l[r] = fine[r] + (fine[r] - coarse[r]) / 3.0;
    return l;
  };
  const std::vector<double> limit_P = richardson(P[1], P[2]), limit_C = richardson(C[0], C[1]);
  const double e1 = velocity_gap(J, P[0], P[1]), e2 = velocity_gap(J, P[1], P[2]);
  const double gap = velocity_gap(J, limit_P, limit_C), own = velocity_gap(J, P[2], limit_P);
  PeriodicBase swapped = base;
  swapped.cos_part.swap(swapped.sin_part);
  const double swap = velocity_gap(J, P[2], floquet_period_map(p, swapped, beta, 200, x));
  INFO("the stepper on 50, 100, 200 steps: " << e1 << ", " << e2 << " (order " << test::observed_order(e1, e2)
       << "); limits apart " << gap << ", the stepper's 200 from its limit " << own
       << ", CN 200 from the stepper's limit " << velocity_gap(J, C[1], limit_P) << "; cos and sin swapped: "
       << swap << "; |Px| " << velocity_gap(J, P[2], std::vector<double>(x.size(), 0.0)));
  // Measured: 1.00e-3, 2.49e-4 (order 2.01); limits 4.4e-6 apart, 8.3e-5 from the 200 steps to their limit;
  // the swapped base's map 0.071 away (|Px| 0.20 on the velocities).
  CHECK(std::fabs(test::observed_order(e1, e2) - 2.0) < 0.1);
  CHECK(gap < 0.1 * own);
  CHECK(gap < 1e-3 * swap);
}

TEST_CASE("[ns][floquet] a base with a short part, or an x of the wrong size, is refused before any solve",
          "[ns][floquet]") {
  const NsParams p = test::cylinder_flow(40.0, 0.5, 16, 8.0);
  const PeriodicBase base = two_harmonic_base(p, 4.0);
  const std::vector<double> x(size_t(spanwise_problem(p, base.mean, 1.0).n), 0.0);
  PeriodicBase fewer_sin = base, short_later = base;
  fewer_sin.sin_part.pop_back();
  short_later.cos_part[1].psi.pop_back();  // a later harmonic of the wrong size
  for (const PeriodicBase* b : {&fewer_sin, &short_later}) {
    CHECK_THROWS_AS(floquet_period_map(p, *b, 1.0, 20, x), std::invalid_argument);
    CHECK_THROWS_AS(floquet_multipliers(p, *b, 1.0), std::invalid_argument);
  }
  CHECK_THROWS_WITH(floquet_period_map(p, fewer_sin, 1.0, 20, x), Catch::Contains("differ in number"));
  CHECK_THROWS_AS(floquet_period_map(p, base, 1.0, 20, std::vector<double>(3, 0.0)), std::invalid_argument);
  CHECK(floquet_period_map(p, base, 1.0, 20, x) == x);  // the zero field stays zero
}
