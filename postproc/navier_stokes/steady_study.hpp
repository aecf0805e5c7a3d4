#pragma once
// A steady state solved on a sequence of grids, coarse to fine, each grid's Newton iteration starting from
// the previous grid's state interpolated onto it (grid sequencing: the fine grids need one or two
// factorisations instead of five or six), and the grid-converged forces by Richardson extrapolation from
// the grids the study solved, with an error bar.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/navier_stokes/newton.hpp"

namespace magnus {

/// The grids of a study and Newton's options on them.
struct SteadyStudyOptions {
  /// Each level's size as a fraction of the case's grid: n_θ,k = scale·n_θ (even), n_r,k − 1 =
  /// scale·(n_r − 1) (R kept); coarse → fine, the last 1. Richardson uses the last three.
  std::vector<double> scales = {0.25, 0.5, 2.0 / 3.0, 1.0};
  /// Plain Newton on the first level (its quadratic convergence shows in the residuals; the first level
  /// is the cheapest), chord steps (newton.chord_ratio) on the others.
  bool plain_first = true;
  /// Newton on each level: tol, max_iterations, chord_ratio (its on_iteration is not called: see below).
  NewtonOptions newton = [] {
    NewtonOptions o;
    o.chord_ratio = 0.3;  // one factorisation per level once the guess is close
    o.tol = 1e-9;         // C_D on each level moves < 1e-10 against 1e-10 (Re 40): far below the grid error
    return o;
  }();
  /// Without spin (ω = 0, U > 0) solve the mirror-symmetric half of each grid (SteadyJacobian's mirror):
  /// the same steady state to round-off for about a third of the cost. Off: the whole grid (the symmetric
  /// state all the same; Newton does not break the symmetry).
  bool mirror = true;
  /// On a machine with two cores or more and with three levels or more, solve the last two side by
  /// side, both started from the level before them, as a run's companion uses the second core: the
  /// finest level, most of the cost, no longer waits for the next-finest (Re 40, 288 × 450: the study in
  /// 2.2 s instead of 3.1 s). Off: one after another, each from the one before.
  bool overlap = true;
  /// After each residual: (level, iteration, scaled max-norm residual); iteration 0 = the level's guess.
  /// Called from two threads when the levels overlap, never at once.
  std::function<void(int, int, double)> on_iteration;
};

/// A Richardson extrapolation f* = f_N + (f_N − f_{N−1})/((h_{N−1}/h_N)^p − 1) of values f_k on grids of
/// spacing h_k (coarse → fine) and its error bar.
struct Richardson {
  double value = 0.0;       ///< f*, the quantity's units
  double finest = 0.0;      ///< f_N, the finest grid's value
  double order = 2.0;       ///< p used: the observed order of three grids when it is in [1, 4], else 2
  bool observed = false;    ///< p was observed (three grids, monotone, in [1, 4])
  /// With an observed order max(|f*(p) − f*(2)|, |f*(p) − f_N|/10): how much the value depends on the
  /// order (on grids in the asymptotic range the two agree), at least a tenth of the correction; without
  /// one |f* − f_N|, the whole correction.
  double error = 0.0;
};

/// Richardson extrapolation of f on grids h (same length ≥ 2, h decreasing); formal order 2. Throws
/// std::invalid_argument for fewer than two grids or h not decreasing.
Richardson richardson(const std::vector<double>& f, const std::vector<double>& h);

/// One level of a study: its grid, how Newton went, the figures on it.
struct SteadyLevel {
  int n_theta = 0, n_r = 0;
  double h = 0.0;  ///< √(Δξ·Δθ), the level's spacing (rad)
  NewtonResult newton;  ///< how Newton went (its state moved out: the finest to SteadyStudy::state)
  double C_D = 0.0, C_L = 0.0;  ///< on ½ρU²·2a (U > 0)
  double recirculation = 0.0;   ///< L/D behind the body (0 when there is no recirculation bubble)
};

/// What a study found.
struct SteadyStudy {
  std::vector<SteadyLevel> levels;  ///< coarse → fine
  NsState state;                    ///< the finest level's steady state
  bool converged = false;           ///< every level's Newton iteration converged
  bool mirror = false;              ///< the levels were solved on the mirror-symmetric half
  std::string message;              ///< the first failure, or a one-line account
  std::optional<Richardson> C_D, C_L, recirculation;  ///< from ≥ 2 levels, U > 0
  double wall_seconds = 0.0;
};

/// Levels coarser than this (n_θ or rings) are left out of a study: Newton's answer there says little.
constexpr int kMinStudyTheta = 16;
constexpr int kMinStudyRings = 8;

/// The grid of level `scale` of the parameters' grid (scale 1: ns_grid(p) itself).
NsParams level_params(const NsParams& p, double scale);

/// A state on grid `from` on grid `to` (same a and R): trigonometric interpolation in θ per ring (every
/// Fourier mode of the coarse ring kept, the Nyquist mode as its cosine), then 4-point Lagrange in ξ; Γ_R kept.
NsState interpolate_state(const PolarGrid& from, const NsState& s, const PolarGrid& to);

/// The study: the first level from `guess` (potential_guess when null; it must be on the first level's
/// grid), each next one from the previous state interpolated. Levels below kMinStudyTheta/Rings are left
/// out; a coarser level where Newton does not converge is left out too (the next starts from the potential
/// flow; message names it); converged = false, message saying why, when the finest does not converge.
/// Throws std::invalid_argument for bad scales.
SteadyStudy steady_study(const NsParams& p, const SteadyStudyOptions& o = {}, const NsState* guess = nullptr);

}  // namespace magnus
