// The pressure field of a navier-stokes state (postproc/navier_stokes/pressure.hpp): exact flows with observed order 2
// (the potential vortex of pure rotation, potential flow with circulation, Kovasznay's flow), and
// a real state whose wall values agree with the wall formula ∂p/∂θ|_a = μ ∂ζ/∂ξ|_0 of viscous_surface.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "postproc/navier_stokes/pressure.hpp"
#include "postproc/navier_stokes/unsteady.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::observed_order;
using magnus::test::sample_state;

namespace {

/// The scene of the exact-flow tests: a = 0.5 m, R/a = e^{π/2}, n_r = n_θ/4 + 1 (square cells Δξ = Δθ,
/// the same domain on every grid), ν = 0.01 m²/s.
NsParams exact_params(int n_theta, double U, double omega) {
  NsParams p;
  p.a = 0.5, p.U = U, p.omega = omega, p.nu = 0.01;
  p.outer_over_a = std::exp(M_PI / 2), p.n_theta = n_theta, p.n_r = n_theta / 4 + 1;
  return p;
}

/// max_ij |p_ij − exact(r_i, θ_j, ξ_i)|, Pa.
double max_error(const PolarGrid& g, const std::vector<double>& p,
                 const std::function<double(double, double, double)>& exact) {
  double e = 0.0;
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j)
      e = std::max(e, std::fabs(p[size_t(i) * g.n_theta + j] - exact(g.r[i], g.theta[j], g.xi[i])));
  return e;
}

/// Errors on three grids (n_θ doubling) and the two observed orders, checked to be 2 ± 0.15.
void check_order_two(const std::vector<double>& e, const char* what) {
  const double p1 = observed_order(e[0], e[1]), p2 = observed_order(e[1], e[2]);
  WARN(what << ": errors " << e[0] << " " << e[1] << " " << e[2] << ", observed orders " << p1 << " " << p2);
  CHECK(p1 == Approx(2.0).margin(0.15));
  CHECK(p2 == Approx(2.0).margin(0.15));
}

constexpr double kRho = 1.2, kPinf = 101325.0;

}  // namespace

TEST_CASE("[ns] pressure field: pure rotation, potential vortex p = p_inf - rho a^4 omega^2/(2 r^2), order 2",
          "[ns]") {
  std::vector<double> e;
  for (int n : {64, 128, 256}) {
    const NsParams p = exact_params(n, 0.0, 3.0);
    const PolarGrid g = ns_grid(p);
    const double a = p.a, w = p.omega, scale = kRho * a * a * w * w;
    NsState s = sample_state(
        g, 0.0, [&](double r, double) { return -a * a * w * std::log(r / a); },
        [](double, double) { return 0.0; });
    s.Gamma_R = 2.0 * M_PI * a * a * w;
    const std::vector<double> pr = ns_pressure_field(g, p, kRho, kPinf, s);
    e.push_back(max_error(g, pr,
                          [&](double r, double, double) {
                            return kPinf - kRho * std::pow(a, 4) * w * w / (2.0 * r * r);
                          }) /
                scale);
  }
  CHECK(e[2] < 2e-3);
  check_order_two(e, "potential vortex");
}

TEST_CASE("[ns] pressure field: potential flow with circulation is Bernoulli's p, order 2", "[ns]") {
  // ζ = 0, ψ = U(r − a²/r) sinθ − (Γ/2π) ln(r/a): u_r = 0 on the wall but u_θ(a) = −2U sinθ + Γ/(2πa) (no
  // no-slip): the wall condition ρu_θ(a)²/a is Bernoulli's, the outer head stays p∞ + ½ρU² (ζ = 0).
  std::vector<double> e;
  for (int n : {128, 256, 512}) {
    const NsParams p = exact_params(n, 2.0, 3.0);
    const PolarGrid g = ns_grid(p);
    const double a = p.a, U = p.U, Gamma = 2.0 * M_PI * a * a * p.omega;
    const NsState s = sample_state(
        g, 0.0,
        [&](double r, double th) {
          return U * (r - a * a / r) * std::sin(th) - Gamma / (2.0 * M_PI) * std::log(r / a);
        },
        [](double, double) { return 0.0; });
    const std::vector<double> pr = ns_pressure_field(g, p, kRho, kPinf, s);
    e.push_back(max_error(g, pr,
                          [&](double r, double th, double) {
                            const double ur = U * (1.0 - a * a / (r * r)) * std::cos(th);
                            const double ut =
                                -U * (1.0 + a * a / (r * r)) * std::sin(th) + Gamma / (2.0 * M_PI * r);
                            return kPinf + 0.5 * kRho * (U * U - ur * ur - ut * ut);
                          }) /
                (kRho * U * U));
  }
  CHECK(e[2] < 5e-3);
  check_order_two(e, "potential flow with circulation");
}

