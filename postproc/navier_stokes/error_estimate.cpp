#include "postproc/navier_stokes/error_estimate.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "postproc/navier_stokes/means_drift.hpp"
#include "postproc/navier_stokes/periodic.hpp"
#include "postproc/result.hpp"

namespace magnus {

NsParams companion_params(const NsParams& p, const PolarGrid& fine) {
  NsParams pc = p;
  pc.n_theta = (fine.n_theta / 2 + 1) / 2 * 2;
  pc.n_r = (fine.n_r - 1) / 2 + 1;
  return pc;
}

std::string companion_refusal(const NsParams& p, const PolarGrid& fine, bool resumed) {
  if (!(p.U > 0.0)) return "U = 0: no coefficients to estimate";
  if (resumed) return "resumed from a checkpoint: a companion would march from rest, past the run's end";
  const NsParams pc = companion_params(p, fine);
  if (pc.n_theta < kCompanionMinTheta)
    return fmt::format("the grid twice as coarse, n_θ {}, is below {} points", pc.n_theta,
                       kCompanionMinTheta);
  if (pc.n_r < kCompanionMinRings)
    return fmt::format("the grid twice as coarse, {} rings, is below {} rings", pc.n_r, kCompanionMinRings);
  return "";
}

namespace {

/// (max − min)/|f| of values (0 when fewer than two or f = 0).
double spread_of(const std::vector<double>& x, double f) {
  if (x.size() < 2 || !(std::fabs(f) > 0.0)) return 0.0;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return (*hi - *lo) / std::fabs(f);
}

}  // namespace

MeansSpread means_spread(const UnsteadyResult& run, int periods, double window) {
  MeansSpread s;
  const std::vector<ForceSample>& h = run.history;
  if (h.empty()) return s;
  if (run.periodic) {
    const std::vector<PeriodWindow> w = lift_periods(h, size_t(std::max(2, periods)));
    std::vector<double> L, D, T;
    for (const PeriodWindow& p : w) L.push_back(p.C_L), D.push_back(p.C_D), T.push_back(p.length());
    s.cl = spread_of(L, run.C_L_mean), s.cd = spread_of(D, run.C_D_mean);
    s.st = spread_of(T, run.period);
    return s;
  }
  const ForceSample& last = h.back();
  const auto from = std::lower_bound(h.begin(), h.end(), last.t - window,
                                     [](const ForceSample& x, double t) { return x.t < t; });
  s.cl = spread_of({from->C_L, last.C_L}, last.C_L), s.cd = spread_of({from->C_D, last.C_D}, last.C_D);
  return s;
}

MeansSpread means_drift_rel(const UnsteadyResult& run) {
  if (!run.periodic) return {};
  const MeansDrift d = means_drift(lift_periods(run.history, kDriftPeriods));
  auto rel = [](double x, double f) { return std::fabs(f) >= kEstimateZero ? x / std::fabs(f) : 0.0; };
  return {rel(d.cl, run.C_L_mean), rel(d.cd, run.C_D_mean), run.period > 0.0 ? d.period / run.period : 0.0};
}

std::optional<double> relative_estimate(double f_h, double f_2h, double spread) {
  if (!std::isfinite(f_h) || !std::isfinite(f_2h) || !(std::fabs(f_h) >= kEstimateZero)) return std::nullopt;
  return std::fabs(f_h - f_2h) / std::fabs(f_h) + spread;
}

bool same_orbit(const UnsteadyResult& run, const UnsteadyResult& coarse) {
  if (!(run.St > 0.0 && coarse.St > 0.0)) return false;
  const double amp = run.C_L_amplitude, amp_c = coarse.C_L_amplitude;
  return std::fabs(coarse.St / run.St - 1.0) <= 0.3 && amp_c <= 2.0 * amp && amp <= 2.0 * amp_c;
}

void record_companion(ViscousPart& v, const char* what, const NsParams& pc, bool rings_only, double seconds) {
  v.companion_n_theta = pc.n_theta, v.companion_n_r = pc.n_r;
  v.companion_seconds = seconds;
  v.error_method = fmt::format("from a companion {} on {} × {}{}: |f − f_coarse|, 3× the Richardson estimate",
                               what, pc.n_theta, pc.n_r, rings_only ? " (coarser in the rings only)" : "");
}

void estimate_from_companion(ViscousPart& v, const UnsteadyResult& fine, const UnsteadyResult& coarse,
                             const MeansSpread& spread, const MeansSpread& drift) {
  v.means_converged = fine.converged;
  if (fine.interrupted) {
    v.error_note = "the run was interrupted";
    return;
  }
  if (!coarse.ok) {
    v.error_note = "the companion run failed: " + coarse.message;
    return;
  }
  if (coarse.interrupted && coarse.state.t < fine.state.t * (1.0 - 1e-9)) {
    v.error_note = "the companion was stopped before it reached the run's time";
    return;
  }
  const MeansSpread add = fine.converged ? MeansSpread{} : spread;
  if (!fine.converged) v.means_spread_rel = std::max({add.cl, add.cd, fine.periodic ? add.st : 0.0});
  if (fine.periodic) {
    v.cl_mean_drift_rel = drift.cl, v.cd_mean_drift_rel = drift.cd;
    v.strouhal_drift_rel = drift.st;
  }
  std::string note;
  auto one = [&](const char* name, double f_h, double f_2h, double s, std::optional<double>& out) {
    out = relative_estimate(f_h, f_2h, s);
    if (!out) note += fmt::format("{}{} ≈ 0: no relative error", note.empty() ? "" : "; ", name);
  };
  one("C_L", fine.C_L_mean, coarse.C_L_mean, add.cl + drift.cl, v.cl_mean_rel_estimate);
  one("C_D", fine.C_D_mean, coarse.C_D_mean, add.cd + drift.cd, v.cd_mean_rel_estimate);
  if (fine.St > 0.0 && coarse.St > 0.0)
    v.strouhal_rel_estimate = relative_estimate(fine.St, coarse.St, add.st + drift.st);
  else if (fine.St > 0.0)
    note += std::string(note.empty() ? "" : "; ") + "St: the companion found no confirmed period";
  v.error_note = note;
}

std::unique_ptr<CompanionRun> start_companion(NsParams pc, UnsteadyOptions o, NsState start) {
  auto m = std::make_unique<CompanionRun>();
  pc.threads = 1;
  std::atomic<double>* stop_at = &m->stop_at;
  o.on_step = [stop_at](const NsState& s, const ViscousForces&) { return s.t < stop_at->load(); };
  o.steps_taken = nullptr;
  m->result = std::async(std::launch::async, [pc, o, s = std::move(start)]() mutable {
    try {
      return run_unsteady(pc, o, std::move(s));
    } catch (const std::exception& e) {  // the companion's failure leaves the estimate undefined, not the run
      UnsteadyResult failed;
      failed.ok = false;
      failed.message = failed.error = e.what();
      return failed;
    }
  });
  return m;
}

UnsteadyResult finish_companion(CompanionRun& m, double t_end, const std::function<bool()>& keep_going) {
  m.stop_at = t_end;
  do {
    if (keep_going && !keep_going()) {
      m.stop_at = -HUGE_VAL;
      m.result.wait();
      UnsteadyResult stopped;
      stopped.ok = false;
      stopped.interrupted = true;
      stopped.message = "it was stopped by an interrupt once the run had finished";
      return stopped;
    }
  } while (keep_going && m.result.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready);
  return m.result.get();
}

}  // namespace magnus
