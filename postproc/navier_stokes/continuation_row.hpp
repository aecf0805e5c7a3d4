#pragma once
// One Re row of the S(Re, α) map: the steady branch continued along α (Newton on the row's Jacobian,
// pseudo-arclength past a failure, the fold), each point finished (steady, or marched when unstable).
// continuation.cpp runs the rows; see continuation.hpp.
#include <functional>
#include <optional>
#include <vector>

#include "postproc/navier_stokes/continuation.hpp"
#include "postproc/navier_stokes/map_orbits.hpp"

namespace magnus {

/// One row: continuation along α (sequential). guess: a steady state to start the row's first point from
/// (the previous row's, continuing in Re); first: set to the first point's steady state when it converged;
/// orbits: the last shedding orbit before the row (the previous row's, continuing in Re), updated to the
/// row's last (null: the row's own chain, starting empty). done: called after each point, and again for a
/// point found bistable afterwards (with orbits, an orbit that starts right after a stable point is carried
/// back into the stable points before it while it persists).
std::vector<NsMapPoint> solve_row(const Case& base, const NsMapOptions& o, int row, double re,
                                  const std::function<void(const NsMapPoint&)>& done,
                                  const NsState* guess = nullptr, std::optional<NsState>* first = nullptr,
                                  OrbitChain* orbits = nullptr);

/// Marks the row's second (one-sided) shedding window (MapRegime::second_window) among its points, in α
/// order: a shedding point after the row has shed and then been steady (or bistable), whose St is under half
/// that of the first window's last shedding point. The frequency tells the two apart: the one-sided mode of
/// high spin sheds several times slower (St 0.01–0.05 against 0.1–0.2), while a wake that stops and starts
/// again near α_L (a stable island between two unstable stretches of the branch) keeps its frequency. A row
/// that starts above its first window cannot tell, and leaves such points as shedding.
void mark_second_window(std::vector<NsMapPoint>& row);

}  // namespace magnus
