// The viscous model's core against exact solutions: the potential vortex of pure rotation, the decaying
// Bessel mode of the rotating cylinder (diffusion, mode 0) and an unsteady Stokes eigenmode (the wall
// closure of a mode k ≥ 1). Advection and the guards: test_ns_advection.cpp.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "solver/navier_stokes/operator.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::max_abs;
using magnus::test::observed_order;
using magnus::test::sample_state;

namespace {

/// Smallest root of f in (lo, hi) by a scan and bisection.
double first_root(const std::function<double(double)>& f, double lo, double hi, double step) {
  double x0 = lo, f0 = f(lo);
  for (double x1 = lo + step; x1 <= hi; x1 += step) {
    const double f1 = f(x1);
    if (f0 * f1 <= 0.0) {
      double a = x0, b = x1, fa = f0;
      for (int it = 0; it < 200; ++it) {
        const double c = 0.5 * (a + b), fc = f(c);
        if (fa * fc <= 0.0)
          b = c;
        else
          a = c, fa = fc;
      }
      return 0.5 * (a + b);
    }
    x0 = x1, f0 = f1;
  }
  throw std::runtime_error("no root");
}

/// Steps of op.dt() from s to t_end (t_end a whole number of steps).
void run_to(const NsOperator& op, NsState& s, double t_end) {
  NsState next;
  const long steps = std::lround((t_end - s.t) / op.dt());
  for (long q = 0; q < steps; ++q) {
    advance(op, s, next);
    std::swap(s, next);
  }
}

// ---- Pure rotation -------------------------------------------------------------------------------------

NsParams rotation_params() {
  NsParams p;
  p.a = 0.1, p.U = 0.0, p.omega = 100.0, p.nu = 1.5e-5;
  p.outer_over_a = 20.0, p.n_theta = 64, p.threads = 1;
  return p;
}

}  // namespace

TEST_CASE("[ns] pure rotation: the potential vortex stays, zeta = 0", "[ns]") {
  const NsParams p = rotation_params();
  const PolarGrid g = ns_grid(p);
  NsState s;
  s.psi.resize(g.nodes());
  s.zeta.assign(g.nodes(), 0.0);
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j) s.psi[size_t(i) * g.n_theta + j] = -p.a * p.a * p.omega * g.xi[i];
  s.Gamma_R = 2.0 * M_PI * p.a * p.a * p.omega;
  const std::vector<double> psi0 = s.psi;
  const NsOperator op(p, cfl_time_step(p, g, s.psi, 0.5));
  run_to(op, s, 50 * op.dt());
  double d = 0.0;
  for (size_t q = 0; q < psi0.size(); ++q) d = std::max(d, std::fabs(s.psi[q] - psi0[q]));
  CHECK(d < 1e-12 * max_abs(psi0));
  CHECK(max_abs(s.zeta) < 1e-9 * p.omega);
  std::vector<double> u_r, u_theta;
  ns_velocity(g, s.psi, u_r, u_theta);
  for (int i : {0, 1, g.n_r / 2, g.n_r - 1})
    CHECK(u_theta[size_t(i) * g.n_theta + 3] == Approx(p.a * p.a * p.omega / g.r[i]).epsilon(1e-12));
}

TEST_CASE("[ns] pure rotation from rest approaches the potential vortex", "[ns]") {
  NsParams p;
  p.a = 1.0, p.U = 0.0, p.omega = 1.0, p.nu = 1.0, p.outer_over_a = 2.0, p.n_theta = 16, p.n_r = 17;
  const PolarGrid g = ns_grid(p);
  NsState s = impulsive_start(p, g);
  const NsOperator op(p, 0.01);
  run_to(op, s, 0.05);
  const double zeta_early = max_abs(s.zeta);
  run_to(op, s, 8.0);
  CHECK(zeta_early > 1.0);  // the spin-up's vortex layer
  CHECK(max_abs(s.zeta) < 1e-7 * zeta_early);
  CHECK(s.Gamma_R == Approx(2.0 * M_PI * p.a * p.a * p.omega).epsilon(1e-7));
  CHECK(s.zeta[0] == Approx(0.0).margin(1e-7));  // τ_w = μ(ζ_w − 2ω) → −2μω
}

// ---- Diffusion: the rotating cylinder's decaying Bessel mode (mode 0, exact NS solution) ---------------
// u_θ = a²ω/r + C e^{−νλ²t} Z_1(λr), ζ = C λ e^{−νλ²t} Z_0(λr), Z_n(x) = J_n(x) Y_1(λa) − Y_n(x) J_1(λa);
// Z_1(λa) = 0 keeps no slip, λ is the first root of Z_0(λR) = 0 so ζ(R) = 0.

