#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "physics/exact.hpp"
#include "solver/potential/cholmod_solver.hpp"
#include "solver/potential/flow_solver.hpp"
#include "support.hpp"

using namespace magnus;
using magnus::test::max_abs;
using magnus::test::max_abs_diff;

namespace {}  // namespace

TEST_CASE("the assembled matrix is symmetric and positive definite", "[solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const auto far = GENERATE(FarField::exact, FarField::freestream);
  const auto stencil = GENERATE(StencilKind::five_point, StencilKind::nine_point);
  if (stencil == StencilKind::nine_point && spacing == Spacing::uniform) return;
  const PolarGrid g = make_grid(1.0, 5.0, 9, 16, spacing);
  const DiscreteOperator op = make_operator(g, stencil, far);
  const SparseMatrix A = assemble_matrix(op, false);
  const SparseMatrix At = A.transpose();
  REQUIRE(A.rows() == op.unknowns());
  REQUIRE((A - At).norm() <= 1e-14 * A.norm());
  const Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense);
  REQUIRE(eig.eigenvalues().minCoeff() > 0.0);
}

TEST_CASE("a sign slip in one ring's coupling breaks symmetry", "[solver]") {
  // The symmetry check above can fail: perturb one coefficient and it must notice.
  const PolarGrid g = make_grid(1.0, 5.0, 9, 16, Spacing::uniform);
  DiscreteOperator op = make_operator(g, StencilKind::five_point, FarField::exact);
  op.ring[3].a[2] *= 1.001;
  const SparseMatrix A = assemble_matrix(op, false);
  const SparseMatrix At = A.transpose();
  REQUIRE((A - At).norm() > 1e-6);
}

TEST_CASE("CHOLMOD and FFT solve the same discrete system to round-off", "[solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const auto far = GENERATE(FarField::exact, FarField::freestream);
  const auto stencil = GENERATE(StencilKind::five_point, StencilKind::nine_point);
  const int n_theta = GENERATE(16, 64);
  if (stencil == StencilKind::nine_point && spacing == Spacing::uniform) return;  // refused, see below
  const PolarGrid g = make_grid(1.0, 20.0, default_n_r(spacing, 20.0, n_theta), n_theta, spacing);
  const DiscreteOperator op = make_operator(g, stencil, far);
  auto chol = make_cholmod_solver(g, op);
  auto fft = make_fft_solver(g, op);
  // Every Fourier mode: a random right-hand side.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> rhs(size_t(op.unknowns()));
  for (double& v : rhs) v = u(rng);
  const auto x1 = chol->solve_unknowns(rhs), x2 = fft->solve_unknowns(rhs);
  REQUIRE(max_abs_diff(x1, x2) <= 1e-12 * max_abs(x1));
  // The flow itself.
  const auto p1 = chol->solve(10.0, 6.0), p2 = fft->solve(10.0, 6.0);
  REQUIRE(max_abs_diff(p1, p2) <= 1e-12 * max_abs(p1));
}

TEST_CASE("superposition: ψ(U, Γ) = U ψ_U + Γ ψ_Γ from two solves", "[solver]") {
  const PolarGrid g = make_grid(0.1, 20.0, 40, 64, Spacing::geometric);
  const auto far = GENERATE(FarField::exact, FarField::freestream);
  const DiscreteOperator op = make_operator(g, StencilKind::five_point, far);
  auto s = make_fft_solver(g, op);
  const PsiBasis basis = solve_basis(*s);
  for (auto [U, G] : {std::pair{10.0, 6.28}, std::pair{0.0, 1.0}, std::pair{3.0, -40.0}}) {
    const auto direct = s->solve(U, G), combined = basis.combine(U, G);
    REQUIRE(max_abs_diff(direct, combined) <= 1e-12 * max_abs(direct));
  }
}

