#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <random>
#include <string>

#include "solver/mode_solver.hpp"
#include "solver/potential/stencil.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::max_abs;
using magnus::test::max_abs_diff;
using magnus::test::observed_order;

namespace {

std::vector<double> random_vector(size_t n, std::mt19937& rng, double lo = -1.0, double hi = 1.0) {
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<double> v(n);
  for (double& x : v) x = d(rng);
  return v;
}

/// One Fourier component A(ξ)·cos(kθ + phase) of the manufactured solution, with A' and A''.
struct Component {
  int k;
  double phase;
  double (*A)(double), (*dA)(double), (*d2A)(double);
};

// k = 0, 1, 3 and k = 8 (n_θ/4 on the coarsest grid: the θ resolution; k = n_θ/2 of the coarsest grid
// would not be in the asymptotic range there, the discrete Nyquist mode is checked against a direct solve).
const Component kComponents[] = {
    {0, 0.0, [](double x) { return 1.0 + std::sin(1.3 * x); },
     [](double x) { return 1.3 * std::cos(1.3 * x); }, [](double x) { return -1.69 * std::sin(1.3 * x); }},
    {1, 0.4, [](double x) { return std::exp(-0.7 * x); }, [](double x) { return -0.7 * std::exp(-0.7 * x); },
     [](double x) { return 0.49 * std::exp(-0.7 * x); }},
    {3, -1.1, [](double x) { return 0.5 * std::cosh(0.9 * x); },
     [](double x) { return 0.45 * std::sinh(0.9 * x); }, [](double x) { return 0.405 * std::cosh(0.9 * x); }},
    {8, 0.3, [](double x) { return 0.1 + 0.2 * std::cos(1.7 * x); },
     [](double x) { return -0.34 * std::sin(1.7 * x); }, [](double x) { return -0.578 * std::cos(1.7 * x); }},
};

double u_exact(double xi, double th) {
  double u = 0.0;
  for (const auto& c : kComponents) u += c.A(xi) * std::cos(c.k * th + c.phase);
  return u;
}
double u_xi_exact(double xi, double th) {
  double u = 0.0;
  for (const auto& c : kComponents) u += c.dA(xi) * std::cos(c.k * th + c.phase);
  return u;
}
/// r²∇²u = u_ξξ + u_θθ.
double r2_laplacian(double xi, double th) {
  double s = 0.0;
  for (const auto& c : kComponents) s += (c.d2A(xi) - c.k * c.k * c.A(xi)) * std::cos(c.k * th + c.phase);
  return s;
}

/// Max nodal error of the manufactured ∇²u − λ(r)u = F on one grid: σ_i = r_i²λ(r_i), f = r²F.
double manufactured_error(const PolarGrid& g, bool variable_lambda, OuterBoundary outer) {
  const double a = g.a;
  const auto lambda = [&](double r) { return variable_lambda ? 3.0 + r * r / (a * a) : 0.0; };
  const int n = g.n_theta, N = g.n_r - 1;
  std::vector<double> sigma(g.n_r), f(size_t(g.n_r) * n), g_wall(n), g_outer(n);
  for (int i = 0; i < g.n_r; ++i) {
    const double r = g.r[i];
    sigma[i] = r * r * lambda(r);
    for (int j = 0; j < n; ++j) {
      const double F = r2_laplacian(g.xi[i], g.theta[j]) / (r * r) - lambda(r) * u_exact(g.xi[i], g.theta[j]);
      f[size_t(i) * n + j] = r * r * F;
    }
  }
  for (int j = 0; j < n; ++j) {
    g_wall[j] = u_exact(0.0, g.theta[j]);
    g_outer[j] =
        outer == OuterBoundary::dirichlet ? u_exact(g.xi[N], g.theta[j]) : u_xi_exact(g.xi[N], g.theta[j]);
  }
  const ModeSolver s(g, sigma, outer);
  const auto u = s.solve(f, g_wall, g_outer);
  double e = 0.0;
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < n; ++j)
      e = std::max(e, std::fabs(u[size_t(i) * n + j] - u_exact(g.xi[i], g.theta[j])));
  return e;
}

/// ξ from 0 to π/2 (R/a = e^{π/2}); n_r = n_θ/4 + 1 makes geometric cells square (Δξ = Δθ).
PolarGrid ladder_grid(int n_theta, Spacing spacing) {
  return make_grid(0.5, std::exp(M_PI / 2), n_theta / 4 + 1, n_theta, spacing);
}

