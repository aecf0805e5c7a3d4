#include "postproc/navier_stokes/continuation.hpp"

#include "solver/navier_stokes/stability.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "postproc/navier_stokes/continuation_row.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/stepper_verdict.hpp"
#include "postproc/navier_stokes/unsteady.hpp"
#include "solver/work_queue.hpp"

namespace magnus {

const char* to_string(MapSource s) {
  switch (s) {
    case MapSource::steady:
      return "steady";
    case MapSource::averaged_unstable:
      return "time-averaged (steady state unstable)";
    case MapSource::averaged_no_steady:
      return "time-averaged (no steady state found)";
    case MapSource::marched_steady:
      return "steady, reached by marching from rest (another state than the continued one)";
    case MapSource::orbit:
      return "time-averaged over the shedding orbit (by shooting)";
    case MapSource::none:
      break;
  }
  return "none";
}

Case map_point_case(const Case& base, double reynolds, double alpha) {
  Case c = base;
  Scene& s = c.scene;
  s.spin = alpha * s.speed / s.radius;
  s.circulation_given = false;
  s.viscosity = s.speed * 2.0 * s.radius / reynolds;
  s.reynolds_given = true;
  s.reynolds_value = reynolds;
  return c;
}

std::vector<int> shard_rows(int rows, int shard, int shards) {
  if (shards < 1 || shard < 1 || shard > shards)
    throw std::invalid_argument(fmt::format("--shard {}/{}: K/N needs 1 ≤ K ≤ N", shard, shards));
  if (shards > rows)
    throw std::invalid_argument(fmt::format(
        "--shard {}/{}: the map has {} Reynolds row{} and a row's continuation is sequential: at most {} "
        "shard{}",
        shard, shards, rows, rows == 1 ? "" : "s", rows, rows == 1 ? "" : "s"));
  std::vector<int> r;
  for (int i = shard - 1; i < rows; i += shards) r.push_back(i);
  return r;
}

std::optional<bool> stability_by_marching(const NsParams& p, const NsState& steady, double span,
                                          double margin) {
  return sign_verdict(marched_growth_rate(p, steady, span), margin);
}

StabilityHook make_stability_hook(StabilityMethod m) {
  if (m == StabilityMethod::march)
    return [](const NsParams& p, const NsState& s) { return stability_by_marching(p, s); };
  return [](const NsParams& p, const NsState& s) -> StabilityVerdict {
    StabilityResult r = leading_eigenvalues(p, s);
    StabilityVerdict v(checked_verdict(p, s, r));  // the time stepper where the search cannot judge
    if (r.eigenvalues.empty()) return v;
    const std::complex<double> lead = r.eigenvalues.front();
    if (lead.real() > 0.0 && lead.imag() > 0.0 && !r.mode_zeta.empty()) {  // the mode is the leading one's
      v.pair = lead;
      v.mode_psi = std::move(r.mode_psi), v.mode_zeta = std::move(r.mode_zeta);
      v.mode_Gamma_R = r.mode_Gamma_R;
    }
    return v;
  };
}

NsMap ns_map(const Case& c, const NsMapOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (c.model != FlowModel::navier_stokes)
    throw std::invalid_argument("model.flow: the steady-state continuation needs \"navier-stokes\"");
  if (!(c.scene.speed > 0.0))
    throw std::invalid_argument("flow.speed: a spin-ratio sweep needs U > 0 (α = aω/U)");
  if (o.alphas.empty()) throw std::invalid_argument("--spin-ratio: no spin ratios");
  if (!std::is_sorted(o.alphas.begin(), o.alphas.end()))
    throw std::invalid_argument("--spin-ratio: the spin ratios must ascend");
  NsMap map;
  map.base = c;
  map.alphas = o.alphas;
  map.reynolds = o.reynolds.empty() ? std::vector<double>{c.scene.reynolds()} : o.reynolds;
  for (double re : map.reynolds)
    if (!(re > 0.0) || !std::isfinite(re))
      throw std::invalid_argument(fmt::format("--reynolds: Re = {:g} must be > 0", re));
  const std::vector<int> rows = shard_rows(int(map.reynolds.size()), o.shard, o.shards);
  map.shard = o.shard, map.shards = o.shards;
  map.stability_method = o.stability ? o.stability_method : "none";
  map.averaged = o.average_unstable && bool(o.stability);
  map.orbits = map.averaged && o.orbits;
  const NsParams p = ns_params(c);
  const PolarGrid g = ns_grid(p);
  map.n_theta = g.n_theta, map.n_r = g.n_r, map.outer_over_a = p.outer_over_a;
  map.threads = std::max(1, std::min<int>(o.threads, int(rows.size())));

  std::vector<std::vector<NsMapPoint>> results(rows.size());
  std::vector<std::string> errors(rows.size());
  std::mutex mu;
  auto done = [&](const NsMapPoint& m) {
    if (!o.on_point) return;
    std::lock_guard<std::mutex> lock(mu);
    o.on_point(m);
  };
  if (map.continued_in_re()) {
    // One spin ratio, several Re: one branch continued in Re, each row starting from the previous one's
    // steady state (sequential, so one thread).
    map.threads = 1;
    std::optional<NsState> state;
    OrbitChain orbits;  // the shedding orbit continued in Re too (o.orbits)
    for (size_t i = 0; i < rows.size(); ++i) {
      std::optional<NsState> first;
      try {
        results[i] = solve_row(c, o, rows[i], map.reynolds[size_t(rows[i])], done, state ? &*state : nullptr,
                               &first, &orbits);
      } catch (const std::exception& e) {
        errors[i] = fmt::format("Re = {:g}: {}", map.reynolds[size_t(rows[i])], e.what());
      }
      if (first) state = std::move(first);
    }
  } else {
    for_each_index(rows.size(), size_t(map.threads), [&](size_t i) {
      try {
        results[i] = solve_row(c, o, rows[i], map.reynolds[size_t(rows[i])], done);
      } catch (const std::exception& e) {
        errors[i] = fmt::format("Re = {:g}: {}", map.reynolds[size_t(rows[i])], e.what());
      }
    });
  }
  for (const auto& e : errors)
    if (!e.empty()) throw std::runtime_error(e);
  for (auto& r : results) map.points.insert(map.points.end(), r.begin(), r.end());
  map.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return map;
}

}  // namespace magnus