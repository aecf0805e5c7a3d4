// Steady states by Newton's method on the time stepper's discrete equations: the analytic Jacobian against
// finite differences, quadratic convergence, and the fixed point of advance() it must be (the time
// stepper's own steady state, reached by marching, to 1e-8).
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "postproc/navier_stokes/forces.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::max_abs;

namespace {

/// D = 1 m, U = 1 m/s: ν = 1/Re, ω = 2α.
NsParams newton_params(double Re, double alpha, int n_theta, double R_over_a) {
  return test::cylinder_flow(Re, alpha, n_theta, R_over_a);
}

double rel_diff(const std::vector<double>& u, const std::vector<double>& v) {
  double d = 0.0;
  for (size_t q = 0; q < u.size(); ++q) d = std::max(d, std::fabs(u[q] - v[q]));
  return d / max_abs(v);
}

/// Time steps from rest until ζ changes by less than tol·max|ζ| per unit time (or max_steps).
NsState march_to_steady(const NsParams& p, double tol, long max_steps, long* steps_out) {
  const PolarGrid g = ns_grid(p);
  NsState s = impulsive_start(p, g), next;
  const NsOperator op(p, cfl_time_step(p, g, s.psi, p.cfl));
  long q = 0;
  for (; q < max_steps; ++q) {
    advance(op, s, next);
    if (q % 50 == 49) {
      const double change = rel_diff(next.zeta, s.zeta) / op.dt();
      if (change < tol) {
        std::swap(s, next);
        ++q;
        break;
      }
    }
    std::swap(s, next);
  }
  if (steps_out) *steps_out = q;
  return s;
}

/// The last Newton steps converge quadratically: once r_k < 1e-2, r_{k+1} ≤ C·r_k² (or hits round-off).
void check_quadratic(const std::vector<double>& r, double C, double floor) {
  int checked = 0;
  for (size_t k = 0; k + 1 < r.size(); ++k) {
    if (r[k] > 1e-2 || r[k + 1] < floor) continue;
    INFO("r_" << k << " = " << r[k] << ", r_" << k + 1 << " = " << r[k + 1]);
    CHECK(r[k + 1] <= C * r[k] * r[k]);
    ++checked;
  }
  CHECK(checked >= 1);
}

std::string residual_list(const std::vector<double>& r) {
  std::string s;
  char buf[32];
  for (double x : r) std::snprintf(buf, sizeof buf, " %.3e", x), s += buf;
  return s;
}

}  // namespace

TEST_CASE("[ns][newton] the analytic Jacobian is the derivative of the residual", "[ns][newton]") {
  struct Variant {
    bool stokes;
    int order, order_xi;
    double wall_refinement;  ///< > 1: rings clustered at the wall (the flux form, nonuniform outer ring)
    NsWallClosure closure = NsWallClosure::thom;
    double absorbing_start = 0.0;  ///< > 0: an absorbing layer from r/a = 3 (λ_R = 2 U/D)
  };
  const NsWallClosure jensen = NsWallClosure::jensen, thom = NsWallClosure::thom;
  for (const auto& [stokes, order, order_xi, refinement, closure, layer] :
       {Variant{false, 2, 2, 1.0}, Variant{true, 2, 2, 1.0}, Variant{false, 4, 2, 1.0},
        Variant{false, 2, 4, 1.0}, Variant{false, 4, 4, 1.0}, Variant{false, 2, 2, 4.0},
        Variant{false, 4, 4, 4.0}, Variant{false, 2, 2, 1.0, jensen}, Variant{false, 2, 2, 4.0, jensen},
        Variant{false, 2, 2, 1.0, thom, 3.0}, Variant{false, 4, 2, 4.0, jensen, 3.0}}) {
    NsParams p = newton_params(30.0, 0.7, 16, 6.0);
    p.absorbing_start = layer, p.absorbing_rate = 2.0 * p.U / (2.0 * p.a);
    p.stokes = stokes;
    p.wall_closure = closure;
    p.advection_order = order, p.advection_order_xi = order_xi;
    p.wall_refinement = refinement, p.wall_layer = 0.5;
    SteadyJacobian jac(p);
    const PolarGrid& g = jac.grid();
    NsState s = potential_guess(p, g);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    for (size_t q = 0; q < s.zeta.size(); ++q) s.zeta[q] = d(rng), s.psi[q] += 0.1 * d(rng);
    s.Gamma_R = 0.3;
    const std::vector<double> x = jac.pack(s);
    jac.factor(x);
    std::vector<double> v(x.size());
    for (double& c : v) c = d(rng);
    const std::vector<double> Jv = jac.multiply(v);
    const double eps = 1e-6;
    std::vector<double> xp = x, xm = x;
    for (size_t q = 0; q < x.size(); ++q) xp[q] += eps * v[q], xm[q] -= eps * v[q];
    const std::vector<double> Fp = jac.residual(xp), Fm = jac.residual(xm);
    double err = 0.0;
    for (size_t q = 0; q < x.size(); ++q)
      err = std::max(err, std::fabs((Fp[q] - Fm[q]) / (2.0 * eps) - Jv[q]));
    INFO("stokes " << stokes << ", advection order " << order << ", in xi " << order_xi << ", wall refinement "
                   << refinement << ", Jensen's wall " << (closure == jensen) << ", layer " << layer << ": |J v − FD| = " << err << ", |J v| = " << max_abs(Jv));
    CHECK(err < 1e-7 * max_abs(Jv));
    // The factors solve the system they were made from (and its transpose).
    const std::vector<double> y = jac.solve(Jv);
    CHECK(rel_diff(y, v) < 1e-9);
  }
}

