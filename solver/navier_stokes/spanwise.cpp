// The spanwise (e^{iβz}) stability problem of spanwise.hpp: the staggered grid and the base's velocities on
// it, then the rows of u_r, u_θ, w̃ (momentum), p (continuity) and the ghosts (boundary conditions). The rows
// are written in SI and scaled once at the end: momentum by a/U², continuity by a/U, a condition on one
// field by that field's scale; the columns by U (velocities) and U² (p).
#include "solver/navier_stokes/spanwise.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/fd_weights.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/stages.hpp"

namespace magnus {

namespace {

enum Field { kU = 0, kV = 1, kW = 2, kP = kSpanwisePressure };

/// Weights of f at three points in a derivative (or, order 0, the value) at x0.
struct Weights3 {
  double m, c, p;
};

/// fd_weights (Fornberg) of the derivative of order `order` at x0 from the points a, b, c.
Weights3 three_point(double x0, double a, double b, double c, int order) {
  const std::vector<double> w = fd_weights(x0, {a, b, c}, order);
  return {w[0], w[1], w[2]};
}

/// The staggered grid: ξ of the rings 0 … N + 1 (the last a ghost beyond R, mirrored) and of the cell
/// centres c = −1 … N (ghosts mirrored across the wall and R), the unknowns' numbering by slot, and the
/// ξ-derivatives' weights at each ring and centre (second order on any spacing; ∂²/∂ξ² first order where
/// the spacing changes).
struct Mac {
  int n = 0, N = 0;  ///< columns; the outer ring's index n_r − 1
  double k = 0.0, a = 0.0;
  std::vector<double> xf, xc;  ///< ξ of ring i at xf[i], of centre c at xc[c + 1]
  std::vector<Weights3> d1_f, d2_f;  ///< ∂/∂ξ, ∂²/∂ξ² at ring i (1 ≤ i ≤ N) from rings i − 1, i, i + 1
  std::vector<Weights3> d1_c, d2_c;  ///< the same at centre c (0 ≤ c < N), at index c + 1
  Weights3 d1_wall;  ///< ∂/∂ξ at centre 0 from the wall (ξ = 0) and centres 0, 1
  /// The ghosts of a field that vanishes on the wall (centre −1) and on R (centre N): the quadratic through
  /// 0 there and the two centres inside, as weights of (0, the nearer centre, the farther).
  Weights3 ghost_wall, ghost_outer;
  explicit Mac(const PolarGrid& g) : n(g.n_theta), N(g.n_r - 1), k(g.d_theta), a(g.a) {
    xf = g.xi;
    xf.push_back(2.0 * g.xi[size_t(N)] - g.xi[size_t(N) - 1]);
    xc.push_back(-0.5 * g.xi[1]);
    for (int c = 0; c < N; ++c) xc.push_back(0.5 * (g.xi[size_t(c)] + g.xi[size_t(c) + 1]));
    xc.push_back(2.0 * g.xi[size_t(N)] - xc.back());
    d1_f.resize(size_t(N) + 1), d2_f.resize(size_t(N) + 1), d1_c.resize(size_t(N) + 1), d2_c.resize(size_t(N) + 1);
    for (int i = 1; i <= N; ++i) {
      const double* x = &xf[size_t(i) - 1];
      d1_f[size_t(i)] = three_point(x[1], x[0], x[1], x[2], 1), d2_f[size_t(i)] = three_point(x[1], x[0], x[1], x[2], 2);
    }
    for (int c = 0; c < N; ++c) {
      const double* x = &xc[size_t(c)];
      d1_c[size_t(c) + 1] = three_point(x[1], x[0], x[1], x[2], 1);
      d2_c[size_t(c) + 1] = three_point(x[1], x[0], x[1], x[2], 2);
    }
    d1_wall = three_point(xi_c(0), 0.0, xi_c(0), xi_c(1), 1);
    ghost_wall = three_point(xi_c(-1), 0.0, xi_c(0), xi_c(1), 0);
    ghost_outer = three_point(xi_c(N), xf[size_t(N)], xi_c(N - 1), xi_c(N - 2), 0);
  }
  double xi_c(int c) const { return xc[size_t(c + 1)]; }
  double r_f(int i) const { return a * std::exp(xf[size_t(i)]); }
  double r_c(int c) const { return a * std::exp(xi_c(c)); }
  int wrap(int j) const { return j < 0 ? j + n : j >= n ? j - n : j; }
  long at(int slot, int j, int f) const { return kSpanwiseFields * (long(slot) * n + wrap(j)) + f; }
  long u(int i, int j) const { return at(i, j, kU); }       ///< u_r on ring i at θ_{j+½}
  long v(int c, int j) const { return at(c + 1, j, kV); }   ///< u_θ at centre c, θ_j
  long w(int c, int j) const { return at(c + 1, j, kW); }   ///< w̃ at centre c, θ_{j+½}
  long pr(int c, int j) const { return at(c + 1, j, kP); }  ///< p at centre c, θ_{j+½}
  long unknowns() const { return spanwise_unknowns(N + 1, n); }
};

/// The base's velocities on the staggered points, m/s: U_r = Ψ_θ/r on ring i at θ_{j+½} (i ≤ N; ring N + 1
/// mirrors N − 1), U_θ = −Ψ_ξ/r at centre c and θ_j (c < N; centre N repeats N − 1), and aω on the wall.
struct MacBase {
  const Mac& m;
  std::vector<double> Ur, Ut;
  double wall = 0.0;
  MacBase(const Mac& mac, const PolarGrid& g, const NsState& s, double omega) : m(mac), wall(g.a * omega) {
    const int n = m.n, N = m.N;
    Ur.resize(size_t(N + 2) * n), Ut.resize(size_t(N + 1) * n);
    auto psi = [&](int i, int j) { return s.psi[size_t(i) * n + size_t(m.wrap(j))]; };
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j < n; ++j) Ur[size_t(i) * n + j] = (psi(i, j + 1) - psi(i, j)) / (m.r_f(i) * m.k);
    for (int j = 0; j < n; ++j) Ur[size_t(N + 1) * n + j] = Ur[size_t(N - 1) * n + j];
    for (int c = 0; c < N; ++c)
      for (int j = 0; j < n; ++j)
        Ut[size_t(c) * n + j] = -(psi(c + 1, j) - psi(c, j)) / (m.r_c(c) * (m.xf[size_t(c) + 1] - m.xf[size_t(c)]));
    for (int j = 0; j < n; ++j) Ut[size_t(N) * n + j] = Ut[size_t(N - 1) * n + j];
  }
  double ur(int i, int j) const { return Ur[size_t(i) * m.n + size_t(m.wrap(j))]; }
  double ut(int c, int j) const { return Ut[size_t(c) * m.n + size_t(m.wrap(j))]; }
};

/// The rows in SI and each row's scale; add() skips zeros.
struct Rows {
  const Mac& m;
  const MacBase& b;
  double nu, beta;
  std::vector<long> ti, tj;
  std::vector<double> tx, scale, mass;
  const NsParams* params;  ///< the absorbing layer's λ(r) (stages.hpp)
  void add(long row, long col, double v) {
    if (v != 0.0) ti.push_back(row), tj.push_back(col), tx.push_back(v);
  }
  /// −U_r f_r − (U_θ/r) f_θ + ν(∇₂²f − β²f) + (diag − λ(r))·f at (i, j) of the field numbered by at(i, j), at
  /// radius r, with the ξ-derivatives' weights d1, d2 there (λ: the absorbing layer's sink on the velocity, as
  /// on the 2D vorticity).
  template <class At>
  void transport(long row, At at, int i, int j, double Ub, double Vb, double r, const Weights3& d1,
                 const Weights3& d2, double diag) {
    const double c = nu / (r * r), k = m.k;
    diag -= absorbing_rate_at(*params, r);
    add(row, at(i - 1, j), -Ub / r * d1.m + c * d2.m);
    add(row, at(i + 1, j), -Ub / r * d1.p + c * d2.p);
    add(row, at(i, j + 1), -Vb / (2.0 * r * k) + c / (k * k));
    add(row, at(i, j - 1), Vb / (2.0 * r * k) + c / (k * k));
    add(row, at(i, j), -Ub / r * d1.c + c * d2.c - 2.0 * c / (k * k) - nu * beta * beta + diag);
  }
  /// A momentum row: scale a/U² (set by the caller's speed), mass 1.
  void dynamic(long row, double s) { scale[size_t(row)] = s, mass[size_t(row)] = 1.0; }
};

/// u_r on ring i (1 ≤ i < N, and N where the wake leaves), θ_{j+½}.
void radial_momentum(Rows& R, int i, int j) {
  const Mac& m = R.m;
  const MacBase& b = R.b;
  const double r = m.r_f(i);
  const double Ub = b.ur(i, j), Vb = 0.25 * (b.ut(i - 1, j) + b.ut(i - 1, j + 1) + b.ut(i, j) + b.ut(i, j + 1));
  const Weights3 &d1 = m.d1_f[size_t(i)], &d2 = m.d2_f[size_t(i)];
  const double Ur_xi = d1.m * b.ur(i - 1, j) + d1.c * Ub + d1.p * b.ur(i + 1, j);
  const double Ur_th = (b.ur(i, j + 1) - b.ur(i, j - 1)) / (2.0 * m.k);
  const long row = m.u(i, j);
  R.transport(row, [&](int ii, int jj) { return m.u(ii, jj); }, i, j, Ub, Vb, r, d1, d2,
              -R.nu / (r * r) - Ur_xi / r);
  const double cv = -0.25 * (Ur_th - 2.0 * Vb) / r, cd = -R.nu / (r * r * m.k);  // ū_θ; −(2ν/r²)u_θ,θ
  for (int c : {i - 1, i}) {
    R.add(row, m.v(c, j), cv - cd), R.add(row, m.v(c, j + 1), cv + cd);
  }
  const double dp = r * (m.xi_c(i) - m.xi_c(i - 1));
  R.add(row, m.pr(i, j), -1.0 / dp), R.add(row, m.pr(i - 1, j), 1.0 / dp);
}

/// u_θ at centre c (0 ≤ c < N), θ_j.
void azimuthal_momentum(Rows& R, int c, int j) {
  const Mac& m = R.m;
  const MacBase& b = R.b;
  const double r = m.r_c(c);
  const double Vb = b.ut(c, j), Ub = 0.25 * (b.ur(c, j - 1) + b.ur(c, j) + b.ur(c + 1, j - 1) + b.ur(c + 1, j));
  const Weights3 &d1 = m.d1_c[size_t(c) + 1], &d2 = m.d2_c[size_t(c) + 1];
  // U_θ,ξ: through the wall's aω next to the wall, the neighbouring centres elsewhere.
  const Weights3& d1_base = c == 0 ? m.d1_wall : d1;
  const double below = c == 0 ? b.wall : b.ut(c - 1, j);
  const double Ut_xi = d1_base.m * below + d1_base.c * Vb + d1_base.p * b.ut(c + 1, j);
  const double Ut_th = (b.ut(c, j + 1) - b.ut(c, j - 1)) / (2.0 * m.k);
  const long row = m.v(c, j);
  R.transport(row, [&](int ii, int jj) { return m.v(ii, jj); }, c, j, Ub, Vb, r, d1, d2,
              -R.nu / (r * r) - (Ut_th + Ub) / r);
  const double cu = -0.25 * (Vb + Ut_xi) / r, cd = R.nu / (r * r * m.k);  // ū_r; +(2ν/r²)u_r,θ
  for (int i : {c, c + 1}) {
    R.add(row, m.u(i, j), cu + cd), R.add(row, m.u(i, j - 1), cu - cd);
  }
  R.add(row, m.pr(c, j), -1.0 / (r * m.k)), R.add(row, m.pr(c, j - 1), 1.0 / (r * m.k));
}

/// w̃ at centre c (0 ≤ c < N), θ_{j+½}.
void spanwise_momentum(Rows& R, int c, int j) {
  const Mac& m = R.m;
  const MacBase& b = R.b;
  const double r = m.r_c(c);
  const double Ub = 0.5 * (b.ur(c, j) + b.ur(c + 1, j)), Vb = 0.5 * (b.ut(c, j) + b.ut(c, j + 1));
  const long row = m.w(c, j);
  R.transport(row, [&](int ii, int jj) { return m.w(ii, jj); }, c, j, Ub, Vb, r, m.d1_c[size_t(c) + 1],
              m.d2_c[size_t(c) + 1], 0.0);
  R.add(row, m.pr(c, j), R.beta);
}

/// Continuity in cell c, θ_{j+½}: (1/r²)(r u_r)_ξ + (1/r) u_θ,θ + β w̃ = 0 (the row of p there).
void continuity(Rows& R, int c, int j) {
  const Mac& m = R.m;
  const double r = m.r_c(c), h = m.xf[size_t(c) + 1] - m.xf[size_t(c)];
  const long row = m.pr(c, j);
  R.add(row, m.u(c + 1, j), m.r_f(c + 1) / (r * r * h)), R.add(row, m.u(c, j), -m.r_f(c) / (r * r * h));
  R.add(row, m.v(c, j + 1), 1.0 / (r * m.k)), R.add(row, m.v(c, j), -1.0 / (r * m.k));
  R.add(row, m.w(c, j), R.beta);
}

/// The ghost f_g of a field that vanishes on a boundary: f_g = L·(0, f_0, f_1) (Mac's ghost weights).
void zero_ghost(Rows& R, long ghost, long f0, long f1, const Weights3& L) {
  R.add(ghost, ghost, 1.0), R.add(ghost, f0, -L.c), R.add(ghost, f1, -L.p);
}

/// The boundary rows of column j: the wall's no slip, and on R zero velocity where the base flows in,
/// p = 0 and ∂u/∂r = 0 where it flows out.
void boundary_rows(Rows& R, const SpanwiseOutflow& out, int j, double U) {
  const Mac& m = R.m;
  const int N = m.N;
  auto fix = [&](long row, double s) { R.add(row, row, 1.0), R.scale[size_t(row)] = s; };
  fix(m.u(0, j), 1.0 / U);
  fix(m.pr(-1, j), 1.0 / (U * U));  // unused
  for (const bool is_v : {true, false}) {
    auto f = [&](int c) { return is_v ? m.v(c, j) : m.w(c, j); };
    zero_ghost(R, f(-1), f(0), f(1), m.ghost_wall);
    R.scale[size_t(f(-1))] = R.scale[size_t(f(N))] = 1.0 / U;
    if (is_v ? out.v[size_t(j)] : out.u[size_t(j)])
      R.add(f(N), f(N), 1.0), R.add(f(N), f(N - 1), -1.0);
    else
      zero_ghost(R, f(N), f(N - 1), f(N - 2), m.ghost_outer);
  }
  R.scale[size_t(m.u(N + 1, j))] = 1.0 / U, R.scale[size_t(m.pr(N, j))] = 1.0 / (U * U);
  if (out.u[size_t(j)]) {
    R.add(m.u(N + 1, j), m.u(N + 1, j), 1.0), R.add(m.u(N + 1, j), m.u(N - 1, j), -1.0);
    R.add(m.pr(N, j), m.pr(N, j), 1.0), R.add(m.pr(N, j), m.pr(N - 1, j), 1.0);  // p = 0 on R: the mean
  } else {
    fix(m.u(N, j), 1.0 / U), fix(m.u(N + 1, j), 1.0 / U), fix(m.pr(N, j), 1.0 / (U * U));
  }
}

/// The grid's nested-dissection order of the slots (grid_order over n_r + 1 rings), each slot's four
/// unknowns together.
std::vector<long> slot_order(const Mac& m) {
  const std::vector<long> two = grid_order(m.N + 2, m.n, false);
  const long slots = long(m.N + 2) * m.n;
  std::vector<long> order;
  order.reserve(size_t(kSpanwiseFields * slots));
  for (long e : two)
    if (e < 2 * slots && e % 2 == 0)
      for (int f = 0; f < kSpanwiseFields; ++f) order.push_back(kSpanwiseFields * (e / 2) + f);
  return order;
}

/// Where x falls in the increasing xs: the index i below it and the weight w = (x − xs_i)/(xs_{i+1} − xs_i)
/// of the one above; below xs[0]: (0, 0); above the last: index −1 (outside).
std::pair<int, double> bracket(const std::vector<double>& xs, double x) {
  if (x <= xs.front()) return {0, 0.0};
  if (x > xs.back()) return {-1, 0.0};
  const int i = int(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
  if (i >= int(xs.size()) - 1) return {int(xs.size()) - 2, 1.0};
  return {i, (x - xs[size_t(i)]) / (xs[size_t(i) + 1] - xs[size_t(i)])};
}

}  // namespace

long spanwise_unknowns(int n_r, int n_theta) { return kSpanwiseFields * long(n_r + 1) * n_theta; }

std::vector<double> spanwise_prolong(const PolarGrid& from, const PolarGrid& to,
                                     const std::vector<double>& x) {
  const Mac a(from), b(to);
  if (long(x.size()) != a.unknowns())
    throw std::invalid_argument("spanwise_prolong: x does not match its grid");
  std::vector<double> y(size_t(b.unknowns()), 0.0);
  for (int f = 0; f < kSpanwiseFields; ++f) {
    const bool ring = f == kU;  // u_r on the rings, the rest at the centres (slot s: centre s − 1)
    const std::vector<double>& xa = ring ? a.xf : a.xc;
    const std::vector<double>& xb = ring ? b.xf : b.xc;
    const double off = f == kV ? 0.0 : 0.5;  // u_θ at θ_j, the rest at θ_{j+½}
    for (int s = 0; s < b.N + 2; ++s) {
      auto [i, wi] = bracket(xa, xb[size_t(s)]);
      if (i < 0 || (f == kP && s == 0))
        continue;                       // beyond the last point of `from`; the wall slot's unused p
      if (f == kP && i == 0) wi = 1.0;  // p has no point at the wall slot: centre 0's value below it
      for (int j = 0; j < b.n; ++j) {
        const double t = (double(j) + off) * b.k / a.k - off;
        const int j0 = int(std::floor(t));
        const double wj = t - double(j0);
        auto at = [&](int si, int jj) { return x[size_t(a.at(si, jj, f))]; };
        const double lo = (1.0 - wj) * at(i, j0) + wj * at(i, j0 + 1);
        const double hi = (1.0 - wj) * at(i + 1, j0) + wj * at(i + 1, j0 + 1);
        y[size_t(b.at(s, j, f))] = (1.0 - wi) * lo + wi * hi;
      }
    }
  }
  return y;
}

SpanwiseOutflow spanwise_outflow(const NsParams& p, const NsState& base) {
  const PolarGrid g = ns_grid(p);
  if (base.psi.size() != size_t(g.nodes())) throw std::invalid_argument("spanwise_outflow: the state does not match the grid");
  const int n = g.n_theta;
  const double* ps = base.psi.data() + size_t(g.n_r - 1) * n;
  SpanwiseOutflow out;
  for (int j = 0; j < n; ++j) {
    out.u.push_back(outflow(p, (ps[(j + 1) % n] - ps[j]) / g.d_theta));
    out.v.push_back(outflow(p, psi_theta(ps, j, n, g.d_theta)));
  }
  return out;
}

EigenProblem spanwise_problem(const NsParams& p, const NsState& base, double beta) {
  return spanwise_problem(p, base, beta, spanwise_outflow(p, base));
}

EigenProblem spanwise_problem(const NsParams& p, const NsState& base, double beta, const SpanwiseOutflow& out) {
  if (!(beta >= 0.0) || !std::isfinite(beta))
    throw std::invalid_argument("spanwise_problem: the wavenumber β must be finite and ≥ 0 (got " +
                                std::to_string(beta) + ")");
  const PolarGrid g = ns_grid(p);
  if (base.psi.size() != size_t(g.nodes()) || out.u.size() != size_t(g.n_theta) || out.v.size() != out.u.size())
    throw std::invalid_argument("spanwise_problem: the state does not match the grid");
  const Mac m(g);
  const MacBase b(m, g, base, p.omega);
  const double U = stability_speed(p), s_mom = p.a / (U * U);
  EigenProblem ep;
  ep.n = m.unknowns();
  Rows R{m, b, p.nu, beta, {}, {}, {}, std::vector<double>(size_t(ep.n), 0.0), std::vector<double>(size_t(ep.n), 0.0), &p};
  // With no outflow column (a closed box) and β = 0 the pressure is free up to a constant: p = 0 in one cell
  // instead of that cell's continuity (redundant there: the sum of all the others).
  bool closed = beta == 0.0;
  for (char o : out.u) closed = closed && !o;
  for (int j = 0; j < m.n; ++j) {
    for (int i = 1; i < m.N; ++i) radial_momentum(R, i, j), R.dynamic(m.u(i, j), s_mom);
    if (out.u[size_t(j)]) radial_momentum(R, m.N, j), R.dynamic(m.u(m.N, j), s_mom);
    for (int c = 0; c < m.N; ++c) {
      azimuthal_momentum(R, c, j), R.dynamic(m.v(c, j), s_mom);
      spanwise_momentum(R, c, j), R.dynamic(m.w(c, j), s_mom);
      R.scale[size_t(m.pr(c, j))] = p.a / U;
      if (!(closed && c == 0 && j == 0)) continuity(R, c, j);
    }
    boundary_rows(R, out, j, U);
  }
  if (closed) R.add(m.pr(0, 0), m.pr(0, 0), 1.0), R.scale[size_t(m.pr(0, 0))] = 1.0 / (U * U);
  for (size_t t = 0; t < R.tx.size(); ++t) {
    const int f = int(R.tj[t] % kSpanwiseFields);
    R.tx[t] *= R.scale[size_t(R.ti[t])] * (f == kP ? U * U : U);
  }
  ep.m.resize(size_t(ep.n));
  for (long r = 0; r < ep.n; ++r) ep.m[size_t(r)] = R.mass[size_t(r)] * R.scale[size_t(r)] * U;
  compress_triplets(ep.n, R.ti, R.tj, R.tx, ep.Ap, ep.Ai, ep.Ax);
  ep.order = slot_order(m);
  return ep;
}

StabilityResult spanwise_eigenvalues(const NsParams& p, const NsState& steady, double beta, int count,
                                     const StabilityOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  check_stability_options(count, o);
  const EigenProblem ep = spanwise_problem(p, steady, beta);
  const double unit = stability_speed(p) / (2.0 * p.a);  // U/D in 1/s
  // Every velocity component gains −νβ² (spanwise diffusion), so the spectrum moves left by about that much,
  // and the shifts with it: at Re 40, β·D = 4 it is 0.4 U/D, and shifts left at 0.1 U/D converged nothing.
  StabilityOptions shifted = o;
  bool left = false;  // a shift moved left of the imaginary axis
  for (std::complex<double>& s : shifted.shifts) s -= p.nu * beta * beta / unit, left = left || s.real() < 0.0;
  StabilityResult res = search_eigenvalues(ep, unit, count, shifted, 0, kSpanwiseFields);
  // A disk centred left of the axis that reaches it says nothing of what lies right of it: no coverage claimed.
  if (left) res.covered = false;
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace magnus
