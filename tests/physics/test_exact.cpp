// The physics layer alone (it links nothing else of magnus): the exact potential flow is consistent with
// itself (velocities are the derivatives of ψ, Bernoulli gives the pressure, the stagnation points are
// where the velocity vanishes), Kutta–Joukowski, and the seed estimate's π/2.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/exact.hpp"

using namespace magnus;

namespace {

/// Largest |u_r − (1/r)∂ψ/∂θ| and |u_θ + ∂ψ/∂r| on a ring of points outside the cylinder, with centred
/// differences of step h (relative to a): second order, error ∝ h².
double velocity_mismatch(const ExactFlow& f, double h) {
  double worst = 0.0;
  for (double r : {1.0, 1.3, 2.0, 5.0})
    for (int j = 0; j < 16; ++j) {
      const double rr = r * f.a, t = 2.0 * M_PI * (j + 0.37) / 16.0, dr = h * f.a;
      const double dpsi_dt = (f.psi(rr, t + h) - f.psi(rr, t - h)) / (2.0 * h);
      const double dpsi_dr = (f.psi(rr + dr, t) - f.psi(rr - dr, t)) / (2.0 * dr);
      worst = std::max(worst, std::fabs(f.u_r(rr, t) - dpsi_dt / rr));
      worst = std::max(worst, std::fabs(f.u_theta(rr, t) + dpsi_dr));
    }
  return worst;
}

}  // namespace

TEST_CASE("exact flow: u_r = (1/r)∂ψ/∂θ and u_θ = −∂ψ/∂r, observed order 2 ± 0.1", "[physics][exact][accuracy]") {
  const ExactFlow f{0.1, 10.0, 2.0 * M_PI * 0.01 * 100.0};  // a = 0.1 m, U = 10 m/s, spin Γ = 2πa²ω, ω = 100
  const double e1 = velocity_mismatch(f, 1e-2), e2 = velocity_mismatch(f, 5e-3);
  const double order = std::log2(e1 / e2);
  CHECK(order == Approx(2.0).margin(0.1));
  CHECK(e2 < 1e-3 * f.U);
}

TEST_CASE("exact flow: ψ = 0 and u_r = 0 on the surface, u → (U, 0) far away", "[physics][exact]") {
  const ExactFlow f{0.5, 3.0, 4.0};
  for (int j = 0; j < 12; ++j) {
    const double t = 2.0 * M_PI * j / 12.0;
    CHECK(f.psi(f.a, t) == Approx(0.0).margin(1e-15));
    CHECK(f.u_r(f.a, t) == Approx(0.0).margin(1e-15));
    // u_x = u_r cosθ − u_θ sinθ → U; u_y = u_r sinθ + u_θ cosθ → 0 (as 1/r).
    const double R = 1e6 * f.a;
    const double ux = f.u_r(R, t) * std::cos(t) - f.u_theta(R, t) * std::sin(t);
    const double uy = f.u_r(R, t) * std::sin(t) + f.u_theta(R, t) * std::cos(t);
    CHECK(ux == Approx(f.U).epsilon(1e-6));
    CHECK(uy == Approx(0.0).margin(1e-5));
  }
}

TEST_CASE("exact flow: Bernoulli top minus bottom, Kutta–Joukowski and C_L = −Γ/(Ua)", "[physics][exact]") {
  const double rho = 1.225;
  const ExactFlow f{0.1, 10.0, 2.0 * M_PI * 0.01 * 100.0};
  // p = p∞ + ½ρU²Cp: the pressure difference between θ = π/2 and 3π/2 on the surface.
  const double dp = 0.5 * rho * f.U * f.U * (f.cp(f.a, M_PI / 2) - f.cp(f.a, 3 * M_PI / 2));
  CHECK(dp == Approx(f.delta_p_top_bottom(rho)).epsilon(1e-13));
  CHECK(f.lift(rho) == Approx(-rho * f.U * f.Gamma).epsilon(1e-15));
  CHECK(f.cl() == Approx(f.lift(rho) / (0.5 * rho * f.U * f.U * 2.0 * f.a)).epsilon(1e-14));
}

TEST_CASE("exact flow: every stagnation point has zero velocity, sorted by θ, for α below, at and above 2",
          "[physics][exact]") {
  for (double alpha : {0.0, 0.5, -1.0, 1.999, 2.0, 3.0, -4.0}) {
    INFO("alpha " << alpha);
    const ExactFlow f{0.2, 5.0, 2.0 * M_PI * 0.2 * 5.0 * alpha};  // Γ = 2πaUα
    const auto pts = f.stagnation_points();
    REQUIRE(!pts.empty());
    const bool free_point = std::fabs(alpha) > 2.0 + 1e-12;
    CHECK(pts.size() == (free_point || std::fabs(std::fabs(alpha) - 2.0) < 1e-12 ? 1u : 2u));
    for (size_t k = 0; k < pts.size(); ++k) {
      const auto& p = pts[k];
      CHECK(p.on_surface == !free_point);
      CHECK(std::fabs(f.u_r(p.r, p.theta)) < 1e-12 * f.U);
      CHECK(std::fabs(f.u_theta(p.r, p.theta)) < 1e-9 * f.U);
      if (k > 0) CHECK(pts[k - 1].theta < p.theta);
    }
    if (free_point) CHECK(pts[0].r / f.a == Approx((std::fabs(alpha) + std::sqrt(alpha * alpha - 4.0)) / 2.0));
  }
}

TEST_CASE("the seed estimate ΔP = 2ρvrω: its lift is π/2 below Kutta–Joukowski, its ΔP half the peak", "[physics][exact]") {
  Scene s;
  for (double omega : {10.0, 100.0, -250.0}) {
    s.spin = omega;
    const ExactFlow f = exact_flow(s);
    CHECK(f.Gamma == Approx(2.0 * M_PI * s.radius * s.radius * omega));
    CHECK(f.cl() / seed_cl(s) == Approx(M_PI / 2).epsilon(1e-14));
    // The exact top-minus-bottom difference is 4ρUaω (for the spin model Γ = 2πa²ω): twice the seed's.
    CHECK(f.delta_p_top_bottom(s.density) / seed_delta_p(s) == Approx(2.0).epsilon(1e-14));
  }
}