namespace {

struct BesselMode {
  double a = 1.0, omega = 1.0, nu = 1.0, R = 3.0, C = 1.0, lambda = 0.0;
  BesselMode() {
    lambda = first_root([this](double l) { return Z(0, l * R, l); }, 0.05, 20.0, 0.01);
  }
  double Z(int n, double x, double l) const {
    return std::cyl_bessel_j(n, x) * std::cyl_neumann(1, l * a) -
           std::cyl_neumann(n, x) * std::cyl_bessel_j(1, l * a);
  }
  double decay(double t) const { return std::exp(-nu * lambda * lambda * t); }
  double psi(double r, double t) const {
    return -a * a * omega * std::log(r / a) +
           C / lambda * (Z(0, lambda * r, lambda) - Z(0, lambda * a, lambda)) * decay(t);
  }
  double zeta(double r, double t) const { return C * lambda * Z(0, lambda * r, lambda) * decay(t); }
  double Gamma(double r, double t) const {
    return 2.0 * M_PI * (a * a * omega + r * C * Z(1, lambda * r, lambda) * decay(t));
  }
  NsParams params(int n_r) const {
    NsParams p;
    p.a = a, p.U = 0.0, p.omega = omega, p.nu = nu, p.outer_over_a = R / a, p.n_theta = 8, p.n_r = n_r;
    p.threads = 1;
    return p;
  }
  NsState state(const PolarGrid& g, double t) const {
    NsState s = sample_state(
        g, t, [&](double r, double) { return psi(r, t); }, [&](double r, double) { return zeta(r, t); });
    s.Gamma_R = Gamma(R, t);
    return s;
  }
};

struct BesselErrors {
  double psi = 0.0, zeta_w = 0.0;
};

BesselErrors bessel_errors(const BesselMode& b, int n_r, double dt, double t_end, NsState* out = nullptr) {
  const NsParams p = b.params(n_r);
  const PolarGrid g = ns_grid(p);
  NsState s = b.state(g, 0.0);
  const NsOperator op(p, dt);
  run_to(op, s, t_end);
  const NsState ex = b.state(g, t_end);
  BesselErrors e;
  for (size_t q = 0; q < s.psi.size(); ++q) e.psi = std::max(e.psi, std::fabs(s.psi[q] - ex.psi[q]));
  e.zeta_w = std::fabs(s.zeta[0] - ex.zeta[0]);
  if (out) *out = s;
  return e;
}

}  // namespace

TEST_CASE("[ns] diffusion: the decaying Bessel mode, second order in space (psi, wall vorticity, torque)",
          "[ns]") {
  const BesselMode b;
  const double t_end = 0.2, dt = 0.2 / 800;
  // 9, 17 rings are pre-asymptotic (orders 1.5, 1.8); from 33 rings on the orders are 1.9–2.0.
  const BesselErrors e1 = bessel_errors(b, 33, dt, t_end), e2 = bessel_errors(b, 65, dt, t_end),
                     e3 = bessel_errors(b, 129, dt, t_end);
  INFO("psi errors " << e1.psi << " " << e2.psi << " " << e3.psi << "; zeta_w errors " << e1.zeta_w << " "
                     << e2.zeta_w << " " << e3.zeta_w);
  // The torque M = 2π a² μ (ζ_w − 2ω): its error is 2πa²μ times the wall vorticity's.
  CHECK(observed_order(e2.psi, e3.psi) == Approx(2.0).margin(0.1));
  CHECK(observed_order(e2.zeta_w, e3.zeta_w) == Approx(2.0).margin(0.1));
  CHECK(e3.zeta_w < 2e-4 * std::fabs(b.zeta(b.a, t_end)));
}

TEST_CASE("[ns] diffusion: Crank-Nicolson with the implicit wall closure is second order in time", "[ns]") {
  const BesselMode b;
  NsState s1, s2, s3;
  bessel_errors(b, 33, 0.02, 0.2, &s1);
  bessel_errors(b, 33, 0.01, 0.2, &s2);
  bessel_errors(b, 33, 0.005, 0.2, &s3);
  double d12 = 0.0, d23 = 0.0;
  for (size_t q = 0; q < s1.zeta.size(); ++q) {
    d12 = std::max(d12, std::fabs(s1.zeta[q] - s2.zeta[q]));
    d23 = std::max(d23, std::fabs(s2.zeta[q] - s3.zeta[q]));
  }
  INFO("successive differences " << d12 << " " << d23);
  CHECK(observed_order(d12, d23) == Approx(2.0).margin(0.1));
}

// ---- The wall closure of a mode k ≥ 1: an unsteady Stokes eigenmode of the annulus a < r < R ------------
// ψ = e^{−νλ²t} P(r) cos kθ, P = Z_k(λr)/λ² + B r^k + C r^{−k}, ζ = e^{−νλ²t} Z_k(λr) cos kθ with
// Z_k(x) = J_k(x) Y_k(λR) − Y_k(x) J_k(λR) (ζ = 0 at R); P(a) = P'(a) = 0 (no slip), P'(R) = 0 (ψ_ξ = 0).

