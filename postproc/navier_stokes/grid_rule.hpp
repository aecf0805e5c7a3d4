#pragma once
// The grid a navier-stokes scene gets by default: chosen from Re and α (from the spin alone in still
// fluid), not one grid for every scene. Two lengths set it:
//  - the boundary layer, δ = D/√(Re(1 + α²)) (spin thins it where the wall moves against the stream): the
//    first ring sits rule_wall_cells(α) cells inside it, and the rings spread out smoothly from there
//    (Δξ grows by at most kRuleGrowth from one ring to the next, NsParams::wall_refinement, wall_layer);
//  - the wake: n_θ and the far rings' Δξ both shrink as 1/√Re (the wake's vortices shrink as the viscous
//    length does): Δξ_far = (2π/(32·⌈6√(Re/100)⌉))/(5/3), the cell shape of the validation studies.
// With the grid comes a scheme: Jensen's second-order wall closure always; where the wake sheds (Re ≥ 60,
// α ≤ 1: the run marches at once) fourth order in θ, whose St converges on n_θ = 32·⌈4√(Re/100)⌉ where
// second order needed 32·⌈6√(Re/100)⌉ (the far rings keep the latter's spacing: the mean forces depend on
// the radial spacing far more than on n_θ); elsewhere second order on n_θ = 32·⌈6√(Re/100)⌉, whose Newton
// factorisation and eigenvalue search are several times cheaper than fourth order's wider stencil.
// grid.refine scales it (n_θ·refine, every spacing /refine); grid.tolerance picks refine.
#include <algorithm>
#include <cstddef>
#include <string>

#include "physics/scene.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// First-ring cells across δ = D/√(Re(1 + α²)) on the default grid (refine = 1) up to α = 1.
constexpr double kRuleWallCells = 10.0;
/// First-ring cells across δ at spin ratio α: kRuleWallCells·min(max(1, α), 4). Above α = 1 the drag is
/// the difference of a pressure and a friction part that grow apart with α, so each needs a finer wall
/// layer (Re 100, α 2: C_D +1.9% with ten cells, +0.5% with twenty; α 4: −3.0% with twenty, −1.0% with 40).
inline double rule_wall_cells(double alpha) { return kRuleWallCells * std::min(std::max(1.0, alpha), 4.0); }
/// Largest relative growth of Δξ from the wall's ring to the next one (the smooth map's steepest point).
constexpr double kRuleGrowth = 0.08;
/// The design error of the default grid (relative; C_D gets twice it): mean C_L and St within 1%.
constexpr double kRuleTolerance = 1e-2;
/// n_θ = 32·⌈factor·√(max(Re, 20)/100)⌉ on the default grid: kRuleThetaFactor second order in θ,
/// kRuleThetaFactorShedding fourth order (where the wake sheds).
constexpr double kRuleThetaFactor = 6.0;
constexpr double kRuleThetaFactorShedding = 4.0;
/// The scene's wall closure, where the case gives neither solver.wall_closure nor a grid.
constexpr const char* kRuleWallClosure = "jensen";

/// Whether the rule takes the wake to shed, so that a run marches at once (time.mode = "auto"): U > 0,
/// Re = U·D/ν ≥ 60 and α ≤ 1 (the onset is Re ≈ 47 at α = 0; shedding stops near α = 1.9 at Re 100).
inline bool wake_sheds(double U, double Re, double alpha) { return U > 0.0 && Re >= 60.0 && alpha <= 1.0; }

/// The scene's absorbing layer, r_s/a (0: none): where the wake sheds and R ≥ 50a, r_s = R/2. The shed
/// vortices fade within it (λ_R = 2 U/D) instead of reaching R, whose outflow condition reflects them: at
/// Re 100, α = 1 on R = 40a the mean drag moved 1.2% when the rings were doubled without a layer, 0.3%
/// with one from 25a; on the default 100a the run settles in 66 D/U instead of 103.
inline double rule_absorbing_layer(bool sheds, double outer_over_a) {
  return sheds && outer_over_a >= 50.0 ? 0.5 * outer_over_a : 0.0;
}

/// The scene's advection order in θ: 4 where the wake sheds, else 2 (solver.advection_order).
inline int rule_advection_order(bool sheds) { return sheds ? 4 : 2; }

/// The scene's grid: n_θ, and the ring map's wall_refinement (Δξ_far/Δξ_wall) and wall_layer (ξ).
struct SceneGrid {
  int n_theta = kNsDefaultNTheta;
  double wall_refinement = 1.0;  ///< Δξ_far/Δξ_wall ≥ 1
  double wall_layer = 0.1;       ///< ξ-length of the transition from Δξ_wall to Δξ_far
  double delta_xi = 0.0;         ///< ξ-thickness of δ: ln(1 + δ/a)
  double radial_refinement = 5.0 / 3.0;  ///< Δθ/Δξ_far (NsParams::radial_refinement)
};

/// The default grid of a scene at Reynolds number Re (U·D/ν, or a|ω|·D/ν in still fluid) and spin ratio α
/// (0 in still fluid), refined by `refine` (> 0; 1: the default): n_θ = 32·⌈c·refine·√(max(Re, 20)/100)⌉
/// (even, ≥ 16; c = 4 where the wake sheds, else 6); Δξ_far = (2π/(32·⌈6√(max(Re, 20)/100)⌉))/(5/3)/refine;
/// Δξ_wall = ln(1 + δ/a)/rule_wall_cells(α), capped at Δξ_far, so
/// q = Δξ_far/Δξ_wall ≥ 1; wall_layer = (q − 1)·Δξ_far/kRuleGrowth (the spacing grows by kRuleGrowth per
/// ring at most), or 0.1 when q = 1. q and the layer are those of refine = 1: a refined grid is the same
/// map with every spacing divided by refine (n_θ·refine), a family for Richardson.
SceneGrid scene_grid(double Re, double alpha, double refine = 1.0, bool sheds = false);

/// The refine factor that grid.tolerance τ (on mean C_L, C_D and St alike) asks for first: the rule's grid
/// meets 2·kRuleTolerance on C_D and the error falls as the spacing squared, so refine = √(2·kRuleTolerance/τ)
/// (at least 0.5).
double tolerance_refine(double tolerance);

/// Whether the scene's rule chooses the grid (and the scheme): the case gives neither grid.n_theta nor grid.n_r.
bool rule_grid(const Case& c);

/// wake_sheds of the case's scene (its U, U·D/ν and α).
bool scene_sheds(const Case& c);

/// Applies the scene's grid to p (n_θ, Δθ/Δξ_far, wall_refinement, wall_layer) where the case leaves them to magnus:
/// all three when neither grid.n_theta nor grid.n_r is given; a case that gives either keeps today's
/// uniform rings unless it gives grid.wall_refinement too. grid.refine and grid.tolerance scale the rule.
void apply_scene_grid(const Case& c, NsParams& p);

/// Throws std::invalid_argument (one line naming the key that chose the grid — grid.tolerance, with the
/// estimate behind it, grid.refine or grid.n_theta — the grid, its memory with the companion run and the
/// limit) when a march on p's grid with its companion needs more than `limit` bytes (0: the memory
/// available). Before anything is solved.
void check_grid_memory(const Case& c, const NsParams& p, size_t limit = 0);

/// One line for the summary: where the grid came from (the scene's rule, refined, or as given).
std::string scene_grid_text(const Case& c);

}  // namespace magnus
