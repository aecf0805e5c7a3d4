#include "postproc/navier_stokes/resolution.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/memory.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

double march_bytes(double nodes, int snapshots) {
  return nodes * ((1.0 + kCompanionBytesShare) * kMarchBytesPerNode + 16.0 * std::max(0, snapshots));
}

size_t passed_limit(double bytes, size_t limit) {
  if (limit == 0) limit = bytes >= double(kUncheckedBytes) ? available_bytes() : 0;
  return limit > 0 && bytes > double(limit) ? limit : 0;
}

ResolvingGrid resolving_grid(const Case& c, double cells) {
  const Scene& s = c.scene;
  const double thickness = boundary_layer_over_a(s.reynolds(), s.spin_ratio());
  const double h = std::log1p(thickness / cells);  // Δξ with a(e^Δξ − 1) = thickness·a/cells
  const NsParams defaults;
  ResolvingGrid g;
  g.n_theta = 2.0 * std::ceil(M_PI / (defaults.radial_refinement * h));
  g.n_r = std::ceil(std::log(c.grid.outer_radius) / h - 1e-9) + 1.0;
  g.nodes = g.n_theta * g.n_r;
  g.bytes = march_bytes(g.nodes, c.output.snapshots);
  return g;
}

void check_resolvable(const Case& c, size_t limit) {
  const Scene& s = c.scene;
  if (!(s.speed > 0.0) || !(s.viscosity > 0.0)) return;
  const ResolvingGrid g = resolving_grid(c, kWallCellsNeeded);
  const bool given = limit > 0;
  limit = passed_limit(g.bytes, limit);
  if (limit == 0) return;
  const std::string key = s.reynolds_given ? "flow.reynolds" : "flow.viscosity";
  const std::string snaps =
      c.output.snapshots > 0 ? fmt::format(", {} of it for output.snapshots = {}", format_bytes(size_t(
                                   std::min(1e18, g.nodes * 16.0 * c.output.snapshots))), c.output.snapshots)
                             : "";
  throw std::invalid_argument(fmt::format(
      "{}: Re = {:.4g} at α = {:.4g} is beyond what the 2D laminar model can resolve here: its boundary layer "
      "D/√(Re(1 + α²)) = {:.2g} D needs {:g} wall cells, a grid of n_θ ≥ {:.0f} and {:.0f} rings ({:.3g} "
      "nodes, about {}{}), more than {} {}; for a real rotor use model.flow = \"potential\": the ideal "
      "bound, and with cylinder.span the shipped rotor data (data/rotor_data.toml) at the scene's α beside it",
      key, s.reynolds(), s.spin_ratio(), 1.0 / std::sqrt(s.reynolds() * (1.0 + s.spin_ratio() * s.spin_ratio())),
      kWallCellsNeeded, g.n_theta, g.n_r, g.nodes, format_bytes(size_t(std::min(1e18, g.bytes))), snaps,
      given ? "the limit" : "the memory available,", format_bytes(limit)));
}

}  // namespace magnus