void check_order_two(bool variable_lambda, OuterBoundary outer, Spacing spacing) {
  std::vector<double> e;
  for (int n_theta : {32, 64, 128})
    e.push_back(manufactured_error(ladder_grid(n_theta, spacing), variable_lambda, outer));
  const double p1 = observed_order(e[0], e[1]), p2 = observed_order(e[1], e[2]);
  INFO("spacing " << (spacing == Spacing::geometric ? "geometric" : "uniform") << ", lambda "
                  << (variable_lambda ? "3 + r^2/a^2" : "0") << ", outer "
                  << (outer == OuterBoundary::dirichlet ? "dirichlet" : "neumann") << ": errors " << e[0]
                  << " " << e[1] << " " << e[2] << ", orders " << p1 << " " << p2);
  REQUIRE(p1 == Approx(2.0).margin(0.1));
  REQUIRE(p2 == Approx(2.0).margin(0.1));
  REQUIRE(e[2] < 1e-2);  // and the error itself is small (max|u| ≈ 3.4), not merely shrinking
}

/// The message of the std::invalid_argument that fn throws ("" if none).
template <class F>
std::string invalid_argument_message(F&& fn) {
  try {
    fn();
  } catch (const std::invalid_argument& ex) {
    return ex.what();
  }
  return "";
}

}  // namespace

TEST_CASE("mode solver: manufactured ∇²u − λ(r)u = F, Dirichlet on both rings, order 2", "[mode_solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const bool variable_lambda = GENERATE(false, true);
  check_order_two(variable_lambda, OuterBoundary::dirichlet, spacing);
}

TEST_CASE("mode solver: manufactured ∇²u − λ(r)u = F, Neumann u_ξ at R, order 2", "[mode_solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const bool variable_lambda = GENERATE(false, true);
  check_order_two(variable_lambda, OuterBoundary::neumann, spacing);
}

TEST_CASE("mode solver: agrees with a dense solve of the stencil.cpp 5-point system plus σ",
          "[mode_solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const auto outer = GENERATE(OuterBoundary::dirichlet, OuterBoundary::neumann);
  const bool zero_sigma = GENERATE(true, false);
  const PolarGrid g = make_grid(1.0, 5.0, 9, 16, spacing);
  const DiscreteOperator op = make_operator(g, StencilKind::five_point, FarField::exact);
  const int n = g.n_theta, N = g.n_r - 1, L = outer == OuterBoundary::neumann ? N : N - 1;
  std::mt19937 rng(7);
  std::vector<double> sigma = random_vector(g.n_r, rng, 0.0, 5.0);
  if (zero_sigma) sigma.assign(g.n_r, 0.0);
  const auto f = random_vector(size_t(g.n_r) * n, rng), g_wall = random_vector(n, rng),
             g_outer = random_vector(n, rng);
  // Rows of the existing operator (−Δθ·h_i times u_ξξ + u_θθ) plus Δθ·h_i·σ_i; right side −Δθ·h_i·f.
  // Neumann: ring N with its full-cell row and the ghost u_{N+1} = u_{N−1} + 2Δξ·g_outer eliminated.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(L * n, L * n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(L * n);
  const auto idx = [&](int i, int j) { return (i - 1) * n + (j + n) % n; };
  for (int i = 1; i <= L; ++i) {
    const RingStencil& s = op.ring[i];
    const double h = i < N ? 0.5 * (g.d_xi(i - 1) + g.d_xi(i)) : g.d_xi(N - 1);
    for (int j = 0; j < n; ++j) {
      const int row = idx(i, j);
      b(row) = -g.d_theta * h * f[size_t(i) * n + j];
      A(row, idx(i, j)) += g.d_theta * h * sigma[i];
      for (int d = -1; d <= 1; ++d) {
        for (int dj = -1; dj <= 1; ++dj) {
          const double c = dj == 0 ? s.a[d + 1] : s.b[d + 1];
          if (c == 0.0) continue;
          const int ii = i + d, jj = (j + dj + n) % n;
          if (ii == 0) {
            b(row) -= c * g_wall[jj];
          } else if (ii == N + 1) {  // Neumann ghost
            A(row, idx(N - 1, jj)) += c;
            b(row) -= c * 2.0 * g.d_xi(N - 1) * g_outer[jj];
          } else if (ii == N && outer == OuterBoundary::dirichlet) {
            b(row) -= c * g_outer[jj];
          } else {
            A(row, idx(ii, jj)) += c;
          }
        }
      }
    }
  }
  const Eigen::VectorXd x = A.partialPivLu().solve(b);
  std::vector<double> direct(size_t(g.n_r) * n);
  for (int j = 0; j < n; ++j) {
    direct[j] = g_wall[j];
    if (outer == OuterBoundary::dirichlet) direct[size_t(N) * n + j] = g_outer[j];
  }
  for (int i = 1; i <= L; ++i)
    for (int j = 0; j < n; ++j) direct[size_t(i) * n + j] = x(idx(i, j));
  const auto u = ModeSolver(g, sigma, outer).solve(f, g_wall, g_outer);
  INFO("relative difference " << max_abs_diff(u, direct) / max_abs(direct));
  REQUIRE(max_abs_diff(u, direct) <= 1e-12 * max_abs(direct));
}