TEST_CASE("[ns] pressure field: Kovasznay's exact Navier-Stokes flow, order 2", "[ns]") {
  // The steady Navier–Stokes solution of Kovasznay (1948), Re_L = UL/ν = 20, λ = Re_L/2 − √(Re_L²/4 + 4π²):
  //   ψ = UL(y/L − e^{λx/L} sin(2πy/L)/2π),  ζ = (U/L)(λ² − 4π²)/(2π) e^{λx/L} sin(2πy/L),
  //   p = ½ρU²(1 − e^{2λx/L}) + c,
  // vortical everywhere (the outer ring crosses vorticity, so the head integral works) and with u_r ≠ 0 on
  // r = a (the general steady wall condition): every part of the field is exercised. c puts the head
  // H = p + ½ρ|u|² at p∞ + ½ρU² at (−R, 0), as the field does.
  const double U = 1.0, L = 4.0, Re = 20.0;
  const double lam = Re / 2.0 - std::sqrt(Re * Re / 4.0 + 4.0 * M_PI * M_PI);
  std::vector<double> e;
  for (int n : {32, 64, 128}) {
    NsParams p = exact_params(n, U, 0.0);
    p.nu = U * L / Re;
    const PolarGrid g = ns_grid(p);
    const double R = g.outer_radius();
    const auto ex = [&](double r, double th) { return std::exp(lam * r * std::cos(th) / L); };
    const NsState s = sample_state(
        g, 0.0,
        [&](double r, double th) {
          return U * L *
                 (r * std::sin(th) / L - ex(r, th) * std::sin(2 * M_PI * r * std::sin(th) / L) / (2 * M_PI));
        },
        [&](double r, double th) {
          return U / L * (lam * lam - 4 * M_PI * M_PI) / (2 * M_PI) * ex(r, th) *
                 std::sin(2 * M_PI * r * std::sin(th) / L);
        });
    const double u_up = U * (1.0 - std::exp(-lam * R / L));  // (u, v) = (u_up, 0) at (−R, 0)
    const double H_up = 0.5 * kRho * U * U * (1.0 - std::exp(-2.0 * lam * R / L)) + 0.5 * kRho * u_up * u_up;
    const double c = kPinf + 0.5 * kRho * U * U - H_up;
    const std::vector<double> pr = ns_pressure_field(g, p, kRho, kPinf, s);
    e.push_back(max_error(g, pr,
                          [&](double r, double th, double) {
                            return 0.5 * kRho * U * U * (1.0 - ex(r, th) * ex(r, th)) + c;
                          }) /
                (kRho * U * U));
  }
  CHECK(e[2] < 0.05);
  check_order_two(e, "Kovasznay flow");
}

TEST_CASE("[ns] pressure field: a real state's wall values match the wall formula dp/dtheta = mu zeta_xi",
          "[ns]") {
  // Re 40, α = 0.5, impulsive start, 4 convective times on n_θ = 64, 128 and 256 (R = 8a): the field's
  // wall values (mean removed) against viscous_surface's θ-integral of μζ_ξ, two discretisations of the
  // same state; the gap shrinks at the scheme's order (measured 1.91, 1.80, 1.90 from n_θ = 32 to 256; the
  // field's wall slope is three-ring, the surface's five-ring, so the gap is not monotone in its order).
  std::vector<double> gap;
  for (int n : {64, 128, 256}) {
    NsParams p;
    p.a = 0.5, p.U = 1.0, p.nu = p.U * 2.0 * p.a / 40.0, p.omega = 0.5 * p.U / p.a;
    p.outer_over_a = 8.0, p.n_theta = n, p.threads = 1;
    UnsteadyOptions o;
    o.t_end = 4.0, o.rho = kRho;
    const PolarGrid g = ns_grid(p);
    const UnsteadyResult res = run_unsteady(p, o, impulsive_start(p, g));
    REQUIRE(res.ok);
    const std::vector<double> pr = ns_pressure_field(g, p, kRho, kPinf, res.state);
    for (double v : pr) REQUIRE(std::isfinite(v));
    const ViscousSurface surf = viscous_surface(g, p, kRho, res.state);
    double mean = 0.0;
    for (int j = 0; j < n; ++j) mean += pr[j] / n;
    double d = 0.0, size = 0.0;
    for (int j = 0; j < n; ++j) {
      d = std::max(d, std::fabs(pr[j] - mean - surf.pressure[j]));
      size = std::max(size, std::fabs(surf.pressure[j]));
    }
    const double q = 0.5 * kRho * p.U * p.U;
    WARN("n_theta " << n << ": wall pressure gap " << d / q << " of ½ρU² (max |p − p̄| " << size / q << ")");
    CHECK(d < (n == 64 ? 0.08 : n == 128 ? 0.03 : 0.008) * size);
    gap.push_back(d / q);
  }
  const double order = observed_order(gap[1], gap[2]);
  WARN("observed order of the wall pressure gap " << order);
  CHECK(order == Approx(2.0).margin(0.2));
}

TEST_CASE("[ns] pressure field: bad input throws std::invalid_argument", "[ns]") {
  const NsParams p = exact_params(32, 1.0, 0.0);
  const PolarGrid g = ns_grid(p);
  NsState s;
  s.psi.assign(g.nodes(), 0.0), s.zeta.assign(g.nodes() - 1, 0.0);
  CHECK_THROWS_AS(ns_pressure_field(g, p, kRho, kPinf, s), std::invalid_argument);
  s.zeta.assign(g.nodes(), 0.0);
  s.psi[5] = std::nan("");
  CHECK_THROWS_AS(ns_pressure_field(g, p, kRho, kPinf, s), std::invalid_argument);
  s.psi[5] = 0.0;
  CHECK_THROWS_AS(ns_pressure_field(g, p, 0.0, kPinf, s), std::invalid_argument);
  CHECK(ns_pressure_field(g, p, kRho, kPinf, s).size() == size_t(g.nodes()));
}
