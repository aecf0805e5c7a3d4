// The spanwise (e^{iβz}) stability problem of spanwise.hpp: the 2D problem's entries moved to five unknowns
// per node, then the β-terms, the potential φ, the spanwise velocity w̃ and the pressure p. Every row is
// scaled to be dimensionless as the 2D rows are (ψ and φ by 1/(U a), ζ by a/U, w̃ by 1/U, p by 1/U², each
// ring's rows times h_i² as the 2D ones).
#include "solver/navier_stokes/spanwise.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/fd_weights.hpp"
#include "solver/navier_stokes/arakawa.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/stages.hpp"

namespace magnus {

namespace {

enum Field { kPsi = 0, kZeta = 1, kPhi = 2, kW = 3, kP = 4 };

/// The base state's fields and the derivatives the linearisation needs, row-major (n_r, n_θ).
struct Base {
  std::vector<double> Psi, Omega;    ///< Ψ (m²/s), Ω (1/s)
  std::vector<double> U_r, U_theta;  ///< velocity, m/s (ns_velocity)
};

/// The triplets of J, the grid and the scales; stencils of one field at a node add to a row through it.
struct Builder {
  const PolarGrid& g;
  const NsParams& p;
  double beta;
  int n, N;  ///< columns; the outer ring's index n_r − 1
  double s_psi, s_zeta, s_w, s_p;
  RadialDerivative d;  ///< ∂/∂ξ, second order: centred inside, one-sided at the wall and on R
  std::vector<long> ti, tj;
  std::vector<double> tx;

