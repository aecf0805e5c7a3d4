#pragma once
// Lift against spin ratio (or circulation) by superposition: one factorization, two solves
// (ψ_U and ψ_Γ), then every point is evaluated from the basis in O(n_θ + n_r) — never one solve per
// point. Its table, CSV and HDF5 files are written by io/sweep_file.
#include <string>
#include <vector>

#include "postproc/potential/superposition.hpp"

namespace magnus {

/// What the sweep varies.
enum class SweepVariable { spin_ratio, circulation };

/// A whole sweep: the base case, the points (each with its case: speed, spin, circulation), and
/// what solving cost.
struct SweepResult {
  Case base;  ///< the resolved case the sweep starts from
  SweepVariable variable = SweepVariable::spin_ratio;
  PolarGrid grid;
  std::string method;       ///< the linear solver that ran ("fft" | "cholmod")
  std::string grid_choice;  ///< how grid.tolerance chose the grid ("" without a tolerance)
  std::vector<SweepPoint> points;
  int linear_solves = 0;  ///< right-hand sides solved with the factorization: 2
  double assemble_s = 0.0, factor_s = 0.0, solve_s = 0.0, evaluate_s = 0.0, total_s = 0.0;
};

/// The spin-ratio sweep: for each α the case with ω = αU/a (spin model). Throws std::invalid_argument
/// when U = 0 (α undefined) or the case has circulation.model = "given" (Γ would not follow α).
SweepResult sweep_spin_ratio(const Case& c, const std::vector<double>& alphas, int threads = 1);

/// The circulation sweep for circulation.model = "given": for each Γ (m²/s) the case with that Γ; the
/// spin (and with it the seed estimate) stays the case's. Throws std::invalid_argument when U = 0 or
/// the model is "spin".
SweepResult sweep_circulation(const Case& c, const std::vector<double>& circulations, int threads = 1);

/// One row of the table, derived from a point; undefined values are NaN.
struct SweepRow {
  double alpha;        ///< spin ratio aω/U (spin sweep) or Γ/(2πaU) (circulation sweep)
  double circulation;  ///< Γ, m²/s
  double lift, drag;   ///< N/m
  double cl, cl_kj, cl_seed, cl_rel_kj, kj_over_seed, cd;
  double delta_p, delta_p_seed;                            ///< Pa
  double stag_theta1_deg, stag_theta2_deg, stag_r_over_a;  ///< free point: θ1 = 90 or 270, θ2 = NaN
};
SweepRow sweep_row(const SweepResult& s, const SweepPoint& p);

}  // namespace magnus
