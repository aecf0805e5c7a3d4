#pragma once
// The spanwise part of `magnus stability CASE --spanwise`: the β-scan of the steady state (postproc's
// spanwise_scan) as a table, a verdict and a JSON object.
#include <string>
#include <vector>

#include "io/json_output.hpp"
#include "solver/navier_stokes/operator.hpp"

namespace magnus {

/// The scan at each β·D of beta_D about the steady state of p (steady non-null: the spanwise eigenvalues
/// with eigensolver) or about its shedding orbit (null: the Floquet multipliers); its table and verdict are
/// appended to text and its JSON object returned. Progress lines go to stderr unless json.
Json spanwise_report(const NsParams& p, const NsState* steady, const std::vector<double>& beta_D,
                     const std::string& eigensolver, bool json, std::string& text);

}  // namespace magnus
