// Compiled twice by the build tests: linked to magnus_physics it must fail (the physics layer cannot see
// mesh/), linked to magnus_mesh it must compile. Together they show the build enforces the layering.
#include "mesh/polar_grid.hpp"

int main() { return magnus::PolarGrid{}.n_r; }
