#pragma once
// One wording for a failed UMFPACK call of the steady Jacobian (assembly, factorisation, solve), and the
// one way its triplets become compressed columns.
#include <string>
#include <vector>

namespace magnus {

/// "SteadyJacobian: UMFPACK WHAT failed (status N[: the Jacobian is singular | : out of memory])".
std::string umfpack_error(const char* what, long status);

/// The n × n compressed-column pattern (Ap, Ai) of triplets (ti, tj), duplicates summed, and each
/// triplet's slot in the values (map); throws std::runtime_error (umfpack_error) when UMFPACK refuses.
void triplet_pattern(long n, const std::vector<long>& ti, const std::vector<long>& tj, std::vector<long>& Ap,
                     std::vector<long>& Ai, std::vector<long>& map);

}  // namespace magnus
