#pragma once
// The march's whole state as one dimensionless vector, for the methods that treat the time stepper as a
// map on it (shooting for periodic orbits, periodic_orbit.hpp; Arnoldi on the linearised march,
// stepper_eigen.hpp): x = [ζ·D/U | ψ/(UD) | N^{n−1}/U² | Γ_R/(UD) | (dΓ_R/dt)^{n−1}/U²], everything the next
// step reads. U_ref = U, or a|ω| without a freestream; D = 2a. Scaled so that one finite-difference ε
// suits every block.
#include <cstddef>
#include <vector>

#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// Packs and unpacks states of one grid as scaled vectors of 3·nodes + 2 unknowns.
struct StateVector {
  /// The scales of p for states of `nodes` nodes.
  StateVector(const NsParams& p, size_t nodes);
  size_t nodes;
  double zeta, psi, N, Gamma, flux;  ///< multiply a state's block by these to get the unknowns
  double time;                       ///< a time in s times this is in D/U
  size_t size() const { return 3 * nodes + 2; }
  /// The unknowns of s (an absent N^{n−1}: zeros).
  std::vector<double> pack(const NsState& s) const;
  /// The state of the unknowns x at t = 0, as after a step of dt (s), so that AB2 goes on with its own Δt.
  NsState unpack(const std::vector<double>& x, double dt) const;
};

}  // namespace magnus
