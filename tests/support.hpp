#pragma once
// Shared helpers for the tests: a case on a chosen grid, solved and post-processed.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>
#include "postproc/navier_stokes/continuation.hpp"
#include "postproc/navier_stokes/orbit.hpp"
#include "postproc/navier_stokes/run_paths.hpp"
#include "postproc/potential/pipeline.hpp"
#include "postproc/run_case.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus::test {

/// The spin-ratio-α case (a = 0.1 m, U = 10 m/s) on an n_θ grid with the given options.
inline Case make_case(double alpha, int n_theta, Spacing spacing = Spacing::geometric,
                      FarField far_field = FarField::exact, StencilKind stencil = StencilKind::five_point,
                      Method method = Method::fft, double outer_radius = 20.0) {
  Case c;
  c.scene.radius = 0.1;
  c.scene.speed = 10.0;
  c.scene.spin = alpha * c.scene.speed / c.scene.radius;
  c.grid.n_theta = n_theta;
  c.grid.spacing = spacing;
  c.grid.far_field = far_field;
  c.solver.stencil = stencil;
  c.solver.method = method;
  c.grid.outer_radius = outer_radius;
  c.output.fields = {"psi"};
  return c;
}

/// Map options for one row of shedding orbits: spin ratios `alphas` at Reynolds number `re`, stability by
/// eigenvalues, shedding points as orbits (NsMapOptions::orbits), no error bars.
inline NsMapOptions orbit_row(std::vector<double> alphas, double re) {
  NsMapOptions o;
  o.alphas = std::move(alphas);
  o.reynolds = {re};
  o.stability = make_stability_hook(StabilityMethod::eigenvalues);
  o.stability_method = "eigenvalues";
  o.orbits = true;
  o.error_estimate = false;
  return o;
}

/// Navier–Stokes parameters of the cylinder a = 0.5 m in U = 1 m/s (D/U = 1 s): ν = 1/Re, ω = 2α, on
/// n_θ points with R = R_over_a·a, one thread.
inline NsParams cylinder_flow(double Re, double alpha, int n_theta, double R_over_a) {
  NsParams p;
  p.a = 0.5, p.U = 1.0, p.nu = 1.0 / Re, p.omega = alpha * p.U / p.a;
  p.n_theta = n_theta, p.outer_over_a = R_over_a, p.threads = 1;
  return p;
}

/// The shedding orbit of p from rest, the mirror symmetry broken as a run breaks it: a short march giving
/// up at t_end (s), then Newton–GMRES shooting to the residual tol (check orbit.converged).
inline OrbitRun shedding_orbit_run(const NsParams& p, double t_end, double tol) {
  OrbitRunOptions o;
  o.t_end = t_end;
  o.orbit.tol = tol;
  const PolarGrid g = ns_grid(p);
  NsState start = impulsive_start(p, g);
  break_symmetry(p, g, start);
  return periodic_orbit_run(p, o, std::move(start));
}

/// Observed order log(e_coarse/e_fine)/log(h_coarse/h_fine) for a refinement ratio.
inline double observed_order(double e_coarse, double e_fine, double ratio = 2.0) {
  return std::log(e_coarse / e_fine) / std::log(ratio);
}

/// max_k |a_k − b_k|.
inline double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (size_t k = 0; k < a.size(); ++k) m = std::max(m, std::fabs(a[k] - b[k]));
  return m;
}

/// max_k |a_k|.
inline double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}

/// A fresh temporary directory for one test.
std::string temp_dir(const std::string& name);

/// What one run of the magnus executable returned and printed.
struct Outcome {
  int status;
  std::string out, err;
};

/// Run the magnus executable with args (each shell-quoted); stdout and stderr go through files in dir.
Outcome magnus_cmd(const std::vector<std::string>& args, const std::string& dir);

/// A file's bytes.
std::string slurp(const std::string& path);

/// Width and height of a complete PNG file, from its IHDR chunk; (0, 0) if it is not a PNG or has no IEND.
std::pair<unsigned long, unsigned long> png_size(const std::string& path);

/// Run `interpreter dir/script.py args…` with the script's text written there first; returns the exit
/// status, and the combined output in *output.
int run_script(const std::string& interpreter, const std::string& dir, const std::string& script,
               const std::vector<std::string>& args, std::string* output);

/// Number of lines (newlines) in s.
size_t lines(const std::string& s);

/// The state at time t (s) with ψ = psi(r, θ) (m²/s) and ζ = zeta(r, θ) (1/s) at every node of g.
inline NsState sample_state(const PolarGrid& g, double t, const std::function<double(double, double)>& psi,
                            const std::function<double(double, double)>& zeta) {
  NsState s;
  s.psi.resize(g.nodes()), s.zeta.resize(g.nodes());
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j) {
      s.psi[size_t(i) * g.n_theta + j] = psi(g.r[i], g.theta[j]);
      s.zeta[size_t(i) * g.n_theta + j] = zeta(g.r[i], g.theta[j]);
    }
  s.t = t;
  return s;
}

/// The line of a text (a summary) that starts with label ("" if none).
std::string line_of(const std::string& text, const std::string& label);

/// True when s is exactly one line (non-empty, one newline, at its end): a refusal's message.
bool one_line(const std::string& s);

/// magnus_cmd with the arguments head, then tail.
Outcome magnus_cmd(std::vector<std::string> head, const std::vector<std::string>& tail,
                   const std::string& dir);

/// A refusal as the house wants it: a non-zero status and one line on standard error that holds `expect`.
bool refused(const Outcome& o, const std::string& expect);

}  // namespace magnus::test
