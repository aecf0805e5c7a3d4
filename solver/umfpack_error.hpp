#pragma once
// One wording for a failed UMFPACK call of the steady Jacobian (assembly, factorisation, solve).
#include <string>

namespace magnus {

/// "SteadyJacobian: UMFPACK WHAT failed (status N[: the Jacobian is singular | : out of memory])".
std::string umfpack_error(const char* what, long status);

}  // namespace magnus
