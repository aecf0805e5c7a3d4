#pragma once
// 2D incompressible laminar Navier–Stokes past the spinning cylinder, vorticity–streamfunction
// on the log-polar grid ξ = ln(r/a) (uniform Δξ, or rings clustered at the wall: ns_grid), J = r²:
//     ψ_ξξ + ψ_θθ = −J ζ,     J ζ_t + ψ_θ ζ_ξ − ψ_ξ ζ_θ = ν (ζ_ξξ + ζ_θθ),     u_r = ψ_θ/r, u_θ = −ψ_ξ/r.
//
// Time step (AB2/CN): the advection N = ψ_θ ζ_ξ − ψ_ξ ζ_θ is Arakawa's Jacobian (energy and enstrophy
// conserving) extrapolated by Adams–Bashforth 2; diffusion is Crank–Nicolson, so per step
//     ζ^{n+1}_ξξ + ζ^{n+1}_θθ − σ_i ζ^{n+1} = −σ_i ζ^n − Lζ^n + (2/ν)·N^{n+1/2},    σ_i = 2 J_i/(ν Δt),
// one ModeSolver (Helmholtz shift per ring), then the Poisson solve for ψ^{n+1} (a second ModeSolver).
//
// Wall (ring 0), no slip: ψ = 0 (Dirichlet) and ψ_ξ = −a²ω. The second condition is imposed through the
// Poisson equation on the wall ring with the centred derivative on a ghost ring ψ_{−1} = ψ_1 + 2Δξ a²ω:
//     (ψ_1 − 2ψ_0 + ψ_{−1})/Δξ² + (ψ_0)_θθ = −a² ζ_w   ⇔   ψ_1 + (a²Δξ²/2)·ζ_w = −Δξ a²ω        (Thom).
// ζ_w^{n+1} is the unknown that makes it hold at t^{n+1}: per Fourier mode k, ζ^{n+1} = ζ* + ζ̂_w,k φ_k and
// ψ^{n+1} = ψ* + ζ̂_w,k χ_k (φ_k: Helmholtz response to unit wall vorticity, χ_k: its ψ), so the closure is
// one scalar per mode:  ζ̂_w,k = (−Δξ a²ω δ_k0 − ψ̂*_{1,k}) / (χ_k(ξ_1) + a²Δξ²/2).  Exact at every step.
// Δξ here is the wall's spacing Δξ_0 = ξ_1 − ξ_0; inside, ξ-derivatives take the mode solver's flux form.
// NsWallClosure::jensen replaces the row by Jensen's (Briley's) second-order one, from Taylor series with
// ψ_0 = 0, ψ_ξ = −a²ω, ψ_ξξ = −a²ζ_w and ψ_ξξξ eliminated with two rings (uniform ξ):
// 8ψ_1 − ψ_2 + 2Δξ²a²ζ_w = −6Δξ a²ω; still one scalar per mode (wall_closure_row, stages.hpp).
//
// Far field at R: ψ_ξ = U R sinθ − Γ_R/(2π) (Neumann: the freestream's tangential velocity, the normal
// velocity free so the wake's displacement flux can leave), with Γ_R the circulation on r = R, advanced
// (AB2) by the exact balance dΓ_R/dt = ∮ (−u_r ζ + ν ∂ζ/∂r) R dθ. This is mode 0: the wall and the
// vorticity inside decide it, nothing imposes it. Vorticity at R: ζ = 0 where u_r < 0 (inflow); where the
// wake leaves, the convective condition ζ_t + (u_r/r) ζ_ξ = 0, i.e. ζ_t + (ψ_θ/J) ζ_ξ = 0 (explicit upwind).
// An absorbing layer (NsParams::absorbing_start) adds −J λ(r) ζ to the right of the vorticity equation:
// Crank–Nicolson with the diffusion (a ring-dependent addition s_i = J_i λ_i/ν to the Helmholtz shift), and
// −∫∫ λ ζ dA to dΓ_R/dt, the circulation it removes.
#include <chrono>
#include <memory>
#include <stdexcept>
#include <vector>

#include "mesh/polar_grid.hpp"
#include "solver/mode_solver.hpp"