namespace {

/// Newton from the potential flow, then the time stepper from rest until it is steady: the same state.
void check_newton_is_the_steppers_steady_state(double Re, double alpha, int n_theta, int order = 2,
                                               int order_xi = 2, double wall_refinement = 1.0,
                                               NsWallClosure closure = NsWallClosure::thom,
                                               long max_steps = 30000, double absorbing_start = 0.0) {
  NsParams p = newton_params(Re, alpha, n_theta, 20.0);
  p.absorbing_start = absorbing_start, p.absorbing_rate = 2.0 * p.U / (2.0 * p.a);  // λ_R = 2 U/D
  p.wall_closure = closure;
  p.advection_order = order, p.advection_order_xi = order_xi;
  p.wall_refinement = wall_refinement, p.wall_layer = 0.5;
  const PolarGrid g = ns_grid(p);
  NewtonOptions o;
  o.tol = 1e-11;
  std::vector<std::pair<int, double>> log;
  o.on_iteration = [&log](int k, double r) { log.emplace_back(k, r); };
  const auto t0 = std::chrono::steady_clock::now();
  const NewtonResult nr = solve_steady(p, potential_guess(p, g), o);
  const double t_newton = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO("Re " << Re << ", alpha " << alpha << ", advection order " << order << ", in xi " << order_xi
             << ", wall refinement " << wall_refinement << ", Jensen's wall " << (closure == NsWallClosure::jensen)
             << ", absorbing layer from r/a = " << absorbing_start << ": "
             << nr.message << "; residuals" << residual_list(nr.residuals));
  REQUIRE(nr.converged);
  REQUIRE(log.size() == nr.residuals.size());
  CHECK(log.back().first == nr.iterations);
  CHECK(log.back().second == nr.residuals.back());
  // Quadratic: r_{k+1} ≤ 10·r_k² once r_k < 1e-2 (measured ratios 0.4–1.2), until round-off (1e-13).
  check_quadratic(nr.residuals, 10.0, 1e-13);
  CHECK(nr.iterations <= 6);
  CHECK(nr.factorisations == nr.iterations);
  CHECK(nr.chord_steps == 0);

  // A fixed point of advance(): 20 steps from Newton's state leave it in place (to round-off).
  {
    const NsOperator op(p, cfl_time_step(p, g, nr.state.psi, p.cfl));
    NsState s = nr.state, next;
    for (int q = 0; q < 20; ++q) advance(op, s, next), std::swap(s, next);
    CHECK(rel_diff(s.psi, nr.state.psi) < 1e-12);
    CHECK(rel_diff(s.zeta, nr.state.zeta) < 1e-12);
    CHECK(std::fabs(s.Gamma_R - nr.state.Gamma_R) < 1e-12 * p.U * p.a);
  }

  // From rest: the slowest mode decays ~e^{−0.03 t}; the distance to the steady state is ~30–40 times the
  // change per unit time, so stopping at 5e-12 leaves ~2e-10
  // (Γ_R, the slowest, ~2e-9 relative).
  long steps = 0;
  const auto t1 = std::chrono::steady_clock::now();
  const NsState marched = march_to_steady(p, 5e-12, max_steps, &steps);
  const double t_march = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  const double d_psi = rel_diff(nr.state.psi, marched.psi), d_zeta = rel_diff(nr.state.zeta, marched.zeta);
  std::printf(
      "newton Re %g alpha %g (%d x %d): %d Newton steps %.3f s; marching %ld steps %.3f s; "
      "|dpsi| %.2e |dzeta| %.2e; Gamma_R %.12g vs %.12g\n",
      Re, alpha, g.n_r, g.n_theta, nr.iterations, t_newton, steps, t_march, d_psi, d_zeta, nr.state.Gamma_R,
      marched.Gamma_R);
  CHECK(steps < max_steps);
  CHECK(d_psi < 1e-8);
  CHECK(d_zeta < 1e-8);
  CHECK(std::fabs(nr.state.Gamma_R - marched.Gamma_R) <
        1e-8 * std::max(std::fabs(marched.Gamma_R), p.U * p.a));

  // Chord steps (old factors while they contract by 3x a step): the same state, fewer factorisations.
  o.chord_ratio = 0.3;
  o.on_iteration = nullptr;
  const NewtonResult chord = solve_steady(p, potential_guess(p, g), o);
  INFO("chord: " << chord.message << "; residuals" << residual_list(chord.residuals));
  REQUIRE(chord.converged);
  CHECK(chord.chord_steps > 0);
  CHECK(chord.factorisations < nr.factorisations);
  CHECK(chord.factorisations + chord.chord_steps == chord.iterations);
  CHECK(rel_diff(chord.state.psi, nr.state.psi) < 1e-10);
  CHECK(rel_diff(chord.state.zeta, nr.state.zeta) < 1e-10);
}

}  // namespace

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: Re 20, alpha 0", "[ns][newton]") {
  check_newton_is_the_steppers_steady_state(20.0, 0.0, 32);
}

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: Re 10, alpha 0.5", "[ns][newton]") {
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32);
}

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: advection of order 4, Re 10, alpha 0.5",
          "[ns][newton]") {
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 4);
}

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: rings clustered at the wall, Re 10, "
          "alpha 0.5",
          "[ns][newton]") {
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 2, 2, 4.0);
}

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: Jensen's wall closure, Re 10, alpha 0.5",
          "[ns][newton]") {
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 2, 2, 1.0, NsWallClosure::jensen);
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 2, 2, 4.0, NsWallClosure::jensen);
}

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: the spin implicit, Re 10, alpha 2",
          "[ns][newton]") {
  // The march takes J(ψ_ref, ζ) by Crank–Nicolson and J(ψ', ζ) by AB2 (rotation.hpp): at a steady state
  // they sum to Newton's full Jacobian again; also on rings clustered at the wall with order 4 in θ.
  // The circulation at R settles more slowly at α 2 than at 0.5: more steps to 5e-12 (in pseudo-time).
  check_newton_is_the_steppers_steady_state(10.0, 2.0, 32, 2, 2, 1.0, NsWallClosure::thom, 100000);
  check_newton_is_the_steppers_steady_state(10.0, 2.0, 32, 4, 2, 4.0, NsWallClosure::thom, 100000);
}

