// The viscous model's advection and guards: Arakawa's conservation and order, the fourth-order-in-θ form,
// the CFL guard, and two threads stepping exactly as one.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <utility>

#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/stages.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::max_abs;
using magnus::test::observed_order;

// ---- Arakawa's Jacobian and the guards ----------------------------------------------------------------

namespace {

/// The advection stage N of op's grid and orders on the whole field (advection_field); rate (optional): the
/// CFL rate, 1/s.
std::vector<double> advection(const NsOperator& op, const std::vector<double>& psi,
                              const std::vector<double>& zeta, double* rate = nullptr) {
  std::vector<double> N(psi.size());
  advection_field(op.grid(), op.params(), psi.data(), zeta.data(), N.data(), rate);
  return N;
}

/// Random ψ and ζ in (−1, 1), zero on the `edge` outer rings each side (no boundary flux: 2 rings for the
/// ξ-stride 1; 4 for order 4 in ξ, whose stride-2 Jacobian on rings 1 and n_r − 2, where the scheme falls
/// back to stride 1, must vanish as well); checks that the advection N of op conserves vorticity,
/// energy and enstrophy: Σ h_i N, Σ h_i ψN, Σ h_i ζN vanish to round-off (h_i = ring_width(i), the mode
/// solver's control widths; constant on a uniform ξ). Returns the fields (psi, zeta) it used.
std::pair<std::vector<double>, std::vector<double>> check_advection_conserves(const NsOperator& op,
                                                                              unsigned seed, int edge = 2) {
  const PolarGrid& g = op.grid();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> psi(g.nodes(), 0.0), zeta(g.nodes(), 0.0);
  for (int i = edge; i < g.n_r - edge; ++i)
    for (int j = 0; j < g.n_theta; ++j)
      psi[size_t(i) * g.n_theta + j] = d(rng), zeta[size_t(i) * g.n_theta + j] = d(rng);
  const std::vector<double> N = advection(op, psi, zeta);
  double s1 = 0.0, s_psi = 0.0, s_zeta = 0.0, scale = 0.0;
  for (size_t q = 0; q < N.size(); ++q) {
    const int i = int(q / size_t(g.n_theta));
    const double w = i > 0 && i < g.n_r - 1 ? g.ring_width(i) : 0.0;  // N = 0 on rings 0 and n_r − 1
    s1 += w * N[q], s_psi += w * psi[q] * N[q], s_zeta += w * zeta[q] * N[q], scale += w * std::fabs(N[q]);
  }
  CHECK(std::fabs(s1) < 1e-12 * scale);
  CHECK(std::fabs(s_psi) < 1e-12 * scale);
  CHECK(std::fabs(s_zeta) < 1e-12 * scale);
  return {psi, zeta};
}

using Field = std::function<double(double, double)>;

/// max over rings edge … n_r−1−edge of |N − exact| for ψ = psi(ξ, θ), ζ = zeta(ξ, θ) sampled on op's grid,
/// with exact(ξ, θ) = ψ_θ ζ_ξ − ψ_ξ ζ_θ (m²/s², for ψ in m²/s and ζ in 1/s).
double advection_error(const NsOperator& op, const Field& psi, const Field& zeta, const Field& exact,
                       int edge = 1) {
  const PolarGrid& g = op.grid();
  const int n = g.n_theta;
  std::vector<double> ps(g.nodes()), ze(g.nodes());
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < n; ++j)
      ps[size_t(i) * n + j] = psi(g.xi[i], g.theta[j]), ze[size_t(i) * n + j] = zeta(g.xi[i], g.theta[j]);
  const std::vector<double> N = advection(op, ps, ze);
  double e = 0.0;
  for (int i = edge; i < g.n_r - edge; ++i)
    for (int j = 0; j < n; ++j) e = std::max(e, std::fabs(N[size_t(i) * n + j] - exact(g.xi[i], g.theta[j])));
  return e;
}

/// advection_error of ψ = sin ξ cos 2θ, ζ = cos 1.5ξ sin θ (smooth fields of both directions).
double smooth_advection_error(const NsOperator& op) {
  return advection_error(
      op, [](double x, double t) { return std::sin(x) * std::cos(2 * t); },
      [](double x, double t) { return std::cos(1.5 * x) * std::sin(t); },
      [](double x, double t) {
        return -2.0 * std::sin(x) * std::sin(2 * t) * (-1.5 * std::sin(1.5 * x) * std::sin(t)) -
               std::cos(x) * std::cos(2 * t) * std::cos(1.5 * x) * std::cos(t);
      });
}

}  // namespace

TEST_CASE("[ns] Arakawa's Jacobian conserves vorticity, energy and enstrophy, it is second order", "[ns]") {
  NsParams p;
  p.a = 1.0, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 10.0, p.n_theta = 32, p.threads = 1;
  check_advection_conserves(NsOperator(p, 0.01), 7);
  // Smooth fields: N → ψ_θ ζ_ξ − ψ_ξ ζ_θ at second order.
  std::vector<double> err;
  for (int n : {32, 64}) {
    p.n_theta = n;
    err.push_back(smooth_advection_error(NsOperator(p, 0.01)));
  }
  CHECK(observed_order(err[0], err[1]) == Approx(2.0).margin(0.1));
}