namespace magnus {

/// Vorticity on the outer ring: ζ = 0 on inflow and convected out on outflow (default), or ζ = 0 all round.
enum class NsOuterVorticity { inflow_outflow, zero };

/// The wall's no-slip closure: Thom's ψ_1 + (a²h²/2)·ζ_w = −h a²ω (first order in ζ_w) or Jensen's
/// 8ψ_1 − ψ_2 + 2h²a²ζ_w = −6h a²ω (second order; wall_closure_row gives both on any two spacings).
enum class NsWallClosure { thom, jensen };

/// The viscous scene and its grid (SI). Re = U·2a/ν. The case-file keys map onto this.
struct NsParams {
  double a = 0.5;               ///< cylinder radius, m
  double U = 1.0;               ///< freestream speed towards +x, m/s
  double omega = 0.0;           ///< spin, rad/s, counter-clockwise positive (α = aω/U)
  double nu = 0.01;             ///< kinematic viscosity, m²/s
  double outer_over_a = 100.0;  ///< R/a; 100 (50 D): C_L, C_D, St move < 0.05% when it doubles
  int n_theta = 192;            ///< points in θ (even)
  /// Rings; 0: Δξ = Δθ/radial_refinement (R kept). At Re 100, α = 1 the mean forces depend on Δξ and
  /// hardly on Δθ (n_θ 128 → 256 moved C_D by 0.06%), while St gains 0.25% from 128 to 192; so the
  /// default is n_θ = 192 with cells 5/3 finer in ξ, Δξ = 2π/320: n_r = 236 at R = 100a.
  int n_r = 0;
  double radial_refinement = 5.0 / 3.0;  ///< Δθ/Δξ when n_r = 0 (1: square cells)
  double wall_refinement = kNsDefaultWallRefinement;  ///< Δξ_far/Δξ_wall ≥ 1 (1: uniform ξ, today's geometric grid)
  double wall_layer = kNsDefaultWallLayer;  ///< ξ-length over which Δξ relaxes from the wall's to the far value
  double dt = 0.0;                       ///< time step, s; 0: from the CFL number
  /// Target CFL number Δt·max(|ψ_θ|/(JΔξ) + |ψ_ξ|/(JΔθ)). The forces do not depend on it (CFL 0.35,
  /// 0.4, 0.5, 0.7 gave the same means to 1e-5 at Re 100, α = 1): the largest safe value below the limit.
  double cfl = 0.7;
  /// Threads for the advection and the mode solves (a persistent pool). 1 by default: on this 2-core
  /// machine a second thread gained about 4% on a whole run at Re 100, n_θ = 128 (8.3 s against 8.6 s).
  int threads = 1;
  bool stokes = false;  ///< drop the advection (unsteady Stokes flow, the creeping limit)
  /// Order of the advection term in θ: 2 (Arakawa's Jacobian) or 4 (its fourth-order-in-θ combination,
  /// solver/navier_stokes/arakawa.hpp). At Re 100, α = 1 order 4 takes St from −0.97% to
  /// −0.82% of Stojković et al. on the default grid, the value order 2 reaches only at n_θ = 512.
  int advection_order = 2;
  /// Order of the advection term in ξ: 2 or 4 (the fourth-order combination in ξ, solver/navier_stokes/arakawa.hpp; second
  /// order on the rings next to the wall and the outer ring). Behind the body ξ is the wake's streamwise
  /// direction, and the wake beyond r = 10a sets the last 0.3% of St at Re 100, α = 1.
  int advection_order_xi = 2;
  NsOuterVorticity outer_vorticity = NsOuterVorticity::inflow_outflow;
  NsWallClosure wall_closure = NsWallClosure::thom;  ///< the wall's ζ_w row: Thom's or Jensen's (stages.hpp)
  /// The wall's spin in the time step: its potential vortex ψ_ref = −a²ω ξ advected by Crank–Nicolson with
  /// the diffusion, the rest by AB2 (rotation.hpp), so the spin does not shrink Δt; false: all by AB2.
  bool implicit_rotation = true;
  /// The absorbing layer: beyond r_s = absorbing_start·a the vorticity equation gains the sink −λ(r) ζ,
  ///     λ(r) = absorbing_rate·((r − r_s)/(R − r_s))²   (1/s),
  /// so the wake's vortices fade before they reach R, where the outflow condition reflects them; the
  /// circulation they take away leaves Γ_R too (circulation_flux). 0: no layer (the default).
  double absorbing_start = 0.0;  ///< r_s/a, 1 < r_s/a < R/a, or 0 (none)
  double absorbing_rate = 0.0;   ///< λ at R, 1/s

