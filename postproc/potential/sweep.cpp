#include "postproc/potential/sweep.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "postproc/potential/pipeline.hpp"
#include "postproc/potential/tolerance.hpp"

namespace magnus {

// ---------------------------------------------------------------------------------------------
// Solving

namespace {

/// Forwards to the real solver and counts the right-hand sides it solves: proof that a sweep solves
/// twice, however many points it has.
class CountingSolver : public PsiSolver {
 public:
  CountingSolver(const PolarGrid& grid, std::unique_ptr<PsiSolver> inner)
      : PsiSolver(grid, inner->op()), inner_(std::move(inner)) {}
  std::vector<double> solve_unknowns(const std::vector<double>& rhs) override {
    ++count;
    return inner_->solve_unknowns(rhs);
  }
  std::vector<double> solve_boundary(const BoundaryData& bd) override {
    ++count;
    return inner_->solve_boundary(bd);  // the solver's own (possibly faster) path
  }
  Method method() const override { return inner_->method(); }
  const PsiSolver& inner() const { return *inner_; }
  int count = 0;

 private:
  std::unique_ptr<PsiSolver> inner_;
};

/// Evaluate every point's scene from the two solves of the base case's discretization.
SweepResult sweep_scenes(const Case& base, const std::vector<Scene>& scenes, SweepVariable variable,
                         int threads) {
  const double t0 = now_s();
  SweepResult s;
  s.base = base;
  s.variable = variable;
  Discretization d = discretize(base, std::max(1, threads));
  s.grid = d.grid;
  CountingSolver solver(s.grid, std::move(d.solver));
  const PsiBasis pb = solve_basis(solver);  // the only two solves of the sweep
  const FlowBasis fb = flow_basis(s.grid, pb.psi_U, pb.psi_Gamma, derivative_order(base.solver.stencil));
  const double t1 = now_s();

  s.points.resize(scenes.size());
  const size_t n_threads =
      std::clamp<size_t>(size_t(std::max(1, threads)), 1, std::max<size_t>(1, scenes.size() / 64));
  auto work = [&](size_t from, size_t to) {
    for (size_t k = from; k < to; ++k) s.points[k] = evaluate(fb, scenes[k]);
  };
  if (n_threads <= 1) {
    work(0, scenes.size());
  } else {
    std::vector<std::thread> pool;
    const size_t chunk = (scenes.size() + n_threads - 1) / n_threads;
    for (size_t t = 0; t < n_threads; ++t)
      pool.emplace_back(work, std::min(scenes.size(), t * chunk), std::min(scenes.size(), (t + 1) * chunk));
    for (auto& th : pool) th.join();
  }

  s.method = to_string(solver.method());
  s.linear_solves = solver.count;
  s.assemble_s = d.setup_s + solver.inner().timing.assemble_s;
  s.factor_s = solver.inner().timing.factor_s;
  s.solve_s = solver.timing.solve_s;
  s.evaluate_s = now_s() - t1;
  s.total_s = now_s() - t0;
  return s;
}

/// The case the sweep solves: with grid.tolerance the grid and stencil are chosen once, at α = 1
/// (Γ = 2πaU): the relative lift error of a grid is the same at every α (lift is linear in Γ at fixed U).
/// `choice` says how the grid was chosen ("" without a tolerance).
Case sweep_case(const Case& c, SweepVariable variable, int threads, std::string& choice) {
  Case p = c;
  if (c.grid.tolerance > 0.0) {
    Case probe = p;
    if (variable == SweepVariable::spin_ratio)
      probe.scene.spin = c.scene.speed / c.scene.radius;
    else
      probe.scene.circulation_value = 2.0 * M_PI * c.scene.radius * c.scene.speed;
    const GridChoice g = choose_grid(probe, std::max(1, threads));
    p.grid.n_theta = g.n_theta;
    p.grid.n_r = 0;
    p.solver.stencil = g.stencil;
    choice =
        fmt::format("chosen for C_L tolerance {:.3g}: n_θ = {}, {} stencil (estimate {:.3g}; grids tried {})",
                    c.grid.tolerance, g.n_theta, to_string(g.stencil), g.estimated_cl_rel, g.trail);
  }
  return p;
}

/// Sweep: one scene per value, set(scene, value) varies it; the result records the grid and stencil that ran.
template <class Set>
SweepResult sweep_values(const Case& c, const std::vector<double>& values, SweepVariable variable,
                         int threads, const Set& set) {
  std::string choice;
  const Case solved = sweep_case(c, variable, threads, choice);
  std::vector<Scene> scenes(values.size(), solved.scene);
  for (size_t k = 0; k < values.size(); ++k) set(scenes[k], values[k]);
  SweepResult s = sweep_scenes(solved, scenes, variable, threads);
  s.grid_choice = choice;
  return s;
}

}  // namespace

SweepResult sweep_spin_ratio(const Case& c, const std::vector<double>& alphas, int threads) {
  if (!(c.scene.speed > 0.0))
    throw std::invalid_argument(
        "a spin-ratio sweep needs flow.speed > 0: with U = 0 the spin ratio α = aω/U is undefined");
  if (c.scene.circulation_given)
    throw std::invalid_argument(
        "--spin-ratio varies the spin, but circulation.model = \"given\" fixes Γ: use --circulation A:B:STEP "
        "instead");
  return sweep_values(c, alphas, SweepVariable::spin_ratio, threads,
                      [](Scene& s, double alpha) { s.spin = alpha * s.speed / s.radius; });
}

SweepResult sweep_circulation(const Case& c, const std::vector<double>& circulations, int threads) {
  if (!(c.scene.speed > 0.0))
    throw std::invalid_argument(
        "a circulation sweep needs flow.speed > 0: with U = 0 the lift coefficients are undefined");
  if (!c.scene.circulation_given)
    throw std::invalid_argument(
        "--circulation needs circulation.model = \"given\" (add --set circulation.model=given), or use "
        "--spin-ratio");
  return sweep_values(c, circulations, SweepVariable::circulation, threads,
                      [](Scene& s, double Gamma) { s.circulation_value = Gamma; });
}

// ---------------------------------------------------------------------------------------------
// Rows, table, CSV

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
double deg(double rad) { return rad * 180.0 / M_PI; }
}  // namespace

