// Floquet multipliers of a periodic base to spanwise disturbances (floquet.hpp): the base's harmonics, the
// spanwise matrices of each, the IMEX linear stepper over one period, and Arnoldi on that period map.
#include "solver/navier_stokes/floquet.hpp"

#include <umfpack.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/gmres.hpp"
#include "solver/navier_stokes/lu.hpp"
#include "solver/navier_stokes/map_arnoldi.hpp"
#include "solver/navier_stokes/shifted_lu.hpp"
#include "solver/navier_stokes/spanwise.hpp"
#include "solver/navier_stokes/stages.hpp"

namespace magnus {

namespace {

/// Triplets of matrices summed with weights (compressed by compress_triplets).
struct Triplets {
  std::vector<long> ti, tj;
  std::vector<double> tx;
  /// scale·A.
  void add(const EigenProblem& A, double scale) {
    for (long c = 0; c < A.n; ++c)
      for (long t = A.Ap[size_t(c)]; t < A.Ap[size_t(c) + 1]; ++t) {
        const long r = A.Ai[size_t(t)];
        ti.push_back(r), tj.push_back(c), tx.push_back(scale * A.Ax[size_t(t)]);
      }
  }
  void compress(EigenProblem& out) const { compress_triplets(out.n, ti, tj, tx, out.Ap, out.Ai, out.Ax); }
};

/// A − B without the entries that cancel: the part of J that does not depend on the base (the pressure,
/// the constraints, the ghosts) drops out exactly, and B(t)·x runs for every harmonic at every step.
EigenProblem difference(const EigenProblem& A, const EigenProblem& B) {
  Triplets t;
  t.add(A, 1.0), t.add(B, -1.0);
  EigenProblem all;
  all.n = A.n;
  t.compress(all);
  EigenProblem D;
  D.n = A.n;
  D.Ap.assign(size_t(D.n) + 1, 0);
  for (long c = 0; c < D.n; ++c) {
    for (long k = all.Ap[size_t(c)]; k < all.Ap[size_t(c) + 1]; ++k)
      if (all.Ax[size_t(k)] != 0.0) D.Ai.push_back(all.Ai[size_t(k)]), D.Ax.push_back(all.Ax[size_t(k)]);
    D.Ap[size_t(c) + 1] = long(D.Ai.size());
  }
  return D;
}

/// The real LU of J_0 − σM (UMFPACK, its METIS order: every period's 400 solves read the factors, and for
/// this operator METIS leaves fewer entries than the grid's nested dissection).
class RealLu {
 public:
  RealLu(const EigenProblem& ep, double sigma) {
    std::vector<double> Az;
    shifted_matrix(ep, sigma, Ap_, Ai_, Ax_, Az);
    const long n = ep.n;
    void* symbolic = nullptr;
    const long st = symbolic_in_grid_order(n, {}, [&](const double* ctl, const long*) {  // no order: METIS
      double inf[UMFPACK_INFO];
      return umfpack_dl_symbolic(n, n, Ap_.data(), Ai_.data(), Ax_.data(), &symbolic, ctl, inf);
    });
    if (st != UMFPACK_OK) throw std::runtime_error(umfpack_error("symbolic analysis (Floquet stepper)", st));
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_dl_defaults(control);
    const SingleThreadBlas one_thread;
    const long sn = umfpack_dl_numeric(Ap_.data(), Ai_.data(), Ax_.data(), symbolic, &numeric_, control, info);
    umfpack_dl_free_symbolic(&symbolic);
    if (sn != UMFPACK_OK) throw std::runtime_error(umfpack_error("factorisation (Floquet stepper)", sn));
  }
  ~RealLu() {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
  }
  RealLu(const RealLu&) = delete;
  RealLu& operator=(const RealLu&) = delete;
  void solve(const std::vector<double>& b, std::vector<double>& x) const {
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_dl_defaults(control);
    control[UMFPACK_IRSTEP] = 0;
    const long st = umfpack_dl_solve(UMFPACK_A, Ap_.data(), Ai_.data(), Ax_.data(), x.data(), b.data(), numeric_,
                                     control, info);
    if (st != UMFPACK_OK) throw std::runtime_error(umfpack_error("solve (Floquet stepper)", st));
  }