TEST_CASE("mode solver: wall data in modes = base solve + influence vectors", "[mode_solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const auto outer = GENERATE(OuterBoundary::dirichlet, OuterBoundary::neumann);
  const PolarGrid g = make_grid(1.0, 8.0, 12, 32, spacing);
  const int n = g.n_theta;
  std::mt19937 rng(11);
  const auto sigma = random_vector(g.n_r, rng, 0.0, 3.0);
  const auto f = random_vector(size_t(g.n_r) * n, rng), g_outer = random_vector(n, rng);
  const ModeSolver s(g, sigma, outer);
  const auto base = s.solve(f, std::vector<double>(n, 0.0), g_outer);
  // Wall data 0.7 + 0.3 sinθ − 1.2 cos3θ + 0.5 sin3θ + 0.9 cos16θ (16 = n_θ/2, the Nyquist mode).
  std::vector<double> g_wall(n);
  for (int j = 0; j < n; ++j) {
    const double t = g.theta[j];
    g_wall[j] =
        0.7 + 0.3 * std::sin(t) - 1.2 * std::cos(3 * t) + 0.5 * std::sin(3 * t) + 0.9 * std::cos(16 * t);
  }
  const auto u = s.solve(f, g_wall, g_outer);
  const auto phi0 = s.influence(0), phi1 = s.influence(1), phi3 = s.influence(3), phi16 = s.influence(16);
  REQUIRE(phi3[0] == 1.0);
  if (outer == OuterBoundary::dirichlet) REQUIRE(phi3[g.n_r - 1] == 0.0);
  std::vector<double> sum(base);
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < n; ++j) {
      const double t = g.theta[j];
      sum[size_t(i) * n + j] += 0.7 * phi0[i] + 0.3 * std::sin(t) * phi1[i] +
                                (-1.2 * std::cos(3 * t) + 0.5 * std::sin(3 * t)) * phi3[i] +
                                0.9 * std::cos(16 * t) * phi16[i];
    }
  INFO("relative difference " << max_abs_diff(u, sum) / max_abs(u));
  REQUIRE(max_abs_diff(u, sum) <= 1e-13 * max_abs(u));
  // The slope accessor is the one-sided derivative of the same vector.
  const double h1 = g.d_xi(0), h2 = g.d_xi(1);
  REQUIRE(s.influence_wall_slope(3) ==
          Approx(-(2 * h1 + h2) / (h1 * (h1 + h2)) + (h1 + h2) / (h1 * h2) * phi3[1] -
                 h1 / (h2 * (h1 + h2)) * phi3[2])
              .epsilon(1e-14));
  REQUIRE_THROWS_AS(s.influence(17), std::invalid_argument);
}

TEST_CASE("mode solver: influence wall slope converges to −k·coth(kΞ) / −k·tanh(kΞ) at order 2",
          "[mode_solver]") {
  // σ = 0: u_ξξ − k²u = 0, u(0) = 1, u(Ξ) = 0 → u'(0) = −k coth(kΞ); u_ξ(Ξ) = 0 → u'(0) = −k tanh(kΞ).
  const auto outer = GENERATE(OuterBoundary::dirichlet, OuterBoundary::neumann);
  const PolarGrid coarse = ladder_grid(128, Spacing::geometric), fine = ladder_grid(256, Spacing::geometric);
  const double Xi = coarse.xi.back();
  const ModeSolver s1(coarse, std::vector<double>(coarse.n_r, 0.0), outer);
  const ModeSolver s2(fine, std::vector<double>(fine.n_r, 0.0), outer);
  const double slope0 = outer == OuterBoundary::dirichlet ? -1.0 / Xi : 0.0;  // linear / constant: exact
  REQUIRE(s1.influence_wall_slope(0) == Approx(slope0).margin(1e-12));
  for (int k : {1, 2, 4}) {
    const double exact = outer == OuterBoundary::dirichlet ? -k / std::tanh(k * Xi) : -k * std::tanh(k * Xi);
    const double e1 = std::fabs(s1.influence_wall_slope(k) - exact),
                 e2 = std::fabs(s2.influence_wall_slope(k) - exact);
    CAPTURE(k, exact, e1, e2, observed_order(e1, e2));
    REQUIRE(e1 < 0.02 * std::fabs(exact));
    REQUIRE(observed_order(e1, e2) == Approx(2.0).margin(0.1));
  }
}