SweepRow sweep_row(const SweepResult& s, const SweepPoint& p) {
  const Scene& scene = p.scene;
  const Forces& f = p.forces;
  SweepRow w{};
  w.circulation = scene.Gamma();
  w.alpha = s.variable == SweepVariable::spin_ratio
                ? scene.spin_ratio()
                : w.circulation / (2.0 * M_PI * scene.radius * scene.speed);
  w.lift = f.lift;
  w.drag = f.drag;
  w.cl = f.cl.value_or(kNaN);
  w.cl_kj = f.cl_kutta_joukowski.value_or(kNaN);
  w.cl_seed = f.cl_seed_estimate.value_or(kNaN);
  w.cl_rel_kj = f.cl && f.cl_kutta_joukowski && *f.cl_kutta_joukowski != 0.0
                    ? *f.cl / *f.cl_kutta_joukowski - 1.0
                    : kNaN;
  w.kj_over_seed = f.cl_kutta_joukowski && f.cl_seed_estimate && *f.cl_seed_estimate != 0.0
                       ? *f.cl_kutta_joukowski / *f.cl_seed_estimate
                       : kNaN;
  w.cd = f.cd.value_or(kNaN);
  w.delta_p = f.delta_p_top_bottom;
  w.delta_p_seed = f.delta_p_seed_estimate;
  w.stag_theta1_deg = w.stag_theta2_deg = w.stag_r_over_a = kNaN;
  const std::vector<StagnationPoint> pts = sorted_stagnation_points(p.stagnation);
  if (!pts.empty()) {
    w.stag_theta1_deg = deg(pts[0].theta);
    w.stag_r_over_a = pts[0].r / scene.radius;
    if (pts.size() > 1) w.stag_theta2_deg = deg(pts[1].theta);
  }
  return w;
}

}  // namespace magnus