namespace {

struct StokesMode {
  int k = 2;
  double a = 1.0, R = 3.0, nu = 1.0, lambda = 0.0, B = 0.0, C = 0.0;
  double Z(double x, double l) const {
    return std::cyl_bessel_j(k, x) * std::cyl_neumann(k, l * R) -
           std::cyl_neumann(k, x) * std::cyl_bessel_j(k, l * R);
  }
  double dZ(double x, double l) const {  // dZ/dx
    auto dj = [this](double y) { return 0.5 * (std::cyl_bessel_j(k - 1, y) - std::cyl_bessel_j(k + 1, y)); };
    auto dy = [this](double y) { return 0.5 * (std::cyl_neumann(k - 1, y) - std::cyl_neumann(k + 1, y)); };
    return dj(x) * std::cyl_neumann(k, l * R) - dy(x) * std::cyl_bessel_j(k, l * R);
  }
  Eigen::Matrix3d M(double l) const {
    Eigen::Matrix3d m;
    m << Z(l * a, l) / (l * l), std::pow(a, k), std::pow(a, -k),             //
        dZ(l * a, l) / l, k * std::pow(a, k - 1), -k * std::pow(a, -k - 1),  //
        dZ(l * R, l) / l, k * std::pow(R, k - 1), -k * std::pow(R, -k - 1);
    return m;
  }
  StokesMode() {
    lambda = first_root([this](double l) { return M(l).determinant(); }, 0.3, 30.0, 0.01);
    const Eigen::Matrix3d m = M(lambda);
    Eigen::Matrix2d m2;
    m2 << m(0, 1), m(0, 2), m(1, 1), m(1, 2);
    const Eigen::Vector2d bc = m2.lu().solve(Eigen::Vector2d(-m(0, 0), -m(1, 0)));
    B = bc(0), C = bc(1);
  }
  double decay(double t) const { return std::exp(-nu * lambda * lambda * t); }
  double P(double r) const {
    return Z(lambda * r, lambda) / (lambda * lambda) + B * std::pow(r, k) + C * std::pow(r, -k);
  }
  double dP(double r) const {
    return dZ(lambda * r, lambda) / lambda + k * B * std::pow(r, k - 1) - k * C * std::pow(r, -k - 1);
  }
  NsParams params(int n_r, int n_theta) const {
    NsParams p;
    p.a = a, p.U = 0.0, p.omega = 0.0, p.nu = nu, p.outer_over_a = R / a, p.n_theta = n_theta, p.n_r = n_r;
    p.stokes = true;
    p.threads = 1;
    p.outer_vorticity = NsOuterVorticity::zero;
    return p;
  }
  NsState state(const PolarGrid& g, double t) const {
    const double d = decay(t);
    return sample_state(
        g, t, [&](double r, double th) { return P(r) * std::cos(k * th) * d; },
        [&](double r, double th) { return Z(lambda * r, lambda) * std::cos(k * th) * d; });
  }
};

}  // namespace

TEST_CASE("[ns] wall closure: a Stokes eigenmode k = 2, both wall conditions exact, order 2", "[ns]") {
  const StokesMode sm;
  REQUIRE(std::fabs(sm.dP(sm.R)) < 1e-10);  // the eigenmode is one
  const double t_end = 0.05;
  std::vector<double> e_psi, e_w;
  // From 17 × 32 on (9 × 16 is pre-asymptotic for ζ_w): errors fall 4× per level.
  for (int level = 1; level < 5; ++level) {
    const int n_r = 8 * (1 << level) + 1, n_theta = 16 * (1 << level);
    const NsParams p = sm.params(n_r, n_theta);
    const PolarGrid g = ns_grid(p);
    NsState s = sm.state(g, 0.0);
    const NsOperator op(p, t_end / 200);
    run_to(op, s, t_end);
    const NsState ex = sm.state(g, t_end);
    double ep = 0.0, ew = 0.0, thom = 0.0;
    const double h = op.d_xi();
    for (int j = 0; j < n_theta; ++j) {
      ew = std::max(ew, std::fabs(s.zeta[j] - ex.zeta[j]));
      CHECK(s.psi[j] == 0.0);
      thom = std::max(thom, std::fabs(s.psi[size_t(n_theta) + j] + 0.5 * sm.a * sm.a * h * h * s.zeta[j]));
    }
    for (size_t q = 0; q < s.psi.size(); ++q) ep = std::max(ep, std::fabs(s.psi[q] - ex.psi[q]));
    CHECK(thom < 1e-13 * max_abs(s.psi));  // Thom's wall row (ψ_ξ = 0) holds to round-off
    e_psi.push_back(ep), e_w.push_back(ew);
  }
  INFO("lambda " << sm.lambda << "; psi errors " << e_psi[0] << " " << e_psi[1] << " " << e_psi[2] << " "
                 << e_psi[3] << "; zeta_w errors " << e_w[0] << " " << e_w[1] << " " << e_w[2] << " "
                 << e_w[3]);
  CHECK(observed_order(e_psi[2], e_psi[3]) == Approx(2.0).margin(0.1));
  CHECK(observed_order(e_w[2], e_w[3]) == Approx(2.0).margin(0.1));
}
