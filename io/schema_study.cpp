// The steady grid study's entries of the schema table (Models::steady_study): a navier-stokes run with
// time.mode = "steady" stores each grid's figures and Newton's work in /steady_study (one value per grid,
// coarse to fine) and the Richardson values with their error bars as attributes of that group. Absent
// from every other result.
#include <deque>

#include "io/schema_build.hpp"
#include "physics/checked_cast.hpp"

namespace magnus::schema_build {

namespace {

const char* S = "/steady_study";

/// The study of a result being read back (created on first use).
SteadyStudy& study(FlowResult& r) {
  ViscousPart& v = vis(r);
  if (!v.steady_study) v.steady_study.emplace();
  return *v.steady_study;
}

const SteadyStudy* study(const FlowResult& r) {
  return r.viscous && r.viscous->steady_study ? &*r.viscous->steady_study : nullptr;
}

/// The level list of a study being read back, grown to n levels.
std::vector<SteadyLevel>& levels(FlowResult& r, size_t n) {
  std::vector<SteadyLevel>& l = study(r).levels;
  if (l.size() < n) l.resize(n);
  return l;
}

/// One value per grid of the study: a member of SteadyLevel (or of its NewtonResult, through `get`).
DatasetSpec per_level(const char* name, const char* units, const char* description,
                      std::function<double(const SteadyLevel&)> get,
                      std::function<void(SteadyLevel&, double)> set) {
  return only(Models::steady_study,
              DatasetSpec{std::string(S) + "/" + name, units, description, DataShape::levels,
                          [get](const FlowResult& r) {
                            std::vector<double> v;
                            if (const SteadyStudy* st = study(r))
                              for (const SteadyLevel& lv : st->levels) v.push_back(get(lv));
                            return v;
                          },
                          [set](FlowResult& r, std::vector<double> v) {
                            std::vector<SteadyLevel>& l = levels(r, v.size());
                            for (size_t k = 0; k < v.size(); ++k) set(l[k], v[k]);
                          }});
}

/// The Richardson value of one quantity and its error bar, order and whether the order was observed.
std::vector<AttrSpec> extrapolated(const char* name, const char* what,
                                   std::optional<Richardson> SteadyStudy::*m) {
  const auto get = [m](double Richardson::*f) {
    return [m, f](const FlowResult& r) -> std::optional<double> {
      const SteadyStudy* st = study(r);
      if (!st || !(st->*m)) return std::nullopt;
      return (*(st->*m)).*f;
    };
  };
  const auto set = [m](double Richardson::*f) {
    return [m, f](FlowResult& r, double v) {
      std::optional<Richardson>& q = study(r).*m;
      if (!q) q.emplace();
      (*q).*f = v;
    };
  };
  const std::string n = name;
  // AttrSpec holds C strings: the composed names and descriptions live in static storage (a deque never
  // moves its elements).
  static std::deque<std::string> kept;
  auto keep = [](std::string s) { return kept.emplace_back(std::move(s)).c_str(); };
  return {
      only(Models::steady_study,
           num(S, keep(n), "1", keep(std::string("Richardson value of ") + what + " from the last three grids"),
               get(&Richardson::value), set(&Richardson::value))),
      only(Models::steady_study,
           num(S, keep(n + "_error"), "1", keep(std::string("error bar of the Richardson value of ") + what),
               get(&Richardson::error), set(&Richardson::error))),
      only(Models::steady_study,
           num(S, keep(n + "_order"), "1",
               keep(std::string("order p used for ") + what + " (observed on three grids when in [1, 4], else 2)"),
               get(&Richardson::order), set(&Richardson::order))),
      only(Models::steady_study,
           integer(
               S, keep(n + "_order_observed"), keep(std::string("1: the order of ") + what + " was observed"),
               [m](const FlowResult& r) -> std::optional<double> {
                 const SteadyStudy* st = study(r);
                 if (!st || !(st->*m)) return std::nullopt;
                 return (st->*m)->observed ? 1.0 : 0.0;
               },
               [m](FlowResult& r, double v) {
                 std::optional<Richardson>& q = study(r).*m;
                 if (!q) q.emplace();
                 q->observed = v != 0.0;
               })),
  };
}

}  // namespace

std::vector<AttrSpec> study_attributes() {
  std::vector<AttrSpec> a = {
      only(Models::steady_study,
           integer(
               S, "converged", "1: Newton converged on every grid of the study",
               [](const FlowResult& r) { return study(r) ? opt(study(r)->converged ? 1.0 : 0.0) : std::nullopt; },
               [](FlowResult& r, double v) { study(r).converged = v != 0.0; })),
      only(Models::steady_study,
           integer(
               S, "mirror", "1: each grid was solved on its mirror-symmetric half (no spin)",
               [](const FlowResult& r) { return study(r) ? opt(study(r)->mirror ? 1.0 : 0.0) : std::nullopt; },
               [](FlowResult& r, double v) { study(r).mirror = v != 0.0; })),
      only(Models::steady_study,
           num(
               S, "seconds", "s", "wall clock of the whole study",
               [](const FlowResult& r) { return study(r) ? opt(study(r)->wall_seconds) : std::nullopt; },
               [](FlowResult& r, double v) { study(r).wall_seconds = v; })),
      only(Models::steady_study,
           text(
               S, "message", "how the study went, or its first failure",
               [](const FlowResult& r) { return study(r) ? study(r)->message : std::string(); },
               [](FlowResult& r, const std::string& v) { study(r).message = v; })),
  };
  for (auto&& q : {extrapolated("cd", "C_D", &SteadyStudy::C_D), extrapolated("cl", "C_L", &SteadyStudy::C_L),
                   extrapolated("recirculation_length", "the recirculation length L/D",
                                &SteadyStudy::recirculation)})
    a.insert(a.end(), q.begin(), q.end());
  return a;
}

std::vector<DatasetSpec> study_datasets() {
  return {
      per_level(
          "n_theta", "1", "points around each grid of the study, coarse to fine",
          [](const SteadyLevel& l) { return double(l.n_theta); }, [](SteadyLevel& l, double v) { l.n_theta = int(v); }),
      per_level(
          "n_r", "1", "rings of each grid", [](const SteadyLevel& l) { return double(l.n_r); },
          [](SteadyLevel& l, double v) { l.n_r = int(v); }),
      per_level(
          "h", "rad", "each grid's spacing √(Δξ·Δθ)", [](const SteadyLevel& l) { return l.h; },
          [](SteadyLevel& l, double v) { l.h = v; }),
      per_level(
          "cd", "1", "drag coefficient on each grid", [](const SteadyLevel& l) { return l.C_D; },
          [](SteadyLevel& l, double v) { l.C_D = v; }),
      per_level(
          "cl", "1", "lift coefficient on each grid", [](const SteadyLevel& l) { return l.C_L; },
          [](SteadyLevel& l, double v) { l.C_L = v; }),
      per_level(
          "recirculation_length", "1", "recirculation length L/D on each grid (0: no bubble)",
          [](const SteadyLevel& l) { return l.recirculation; }, [](SteadyLevel& l, double v) { l.recirculation = v; }),
      per_level(
          "newton_steps", "1", "Newton (and chord) steps on each grid",
          [](const SteadyLevel& l) { return double(l.newton.iterations); },
          [](SteadyLevel& l, double v) { l.newton.iterations = checked_cast<int>(v, "newton_iterations"); }),
      per_level(
          "factorisations", "1", "LU factorisations on each grid",
          [](const SteadyLevel& l) { return double(l.newton.factorisations); },
          [](SteadyLevel& l, double v) { l.newton.factorisations = checked_cast<int>(v, "factorisations"); }),
      per_level(
          "residual", "1", "Newton's last scaled max-norm residual on each grid",
          [](const SteadyLevel& l) { return l.newton.residuals.empty() ? 0.0 : l.newton.residuals.back(); },
          [](SteadyLevel& l, double v) { l.newton.residuals = {v}; }),
      per_level(
          "seconds", "s", "wall clock of Newton on each grid",
          [](const SteadyLevel& l) { return l.newton.wall_seconds; },
          [](SteadyLevel& l, double v) { l.newton.wall_seconds = v; }),
  };
}

}  // namespace magnus::schema_build