  /// Re = U·2a/ν (0 when U = 0).
  double reynolds() const { return nu > 0.0 ? U * 2.0 * a / nu : 0.0; }
};

/// The CFL number above which advance() refuses to step (AB2 with centred advection: its stability
/// region on the imaginary axis is thin; diffusion is implicit and sets no limit).
constexpr double kNsCflLimit = 0.8;

/// The state of the AB2/CN scheme at time t: fields (n_r, n_θ) row-major, ring 0 = wall.
struct NsState {
  std::vector<double> psi;       ///< ψ, m²/s
  std::vector<double> zeta;      ///< ζ = −∇²ψ, 1/s (ring 0: the wall vorticity ζ_w)
  double t = 0.0;                ///< time, s
  double Gamma_R = 0.0;          ///< circulation on r = R, m²/s
  std::vector<double> N_prev;    ///< advection N^{n−1} (empty: first step, AB2 starts with Euler)
  double Gamma_flux_prev = 0.0;  ///< dΓ_R/dt at t^{n−1}, m²/s²
  double dt_prev = 0.0;          ///< Δt of the previous step, s
  /// The rate r of the state the last step started from (CFL number = r·Δt, as advance() checks it), 1/s;
  /// 0 before a step. A cheap estimate of this state's rate: the velocity moves little in one step.
  double rate_prev = 0.0;
};

/// Wall seconds spent in each part of the time steps (summed over steps; advance() adds to it).
struct NsStepTimes {
  double advection = 0.0;  ///< Arakawa's Jacobian and the Crank–Nicolson right-hand side
  double helmholtz = 0.0;  ///< the implicit diffusion solve for ζ (its FFTs and mode solves)
  double poisson = 0.0;    ///< the Poisson solve for ψ (its mode solves and inverse FFT)
  double wall = 0.0;       ///< the wall closure (influence-matrix correction per mode)
  double other = 0.0;      ///< boundary data, circulation, checks, copies
  double forces = 0.0;     ///< forces and coefficients per step (filled by run_unsteady)
  long steps = 0;
  double total() const { return advection + helmholtz + poisson + wall + other + forces; }
  NsStepTimes& operator+=(const NsStepTimes& o) {
    advection += o.advection, helmholtz += o.helmholtz, poisson += o.poisson, wall += o.wall;
    other += o.other, forces += o.forces, steps += o.steps;
    return *this;
  }
};

/// Adds the wall seconds of its lifetime to *sum (a part of a step's cost, NsStepTimes); null: no clock read.
class ScopedTimer {
 public:
  explicit ScopedTimer(double* sum) : sum_(sum) {
    if (sum_) t0_ = clock::now();
  }
  ~ScopedTimer() {
    if (sum_) *sum_ += std::chrono::duration<double>(clock::now() - t0_).count();
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  using clock = std::chrono::steady_clock;
  double* sum_;
  clock::time_point t0_;
};

/// Discrete operators for one (params, Δt): the grid, the Helmholtz and Poisson mode solvers and the
/// wall-closure influence data. Immutable; a new Δt = a new operator (factoring costs ~ a few steps).
class NsOperator {
 public:
  /// Throws std::invalid_argument on ν ≤ 0, a ≤ 0, U < 0, odd or small n_θ, dt ≤ 0 or non-finite values.
  NsOperator(const NsParams& p, double dt);
  ~NsOperator();
  NsOperator(const NsOperator&) = delete;
  NsOperator& operator=(const NsOperator&) = delete;

  const NsParams& params() const { return p_; }
  const PolarGrid& grid() const { return grid_; }
  double dt() const { return dt_; }
  /// Δξ_0 = ξ_1 − ξ_0, the wall's spacing (Thom's closure; every Δξ on a uniform ξ).
  double d_xi() const { return h_; }

