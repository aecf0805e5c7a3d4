#include "postproc/navier_stokes/hopf_track.hpp"

#include <optional>
#include <stdexcept>

#include "postproc/navier_stokes/hopf_steady.hpp"
#include "solver/navier_stokes/operator.hpp"
#include "solver/navier_stokes/stepper_eigen.hpp"

namespace magnus {

void track_pair(const NsParams& p, HopfParameter which, HopfEvaluation& e, std::complex<double> near,
                const HopfOptions& o, bool sharp, const std::vector<std::complex<double>>* like) {
  const bool follow = like && !like->empty();
  StabilityOptions so;
  so.eigensolver = o.full.eigensolver;
  so.shifts = {near};
  so.extra_shifts = 0;
  so.want = sharp || follow ? 1 : 2;
  so.krylov = follow ? 11 : sharp ? 16 : o.track_krylov;
  if (follow)
    so.follow = *like, so.restarts = 2;
  else
    so.follow_near = near;
  // Following: the pair alone is wanted, so 11 vectors (leading_eigenvalues keeps count + 10 at least).
  e.stability = leading_eigenvalues(with_parameter(p, which, e.x), e.state, follow ? 1 : o.count, so);
  StabilityResult& r = e.stability;
  if (follow && !(r.followed_overlap >= kFollowOverlap && r.followed.imag() > 0.0)) {
    const double seconds = r.seconds, overlap = r.followed_overlap;
    track_pair(p, which, e, near, o, sharp);  // another mode: the pair nearest the prediction instead
    e.stability.seconds += seconds;
    e.overlap = overlap;  // not followed
    return;
  }
  e.mode = r.followed.imag() > 0.0 ? r.followed : 0.0;
  e.vector = std::move(r.followed_vector);
  r.followed_vector.clear();
  e.overlap = r.followed_overlap;
  e.tracked = true;
}

HopfEvaluation steady_point(const NsParams& p, HopfParameter which, double x, const HopfEvaluation* from,
                            const NsState* guess, bool potential_first) {
  if (!(p.U > 0.0)) throw std::invalid_argument("onset of shedding: flow.speed must be > 0 (α = aω/U, Re = 2aU/ν)");
  HopfEvaluation e;
  e.x = x;
  std::optional<NsState> s;
  {
    const ScopedTimer timer(&e.newton_seconds);
    s = steady_at(p, which, x, from, guess, potential_first);
  }
  e.converged = s.has_value();
  if (e.converged) e.state = std::move(*s);
  return e;
}

void full_search(const NsParams& p, HopfParameter which, HopfEvaluation& e, const HopfOptions& o) {
  e.stability = leading_eigenvalues(with_parameter(p, which, e.x), e.state, o.count, o.full);
  e.mode = e.stability.leading_pair().value_or(0.0);
  e.tracked = false;
}

bool seeded_search(const NsParams& p, HopfParameter which, HopfEvaluation& e, const HopfOptions& o) {
  if (!o.seed_ends) return false;
  const StepperEigenResult r = stepper_eigenvalues(with_parameter(p, which, e.x), e.state, o.seed);
  const auto pair = r.leading_pair();
  if (!pair || pair->real() <= 0.0) return false;
  HopfEvaluation t = e;
  track_pair(p, which, t, *pair, o, true);
  if (t.mode == 0.0 || t.growth() < 0.0 || std::abs(t.mode - *pair) > 0.05) return false;
  t.stability.seconds += r.seconds;
  t.seeded = true;
  e = std::move(t);
  return true;
}

}  // namespace magnus
