// A small driver of the BiGlobal (spanwise) problem for the README's grid figures: the leading eigenvalues
// about the steady state, found by Newton's method even where that state is unstable in 2D (which
// `magnus stability --spanwise` would replace by the shedding orbit):
//     spanwise_study Re alpha R_over_a beta_D n_theta…
// D = 1 m, U = 1 m/s. Environment: NS_N_R=k rings instead of the grid rule's, NS_ORDER=4 advection order 4
// in θ and ξ. One line per n_θ: n_r, the twelve leading eigenvalues λ·D/U and the search's seconds.
#include <cstdio>
#include <cstdlib>

#include "postproc/navier_stokes/run_paths.hpp"
#include "solver/navier_stokes/newton.hpp"
#include "solver/navier_stokes/spanwise.hpp"

int main(int argc, char** argv) {
  using namespace magnus;
  if (argc < 6) {
    std::fprintf(stderr, "usage: spanwise_study Re alpha R_over_a beta_D n_theta…\n");
    return 2;
  }
  const double Re = std::atof(argv[1]), alpha = std::atof(argv[2]), R = std::atof(argv[3]);
  const double beta_D = std::atof(argv[4]);
  for (int a = 5; a < argc; ++a) {
    NsParams p;
    p.a = 0.5, p.U = 1.0, p.nu = p.U * 2.0 * p.a / Re, p.omega = alpha * p.U / p.a;
    p.n_theta = std::atoi(argv[a]), p.outer_over_a = R;
    if (const char* nr = std::getenv("NS_N_R")) p.n_r = std::atoi(nr);
    if (const char* order = std::getenv("NS_ORDER")) p.advection_order = p.advection_order_xi = std::atoi(order);
    const NewtonResult s = solve_steady(p, potential_guess(p, ns_grid(p)));
    if (!s.converged) {
      std::printf("n_theta %d: no steady state\n", p.n_theta);
      continue;
    }
    const StabilityResult r = spanwise_eigenvalues(p, s.state, beta_D / (2.0 * p.a), 12, StabilityOptions{});
    std::printf("n_theta %d n_r %d:", p.n_theta, ns_grid(p).n_r);
    for (const auto& l : r.eigenvalues) std::printf("  %+.6f%+.6fi", l.real(), l.imag());
    std::printf("  (%.1f s)\n", r.seconds);
    std::fflush(stdout);
  }
  return 0;
}