TEST_CASE("[ns][newton] Newton's steady state is the time stepper's: an absorbing layer, Re 10, alpha 0.5",
          "[ns][newton]") {
  // The layer's sink (Crank–Nicolson in the march, a diagonal in Newton's rows) and the circulation it
  // removes from Γ_R (the flux row) are one term in both: the same fixed point, the spin implicit or not.
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 2, 2, 1.0, NsWallClosure::thom, 30000, 8.0);
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 4, 2, 4.0, NsWallClosure::jensen, 30000, 8.0);
}

TEST_CASE(
    "[ns][newton] Newton's steady state is the time stepper's: order 4 in theta and xi, Re 10, alpha 0.5",
    "[ns][newton]") {
  check_newton_is_the_steppers_steady_state(10.0, 0.5, 32, 4, 4);
}

TEST_CASE("[ns][newton] Re 40, alpha 0 on the default grid: C_D and the time to converge",
          "[ns][newton][validation]") {
  const NsParams p = newton_params(40.0, 0.0, 192, 100.0);
  const PolarGrid g = ns_grid(p);
  REQUIRE(g.n_r == 236);
  double C_D[2] = {0.0, 0.0};
  for (const double chord_ratio : {0.0, 0.3}) {
    NewtonOptions o;
    o.chord_ratio = chord_ratio;
    o.on_iteration = [](int k, double r) { std::printf("  step %d: residual %.3e\n", k, r); };
    const NewtonResult nr = solve_steady(p, potential_guess(p, g), o);
    INFO(nr.message);
    REQUIRE(nr.converged);
    const ViscousForces f = viscous_forces(g, p, 1.0, nr.state);
    std::printf(
        "Re 40, alpha 0, %d x %d, chord ratio %g: %s, %.2f s (factorisations %.2f s); C_D %.6f "
        "(pressure %.6f, friction %.6f), C_L %.2e\n",
        g.n_r, g.n_theta, chord_ratio, nr.message.c_str(), nr.wall_seconds, nr.factor_seconds, *f.C_D,
        *f.C_D_pressure, *f.C_D_friction, *f.C_L);
    CHECK(*f.C_D == Approx(1.498).epsilon(0.01));  // Fornberg 1980: 1.498; Dennis & Chang 1970: 1.522
    CHECK(std::fabs(*f.C_L) < 1e-8);
    C_D[chord_ratio > 0.0 ? 1 : 0] = *f.C_D;
  }
  CHECK(C_D[1] == Approx(C_D[0]).epsilon(1e-9));
}