  /// The closure: ζ_w (and ψ, from ζ with ψ = 0 on the wall and the far-field ψ_ξ = U R sinθ − Γ_R/2π)
  /// such that ψ = 0 and the closure's ψ_ξ = −a²ω hold on the wall; zeta's rings 1…n_r−1 are kept, its wall ring
  /// and psi are overwritten (a state interpolated from another grid).
  void close_wall(std::vector<double>& psi, std::vector<double>& zeta, double Gamma_R) const;

  struct Impl;

 private:
  NsParams p_;
  PolarGrid grid_;
  double dt_, h_;
  std::unique_ptr<Impl> impl_;
  friend void advance(const NsOperator&, const NsState&, NsState&, NsStepTimes*);
};

/// The grid of the parameters: geometric spacing; n_r = 0: the fewest rings with Δξ ≤ Δθ/radial_refinement
/// (R as asked; radial_refinement ≤ 0 or 1 with n_r = 0: square cells, R rounded up to whole cells).
/// wall_refinement > 1: the rings clustered at the wall (make_stretched_grid, Δ_f = Δθ/radial_refinement).
PolarGrid ns_grid(const NsParams& p);

/// advance()'s refusal of a step whose CFL number (of the state it starts from) is above kNsCflLimit: the
/// step taken was too long for that state; nothing was changed but `next`.
struct CflExceeded : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One AB2/CN step of op.dt() from old to next (next may not alias old). Throws CflExceeded when the CFL
/// number of old exceeds kNsCflLimit, std::runtime_error when the new fields are not finite (message: time
/// and likely cause).
/// The whole step after the advection stays in Fourier space (one forward FFT of the right-hand side, the
/// Helmholtz, Poisson and wall-closure solves per mode, two inverse FFTs), on params().threads threads of a
/// persistent pool. Steps on one operator run one at a time (its work buffers are shared).
/// times (optional): the wall seconds of each part are added to it, and steps is incremented.
void advance(const NsOperator& op, const NsState& old, NsState& next, NsStepTimes* times);
inline void advance(const NsOperator& op, const NsState& old, NsState& next) {
  advance(op, old, next, nullptr);
}

/// CFL number Δt·max_ij(κ_ξ|ψ_θ|/(J Δξ) + κ_θ|ψ_ξ − psi_xi_ref|/(J Δθ)) of a state (central differences),
/// dimensionless; κ_θ = advection_factor(order_theta), κ_ξ = advection_factor(order_xi): 1 for order 2,
/// 1.3722 for order 4. psi_xi_ref (m²/s): the ψ_ξ taken implicitly (reference_psi_xi, rotation.hpp), 0: none.
double cfl_number(const PolarGrid& g, const std::vector<double>& psi, double dt, int order_theta = 2,
                  int order_xi = 2, double psi_xi_ref = 0.0);

/// Δt (s) that gives the CFL number `cfl` (of p's advection orders, of the explicit part) for the state,
/// using at least the speed |U| + |aω| + U (the impulsive start's 2U at the shoulders plus the wall speed;
/// without |aω| when the rotation is implicit) across θ.
double cfl_time_step(const NsParams& p, const PolarGrid& g, const std::vector<double>& psi, double cfl);

/// Impulsive start ("from rest" in the body frame): the irrotational flow without circulation,
/// ψ = U (r − a²/r) sinθ, ζ = 0, Γ_R = 0; the first step creates the wall's vortex sheet.
NsState impulsive_start(const NsParams& p, const PolarGrid& g);

/// Add a Gaussian vortex ζ += Γ_b/(πs²)·exp(−|x − x_b|²/s²) at (x_b, y_b) (m) of circulation Γ_b (m²/s):
/// a small one breaks the mirror symmetry of a non-spinning start so that shedding begins. ψ follows at
/// the next step's solve.
void add_vortex_blob(const PolarGrid& g, NsState& s, double x_b, double y_b, double radius, double Gamma_b);

/// Velocity components on the grid: u_r = ψ_θ/r, u_θ = −ψ_ξ/r (central; one-sided at the wall and R), m/s.
void ns_velocity(const PolarGrid& g, const std::vector<double>& psi, std::vector<double>& u_r,
                 std::vector<double>& u_theta);

}  // namespace magnus