TEST_CASE("mode solver: one factorisation, many right-hand sides, any threads", "[mode_solver]") {
  const PolarGrid g = make_grid(1.0, 10.0, 20, 64, Spacing::uniform);
  const int n = g.n_theta;
  std::mt19937 rng(3);
  const auto sigma = random_vector(g.n_r, rng, 0.0, 2.0);
  const auto outer = GENERATE(OuterBoundary::dirichlet, OuterBoundary::neumann);
  const auto f1 = random_vector(size_t(g.n_r) * n, rng), w1 = random_vector(n, rng),
             o1 = random_vector(n, rng);
  const auto f2 = random_vector(size_t(g.n_r) * n, rng), w2 = random_vector(n, rng),
             o2 = random_vector(n, rng);
  const ModeSolver s(g, sigma, outer);
  const auto u1 = s.solve(f1, w1, o1), u2 = s.solve(f2, w2, o2), u1_again = s.solve(f1, w1, o1);
  const auto fresh1 = ModeSolver(g, sigma, outer).solve(f1, w1, o1);
  const auto fresh2 = ModeSolver(g, sigma, outer).solve(f2, w2, o2);
  REQUIRE(max_abs_diff(u1, u2) > 0.1 * max_abs(u1));  // genuinely different problems
  INFO("reuse vs fresh " << max_abs_diff(u1, fresh1) << " " << max_abs_diff(u2, fresh2));
  REQUIRE(max_abs_diff(u1, fresh1) <= 1e-14 * max_abs(fresh1));
  REQUIRE(max_abs_diff(u2, fresh2) <= 1e-14 * max_abs(fresh2));
  REQUIRE(max_abs_diff(u1, u1_again) == 0.0);

  // Threads split the modes (m ≥ 256): same answer as one thread.
  const PolarGrid big = make_grid(1.0, 10.0, 40, 1024, Spacing::geometric);
  const auto sb = random_vector(big.n_r, rng, 0.0, 2.0);
  const auto fb = random_vector(size_t(big.n_r) * big.n_theta, rng), wb = random_vector(big.n_theta, rng),
             ob = random_vector(big.n_theta, rng);
  const auto one = ModeSolver(big, sb, outer, 1).solve(fb, wb, ob);
  const auto four = ModeSolver(big, sb, outer, 4).solve(fb, wb, ob);
  INFO("1 vs 4 threads " << max_abs_diff(one, four) / max_abs(one));
  REQUIRE(max_abs_diff(one, four) <= 1e-13 * max_abs(one));
}

TEST_CASE("mode solver: bad input throws std::invalid_argument with one line", "[mode_solver]") {
  const PolarGrid g = make_grid(1.0, 5.0, 9, 16, Spacing::geometric);
  const int n = g.n_theta;
  const std::vector<double> sigma(g.n_r, 1.0), f(size_t(g.n_r) * n, 0.0), w(n, 0.0);
  const ModeSolver s(g, sigma, OuterBoundary::neumann);
  std::vector<double> f_nan = f, w_inf = w, sigma_neg = sigma, sigma_nan = sigma;
  f_nan[size_t(3) * n + 5] = std::nan("");
  w_inf[2] = INFINITY;
  sigma_neg[4] = -1e-3;
  sigma_nan[1] = std::nan("");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {invalid_argument_message([&] { s.solve(f_nan, w, w); }), "f[53] is not finite"},
      {invalid_argument_message([&] { s.solve(f, w_inf, w); }), "g_wall[2] is not finite"},
      {invalid_argument_message([&] { s.solve(f, w, w_inf); }), "g_outer[2] is not finite"},
      {invalid_argument_message([&] { s.solve(std::vector<double>(10), w, w); }),
       "f has 10 values, expected 144"},
      {invalid_argument_message([&] { s.solve(f, std::vector<double>(15), w); }), "g_wall has 15 values"},
      {invalid_argument_message([&] { s.solve(f, w, std::vector<double>(17)); }), "g_outer has 17 values"},
      {invalid_argument_message([&] { ModeSolver(g, sigma_neg, OuterBoundary::dirichlet); }), "sigma[4]"},
      {invalid_argument_message([&] { ModeSolver(g, sigma_nan, OuterBoundary::dirichlet); }),
       "sigma[1] is not finite"},
      {invalid_argument_message([&] { ModeSolver(g, std::vector<double>(8), OuterBoundary::dirichlet); }),
       "sigma has 8 values"},
      {invalid_argument_message([&] { s.influence(-1); }), "mode -1"},
  };
  for (const auto& [message, expected] : cases) {
    CAPTURE(message, expected);
    REQUIRE(message.find(expected) != std::string::npos);
    REQUIRE(message.find('\n') == std::string::npos);
  }
}

