// The AB2/CN time step of the viscous model (operator.hpp): the operator's stages (stages.hpp) in order,
// on the operator's pool, each part of the step timed by a ScopedTimer.
#include "solver/navier_stokes/operator.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>

#include "solver/fft_modes.hpp"
#include "solver/navier_stokes/operator_impl.hpp"
#include "solver/navier_stokes/rotation.hpp"
#include "solver/navier_stokes/stages.hpp"
#include "solver/pool.hpp"

namespace magnus {

namespace {

using cplx = std::complex<double>;

std::string fmt_time(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g s", t);
  return buf;
}

/// A CFL number for a message: 4 digits, or "not finite" (never "inf" or a 300-digit number).
std::string fmt_cfl(double c) {
  if (!std::isfinite(c)) return "not finite";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", c);
  return buf;
}

std::runtime_error non_finite(double t, double dt, const std::string& where) {
  return std::runtime_error("advance: the flow turned non-finite at t = " + fmt_time(t) + " (" + where +
                            "); likely cause: the time step " + fmt_time(dt) +
                            " is above the stability limit, or the grid is too coarse for Re");
}

/// AB2 weights for a step dt after a step dt_prev: N^{n+1/2} = w1 N^n + w0 N^{n−1} (first: Euler, N^n).
struct Ab2 {
  bool first;
  double w1, w0;
};
Ab2 ab2_weights(const NsState& old, double dt, size_t size) {
  const bool first = old.N_prev.size() != size || !(old.dt_prev > 0.0);
  const double r = first ? 0.0 : dt / old.dt_prev;
  return {first, 1.0 + 0.5 * r, -0.5 * r};
}

/// Seconds of a step's parts as advance() measures them (ScopedTimer): the boundary part, the three parallel
/// regions' wall seconds (rhs, modes, back) and thread 0's seconds in each stage inside them.
struct StepClock {
  double boundary = 0.0, rhs = 0.0, rhs_rings = 0.0, modes = 0.0, helmholtz = 0.0, poisson = 0.0, wall = 0.0;
  double back = 0.0, c2r_zeta = 0.0, c2r_psi = 0.0;
};

/// Adds a step's clock to the parts of `t`: each parallel region is shared out as thread 0 spent it.
void add_times(const StepClock& c, NsStepTimes& t) {
  const double a_share = c.rhs > 0.0 ? std::min(1.0, c.rhs_rings / c.rhs) : 1.0;
  t.advection += a_share * c.rhs;
  t.helmholtz += (1.0 - a_share) * c.rhs;  // the r2c of the right-hand side
  const double mode_sum = c.helmholtz + c.poisson + c.wall;
  if (mode_sum > 0.0) {
    t.helmholtz += c.modes * c.helmholtz / mode_sum;
    t.poisson += c.modes * c.poisson / mode_sum;
    t.wall += c.modes * c.wall / mode_sum;
  } else {
    t.helmholtz += c.modes;
  }
  const double fft_sum = c.c2r_zeta + c.c2r_psi, fft_region = std::min(c.back, fft_sum);
  t.helmholtz += fft_sum > 0.0 ? fft_region * c.c2r_zeta / fft_sum : 0.0;
  t.poisson += fft_sum > 0.0 ? fft_region * c.c2r_psi / fft_sum : 0.0;
  t.other += c.boundary + (c.back - fft_region);
  ++t.steps;
}

/// What the parts of one step share: the operator's grid, factors, pool and buffers, and the step's clock.
struct Step {
  Step(const NsOperator& op, NsOperator::Impl& parts, bool timed_step)
      : im(parts), g(op.grid()), p(op.params()), b(*parts.buffers), pool(*parts.pool), nr(g.n_r),
        n(g.n_theta), m(n / 2 + 1), dt(op.dt()), h(op.d_xi()), timed(timed_step), rot(parts.rotation != nullptr) {}
  const NsOperator::Impl& im;
  const PolarGrid& g;
  const NsParams& p;
  StepBuffers& b;
  ThreadPool& pool;
  int nr, n, m;
  double dt, h;
  bool timed;
  bool rot;  ///< the rotation implicit (rotation.hpp): N' = J(ψ', ζ) explicit, A with the diffusion
  StepClock clock;
  /// Where thread t adds the seconds of a stage: x on thread 0 of a timed step, else nowhere.
  double* at(double& x, int t = 0) { return timed && t == 0 ? &x : nullptr; }
};

/// Advection N^n (Arakawa) into N and the Crank–Nicolson right-hand side f into b.f on rings 1…n_r−2 (0 on
/// the wall and outer rings), then f̂ (r2c) into b.zeta_hat, each thread its rings. With the rotation
/// implicit N is N' = J(ψ', ζ) (ψ' in b.psi_prime) and f gains Aζ^n/ν (after acc: a non-finite ζ^n shows in
/// the new fields). rate: the CFL rate of old's explicit part (1/s; with the wall ring's |ω|/Δθ unless the
/// rotation is implicit); acc: Σ f.
void right_hand_side(Step& s, const NsState& old, const Ab2& ab, std::vector<double>& N, double& rate,
                     double& acc) {
  const int parts = s.pool.size(), n = s.n, m = s.m;
  if (s.rot)  // ψ' = ψ − ψ_ref, the explicit part's streamfunction
    for (size_t q = 0; q < old.psi.size(); ++q) s.b.psi_prime[q] = old.psi[q] - s.im.psi_ref[q];
  const double* psi = s.rot ? s.b.psi_prime.data() : old.psi.data();
  std::vector<double> rate_part(size_t(parts), 0.0), sum_part(size_t(parts), 0.0);
  s.pool.run([&](int t) {
    const int rb = s.im.ring_begin[t], re = s.im.ring_end[t];
    double rmax = 0.0, sum = 0.0;
    {
      ScopedTimer timer(s.at(s.clock.rhs_rings, t));
      for (int i = rb; i < re; ++i) {
        double* Ni = &N[size_t(i) * n];
        double* f = s.b.f.p + size_t(i) * n;
        if (i == 0 || i == s.nr - 1) {
          std::fill(Ni, Ni + n, 0.0);
          std::fill(f, f + n, 0.0);
          continue;
        }
        const double ring = advection_ring(s.g, s.p, psi, old.zeta.data(), i, Ni);
        const double* N_prev = ab.first ? nullptr : &old.N_prev[size_t(i) * n];
        diffusion_rhs_ring(s.g, s.p, s.dt, old.zeta.data(), i, Ni, N_prev, ab.w1, ab.w0, f, sum);
        if (s.rot) add_rotation_ring(s.im.rotation_stencil, old.zeta.data(), i, 1.0 / s.p.nu, f);
        rmax = std::max(rmax, ring_cfl_rate(s.g, i, ring));
      }
    }
    rate_part[t] = rmax;
    sum_part[t] = sum;
    fftw_execute_dft_r2c(s.im.part_r2c[t], s.b.f.p + size_t(rb) * n,
                         reinterpret_cast<fftw_complex*>(s.b.zeta_hat.p + size_t(rb) * m));
  });
  rate = s.rot ? 0.0 : std::fabs(s.p.omega) / s.g.d_theta;  // the wall ring: ψ_θ = 0, ψ_ξ = −a²ω
  acc = 0.0;
  for (int t = 0; t < parts; ++t) rate = std::max(rate, rate_part[t]), acc += sum_part[t];
}

/// The CFL number of old (std::runtime_error above kNsCflLimit); throws when the right-hand side's sum acc
/// or the new Γ_R is not finite.
double check_step(const Step& s, const NsState& old, const NsState& next, double rate, double acc) {
  const NsParams& p = s.p;
  const double dt = s.dt;
  const double cfl =
      p.stokes ? cfl_number(s.g, old.psi, dt, p.advection_order, p.advection_order_xi) : rate * dt;
  if (!(cfl <= kNsCflLimit))
    throw CflExceeded("advance: at t = " + fmt_time(old.t) + " the CFL number is " + fmt_cfl(cfl) + " > " +
                      fmt_cfl(kNsCflLimit) + ": the time step " + fmt_time(dt) +
                      " is above the stability limit (reduce dt or the CFL number)");
  if (!std::isfinite(acc)) throw non_finite(old.t + dt, dt, "vorticity right-hand side");
  if (!std::isfinite(next.Gamma_R)) throw non_finite(old.t + dt, dt, "circulation at R");
  return cfl;
}

/// Per Fourier mode, each thread its modes: Helmholtz ζ̂*, Poisson ψ̂* of −J ζ̂* (far field of Γ_R), and
/// the wall closure along (φ_k, χ_k).
void solve_modes(Step& s, double Gamma_R) {
  StepBuffers& b = s.b;
  std::vector<cplx> g_hat(size_t(s.m));
  far_field_hat(s.g, s.p, Gamma_R, g_hat.data());
  const double target0 = -double(s.n) * s.h * s.p.a * s.p.a * s.p.omega * s.im.wall.row.kappa;
  s.pool.run([&](int t) {
    int kb, ke;
    s.pool.split(s.m, t, kb, ke);
    {
      ScopedTimer timer(s.at(s.clock.helmholtz, t));
      if (s.rot)
        solve_rotation_modes(*s.im.rotation, b.zeta_hat.p, b.zero_hat.data(), b.ring_hat.p, kb, ke);
      else
        helmholtz_modes(*s.im.helmholtz, b.zeta_hat.p, b.zero_hat.data(), b.ring_hat.p, kb, ke);
    }
    {
      ScopedTimer timer(s.at(s.clock.poisson, t));
      poisson_modes(*s.im.poisson, s.g, b.zeta_hat.p, b.psi_hat.p, b.zero_hat.data(), g_hat.data(), kb, ke);
    }
    ScopedTimer timer(s.at(s.clock.wall, t));
    wall_closure_modes(s.im.wall, s.nr, s.m, target0, b.zeta_hat.p, b.psi_hat.p, b.delta.data(), kb, ke);
  });
}

/// Back to the grid, each thread its rings: ζ and ψ (c2r) scaled by 1/n_θ into next, ψ = 0 on the wall
/// exactly; throws when they are not finite (naming the first ring that is not).
void to_grid(Step& s, const NsState& old, NsState& next) {
  const int n = s.n, m = s.m, parts = s.pool.size();
  const size_t size = size_t(s.nr) * n;
  StepBuffers& b = s.b;
  next.zeta.resize(size);
  next.psi.resize(size);
  std::vector<double> sum_part(size_t(parts), 0.0);
  s.pool.run([&](int t) {
    const int rb = s.im.ring_begin[t], re = s.im.ring_end[t];
    {
      ScopedTimer timer(s.at(s.clock.c2r_zeta, t));
      fftw_execute_dft_c2r(s.im.part_c2r[t], reinterpret_cast<fftw_complex*>(b.zeta_hat.p + size_t(rb) * m),
                           b.zeta.p + size_t(rb) * n);
    }
    {
      ScopedTimer timer(s.at(s.clock.c2r_psi, t));
      fftw_execute_dft_c2r(s.im.part_c2r[t], reinterpret_cast<fftw_complex*>(b.psi_hat.p + size_t(rb) * m),
                           b.psi.p + size_t(rb) * n);
    }
    const double inv_n = 1.0 / n;
    double sum = 0.0;
    for (size_t q = size_t(rb) * n; q < size_t(re) * n; ++q) {
      next.zeta[q] = b.zeta.p[q] * inv_n;
      next.psi[q] = b.psi.p[q] * inv_n;
      sum += next.zeta[q] + next.psi[q];
    }
    if (rb == 0) std::fill(next.psi.begin(), next.psi.begin() + n, 0.0);
    sum_part[t] = sum;
  });
  double acc = 0.0;
  for (int t = 0; t < parts; ++t) acc += sum_part[t];
  if (std::isfinite(acc)) return;
  for (size_t q = 0; q < size; ++q)
    if (!std::isfinite(next.zeta[q]) || !std::isfinite(next.psi[q]))
      throw non_finite(old.t + s.dt, s.dt, "ring " + std::to_string(q / n));
  throw non_finite(old.t + s.dt, s.dt, "the fields");
}

}  // namespace

void advance(const NsOperator& op, const NsState& old, NsState& next, NsStepTimes* times) {
  const PolarGrid& g = op.grid();
  const size_t size = size_t(g.n_r) * g.n_theta;
  if (old.psi.size() != size || old.zeta.size() != size)
    throw std::invalid_argument("advance: the state does not match the operator's grid");
  if (&old == &next) throw std::invalid_argument("advance: next may not alias old");
  NsOperator::Impl& im = *op.impl_;
  std::lock_guard<std::mutex> step_lock(im.step_mutex);
  Step s(op, im, times != nullptr);
  const Ab2 ab = ab2_weights(old, s.dt, size);
  double flux;
  {
    // Outer ring: dΓ_R/dt, Γ_R^{n+1} by AB2, and ζ^{n+1} there (its r2c: the Helmholtz solve's data at R).
    ScopedTimer timer(s.at(s.clock.boundary));
    flux = circulation_flux(g, s.p, old.psi.data(), old.zeta.data());
    outer_vorticity(g, s.p, s.dt, old.psi.data(), old.zeta.data(), s.b.ring.p);
    fftw_execute_dft_r2c(im.step_ring_r2c, s.b.ring.p, reinterpret_cast<fftw_complex*>(s.b.ring_hat.p));
    next.Gamma_R = old.Gamma_R + s.dt * (ab.w1 * flux + ab.w0 * old.Gamma_flux_prev);
  }
  next.N_prev.resize(size);
  double rate, acc, cfl;
  {
    ScopedTimer timer(s.at(s.clock.rhs));
    right_hand_side(s, old, ab, next.N_prev, rate, acc);  // N^n, f = −σζ^n − Lζ^n + (2/ν)N^{n+1/2}, f̂
  }
  {
    ScopedTimer timer(s.at(s.clock.modes));
    cfl = check_step(s, old, next, rate, acc);
    solve_modes(s, next.Gamma_R);  // ζ̂^{n+1}, ψ̂^{n+1}: Helmholtz, Poisson, wall closure
  }
  {
    ScopedTimer timer(s.at(s.clock.back));
    to_grid(s, old, next);
    next.t = old.t + s.dt;
    next.Gamma_flux_prev = flux;
    next.dt_prev = s.dt;
    next.rate_prev = s.dt > 0.0 ? cfl / s.dt : 0.0;
  }
  if (times) add_times(s.clock, *times);
}

}  // namespace magnus
