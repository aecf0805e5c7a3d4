// GMRES (solver/gmres.hpp) against exact solutions: a nonsymmetric system solved to round-off, and the
// identity plus a rank-2 matrix, whose minimal polynomial has degree 3, solved in 3 products.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/gmres.hpp"

using namespace magnus;

namespace {

/// y = A v for A dense, n × n row-major.
auto product(const std::vector<double>& A, size_t n) {
  return [&A, n](const std::vector<double>& v, std::vector<double>& y) {
    for (size_t i = 0; i < n; ++i) {
      y[i] = 0.0;
      for (size_t j = 0; j < n; ++j) y[i] += A[i * n + j] * v[j];
    }
  };
}

}  // namespace

TEST_CASE("gmres: a nonsymmetric system is solved to round-off, the residual it reports is the true one",
          "[gmres]") {
  const size_t n = 40;
  std::vector<double> A(n * n), x_exact(n), b(n, 0.0), x;
  for (size_t i = 0; i < n; ++i) {
    x_exact[i] = std::sin(1.0 + double(i));
    for (size_t j = 0; j < n; ++j) A[i * n + j] = (i == j ? 4.0 : 0.0) + std::cos(double(3 * i + 7 * j)) / 3.0;
  }
  product(A, n)(x_exact, b);
  const GmresResult r = gmres(product(A, n), b, x, 1e-12, int(n));
  CHECK(r.converged);
  double err = 0.0;
  for (size_t i = 0; i < n; ++i) err = std::max(err, std::fabs(x[i] - x_exact[i]));
  CHECK(err < 1e-10);
  std::vector<double> Ax(n);
  product(A, n)(x, Ax);
  for (size_t i = 0; i < n; ++i) Ax[i] -= b[i];
  CHECK(norm2(Ax) / norm2(b) < 1e-11);
  // The residual the recurrence reports is the true one, to round-off.
  CHECK(norm2(Ax) / norm2(b) == Approx(r.residual).margin(1e-13));
}

TEST_CASE("gmres: identity plus rank 2 takes three products", "[gmres]") {
  const size_t n = 50;
  std::vector<double> A(n * n, 0.0), b(n), x;
  for (size_t i = 0; i < n; ++i) {
    b[i] = 1.0 + 0.1 * double(i % 7);
    for (size_t j = 0; j < n; ++j)
      A[i * n + j] = (i == j ? 1.0 : 0.0) + 0.02 * std::sin(double(i + 1)) * std::cos(double(2 * j)) +
                     0.03 * std::cos(double(i)) * std::sin(double(j) + 0.5);
  }
  const GmresResult r = gmres(product(A, n), b, x, 1e-12, int(n));
  CHECK(r.converged);
  CHECK(r.iterations <= 3);
  std::vector<double> zero(n, 0.0);
  const GmresResult z = gmres(product(A, n), zero, x, 1e-12, 5);
  CHECK(z.converged);
  CHECK(z.iterations == 0);
  CHECK(norm2(x) == 0.0);
}