TEST_CASE("the discrete circulation is the same on every ring and equals Γ", "[solver]") {
  const auto spacing = GENERATE(Spacing::geometric, Spacing::uniform);
  const auto far = GENERATE(FarField::exact, FarField::freestream);
  const PolarGrid g = make_grid(0.1, 20.0, 30, 32, spacing);
  const DiscreteOperator op = make_operator(g, StencilKind::five_point, far);
  const double Gamma = 6.2831853;
  const auto psi = make_fft_solver(g, op)->solve(10.0, Gamma);
  const int n = g.n_theta;
  for (int i = 0; i + 1 < g.n_r; ++i) {
    double flux = 0.0;
    for (int j = 0; j < n; ++j) flux += psi[size_t(i) * n + j] - psi[size_t(i + 1) * n + j];
    REQUIRE(op.w[i] * flux == Approx(Gamma).epsilon(1e-11));
  }
}

TEST_CASE("exact far field: the decaying roots are those of the exterior recurrence", "[solver]") {
  const auto stencil = GENERATE(StencilKind::five_point, StencilKind::nine_point);
  const double aspect = GENERATE(0.1, 1.0, 2.0, 10.0);  // Δξ/Δθ
  const int n_theta = 32;
  const int cells = std::max(2, int(std::lround(std::log(10.0) / (aspect * 2 * M_PI / n_theta))));
  const PolarGrid g =
      make_grid(1.0, std::exp(cells * aspect * 2 * M_PI / n_theta), cells + 1, n_theta, Spacing::geometric);
  const DiscreteOperator op = make_operator(g, stencil, FarField::exact);
  const int N = g.n_r - 1;
  REQUIRE(op.mu[0] == 1.0);
  for (int k = 1; k <= g.n_theta / 2; ++k) {
    const double mu = op.mu[k];
    CAPTURE(to_string(stencil), aspect, k, mu);
    REQUIRE(std::fabs(mu) < 1.0);  // decaying; negative (alternating) for 9-point high modes on tall cells
    // off·μ² + diag·μ + off = 0 with the exterior ring's symbols.
    const double off = op.symbol(N, +1, k), diag = op.symbol(N, 0, k);
    REQUIRE(off * mu * mu + diag * mu + off == Approx(0.0).margin(1e-12 * std::fabs(diag)));
  }
  // Mode k decays like (a/r)^k: μ_1 ≈ e^{−Δξ} for Δθ, Δξ ≪ 1.
  if (aspect == 1.0) REQUIRE(op.mu[1] == Approx(std::exp(-g.d_xi(0))).epsilon(1e-3));
}

TEST_CASE("the 9-point stencil is refused where its conditions fail (uniform spacing)", "[solver]") {
  const PolarGrid g = make_grid(1.0, 5.0, 9, 16, Spacing::uniform);
  REQUIRE_THROWS_WITH(make_operator(g, StencilKind::nine_point, FarField::exact),
                      Catch::Contains("geometric"));
  REQUIRE(stencil_refusal(make_grid(1.0, 5.0, 9, 16, Spacing::geometric), StencilKind::nine_point).empty());
}

TEST_CASE("9-point symbols: Mehrstellen weights on square cells", "[solver]") {
  const PolarGrid g = make_grid(1.0, std::exp(2 * M_PI / 16 * 8), 9, 16, Spacing::geometric);
  const DiscreteOperator op = make_operator(g, StencilKind::nine_point, FarField::exact);
  const RingStencil& s = op.ring[3];
  // (1/6h²)[20 C − 4 (N+S+E+W) − (corners)], times h²: 10/3, −2/3, −1/6.
  REQUIRE(s.a[1] == Approx(10.0 / 3));
  REQUIRE(s.a[0] == Approx(-2.0 / 3));
  REQUIRE(s.b[1] == Approx(-2.0 / 3));
  REQUIRE(s.b[0] == Approx(-1.0 / 6));
  REQUIRE(op.w[3] == Approx(1.0));  // mode-0 flux weight Δθ/Δξ
}
