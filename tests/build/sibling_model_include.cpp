// Compiled twice by the build tests: linked to magnus_potential it must fail (one model's solver cannot see
// the other's: solver/potential/ and solver/navier_stokes/ share only the solver core), linked to
// magnus_navier_stokes it must compile. Together they show the build enforces the graph, not only a chain.
#include "solver/navier_stokes/operator.hpp"

int main() { return magnus::NsParams{}.n_r; }