 private:
  std::vector<long> Ap_, Ai_;
  std::vector<double> Ax_;
  void* numeric_ = nullptr;
};

/// The linear stepper over one period (floquet.hpp's scheme): J0's pressure enters at the half step only.
struct PeriodMap {
  const EigenProblem& J0;
  const HarmonicSum& B;  ///< cos and sin parts of harmonic k at 2(k − 1) and 2(k − 1) + 1
  const RealLu& lu;      ///< of J0 with its pressure columns doubled, less (2/Δt)M
  double T, dt;
  int steps;
  /// B(t) x = Σ_k cos(kωt) B_k^c x + sin(kωt) B_k^s x into y.
  void periodic_part(double t, const std::vector<double>& x, std::vector<double>& y) const {
    std::vector<double> c(B.H);
    for (size_t k = 0; 2 * k < B.H; ++k) {
      const double w = 2.0 * M_PI * double(k + 1) / T;
      c[2 * k] = std::cos(w * t), c[2 * k + 1] = std::sin(w * t);
    }
    B.apply(c.data(), x, y);
  }
  std::vector<double> operator()(std::vector<double> x) const {
    const size_t n = x.size();
    std::vector<double> Bx(n), Bx_prev(n), rhs(n), next(n);
    for (int s = 0; s < steps; ++s) {
      periodic_part(s * dt, x, Bx);
      for (size_t r = kSpanwisePressure; r < n; r += kSpanwiseFields) x[r] = 0.0;  // p^{n−½} is not carried
      std::fill(rhs.begin(), rhs.end(), 0.0);
      J0.multiply_add(x, 0.5, rhs);
      for (size_t r = 0; r < n; ++r) {
        const double b = s == 0 ? Bx[r] : 1.5 * Bx[r] - 0.5 * Bx_prev[r];
        const double e = s == 0 ? Bx[r] : 2.0 * Bx[r] - Bx_prev[r];
        // (J_0' − (2/Δt)M) x^{n+1} = −2[(M/Δt) x^n + ½J_0 x^n + b] on rows with mass, −e on constraints.
        rhs[r] = J0.m[r] != 0.0 ? -2.0 * (J0.m[r] / dt * x[r] + rhs[r] + b) : -e;
      }
      lu.solve(rhs, next);
      x.swap(next);
      Bx_prev.swap(Bx);
    }
    return x;
  }
};

/// J0 with the pressure's columns doubled: the stepper's unknown there is p^{n+½}, all of it implicit.
EigenProblem half_step_pressure(EigenProblem J0) {
  for (long c = kSpanwisePressure; c < J0.n; c += kSpanwiseFields)
    for (long t = J0.Ap[size_t(c)]; t < J0.Ap[size_t(c) + 1]; ++t) J0.Ax[size_t(t)] *= 2.0;
  return J0;
}

/// Arnoldi on P from o.start, or a random vector (map_arnoldi): stops at o.krylov vectors, or once the
/// leading Ritz estimate meets FloquetOptions'. The multipliers, their estimates, the periods run and the
/// leading Ritz vector's real part into res.
void arnoldi(const PeriodMap& P, const FloquetOptions& o, size_t n, FloquetResult& res) {
  MapArnoldiOptions mo;
  mo.krylov = std::max(o.krylov, o.count + 2);
  mo.min_vectors = o.count + 2;
  mo.start = o.start, mo.seed = o.seed;
  const bool stops = o.tolerance > 0.0 || o.relative > 0.0;
  const MapArnoldiResult r =
      map_arnoldi([&](const std::vector<double>& x) { return P(x); }, n, mo,
                  [&](const std::vector<MapRitz>& ritz) { return stops && o.met(ritz.front().mu, ritz.front().residual); });
  res.periods += r.products;
  for (int k = 0; k < std::min(o.count, int(r.ritz.size())); ++k)
    res.multipliers.push_back(r.ritz[size_t(k)].mu), res.residuals.push_back(r.ritz[size_t(k)].residual);
  res.mode = r.leading;
}

}  // namespace

FourierAccumulator::FourierAccumulator(size_t nodes, int N, int K, double T) : N_(N) {
  if (N < 4 || K < 1 || K > N / 2 - 1)
    throw std::invalid_argument("FourierAccumulator: needs N ≥ 4 samples and 1 ≤ K ≤ N/2 − 1 harmonics");
  NsState zero;
  zero.psi.assign(nodes, 0.0), zero.zeta.assign(nodes, 0.0);
  b_.mean = zero, b_.T = T;
  b_.cos_part.assign(size_t(K), zero), b_.sin_part.assign(size_t(K), zero);
}

void FourierAccumulator::add(int n, const NsState& s) {
  const double N = double(N_);
  const size_t nodes = b_.mean.psi.size();
  for (size_t q = 0; q < nodes; ++q) b_.mean.psi[q] += s.psi[q] / N, b_.mean.zeta[q] += s.zeta[q] / N;
  b_.mean.Gamma_R += s.Gamma_R / N;
  for (size_t k = 1; k <= b_.cos_part.size(); ++k) {
    const double c = 2.0 * std::cos(2.0 * M_PI * double(k) * n / N) / N;
    const double d = 2.0 * std::sin(2.0 * M_PI * double(k) * n / N) / N;
    NsState &C = b_.cos_part[k - 1], &S = b_.sin_part[k - 1];
    for (size_t q = 0; q < nodes; ++q) {
      C.psi[q] += c * s.psi[q], C.zeta[q] += c * s.zeta[q];
      S.psi[q] += d * s.psi[q], S.zeta[q] += d * s.zeta[q];
    }
  }
}

PeriodicBase canonical_phase(PeriodicBase b) {
  if (b.cos_part.empty()) return b;
  double C = 0.0, S = 0.0;
  for (double z : b.cos_part.front().zeta) C += z;
  for (double z : b.sin_part.front().zeta) S += z;
  if (!(std::hypot(C, S) > 0.0)) return b;
  const double phi = std::atan2(S, C);  // ωt_0: C cos ωt + S sin ωt = A cos(ω(t + t_0))
  for (size_t k = 1; k <= b.cos_part.size(); ++k) {
    const double c = std::cos(double(k) * phi), s = std::sin(double(k) * phi);
    NsState &Ck = b.cos_part[k - 1], &Sk = b.sin_part[k - 1];
    for (auto [x, y] : {std::pair{&Ck.psi, &Sk.psi}, std::pair{&Ck.zeta, &Sk.zeta}})
      for (size_t q = 0; q < x->size(); ++q) {
        const double xc = (*x)[q], ys = (*y)[q];
        (*x)[q] = xc * c + ys * s, (*y)[q] = ys * c - xc * s;
      }
    const double gc = Ck.Gamma_R, gs = Sk.Gamma_R;
    Ck.Gamma_R = gc * c + gs * s, Sk.Gamma_R = gs * c - gc * s;
  }
  return b;
}

double PeriodicBase::truncation() const {
  if (cos_part.empty()) return 0.0;
  const double last = norm2(cos_part.back().zeta) + norm2(sin_part.back().zeta);
  return last / std::max(1e-300, norm2(cos_part.front().zeta) + norm2(sin_part.front().zeta));
}

HarmonicSum::HarmonicSum(const std::vector<EigenProblem>& B) : n(B.empty() ? 0 : B.front().n), H(B.size()) {
  Ap.assign(size_t(n) + 1, 0);
  std::vector<long> slot(size_t(n), -1);  // a row's entry in the current column
  for (long c = 0; c < n; ++c) {
    const size_t first = Ai.size();
    for (size_t h = 0; h < H; ++h)
      for (long t = B[h].Ap[size_t(c)]; t < B[h].Ap[size_t(c) + 1]; ++t) {
        const long r = B[h].Ai[size_t(t)];
        if (slot[size_t(r)] < long(first)) {
          slot[size_t(r)] = long(Ai.size());
          Ai.push_back(r);
          V.resize(V.size() + H, 0.0);
        }
        V[size_t(slot[size_t(r)]) * H + h] = B[h].Ax[size_t(t)];
      }
    Ap[size_t(c) + 1] = long(Ai.size());
  }
  Ai.shrink_to_fit(), V.shrink_to_fit();  // held for the whole Arnoldi run: no spare capacity
}

void HarmonicSum::apply(const double* c, const std::vector<double>& x, std::vector<double>& y) const {
  std::fill(y.begin(), y.end(), 0.0);
  for (long col = 0; col < n; ++col) {
    const double xc = x[size_t(col)];
    if (xc == 0.0) continue;
    for (long t = Ap[size_t(col)]; t < Ap[size_t(col) + 1]; ++t) {
      const double* v = &V[size_t(t) * H];
      double a = 0.0;
      for (size_t h = 0; h < H; ++h) a += c[h] * v[h];
      y[size_t(Ai[size_t(t)])] += a * xc;
    }
  }
}

namespace {

/// The refusals of floquet_multipliers and floquet_period_map (`who`, the message's prefix); the grid.
PolarGrid check_floquet_input(const char* who, const NsParams& p, const PeriodicBase& base, double beta,
                              int steps) {
  const std::string w = who;
  const double T = base.T;
  if (!(T > 0.0) || !std::isfinite(T)) throw std::invalid_argument(w + ": the period must be > 0");
  if (!(beta >= 0.0) || !std::isfinite(beta))
    throw std::invalid_argument(w + ": the wavenumber β must be finite and ≥ 0");
  if (base.cos_part.empty()) throw std::invalid_argument(w + ": the base has no harmonic");
  if (base.sin_part.size() != base.cos_part.size())
    throw std::invalid_argument(w + ": the base's cos and sin parts differ in number");
  if (steps < 4) throw std::invalid_argument(w + ": needs at least 4 steps per period");
  PolarGrid g = ns_grid(p);
  const size_t nodes = size_t(g.nodes());
  auto fits = [nodes](const NsState& s) { return s.psi.size() == nodes && s.zeta.size() == nodes; };
  if (!fits(base.mean) || !std::all_of(base.cos_part.begin(), base.cos_part.end(), fits) ||
      !std::all_of(base.sin_part.begin(), base.sin_part.end(), fits))
    throw std::invalid_argument(w + ": the base does not match the grid");
  return g;
}

/// B_k^c and B_k^s of every harmonic k (at 2(k − 1) and 2(k − 1) + 1): J(b_0 + b_k) − J(b_0), exact because
/// J is affine in the base.
std::vector<EigenProblem> harmonic_matrices(const NsParams& p, const PeriodicBase& base, double beta,
                                            const SpanwiseOutflow& out, const EigenProblem& J0) {
  std::vector<EigenProblem> B;
  for (size_t k = 0; k < base.cos_part.size(); ++k)
    for (const NsState* part : {&base.cos_part[k], &base.sin_part[k]}) {
      NsState b = base.mean;
      for (size_t q = 0; q < b.psi.size(); ++q) b.psi[q] += part->psi[q], b.zeta[q] += part->zeta[q];
      B.push_back(difference(spanwise_problem(p, b, beta, out), J0));
    }
  return B;
}

/// What the period map steps with, built once for a base and a step count (members in this order: each
/// is built from the ones before it).
struct FloquetStepper {
  double T;             ///< the base's period, s
  int steps;            ///< steps per period
  double dt;            ///< Δt = T/steps, s
  SpanwiseOutflow out;  ///< the outflow columns of R, the mean flow's
  EigenProblem J0;      ///< J(b_0), the mean flow's spanwise problem
  HarmonicSum harmonics;  ///< the B_k^c, B_k^s of every harmonic, summed in one pass
  RealLu lu;            ///< of J0 with its pressure columns doubled, less (2/Δt)M
  FloquetStepper(const NsParams& p, const PeriodicBase& base, double beta, int n)
      : T(base.T),
        steps(n),
        dt(base.T / n),
        out(spanwise_outflow(p, base.mean)),
        J0(spanwise_problem(p, base.mean, beta, out)),
        harmonics(harmonic_matrices(p, base, beta, out, J0)),
        lu(half_step_pressure(J0), 2.0 / dt) {}
  /// The period map P (it refers to this stepper's parts: use it while the stepper lives).
  PeriodMap map() const { return PeriodMap{J0, harmonics, lu, T, dt, steps}; }
};

}  // namespace

std::vector<double> floquet_period_map(const NsParams& p, const PeriodicBase& base, double beta, int steps,
                                       std::vector<double> x) {
  const PolarGrid g = check_floquet_input("floquet_period_map", p, base, beta, steps);
  if (x.size() != size_t(spanwise_unknowns(g.n_r, g.n_theta)))
    throw std::invalid_argument("floquet_period_map: x does not match the spanwise problem");
  return FloquetStepper(p, base, beta, steps).map()(std::move(x));
}

FloquetResult floquet_multipliers(const NsParams& p, const PeriodicBase& base, double beta,
                                  const FloquetOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  check_floquet_input("floquet_multipliers", p, base, beta, o.steps);
  FloquetResult res;
  res.T = base.T;
  res.harmonics = int(base.cos_part.size());
  res.steps = o.steps;
  res.truncation = base.truncation();
  const FloquetStepper stepper(p, base, beta, o.steps);
  arnoldi(stepper.map(), o, size_t(stepper.J0.n), res);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace magnus
