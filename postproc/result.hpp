#pragma once
// Everything one run produces, post-processed from ψ: what the files and the summary show.
#include <string>
#include <vector>
#include "postproc/fields.hpp"
#include "postproc/forces.hpp"

namespace magnus {

/// Wall-clock seconds per phase of a run.
struct Timing {
  double total_s = 0.0, assemble_s = 0.0, factor_s = 0.0, solve_s = 0.0, postproc_s = 0.0;
};

/// What a run reports besides the fields: which method ran, the grid choice, the error estimate.
struct RunInfo {
  std::string method = "fft";
  std::string grid_choice;         ///< how the grid was chosen (tolerance mode)
  double estimated_cl_rel = -1.0;  ///< a-posteriori estimate, < 0 if none
  int threads = 1;
};

struct FlowResult {
  Case c;
  PolarGrid grid;
  Fields fields;
  Surface surface;
  Forces forces;
  Errors errors;
  std::vector<StagnationPoint> stagnation, stagnation_exact;
  Timing timing;
  RunInfo info;
};

/// Fields, surface, forces, stagnation points and errors from the superposition basis ψ_U, ψ_Γ
/// (ψ = U·ψ_U + Γ·ψ_Γ; the surface split of surface_from_basis keeps the forces free of ε·α round-off).
FlowResult postprocess(const PolarGrid& g, const Case& c, const std::vector<double>& psi_U,
                       const std::vector<double>& psi_Gamma, const FieldSelection& sel);

}  // namespace magnus