TEST_CASE("[ns][newton] the mirror half: the whole grid's steady state at half the size, Re 30, alpha 0",
          "[ns][newton]") {
  // Without spin the steady state is odd in θ; the half system (0 < θ_j < π) is the whole Newton system
  // restricted to odd corrections, so both iterations take the same steps to round-off.
  for (const int order : {2, 4}) {
    NsParams p = newton_params(30.0, 0.0, 48, 30.0);
    p.advection_order = order;
    INFO("advection order " << order);
    const PolarGrid g = ns_grid(p);
    NewtonResult res[2];
    long lu[2] = {0, 0};
    for (const bool mirror : {false, true}) {
      SteadyJacobian jac(p, mirror);
      REQUIRE(jac.mirror() == mirror);
      res[mirror] = solve_steady(jac, potential_guess(p, g));
      INFO(res[mirror].message);
      REQUIRE(res[mirror].converged);
      lu[mirror] = jac.lu_nonzeros();
    }
    const NsState &whole = res[0].state, &half = res[1].state;
    CHECK(res[1].factorisations == res[0].factorisations);
    CHECK(rel_diff(half.psi, whole.psi) < 1e-10);
    CHECK(rel_diff(half.zeta, whole.zeta) < 1e-10);
    CHECK(half.Gamma_R == 0.0);
    // The half's state is odd in θ to the last bit: ψ and ζ at θ_{n−j} are those at θ_j negated.
    const int n = g.n_theta;
    double asym = 0.0;
    for (int i = 0; i < g.n_r; ++i)
      for (int j = 1; j < n; ++j)
        asym = std::max(asym, std::fabs(half.zeta[size_t(i) * n + j] + half.zeta[size_t(i) * n + (n - j)]));
    CHECK(asym == 0.0);
    const double C_D[2] = {*viscous_forces(g, p, 1.0, whole).C_D, *viscous_forces(g, p, 1.0, half).C_D};
    CHECK(C_D[1] == Approx(C_D[0]).epsilon(1e-10));
    // Half the unknowns: the LU has less than half the whole one's nonzeros.
    INFO("LU nonzeros: whole " << lu[0] << ", half " << lu[1]);
    CHECK(lu[1] < lu[0] / 2);
  }
}

TEST_CASE("[ns][newton] the mirror half is refused with spin or without a stream", "[ns][newton]") {
  NsParams p = newton_params(30.0, 0.5, 32, 20.0);
  CHECK_THROWS_AS(SteadyJacobian(p, true), std::invalid_argument);
  p.omega = 0.0, p.U = 0.0;
  CHECK_THROWS_AS(SteadyJacobian(p, true), std::invalid_argument);
  p.U = 1.0;
  CHECK_NOTHROW(SteadyJacobian(p, true));
}