  long at(int i, int j, int field) const { return long(kSpanwiseFields) * (long(i) * n + wrap(j)) + field; }
  int wrap(int j) const { return j < 0 ? j + n : j >= n ? j - n : j; }
  size_t node(int i, int j) const { return size_t(i) * n + size_t(wrap(j)); }
  void add(long row, long col, double v) {
    if (v != 0.0) ti.push_back(row), tj.push_back(col), tx.push_back(v);
  }
  /// coef·∂f/∂ξ at (i, j) of the field's unknowns.
  void add_xi(long row, int i, int j, int field, double coef) {
    const std::vector<double>& w = d.weights[size_t(i)];
    for (size_t k = 0; k < w.size(); ++k) add(row, at(d.first[size_t(i)] + int(k), j, field), coef * w[k]);
  }
  /// coef·∂f/∂θ at (i, j), centred.
  void add_theta(long row, int i, int j, int field, double coef) {
    add(row, at(i, j + 1, field), coef / (2.0 * g.d_theta));
    add(row, at(i, j - 1, field), -coef / (2.0 * g.d_theta));
  }
  /// coef·∂²f/∂ξ² at ring 1 ≤ i ≤ N − 1 (compact: the Laplacian's flux form over h_i²) and coef·∂²f/∂θ²
  /// (compact), coef·∂²f/∂ξ∂θ (centred in both).
  void add_xi_xi(long row, int i, int j, int field, double coef) {
    const XiFlux xf = xi_flux(g, i);
    const double c = coef / (xf.h * xf.h);
    add(row, at(i + 1, j, field), c * xf.c_p), add(row, at(i - 1, j, field), c * xf.c_m);
    add(row, at(i, j, field), -c * (xf.c_m + xf.c_p));
  }
  void add_theta_theta(long row, int i, int j, int field, double coef) {
    const double c = coef / (g.d_theta * g.d_theta);
    add(row, at(i, j + 1, field), c), add(row, at(i, j - 1, field), c), add(row, at(i, j, field), -2.0 * c);
  }
  void add_xi_theta(long row, int i, int j, int field, double coef) {
    add_xi(row, i, j + 1, field, coef / (2.0 * g.d_theta));
    add_xi(row, i, j - 1, field, -coef / (2.0 * g.d_theta));
  }
  /// ∂f/∂ξ and ∂f/∂θ of a base field at (i, j).
  double xi_of(const std::vector<double>& f, int i, int j) const {
    const std::vector<double>& w = d.weights[size_t(i)];
    double s = 0.0;
    for (size_t k = 0; k < w.size(); ++k) s += w[k] * f[node(d.first[size_t(i)] + int(k), j)];
    return s;
  }
  double theta_of(const std::vector<double>& f, int i, int j) const {
    return (f[node(i, j + 1)] - f[node(i, j - 1)]) / (2.0 * g.d_theta);
  }
  /// The 5-point Laplacian of the field at ring 1 ≤ i ≤ N − 1, times h_i² (flux form) and coef.
  void add_laplacian(long row, int i, int j, int field, double coef) {
    const double h = g.ring_width(i);
    add_xi_xi(row, i, j, field, coef * h * h), add_theta_theta(row, i, j, field, coef * h * h);
  }
  /// h_i² J_i of ring i (its rows are scaled by h_i², ring_width) times coef: the shift −β²J, the couplings.
  double h2J(int i, double coef) const {
    const double h = g.ring_width(i);
    return coef * h * h * g.r[size_t(i)] * g.r[size_t(i)];
  }
  /// The same on the wall ring with the Neumann condition's mirror ghost f_{−1} = f_1 (its data apart),
  /// times h_0²: 2(f_1 − f_0) + (h_0/Δθ)²(f_e − 2f_0 + f_w).
  void add_wall_laplacian(long row, int j, int field, double coef) {
    const double h = g.d_xi(0), q2 = (h / g.d_theta) * (h / g.d_theta);
    add(row, at(1, j, field), 2.0 * coef), add(row, at(0, j, field), coef * (-2.0 - 2.0 * q2));
    add(row, at(0, j + 1, field), coef * q2), add(row, at(0, j - 1, field), coef * q2);
  }
};

/// The 2D problem's entries and mass on the (ψ, ζ, Γ_R) unknowns of the five-field numbering.
void move_2d(Builder& b, const EigenProblem& two, std::vector<double>& m) {
  const long nodes2 = two.n - 1;  // 2·nodes
  auto moved = [&](long k) { return k == nodes2 ? long(kSpanwiseFields) * (nodes2 / 2) : kSpanwiseFields * (k / 2) + k % 2; };
  for (long c = 0; c < two.n; ++c) {
    for (long t = two.Ap[size_t(c)]; t < two.Ap[size_t(c) + 1]; ++t)
      b.add(moved(two.Ai[size_t(t)]), moved(c), two.Ax[size_t(t)]);
    m[size_t(moved(c))] = two.m[size_t(c)];
  }
}

/// The β-terms of the ζ rows (rings 1…N−1): −ν β² J ζ, and the potential part's advection of Ω with the
/// stretching β J Ω w̃, together −∇·(Ω∇φ) in flux form (the rows are (h²/ν)·(…)·s_ζ as in 2D); the wall
/// closure's slip φ_θ; the circulation's −νβ²Γ_R and −φ_ξ Ω.
/// The flux form is the discrete identity −∇φ·∇Ω + βΩw̃ = −∇·(Ω∇φ) (∇²φ = −βw̃ with the same compact
/// Laplacian): written as the centred product plus the stretching, the two did not cancel where the
/// shear layers are under-resolved in θ, and a spurious stationary mode grew in the Re 40 wake (+0.029
/// U/D at n_θ 48, +0.012 at 64; the flux form: −0.0097 and −0.0099, the slow far-field modes leading).
void vorticity_terms(Builder& b, const Base& base) {
  const PolarGrid& g = b.g;
  const double nu = b.p.nu, beta = b.beta;
  for (int i = 1; i < b.N; ++i) {
    const double h = g.ring_width(i);
    for (int j = 0; j < b.n; ++j) {
      const long row = b.at(i, j, kZeta);
      b.add(row, row, -b.h2J(i, beta * beta * b.s_zeta));
      // −(φ_ξΩ_ξ + φ_θΩ_θ) + βJΩw̃ = −[(Ωφ_ξ)_ξ + (Ωφ_θ)_θ] with ∇²φ = −βJw̃: the flux form, Ω at the faces.
      const XiFlux xf = xi_flux(g, i);
      const double q2 = (h / g.d_theta) * (h / g.d_theta), cf = -b.s_zeta / nu;
      const double O = base.Omega[b.node(i, j)];
      const double Op = 0.5 * (O + base.Omega[b.node(i + 1, j)]), Om = 0.5 * (O + base.Omega[b.node(i - 1, j)]);
      const double Oe = 0.5 * (O + base.Omega[b.node(i, j + 1)]), Ow = 0.5 * (O + base.Omega[b.node(i, j - 1)]);
      b.add(row, b.at(i + 1, j, kPhi), cf * xf.c_p * Op), b.add(row, b.at(i - 1, j, kPhi), cf * xf.c_m * Om);
      b.add(row, b.at(i, j, kPhi), -cf * (xf.c_p * Op + xf.c_m * Om + q2 * (Oe + Ow)));
      b.add(row, b.at(i, j + 1, kPhi), cf * q2 * Oe), b.add(row, b.at(i, j - 1, kPhi), cf * q2 * Ow);
    }
  }
  // The closure's row c_1ψ_1 − c_2ψ_2 + c_w ζ_w = κ h_0 ψ_ξ|wall, its slip ψ_ξ = φ_θ (2D: −a²ω).
  const WallClosureRow wc = wall_closure_row(g, b.p);
  for (int j = 0; j < b.n; ++j) b.add_theta(b.at(0, j, kZeta), 0, j, kPhi, -wc.kappa * g.d_xi(0) * b.s_psi);
  const long gamma = long(kSpanwiseFields) * g.nodes();
  const double hN = g.d_xi(b.N - 1), ff = hN / (2.0 * M_PI * nu) * b.s_zeta;
  b.add(gamma, gamma, -nu * beta * beta * ff);
  for (int j = 0; j < b.n; ++j) b.add_xi(gamma, b.N, j, kPhi, -base.Omega[b.node(b.N, j)] * g.d_theta * ff);
}

/// φ: ∇²φ = −βw̃ inside, φ_ξ = 0 on the wall, φ = 0 on R (rows times s_ψ).
void potential_rows(Builder& b) {
  for (int j = 0; j < b.n; ++j) {
    b.add_wall_laplacian(b.at(0, j, kPhi), j, kPhi, b.s_psi);
    b.add(b.at(b.N, j, kPhi), b.at(b.N, j, kPhi), b.s_psi);
  }
  for (int i = 1; i < b.N; ++i)
    for (int j = 0; j < b.n; ++j) {
      b.add_laplacian(b.at(i, j, kPhi), i, j, kPhi, b.s_psi);
      b.add(b.at(i, j, kPhi), b.at(i, j, kW), b.h2J(i, b.beta * b.s_psi));
    }
}

/// w̃: J w̃_t = −{Ψ, w̃} + βJp + ν(∇²w̃ − β²Jw̃) inside (rows (h²/ν)·(…)·s_w, mass s_w h² J/ν); 0 on the wall;
/// on R 0 on inflow and convected out on outflow, as ζ.
void spanwise_velocity_rows(Builder& b, const Base& base, std::vector<double>& m) {
  const PolarGrid& g = b.g;
  const NsParams& p = b.p;
  for (int i = 1; i < b.N; ++i) {
    const double h = g.ring_width(i), J = g.r[size_t(i)] * g.r[size_t(i)];
    const double cN = -h * h / p.nu / (12.0 * g.d_theta * h) * b.s_w;  // of −(h²/ν)·{Ψ, w̃}, as the 2D rows
    AdvectionStride st[2];
    const int terms = p.stokes ? 0 : advection_terms(p.advection_order, p.advection_order_xi, i, g.n_r, st);
    for (int j = 0; j < b.n; ++j) {
      const long row = b.at(i, j, kW);
      b.add_laplacian(row, i, j, kW, b.s_w);
      b.add(row, row, -h * h * b.beta * b.beta * J * b.s_w);
      b.add(row, b.at(i, j, kP), h * h / p.nu * b.beta * J * b.s_w);
      for (int q = 0; q < terms; ++q)
        for (const ArakawaTerm& t : kArakawa) {
          const int s = st[q].s_theta, sx = st[q].s_xi;
          b.add(row, b.at(i + sx * t.zi, j + s * t.zj, kW),
                cN * st[q].weight * t.c * base.Psi[b.node(i + sx * t.pi, j + s * t.pj)]);
        }
      m[size_t(row)] = b.s_w * h * h * J / p.nu;
    }
  }
  const double hN = g.d_xi(b.N - 1), R = g.outer_radius();
  for (int j = 0; j < b.n; ++j) {
    b.add(b.at(0, j, kW), b.at(0, j, kW), b.s_w);
    const long row = b.at(b.N, j, kW);
    b.add(row, row, b.s_w);
    const double p_theta = b.theta_of(base.Psi, b.N, j);
    if (outflow(p, p_theta)) {
      b.add(row, b.at(b.N - 1, j, kW), -b.s_w);
      m[size_t(row)] = -b.s_w * hN * R * R / p_theta;
    }
  }
}

/// 2S = 2J tr(∇U·∇u) at (i, j) times coef into row. With u_r = (ψ_θ + φ_ξ)/r, u_θ = (φ_θ − ψ_ξ)/r:
///     r u_r,ξ = ψ_ξθ + φ_ξξ − ψ_θ − φ_ξ,        r u_θ,ξ = φ_ξθ − ψ_ξξ − φ_θ + ψ_ξ,
///     r (u_r,θ − u_θ) = ψ_θθ + φ_ξθ − φ_θ + ψ_ξ, r (u_θ,θ + u_r) = φ_θθ − ψ_ξθ + ψ_θ + φ_ξ,
/// the pure second derivatives compact, as in the Laplacians (the differences of centred differences
/// skip every other node: on n_θ 48 they let a spurious stationary mode grow in the Re 40 wake). On the
/// wall (u = 0, ψ_ξ = φ_θ, φ_ξ = 0, ψ_ξξ = −a²ζ_w) only r u_θ,ξ = a²ζ_w is left.
void add_strain_product(Builder& b, const Base& base, long row, int i, int j, double coef) {
  const double Ur_xi = b.xi_of(base.U_r, i, j), Ur_th = b.theta_of(base.U_r, i, j);
  const double Ut_xi = b.xi_of(base.U_theta, i, j), Ut_th = b.theta_of(base.U_theta, i, j);
  const double Ur = base.U_r[b.node(i, j)], Ut = base.U_theta[b.node(i, j)];
  const double r = b.g.r[size_t(i)], c = 2.0 * coef / r;
  const double A[4] = {c * Ur_xi, c * (Ur_th - Ut), c * Ut_xi, c * (Ut_th + Ur)};
  if (i == 0) {
    b.add(row, b.at(0, j, kZeta), A[1] * r * r);
    return;
  }
  b.add_xi_theta(row, i, j, kPsi, A[0] - A[3]), b.add_xi_xi(row, i, j, kPhi, A[0]);
  b.add_theta(row, i, j, kPsi, A[3] - A[0]), b.add_xi(row, i, j, kPhi, A[3] - A[0]);
  b.add_xi_theta(row, i, j, kPhi, A[1] + A[2]), b.add_xi_xi(row, i, j, kPsi, -A[1]);
  b.add_theta(row, i, j, kPhi, -A[1] - A[2]), b.add_xi(row, i, j, kPsi, A[1] + A[2]);
  b.add_theta_theta(row, i, j, kPsi, A[2]), b.add_theta_theta(row, i, j, kPhi, A[3]);
}

/// p: ∇²p − β²Jp = −2S inside; on the wall p_ξ = −ν(ζ_θ + βw̃_ξ) through the mirror ghost; 0 on R
/// (rows times h_i²·s_p).
void pressure_rows(Builder& b, const Base& base) {
  const PolarGrid& g = b.g;
  const double h0 = g.d_xi(0), a2 = g.r[0] * g.r[0];
  for (int j = 0; j < b.n; ++j) {
    const long row = b.at(0, j, kP);
    b.add_wall_laplacian(row, j, kP, b.s_p);
    b.add(row, row, -h0 * h0 * b.beta * b.beta * a2 * b.s_p);
    add_strain_product(b, base, row, 0, j, h0 * h0 * b.s_p);
    // −2h_0·p_ξ = 2h_0 ν (ζ_θ + β w̃_ξ)
    b.add_theta(row, 0, j, kZeta, 2.0 * h0 * b.p.nu * b.s_p);
    b.add_xi(row, 0, j, kW, 2.0 * h0 * b.p.nu * b.beta * b.s_p);
    b.add(b.at(b.N, j, kP), b.at(b.N, j, kP), b.s_p);
  }
  for (int i = 1; i < b.N; ++i)
    for (int j = 0; j < b.n; ++j) {
      const long row = b.at(i, j, kP);
      b.add_laplacian(row, i, j, kP, b.s_p);
      b.add(row, row, -b.h2J(i, b.beta * b.beta * b.s_p));
      add_strain_product(b, base, row, i, j, g.ring_width(i) * g.ring_width(i) * b.s_p);
    }
}

/// The grid's nested-dissection order (grid_order: ψ, ζ pairs per node, then Γ_R) with each node's five
/// unknowns kept together.
std::vector<long> five_field_order(const std::vector<long>& two, long nodes) {
  std::vector<long> order;
  order.reserve(size_t(kSpanwiseFields * nodes + 1));
  for (long e : two) {
    if (e == 2 * nodes)
      order.push_back(kSpanwiseFields * nodes);
    else if (e % 2 == 0)
      for (int f = 0; f < kSpanwiseFields; ++f) order.push_back(kSpanwiseFields * (e / 2) + f);
  }
  return order;
}

}  // namespace

EigenProblem spanwise_problem(const NsParams& p, const NsState& steady, double beta) {
  if (!(beta >= 0.0) || !std::isfinite(beta))
    throw std::invalid_argument("spanwise_problem: the wavenumber β must be finite and ≥ 0 (got " +
                                std::to_string(beta) + ")");
  const EigenProblem two = stability_problem(p, steady);
  const PolarGrid g = ns_grid(p);
  const long nodes = g.nodes();
  const double speed = stability_speed(p);
  Builder b{g, p, beta, g.n_theta, g.n_r - 1, 1.0 / (speed * p.a), p.a / speed, 1.0 / speed,
            1.0 / (speed * speed), radial_derivative(g.xi, 2, false), {}, {}, {}};
  Base base{steady.psi, steady.zeta, {}, {}};
  ns_velocity(g, steady.psi, base.U_r, base.U_theta);

  EigenProblem ep;
  ep.n = kSpanwiseFields * nodes + 1;
  ep.m.assign(size_t(ep.n), 0.0);
  move_2d(b, two, ep.m);
  vorticity_terms(b, base);
  potential_rows(b);
  spanwise_velocity_rows(b, base, ep.m);
  pressure_rows(b, base);
  compress_triplets(ep.n, b.ti, b.tj, b.tx, ep.Ap, ep.Ai, ep.Ax);
  // Every row reaches one ring and one column (the advection of order 4 two): the 2D problem's cuts.
  ep.order = five_field_order(two.order, nodes);
  return ep;
}

StabilityResult spanwise_eigenvalues(const NsParams& p, const NsState& steady, double beta, int count,
                                     const StabilityOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  check_stability_options(count, o);
  const EigenProblem ep = spanwise_problem(p, steady, beta);
  const double unit = stability_speed(p) / (2.0 * p.a);  // U/D in 1/s
  StabilityResult res = search_eigenvalues(ep, unit, count, o, steady.psi.size(), kSpanwiseFields);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace magnus
