#pragma once
// The steady Jacobian's sparse LU plumbing: one wording for a failed UMFPACK call (assembly,
// factorisation, solve), the one way its triplets become compressed columns, and the fill-reducing
// order of its unknowns that UMFPACK is given.
#include <functional>
#include <string>
#include <vector>

namespace magnus {

/// "UMFPACK WHAT failed (status N[: the matrix is singular | : out of memory])"; WHAT names the step and
/// whose matrix it is ("numeric factorisation (Newton's Jacobian)").
std::string umfpack_error(const char* what, long status);

/// The n × n compressed-column pattern (Ap, Ai) of triplets (ti, tj), duplicates summed, and each
/// triplet's slot in the values (map); throws std::runtime_error (umfpack_error) when UMFPACK refuses.
void triplet_pattern(long n, const std::vector<long>& ti, const std::vector<long>& tj, std::vector<long>& Ap,
                     std::vector<long>& Ai, std::vector<long>& map);

/// The n × n compressed columns (Ap, Ai, Ax) of the triplets (ti, tj, tx), duplicates summed (the
/// linear-stability problems, assembled once).
void compress_triplets(long n, const std::vector<long>& ti, const std::vector<long>& tj, const std::vector<double>& tx,
                       std::vector<long>& Ap, std::vector<long>& Ai, std::vector<double>& Ax);

/// A fill-reducing order of the Jacobian's unknowns, given to UMFPACK: nested dissection of the grid's
/// nodes, each node's (ψ, ζ) pair kept together. The whole grid (periodic in θ) is first cut along the
/// rays θ = 0 and θ = π, which come last, then Γ_R; the mirror half, the nodes 0 < θ_j < π, is a plain
/// box. Timed once around the calls on the Re 40 grid (256 × 314, the half): UMFPACK's analysis 0.09 s
/// with it against 0.69 s with its own METIS ordering, the factorisation 0.43 s against 0.54 s.
/// theta_reach: how many columns the stencil reaches either side in θ (1; 2 for advection order 4 in θ),
/// the width of the cuts across θ (the cuts along the rays θ = 0 and π are then that many columns wide);
/// xi_reach likewise in rings (2 for advection order 4 in ξ), the width of the cuts across ξ.
std::vector<long> grid_order(int nr, int n, bool mirror, int theta_reach = 1, int xi_reach = 1);

/// UMFPACK's symbolic analysis the one way the steady Jacobian and its shifted complex copy want it: the
/// order q (grid_order) given, with the symmetric strategy (the order for rows and columns alike); should
/// that be refused, UMFPACK's METIS, then its default. `analyse(control, q)` calls umfpack_{dl,zl}_qsymbolic
/// with q, or umfpack_{dl,zl}_symbolic when q is null, and returns its status. The status of the last try.
long symbolic_in_grid_order(long n, const std::vector<long>& q,
                            const std::function<long(const double* control, const long* q)>& analyse);

/// OpenBLAS on one thread while it lives (restored after): UMFPACK's frontal matrices are small. On the
/// shared 2-core machine the default grid's factorisation (90625 unknowns, 3.1 GFlop) took 1.0–1.6 s with
/// OPENBLAS_NUM_THREADS=1 against 1.4–2.3 s with 2 (same CPU seconds: the second thread only waits).
/// Found at run time, so any other BLAS is left alone. Nested or on several threads at once, the first
/// sets one thread and the last restores the count.
class SingleThreadBlas {
 public:
  SingleThreadBlas();
  ~SingleThreadBlas();
  SingleThreadBlas(const SingleThreadBlas&) = delete;
  SingleThreadBlas& operator=(const SingleThreadBlas&) = delete;

 private:
  int (*get_)() = nullptr;
  void (*set_)(int) = nullptr;
};

}  // namespace magnus