TEST_CASE("[ns] Arakawa's Jacobian on rings clustered at the wall conserves with the ring widths h_i",
          "[ns]") {
  // On a stretched ξ the stencil is Arakawa's in the ring index s over 12Δθh_i: Σ h_i N, Σ h_i ψN and
  // Σ h_i ζN vanish; with the widths of a uniform grid instead (dropping h_i) they would not.
  NsParams p;
  p.a = 1.0, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 10.0, p.n_theta = 32, p.threads = 1;
  p.wall_refinement = 4.0, p.wall_layer = 0.5;
  for (const auto& [order, order_xi] : {std::pair{2, 2}, std::pair{4, 2}, std::pair{2, 4}, std::pair{4, 4}}) {
    p.advection_order = order, p.advection_order_xi = order_xi;
    const NsOperator op(p, 0.01);
    REQUIRE(!op.grid().uniform_in_xi());
    INFO("advection order " << order << ", in xi " << order_xi);
    check_advection_conserves(op, 5, order_xi == 4 ? 4 : 2);
  }
  // Smooth fields: N → ψ_θ ζ_ξ − ψ_ξ ζ_θ at second order on the stretched rings too (n_θ and n_r doubled).
  std::vector<double> err;
  p.advection_order = 2, p.advection_order_xi = 2;
  for (int n : {32, 64, 128}) {
    p.n_theta = n;
    err.push_back(smooth_advection_error(NsOperator(p, 0.01)));
  }
  INFO("errors " << err[0] << " " << err[1] << " " << err[2]);
  CHECK(observed_order(err[1], err[2]) == Approx(2.0).margin(0.1));
}

TEST_CASE("[ns] advection of order 4 in theta: it conserves as Arakawa's does, fourth order in theta",
          "[ns]") {
  // Fields linear in ξ: every ξ-difference of the three forms (of products at most quadratic in ξ) is
  // exact, so what is left is the θ error alone; n_r stays fixed while n_θ doubles.
  auto theta_errors = [](int order) {
    std::vector<double> err;
    for (int n : {32, 64, 128}) {
      NsParams p;
      p.a = 1.0, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 10.0, p.n_theta = n, p.n_r = 12, p.threads = 1;
      p.advection_order = order;
      err.push_back(advection_error(
          NsOperator(p, 0.01), [](double x, double t) { return x * std::cos(2 * t) + std::sin(t); },
          [](double x, double t) { return (1.0 - x) * std::sin(3 * t) + x * std::cos(t); },
          [](double x, double t) {
            const double p_t = -2.0 * x * std::sin(2 * t) + std::cos(t), p_x = std::cos(2 * t);
            const double z_t = 3.0 * (1.0 - x) * std::cos(3 * t) - x * std::sin(t),
                         z_x = -std::sin(3 * t) + std::cos(t);
            return p_t * z_x - p_x * z_t;
          }));
    }
    return err;
  };
  const std::vector<double> e2 = theta_errors(2), e4 = theta_errors(4);
  INFO("order 2: " << e2[0] << " " << e2[1] << " " << e2[2] << "; order 4: " << e4[0] << " " << e4[1] << " "
                   << e4[2]);
  CHECK(observed_order(e2[1], e2[2]) == Approx(2.0).margin(0.1));
  CHECK(observed_order(e4[1], e4[2]) == Approx(4.0).margin(0.1));
  CHECK(e4[2] < 1e-2 * e2[2]);  // measured 6.6e-3 at n_θ = 128

  // Random fields: order 4 conserves what Arakawa's Jacobian conserves.
  NsParams p;
  p.a = 1.0, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 10.0, p.n_theta = 32, p.threads = 1;
  p.advection_order = 4;
  const NsOperator op(p, 0.01);
  const auto [psi, zeta] = check_advection_conserves(op, 11);
  double rate = 0.0;
  advection(op, psi, zeta, &rate);
  // The CFL rate's θ part carries the fourth-order difference's largest wavenumber, 1.3722/Δθ.
  double rate2 = 0.0;
  p.advection_order = 2;
  const NsOperator op2(p, 0.01);
  advection(op2, psi, zeta, &rate2);
  CHECK(rate > rate2);
  CHECK(rate < 1.3723 * rate2);
}