namespace {

/// Random diagonally dominant rows on L rings (symmetric positive definite for every mode).
ModeRows random_rows(int L, int n_theta, std::mt19937& rng) {
  ModeRows rows;
  rows.n_theta = n_theta;
  rows.d_theta = 2.0 * M_PI / n_theta;
  rows.diag_a = random_vector(size_t(L) + 1, rng, 5.0, 6.0);
  rows.diag_b = random_vector(size_t(L) + 1, rng, -0.5, 0.5);
  rows.off_a = random_vector(size_t(L) + 1, rng, -1.5, -0.5);
  rows.off_b = random_vector(size_t(L) + 1, rng, -0.3, 0.3);
  return rows;
}

}  // namespace

TEST_CASE("mode solver: general rows with the exterior or bordered closure match a dense solve",
          "[mode_solver]") {
  const int L = 7, n_theta = 16, m = n_theta / 2 + 1;
  std::mt19937 rng(11);
  ModeRows rows = random_rows(L, n_theta, rng);
  const bool bordered = GENERATE(false, true);
  if (bordered)
    rows.border = 0.8;
  else
    rows.exterior = random_vector(size_t(m), rng, 0.1, 1.0);
  const bool last_ring_only = GENERATE(false, true);
  const ModeSolver s(rows);
  std::vector<std::complex<double>> y(size_t(L) * m);
  for (int i = 1; i <= L; ++i)
    for (int k = 0; k < m; ++k) {
      const auto v = random_vector(2, rng);  // mode 0 of a real signal is real
      if (!(last_ring_only && i < L)) y[size_t(i - 1) * m + k] = {v[0], k == 0 ? 0.0 : v[1]};
    }
  const double b_X = 0.37;
  std::vector<std::complex<double>> x = y;
  const double X = s.solve_spectrum(x.data(), b_X, last_ring_only);
  for (int k = 0; k < m; ++k) {
    const int size = L + (bordered && k == 0 ? 1 : 0);
    const double c = 2.0 * std::cos(k * rows.d_theta);
    Eigen::MatrixXcd T = Eigen::MatrixXcd::Zero(size, size);
    Eigen::VectorXcd b(size);
    for (int i = 1; i <= L; ++i) {
      T(i - 1, i - 1) = rows.diag_a[i] + c * rows.diag_b[i] + (i == L && !bordered ? rows.exterior[k] : 0.0);
      if (i < L) T(i - 1, i) = T(i, i - 1) = rows.off_a[i] + c * rows.off_b[i];
      b(i - 1) = y[size_t(i - 1) * m + k];
    }
    if (size > L) {
      T(L - 1, L) = T(L, L - 1) = -rows.border;
      T(L, L) = rows.border;
      b(L) = b_X;
    }
    const Eigen::VectorXcd ref = T.lu().solve(b);
    for (int i = 1; i <= L; ++i) {
      CAPTURE(bordered, last_ring_only, k, i);
      REQUIRE(std::abs(x[size_t(i - 1) * m + k] - ref(i - 1)) <= 1e-13 * ref.cwiseAbs().maxCoeff());
    }
    if (size > L) REQUIRE(std::abs(X - ref(L).real()) <= 1e-13 * ref.cwiseAbs().maxCoeff());
  }
  if (!bordered) REQUIRE(X == 0.0);
  // Built from rows, the grid's solves do not apply.
  REQUIRE_THROWS_AS(s.influence(0), std::logic_error);

  // The pool splits the modes (m ≥ 256): bit for bit the one-thread answer (each mode is independent).
  const ModeRows big = random_rows(12, 1024, rng);
  std::vector<std::complex<double>> y1(size_t(12) * 513);
  for (auto& v : y1) v = {random_vector(1, rng)[0], random_vector(1, rng)[0]};
  std::vector<std::complex<double>> y4 = y1;
  ModeSolver(big, 1).solve_spectrum(y1.data(), 0.0, false);
  ModeSolver(big, 4).solve_spectrum(y4.data(), 0.0, false);
  REQUIRE(y1 == y4);
}
