#pragma once
// Checkpoints of a navier-stokes run (format "magnus-checkpoint", version 1): the state of the time
// stepper, the force history and the kept snapshots, written atomically beside the result so that a killed
// run resumes (`magnus run CASE --resume`) and loses at most one checkpoint interval.
#include <string>

#include "postproc/viscous_run.hpp"

namespace magnus {

/// The checkpoint file of a result path: "out.h5" → "out.checkpoint.h5".
std::string checkpoint_path(const std::string& result_path);

/// What must agree for a checkpoint to continue a case: the scene and the grid (a, U, ω, ν, ρ, R/a,
/// n_θ, n_r); time.end, the output and the tolerances may change between runs.
std::string checkpoint_key(const Case& c);

/// Write cp for case c to path atomically (temporary name, then rename).
void write_checkpoint(const std::string& path, const Case& c, const Checkpoint& cp);

/// Read the checkpoint at path for case c. Throws std::runtime_error in one line when it is missing,
/// damaged, or belongs to another scene or grid (naming what differs).
Checkpoint read_checkpoint(const std::string& path, const Case& c);

}  // namespace magnus
