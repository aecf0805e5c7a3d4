#pragma once
// The spanwise part of `magnus stability CASE --spanwise`: the β-scan of the steady state (postproc's
// spanwise_scan) as a table, a verdict and a JSON object; and the search for the 3D onset in Re.
#include <string>
#include <vector>

#include "io/json_output.hpp"
#include "postproc/navier_stokes/critical.hpp"

namespace magnus {

/// The scan at each β·D of beta_D (spanwise_stability: about the steady state s when it is stable, else
/// about the shedding orbit); its table and verdict are appended to text and its JSON object returned.
/// Progress lines go to stderr unless json.
Json spanwise_report(const NsParams& p, const HopfEvaluation& s, const std::vector<double>& beta_D,
                     const std::string& eigensolver, bool json, std::string& text);

/// The 3D onset in [Re_a, Re_b] to within tol (spanwise_critical at the wavenumbers beta_D): one line per
/// Reynolds number searched (to stderr as it goes unless json), the crossing and its wavelength appended to
/// text; its JSON object returned. With `fine`, the onset is then refined on that grid
/// (spanwise_critical_fine), under "fine_grid".
Json spanwise_critical_report(const NsParams& p, const std::vector<double>& beta_D, double Re_a, double Re_b,
                              double tol, const std::string& eigensolver, bool json, std::string& text,
                              const NsParams* fine = nullptr);

}  // namespace magnus