TEST_CASE("[ns][newton] the grid's nested-dissection order is a permutation of the unknowns",
          "[ns][newton]") {
  // UMFPACK falls back to its own ordering when the given one is not a permutation: a broken order would
  // only show as a slower factorisation, so it is checked here.
  for (const auto& [reach, reach_xi] : {std::pair{1, 1}, std::pair{2, 1}, std::pair{1, 2}, std::pair{2, 2}})
    for (const bool mirror : {false, true})
      for (const auto& [nr, n] : {std::pair{5, 8}, std::pair{79, 64}, std::pair{37, 170}}) {
        const std::vector<long> q = grid_order(nr, n, mirror, reach, reach_xi);
        const long size = mirror ? 2L * nr * (n / 2 - 1) : 2L * nr * n + 1;
        INFO("n_r " << nr << ", n_theta " << n << (mirror ? ", mirror" : ", whole") << ", reach " << reach
                    << ", " << reach_xi);
        REQUIRE(long(q.size()) == size);
        std::vector<long> sorted = q, identity(q.size());
        std::sort(sorted.begin(), sorted.end());
        for (size_t u = 0; u < identity.size(); ++u) identity[u] = long(u);
        CHECK(sorted == identity);                 // each unknown exactly once
        if (!mirror) CHECK(q.back() == size - 1);  // Γ_R last
      }
}

namespace {

/// C_D's observed order over three grids of ratio 2 and its Richardson limit at that order.
struct CdConvergence {
  double order = 0.0, limit = 0.0;
};

/// C_D of Newton's steady state at Re, α on three grids of ratio 2 (n_θ n0/2n0/4n0, rings 3n_θ/4 + 1
/// clustered at the wall, R = 20a) with the wall closure c: the observed order log2(d_01/d_12) and the limit.

CdConvergence steady_cd_order(double Re, double alpha, NsWallClosure c, int n0 = 64) {
  std::vector<double> C_D;
  for (const int n_theta : {n0, 2 * n0, 4 * n0}) {
    const int n_r = 3 * n_theta / 4 + 1;
    NsParams p = newton_params(Re, alpha, n_theta, 20.0);
    p.n_r = n_r, p.wall_refinement = 4.0, p.wall_layer = 0.5, p.wall_closure = c;
    const PolarGrid g = ns_grid(p);
    NewtonOptions o;
    o.tol = 1e-10;
    const NewtonResult nr = solve_steady(p, potential_guess(p, g), o);
    INFO(nr.message);
    REQUIRE(nr.converged);
    C_D.push_back(*viscous_forces(g, p, 1.0, nr.state).C_D);
  }
  CdConvergence r;
  r.order = std::log2((C_D[0] - C_D[1]) / (C_D[1] - C_D[2]));
  r.limit = C_D[2] + (C_D[2] - C_D[1]) / (std::pow(2.0, r.order) - 1.0);
  std::printf("%s wall, Re %g, alpha %g: C_D %.8f %.8f %.8f, observed order %.3f, Richardson %.8f\n",
              c == NsWallClosure::jensen ? "Jensen's" : "Thom's", Re, alpha, C_D[0], C_D[1], C_D[2], r.order,
              r.limit);
  return r;
}

}  // namespace

TEST_CASE("[ns][newton] rings clustered at the wall: C_D converges at second order, Re 20, alpha 0",
          "[ns][newton]") {
  // Three grids of ratio 2 in θ and in the ring index (n_r − 1 doubles: Δ_f halves and L = wall_layer/Δ_f
  // doubles, so the coarse rings are every other fine ring), q = 4: the discretisation is second order in
  // the ring index s of the smooth map ξ(s), so C_D's differences shrink 4 times per level: measured 1.964
  // on n_θ 64/128/256. On 32/64/128 it is 2.108: the fourth-order wall derivative of the forces leaves the
  // field's own error, whose higher terms still show on the coarsest grid (with the three-ring derivative
  // it was 1.987 there, and 1.785 at α 0.5, where it is 2.014 now).
  CHECK(steady_cd_order(20.0, 0.0, NsWallClosure::thom).order == Approx(2.0).margin(0.1));
}

TEST_CASE("[ns][newton] Jensen's wall closure: C_D converges at second order, Re 20, alpha 0.5",
          "[ns][newton]") {
  // The same grids with spin: Jensen's row and Thom's both converge at second order (measured 1.927 and
  // 1.906 on 64/128/256; with the three-ring wall derivative 1.90 and 1.88, and 1.835 and 1.785 on
  // 32/64/128) to the same limit, which does not depend on the closure: measured 1.91914986 and
  // 1.91915383, 2e-6 apart.
  const CdConvergence jensen = steady_cd_order(20.0, 0.5, NsWallClosure::jensen);
  const CdConvergence thom = steady_cd_order(20.0, 0.5, NsWallClosure::thom);
  CHECK(jensen.order == Approx(2.0).margin(0.1));
  CHECK(thom.order == Approx(2.0).margin(0.1));
  CHECK(jensen.limit == Approx(thom.limit).epsilon(1e-5));
}