TEST_CASE("[ns] advection of order 4 in xi: it conserves, fourth order in xi, and in both directions",
          "[ns]") {
  // Smooth fields of θ-wavenumber 1 on n_θ = 512 with order 4 in θ: the θ error (about 5e-8) stays far
  // below the ξ error while the rings double. Rings 1 and n_r − 2 fall back to second order in ξ (they have
  // no rings i ± 2), so the error is taken on rings 2 … n_r − 3.
  auto errors = [](int order_xi, bool refine_theta) {
    std::vector<double> err;
    for (int level = 0; level < 3; ++level) {
      NsParams p;
      p.a = 1.0, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 10.0, p.threads = 1;
      p.n_r = 24 << level, p.n_theta = refine_theta ? 32 << level : 512;
      p.advection_order = 4, p.advection_order_xi = order_xi;
      err.push_back(advection_error(
          NsOperator(p, 0.01), [](double x, double t) { return std::sin(2 * x) * std::cos(t) + std::cos(x); },
          [](double x, double t) { return std::cos(3 * x) * std::sin(t) + std::sin(x) * std::cos(t); },
          [](double x, double t) {
            const double p_t = -std::sin(2 * x) * std::sin(t),
                         p_x = 2.0 * std::cos(2 * x) * std::cos(t) - std::sin(x);
            const double z_t = std::cos(3 * x) * std::cos(t) - std::sin(x) * std::sin(t),
                         z_x = -3.0 * std::sin(3 * x) * std::sin(t) + std::cos(x) * std::cos(t);
            return p_t * z_x - p_x * z_t;
          },
          2));
    }
    return err;
  };
  const std::vector<double> e2 = errors(2, false), e4 = errors(4, false), both = errors(4, true);
  INFO("xi order 2: " << e2[0] << " " << e2[1] << " " << e2[2] << "; xi order 4: " << e4[0] << " " << e4[1]
                      << " " << e4[2] << "; both refined: " << both[0] << " " << both[1] << " " << both[2]);
  CHECK(observed_order(e2[1], e2[2]) == Approx(2.0).margin(0.1));
  CHECK(observed_order(e4[1], e4[2]) == Approx(4.0).margin(0.1));
  CHECK(observed_order(both[1], both[2]) == Approx(4.0).margin(0.1));
  CHECK(e4[2] < 1e-2 * e2[2]);

  // Random fields: order 4 in ξ (alone and with order 4 in θ) conserves what Arakawa's Jacobian conserves;
  // the CFL rate's ξ part carries the largest wavenumber 1.3722/Δξ.
  NsParams p;
  p.a = 1.0, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 10.0, p.n_theta = 32, p.threads = 1;
  double rate2 = 0.0;
  std::pair<std::vector<double>, std::vector<double>> f;
  {
    const NsOperator op2(p, 0.01);
    f = check_advection_conserves(op2, 13, 4);
    advection(op2, f.first, f.second, &rate2);
  }
  for (int order_theta : {2, 4}) {
    p.advection_order = order_theta, p.advection_order_xi = 4;
    const NsOperator op(p, 0.01);
    check_advection_conserves(op, 17, 4);
    double rate = 0.0;
    advection(op, f.first, f.second, &rate);
    CHECK(rate > rate2);
    CHECK(rate < 1.3723 * rate2);
  }
}

TEST_CASE("[ns] a time step above the CFL limit is refused with the time and the cause", "[ns]") {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 0.01, p.outer_over_a = 20.0, p.n_theta = 32, p.threads = 1;
  const PolarGrid g = ns_grid(p);
  const NsState s = impulsive_start(p, g);
  const double dt_ok = cfl_time_step(p, g, s.psi, 0.5);
  CHECK(cfl_number(g, s.psi, dt_ok) <= 0.5 + 1e-12);
  const NsOperator too_big(p, 4.0 * dt_ok / 0.5);
  NsState next;
  try {
    advance(too_big, s, next);
    FAIL("advance accepted CFL 4");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK(what.find("t = 0 s") != std::string::npos);
    CHECK(what.find("stability limit") != std::string::npos);
  }
  NsState bad = s;
  bad.zeta[5 * g.n_theta + 3] = std::nan("");
  const NsOperator op(p, dt_ok);
  CHECK_THROWS_WITH(advance(op, bad, next), Catch::Contains("non-finite") && Catch::Contains("t = "));
}

TEST_CASE("[ns] two threads step exactly as one (the pool splits rings and modes, not the arithmetic)",
          "[ns]") {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.omega = 1.0, p.nu = 0.01, p.outer_over_a = 20.0, p.n_theta = 64;
  const PolarGrid g = ns_grid(p);
  NsState s1 = impulsive_start(p, g), s2 = s1;
  const double dt = cfl_time_step(p, g, s1.psi, 0.5);
  NsParams p2 = p;
  p2.threads = 2;
  const NsOperator o1(p, dt), o2(p2, dt);
  NsStepTimes times;
  NsState n1, n2;
  for (int q = 0; q < 30; ++q) {
    advance(o1, s1, n1);
    advance(o2, s2, n2, &times);
    std::swap(s1, n1);
    std::swap(s2, n2);
  }
  double d = 0.0;
  for (size_t q = 0; q < s1.zeta.size(); ++q) d = std::max(d, std::fabs(s1.zeta[q] - s2.zeta[q]));
  CHECK(d <= 1e-12 * max_abs(s1.zeta));
  CHECK(s1.Gamma_R == Approx(s2.Gamma_R).margin(1e-12 * p.U * p.a * p.outer_over_a));
  CHECK(times.steps == 30);
  CHECK(times.total() > 0.0);
}
